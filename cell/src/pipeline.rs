//! The per-frame pipeline: camera views in; fused skeleton, filtered skeleton, RULA, warnings and
//! the height decision out. It is wired here and only here.
//!
//! ```text
//! views ─► FrameAssembler ─► FusionEngine ─► tracked? ─► FixedLagSmoother ─► RulaAssessor ─► WarningTracker
//!          (time-aligns)     (default|paper)  (gate)  │   (default; or the   │
//!                                                     │   causal One-Euro)   │
//!                                                     └─► HeightEstimator (unfiltered, until decided), the operator at once
//! ```
//!
//! The session state machine owns one [`Pipeline`]; the digital twin's experiments, the demo and
//! `ergocell run` run the same type with the same defaults ([`PipelineConfig::new`], or the cell
//! file's `[pipeline]`, `[assessment]`, `[task]`, `[warnings]` and `[height]`), so a figure measured
//! on the twin is a figure of the controller that ships. The offline commands run its stages:
//! `ergocell triangulate` the [`Reconstruction`] (without the tracked gate, the filter only when
//! asked), `ergocell rula track` the [`Assessment`], `ergocell height` the height estimator.
//!
//! Two named stages, composed once in [`Pipeline`]:
//! - [`Reconstruction`]: assembly → fusion → tracked gate → filter, each camera's learnt image
//!   offset taken out of its views before fusion ([`ergocell_perception::view_offset`]).
//!   `ergocell triangulate` runs it alone (an imported calibration may not know the world's
//!   vertical);
//! - [`Assessment`]: RULA → warnings, and the height. `ergocell rula track` runs it alone on a 3D
//!   landmarks file.
//!
//! [`Pipeline::push_views`] takes views as they arrive (the session, the experiments);
//! [`Pipeline::process_frame`] a frame already time-aligned.
//!
//! The height is measured on the **unfiltered** fused skeleton (the filter's lag would bias a
//! stature measured while the operator walks in) and only until the first decision, which is final:
//! the class is decided once per session. RULA runs on the filtered skeleton of every tracked frame.
//!
//! With a fixed lag ([`PipelineConfig::fixed_lag_s`], the default) the causal filter is off and RULA runs on
//! each tracked frame's mean over the frames up to the half window before and after it
//! ([`ergocell_perception::fixed_lag`]): every score and warning comes out that much later, each [`TrackedFrame`] with its own (earlier) stamp. The operator's presence, hands
//! and height ([`FrameOutput::operator`], [`FrameOutput::height`]) come at once, so nothing the robot
//! waits for is delayed. Frames are released on the clock ([`Pipeline::release_due`], which the
//! session calls every step): a frame is scored once the clock is past its stamp by the half
//! window (and no sooner than the half window less 0.1 s after it arrived), on the frames that
//! have arrived, so what the cameras' transport delays is left out of its window, up to 0.1 s of
//! it, rather than waited for. A session that ends sooner leaves the last half window of frames
//! unscored.

use ergocell_ergonomics::{
    AssessmentConfig, ErgonomicsError, FrameAssessment, HeightConfig, HeightDecision,
    HeightEstimator, HeightStatus, RulaAssessor, UpVector, WarningConfig, WarningEvent,
    WarningTracker,
};
use ergocell_perception::camera_health::{
    CameraResidualMonitor, OutOfCalibration, ResidualMonitorConfig,
};
use ergocell_perception::fixed_lag::FixedLagSmoother;
use ergocell_perception::operator_gate::{other_person_views, torso_of};
use ergocell_perception::temporal::{FrameAssembler, OneEuroFilter, OneEuroParams};
use ergocell_perception::view_offset::{ViewOffsetConfig, ViewOffsets};
use ergocell_perception::{
    CameraRig, Frame2, FusedFrame, FusionEngine, FusionMethod, PerceptionError, View2,
};
use ergocell_skeleton::Skeleton3;

use crate::CellError;

/// The reconstruction stage's tunables: pixels to a tracked, filtered skeleton. Times in integer
/// nanoseconds.
#[derive(Debug, Clone, PartialEq)]
pub struct ReconstructionConfig {
    /// Which fusion (default: ergocell's robust N-view fusion with the bone prior).
    pub fusion: FusionMethod,
    /// The causal One-Euro filter; `None` = no filter.
    pub filter: Option<OneEuroParams>,
    /// A fused skeleton with fewer landmarks than this is not "the operator tracked": it is not
    /// filtered, assessed or measured (default 20 of 33).
    pub min_tracked_landmarks: usize,
    /// Frame assembly: stamps this close are one instant (default 15 ms).
    pub assembly_tolerance_nanos: i64,
    /// Frame assembly: how long a frame waits for missing cameras (default 40 ms).
    pub assembly_max_wait_nanos: i64,
    /// Finding cameras knocked out of calibration by their reprojection residuals, which are then
    /// left out of fusion (default on, [`ResidualMonitorConfig::default`]); `None` = never.
    pub residual_monitor: Option<ResidualMonitorConfig>,
    /// Learning each camera's persistent image offset from the fused skeleton and taking it out of
    /// its views before fusion (default on, [`ViewOffsetConfig::default`]; default fusion only):
    /// [`ergocell_perception::view_offset`]. `None` = views fused as delivered.
    pub view_offsets: Option<ViewOffsetConfig>,
    /// Leaving out the views of someone other than the operator (a single-person detector per
    /// camera, two people in the cell): [`OperatorZone`]. `None` (the default) = every view is
    /// the operator's; the session sets it from the station.
    pub operator_zone: Option<OperatorZone>,
}

/// Where the operator is expected, for [`ergocell_perception::operator_gate`]: a view whose torso
/// ray passes farther than `radius_m` from the operator's last tracked torso (within `memory_nanos`)
/// or, with none, from the station's torso point, shows someone else and is left out of fusion.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct OperatorZone {
    /// The torso of an operator standing at the station, world frame.
    pub station_torso_world: nalgebra::Point3<f64>,
    pub radius_m: f64,
    pub memory_nanos: i64,
}

impl Default for ReconstructionConfig {
    fn default() -> Self {
        Self {
            fusion: FusionMethod::Default,
            filter: Some(OneEuroParams::default()),
            min_tracked_landmarks: 20,
            assembly_tolerance_nanos: 15_000_000,
            assembly_max_wait_nanos: 40_000_000,
            residual_monitor: Some(ResidualMonitorConfig::default()),
            view_offsets: Some(ViewOffsetConfig::default()),
            operator_zone: None,
        }
    }
}

/// Everything the pipeline is tuned by.
#[derive(Debug, Clone, PartialEq)]
pub struct PipelineConfig {
    pub reconstruction: ReconstructionConfig,
    /// RULA (its `up` is the world's vertical).
    pub assessment: AssessmentConfig,
    pub warnings: WarningConfig,
    /// The height estimator (its `up` is the world's vertical).
    pub height: HeightConfig,
    /// Score each tracked frame on the mean over ± this many seconds of it in place of the causal
    /// filter (a fixed-lag smoother; the reconstruction's filter is then not run), at a latency of
    /// the half window (default [`DEFAULT_FIXED_LAG_S`]). `None`: the causal filter, no latency.
    pub fixed_lag_s: Option<f64>,
}

impl PipelineConfig {
    /// Every default, on a world whose vertical is `up`.
    pub fn new(up: UpVector) -> Self {
        Self {
            reconstruction: ReconstructionConfig::default(),
            assessment: AssessmentConfig::new(up),
            warnings: WarningConfig::default(),
            height: HeightConfig::new(up),
            fixed_lag_s: Some(DEFAULT_FIXED_LAG_S),
        }
    }
}

/// The default half window of the fixed-lag smoother, seconds: chosen on the digital twin's tuning
/// seeds under the detector fitted to real MediaPipe data (five frames either side at 10 Hz, with
/// room for the cameras' capture-time jitter). RULA's grand score then agrees with the true
/// posture at κ 0.88 instead of the causal filter's 0.77 (`docs/sim`); every score and warning
/// comes 0.55 s later, nothing the robot waits for does.
pub const DEFAULT_FIXED_LAG_S: f64 = 0.55;

/// What the pipeline made of one frame.
#[derive(Debug, Clone, PartialEq)]
pub struct FrameOutput {
    /// The frame's stamp (its first view's capture time).
    pub stamp_nanos: i64,
    /// The fused skeleton, unfiltered, with the fusion's counts.
    pub fused: FusedFrame,
    /// The operator in this frame, when tracked (enough landmarks): the filtered skeleton (with a
    /// fixed lag, the fused one as it is). What the session follows the operator by — present or
    /// not, where the hands are — at once, whatever the lag.
    pub operator: Option<Skeleton3>,
    /// The height decision, in the one frame that made it.
    pub height: Option<HeightDecision>,
    /// The tracked frames scored by this frame (RULA, warnings), in time order: this frame itself
    /// when the operator is tracked in it; with a fixed lag, the earlier frames whose window it
    /// closed (zero, one, or after a gap several), each at its own stamp.
    pub tracked: Vec<TrackedFrame>,
    /// A camera this frame found out of calibration (left out of fusion from the next frame on).
    pub out_of_calibration: Option<OutOfCalibration>,
}

/// A tracked frame scored: the skeleton RULA saw, its assessment and the warnings it moved.
#[derive(Debug, Clone, PartialEq)]
pub struct TrackedFrame {
    /// The filtered skeleton (the fused one when no filter is configured; with a fixed lag, the
    /// smoothed one), at its own stamp.
    pub skeleton: Skeleton3,
    /// RULA of both sides; `Err` when the frame could not be assessed (e.g. time went backwards).
    pub assessment: Result<FrameAssessment, ErgonomicsError>,
    /// Posture warnings raised, changed or cleared by this frame.
    pub warnings: Vec<WarningEvent>,
}

/// What the reconstruction stage made of one frame.
#[derive(Debug, Clone, PartialEq)]
pub struct Reconstructed {
    /// The frame's stamp (its first view's capture time).
    pub stamp_nanos: i64,
    /// The fused skeleton, unfiltered, with the fusion's counts.
    pub fused: FusedFrame,
    /// The filtered skeleton when the operator is tracked (enough landmarks), else `None`.
    pub tracked: Option<Skeleton3>,
    /// A camera this frame found out of calibration (left out of fusion from the next frame on).
    pub out_of_calibration: Option<OutOfCalibration>,
}

/// The first stage: views → time-aligned frame → fused skeleton → tracked gate → causal filter.
/// `ergocell triangulate` runs this stage alone (no world vertical needed); [`Pipeline`] runs it
/// first.
#[derive(Debug)]
pub struct Reconstruction {
    config: ReconstructionConfig,
    assembler: FrameAssembler,
    fusion: FusionEngine,
    filter: Option<OneEuroFilter>,
    monitor: Option<CameraResidualMonitor>,
    offsets: Option<ViewOffsets>,
    /// The frame without the cameras found out of calibration or showing someone else (reused).
    kept: Frame2,
    /// The operator's last tracked torso (stamp, world point), for the [`OperatorZone`].
    last_torso: Option<(i64, nalgebra::Point3<f64>)>,
}

impl Reconstruction {
    pub fn new(rig: CameraRig, config: ReconstructionConfig) -> Result<Self, CellError> {
        let assembler = FrameAssembler::new(
            rig.len(),
            config.assembly_tolerance_nanos,
            config.assembly_max_wait_nanos,
        );
        Ok(Self {
            assembler,
            monitor: config
                .residual_monitor
                .map(|c| CameraResidualMonitor::new(rig.len(), c)),
            offsets: config
                .view_offsets
                .filter(|_| config.fusion == FusionMethod::Default)
                .map(|c| ViewOffsets::new(rig.len(), c)),
            fusion: FusionEngine::new(rig, config.fusion)?,
            filter: config.filter.map(OneEuroFilter::new),
            kept: Frame2 {
                stamp_nanos: 0,
                views: Vec::new(),
            },
            last_torso: None,
            config,
        })
    }

    pub fn config(&self) -> &ReconstructionConfig {
        &self.config
    }

    /// The rig the fusion runs on.
    pub fn rig(&self) -> &CameraRig {
        self.fusion.rig()
    }

    /// The image offset (pixels) currently taken out of camera `k`'s views, when the views'
    /// offsets are learnt ([`ReconstructionConfig::view_offsets`]).
    pub fn view_offset(&self, k: usize) -> Option<nalgebra::Vector2<f64>> {
        self.offsets.as_ref().and_then(|o| o.offset(k))
    }

    /// Views that arrived by `now_nanos` → the frames they complete (or whose wait expired), in
    /// time order.
    pub fn push_views(&mut self, now_nanos: i64, views: Vec<View2>) -> Vec<Frame2> {
        let mut frames = Vec::new();
        for view in views {
            frames.extend(self.assembler.push(view, now_nanos));
        }
        frames.extend(self.assembler.poll(now_nanos));
        frames
    }

    /// One time-aligned frame: fused, gated, filtered.
    /// Cameras found out of calibration are left out of the fusion; every camera's views are still
    /// compared with the fused skeleton.
    pub fn process_frame(&mut self, frame: &Frame2) -> Result<Reconstructed, PerceptionError> {
        let other_person_views = match self.config.operator_zone {
            Some(zone) => {
                let (reference, tracking) = match self.last_torso {
                    Some((t, p)) if frame.stamp_nanos - t <= zone.memory_nanos => (p, true),
                    _ => (zone.station_torso_world, false),
                };
                other_person_views(
                    self.fusion.rig(),
                    frame,
                    &reference,
                    zone.radius_m,
                    !tracking,
                )
            }
            None => 0,
        };
        let monitor = self.monitor.as_ref();
        let flagged = monitor.map_or(0u64, |m| {
            m.flagged()
                .filter(|k| *k < 64)
                .fold(0, |mask, k| mask | (1 << k))
        });
        let left_out = flagged | other_person_views;
        let fused = if left_out != 0 || self.offsets.is_some() {
            self.kept.stamp_nanos = frame.stamp_nanos;
            self.kept.views.clear();
            let offsets = self.offsets.as_ref();
            self.kept.views.extend(
                frame
                    .views
                    .iter()
                    .filter(|v| v.camera >= 64 || left_out & (1 << v.camera) == 0)
                    .map(|v| offsets.map_or_else(|| v.clone(), |o| o.correct(v))),
            );
            self.fusion.fuse(&self.kept)?
        } else {
            self.fusion.fuse(frame)?
        };
        let out_of_calibration = self
            .monitor
            .as_mut()
            .and_then(|m| m.observe_frame(self.fusion.rig(), frame, &fused.skeleton));
        let tracked =
            (fused.skeleton.observed_count() >= self.config.min_tracked_landmarks).then(|| {
                match self.filter.as_mut() {
                    Some(f) => f.filter(&fused.skeleton),
                    None => fused.skeleton.clone(),
                }
            });
        if tracked.is_some() {
            if let Some(offsets) = self.offsets.as_mut() {
                offsets.observe(
                    self.fusion.rig(),
                    &self.kept,
                    &fused.skeleton,
                    fused.swapped_views,
                    0,
                );
            }
            if let Some(torso) = torso_of(&fused.skeleton) {
                self.last_torso = Some((frame.stamp_nanos, torso));
            }
        }
        Ok(Reconstructed {
            stamp_nanos: frame.stamp_nanos,
            fused,
            tracked,
            out_of_calibration,
        })
    }
}

/// The second stage: a tracked frame's RULA, warnings and the height. `ergocell rula track` runs
/// this stage alone on a 3D landmarks file; [`Pipeline`] runs it on every tracked frame.
#[derive(Debug)]
pub struct Assessment {
    assessor: RulaAssessor,
    warnings: WarningTracker,
    height: HeightEstimator,
    height_decided: bool,
    /// Tracked frames not measured because the person stood away from the station.
    away_from_station: usize,
}

impl Assessment {
    /// The stage with `config`'s assessment, warnings and height (its reconstruction part unused).
    pub fn new(config: &PipelineConfig) -> Result<Self, CellError> {
        Ok(Self {
            assessor: RulaAssessor::new(config.assessment)?,
            warnings: WarningTracker::new(config.warnings),
            height: HeightEstimator::new(config.height.clone()),
            height_decided: false,
            away_from_station: 0,
        })
    }

    /// The height measured on a tracked frame's unfiltered skeleton, until the first decision (the
    /// frame counted as away from the station unless `measure_height`).
    pub fn measure_height(
        &mut self,
        raw: &Skeleton3,
        measure_height: bool,
    ) -> Option<HeightDecision> {
        if !self.height_decided && !measure_height {
            self.away_from_station += 1;
        }
        if self.height_decided || !measure_height {
            None
        } else {
            let d = self.height.push(raw);
            self.height_decided = d.is_some();
            d
        }
    }

    /// RULA and the warnings of a tracked frame's (filtered or smoothed) skeleton.
    pub fn score(&mut self, filtered: Skeleton3) -> TrackedFrame {
        let assessment = self.assessor.assess(&filtered);
        let warnings = match &assessment {
            Ok(a) => self.warnings.update(a),
            Err(_) => Vec::new(),
        };
        TrackedFrame {
            skeleton: filtered,
            assessment,
            warnings,
        }
    }

    /// Where the height measurement stands (decided, or still measuring and why — including the
    /// tracked frames left unmeasured because the person stood away from the station).
    pub fn height_status(&self) -> HeightStatus {
        match self.height.status() {
            HeightStatus::Measuring {
                frames_seen,
                upright_frames,
                estimate,
                why,
            } if self.away_from_station > 0 => HeightStatus::Measuring {
                frames_seen,
                upright_frames,
                estimate,
                why: format!(
                    "{why}; {} tracked frame(s) not measured: the person stood away from the station",
                    self.away_from_station
                ),
            },
            status => status,
        }
    }
}

/// The per-frame pipeline (see the module docs): [`Reconstruction`] then [`Assessment`] on every
/// tracked frame. One per operator session: its filter, smoother, warnings, bone prior and height
/// estimator carry state from frame to frame.
#[derive(Debug)]
pub struct Pipeline {
    config: PipelineConfig,
    reconstruction: Reconstruction,
    assessment: Assessment,
    /// The fixed-lag smoother, when configured.
    lag: Option<FixedLagSmoother>,
    /// When the frames being processed arrived (the clock of [`Pipeline::push_views`]); `None`:
    /// at their own stamps (a frame handed to [`Pipeline::process_frame`] directly).
    arrival_nanos: Option<i64>,
}

impl Pipeline {
    /// A pipeline on `rig`.
    /// With [`PipelineConfig::fixed_lag_s`] the reconstruction runs without its causal filter.
    pub fn new(rig: CameraRig, config: PipelineConfig) -> Result<Self, CellError> {
        let lag = config
            .fixed_lag_s
            .map(FixedLagSmoother::new)
            .transpose()
            .map_err(|e| CellError::Config {
                file: "pipeline".to_owned(),
                reason: format!("fixed_lag_s: {e}"),
            })?;
        let mut reconstruction = config.reconstruction.clone();
        if lag.is_some() {
            reconstruction.filter = None;
        }
        Ok(Self {
            reconstruction: Reconstruction::new(rig, reconstruction)?,
            assessment: Assessment::new(&config)?,
            config,
            lag,
            arrival_nanos: None,
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
        self.reconstruction.rig()
    }

    /// Views that arrived by `now_nanos`: every frame they complete (or whose wait expired) is run
    /// through the pipeline, in time order. A frame the fusion refuses is an `Err` in its place.
    pub fn push_views(
        &mut self,
        now_nanos: i64,
        views: Vec<View2>,
    ) -> Vec<Result<FrameOutput, PerceptionError>> {
        let frames = self.reconstruction.push_views(now_nanos, views);
        self.arrival_nanos = Some(now_nanos);
        let out = frames.iter().map(|f| self.process_frame(f)).collect();
        self.arrival_nanos = None;
        out
    }

    /// The clock has reached `now_nanos`: with a fixed lag, every frame due is scored now, on the
    /// frames that have arrived: what is still in transit is not waited for, up to
    /// [`ergocell_perception::fixed_lag::MAX_CUT_NANOS`] of it, so the scores and the warnings come
    /// at the designed lag. Without a fixed lag nothing is waiting.
    pub fn release_due(&mut self, now_nanos: i64) -> Vec<TrackedFrame> {
        let Some(lag) = self.lag.as_mut() else {
            return Vec::new();
        };
        lag.release_due(now_nanos)
            .into_iter()
            .map(|smoothed| self.assessment.score(smoothed))
            .collect()
    }

    /// One time-aligned frame through both stages.
    ///
    /// With an operator zone ([`ReconstructionConfig::operator_zone`]) the height is measured only on
    /// frames whose fused torso stands at the station (horizontally within the zone's radius of the
    /// station torso): the class that picks the robot's trajectory is the station's person's. When
    /// the cameras follow someone else — a bystander most cameras see, a ghost of two people's views
    /// — the height stays undecided and the robot does not move, rather than be locked to another
    /// person's class.
    pub fn process_frame(&mut self, frame: &Frame2) -> Result<FrameOutput, PerceptionError> {
        let r = self.reconstruction.process_frame(frame)?;
        let at_station = self.config.reconstruction.operator_zone.is_none_or(|zone| {
            torso_of(&r.fused.skeleton).is_some_and(|torso| {
                let up = self.config.height.up.vector();
                let d = torso - zone.station_torso_world;
                (d - up * d.dot(&up)).norm() <= zone.radius_m
            })
        });
        let height = r.tracked.as_ref().and_then(|_| {
            self.assessment
                .measure_height(&r.fused.skeleton, at_station)
        });
        let operator = r.tracked.clone();
        let tracked = match self.lag.as_mut() {
            None => r
                .tracked
                .map(|filtered| self.assessment.score(filtered))
                .into_iter()
                .collect(),
            Some(lag) => {
                let released = match r.tracked {
                    Some(skeleton) => match self.arrival_nanos {
                        Some(arrived) => lag.push_arrived(skeleton, arrived),
                        None => lag.push(skeleton),
                    },
                    None => lag.advance(r.stamp_nanos),
                };
                released
                    .into_iter()
                    .map(|smoothed| self.assessment.score(smoothed))
                    .collect()
            }
        };
        Ok(FrameOutput {
            stamp_nanos: r.stamp_nanos,
            fused: r.fused,
            operator,
            height,
            tracked,
            out_of_calibration: r.out_of_calibration,
        })
    }

    /// Where the height measurement stands (decided, or still measuring and why).
    pub fn height_status(&self) -> HeightStatus {
        self.assessment.height_status()
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
    use ergocell_formats::rig_file::parse_rig;

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
        assert!(out.tracked.is_empty());
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
