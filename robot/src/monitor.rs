//! Execution monitor: is the robot running the locked trajectory, right now?
//!
//! Every joint-state sample is compared with the leg being executed at that sample's time (the locked
//! knots, cubic Hermite between them with the locked velocities, as the joint trajectory controller
//! interpolates). The controller's own tolerances are the controller's business; this is ergocell's
//! independent check of what the robot does, and the ROS backend's monitor task
//! (`ergocell_ros_backend::monitor`) cancels the goal and holds the robot on the first
//! [`Deviation`]:
//!
//! - a joint farther from the lock than its path tolerance while the leg runs ([`Deviation::Path`]),
//!   diagnosed as [`Deviation::Lagging`] when the robot is on the locked path but behind it in time;
//! - a stall: over the last `stall_window_s` the lock moved and the robot did not ([`Deviation::Stalled`]);
//! - the leg's end not reached within the goal tolerance by `goal_time_tolerance_s` after its end time
//!   ([`Deviation::Goal`]);
//! - motion while the robot should be at rest ([`Deviation::MotionAtRest`]): after a leg has arrived,
//!   and after a hold once the robot has had `stop_time_s` to stop;
//! - a sample that cannot be read (a joint missing, NaN): [`Deviation::BadSample`].
//!
//! Stale samples are the caller's clock's business: [`ExecutionMonitor::stale_for_s`].
//!
//! Path tolerances come from the lock ([`path_tolerances`]): the separation margin the validation
//! found, shared over the joints by their lever arms, so that the joints' errors together cannot move
//! any point of the arm by more than that margin.
//!
//! Pure: the caller passes the time (nanoseconds on its clock) and the positions (in the lock's joint
//! order). Units: radians, seconds.

use std::collections::VecDeque;
use std::fmt;

use nalgebra::Isometry3;

use crate::lock::LockPoint;
use crate::{RobotError, RobotModel};

/// The monitor's limits.
#[derive(Debug, Clone, PartialEq)]
pub struct MonitorSettings {
    /// Per joint: the largest deviation from the lock while a leg runs.
    pub path_tolerance_rad: Vec<f64>,
    /// Every joint: the largest deviation from a leg's last knot once it has arrived.
    pub goal_tolerance_rad: f64,
    /// How long after a leg's end time it may still arrive.
    pub goal_time_tolerance_s: f64,
    /// At rest, the largest motion from where the robot came to rest.
    pub rest_tolerance_rad: f64,
    /// A stall is judged over this window.
    pub stall_window_s: f64,
    /// After a hold, the time the robot has to stop before it must be at rest.
    pub stop_time_s: f64,
}

/// The monitor's limits other than the path tolerance (which the validation derives), decided
/// when a trajectory is locked: the cell file's `[monitor]` table ([`crate::CellConfig::monitor`],
/// covered by the lock's cell hash), copied into the lock ([`crate::lock::LockSummary::monitor`]) and
/// so signed off with the trajectory. At run time the cell may only tighten them
/// ([`MonitorLimits::tightened`]).
///
/// Strict when read: a `[monitor]` table (and a lock's `[summary.monitor]`) names all five limits;
/// only a cell file without the table takes [`MonitorLimits::default`].
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub struct MonitorLimits {
    /// Every joint at a leg's end, and the FollowJointTrajectory goal's goal tolerance.
    pub goal_tolerance_rad: f64,
    /// How late a leg may arrive after its end time (and the goal's goal time tolerance; at least
    /// [`MIN_GOAL_TIME_TOLERANCE_S`], since control_msgs reads 0 as "the controller's default").
    pub goal_time_tolerance_s: f64,
    /// At rest, the largest motion from where the robot came to rest.
    pub rest_tolerance_rad: f64,
    /// A stall is judged over this window.
    pub stall_window_s: f64,
    /// After a hold, the time the robot has to stop before it must be at rest.
    pub stop_time_s: f64,
}

impl Default for MonitorLimits {
    /// 0.01 rad at the goal and at rest, 1 s late at most, stalls over 0.1 s, 0.5 s to stop.
    fn default() -> Self {
        Self {
            goal_tolerance_rad: 0.01,
            goal_time_tolerance_s: 1.0,
            rest_tolerance_rad: 0.01,
            stall_window_s: 0.1,
            stop_time_s: 0.5,
        }
    }
}

/// The limits a cell's run-time settings impose on top of a lock's: each `None` leaves the lock's.
/// The stall window is not among them: a shorter window is not a stricter one (a stall is named
/// only where the lock moved more than the rest tolerance within the window, so a shorter window
/// misses stalls on slow legs); it is the lock's alone.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct MonitorCaps {
    pub goal_tolerance_rad: Option<f64>,
    pub goal_time_tolerance_s: Option<f64>,
    pub rest_tolerance_rad: Option<f64>,
    pub stop_time_s: Option<f64>,
}

/// The largest value any monitor limit may have (radians or seconds).
pub const MONITOR_LIMIT_MAX: f64 = 10.0;

/// The smallest goal time tolerance, seconds: control_msgs' FollowJointTrajectory reads a zero
/// tolerance as "use the action server's default", which kuka_drivers leaves unbounded.
pub const MIN_GOAL_TIME_TOLERANCE_S: f64 = 0.001;

impl MonitorLimits {
    /// The limits by name, with the least each may be and whether that least is allowed.
    fn named(&self) -> [(&'static str, f64, f64, bool); 5] {
        [
            ("goal_tolerance_rad", self.goal_tolerance_rad, 0.0, false),
            (
                "goal_time_tolerance_s",
                self.goal_time_tolerance_s,
                MIN_GOAL_TIME_TOLERANCE_S,
                true,
            ),
            ("rest_tolerance_rad", self.rest_tolerance_rad, 0.0, false),
            ("stall_window_s", self.stall_window_s, 0.0, false),
            ("stop_time_s", self.stop_time_s, 0.0, true),
        ]
    }

    /// Each limit finite and at most [`MONITOR_LIMIT_MAX`]; the tolerances and the stall window
    /// above zero, the goal time tolerance at least [`MIN_GOAL_TIME_TOLERANCE_S`], the stop time
    /// at least zero. The error names the first key that is not.
    pub fn check(&self) -> Result<(), MonitorError> {
        for (key, value, least, least_ok) in self.named() {
            let low_ok = if least_ok {
                value >= least
            } else {
                value > least
            };
            if !(value.is_finite() && low_ok && value <= MONITOR_LIMIT_MAX) {
                return Err(MonitorError::Limit {
                    key,
                    value,
                    least,
                    least_allowed: least_ok,
                    max: MONITOR_LIMIT_MAX,
                });
            }
        }
        Ok(())
    }

    /// These limits with each one `caps` sets lowered to it: a cap never loosens a limit.
    #[must_use]
    pub fn tightened(&self, caps: &MonitorCaps) -> Self {
        let cap = |limit: f64, cap: Option<f64>| cap.map_or(limit, |c| c.min(limit));
        Self {
            goal_tolerance_rad: cap(self.goal_tolerance_rad, caps.goal_tolerance_rad),
            goal_time_tolerance_s: cap(self.goal_time_tolerance_s, caps.goal_time_tolerance_s),
            rest_tolerance_rad: cap(self.rest_tolerance_rad, caps.rest_tolerance_rad),
            stall_window_s: self.stall_window_s,
            stop_time_s: cap(self.stop_time_s, caps.stop_time_s),
        }
    }

    /// The monitor's settings: these limits and the leg's path tolerances.
    pub fn settings(&self, path_tolerance_rad: Vec<f64>) -> MonitorSettings {
        MonitorSettings {
            path_tolerance_rad,
            goal_tolerance_rad: self.goal_tolerance_rad,
            goal_time_tolerance_s: self.goal_time_tolerance_s,
            rest_tolerance_rad: self.rest_tolerance_rad,
            stall_window_s: self.stall_window_s,
            stop_time_s: self.stop_time_s,
        }
    }
}

/// Why the monitor stopped trusting the execution.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum Deviation {
    /// A joint beyond its path tolerance.
    Path {
        leg: String,
        joint: String,
        error_rad: f64,
        tolerance_rad: f64,
        at_s: f64,
    },
    /// On the locked path, but behind it in time by `behind_s` (beyond the path tolerance).
    Lagging {
        leg: String,
        behind_s: f64,
        error_rad: f64,
        at_s: f64,
    },
    /// The lock moved by `locked_moved_rad` over the last `window_s`, the robot by `moved_rad`.
    Stalled {
        leg: String,
        window_s: f64,
        locked_moved_rad: f64,
        moved_rad: f64,
        at_s: f64,
    },
    /// The leg's end not reached within the goal tolerance in time.
    Goal {
        leg: String,
        joint: String,
        error_rad: f64,
        tolerance_rad: f64,
        late_s: f64,
    },
    /// Motion while the robot should be at rest.
    MotionAtRest {
        joint: String,
        moved_rad: f64,
        tolerance_rad: f64,
    },
    /// A sample that cannot be judged.
    BadSample { reason: String },
}

impl fmt::Display for Deviation {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::Path {
                leg,
                joint,
                error_rad,
                tolerance_rad,
                at_s,
            } => write!(
                f,
                "execution monitor: {joint} {error_rad:+.4} rad off the locked trajectory ({leg}, \
                 {at_s:.2} s in; path tolerance {tolerance_rad:.4} rad)"
            ),
            Self::Lagging {
                leg,
                behind_s,
                error_rad,
                at_s,
            } => write!(
                f,
                "execution monitor: the robot lags the locked trajectory by {behind_s:.2} s ({leg}, \
                 {at_s:.2} s in; {error_rad:.4} rad off)"
            ),
            Self::Stalled {
                leg,
                window_s,
                locked_moved_rad,
                moved_rad,
                at_s,
            } => write!(
                f,
                "execution monitor: the robot stalled ({leg}, {at_s:.2} s in): it moved {moved_rad:.4} \
                 rad in the last {window_s:.2} s while the locked trajectory moved {locked_moved_rad:.4} rad"
            ),
            Self::Goal {
                leg,
                joint,
                error_rad,
                tolerance_rad,
                late_s,
            } => write!(
                f,
                "execution monitor: {leg} did not arrive: {joint} {error_rad:+.4} rad from the end \
                 {late_s:.2} s after its end time (goal tolerance {tolerance_rad:.4} rad)"
            ),
            Self::MotionAtRest {
                joint,
                moved_rad,
                tolerance_rad,
            } => write!(
                f,
                "execution monitor: {joint} moved {moved_rad:+.4} rad while the robot should be at rest \
                 (rest tolerance {tolerance_rad:.4} rad)"
            ),
            Self::BadSample { reason } => write!(f, "execution monitor: {reason}"),
        }
    }
}

/// Settings or a leg that cannot be monitored.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum MonitorError {
    #[error("execution monitor: {0}")]
    Invalid(String),
    /// A limit out of its range: finite, above `least` (or equal to it when `least_allowed`), at
    /// most `max`.
    #[error(
        "[monitor] {key} = {value}: expected a finite number {} {least}, at most {max}",
        if *least_allowed { ">=" } else { ">" }
    )]
    Limit {
        key: &'static str,
        value: f64,
        least: f64,
        least_allowed: bool,
        max: f64,
    },
}

/// A leg: knot times (from its start, increasing), positions and velocities.
#[derive(Debug, Clone, PartialEq)]
struct Leg {
    label: String,
    times_s: Vec<f64>,
    positions: Vec<Vec<f64>>,
    velocities: Vec<Vec<f64>>,
}

impl Leg {
    fn duration_s(&self) -> f64 {
        self.times_s.last().copied().unwrap_or(0.0)
    }

    /// The locked positions at `t` seconds into the leg (clamped to its ends).
    fn at(&self, t: f64, out: &mut [f64]) {
        let n = self.times_s.len();
        let (Some(first), Some(last)) = (self.positions.first(), self.positions.last()) else {
            return;
        };
        if n < 2 || t <= self.times_s[0] {
            out.copy_from_slice(first);
            return;
        }
        if t >= self.times_s[n - 1] {
            out.copy_from_slice(last);
            return;
        }
        let k = self.times_s.partition_point(|&x| x <= t).clamp(1, n - 1);
        let (t0, t1) = (self.times_s[k - 1], self.times_s[k]);
        let h = t1 - t0;
        let s = (t - t0) / h;
        let (s2, s3) = (s * s, s * s * s);
        let (h00, h10, h01, h11) = (
            2.0 * s3 - 3.0 * s2 + 1.0,
            s3 - 2.0 * s2 + s,
            -2.0 * s3 + 3.0 * s2,
            s3 - s2,
        );
        for (j, o) in out.iter_mut().enumerate() {
            *o = h00 * self.positions[k - 1][j]
                + h10 * h * self.velocities[k - 1][j]
                + h01 * self.positions[k][j]
                + h11 * h * self.velocities[k][j];
        }
    }
}

#[derive(Debug, Clone, PartialEq)]
enum Phase {
    /// Nothing commanded yet: nothing to compare with.
    Idle,
    /// Sent, not started (an action goal not yet accepted): the robot must stay at the leg's start.
    Pending(Leg),
    Moving {
        leg: Leg,
        t0_nanos: i64,
    },
    /// Held: the robot may still be stopping until `until_nanos`.
    Stopping {
        until_nanos: i64,
    },
    /// At rest where the first sample put it (`None`: the next sample is the reference).
    AtRest(Option<Vec<f64>>),
}

/// How much of the stall window must show a standing robot before a path or lag verdict is
/// reported as a stall instead (five samples at 250 Hz).
const STALL_EVIDENCE_S: f64 = 0.02;

/// The execution monitor of one robot (see the module doc).
#[derive(Debug, Clone)]
pub struct ExecutionMonitor {
    settings: MonitorSettings,
    joints: Vec<String>,
    phase: Phase,
    /// Moving: (seconds into the leg, measured, locked) over the stall window.
    window: VecDeque<(f64, Vec<f64>, Vec<f64>)>,
    active_since_nanos: Option<i64>,
    last_sample_nanos: Option<i64>,
    scratch: Vec<f64>,
    /// The largest |error| / tolerance seen while moving, and its joint.
    worst_path_ratio: (f64, usize),
}

fn positive(x: f64) -> bool {
    x.is_finite() && x > 0.0
}

impl ExecutionMonitor {
    /// A monitor of these joints (the lock's order).
    pub fn new(joints: Vec<String>, settings: MonitorSettings) -> Result<Self, MonitorError> {
        let bad = |what: &str| Err(MonitorError::Invalid(what.to_owned()));
        if joints.is_empty() {
            return bad("no joints");
        }
        if settings.path_tolerance_rad.len() != joints.len() {
            return Err(MonitorError::Invalid(format!(
                "{} path tolerances for {} joints",
                settings.path_tolerance_rad.len(),
                joints.len()
            )));
        }
        if !settings.path_tolerance_rad.iter().all(|&t| positive(t)) {
            return bad("path tolerances must be > 0");
        }
        if !(positive(settings.goal_tolerance_rad)
            && positive(settings.rest_tolerance_rad)
            && positive(settings.stall_window_s)
            && settings.goal_time_tolerance_s.is_finite()
            && settings.goal_time_tolerance_s >= 0.0
            && settings.stop_time_s.is_finite()
            && settings.stop_time_s >= 0.0)
        {
            return bad("goal and rest tolerances and the stall window must be > 0, the goal time tolerance and the stop time ≥ 0");
        }
        let n = joints.len();
        Ok(Self {
            settings,
            joints,
            phase: Phase::Idle,
            window: VecDeque::new(),
            active_since_nanos: None,
            last_sample_nanos: None,
            scratch: vec![0.0; n],
            worst_path_ratio: (0.0, 0),
        })
    }

    pub fn joints(&self) -> &[String] {
        &self.joints
    }

    pub fn settings(&self) -> &MonitorSettings {
        &self.settings
    }

    /// A leg was sent: `times_s` from its start, `positions` and `velocities` per knot in the
    /// monitor's joint order. The robot must stay at its start until [`Self::leg_started`].
    pub fn leg_sent(
        &mut self,
        now_nanos: i64,
        label: &str,
        times_s: Vec<f64>,
        positions: Vec<Vec<f64>>,
        velocities: Vec<Vec<f64>>,
    ) -> Result<(), MonitorError> {
        let n = self.joints.len();
        let bad = |what: String| Err(MonitorError::Invalid(format!("leg {label}: {what}")));
        if times_s.is_empty() || times_s.len() != positions.len() {
            return bad(format!(
                "{} knot times for {} positions",
                times_s.len(),
                positions.len()
            ));
        }
        if !times_s.windows(2).all(|w| w[1] > w[0]) || !times_s.iter().all(|t| t.is_finite()) {
            return bad("knot times must increase".to_owned());
        }
        // Missing velocities (a trajectory of positions only) are zero: linear-ish, still bounded.
        let velocities = if velocities.len() == positions.len() {
            velocities
        } else {
            vec![vec![0.0; n]; positions.len()]
        };
        if positions
            .iter()
            .chain(&velocities)
            .any(|p| p.len() != n || !p.iter().all(|x| x.is_finite()))
        {
            return bad(format!(
                "every knot needs {n} finite positions and velocities"
            ));
        }
        self.phase = Phase::Pending(Leg {
            label: label.to_owned(),
            times_s,
            positions,
            velocities,
        });
        self.window.clear();
        self.active_since_nanos.get_or_insert(now_nanos);
        Ok(())
    }

    /// The controller started the sent leg at `now_nanos` (the topic: when it was published; an
    /// action goal: when it was accepted). Ignored when no leg is pending.
    pub fn leg_started(&mut self, now_nanos: i64) {
        if let Phase::Pending(leg) = std::mem::replace(&mut self.phase, Phase::Idle) {
            self.phase = Phase::Moving {
                leg,
                t0_nanos: now_nanos,
            };
        }
    }

    /// The robot was held at `now_nanos`: it may stop within `stop_time_s`, then must be at rest.
    pub fn held(&mut self, now_nanos: i64) {
        let stop = (self.settings.stop_time_s * 1e9) as i64;
        self.phase = Phase::Stopping {
            until_nanos: now_nanos.saturating_add(stop),
        };
        self.window.clear();
        self.active_since_nanos.get_or_insert(now_nanos);
    }

    /// Seconds since the last sample (or since the monitor had something to watch), if that is
    /// longer than `timeout_s`; `None` before anything was commanded.
    pub fn stale_for_s(&self, now_nanos: i64, timeout_s: f64) -> Option<f64> {
        let since = self.last_sample_nanos.or(self.active_since_nanos)?;
        let age = (now_nanos - since) as f64 * 1e-9;
        (age > timeout_s).then_some(age)
    }

    /// After a gap in the samples the rest reference is taken again from the next sample (the
    /// robot may have been homed meanwhile; where it may restart from is the session's business).
    pub fn resync_rest(&mut self) {
        if matches!(self.phase, Phase::AtRest(_) | Phase::Stopping { .. }) {
            self.phase = Phase::AtRest(None);
        }
    }

    /// The largest |error| / path tolerance seen while moving so far, and its joint.
    pub fn worst_path_ratio(&self) -> (f64, &str) {
        let (r, j) = self.worst_path_ratio;
        (r, self.joints.get(j).map_or("", String::as_str))
    }

    /// Judges one sample: `positions` in the monitor's joint order, received at `now_nanos`.
    pub fn observe(&mut self, now_nanos: i64, positions: &[f64]) -> Result<(), Deviation> {
        if positions.len() != self.joints.len() {
            return Err(Deviation::BadSample {
                reason: format!(
                    "a joint state with {} of the {} joints",
                    positions.len(),
                    self.joints.len()
                ),
            });
        }
        if let Some(j) = positions.iter().position(|x| !x.is_finite()) {
            return Err(Deviation::BadSample {
                reason: format!("{} is {} in a joint state", self.joints[j], positions[j]),
            });
        }
        self.last_sample_nanos = Some(now_nanos);
        let phase = std::mem::replace(&mut self.phase, Phase::Idle);
        let (next, verdict) = self.judge(phase, now_nanos, positions);
        self.phase = next;
        verdict
    }

    fn judge(&mut self, phase: Phase, now_nanos: i64, q: &[f64]) -> (Phase, Result<(), Deviation>) {
        match phase {
            Phase::Idle => (Phase::Idle, Ok(())),
            Phase::Pending(leg) => {
                leg.at(0.0, &mut self.scratch);
                let verdict = self.check_path(&leg, 0.0, q);
                (Phase::Pending(leg), verdict)
            }
            Phase::Moving { leg, t0_nanos } => {
                let t = (now_nanos - t0_nanos) as f64 * 1e-9;
                let end = leg.duration_s();
                if t > end {
                    let last = leg.positions.last().cloned().unwrap_or_default();
                    let far = q
                        .iter()
                        .zip(&last)
                        .enumerate()
                        .map(|(j, (a, b))| (j, a - b))
                        .max_by(|x, y| x.1.abs().total_cmp(&y.1.abs()));
                    match far {
                        Some((_, e)) if e.abs() <= self.settings.goal_tolerance_rad => {
                            return (Phase::AtRest(Some(q.to_vec())), Ok(()));
                        }
                        Some((j, e)) if t - end > self.settings.goal_time_tolerance_s => {
                            let d = Deviation::Goal {
                                leg: leg.label.clone(),
                                joint: self.joints[j].clone(),
                                error_rad: e,
                                tolerance_rad: self.settings.goal_tolerance_rad,
                                late_s: t - end,
                            };
                            return (Phase::Moving { leg, t0_nanos }, Err(d));
                        }
                        _ => {}
                    }
                }
                self.push_window(&leg, t, q);
                // A robot off its path that has not moved since the window began stalled: say so
                // (it is also late, but "lags" would hide that it stopped dead).
                let verdict = match self.check_path(&leg, t, q) {
                    Ok(()) => self.stalled(&leg, t, self.settings.stall_window_s),
                    Err(d) => self.stalled(&leg, t, STALL_EVIDENCE_S).and(Err(d)),
                };
                (Phase::Moving { leg, t0_nanos }, verdict)
            }
            Phase::Stopping { until_nanos } if now_nanos >= until_nanos => {
                (Phase::AtRest(Some(q.to_vec())), Ok(()))
            }
            p @ Phase::Stopping { .. } => (p, Ok(())),
            Phase::AtRest(None) => (Phase::AtRest(Some(q.to_vec())), Ok(())),
            Phase::AtRest(Some(rest)) => {
                let far = q
                    .iter()
                    .zip(&rest)
                    .enumerate()
                    .map(|(j, (a, b))| (j, a - b))
                    .find(|(_, e)| e.abs() > self.settings.rest_tolerance_rad);
                let verdict = match far {
                    Some((j, e)) => Err(Deviation::MotionAtRest {
                        joint: self.joints[j].clone(),
                        moved_rad: e,
                        tolerance_rad: self.settings.rest_tolerance_rad,
                    }),
                    None => Ok(()),
                };
                (Phase::AtRest(Some(rest)), verdict)
            }
        }
    }

    /// `q` against the leg at `t` (clamped to the leg's ends).
    fn check_path(&mut self, leg: &Leg, t: f64, q: &[f64]) -> Result<(), Deviation> {
        leg.at(t, &mut self.scratch);
        let tol = &self.settings.path_tolerance_rad;
        let mut worst = (0.0_f64, 0usize);
        for (j, (a, b)) in q.iter().zip(&self.scratch).enumerate() {
            let ratio = (a - b).abs() / tol[j];
            if ratio > worst.0 {
                worst = (ratio, j);
            }
        }
        if worst.0 > self.worst_path_ratio.0 {
            self.worst_path_ratio = worst;
        }
        if worst.0 <= 1.0 {
            return Ok(());
        }
        let j = worst.1;
        let error_rad = q[j] - self.scratch[j];
        // On the locked path but late? The time within the last 2 s where the lock best matches.
        let mut best = (f64::INFINITY, t);
        let mut tau = t;
        while tau >= (t - 2.0).max(0.0) {
            leg.at(tau, &mut self.scratch);
            let r = q
                .iter()
                .zip(&self.scratch)
                .zip(tol)
                .map(|((a, b), tl)| (a - b).abs() / tl)
                .fold(0.0_f64, f64::max);
            if r < best.0 {
                best = (r, tau);
            }
            tau -= 0.005;
        }
        if best.0 <= 0.5 && t - best.1 >= 0.02 {
            return Err(Deviation::Lagging {
                leg: leg.label.clone(),
                behind_s: t - best.1,
                error_rad: error_rad.abs(),
                at_s: t,
            });
        }
        Err(Deviation::Path {
            leg: leg.label.clone(),
            joint: self.joints[j].clone(),
            error_rad,
            tolerance_rad: tol[j],
            at_s: t,
        })
    }

    /// Keeps (t, measured, locked) over the stall window.
    fn push_window(&mut self, leg: &Leg, t: f64, q: &[f64]) {
        leg.at(t.min(leg.duration_s()), &mut self.scratch);
        self.window.push_back((t, q.to_vec(), self.scratch.clone()));
        let w = self.settings.stall_window_s;
        while self.window.len() > 2 && self.window.get(1).is_some_and(|(t1, ..)| t - t1 >= w) {
            self.window.pop_front();
        }
    }

    /// `Err(Stalled)` when, over the last `min_span_s` (at most the window), the lock moved clearly
    /// (more than the rest tolerance) and the robot by under a fifth of that.
    fn stalled(&self, leg: &Leg, t: f64, min_span_s: f64) -> Result<(), Deviation> {
        // The newest sample at least `min_span_s` old: the robot's motion since then.
        let old = self
            .window
            .iter()
            .rev()
            .find(|(t_i, ..)| t - t_i >= min_span_s);
        let (Some((t_old, q_old, r_old)), Some((_, q_new, r_new))) = (old, self.window.back())
        else {
            return Ok(());
        };
        let max_delta = |a: &[f64], b: &[f64]| {
            a.iter()
                .zip(b)
                .map(|(x, y)| (x - y).abs())
                .fold(0.0_f64, f64::max)
        };
        let locked = max_delta(r_new, r_old);
        let moved = max_delta(q_new, q_old);
        if locked > self.settings.rest_tolerance_rad && moved < 0.2 * locked {
            return Err(Deviation::Stalled {
                leg: leg.label.clone(),
                window_s: t - t_old,
                locked_moved_rad: locked,
                moved_rad: moved,
                at_s: t,
            });
        }
        Ok(())
    }
}

/// Path tolerances derived from the lock: the separation margin the validation found
/// (`min_separation_m − required_separation_m`, in the lock's summary) shared equally over the `n`
/// joints by each one's largest lever arm over the locked samples, so that the joints' errors
/// together move no point of the arm by more than the margin: `δ_j = margin / (n · r_j)`
/// ([`RobotModel::joint_lever_arms_m`]), at most `cap_rad`. A lock with no margin gets an error, not
/// a zero tolerance.
pub fn path_tolerances(
    model: &RobotModel,
    T_flange_tcp: &Isometry3<f64>,
    points: &[LockPoint],
    margin_m: f64,
    cap_rad: f64,
) -> Result<Vec<f64>, RobotError> {
    let positions: Vec<&[f64]> = points.iter().map(|p| p.positions_rad.as_slice()).collect();
    path_tolerances_of(model, T_flange_tcp, &positions, margin_m, cap_rad)
}

/// [`path_tolerances`] over joint positions (`[sample][joint]`, radians): what the validation
/// derives for its lock ([`crate::lock::LockSummary::path_tolerance_rad`]).
pub fn path_tolerances_of(
    model: &RobotModel,
    T_flange_tcp: &Isometry3<f64>,
    positions: &[&[f64]],
    margin_m: f64,
    cap_rad: f64,
) -> Result<Vec<f64>, RobotError> {
    let invalid = |reason: String| RobotError::Config {
        reason: format!("path tolerances: {reason}"),
    };
    if !(margin_m.is_finite() && margin_m > 0.0) {
        return Err(invalid(format!(
            "the lock's separation margin is {margin_m} m: no deviation is allowed"
        )));
    }
    if !(cap_rad.is_finite() && cap_rad > 0.0) {
        return Err(invalid(format!("the cap {cap_rad} rad must be > 0")));
    }
    let n = model.dof();
    let mut arms = vec![0.0_f64; n];
    for p in positions {
        for (a, r) in arms
            .iter_mut()
            .zip(model.joint_lever_arms_m(p, T_flange_tcp)?)
        {
            *a = a.max(r);
        }
    }
    Ok(arms
        .iter()
        .map(|&r| {
            if r > 0.0 {
                (margin_m / (n as f64 * r)).min(cap_rad)
            } else {
                cap_rad
            }
        })
        .collect())
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used, clippy::expect_used)]
    use super::*;

    /// A cap lowers a limit and never raises it; each limit out of range is refused by its name.
    #[test]
    fn a_cap_only_tightens_and_a_limit_out_of_range_is_named() {
        type Set = fn(&mut MonitorLimits, f64);
        let locked = MonitorLimits::default();
        let caps = MonitorCaps {
            goal_tolerance_rad: Some(0.005),
            stop_time_s: Some(5.0),
            ..MonitorCaps::default()
        };
        let t = locked.tightened(&caps);
        assert_eq!(t.goal_tolerance_rad, 0.005);
        assert_eq!(
            t.stop_time_s, locked.stop_time_s,
            "a looser cap leaves the lock's"
        );
        assert_eq!(t.goal_time_tolerance_s, locked.goal_time_tolerance_s);
        assert_eq!(locked.check(), Ok(()));
        let fields: [(&str, Set); 5] = [
            ("goal_tolerance_rad", |m, v| m.goal_tolerance_rad = v),
            ("goal_time_tolerance_s", |m, v| m.goal_time_tolerance_s = v),
            ("rest_tolerance_rad", |m, v| m.rest_tolerance_rad = v),
            ("stall_window_s", |m, v| m.stall_window_s = v),
            ("stop_time_s", |m, v| m.stop_time_s = v),
        ];
        for (name, set) in fields {
            for bad in [f64::NAN, -0.1, 10.5, f64::INFINITY] {
                let mut m = MonitorLimits::default();
                set(&mut m, bad);
                assert!(
                    matches!(m.check(), Err(MonitorError::Limit { key, .. }) if key == name),
                    "{name} = {bad}"
                );
            }
        }
        // zero: a tolerance, a window and the goal time (control_msgs' "default") are refused, the
        // stop time allowed
        let mut m = MonitorLimits {
            stop_time_s: 0.0,
            goal_time_tolerance_s: MIN_GOAL_TIME_TOLERANCE_S,
            ..MonitorLimits::default()
        };
        assert_eq!(m.check(), Ok(()));
        m.goal_time_tolerance_s = 0.0;
        assert!(matches!(
            m.check(),
            Err(MonitorError::Limit {
                key: "goal_time_tolerance_s",
                ..
            })
        ));
        m.goal_time_tolerance_s = 1.0;
        m.stall_window_s = 0.0;
        assert!(matches!(
            m.check(),
            Err(MonitorError::Limit {
                key: "stall_window_s",
                ..
            })
        ));
    }

    const MS: i64 = 1_000_000;

    fn settings() -> MonitorSettings {
        MonitorSettings {
            path_tolerance_rad: vec![0.02, 0.05],
            goal_tolerance_rad: 0.01,
            goal_time_tolerance_s: 0.5,
            rest_tolerance_rad: 0.01,
            stall_window_s: 0.1,
            stop_time_s: 0.3,
        }
    }

    /// Joint a goes 0 → 1 rad in 1 s (cubic with zero end velocities), b stays at 0.5.
    fn leg() -> (Vec<f64>, Vec<Vec<f64>>, Vec<Vec<f64>>) {
        let times: Vec<f64> = (0..=20).map(|k| f64::from(k) * 0.05).collect();
        let a = |t: f64| 3.0 * t * t - 2.0 * t * t * t;
        let da = |t: f64| 6.0 * t - 6.0 * t * t;
        let pos = times.iter().map(|&t| vec![a(t), 0.5]).collect();
        let vel = times.iter().map(|&t| vec![da(t), 0.0]).collect();
        (times, pos, vel)
    }

    fn truth(t: f64) -> [f64; 2] {
        let t = t.clamp(0.0, 1.0);
        [3.0 * t * t - 2.0 * t * t * t, 0.5]
    }

    fn moving() -> ExecutionMonitor {
        let mut m = ExecutionMonitor::new(vec!["a".into(), "b".into()], settings()).unwrap();
        let (t, p, v) = leg();
        m.leg_sent(0, "home → handover", t, p, v).unwrap();
        m.leg_started(0);
        m
    }

    /// Runs samples every 4 ms (250 Hz) until `until_s`, positions from `f(t)`; the first deviation.
    fn run(
        m: &mut ExecutionMonitor,
        until_s: f64,
        f: impl Fn(f64) -> [f64; 2],
    ) -> Option<(f64, Deviation)> {
        let mut k = 0i64;
        loop {
            let t = (k * 4 * MS) as f64 * 1e-9;
            if t > until_s {
                return None;
            }
            if let Err(d) = m.observe(k * 4 * MS, &f(t)) {
                return Some((t, d));
            }
            k += 1;
        }
    }

    #[test]
    fn hermite_interpolation_reproduces_the_cubic_between_knots() {
        let (t, p, v) = leg();
        let leg = Leg {
            label: String::new(),
            times_s: t,
            positions: p,
            velocities: v,
        };
        let mut out = [0.0; 2];
        for k in 0..=1000 {
            let t = f64::from(k) * 0.001;
            leg.at(t, &mut out);
            assert!((out[0] - truth(t)[0]).abs() < 1e-12, "{t}");
        }
    }

    #[test]
    fn a_faithful_execution_passes_and_comes_to_rest() {
        let mut m = moving();
        // Small noise and a 3 ms offset: within the tolerances.
        assert_eq!(
            run(&mut m, 2.0, |t| {
                let q = truth(t - 0.003);
                [q[0] + 1e-4, q[1] - 1e-4]
            }),
            None
        );
        assert!(m.worst_path_ratio().0 < 0.5, "{:?}", m.worst_path_ratio());
        // Now at rest at the end: a nudge of one joint beyond the rest tolerance is motion at rest.
        let at = 2_004 * MS;
        assert!(m.observe(at, &[1.0, 0.5]).is_ok());
        let e = m.observe(at + 4 * MS, &[1.0, 0.5 + 0.011]).unwrap_err();
        assert!(
            matches!(&e, Deviation::MotionAtRest { joint, .. } if joint == "b"),
            "{e}"
        );
        assert!(
            e.to_string()
                .contains("b moved +0.0111 rad while the robot should be at rest"),
            "{e}"
        );
    }

    #[test]
    fn drift_of_one_joint_is_caught_on_the_first_sample_beyond_its_tolerance() {
        let mut m = moving();
        // b drifts at 0.1 rad/s: beyond 0.05 rad after 0.5 s.
        let (t, d) = run(&mut m, 2.0, |t| [truth(t)[0], 0.5 + 0.1 * t]).unwrap();
        assert!((0.5..=0.504 + 1e-9).contains(&t), "caught at {t}");
        assert!(
            matches!(&d, Deviation::Path { joint, .. } if joint == "b"),
            "{d}"
        );
    }

    #[test]
    fn a_late_robot_on_the_locked_path_is_diagnosed_as_lagging() {
        let mut m = moving();
        // Runs the trajectory at 80 % speed.
        let (t, d) = run(&mut m, 2.0, |t| truth(0.8 * t)).unwrap();
        assert!(t < 0.5, "caught at {t}");
        match d {
            Deviation::Lagging { behind_s, .. } => {
                assert!((behind_s - 0.2 * t).abs() < 0.01, "{behind_s} at {t}");
            }
            other => panic!("{other}"),
        }
    }

    #[test]
    fn a_stall_is_caught_before_the_path_tolerance_and_named() {
        let mut m = ExecutionMonitor::new(
            vec!["a".into(), "b".into()],
            MonitorSettings {
                path_tolerance_rad: vec![0.2, 0.2],
                ..settings()
            },
        )
        .unwrap();
        let (tt, p, v) = leg();
        m.leg_sent(0, "leg", tt, p, v).unwrap();
        m.leg_started(0);
        // Stops dead at 0.4 s (a = 0.352): the lock moves ≈ 0.14 rad in the next 0.1 s.
        let (t, d) = run(&mut m, 2.0, |t| truth(t.min(0.4))).unwrap();
        assert!(matches!(d, Deviation::Stalled { .. }), "{d}");
        assert!(t > 0.4 && t <= 0.51, "caught at {t}");
    }

    #[test]
    fn a_robot_that_stops_dead_at_speed_is_named_stalled_when_it_leaves_its_path() {
        // Tight path tolerances: the path is left before the stall window fills; it is a stall all
        // the same (the robot stands while the lock moves), not a lag.
        let mut m = moving();
        let (t, d) = run(&mut m, 2.0, |t| truth(t.min(0.4))).unwrap();
        assert!(t > 0.4 && t <= 0.46, "caught at {t}");
        match d {
            Deviation::Stalled {
                moved_rad,
                locked_moved_rad,
                ..
            } => assert!(
                moved_rad < 0.2 * locked_moved_rad && locked_moved_rad > 0.02,
                "{d}"
            ),
            other => panic!("{other}"),
        }
    }

    #[test]
    fn a_robot_that_never_arrives_fails_the_goal_tolerance_after_the_goal_time() {
        let mut m = ExecutionMonitor::new(
            vec!["a".into(), "b".into()],
            MonitorSettings {
                path_tolerance_rad: vec![0.05, 0.05],
                ..settings()
            },
        )
        .unwrap();
        let (tt, p, v) = leg();
        m.leg_sent(0, "leg", tt, p, v).unwrap();
        m.leg_started(0);
        let (t, d) = run(&mut m, 3.0, |t| {
            let q = truth(t);
            [q[0] - 0.03, q[1]]
        })
        .unwrap();
        assert!(matches!(d, Deviation::Goal { .. }), "{d}");
        assert!((t - 1.5).abs() < 0.01, "caught at {t}");
    }

    #[test]
    fn a_pending_goal_must_not_move_and_a_hold_gives_the_robot_its_stop_time() {
        let mut m = ExecutionMonitor::new(vec!["a".into(), "b".into()], settings()).unwrap();
        assert_eq!(m.stale_for_s(10 * MS, 0.1), None, "nothing to watch yet");
        assert!(m.observe(0, &[5.0, 5.0]).is_ok(), "idle: not judged");
        let (tt, p, v) = leg();
        m.leg_sent(0, "leg", tt, p, v).unwrap();
        assert!(m.observe(4 * MS, &[0.0, 0.5]).is_ok());
        assert!(matches!(
            m.observe(8 * MS, &[0.03, 0.5]),
            Err(Deviation::Path { .. })
        ));
        m.held(10 * MS);
        // Stopping: motion allowed for 0.3 s; then the first sample is the rest reference.
        assert!(m.observe(100 * MS, &[0.2, 0.5]).is_ok());
        assert!(m.observe(320 * MS, &[0.25, 0.5]).is_ok());
        assert!(m.observe(324 * MS, &[0.255, 0.5]).is_ok());
        assert!(matches!(
            m.observe(328 * MS, &[0.27, 0.5]),
            Err(Deviation::MotionAtRest { .. })
        ));
        // Stale: 150 ms without samples against a 0.1 s timeout.
        assert!(m
            .stale_for_s(478 * MS, 0.1)
            .is_some_and(|a| (a - 0.15).abs() < 1e-9));
        assert_eq!(m.stale_for_s(400 * MS, 0.1), None);
        // After a gap the rest reference is taken again.
        m.resync_rest();
        assert!(m.observe(900 * MS, &[0.0, 0.5]).is_ok());
        assert!(m.observe(904 * MS, &[0.0, 0.5]).is_ok());
    }

    #[test]
    fn unreadable_samples_and_unusable_settings_are_refused() {
        let mut m = moving();
        assert!(matches!(
            m.observe(0, &[0.0]),
            Err(Deviation::BadSample { .. })
        ));
        let e = m.observe(0, &[f64::NAN, 0.5]).unwrap_err();
        assert!(e.to_string().contains("a is NaN"), "{e}");
        assert!(ExecutionMonitor::new(vec!["a".into()], settings()).is_err());
        let zero = MonitorSettings {
            path_tolerance_rad: vec![0.0, 0.1],
            ..settings()
        };
        assert!(ExecutionMonitor::new(vec!["a".into(), "b".into()], zero).is_err());
        let mut m = ExecutionMonitor::new(vec!["a".into(), "b".into()], settings()).unwrap();
        assert!(m
            .leg_sent(0, "x", vec![0.0, 0.0], vec![vec![0.0; 2]; 2], vec![])
            .is_err());
        assert!(m
            .leg_sent(0, "x", vec![0.0], vec![vec![0.0; 3]], vec![])
            .is_err());
    }
}
