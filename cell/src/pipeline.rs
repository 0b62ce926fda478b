//! The per-frame pipeline: camera views in; fused skeleton, filtered skeleton, RULA, warnings and
//! the height decision out. It is wired here and only here.
//!
//! ```text
//! views ─► FrameAssembler ─► FusionEngine ─► tracked? ─► OneEuroFilter ─► RulaAssessor ─► WarningTracker
//!          (time-aligns)     (default|paper)  (gate)      (causal)     │
//!                                                                      └─► HeightEstimator (unfiltered, until decided)
//! ```
//!
//! The session state machine owns one [`Pipeline`]; the digital twin's experiments, `ergocell
//! triangulate`, `ergocell rula track`, `ergocell height`, the demo and `ergocell run` run the same
//! type with the same defaults ([`PipelineConfig::new`], or the cell file's `[pipeline]`,
//! `[assessment]`, `[task]`, `[warnings]` and `[height]`), so a figure measured on the twin is a
//! figure of the controller that ships.
//!
//! Entry points, from raw to late:
//! - [`Pipeline::push_views`]: views as they arrive (the session, the experiments);
//! - [`Pipeline::process_frame`]: a frame already time-aligned (an offline detections file);
//! - [`Pipeline::process_fused`]: a skeleton already fused (a 3D landmarks file).
//!
//! The height is measured on the **unfiltered** fused skeleton (the filter's lag would bias a
//! stature measured while the operator walks in) and only until the first decision, which is final:
//! the class is decided once per session. RULA runs on the filtered skeleton of every tracked frame.

use ergocell_ergonomics::warnings::WarningKind;
use ergocell_ergonomics::{
    AssessmentConfig, ErgonomicsError, FrameAssessment, HeightConfig, HeightDecision,
    HeightEstimator, HeightStatus, RulaAssessor, UpVector, WarningConfig, WarningEvent,
    WarningTracker,
};
use ergocell_perception::temporal::{FrameAssembler, OneEuroFilter, OneEuroParams};
use ergocell_perception::{
    CameraRig, Frame2, FusedFrame, FusionEngine, FusionMethod, PerceptionError, View2,
};
use ergocell_skeleton::Skeleton3;

use crate::CellError;

/// Everything the pipeline is tuned by. Times in integer nanoseconds.
#[derive(Debug, Clone, PartialEq)]
pub struct PipelineConfig {
    /// Which fusion (default: ergocell's robust N-view fusion with the bone prior).
    pub fusion: FusionMethod,
    /// The causal One-Euro filter; `None` = no filter (a landmarks file that was filtered already).
    pub filter: Option<OneEuroParams>,
    /// A fused skeleton with fewer landmarks than this is not "the operator tracked": it is not
    /// filtered, assessed or measured (default 20 of 33).
    pub min_tracked_landmarks: usize,
    /// Frame assembly: stamps this close are one instant (default 15 ms).
    pub assembly_tolerance_nanos: i64,
    /// Frame assembly: how long a frame waits for missing cameras (default 40 ms).
    pub assembly_max_wait_nanos: i64,
    /// RULA (its `up` is the world's vertical).
    pub assessment: AssessmentConfig,
    pub warnings: WarningConfig,
    /// The height estimator (its `up` is the world's vertical).
    pub height: HeightConfig,
}

impl PipelineConfig {
    /// Every default, on a world whose vertical is `up`.
    pub fn new(up: UpVector) -> Self {
        Self {
            fusion: FusionMethod::Default,
            filter: Some(OneEuroParams::default()),
            min_tracked_landmarks: 20,
            assembly_tolerance_nanos: 15_000_000,
            assembly_max_wait_nanos: 40_000_000,
            assessment: AssessmentConfig::new(up),
            warnings: WarningConfig::default(),
            height: HeightConfig::new(up),
        }
    }

    /// The defaults of the up-independent fields (for the config file's defaults).
    pub(crate) fn defaults_without_up() -> Self {
        Self::new(UpVector::z())
    }
}

/// What the pipeline made of one frame.
#[derive(Debug, Clone, PartialEq)]
pub struct FrameOutput {
    /// The frame's stamp (its first view's capture time).
    pub stamp_nanos: i64,
    /// The fused skeleton, unfiltered, with the fusion's counts.
    pub fused: FusedFrame,
    /// `None` when the operator is not tracked in this frame (too few landmarks).
    pub tracked: Option<TrackedFrame>,
}

/// The rest of the pipeline for a frame in which the operator is tracked.
#[derive(Debug, Clone, PartialEq)]
pub struct TrackedFrame {
    /// The filtered skeleton (the fused one when no filter is configured).
    pub skeleton: Skeleton3,
    /// RULA of both sides; `Err` when the frame could not be assessed (e.g. time went backwards).
    pub assessment: Result<FrameAssessment, ErgonomicsError>,
    /// Posture warnings raised, changed or cleared by this frame.
    pub warnings: Vec<WarningEvent>,
    /// The height decision, in the one frame that made it.
    pub height: Option<HeightDecision>,
}

impl TrackedFrame {
    /// Warnings of this frame that were raised (not changed or cleared).
    pub fn raised(&self) -> impl Iterator<Item = &WarningEvent> {
        self.warnings
            .iter()
            .filter(|w| w.kind == WarningKind::Raised)
    }
}

/// The per-frame pipeline (see the module docs). One per operator session: its filter, smoother,
/// warnings, bone prior and height estimator carry state from frame to frame.
#[derive(Debug)]
pub struct Pipeline {
    config: PipelineConfig,
    assembler: FrameAssembler,
    fusion: FusionEngine,
    filter: Option<OneEuroFilter>,
    assessor: RulaAssessor,
    warnings: WarningTracker,
    height: HeightEstimator,
    height_decided: bool,
}

impl Pipeline {
    /// A pipeline on `rig`.
    pub fn new(rig: CameraRig, config: PipelineConfig) -> Result<Self, CellError> {
        let assembler = FrameAssembler::new(
            rig.len(),
            config.assembly_tolerance_nanos,
            config.assembly_max_wait_nanos,
        );
        let fusion = FusionEngine::new(rig, config.fusion)?;
        let assessor = RulaAssessor::new(config.assessment)?;
        Ok(Self {
            assembler,
            fusion,
            filter: config.filter.map(OneEuroFilter::new),
            assessor,
            warnings: WarningTracker::new(config.warnings),
            height: HeightEstimator::new(config.height),
            height_decided: false,
            config,
        })
    }

    /// A pipeline with every default on `rig`, whose `up` must be known (RULA and height need the
    /// world's vertical).
    pub fn with_defaults(rig: CameraRig) -> Result<Self, CellError> {
        let up = rig_up(&rig)?;
        Self::new(rig, PipelineConfig::new(up))
    }

    pub fn config(&self) -> &PipelineConfig {
        &self.config
    }

    /// The rig the fusion runs on.
    pub fn rig(&self) -> &CameraRig {
        self.fusion.rig()
    }

    /// Views that arrived by `now_nanos`: every frame they complete (or whose wait expired) is run
    /// through the pipeline, in time order. A frame the fusion refuses is an `Err` in its place.
    pub fn push_views(
        &mut self,
        now_nanos: i64,
        views: Vec<View2>,
    ) -> Vec<Result<FrameOutput, PerceptionError>> {
        let mut frames = Vec::new();
        for view in views {
            frames.extend(self.assembler.push(view, now_nanos));
        }
        frames.extend(self.assembler.poll(now_nanos));
        frames.iter().map(|f| self.process_frame(f)).collect()
    }

    /// Releases the frames still waiting for cameras (end of a stream) and runs them.
    pub fn flush(&mut self) -> Vec<Result<FrameOutput, PerceptionError>> {
        let frames = self.assembler.flush();
        frames.iter().map(|f| self.process_frame(f)).collect()
    }

    /// One time-aligned frame.
    pub fn process_frame(&mut self, frame: &Frame2) -> Result<FrameOutput, PerceptionError> {
        let fused = self.fusion.fuse(frame)?;
        Ok(self.after_fusion(frame.stamp_nanos, fused))
    }

    /// A skeleton fused elsewhere (a 3D landmarks file): the rest of the pipeline.
    pub fn process_fused(&mut self, skeleton: Skeleton3) -> FrameOutput {
        let stamp_nanos = skeleton.stamp_nanos;
        let fused = FusedFrame {
            skeleton,
            rejected_views: 0,
            undistortion_failures: 0,
            cameras_present: 0,
        };
        self.after_fusion(stamp_nanos, fused)
    }

    fn after_fusion(&mut self, stamp_nanos: i64, fused: FusedFrame) -> FrameOutput {
        let tracked = (fused.skeleton.observed_count() >= self.config.min_tracked_landmarks)
            .then(|| self.tracked(&fused.skeleton));
        FrameOutput {
            stamp_nanos,
            fused,
            tracked,
        }
    }

    fn tracked(&mut self, raw: &Skeleton3) -> TrackedFrame {
        let height = if self.height_decided {
            None
        } else {
            let d = self.height.push(raw);
            self.height_decided = d.is_some();
            d
        };
        let skeleton = match self.filter.as_mut() {
            Some(f) => f.filter(raw),
            None => raw.clone(),
        };
        let assessment = self.assessor.assess(&skeleton);
        let warnings = match &assessment {
            Ok(a) => self.warnings.update(a),
            Err(_) => Vec::new(),
        };
        TrackedFrame {
            skeleton,
            assessment,
            warnings,
            height,
        }
    }

    /// Where the height measurement stands (decided, or still measuring and why).
    pub fn height_status(&self) -> HeightStatus {
        self.height.status()
    }

    /// Views that arrived after their frame was released (dropped).
    pub fn late_views(&self) -> usize {
        self.assembler.late_views()
    }
}

/// The rig's up vector, required by RULA and the height.
pub fn rig_up(rig: &CameraRig) -> Result<UpVector, CellError> {
    let up = rig.up().ok_or_else(|| {
        CellError::Rig(
            "the rig has no `up` vector: RULA and height need the world's vertical".to_owned(),
        )
    })?;
    Ok(UpVector::new(up)?)
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used, clippy::expect_used)]
    use super::*;
    use ergocell_perception::rig_file::parse_rig;

    fn rig() -> CameraRig {
        parse_rig(include_str!("../../config/rig.toml"), "config/rig.toml")
            .unwrap()
            .0
    }

    #[test]
    fn too_few_landmarks_is_not_tracked_and_feeds_nothing() {
        let mut p = Pipeline::with_defaults(rig()).unwrap();
        let empty = (0..p.rig().len())
            .map(|k| View2::empty(k, 1_000))
            .collect::<Vec<_>>();
        let out = p.push_views(1_000, empty);
        assert_eq!(
            out.len(),
            1,
            "all six cameras reported: the frame is complete"
        );
        let out = out.into_iter().next().unwrap().unwrap();
        assert!(out.tracked.is_none());
        assert!(matches!(
            p.height_status(),
            HeightStatus::Measuring { frames_seen: 0, .. }
        ));
    }

    #[test]
    fn a_rig_without_up_cannot_carry_ergonomics() {
        let text = include_str!("../../config/rig.toml");
        let no_up: String = text
            .lines()
            .filter(|l| !l.trim_start().starts_with("up"))
            .collect::<Vec<_>>()
            .join("\n");
        let rig = parse_rig(&no_up, "rig").unwrap().0;
        assert!(rig.up().is_none(), "the test rig must have lost its up");
        let e = Pipeline::with_defaults(rig).unwrap_err();
        assert!(e.to_string().contains("up"), "{e}");
    }
}
