//! `ergocell sim adaptation --record-height <m>`: one operator's handover task recorded before and
//! after the adaptation, as two session recordings (MCAP) for `ergocell report --compare` — the
//! seed paper's Figs. 7–9 for one person, readable by the ergonomics expert.
//!
//! Each recording is the digital twin's operator doing the task seen by the rig's cameras with
//! pose-estimator noise, run through the cell controller's own per-frame pipeline
//! ([`ergocell_cell::Pipeline`], the defaults a session runs: fusion, tracked gate, filter, RULA,
//! warnings); "before" reaches for the unadapted robot's handover point
//! (set for a 1.75 m operator), "after" for the class-specific one. There is no robot motion in the
//! simulator's task, so the recording holds the handover point and no TCP track. The messages are
//! a session's (`ergocell_ros_backend::twin_recording`); this runs the twin and writes them.

use std::path::{Path, PathBuf};

use crate::messages;
use crate::recording::{self, topics, McapRecorder, RecordingError};
use ergocell_cell::{CellError, Pipeline, TrackedFrame};
use ergocell_ergonomics::height::ClassThresholds;
use ergocell_ergonomics::HeightClass;
use ergocell_ros_backend::twin_recording;
use ergocell_sim::experiments::{Handovers, Setup};
use ergocell_sim::{Operator, SessionScript, SimConfig, Simulation};
use nalgebra::Point3;

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
    let conditions = [Condition::Before, Condition::After];
    let paths =
        conditions.map(|c| out_dir.join(format!("adaptation_{stature_m:.2}m_{}.mcap", c.name())));
    // Refuse before writing anything when "after" cannot exist.
    check_served(handovers, stature_m)?;
    for (condition, path) in conditions.into_iter().zip(&paths) {
        record(setup, handovers, stature_m, cycles, condition, path)?;
    }
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

/// The point the operator reaches for under `condition`, and what it is, in words.
fn reach_target(
    handovers: &Handovers,
    class: HeightClass,
    condition: Condition,
) -> (Point3<f64>, String) {
    match condition {
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
    let (handover, what) = reach_target(handovers, class, condition);
    let reason = format!(
        "digital twin, seed {}: a {stature_m:.2} m operator ({}) reaching for {what}, {cycles} cycles; {}",
        setup.seed,
        class.name(),
        condition.name()
    );
    let mut script = SessionScript::new(handover);
    script.cycles = cycles;
    let config = SimConfig {
        noise: setup.noise,
        ..SimConfig::new(setup.seed)
    };
    let sim = Simulation::new(setup.rig.clone(), Operator::new(stature_m)?, script, config)?;
    let mut pipeline = Pipeline::with_defaults(setup.rig.clone())?;
    let mut rec = McapRecorder::create(path)?;
    let mut opening = Some(reason);
    for tick in sim {
        let tick = tick?;
        let now = tick.truth.stamp_nanos;
        if let Some(reason) = opening.take() {
            let state = twin_recording::simulated_state(now, reason, stature_m, class);
            rec.write(topics::SESSION_STATE, now, &state)?;
        }
        for output in pipeline.push_views(now, tick.frame.views) {
            record_tracked(&mut rec, now, output?.tracked)?;
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

/// The tracked frames a pipeline output scored, each recorded as a session records it.
fn record_tracked(
    rec: &mut McapRecorder,
    now: i64,
    tracked: Vec<TrackedFrame>,
) -> Result<(), SimRecordError> {
    for t in tracked {
        let assessment = t.assessment?;
        let out = twin_recording::tracked_messages(&t.skeleton, &assessment, &t.warnings);
        recording::record(rec, now, &out)?;
    }
    Ok(())
}
