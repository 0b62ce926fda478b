//! What `run` and `demo` say on their consoles, as text: `run`'s start line, each session's
//! summary, the execution monitor's figures and the steps' latency; the demo's event lines, status
//! RULA and summary. The binary prints them; the figures (percentiles of
//! the monitor's and the steps' timings) are computed here.

use std::fmt::Write as _;
use std::time::Duration;

use ergocell_bridge::scope::NetworkScope;
use ergocell_bridge::transport::{RobotInterface, RosConfig};
use ergocell_cell::session::{SessionEvent, SessionMachine};
use ergocell_ergonomics::warnings::WarningKind;
use ergocell_ergonomics::{FrameAssessment, SideAssessment};
use ergocell_robot::TrajectoryClass;

use crate::messages;
use crate::monitor::MonitorStats;
use crate::robot::{radians_list, RosRobot, TrajectoryTopic};

/// The value at quantile `p` (0..=1) of `sorted` (ascending), the nearest rank; NaN when empty.
pub use ergocell_perception::metrics::rank_quantile as percentile;

fn sorted(values: &[f64]) -> Vec<f64> {
    let mut v = values.to_vec();
    v.sort_by(f64::total_cmp);
    v
}

/// Seconds from `start_nanos` to `t_nanos`, as the console says times into a session.
pub fn elapsed_s(t_nanos: i64, start_nanos: i64) -> f64 {
    t_nanos.saturating_sub(start_nanos) as f64 * 1e-9
}

/// The line said when the wall clock steps by `step_nanos` under a session.
pub fn wall_step_line(step_nanos: i64) -> String {
    format!(
        "  wall clock stepped by {:+.3} s: session timing goes on unchanged (monotonic)",
        step_nanos as f64 * 1e-9
    )
}

/// `run`'s first lines: the node, the cameras, the robot's interface with its tolerances, the
/// execution monitor and the driver's state.
pub fn start_text(ros: &RosConfig, cameras: usize, scope: &NetworkScope) -> String {
    let robot = match ros.robot_interface {
        RobotInterface::Topic => format!("{} (topic)", ros.joint_trajectory_topic),
        RobotInterface::Action => format!(
            "{} (FollowJointTrajectory, control_msgs of {}; tolerances from the lock: path at most {} rad, goal {})",
            ros.follow_joint_trajectory_action,
            ros.distro,
            ros.path_tolerance_rad,
            match (ros.goal_tolerance_rad, ros.goal_time_tolerance_s) {
                (None, None) => "as locked".to_owned(),
                (rad, s) => format!(
                    "as locked, at most {} rad and {} s late",
                    rad.map_or("(locked)".to_owned(), |v| v.to_string()),
                    s.map_or("(locked)".to_owned(), |v| v.to_string())
                ),
            }
        ),
    };
    let monitor = if ros.monitor_execution {
        format!(
            "on (every {} sample against the lock; stale after {} s)",
            ros.joint_states_topic, ros.joint_state_timeout_s
        )
    } else {
        "off ([ros] monitor_execution = false)".to_owned()
    };
    let driver = if ros.driver_state {
        format!(
            "{} and {}",
            ros.is_configured_topic, ros.hardware_event_topic
        )
    } else {
        "not read ([ros] driver_state = false)".to_owned()
    };
    format!(
        "ergocell run: node {}/{} on DDS domain {} ({scope}), {cameras} camera topics, robot on {robot}\n\
         execution monitor: {monitor}; driver state: {driver}",
        ros.namespace, ros.node_name, ros.domain_id,
    )
}

/// A session's summary line, and the cameras to recalibrate when there are any.
pub fn session_summary(machine: &SessionMachine, rejected: u64) -> String {
    let s = machine.summary();
    let mut text = format!(
        "session: {} — {} frames fused, {} tracked, class {}, lock {}, {} hold(s), {} robot command(s), {} part(s) taken, {} camera message(s) rejected; {}",
        machine.state(),
        s.frames_fused,
        s.frames_tracked,
        s.class.map_or_else(|| "-".to_owned(), |c| c.to_string()),
        s.lock_sha256.as_deref().unwrap_or("-"),
        s.holds,
        s.robot_commands,
        s.parts_taken,
        rejected,
        s.end_reason
    );
    if !s.cameras_out_of_calibration.is_empty() {
        let _ = write!(
            text,
            "\nrecalibrate: {} (found out of calibration during the session, left out of fusion)",
            s.cameras_out_of_calibration.join(", ")
        );
    }
    text
}

/// The execution monitor's figures at the end: samples judged, the verdict's and the samples'
/// transit times, the largest deviation and the hold's delay; `None` when nothing was monitored.
pub fn monitor_text<T: TrajectoryTopic>(
    robot: &RosRobot<T>,
    stats: &MonitorStats,
) -> Option<String> {
    let monitor = robot.monitor();
    let guard = monitor.lock().ok()?;
    let m = guard.monitor()?;
    let v = sorted(&stats.verdict_us);
    let t = sorted(&stats.transit_us);
    let (ratio, joint) = m.worst_path_ratio();
    Some(format!(
        "execution monitor: {} joint states judged, arrival → verdict p50 {:.1} µs, p99 {:.1} µs, max {:.1} µs; sample stamp → arrival (the controller's clock: a like-for-like figure only for a controller on this host) p50 {:.3} ms, p99 {:.3} ms; largest deviation while moving {:.2} of the path tolerance ({joint}); path tolerances [{}] rad{}",
        v.len(),
        percentile(&v, 0.5),
        percentile(&v, 0.99),
        v.last().copied().unwrap_or(f64::NAN),
        percentile(&t, 0.5) * 1e-3,
        percentile(&t, 0.99) * 1e-3,
        ratio,
        radians_list(&m.settings().path_tolerance_rad),
        robot.held_after_ms().map_or_else(String::new, |ms| format!(
            "; cancelled and held {ms:.3} ms after the bad sample arrived"
        ))
    ))
}

/// `--latency-report`: each step's time from its start (a camera message, or the clock's tick) to
/// the RULA state published.
#[derive(Debug, Default, Clone)]
pub struct StepLatency {
    ms: Vec<f64>,
}

/// The process's CPU use over the run, for [`StepLatency::report`].
#[derive(Debug, Clone, Copy)]
pub struct CpuUse {
    /// User + system CPU seconds used.
    pub cpu_s: f64,
    /// Wall-clock seconds they were used over.
    pub wall_s: f64,
}

impl StepLatency {
    /// One step's latency.
    pub fn push(&mut self, latency: Duration) {
        self.ms.push(latency.as_secs_f64() * 1e3);
    }

    /// Steps timed.
    pub fn len(&self) -> usize {
        self.ms.len()
    }

    /// No step timed.
    pub fn is_empty(&self) -> bool {
        self.ms.is_empty()
    }

    /// The report's line: the count, p50, p99 and the largest, and the CPU used (`None`: not
    /// known on this system).
    pub fn report(&self, cpu: Option<CpuUse>) -> String {
        let ms = sorted(&self.ms);
        format!(
            "latency (step start → RULA state published): n = {}, p50 = {:.3} ms, p99 = {:.3} ms, max = {:.3} ms; CPU {}",
            ms.len(),
            percentile(&ms, 0.5),
            percentile(&ms, 0.99),
            ms.last().copied().unwrap_or(f64::NAN),
            cpu.map_or("n/a".to_owned(), |c| format!(
                "{:.2} s over {:.1} s = {:.1} % of one core",
                c.cpu_s,
                c.wall_s,
                100.0 * c.cpu_s / c.wall_s
            ))
        )
    }
}

/// The demo's summary at the end (each line ending in a newline, the first one empty): the
/// session, the height measured against the operator's `true_stature_m`, the decision against the
/// `true_class`, the trajectory, the frames, RULA, the faults and the robot's commands.
pub fn demo_summary(
    machine: &SessionMachine,
    true_stature_m: f64,
    true_class: TrajectoryClass,
    elapsed_s: f64,
) -> String {
    let s = machine.summary();
    let mut out = String::new();
    let _ = writeln!(out);
    let _ = writeln!(out, "summary");
    let _ = writeln!(
        out,
        "  session:        {} after {elapsed_s:.1} s of simulated time",
        machine.state()
    );
    let _ = writeln!(
        out,
        "  height:         {} (true {true_stature_m:.3} m) → class {}",
        s.height_m.map_or("not measured".to_owned(), |h| format!(
            "{h:.3} ± {:.3} m",
            s.height_uncertainty_m.unwrap_or(f64::NAN)
        )),
        s.class.map_or_else(|| "none".to_owned(), |c| c.to_string())
    );
    if let Some(d) = machine.decision() {
        let _ = writeln!(
            out,
            "  decision:       {} (probability {:.2}{}); true class {true_class}",
            d.basis.name(),
            d.probability,
            messages::rula_cost_clause(d.expected_rula_cost)
        );
    }
    let _ = writeln!(
        out,
        "  trajectory:     {}",
        s.lock_sha256.as_deref().unwrap_or("not locked")
    );
    let _ = writeln!(
        out,
        "  frames:         {} fused, {} with the operator tracked",
        s.frames_fused, s.frames_tracked
    );
    let _ = writeln!(
        out,
        "  RULA:           {} warnings raised, worst action level {}",
        s.warnings_raised, s.max_action_level
    );
    let _ = writeln!(
        out,
        "  faults:         {} camera degradation(s), {} hold(s), {} change request(s) refused",
        s.camera_degradations, s.holds, s.changes_refused
    );
    if !s.cameras_out_of_calibration.is_empty() {
        let _ = writeln!(
            out,
            "  recalibrate:    {} (out of calibration, left out of fusion)",
            s.cameras_out_of_calibration.join(", ")
        );
    }
    let _ = writeln!(
        out,
        "  robot commands: {} ({} part(s) taken at the handover point)",
        s.robot_commands, s.parts_taken
    );
    let _ = writeln!(out, "  ended:          {}", s.end_reason);
    out
}

/// The demo's lines for a step's events, `elapsed_s` into the session: every event as
/// [`messages::describe`] says it, but frames and a warning's changes (its raise and clear are
/// said).
pub fn demo_event_lines(events: &[SessionEvent], elapsed_s: f64) -> Vec<String> {
    events
        .iter()
        .filter(|e| !matches!(e, SessionEvent::Frame { .. }))
        .filter(|e| !matches!(e, SessionEvent::Warning(w) if w.kind == WarningKind::Changed))
        .map(|e| format!("  t={elapsed_s:5.1} s  {}", messages::describe(e)))
        .collect()
}

/// The demo's status line's RULA: both sides' grand scores and the action level of the worse.
pub fn rula_status(a: &FrameAssessment) -> String {
    let score = |side: Option<&SideAssessment>| {
        side.map_or("-".to_owned(), |s| s.scores.final_score.to_string())
    };
    format!(
        "RULA left {} right {} (action level {})",
        score(a.left.as_ref()),
        score(a.right.as_ref()),
        a.headline().map_or(0, |h| h.scores.action_level)
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn percentile_is_the_nearest_rank_and_nan_when_empty() {
        let v = [1.0, 2.0, 3.0, 4.0, 5.0];
        assert_eq!(percentile(&v, 0.0), 1.0);
        assert_eq!(percentile(&v, 0.5), 3.0);
        assert_eq!(percentile(&v, 0.99), 5.0);
        assert_eq!(percentile(&v, 1.0), 5.0);
        // (4 - 1) · 0.5 = 1.5 rounds to rank 2
        assert_eq!(percentile(&[10.0, 20.0, 30.0, 40.0], 0.5), 30.0);
        assert!(percentile(&[], 0.5).is_nan());
    }

    #[test]
    fn the_latency_report_sorts_its_steps_and_states_the_cpu() {
        let mut l = StepLatency::default();
        for ms in [3.0, 1.0, 2.0] {
            l.push(Duration::from_secs_f64(ms * 1e-3));
        }
        assert_eq!(l.len(), 3);
        let cpu = CpuUse {
            cpu_s: 0.5,
            wall_s: 2.0,
        };
        assert_eq!(
            l.report(Some(cpu)),
            "latency (step start → RULA state published): n = 3, p50 = 2.000 ms, p99 = 3.000 ms, \
             max = 3.000 ms; CPU 0.50 s over 2.0 s = 25.0 % of one core"
        );
        assert!(StepLatency::default().report(None).ends_with("; CPU n/a"));
    }
}
