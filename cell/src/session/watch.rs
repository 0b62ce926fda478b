//! The execution watch: the rules around [`ExecutionMonitor`] that every robot backend runs the
//! same way, the ROS 2 backend's monitor task and the digital twin alike.
//!
//! - Each leg sent is watched against the lock's knots, with the path tolerances and limits it was
//!   sent with ([`ExecutionWatch::leg_sent`]); the controller's start ([`ExecutionWatch::leg_started`])
//!   and a hold ([`ExecutionWatch::held`]) move the monitor on.
//! - Every joint state is judged as it arrives ([`ExecutionWatch::sample`]). The first deviation is
//!   the verdict ([`RobotReport::Deviation`]); the backend holds the robot at once through its robot
//!   port, without waiting for the cell loop, and hands the report on. Later samples still move the
//!   monitor on, but no later deviation is reported.
//! - A joint state missing one of the lock's joints is a bad sample, a deviation like any other.
//! - No joint state for longer than the timeout is [`RobotReport::JointStatesStale`] (the session
//!   holds until they are back, [`RobotReport::JointStatesBack`]); after such a gap the rest
//!   reference is taken again from the next sample.

use ergocell_robot::monitor::{Deviation, ExecutionMonitor, MonitorError, MonitorLimits};

use super::robot_side::RobotReport;
use super::LegTrajectory;

/// The execution monitor of one robot, with the rules of when it judges and what it reports.
#[derive(Debug)]
pub struct ExecutionWatch {
    monitor: Option<ExecutionMonitor>,
    /// Joint states older than this are stale, seconds.
    timeout_s: f64,
    tripped: bool,
    stale: bool,
}

impl ExecutionWatch {
    /// A watch whose joint states go stale after `timeout_s`.
    pub fn new(timeout_s: f64) -> Self {
        Self {
            monitor: None,
            timeout_s,
            tripped: false,
            stale: false,
        }
    }

    /// The monitor, once a leg has been sent.
    pub fn monitor(&self) -> Option<&ExecutionMonitor> {
        self.monitor.as_ref()
    }

    /// The joints a sample must name (the lock's order), once a leg has been sent.
    pub fn joints(&self) -> Option<&[String]> {
        self.monitor.as_ref().map(ExecutionMonitor::joints)
    }

    /// Joint states older than this are stale, seconds.
    pub fn timeout_s(&self) -> f64 {
        self.timeout_s
    }

    /// Whether a deviation has been found (the robot was held; nothing more is judged).
    pub fn tripped(&self) -> bool {
        self.tripped
    }

    /// `trajectory` was just sent (labelled `label` in the monitor's words), to be followed within
    /// `path_rad` per joint and `limits`: it is watched from now, the monitor made anew when the
    /// joints or the limits differ from the last leg's.
    pub fn leg_sent(
        &mut self,
        now_nanos: i64,
        label: &str,
        trajectory: &LegTrajectory,
        path_rad: &[f64],
        limits: &MonitorLimits,
    ) -> Result<(), MonitorError> {
        let settings = limits.settings(path_rad.to_vec());
        let fits = self.monitor.as_ref().is_some_and(|m| {
            m.joints() == trajectory.joint_names.as_slice() && *m.settings() == settings
        });
        if !fits {
            self.monitor = Some(ExecutionMonitor::new(
                trajectory.joint_names.clone(),
                settings,
            )?);
        }
        if let Some(m) = self.monitor.as_mut() {
            let p = &trajectory.points;
            m.leg_sent(
                now_nanos,
                label,
                p.iter().map(|k| k.time_from_start_s).collect(),
                p.iter().map(|k| k.positions_rad.clone()).collect(),
                p.iter().map(|k| k.velocities_rad_s.clone()).collect(),
            )?;
        }
        Ok(())
    }

    /// The controller started the sent leg (a topic: when it was published; an action goal: when
    /// it was accepted).
    pub fn leg_started(&mut self, now_nanos: i64) {
        if let Some(m) = self.monitor.as_mut() {
            m.leg_started(now_nanos);
        }
    }

    /// The robot was held: it may stop within the stop time, then must be at rest.
    pub fn held(&mut self, now_nanos: i64) {
        if let Some(m) = self.monitor.as_mut() {
            m.held(now_nanos);
        }
    }

    /// A joint state that arrived at `now_nanos`: `positions` in the order of
    /// [`ExecutionWatch::joints`], `None` when it lacks one of them. The reports, in order: the
    /// joint states back after a stale spell, then the first deviation (the caller holds the robot
    /// at once). Nothing before a leg has been sent.
    pub fn sample(&mut self, now_nanos: i64, positions: Option<&[f64]>) -> Vec<RobotReport> {
        let mut reports = Vec::new();
        let Some(m) = self.monitor.as_mut() else {
            return reports;
        };
        if self.stale {
            m.resync_rest();
            self.stale = false;
            reports.push(RobotReport::JointStatesBack);
        }
        let verdict = match positions {
            Some(p) => m.observe(now_nanos, p),
            None => Err(Deviation::BadSample {
                reason: format!(
                    "a joint state without every joint of the lock ({})",
                    m.joints().join(", ")
                ),
            }),
        };
        if let (Err(deviation), false) = (verdict, self.tripped) {
            self.tripped = true;
            reports.push(RobotReport::Deviation(deviation));
        }
        reports
    }

    /// The clock at `now_nanos`: [`RobotReport::JointStatesStale`] when the joint states have just
    /// gone stale.
    pub fn tick(&mut self, now_nanos: i64) -> Option<RobotReport> {
        let m = self.monitor.as_ref()?;
        m.stale_for_s(now_nanos, self.timeout_s)?;
        if self.stale {
            return None;
        }
        self.stale = true;
        Some(RobotReport::JointStatesStale {
            timeout_s: self.timeout_s,
        })
    }
}
