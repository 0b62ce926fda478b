//! `ergocell sim adaptation --record-height <m>`: one operator's handover task recorded before and
//! after the adaptation, as two session recordings (MCAP) for `ergocell report --compare` — the
//! seed paper's Figs. 7–9 for one person, readable by the ergonomics expert.
//!
//! Each recording is the digital twin's operator doing the task seen by the rig's cameras with
//! pose-estimator noise, run through the cell controller's own per-frame pipeline
//! ([`ergocell_cell::Pipeline`], the defaults a session runs: fusion, tracked gate, filter, RULA,
//! warnings); "before" reaches for the unadapted robot's handover point
//! (set for a 1.75 m operator), "after" for the class-specific one. There is no robot motion in the
//! simulator's task, so the recording holds the handover point and no TCP track.

use std::path::{Path, PathBuf};

use crate::messages;
use crate::recording::{self, topics, McapRecorder, RecordingError};
use ergocell_bridge::msg::{Header, SessionState};
use ergocell_cell::{CellError, Pipeline};
use ergocell_ergonomics::height::ClassThresholds;
use ergocell_ergonomics::HeightClass;
use ergocell_sim::experiments::{Handovers, Setup};
use ergocell_sim::{Operator, SessionScript, SimConfig, Simulation};

/// A simulated session could not be recorded.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum SimRecordError {
    #[error(transparent)]
    Recording(#[from] RecordingError),
    #[error("simulator: {0}")]
    Sim(#[from] ergocell_sim::SimError),
    #[error("fusion: {0}")]
    Perception(#[from] ergocell_perception::PerceptionError),
    #[error("ergonomics: {0}")]
    Ergonomics(#[from] ergocell_ergonomics::ErgonomicsError),
    #[error("pipeline: {0}")]
    Cell(#[from] CellError),
    /// After adaptation the cell does not serve this operator (the session ends without moving the
    /// robot), so there is no task to record.
    #[error("a {stature_m:.2} m operator is outside the statures {min_m:.2}–{max_m:.2} m class {class}'s trajectory is served for: after adaptation the cell does not serve them (the session ends without moving the robot), so there is no \"after\" task to record")]
    NotServed {
        stature_m: f64,
        class: &'static str,
        min_m: f64,
        max_m: f64,
    },
}

/// Which handover point the operator reaches for.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Condition {
    Before,
    After,
}

impl Condition {
    pub fn name(self) -> &'static str {
        match self {
            Condition::Before => "before",
            Condition::After => "after",
        }
    }
}

/// Records both conditions for an operator of `stature_m`; returns the two paths.
pub fn record_both(
    setup: &Setup,
    handovers: &Handovers,
    stature_m: f64,
    cycles: usize,
    out_dir: &Path,
) -> Result<[PathBuf; 2], SimRecordError> {
    let path = |c: Condition| out_dir.join(format!("adaptation_{stature_m:.2}m_{}.mcap", c.name()));
    let paths = [path(Condition::Before), path(Condition::After)];
    // Refuse before writing anything when "after" cannot exist.
    check_served(handovers, stature_m)?;
    record(
        setup,
        handovers,
        stature_m,
        cycles,
        Condition::Before,
        &paths[0],
    )?;
    record(
        setup,
        handovers,
        stature_m,
        cycles,
        Condition::After,
        &paths[1],
    )?;
    Ok(paths)
}

fn check_served(handovers: &Handovers, stature_m: f64) -> Result<(), SimRecordError> {
    let class = HeightClass::of(stature_m, &ClassThresholds::default());
    // The session's rule, for a stature known exactly (the interval is the point).
    let [min_m, max_m] = handovers.served_m(class);
    if handovers.serves(class, [stature_m, stature_m]) {
        Ok(())
    } else {
        Err(SimRecordError::NotServed {
            stature_m,
            class: class.name(),
            min_m,
            max_m,
        })
    }
}

/// Records one condition into `path`.
pub fn record(
    setup: &Setup,
    handovers: &Handovers,
    stature_m: f64,
    cycles: usize,
    condition: Condition,
    path: &Path,
) -> Result<(), SimRecordError> {
    let class = HeightClass::of(stature_m, &ClassThresholds::default());
    if condition == Condition::After {
        check_served(handovers, stature_m)?;
    }
    let (handover, what) = match condition {
        Condition::Before => (
            handovers.before_m,
            "the unadapted robot's handover point (set for a 1.75 m operator)".to_owned(),
        ),
        Condition::After => (
            handovers.for_class(class),
            format!(
                "the class-specific handover point of class {}",
                class.name()
            ),
        ),
    };
    let mut script = SessionScript::new(handover);
    script.cycles = cycles;
    let config = SimConfig {
        noise: setup.noise,
        ..SimConfig::new(setup.seed)
    };
    let sim = Simulation::new(setup.rig.clone(), Operator::new(stature_m)?, script, config)?;
    let mut pipeline = Pipeline::with_defaults(setup.rig.clone())?;
    let mut rec = McapRecorder::create(path)?;
    let mut first = true;
    for tick in sim {
        let tick = tick?;
        let now = tick.truth.stamp_nanos;
        if first {
            first = false;
            let state = SessionState {
                header: Header::new(now, "world"),
                state: "simulated".to_owned(),
                reason: format!(
                    "digital twin, seed {}: a {stature_m:.2} m operator ({}) reaching for {what}, {cycles} cycles; {}",
                    setup.seed,
                    class.name(),
                    condition.name()
                ),
                height_m: stature_m,
                // The true stature (the simulator knows it), not a measurement: no uncertainty.
                height_uncertainty_m: f64::NAN,
                height_class: class.name().to_owned(),
                // The class is the truth's, not a decision: no basis, probability or cost.
                height_class_probability: f64::NAN,
                height_expected_rula_cost: f64::NAN,
                last_part_closest_m: f64::NAN,
                ..SessionState::default()
            };
            rec.write(topics::SESSION_STATE, now, &state)?;
        }
        for output in pipeline.push_views(now, tick.frame.views) {
            for tracked in output?.tracked {
                let assessment = tracked.assessment?;
                // The messages a session sends for a frame and its warnings, recorded alike.
                let mut out = messages::frame_messages(&tracked.skeleton, Some(&assessment));
                out.extend(
                    tracked
                        .warnings
                        .iter()
                        .map(|w| messages::Outgoing::Warning(messages::warning_message(w))),
                );
                recording::record(&mut rec, now, &out)?;
            }
        }
        rec.write(
            topics::ROBOT_MARKERS,
            now,
            &messages::robot_markers_message(now, None, Some(handover)),
        )?;
    }
    rec.finish()?;
    Ok(())
}
