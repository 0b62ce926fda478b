//! `ergocell run`: the session state machine on the ROS 2 backend, and `ergocell replay --ros`:
//! recorded camera landmarks published as the Jetsons would.
//!
//! `run` subscribes to one landmark topic per camera and to `/joint_states`, commands the robot on the
//! joint trajectory controller's topic (a hold is an empty `JointTrajectory`: not an emergency stop),
//! and publishes the session state, the RULA state and the warnings. Topic names and the DDS domain
//! come from `[ros]` in the cell config; QoS from `ergocell_bridge::qos`. Ctrl-C (SIGINT) and SIGTERM
//! (systemd, `docker stop`, `timeout`) hold the robot (an empty trajectory, published), close the
//! recording with its summary and footer, and exit with 130 / 143.

use std::path::PathBuf;
use std::sync::{Arc, Mutex};
use std::time::Duration;

use anyhow::Context as _;
use ergocell::messages::{self, Outgoing};
use ergocell::recording::{self, topics, McapRecorder};
use ergocell::session::provider::FileTrajectories;
use ergocell::session::{
    BackendError, RobotCommand, RobotSink, SessionEvent, SessionMachine, SessionState,
};
use ergocell_bridge::action::{FeedbackLayout, FeedbackWithIndex, FeedbackWithoutIndex};
use ergocell_bridge::controller::{run_controller, ControllerCommand, ControllerReport};
use ergocell_bridge::msg::{CameraLandmarks, ControllerEvent, JointState, JointTrajectory};
use ergocell_bridge::qos;
use ergocell_bridge::transport::{
    publish, CellTopics, Publisher, RobotInterface, RosConfig, RosNode,
};
use ergocell_cell::CellSettings;
use ergocell_perception::rig_file::parse_rig;
use ergocell_robot::monitor::{ExecutionMonitor, MonitorSettings};
use futures::StreamExt as _;

use super::signals::{Signal, StopFlag, Stopped};
use super::{output, UsageError};

/// The longest `--max-secs`: a year.
const MAX_SECS_LIMIT: f64 = 365.0 * 24.0 * 3600.0;

/// `replay --speed` bounds.
const SPEED_RANGE: std::ops::RangeInclusive<f64> = 0.01..=100.0;

#[derive(Debug, clap::Args)]
#[command(
    after_help = "Exit codes: 0 the sessions ended normally (--sessions reached); 1 a session \
    did not end normally (a trajectory that does not verify, --max-secs reached: robot held) or a \
    failure; 2 bad input (an existing --record file without --force); 130 stopped by Ctrl-C \
    (SIGINT), 143 stopped by SIGTERM (systemd: SuccessExitStatus=143) — in both the robot is held \
    (empty trajectory published) and the recording closed with its summary and footer."
)]
pub struct Args {
    /// Cell configuration: `[robot]`, `[station]` and `[ros]`.
    #[arg(long, default_value = "config/cell.toml")]
    pub config: PathBuf,
    /// Camera rig; its camera ids must match `[ros] cameras`.
    #[arg(long, default_value = "config/rig.toml")]
    pub rig: PathBuf,
    /// A camera whose node sends images that are not its calibrated image (their size is in each
    /// message): `CAMERA=fit` (the calibrated image scaled to fit, centred) or
    /// `CAMERA=affine:SX,SY,OX,OY` (`x_cal = SX·(x − OX)`, likewise y). Repeat per camera. Without
    /// one, a message whose image size is not the calibrated size is rejected.
    #[arg(long = "video-geometry", value_name = "CAMERA=SPEC")]
    pub video_geometry: Vec<String>,
    /// Serve the operator display on this address (e.g. `127.0.0.1:8090`; port 0 picks a free
    /// one, printed): the current warning per body region with its advice, the action level as
    /// colour, the session state and the skeleton, pushed as it happens. Only loopback `Host`s are
    /// answered unless the address is not a loopback one.
    #[arg(long, value_name = "ADDR")]
    pub display: Option<std::net::SocketAddr>,
    /// Folder of the trajectory files and `locks/`.
    #[arg(long, default_value = "trajectories")]
    pub trajectories: PathBuf,
    /// Folder of the approvals (default `<trajectories>/approvals`).
    #[arg(long)]
    pub approvals: Option<PathBuf>,
    /// Record the session to this MCAP file (an existing file is refused unless --force).
    #[arg(long)]
    pub record: Option<PathBuf>,
    /// Overwrite an existing --record file.
    #[arg(long)]
    pub force: bool,
    /// Stop (holding the robot) after this many seconds if the session has not ended (> 0, at most
    /// a year).
    #[arg(long)]
    pub max_secs: Option<f64>,
    /// Stop after this many sessions (default: one operator session after another until Ctrl-C). A
    /// session that ends without the operator leaving normally (e.g. a trajectory that does not
    /// verify) always stops the program with exit code 1: it needs a person.
    #[arg(long)]
    pub sessions: Option<u32>,
    /// Print the latency from a camera message's arrival to the RULA state published (p50/p99) and
    /// the process's CPU use at the end.
    #[arg(long)]
    pub latency_report: bool,
    /// SROS2 keystore (DDS Security, enclave `/ergocell/cell`, or ROS_SECURITY_ENCLAVE_OVERRIDE);
    /// default ROS_SECURITY_KEYSTORE, then `[ros] keystore`.
    #[arg(long)]
    pub keystore: Option<PathBuf>,
}

#[derive(Debug, clap::Args)]
pub struct ReplayArgs {
    /// An MCAP recording (e.g. from `ergocell demo`).
    pub recording: PathBuf,
    /// Publish the camera landmarks over ROS 2 (the only output so far; required).
    #[arg(long)]
    pub ros: bool,
    /// Cell configuration with the `[ros]` table.
    #[arg(long, default_value = "config/cell.toml")]
    pub config: PathBuf,
    /// Playback speed factor (1 = as recorded; 0.01..=100).
    #[arg(long, default_value_t = 1.0)]
    pub speed: f64,
    /// SROS2 keystore (DDS Security, enclave `/ergocell/replay`, or ROS_SECURITY_ENCLAVE_OVERRIDE);
    /// default ROS_SECURITY_KEYSTORE, then `[ros] keystore`.
    #[arg(long)]
    pub keystore: Option<PathBuf>,
}

/// Wall-clock time, nanoseconds since the Unix epoch: the binary's clock boundary (camera stamps are
/// ROS time).
#[allow(clippy::disallowed_methods)]
fn now_nanos() -> i64 {
    std::time::SystemTime::now()
        .duration_since(std::time::UNIX_EPOCH)
        .map_or(0, |d| i64::try_from(d.as_nanos()).unwrap_or(i64::MAX))
}

/// `run`'s clock: the wall clock read once at start, advanced by the monotonic clock. Everything the
/// session times — stale cameras, hold, resume and departure bounds, the height timeout, `--max-secs`,
/// the recording's log times and the stamps ergocell publishes — runs on it, so a step of the system
/// clock during a session (an NTP correction, someone setting the time) moves none of them: the step
/// is noticed on the next tick and reported once, and the session goes on as if nothing happened.
/// (The cameras' stamps are their own clock's: a camera whose clock steps is handled by the staleness
/// and fusion windows, which compare arrival times on this clock.)
#[derive(Clone)]
struct SessionClock {
    wall0_nanos: i64,
    mono0: std::time::Instant,
    /// The wall clock minus this clock when last reported (0 at start).
    reported_offset_nanos: i64,
}

/// A wall clock that departs from the session clock by more than this since the last report is a step.
const WALL_STEP_NANOS: i64 = 1_000_000_000;

impl SessionClock {
    fn start() -> Self {
        Self::anchored(now_nanos(), instant())
    }

    fn anchored(wall0_nanos: i64, mono0: std::time::Instant) -> Self {
        Self {
            wall0_nanos,
            mono0,
            reported_offset_nanos: 0,
        }
    }

    /// Nanoseconds since the Unix epoch, on the session's monotonic time line.
    fn now(&self) -> i64 {
        let elapsed = i64::try_from(self.mono0.elapsed().as_nanos()).unwrap_or(i64::MAX);
        self.wall0_nanos.saturating_add(elapsed)
    }

    /// The step of the wall clock (`wall_nanos`, read at session time `now`) since the last one
    /// reported, in nanoseconds, when it exceeds [`WALL_STEP_NANOS`]; then it is the new reference.
    fn wall_step(&mut self, wall_nanos: i64, now: i64) -> Option<i64> {
        let offset = wall_nanos.saturating_sub(now);
        let step = offset.saturating_sub(self.reported_offset_nanos);
        (step.abs() > WALL_STEP_NANOS).then(|| {
            self.reported_offset_nanos = offset;
            step
        })
    }
}

/// Monotonic instant for latency measurements.
#[allow(clippy::disallowed_methods)]
fn instant() -> std::time::Instant {
    std::time::Instant::now()
}

/// The robot over ROS 2: commands published on the trajectory topic (or sent as FollowJointTrajectory
/// goals), positions from `/joint_states`, and the execution monitor that judges every sample.
struct RosRobot {
    /// The controller's `joint_trajectory` topic: every command in topic mode, and in action mode the
    /// empty trajectory of a hold too (it overrides any active goal), beside the cancel.
    publisher: Arc<Publisher<JointTrajectory>>,
    /// Action mode: the FollowJointTrajectory task's commands and the goals' tolerances.
    action: Option<(
        tokio::sync::mpsc::UnboundedSender<ControllerCommand>,
        ergocell_bridge::action::GoalTolerances,
    )>,
    latest: Arc<Mutex<Option<JointState>>>,
    /// The `[ros]` settings (the path tolerances' cap among them).
    ros: RosConfig,
    /// The execution monitor, once a leg was sent (`[ros] monitor_execution`); shared with the
    /// monitor task, which judges every sample with it.
    monitor: Arc<Mutex<Option<ExecutionMonitor>>>,
    /// Controller events to publish and record (the loop drains it).
    events: Vec<ControllerEvent>,
}

impl RosRobot {
    fn publish(&self, message: JointTrajectory) -> Result<(), BackendError> {
        self.publisher.publish(message).map_err(|e| BackendError {
            backend: "ROS 2 joint trajectory",
            reason: format!("{e:?}"),
        })
    }

    /// The path tolerances of the lock `lock_sha256`, derived once per lock.
    /// The leg's path tolerances: the lock's (derived when it was validated, signed off with it),
    /// each at most `[ros] path_tolerance_rad`. A leg without them is not sent.
    fn path_tolerances(
        &self,
        trajectory: &ergocell::session::LegTrajectory,
    ) -> Result<Vec<f64>, BackendError> {
        let t = &trajectory.path_tolerance_rad;
        if t.len() != trajectory.joint_names.len() || !t.iter().all(|v| v.is_finite() && *v > 0.0) {
            return Err(BackendError {
                backend: "execution monitor",
                reason: format!(
                    "the leg carries path tolerances {t:?}, not one positive tolerance per joint ({})",
                    trajectory.joint_names.len()
                ),
            });
        }
        let cap = self.ros.path_tolerance_rad;
        Ok(t.iter().map(|v| v.min(cap)).collect())
    }

    /// Starts monitoring `trajectory` (a leg just sent), making the monitor if needed.
    fn watch_leg(
        &mut self,
        now_nanos: i64,
        label: &str,
        trajectory: &ergocell::session::LegTrajectory,
        path_rad: &[f64],
    ) -> Result<(), BackendError> {
        let refused = |e: ergocell_robot::monitor::MonitorError| BackendError {
            backend: "execution monitor",
            reason: e.to_string(),
        };
        let mut guard = self.monitor.lock().map_err(|_| BackendError {
            backend: "execution monitor",
            reason: "the monitor task failed".to_owned(),
        })?;
        let fits = guard.as_ref().is_some_and(|m| {
            m.joints() == trajectory.joint_names.as_slice()
                && m.settings().path_tolerance_rad == path_rad
        });
        if !fits {
            let settings = MonitorSettings {
                path_tolerance_rad: path_rad.to_vec(),
                goal_tolerance_rad: self.ros.goal_tolerance_rad,
                goal_time_tolerance_s: self.ros.goal_time_tolerance_s,
                rest_tolerance_rad: self.ros.rest_tolerance_rad,
                stall_window_s: self.ros.stall_window_s,
                stop_time_s: self.ros.stop_time_s,
            };
            *guard = Some(
                ExecutionMonitor::new(trajectory.joint_names.clone(), settings).map_err(refused)?,
            );
        }
        if let Some(m) = guard.as_mut() {
            let p = &trajectory.points;
            m.leg_sent(
                now_nanos,
                label,
                p.iter().map(|k| k.time_from_start_s).collect(),
                p.iter().map(|k| k.positions_rad.clone()).collect(),
                p.iter().map(|k| k.velocities_rad_s.clone()).collect(),
            )
            .map_err(refused)?;
        }
        Ok(())
    }
}

/// A leg's name in the controller's reports.
fn leg_label(leg: ergocell::session::Leg) -> &'static str {
    match leg {
        ergocell::session::Leg::ToHandover => "home → handover",
        ergocell::session::Leg::ToHome => "handover → home",
    }
}

/// Joint values in radians as printed and published: "0.0187, 0.0194, …".
fn radians_list(values: &[f64]) -> String {
    values
        .iter()
        .map(|t| format!("{t:.4}"))
        .collect::<Vec<_>>()
        .join(", ")
}

/// The FollowJointTrajectory task is gone: nothing can be sent to the controller.
fn controller_task_stopped() -> BackendError {
    BackendError {
        backend: "ROS 2 FollowJointTrajectory",
        reason: "the controller task has stopped".to_owned(),
    }
}

/// A controller event of `kind` about `leg` with `text`.
fn controller_event(now_nanos: i64, kind: &str, leg: &str, text: String) -> ControllerEvent {
    ControllerEvent {
        header: ergocell_bridge::msg::Header::new(now_nanos, ""),
        kind: kind.to_owned(),
        leg: leg.to_owned(),
        text,
        max_error: f64::NAN,
        ..ControllerEvent::default()
    }
}

impl RobotSink for RosRobot {
    fn send(&mut self, now_nanos: i64, command: &RobotCommand) -> Result<(), BackendError> {
        let message = messages::command_message(command, now_nanos);
        match command {
            RobotCommand::Execute {
                leg,
                lock_sha256: _,
                trajectory,
            } => {
                let label = leg_label(*leg);
                // No tolerances, no monitor: the leg is not sent (the robot does not move).
                let path_rad = self.path_tolerances(trajectory)?;
                if self.ros.monitor_execution {
                    self.watch_leg(now_nanos, label, trajectory, &path_rad)?;
                }
                match &self.action {
                    None => {
                        self.publish(message)?;
                        // The controller starts a topic trajectory on receipt.
                        if let Some(m) = self.monitor.lock().ok().as_mut().and_then(|g| g.as_mut())
                        {
                            m.leg_started(now_nanos);
                        }
                    }
                    Some((commands, tolerances)) => commands
                        .send(ControllerCommand::Execute {
                            label: label.to_owned(),
                            goal: Box::new(ergocell_bridge::action::goal(
                                message,
                                &path_rad,
                                *tolerances,
                            )),
                        })
                        .map_err(|_| controller_task_stopped())?,
                }
                self.events.push(controller_event(
                    now_nanos,
                    "goal_sent",
                    label,
                    format!(
                        "{} points over {:.2} s; path tolerances {} rad",
                        trajectory.points.len(),
                        trajectory.duration_s(),
                        radians_list(&path_rad)
                    ),
                ));
                Ok(())
            }
            RobotCommand::Hold { .. } => {
                if let Some(m) = self.monitor.lock().ok().as_mut().and_then(|g| g.as_mut()) {
                    m.held(now_nanos);
                }
                let Some((commands, _)) = &self.action else {
                    return self.publish(message);
                };
                // Both, so that either stops the robot: the cancel ends the goal the controller
                // reports on, the empty trajectory overrides whatever it runs.
                let cancel = commands
                    .send(ControllerCommand::Cancel)
                    .map_err(|_| controller_task_stopped());
                self.publish(message)?;
                cancel
            }
        }
    }

    fn joint_positions(&mut self, _now_nanos: i64, names: &[String]) -> Option<Vec<f64>> {
        self.latest
            .lock()
            .ok()?
            .as_ref()
            .and_then(|js| js.positions_for(names))
    }
}

/// The KUKA driver's state as kuka_drivers reports it (`[ros] driver_state`).
#[derive(Debug, Default)]
struct DriverState {
    configured: Option<bool>,
    controlling: bool,
    /// "stopped by user (4)" / "stopped by error (6)" since the last "control started".
    stopped: Option<String>,
}

impl DriverState {
    fn on_event(&mut self, e: &ergocell_bridge::msg::HardwareEvent) {
        use ergocell_bridge::msg::HardwareEvent as H;
        match e.event {
            H::CONTROL_STARTED => {
                self.controlling = true;
                self.stopped = None;
            }
            H::CONTROL_STOPPED | H::ERROR => {
                self.controlling = false;
                self.stopped = Some(e.describe());
            }
            _ => {}
        }
    }

    /// Why no goal may be sent now, if none may.
    fn unready(&self) -> Option<String> {
        match self.configured {
            None => return Some("waiting for the KUKA driver: no is_configured yet".to_owned()),
            Some(false) => return Some("the KUKA driver is not configured".to_owned()),
            Some(true) => {}
        }
        if let Some(s) = &self.stopped {
            return Some(format!("the KUKA driver reports: {s}"));
        }
        (!self.controlling).then(|| "waiting for the KUKA driver: control not started".to_owned())
    }
}

/// What the monitor task tells the session loop.
enum MonitorNote {
    /// A joint state as it arrived (session time), for the recording.
    Sample(JointState, i64),
    /// The execution deviated: the goal was cancelled and the robot held already.
    Deviation {
        event: ControllerEvent,
        held_after_ms: f64,
    },
    /// No joint state for longer than the timeout.
    Stale(ControllerEvent),
    /// Joint states again after a stale spell.
    Back(ControllerEvent),
}

#[derive(Debug, Default)]
struct MonitorStats {
    /// Arrival → verdict, microseconds, every judged sample.
    verdict_us: Vec<f64>,
    /// The sample's stamp → its arrival here on the wall clock, microseconds, every judged sample:
    /// the controller's publish → ergocell's read, when the controller stamps on this host's clock
    /// (a peer on this machine; on a real cell it includes the two clocks' offset).
    transit_us: Vec<f64>,
}

/// What the monitor task shares with the session loop.
struct MonitorLinks {
    monitor: Arc<Mutex<Option<ExecutionMonitor>>>,
    latest: Arc<Mutex<Option<JointState>>>,
    /// The controller's trajectory topic: a deviation publishes the empty trajectory (hold) at once.
    hold: Arc<Publisher<JointTrajectory>>,
    /// Action mode: a deviation cancels the goal at once.
    cancel: Option<tokio::sync::mpsc::UnboundedSender<ControllerCommand>>,
    notes: tokio::sync::mpsc::UnboundedSender<MonitorNote>,
    stats: Arc<Mutex<MonitorStats>>,
}

/// The execution monitor's own task: it alone reads `/joint_states`, judges every sample as it
/// arrives and, on the first deviation, cancels the goal and publishes the hold itself (the session
/// loop may be busy verifying a lock or fusing a frame; the robot must not wait for it), then tells
/// the loop, which ends the session. Every 5 ms it checks for stale joint states.
async fn monitor_task(
    joint_states: ergocell_bridge::transport::Subscription<JointState>,
    links: MonitorLinks,
    clock: SessionClock,
    timeout_s: f64,
) {
    let mut stream = Box::pin(joint_states.async_stream());
    let mut tick = tokio::time::interval(Duration::from_millis(5));
    let mut tripped = false;
    let mut stale = false;
    let note = |n: MonitorNote| {
        // The loop is gone when nobody listens: the session is over.
        let _ = links.notes.send(n);
    };
    loop {
        tokio::select! {
            item = stream.next() => {
                let Some(Ok((js, _))) = item else {
                    if item.is_none() {
                        return;
                    }
                    continue;
                };
                let js: JointState = js;
                let arrival = instant();
                let transit_us = (now_nanos() - js.header.stamp.to_nanos()) as f64 * 1e-3;
                let now = clock.now();
                let judged = links.monitor.lock().ok().and_then(|mut g| {
                    let m = g.as_mut()?;
                    if stale {
                        m.resync_rest();
                    }
                    let verdict = match js.positions_for(m.joints()) {
                        Some(p) => m.observe(now, &p),
                        None => Err(ergocell_robot::monitor::Deviation::BadSample {
                            reason: format!(
                                "a joint state without every joint of the lock ({})",
                                m.joints().join(", ")
                            ),
                        }),
                    };
                    Some((verdict, m.worst_path_ratio().0))
                });
                if let Some((verdict, worst)) = judged {
                    if let Ok(mut st) = links.stats.lock() {
                        st.verdict_us.push(arrival.elapsed().as_secs_f64() * 1e6);
                        st.transit_us.push(transit_us);
                    }
                    if stale {
                        stale = false;
                        note(MonitorNote::Back(controller_event(now, "monitor", "", "joint states back".to_owned())));
                    }
                    if let (Err(d), false) = (verdict, tripped) {
                        tripped = true;
                        if let Some(tx) = &links.cancel {
                            let _ = tx.send(ControllerCommand::Cancel);
                        }
                        let hold = messages::command_message(
                            &RobotCommand::Hold { reason: d.to_string() },
                            now,
                        );
                        if let Err(e) = links.hold.publish(hold) {
                            tracing::error!(error = ?e, "the execution monitor's hold was not published");
                        }
                        let held_after_ms = arrival.elapsed().as_secs_f64() * 1e3;
                        let mut event = controller_event(now, "monitor", "", d.to_string());
                        event.max_error = worst;
                        event.sample_stamp = js.header.stamp;
                        note(MonitorNote::Deviation { event, held_after_ms });
                    }
                }
                if let Ok(mut l) = links.latest.lock() {
                    *l = Some(js.clone());
                }
                note(MonitorNote::Sample(js, now));
            }
            _ = tick.tick() => {
                let now = clock.now();
                let age = links.monitor.lock().ok().and_then(|g| g.as_ref()?.stale_for_s(now, timeout_s));
                if let (Some(age), false) = (age, stale) {
                    stale = true;
                    let why = format!("joint states stale (none for more than {timeout_s} s)");
                    tracing::warn!(age_s = age, "{why}");
                    note(MonitorNote::Stale(controller_event(now, "monitor", "", why)));
                }
            }
        }
    }
}

/// Records a joint state and, once a class is locked, the TCP and handover markers (at most 20 Hz).
fn record_joint_state(
    recording: &mut Recording,
    machine: &SessionMachine,
    geometry: &mut Option<(
        ergocell_robot::TrajectoryClass,
        ergocell::robot_markers::RobotGeometry,
    )>,
    last_marker_nanos: &mut i64,
    js: &JointState,
    now: i64,
    provider: impl Fn() -> FileTrajectories,
) {
    if !recording.is_on() {
        return;
    }
    recording.with(|rec| rec.write(topics::JOINT_STATES, now, js));
    let class = machine.locked_class();
    if geometry.as_ref().map(|(c, _)| *c) != class {
        *geometry = class.and_then(|c| match provider().robot_geometry(c) {
            Ok(g) => Some((c, g)),
            Err(e) => {
                tracing::warn!(error = %e, "no robot markers in the recording");
                None
            }
        });
    }
    if let Some((_, g)) = geometry.as_ref() {
        if now - *last_marker_nanos >= 50_000_000 {
            if let Some(p) = g.tcp_world(js) {
                *last_marker_nanos = now;
                recording.with(|rec| {
                    rec.write(
                        topics::ROBOT_MARKERS,
                        now,
                        &messages::robot_markers_message(now, Some(p), Some(g.handover_world())),
                    )
                });
            }
        }
    }
}

/// User + system CPU seconds of this process (Linux `/proc/self/stat`, clock ticks of 100 Hz).
fn cpu_secs() -> Option<f64> {
    let stat = std::fs::read_to_string("/proc/self/stat").ok()?;
    let after = stat.rsplit_once(')')?.1;
    let fields: Vec<&str> = after.split_whitespace().collect();
    let utime: f64 = fields.get(11)?.parse().ok()?;
    let stime: f64 = fields.get(12)?.parse().ok()?;
    Some((utime + stime) / 100.0)
}

fn percentile(sorted: &[f64], p: f64) -> f64 {
    if sorted.is_empty() {
        return f64::NAN;
    }
    let k = ((sorted.len() - 1) as f64 * p).round() as usize;
    sorted[k.min(sorted.len() - 1)]
}

pub fn run(args: &Args) -> anyhow::Result<()> {
    if let Some(limit) = args.max_secs {
        if !(limit.is_finite() && limit > 0.0 && limit <= MAX_SECS_LIMIT) {
            return Err(UsageError(format!(
                "--max-secs {limit:?}: must be a number of seconds > 0 and at most {MAX_SECS_LIMIT} (a year)"
            ))
            .into());
        }
    }
    if let Some(record) = &args.record {
        output::check(
            "--record",
            record,
            args.force,
            &[
                ("--config", args.config.as_path()),
                ("--rig", args.rig.as_path()),
            ],
        )?;
    }
    let (cell_text, cell_label) = ergocell::shipped::read_or_shipped(&args.config)?;
    let ros = RosConfig::from_cell_toml(&cell_text)
        .map_err(|e| UsageError(format!("{cell_label}: {e}")))?;
    let settings = CellSettings::from_toml_str(&cell_text, &cell_label)
        .map_err(|e| UsageError(e.to_string()))?;
    let (rig_text, rig_label) = ergocell::shipped::read_or_shipped(&args.rig)?;
    let (rig, _) = parse_rig(&rig_text, &rig_label).map_err(|e| UsageError(e.to_string()))?;
    for id in &ros.cameras {
        if rig.index_of_name(id).is_none() {
            return Err(UsageError(format!(
                "{cell_label}: [ros] camera `{id}` is not in the rig {rig_label}"
            ))
            .into());
        }
    }
    let video_geometries =
        ergocell_perception::video_geometry::parse_declarations(&rig, &args.video_geometry)
            .map_err(|e| UsageError(format!("--video-geometry: {e}")))?;
    let approvals = args.approvals.clone().unwrap_or_else(|| {
        ergocell_robot::TrajectoryLayout::new(&args.trajectories)
            .approvals_dir()
            .to_owned()
    });
    let new_machine = || {
        let provider = FileTrajectories::new(&args.config, &args.trajectories, &approvals);
        SessionMachine::from_settings(rig.clone(), &settings, Box::new(provider))
            .map_err(|e| anyhow::anyhow!(e))
    };
    let mut machine = new_machine()?;

    let runtime = tokio::runtime::Builder::new_multi_thread()
        .worker_threads(2)
        .enable_all()
        .build()
        .context("tokio runtime")?;
    // From here on SIGINT and SIGTERM hold the robot and close the recording (before the recording
    // and the DDS participant exist, so neither is left half made).
    let (stop, stop_task) = {
        let _context = runtime.enter();
        StopFlag::spawn()?
    };
    let mut recording = Recording {
        recorder: args
            .record
            .as_deref()
            .map(|path| -> anyhow::Result<McapRecorder> {
                Ok(McapRecorder::from_file(output::create(
                    "--record", path, args.force,
                )?)?)
            })
            .transpose()?,
        failure: None,
        reported: false,
    };
    let scope = network_scope(&ros)?;
    let enclave = security_enclave(
        &ros,
        &args.config,
        args.keystore.as_deref(),
        "/ergocell/cell",
    )?;
    let mut node = RosNode::new(
        ros.domain_id,
        &ros.namespace,
        &ros.node_name,
        &scope,
        enclave.as_deref(),
    )?;
    let participant = node.participant();
    runtime.spawn(node.spinner()?);
    let display = match args.display {
        Some(addr) => {
            let (listener, bound) = ergocell::display::bind(addr)
                .map_err(|e| UsageError(format!("--display: cannot listen on {addr}: {e}")))?;
            let display = ergocell::display::Display::new();
            let served = display.clone();
            // served until the process ends (the runtime is dropped with it)
            runtime.spawn(async move {
                if let Err(e) =
                    ergocell::display::serve(listener, served, std::future::pending()).await
                {
                    tracing::error!("operator display: {e}");
                }
            });
            println!("operator display: http://{bound}/");
            Some(display)
        }
        None => None,
    };
    let result = runtime.block_on(async {
        let CellTopics {
            cameras,
            joint_states,
            joint_trajectory,
            session_state,
            session_events,
            ergonomics,
            reba,
            warnings,
            skeleton,
            controller_events,
            driver,
        } = CellTopics::new(&mut node, &ros)?;
        let out = Outputs {
            session_state,
            session_events,
            ergonomics,
            reba,
            warnings,
            skeleton,
            controller_events,
        };
        let latest = Arc::new(Mutex::new(None::<JointState>));
        let (reports_tx, mut controller_reports) =
            tokio::sync::mpsc::unbounded_channel::<ControllerReport>();
        let action = match ros.robot_interface {
            RobotInterface::Topic => None,
            RobotInterface::Action => {
                let (tx, rx) = tokio::sync::mpsc::unbounded_channel();
                let timeout = Duration::from_secs(5);
                let name = &ros.follow_joint_trajectory_action;
                match ros.feedback_layout() {
                    Some(FeedbackLayout::WithIndex) => {
                        let client = node.follow_joint_trajectory_client::<FeedbackWithIndex>(name)?;
                        tokio::spawn(run_controller(client, rx, reports_tx, timeout));
                    }
                    Some(FeedbackLayout::WithoutIndex) | None => {
                        let client =
                            node.follow_joint_trajectory_client::<FeedbackWithoutIndex>(name)?;
                        tokio::spawn(run_controller(client, rx, reports_tx, timeout));
                    }
                }
                Some((tx, ros.goal_tolerances()))
            }
        };
        let mut controller_failure: Option<String> = None;
        // A goal the controller accepted and has not finished: its result is waited for (2 s at
        // most) before run exits, so the last leg's result is on record.
        let mut goal_outstanding = false;
        let mut robot = RosRobot {
            publisher: Arc::new(joint_trajectory),
            action,
            latest: latest.clone(),
            ros: ros.clone(),
            monitor: Arc::new(Mutex::new(None)),
            events: Vec::new(),
        };
        // The execution monitor runs in its own task (below): the hold's latency after a bad sample,
        // and whether the joint states are stale, as it reported them.
        let mut hold_after_bad_ms: Option<f64> = None;
        let mut stale: Option<String> = None;
        let mut driver_state = driver.as_ref().map(|_| DriverState::default());
        let mut driver_said: Option<Option<String>> = None;
        let (mut configured_stream, mut hardware_stream) = match &driver {
            Some((c, h)) => (c.async_stream().boxed(), h.async_stream().boxed()),
            None => (
                futures::stream::pending().boxed(),
                futures::stream::pending().boxed(),
            ),
        };
        let mut camera_stream =
            futures::stream::select_all(cameras.iter().map(|s| Box::pin(s.async_stream())));
        let mut geometry: Option<(
            ergocell_robot::TrajectoryClass,
            ergocell::robot_markers::RobotGeometry,
        )> = None;
        let mut last_marker_nanos = i64::MIN / 2;
        let mut tick = tokio::time::interval(Duration::from_millis(20));
        let mut interrupted: Option<Signal> = None;
        let mut clock = SessionClock::start();
        let started = clock.now();
        let stats = Arc::new(Mutex::new(MonitorStats::default()));
        let (notes_tx, mut monitor_notes) = tokio::sync::mpsc::unbounded_channel();
        let monitor_task = tokio::spawn(monitor_task(
            joint_states,
            MonitorLinks {
                monitor: robot.monitor.clone(),
                latest: latest.clone(),
                hold: robot.publisher.clone(),
                cancel: robot.action.as_ref().map(|(tx, _)| tx.clone()),
                notes: notes_tx,
                stats: stats.clone(),
            },
            clock.clone(),
            ros.joint_state_timeout_s,
        ));
        let cpu0 = cpu_secs();
        let wall0 = instant();
        let mut latencies_ms: Vec<f64> = Vec::new();
        let mut rejected = 0u64;
        let mut sessions_done = 0u32;
        println!(
            "ergocell run: node {}/{} on DDS domain {} ({scope}), {} camera topics, robot on {}",
            ros.namespace,
            ros.node_name,
            ros.domain_id,
            cameras.len(),
            match ros.robot_interface {
                RobotInterface::Topic => format!("{} (topic)", ros.joint_trajectory_topic),
                RobotInterface::Action => format!(
                    "{} (FollowJointTrajectory, control_msgs of {}; tolerances: path from the lock, at most {} rad, goal {} rad, {} s)",
                    ros.follow_joint_trajectory_action,
                    ros.distro,
                    ros.path_tolerance_rad,
                    ros.goal_tolerance_rad,
                    ros.goal_time_tolerance_s
                ),
            }
        );
        println!(
            "execution monitor: {}; driver state: {}",
            if ros.monitor_execution {
                format!(
                    "on (every {} sample against the lock; stale after {} s)",
                    ros.joint_states_topic, ros.joint_state_timeout_s
                )
            } else {
                "off ([ros] monitor_execution = false)".to_owned()
            },
            if ros.driver_state {
                format!("{} and {}", ros.is_configured_topic, ros.hardware_event_topic)
            } else {
                "not read ([ros] driver_state = false)".to_owned()
            }
        );
        let first = messages::session_state_message(&machine, started, "started");
        publish(&out.session_state, first.clone()).await?;
        publish(&out.session_events, first).await?;
        loop {
            let mut arrival = None;
            let views = tokio::select! {
                Some(item) = camera_stream.next() => {
                    arrival = Some(instant());
                    match item {
                        Ok((m, _info)) => {
                            let m: CameraLandmarks = m;
                            recording.with(|rec| rec.write(&topics::camera(&m.camera_id), clock.now(), &m));
                            match messages::view_from_message_with(&rig, &video_geometries, &m) {
                                Ok(v) => vec![v],
                                Err(e) => {
                                    rejected += 1;
                                    tracing::warn!(error = %e, "camera message rejected");
                                    Vec::new()
                                }
                            }
                        }
                        Err(e) => {
                            tracing::warn!(error = ?e, "camera read error");
                            Vec::new()
                        }
                    }
                }
                Some(note) = monitor_notes.recv() => match note {
                    MonitorNote::Sample(js, now) => {
                        record_joint_state(&mut recording, &machine, &mut geometry, &mut last_marker_nanos, &js, now, || {
                            FileTrajectories::new(&args.config, &args.trajectories, &approvals)
                        });
                        continue;
                    }
                    MonitorNote::Deviation { event, held_after_ms } => {
                        println!("  {} — cancelled and held {held_after_ms:.3} ms after the sample arrived", event.text);
                        hold_after_bad_ms = Some(held_after_ms);
                        controller_failure.get_or_insert(event.text.clone());
                        robot.events.push(event);
                        Vec::new()
                    }
                    MonitorNote::Stale(event) => {
                        println!("  {}", event.text);
                        stale = Some(event.text.clone());
                        robot.events.push(event);
                        Vec::new()
                    }
                    MonitorNote::Back(event) => {
                        stale = None;
                        robot.events.push(event);
                        Vec::new()
                    }
                },
                Some(report) = controller_reports.recv() => {
                    println!("  controller: {}", report.describe());
                    tracing::info!(?report, "controller");
                    goal_outstanding = report.goal_running();
                    let now = clock.now();
                    if matches!(report, ControllerReport::Accepted { .. }) {
                        // The controller starts an accepted goal now.
                        if let Some(m) = robot.monitor.lock().ok().as_mut().and_then(|g| g.as_mut()) {
                            m.leg_started(now);
                        }
                    }
                    robot.events.push(report.to_message(now));
                    if let Some(why) = report.failure() {
                        controller_failure.get_or_insert(why);
                    }
                    Vec::new()
                }
                Some(item) = configured_stream.next() => {
                    if let (Ok((m, _)), Some(d)) = (item, driver_state.as_mut()) {
                        let m: ergocell_bridge::msg::BoolMsg = m;
                        d.configured = Some(m.data);
                    }
                    Vec::new()
                }
                Some(item) = hardware_stream.next() => {
                    if let (Ok((m, _)), Some(d)) = (item, driver_state.as_mut()) {
                        let m: ergocell_bridge::msg::HardwareEvent = m;
                        println!("  driver: {} ({})", m.describe(), m.robot_name);
                        d.on_event(&m);
                    }
                    Vec::new()
                }
                _ = tick.tick() => Vec::new(),
            };
            let now = clock.now();
            if let Some(step) = clock.wall_step(now_nanos(), now) {
                println!(
                    "  wall clock stepped by {:+.3} s: session timing goes on unchanged (monotonic)",
                    step as f64 * 1e-9
                );
                tracing::warn!(step_s = step as f64 * 1e-9, "wall clock stepped");
            }
            // The robot side's readiness: the driver (configured, controlling), fresh joint states.
            if let Some(d) = driver_state.as_ref() {
                let why = d.unready();
                if driver_said.as_ref() != Some(&why) {
                    let text = why.clone().unwrap_or_else(|| "configured and controlling".to_owned());
                    println!("  driver: {text}");
                    let status = if why.is_some() { "not_ready" } else { "ready" };
                    let e = ControllerEvent {
                        status: status.to_owned(),
                        ..controller_event(now, "driver", "", text)
                    };
                    robot.events.push(e);
                    driver_said = Some(why);
                }
            }
            machine.set_robot_unready(
                driver_said
                    .clone()
                    .flatten()
                    .or_else(|| stale.clone()),
            );
            // Flushed on the clock, not only when messages arrive (kill -9 loses at most a second).
            recording.with(|rec| rec.tick(now));
            // Why the session must end now, if it must, in this order: a recording that cannot be
            // written (disk full, the disk gone: a cell that records must not run on unrecorded;
            // nothing more is recorded); the controller refused, aborted or did not answer a goal
            // (its reason; a person must look); Ctrl-C or SIGTERM; --max-secs. Each holds the robot.
            let end = if let Some(why) = recording.new_failure() {
                Some((format!("recording failed: {why}"), false))
            } else if let Some(why) = controller_failure.take() {
                Some((why, true))
            } else if let Some(signal) = stop.get() {
                interrupted = Some(signal);
                Some((signal.name().to_owned(), true))
            } else if args
                .max_secs
                .is_some_and(|limit| (now - started) as f64 * 1e-9 > limit)
            {
                Some(("--max-secs reached".to_owned(), true))
            } else {
                None
            };
            if let Some((why, record)) = end {
                let events = machine.shutdown(now, &mut robot, &why);
                if let Some(d) = &display {
                    d.update(&machine, &events);
                }
                flush_controller_events(&mut robot.events, &out, &mut recording, now).await?;
                for e in &events {
                    println!("  {}", messages::describe(e));
                }
                let outgoing = messages::step_messages(&machine, now, &events);
                publish_messages(&outgoing, &out).await?;
                if record {
                    recording.with(|rec| recording::record(rec, now, &outgoing));
                }
                break;
            }
            let events = machine.step(now, views, &mut robot);
            if let Some(d) = &display {
                d.update(&machine, &events);
            }
            for e in &events {
                if !matches!(e, SessionEvent::Frame { .. }) {
                    println!("  {}", messages::describe(e));
                }
            }
            flush_controller_events(&mut robot.events, &out, &mut recording, now).await?;
            let outgoing = messages::step_messages(&machine, now, &events);
            let published_frame = publish_messages(&outgoing, &out).await?;
            if let (Some(t0), true) = (arrival, published_frame) {
                latencies_ms.push(t0.elapsed().as_secs_f64() * 1e3);
            }
            recording.with(|rec| recording::record(rec, now, &outgoing));
            if machine.state() == SessionState::SessionEnded {
                sessions_done += 1;
                let more = args.sessions.is_none_or(|n| sessions_done < n);
                if machine.summary().ended && more {
                    print_summary(&machine, rejected);
                    machine = new_machine()?;
                    println!("next session: waiting for an operator");
                    continue;
                }
                break;
            }
        }
        let drain_until = tokio::time::Instant::now() + Duration::from_secs(2);
        while goal_outstanding {
            match tokio::time::timeout_at(drain_until, controller_reports.recv()).await {
                Ok(Some(report)) => {
                    println!("  controller: {}", report.describe());
                    goal_outstanding = report.goal_running();
                    let now = clock.now();
                    robot.events.push(report.to_message(now));
                    flush_controller_events(&mut robot.events, &out, &mut recording, now).await?;
                }
                Ok(None) | Err(_) => break,
            }
        }
        print_summary(&machine, rejected);
        monitor_task.abort();
        if let (Ok(guard), Ok(st)) = (robot.monitor.lock(), stats.lock()) {
            if let Some(m) = guard.as_ref() {
                let mut v = st.verdict_us.clone();
                v.sort_by(f64::total_cmp);
                let mut t = st.transit_us.clone();
                t.sort_by(f64::total_cmp);
                let (ratio, joint) = m.worst_path_ratio();
                println!(
                    "execution monitor: {} joint states judged, arrival → verdict p50 {:.1} µs, p99 {:.1} µs, max {:.1} µs; sample stamp → arrival (the controller's clock: a like-for-like figure only for a controller on this host) p50 {:.3} ms, p99 {:.3} ms; largest deviation while moving {:.2} of the path tolerance ({joint}); path tolerances [{}] rad{}",
                    v.len(),
                    percentile(&v, 0.5),
                    percentile(&v, 0.99),
                    v.last().copied().unwrap_or(f64::NAN),
                    percentile(&t, 0.5) * 1e-3,
                    percentile(&t, 0.99) * 1e-3,
                    ratio,
                    radians_list(&m.settings().path_tolerance_rad),
                    hold_after_bad_ms.map_or_else(String::new, |ms| format!(
                        "; cancelled and held {ms:.3} ms after the bad sample arrived"
                    ))
                );
            }
        }
        if args.latency_report {
            latencies_ms.sort_by(f64::total_cmp);
            let wall = wall0.elapsed().as_secs_f64();
            let cpu = cpu0.zip(cpu_secs()).map(|(a, b)| b - a);
            println!(
                "latency (camera message arrival → RULA state published): n = {}, p50 = {:.3} ms, p99 = {:.3} ms, max = {:.3} ms; CPU {}",
                latencies_ms.len(),
                percentile(&latencies_ms, 0.5),
                percentile(&latencies_ms, 0.99),
                latencies_ms.last().copied().unwrap_or(f64::NAN),
                cpu.map_or("n/a".to_owned(), |c| format!(
                    "{c:.2} s over {wall:.1} s = {:.1} % of one core",
                    100.0 * c / wall
                ))
            );
        }
        if let Some(signal) = interrupted {
            return Err(Stopped {
                signal,
                what: match &args.record {
                    Some(p) => format!("robot held, recording {} closed", p.display()),
                    None => "robot held".to_owned(),
                },
            }
            .into());
        }
        if machine.state() == SessionState::SessionEnded && !machine.summary().ended {
            anyhow::bail!("session {}", machine.summary().end_reason);
        }
        anyhow::Ok(())
    });
    stop_task.abort();
    // The node first (it tells the spinner to stop), then a moment for the spinner to finish while
    // the runtime still runs: every reader and writer says goodbye before the DDS participant goes.
    drop(node);
    runtime.block_on(async { tokio::time::sleep(Duration::from_millis(100)).await });
    drop(runtime);
    // the participant last: every entity has been removed from it (RosNode::participant)
    drop(participant);
    // The recording is closed (summary and footer) on every way out: a normal end, a signal, an error.
    let closed = match recording.failure {
        // nothing more is written into a failed recording: what reached the disk stays readable
        // (the session's own error says why it ended)
        Some(_) => {
            eprintln!(
                "note: the recording holds what was written before it failed, without its footer"
            );
            Ok(None)
        }
        None => recording
            .recorder
            .map(McapRecorder::finish)
            .transpose()
            .map_err(|e| anyhow::Error::new(e).context("closing the recording")),
    };
    match (result, closed) {
        (Ok(()), Ok(_)) => Ok(()),
        (Ok(()), Err(e)) | (Err(e), Ok(_)) => Err(e),
        (Err(e), Err(c)) => Err(e.context(format!("and the recording could not be closed: {c}"))),
    }
}

/// `run`'s recording: the recorder while it works, and the first write error, after which nothing
/// more is written (and the session is held: the loop checks [`Recording::new_failure`]).
struct Recording {
    recorder: Option<McapRecorder>,
    failure: Option<String>,
    reported: bool,
}

impl Recording {
    /// Recording, and nothing has failed.
    fn is_on(&self) -> bool {
        self.recorder.is_some() && self.failure.is_none()
    }

    /// Runs one write; its error is kept (logged once) instead of ending the loop unheld.
    fn with(
        &mut self,
        write: impl FnOnce(&mut McapRecorder) -> Result<(), recording::RecordingError>,
    ) {
        if !self.is_on() {
            return;
        }
        if let Some(rec) = self.recorder.as_mut() {
            if let Err(e) = write(rec) {
                // the whole chain: "MCAP: I/O error …: No space left on device (os error 28)"
                let mut why = e.to_string();
                let mut source = std::error::Error::source(&e);
                while let Some(s) = source {
                    let text = s.to_string();
                    if !why.contains(&text) {
                        why = format!("{why}: {text}");
                    }
                    source = s.source();
                }
                tracing::error!(error = %why, "the recording cannot be written");
                self.failure = Some(why);
            }
        }
    }

    /// The failure, the first time it is asked for after it happened.
    fn new_failure(&mut self) -> Option<String> {
        if self.reported {
            return None;
        }
        let f = self.failure.clone()?;
        self.reported = true;
        Some(f)
    }
}

fn print_summary(machine: &SessionMachine, rejected: u64) {
    let s = machine.summary();
    println!(
        "session: {} — {} frames fused, {} tracked, class {}, lock {}, {} hold(s), {} robot command(s), {} part(s) taken, {} camera message(s) rejected; {}",
        machine.state(),
        s.frames_fused,
        s.frames_tracked,
        s.class.as_deref().unwrap_or("-"),
        s.lock_sha256.as_deref().unwrap_or("-"),
        s.holds,
        s.robot_commands,
        s.parts_taken,
        rejected,
        s.end_reason
    );
    if !s.cameras_out_of_calibration.is_empty() {
        println!(
            "recalibrate: {} (found out of calibration during the session, left out of fusion)",
            s.cameras_out_of_calibration.join(", ")
        );
    }
}

/// The cell's outputs.
struct Outputs {
    session_state: Publisher<ergocell_bridge::msg::SessionState>,
    /// The same messages, every one (deeper history).
    session_events: Publisher<ergocell_bridge::msg::SessionState>,
    ergonomics: Publisher<ergocell_bridge::msg::ErgonomicState>,
    reba: Publisher<ergocell_bridge::msg::RebaState>,
    warnings: Publisher<ergocell_bridge::msg::PostureWarning>,
    skeleton: Publisher<ergocell_bridge::msg::MarkerArray>,
    controller_events: Publisher<ControllerEvent>,
}

/// Publishes and records the robot side's events, in order.
async fn flush_controller_events(
    events: &mut Vec<ControllerEvent>,
    out: &Outputs,
    recording: &mut Recording,
    now: i64,
) -> anyhow::Result<()> {
    for e in events.drain(..) {
        recording.with(|rec| rec.write(topics::CONTROLLER_EVENTS, now, &e));
        publish(&out.controller_events, e).await?;
    }
    Ok(())
}

/// Publishes a step's outgoing messages (the same ones the recorder writes); true if a RULA state
/// was published. The robot command is the robot sink's to publish; the operator pose is recorded
/// only.
async fn publish_messages(messages: &[Outgoing], out: &Outputs) -> anyhow::Result<bool> {
    let mut frame = false;
    for m in messages {
        match m {
            Outgoing::SessionState(m) => {
                publish(&out.session_state, m.clone()).await?;
                publish(&out.session_events, m.clone()).await?;
            }
            Outgoing::Ergonomics(m) => {
                publish(&out.ergonomics, m.clone()).await?;
                frame = true;
            }
            Outgoing::Reba(m) => publish(&out.reba, m.clone()).await?,
            Outgoing::Warning(m) => publish(&out.warnings, m.clone()).await?,
            Outgoing::Skeleton(m) => publish(&out.skeleton, m.clone()).await?,
            Outgoing::OperatorPose(_) | Outgoing::Trajectory(_) => {}
        }
    }
    Ok(frame)
}

pub fn replay(args: &ReplayArgs) -> anyhow::Result<()> {
    if !args.ros {
        return Err(UsageError("replay publishes over ROS 2: pass --ros".to_owned()).into());
    }
    if !SPEED_RANGE.contains(&args.speed) {
        return Err(UsageError(format!(
            "--speed {:?}: must be a factor from {} to {}",
            args.speed,
            SPEED_RANGE.start(),
            SPEED_RANGE.end()
        ))
        .into());
    }
    let (cell_text, cell_label) = ergocell::shipped::read_or_shipped(&args.config)?;
    let ros = RosConfig::from_cell_toml(&cell_text)
        .map_err(|e| UsageError(format!("{cell_label}: {e}")))?;
    let bytes = std::fs::read(&args.recording)
        .with_context(|| format!("cannot read {}", args.recording.display()))?;
    // Camera messages in log-time order; a recording cut by a crash is read up to its last chunk.
    let recording::CameraReadout {
        mut frames,
        damaged,
        undecodable,
    } = recording::read_camera_landmarks(&bytes)
        .map_err(|e| UsageError(format!("{}: {e}", args.recording.display())))?;
    // A damaged or cut recording is replayed up to where it can be read, and says so.
    if let Some(e) = damaged {
        eprintln!(
            "warning: {}: the recording cannot be read past {} camera messages ({e}); replaying \
             those",
            args.recording.display(),
            frames.len()
        );
    }
    if undecodable > 0 {
        eprintln!(
            "warning: {}: {undecodable} camera messages do not decode as CameraLandmarks and are \
             skipped",
            args.recording.display()
        );
    }
    frames.sort_by_key(|(t, _)| *t);
    if frames.is_empty() {
        return Err(UsageError(format!(
            "{}: no camera landmarks in the recording",
            args.recording.display()
        ))
        .into());
    }
    let runtime = tokio::runtime::Builder::new_multi_thread()
        .worker_threads(2)
        .enable_all()
        .build()
        .context("tokio runtime")?;
    let scope = network_scope(&ros)?;
    let enclave = security_enclave(
        &ros,
        &args.config,
        args.keystore.as_deref(),
        "/ergocell/replay",
    )?;
    let mut node = RosNode::new(
        ros.domain_id,
        &ros.namespace,
        "replay",
        &scope,
        enclave.as_deref(),
    )?;
    let participant = node.participant();
    runtime.spawn(node.spinner()?);
    let result = runtime.block_on(async {
        let mut publishers = std::collections::BTreeMap::new();
        for id in &ros.cameras {
            let p =
                node.publisher::<CameraLandmarks>(&ros.camera_topic_of(id), qos::CAMERA_LANDMARKS)?;
            publishers.insert(id.clone(), p);
        }
        // Give discovery a moment before the first frame.
        tokio::time::sleep(Duration::from_millis(1500)).await;
        let t0_log = frames[0].0;
        let t0 = instant();
        let start = now_nanos();
        let mut sent = 0usize;
        for (log_time, mut m) in frames {
            let offset_secs = log_time.saturating_sub(t0_log) as f64 * 1e-9 / args.speed;
            // Never a panic on a huge offset (a recording spanning centuries at a slow speed).
            let due = Duration::try_from_secs_f64(offset_secs).unwrap_or(Duration::MAX);
            if let Some(wait) = due.checked_sub(t0.elapsed()) {
                tokio::time::sleep(wait).await;
            }
            // Re-stamp as a live camera would: capture time now.
            m.header.stamp =
                ergocell_bridge::msg::Time::from_nanos(start + (offset_secs * 1e9) as i64);
            if let Some(p) = publishers.get(&m.camera_id) {
                publish(p, m).await?;
                sent += 1;
            }
        }
        println!(
            "replayed {sent} camera messages from {}",
            args.recording.display()
        );
        anyhow::Ok(())
    });
    // The node first (it tells the spinner to stop), then a moment for the spinner to finish while
    // the runtime still runs: every reader and writer says goodbye before the DDS participant goes.
    drop(node);
    runtime.block_on(async { tokio::time::sleep(Duration::from_millis(100)).await });
    drop(runtime);
    // the participant last: every entity has been removed from it (RosNode::participant)
    drop(participant);
    result
}

/// The SROS2 enclave folder for this node, or `None` without DDS Security (said on stdout either way),
/// from `--keystore`, the ROS_SECURITY_* variables and `[ros]` (`security_required`, `keystore`
/// relative to the cell file's folder).
fn security_enclave(
    ros: &RosConfig,
    config: &std::path::Path,
    cli: Option<&std::path::Path>,
    default_enclave: &str,
) -> anyhow::Result<Option<PathBuf>> {
    use ergocell_bridge::security::{resolve_security, SecurityDecision, SecurityEnv};
    let var = |name: &str| std::env::var(name).ok();
    let env = SecurityEnv {
        enable: var("ROS_SECURITY_ENABLE"),
        strategy: var("ROS_SECURITY_STRATEGY"),
        keystore: var("ROS_SECURITY_KEYSTORE"),
        enclave_override: var("ROS_SECURITY_ENCLAVE_OVERRIDE"),
    };
    let config_keystore = ros.keystore.as_ref().map(|k| {
        config
            .parent()
            .unwrap_or_else(|| std::path::Path::new("."))
            .join(k)
    });
    let decision = resolve_security(
        ros.security_required,
        config_keystore.as_deref(),
        cli,
        default_enclave,
        &env,
        |dir| {
            ergocell_bridge::transport::ENCLAVE_FILES
                .iter()
                .all(|f| dir.join(f).is_file())
        },
    )
    .map_err(|e| UsageError(e.to_string()))?;
    Ok(match decision {
        SecurityDecision::Off(why) => {
            println!("{why}");
            None
        }
        SecurityDecision::Enclave { name, dir } => {
            println!(
                "DDS Security on: enclave {name} ({}): authenticated, access-controlled, encrypted",
                dir.display()
            );
            Some(dir)
        }
    })
}

/// The DDS participant's network scope from `[ros]` and the ROS 2 environment variables
/// (`ROS_AUTOMATIC_DISCOVERY_RANGE`, `ROS_STATIC_PEERS`, `ROS_LOCALHOST_ONLY`).
fn network_scope(ros: &RosConfig) -> anyhow::Result<ergocell_bridge::scope::NetworkScope> {
    let var = |name: &str| std::env::var(name).ok();
    let env = ergocell_bridge::scope::ScopeEnv {
        automatic_discovery_range: var("ROS_AUTOMATIC_DISCOVERY_RANGE"),
        static_peers: var("ROS_STATIC_PEERS"),
        localhost_only: var("ROS_LOCALHOST_ONLY"),
    };
    Ok(ergocell_bridge::scope::NetworkScope::resolve(
        ros.discovery_range,
        ros.interfaces.as_deref(),
        &env,
    )?)
}

#[cfg(test)]
mod tests {
    use super::SessionClock;

    #[test]
    fn session_clock_reports_each_wall_clock_step_once_and_ignores_drift() {
        let mono0 = super::instant();
        let mut clock = SessionClock::anchored(1_000_000_000_000, mono0);
        let now = clock.now();
        assert!(now >= 1_000_000_000_000);
        // Drift under a second: not a step.
        assert_eq!(clock.wall_step(now + 400_000_000, now), None);
        // One hour forward: reported once, then the new reference.
        let hour = 3_600_000_000_000;
        assert_eq!(clock.wall_step(now + hour, now), Some(hour));
        assert_eq!(clock.wall_step(now + hour + 200_000_000, now), None);
        // Back by ten minutes from there.
        assert_eq!(
            clock.wall_step(now + hour - 600_000_000_000, now),
            Some(-600_000_000_000)
        );
        // The session clock never went back, whatever the wall clock did.
        assert!(clock.now() >= now);
    }
}
