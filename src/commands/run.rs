//! `ergocell run`: the session state machine on the ROS 2 backend.
//!
//! `run` subscribes to one landmark topic per camera and to `/joint_states`, commands the robot on the
//! joint trajectory controller's topic (a hold is an empty `JointTrajectory`: not an emergency stop),
//! and publishes the session state, the RULA state and the warnings. Topic names and the DDS domain
//! come from `[ros]` in the cell config; QoS from `ergocell_bridge::qos`. Ctrl-C (SIGINT) and SIGTERM
//! (systemd, `docker stop`, `timeout`) hold the robot (an empty trajectory, published), close the
//! recording with its summary and footer, and exit with 130 / 143.

use super::parse_operator;
use ergocell_bridge::session_info::OperatorId;
use std::path::PathBuf;
use std::sync::Arc;
use std::time::Duration;

use anyhow::Context as _;
use ergocell::session::provider::FileTrajectories;
use ergocell::session::{
    CellLoop, CellOutputs, Driver, ExitStatus, Input, Interruption, OutputError, ReportEffect,
    RobotReport, SessionEvent, SessionMachine, Station, Step, Timed,
};
use ergocell_bridge::action::{FeedbackLayout, FeedbackWithIndex, FeedbackWithoutIndex};
use ergocell_bridge::controller::{run_controller, ControllerCommand, ControllerReport};
use ergocell_bridge::msg::{CameraLandmarks, JointState};
use ergocell_bridge::transport::{
    publish, CellTopics, RobotInterface, RosConfig, RosNode, Subscription,
};
use ergocell_cell::CellSettings;
use ergocell_formats::rig_file::parse_rig;
use ergocell_perception::video_geometry::VideoGeometry;
use ergocell_perception::CameraRig;
use ergocell_robot::TrajectoryClass;
use ergocell_ros_backend::cameras::CameraInbox;
use ergocell_ros_backend::clock::{instant, now_nanos, SessionClock};
use ergocell_ros_backend::messages;
use ergocell_ros_backend::monitor::{monitor_task, Judge, MonitorNote, MonitorStats};
use ergocell_ros_backend::outputs::RosOutputs;
use ergocell_ros_backend::recording::{self, topics, McapRecorder, Recording};
use ergocell_ros_backend::robot::{announce_driver, radians_list, RobotInput, RosRobot};
use ergocell_ros_backend::robot_markers::RobotGeometry;
use ergocell_web::display::Display;
use futures::StreamExt as _;

use super::signals::{Signal, StopFlag, Stopped};
use super::{output, UsageError};

/// The longest `--max-secs`: a year.
const MAX_SECS_LIMIT: f64 = 365.0 * 24.0 * 3600.0;

#[derive(Debug, clap::Args)]
#[command(
    after_help = "Exit codes: 0 the sessions ended normally (--sessions reached); 1 a session \
    did not end normally (a trajectory that does not verify, --max-secs reached: robot held) or a \
    failure; 2 bad input (an existing --record file without --force); 130 stopped by Ctrl-C \
    (SIGINT), 143 stopped by SIGTERM (systemd: SuccessExitStatus=143) — in both the robot is held \
    (empty trajectory published) and the recording closed with its summary and footer."
)]
pub struct Args {
    /// Cell configuration: `[robot]`, `[station]`, `[monitor]` and `[ros]`.
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
    /// Overwrite an existing --record or --outcome file.
    #[arg(long)]
    pub force: bool,
    /// How the sessions ended, as JSON for a program (CI, a supervisor's script): the exit code,
    /// the last session's typed end, every command sent to the robot with its typed reason.
    /// Written when the sessions are over, on a stop signal too.
    #[arg(long, value_name = "FILE")]
    pub outcome: Option<PathBuf>,
    /// The operator's pseudonymous id, written into the --record file (letters, digits, '-', '_',
    /// '.'; never a name: the plant keeps the mapping). `ergocell exposure` groups by it.
    #[arg(long, value_name = "ID", value_parser = parse_operator, requires = "record")]
    pub operator: Option<OperatorId>,
    /// Stop (holding the robot) after this many seconds if the session has not ended (> 0, at most
    /// a year).
    #[arg(long)]
    pub max_secs: Option<f64>,
    /// Stop after this many sessions (default: one operator session after another until Ctrl-C). A
    /// session that ends without the operator leaving normally (e.g. a trajectory that does not
    /// verify) always stops the program with exit code 1: it needs a person.
    #[arg(long)]
    pub sessions: Option<u32>,
    /// Print the latency from the start of each step that publishes a RULA state (woken by a camera
    /// message, or by the clock releasing frames whose fixed lag has passed) to that state published
    /// (p50/p99), and the process's CPU use, at the end.
    #[arg(long)]
    pub latency_report: bool,
    /// SROS2 keystore (DDS Security, enclave `/ergocell/cell`, or ROS_SECURITY_ENCLAVE_OVERRIDE);
    /// default ROS_SECURITY_KEYSTORE, then `[ros] keystore`.
    #[arg(long)]
    pub keystore: Option<PathBuf>,
}

/// What `run` reads before it starts: the cell, the rig, the video geometries, the approvals.
struct Setup {
    ros: RosConfig,
    settings: CellSettings,
    rig: CameraRig,
    video_geometries: Vec<Option<VideoGeometry>>,
    config: PathBuf,
    trajectories: PathBuf,
    approvals: PathBuf,
}

impl Setup {
    fn load(args: &Args) -> anyhow::Result<Self> {
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
        Ok(Self {
            ros,
            settings,
            rig,
            video_geometries,
            config: args.config.clone(),
            trajectories: args.trajectories.clone(),
            approvals,
        })
    }

    fn provider(&self) -> FileTrajectories {
        ergocell::session::provider::on_disk(&self.config, &self.trajectories, &self.approvals)
    }

    fn new_machine(&self) -> anyhow::Result<SessionMachine> {
        SessionMachine::from_settings(self.rig.clone(), &self.settings, Box::new(self.provider()))
            .map_err(|e| anyhow::anyhow!(e))
    }
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
    let flagged = [
        ("--config", args.config.as_path()),
        ("--rig", args.rig.as_path()),
    ];
    if let Some(record) = &args.record {
        // Before anything is read: an existing file without --force, or a named input.
        output::check("--record", record, args.force, &flagged)?;
    }
    let setup = Setup::load(args)?;
    if let Some(record) = &args.record {
        // Every file the cell reads is an input, not only the ones named by a flag.
        let read = setup.provider().input_files();
        let mut inputs = flagged.to_vec();
        inputs.extend(read.iter().map(|p| ("a file the cell reads:", p.as_path())));
        output::check("--record", record, args.force, &inputs)?;
    }
    if let Some(path) = &args.outcome {
        let read = setup.provider().input_files();
        let mut inputs = flagged.to_vec();
        inputs.extend(args.record.iter().map(|p| ("--record", p.as_path())));
        inputs.extend(read.iter().map(|p| ("a file the cell reads:", p.as_path())));
        super::outcome::check(path, args.force, &inputs)?;
    }
    // The first session's machine before anything is started: a cell that cannot run is said now.
    let machine = setup.new_machine()?;
    // Which classes the robot can serve, said before anyone is measured.
    println!("{}", ApprovalSummary::of(&mut setup.provider()));
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
    let recorder = args
        .record
        .as_deref()
        .map(|path| -> anyhow::Result<McapRecorder> {
            let mut rec = McapRecorder::from_file(output::create("--record", path, args.force)?)?;
            if let Some(operator) = &args.operator {
                rec.write_operator(operator)?;
            }
            Ok(rec)
        })
        .transpose()?;
    let mut recording = Some(Recording::new(recorder));
    let ros = &setup.ros;
    let scope = network_scope(ros)?;
    let enclave = security_enclave(
        ros,
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
    let display = start_display(args.display, &runtime)?;
    let result = runtime.block_on(serve(
        args,
        &setup,
        machine,
        &mut node,
        &mut recording,
        display,
        &stop,
    ));
    stop_task.abort();
    // The node first (it tells the spinner to stop), then a moment for the spinner to finish while
    // the runtime still runs: every reader and writer says goodbye before the DDS participant goes.
    drop(node);
    runtime.block_on(async { tokio::time::sleep(Duration::from_millis(100)).await });
    drop(runtime);
    // the participant last: every entity has been removed from it (RosNode::participant)
    drop(participant);
    // The recording is closed (summary and footer) on every way out: a normal end, a signal, an error.
    let closed = match recording {
        // nothing more is written into a failed recording: what reached the disk stays readable
        // (the session's own error says why it ended)
        Some(r) if r.failed() => {
            eprintln!(
                "note: the recording holds what was written before it failed, without its footer"
            );
            Ok(None)
        }
        Some(r) => r
            .close()
            .map_err(|e| anyhow::Error::new(e).context("closing the recording")),
        None => Ok(None),
    };
    if let (Ok(Some(messages)), Some(path)) = (&closed, &args.record) {
        println!(
            "recording: {} ({messages} messages, {}-compressed chunks)",
            path.display(),
            recording::COMPRESSION
        );
    }
    match (result, closed) {
        (Ok(()), Ok(_)) => Ok(()),
        (Ok(()), Err(e)) | (Err(e), Ok(_)) => Err(e),
        (Err(e), Err(c)) => Err(e.context(format!("and the recording could not be closed: {c}"))),
    }
}

/// The operator display, served until the process ends (the runtime is dropped with it).
fn start_display(
    addr: Option<std::net::SocketAddr>,
    runtime: &tokio::runtime::Runtime,
) -> anyhow::Result<Option<Arc<Display>>> {
    let Some(addr) = addr else {
        return Ok(None);
    };
    let (listener, bound) = ergocell_web::display::bind(addr)
        .map_err(|e| UsageError(format!("--display: cannot listen on {addr}: {e}")))?;
    let display = Display::new();
    let served = display.clone();
    runtime.spawn(async move {
        if let Err(e) = ergocell_web::display::serve(listener, served, std::future::pending()).await
        {
            tracing::error!("operator display: {e}");
        }
    });
    println!("operator display: http://{bound}/");
    Ok(Some(display))
}

/// `run`'s outputs: the operator display, the console, then the ROS 2 topics and the recording.
struct RunOutputs {
    display: Option<Arc<Display>>,
    ros: RosOutputs,
}

impl CellOutputs for RunOutputs {
    fn session_step(
        &mut self,
        now: i64,
        machine: &SessionMachine,
        events: &[SessionEvent],
    ) -> Result<(), OutputError> {
        if let Some(d) = &self.display {
            d.update(machine, events);
        }
        for line in messages::describe_step(events) {
            println!("  {line}");
        }
        self.ros.session_step(now, machine, events)
    }

    fn take_failure(&mut self) -> Option<OutputError> {
        self.ros.take_failure()
    }
}

type RunLoop = CellLoop<RosRobot, RunOutputs>;

/// The FollowJointTrajectory task (with `robot_interface = "action"`): its command channel and its
/// reports.
#[allow(clippy::type_complexity)]
fn controller_task(
    node: &mut RosNode,
    ros: &RosConfig,
) -> anyhow::Result<(
    Option<tokio::sync::mpsc::UnboundedSender<ControllerCommand>>,
    tokio::sync::mpsc::UnboundedReceiver<ControllerReport>,
)> {
    let (reports_tx, reports) = tokio::sync::mpsc::unbounded_channel::<ControllerReport>();
    if ros.robot_interface == RobotInterface::Topic {
        return Ok((None, reports));
    }
    let (tx, rx) = tokio::sync::mpsc::unbounded_channel();
    let timeout = Duration::from_secs(5);
    let name = &ros.follow_joint_trajectory_action;
    if ros.feedback_layout() == Some(FeedbackLayout::WithIndex) {
        let client = node.follow_joint_trajectory_client::<FeedbackWithIndex>(name)?;
        tokio::spawn(run_controller(client, rx, reports_tx, timeout));
    } else {
        let client = node.follow_joint_trajectory_client::<FeedbackWithoutIndex>(name)?;
        tokio::spawn(run_controller(client, rx, reports_tx, timeout));
    }
    Ok((Some(tx), reports))
}

/// How long `run` waits, before it exits, for its last messages to be acknowledged.
const COMMAND_ACK_WAIT: Duration = Duration::from_secs(2);

/// Before the node and the process go: a publish only queues a sample, and the last step's messages
/// (the hold, when a session ended early, then the session's final state and events) must not leave
/// with the process. Waits, within one [`COMMAND_ACK_WAIT`], until every matched reliable reader
/// has acknowledged them: the robot's commands first (said when the controller has not), then the
/// session state, its events and the controller events. A topic nobody reads has nothing to wait
/// for; a best-effort reader acknowledges nothing.
fn wait_delivered(cell: &RunLoop) {
    let deadline = instant() + COMMAND_ACK_WAIT;
    let left = || deadline.saturating_duration_since(instant());
    match cell.robot().commands_delivered(left()) {
        Ok(true) => {}
        Ok(false) => say(Some(format!(
            "warning: the controller has not acknowledged the robot's last command within {} s \
             (is its node still running?)",
            COMMAND_ACK_WAIT.as_secs_f64()
        ))),
        Err(e) => say(Some(format!("warning: the robot's last command: {e}"))),
    }
    let p = &cell.outputs().ros.publishers;
    // Best effort within what is left: these readers are told, not obeyed.
    let _ = p.session_state.wait_for_acknowledgments(left());
    let _ = p.session_events.wait_for_acknowledgments(left());
    let _ = p.controller_events.wait_for_acknowledgments(left());
}

/// The sessions on the ROS 2 node: the cell loop fed by the camera topics, the monitor task, the
/// controller's reports, the driver's state and a 20 ms tick, until the sessions are done or one
/// ends early. The recording is taken from `recording` and put back.
async fn serve(
    args: &Args,
    setup: &Setup,
    machine: SessionMachine,
    node: &mut RosNode,
    recording: &mut Option<Recording>,
    display: Option<Arc<Display>>,
    stop: &StopFlag,
) -> anyhow::Result<()> {
    let ros = &setup.ros;
    let scope = network_scope(ros)?;
    let topics = CellTopics::new(node, ros)?;
    let (action, reports) = controller_task(node, ros)?;
    let robot = RosRobot::new(Arc::new(topics.joint_trajectory), action, ros.clone());
    let clock = SessionClock::start();
    let judge = Judge::new(robot.monitor(), robot.latest(), robot.port());
    let stats = judge.stats.clone();
    let (notes_tx, notes) = tokio::sync::mpsc::unbounded_channel();
    let monitor = tokio::spawn(monitor_task(
        topics.joint_states,
        judge,
        notes_tx,
        clock.clone(),
    ));
    let outputs = RunOutputs {
        display,
        ros: RosOutputs {
            events: robot.events(),
            publishers: topics.publishers,
            recording: recording.take().unwrap_or_else(|| Recording::new(None)),
            published_frame: false,
        },
    };
    let mut cell = ergocell_ros_backend::robot::cell_loop(machine, robot, outputs);
    if args.outcome.is_some() {
        cell = cell.with_command_log();
    }
    if let Some(limit) = args.max_secs {
        let at = clock.now() + (limit * 1e9).round() as i64;
        cell = cell.with_deadline(at, limit);
    }
    print_start(ros, topics.cameras.len(), &scope);
    say(multicast_note(&scope));
    let first = messages::session_state_message(cell.machine(), clock.now(), "started");
    let p = &cell.outputs().ros.publishers;
    let started = async {
        publish(&p.session_state, first.clone()).await?;
        publish(&p.session_events, first).await
    };
    if let Err(e) = started.await {
        monitor.abort();
        let (_, _, outputs) = cell.into_parts();
        *recording = Some(outputs.ros.recording);
        return Err(e.into());
    }
    let readiness = cell.driver_readiness();
    say(announce_driver(&mut cell, clock.now(), readiness));
    let mut station = RunStation::new(
        setup,
        &topics.cameras,
        topics.driver.as_ref(),
        notes,
        reports,
        clock,
    );
    // The sessions, one after another, by the cell's rules (the session driver's).
    let mut driver = Driver::new(cell, args.sessions);
    let outcome = driver.run(&mut station, stop).await;
    monitor.abort();
    let cell = driver.into_cell();
    tokio::task::block_in_place(|| wait_delivered(&cell));
    if let Ok(stats) = stats.lock() {
        print_monitor(cell.robot(), &stats);
    }
    print_summary(cell.machine(), station.inbox.rejected());
    if args.latency_report {
        station.latency.print();
    }
    let monitor_held = cell.robot().held_after_ms().is_some();
    let (machine, _, outputs) = cell.into_parts();
    *recording = Some(outputs.ros.recording);
    // An input that failed ended the session held: its error is run's.
    let outcome = super::outcome::written(
        outcome,
        args.outcome.as_deref(),
        args.force,
        machine.summary(),
        monitor_held,
    )?;
    match outcome.status {
        ExitStatus::Done => Ok(()),
        ExitStatus::Stopped(signal) => Err(Stopped {
            signal: Signal::from(signal),
            what: match &args.record {
                Some(p) => format!("robot held, recording {} closed", p.display()),
                None => "robot held".to_owned(),
            },
        }
        .into()),
        ExitStatus::NeedsAPerson => {
            if let Some(Interruption::TimeLimit { limit_s }) = outcome.ending.interruption() {
                anyhow::bail!(
                    "session interrupted: --max-secs reached (robot held) after {limit_s} s"
                );
            }
            anyhow::bail!("session {}", machine.summary().end_reason)
        }
    }
}

type Items<'a, T> = futures::stream::LocalBoxStream<'a, Result<T, String>>;

/// `run`'s station: the camera topics through the inbox, the robot side's reports (the monitor
/// task, the controller task, the driver's topics) and a 20 ms tick, stamped by the session
/// clock; the recording's camera messages, joint states and markers; the latency report.
struct RunStation<'a> {
    setup: &'a Setup,
    cameras: Items<'a, CameraLandmarks>,
    configured: Items<'a, ergocell_bridge::msg::BoolMsg>,
    hardware: Items<'a, ergocell_bridge::msg::HardwareEvent>,
    notes: tokio::sync::mpsc::UnboundedReceiver<MonitorNote>,
    reports: tokio::sync::mpsc::UnboundedReceiver<ControllerReport>,
    tick: tokio::time::Interval,
    clock: SessionClock,
    inbox: CameraInbox,
    markers: Markers,
    latency: Latency,
    /// When the step now under way was woken (a camera message or the tick).
    woken: Option<std::time::Instant>,
    /// How long the controller's last answer is waited for after the last session.
    settle_until: Option<tokio::time::Instant>,
}

impl<'a> RunStation<'a> {
    fn new(
        setup: &'a Setup,
        cameras: &'a [Subscription<CameraLandmarks>],
        driver: Option<&'a (
            Subscription<ergocell_bridge::msg::BoolMsg>,
            Subscription<ergocell_bridge::msg::HardwareEvent>,
        )>,
        notes: tokio::sync::mpsc::UnboundedReceiver<MonitorNote>,
        reports: tokio::sync::mpsc::UnboundedReceiver<ControllerReport>,
        clock: SessionClock,
    ) -> Self {
        fn items<M: 'static + serde::de::DeserializeOwned>(s: &Subscription<M>) -> Items<'_, M> {
            s.async_stream()
                .map(|r| r.map(|(m, _)| m).map_err(|e| format!("{e:?}")))
                .boxed_local()
        }
        let (configured, hardware) = match driver {
            Some((c, h)) => (items(c), items(h)),
            None => (
                futures::stream::pending().boxed_local(),
                futures::stream::pending().boxed_local(),
            ),
        };
        Self {
            setup,
            cameras: futures::stream::select_all(cameras.iter().map(items)).boxed_local(),
            configured,
            hardware,
            notes,
            reports,
            tick: tokio::time::interval(Duration::from_millis(20)),
            clock,
            inbox: CameraInbox::new(setup.rig.clone(), setup.video_geometries.clone()),
            markers: Markers::default(),
            latency: Latency::start(),
            woken: None,
            settle_until: None,
        }
    }
}

/// The robot side's input in the cell's reports, its line said.
fn robot_input(cell: &mut RunLoop, now: i64, input: RobotInput) -> Input {
    let (reports, line) = ergocell_ros_backend::robot::reports_of(cell.robot_mut(), now, input);
    say(line);
    Input::Reports(reports)
}

impl Station<RosRobot, RunOutputs> for RunStation<'_> {
    type Error = anyhow::Error;

    fn name(&self) -> &'static str {
        "ROS 2 inputs"
    }

    fn now_nanos(&mut self) -> i64 {
        self.clock.now()
    }

    /// One camera message, robot-side report or 20 ms tick.
    async fn next(&mut self, cell: &mut RunLoop) -> anyhow::Result<Option<Timed>> {
        enum Woke {
            Camera(CameraLandmarks),
            Robot(RobotInput),
            Tick,
        }
        let woke = tokio::select! {
            Some(item) = self.cameras.next() => match item {
                Ok(m) => Woke::Camera(m),
                Err(e) => {
                    tracing::warn!(error = %e, "camera read error");
                    return Ok(None);
                }
            },
            Some(note) = self.notes.recv() => {
                if let MonitorNote::Sample(js, now) = &note {
                    self.markers.record(cell, js, *now, self.setup);
                    return Ok(None);
                }
                Woke::Robot(RobotInput::Monitor(note))
            }
            Some(report) = self.reports.recv() => Woke::Robot(RobotInput::Controller(report)),
            Some(Ok(m)) = self.configured.next() => Woke::Robot(RobotInput::DriverConfigured(m.data)),
            Some(Ok(m)) = self.hardware.next() => Woke::Robot(RobotInput::DriverEvent(m)),
            _ = self.tick.tick() => Woke::Tick,
        };
        // The step starts now, woken by a camera message or the clock's tick (which releases the
        // frames whose fixed lag has passed): the latency report times it to the RULA state.
        self.woken = Some(instant());
        let now = self.clock.now();
        if let Some(step) = self.clock.wall_step(now_nanos(), now) {
            println!(
                "  wall clock stepped by {:+.3} s: session timing goes on unchanged (monotonic)",
                step as f64 * 1e-9
            );
            tracing::warn!(step_s = step as f64 * 1e-9, "wall clock stepped");
        }
        // Flushed on the clock, not only when messages arrive (kill -9 loses at most a second).
        cell.outputs_mut().ros.recording.with(|rec| rec.tick(now));
        let input = match woke {
            Woke::Camera(m) => {
                cell.outputs_mut()
                    .ros
                    .recording
                    .with(|rec| rec.write(&topics::camera(&m.camera_id), now, &m));
                Input::Views(self.inbox.accept(&m).into_iter().collect())
            }
            Woke::Robot(input) => robot_input(cell, now, input),
            Woke::Tick => Input::Tick,
        };
        Ok(Some(Timed::new(now, input)))
    }

    fn reported(
        &mut self,
        cell: &mut RunLoop,
        at: i64,
        _report: &RobotReport,
        effect: &ReportEffect,
    ) -> anyhow::Result<()> {
        say(announce_driver(cell, at, effect.driver_readiness.clone()));
        Ok(())
    }

    fn stepped(&mut self, cell: &mut RunLoop, _at: i64, _step: &Step) -> anyhow::Result<()> {
        if cell.outputs().ros.published_frame {
            if let Some(woken) = self.woken.take() {
                self.latency.push(woken);
            }
        }
        Ok(())
    }

    fn next_machine(&mut self, cell: &mut RunLoop) -> anyhow::Result<SessionMachine> {
        print_summary(cell.machine(), self.inbox.rejected());
        self.setup.new_machine()
    }

    fn session_began(&mut self, cell: &mut RunLoop) {
        if let Some(d) = &cell.outputs().display {
            d.next_session(cell.machine());
        }
        println!("next session: waiting for an operator");
    }

    /// The controller's reports for at most 2 s after the last session, each published at once.
    async fn settle(&mut self, cell: &mut RunLoop) -> anyhow::Result<Option<Timed>> {
        let until = *self
            .settle_until
            .get_or_insert_with(|| tokio::time::Instant::now() + Duration::from_secs(2));
        let Ok(Some(report)) = tokio::time::timeout_at(until, self.reports.recv()).await else {
            return Ok(None);
        };
        let now = self.clock.now();
        let input = robot_input(cell, now, RobotInput::Controller(report));
        cell.outputs_mut().ros.flush_events(now)?;
        Ok(Some(Timed::new(now, input)))
    }
}

/// Prints a line about the robot side, if there is one.
pub(super) fn say(line: Option<String>) {
    if let Some(line) = line {
        println!("  {line}");
    }
}

fn print_start(ros: &RosConfig, cameras: usize, scope: &ergocell_bridge::scope::NetworkScope) {
    println!(
        "ergocell run: node {}/{} on DDS domain {} ({scope}), {cameras} camera topics, robot on {}",
        ros.namespace,
        ros.node_name,
        ros.domain_id,
        match ros.robot_interface {
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
            format!(
                "{} and {}",
                ros.is_configured_topic, ros.hardware_event_topic
            )
        } else {
            "not read ([ros] driver_state = false)".to_owned()
        }
    );
}

/// The execution monitor's figures at the end.
fn print_monitor(robot: &RosRobot, stats: &MonitorStats) {
    let monitor = robot.monitor();
    let Ok(guard) = monitor.lock() else {
        return;
    };
    let Some(m) = guard.monitor() else {
        return;
    };
    let mut v = stats.verdict_us.clone();
    v.sort_by(f64::total_cmp);
    let mut t = stats.transit_us.clone();
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
        robot.held_after_ms().map_or_else(String::new, |ms| format!(
            "; cancelled and held {ms:.3} ms after the bad sample arrived"
        ))
    );
}

/// `--latency-report`: a step's start (a camera message, or the clock's tick) → RULA state
/// published, and the CPU used.
struct Latency {
    ms: Vec<f64>,
    cpu0: Option<f64>,
    wall0: std::time::Instant,
}

impl Latency {
    fn start() -> Self {
        Self {
            ms: Vec::new(),
            cpu0: cpu_secs(),
            wall0: instant(),
        }
    }

    fn push(&mut self, arrival: std::time::Instant) {
        self.ms.push(arrival.elapsed().as_secs_f64() * 1e3);
    }

    fn print(&mut self) {
        self.ms.sort_by(f64::total_cmp);
        let wall = self.wall0.elapsed().as_secs_f64();
        let cpu = self.cpu0.zip(cpu_secs()).map(|(a, b)| b - a);
        println!(
            "latency (step start → RULA state published): n = {}, p50 = {:.3} ms, p99 = {:.3} ms, max = {:.3} ms; CPU {}",
            self.ms.len(),
            percentile(&self.ms, 0.5),
            percentile(&self.ms, 0.99),
            self.ms.last().copied().unwrap_or(f64::NAN),
            cpu.map_or("n/a".to_owned(), |c| format!(
                "{c:.2} s over {wall:.1} s = {:.1} % of one core",
                100.0 * c / wall
            ))
        );
    }
}

/// The recording's joint states and, once a class is locked, the TCP and handover markers (at most
/// 20 Hz).
#[derive(Default)]
struct Markers {
    geometry: Option<(TrajectoryClass, RobotGeometry)>,
    last_nanos: Option<i64>,
}

impl Markers {
    fn record(&mut self, cell: &mut RunLoop, js: &JointState, now: i64, setup: &Setup) {
        let class = cell.machine().locked_class();
        let recording = &mut cell.outputs_mut().ros.recording;
        if !recording.is_on() {
            return;
        }
        recording.with(|rec| rec.write(topics::JOINT_STATES, now, js));
        if self.geometry.as_ref().map(|(c, _)| *c) != class {
            self.geometry = class.and_then(|c| {
                match ergocell::session::provider::robot_geometry(&setup.provider(), c) {
                    Ok(g) => Some((c, g)),
                    Err(e) => {
                        tracing::warn!(error = %e, "no robot markers in the recording");
                        None
                    }
                }
            });
        }
        let Some((_, g)) = self.geometry.as_ref() else {
            return;
        };
        if self.last_nanos.is_some_and(|t| now - t < 50_000_000) {
            return;
        }
        if let Some(p) = g.tcp_world(js) {
            self.last_nanos = Some(now);
            let m = messages::robot_markers_message(now, Some(p), Some(g.handover_world()));
            recording.with(|rec| rec.write(topics::ROBOT_MARKERS, now, &m));
        }
    }
}

fn print_summary(machine: &SessionMachine, rejected: u64) {
    let s = machine.summary();
    println!(
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
        println!(
            "recalibrate: {} (found out of calibration during the session, left out of fusion)",
            s.cameras_out_of_calibration.join(", ")
        );
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

/// The SROS2 enclave folder for this node, or `None` without DDS Security (said on stdout either way),
/// from `--keystore`, the ROS_SECURITY_* variables and `[ros]` (`security_required`, `keystore`
/// relative to the cell file's folder).
pub(super) fn security_enclave(
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

/// DDS discovery's multicast group (SPDP, every domain: RTPS 2.x §9.6.1.4.1).
const DISCOVERY_GROUP: std::net::Ipv4Addr = std::net::Ipv4Addr::new(239, 255, 0, 1);

/// One line when this machine cannot join DDS discovery's multicast group on any interface the
/// participant may use (a container or network namespace with loopback only, an interface without
/// multicast): what it means for discovery, said once instead of RustDDS's per-message warnings.
/// `None` when a join succeeds, or when the scope does not look beyond this machine.
pub(super) fn multicast_note(scope: &ergocell_bridge::scope::NetworkScope) -> Option<String> {
    use std::net::{IpAddr, Ipv4Addr, UdpSocket};
    let interfaces: Vec<Ipv4Addr> = match scope.participant_filter().0 {
        // No list: the kernel picks the interface from its routes, as for any multicast join.
        None => vec![Ipv4Addr::UNSPECIFIED],
        Some(list) => list
            .into_iter()
            .filter_map(|a| match a {
                IpAddr::V4(a) if !a.is_loopback() => Some(a),
                _ => None,
            })
            .collect(),
    };
    if interfaces.is_empty() {
        return None; // LOCALHOST or OFF: discovery is not meant to leave this machine
    }
    let socket = match UdpSocket::bind((Ipv4Addr::UNSPECIFIED, 0)) {
        Ok(s) => s,
        Err(e) => {
            return Some(format!(
                "DDS discovery: no UDP socket could be opened ({e})"
            ))
        }
    };
    let mut last_error = None;
    for interface in &interfaces {
        match socket.join_multicast_v4(&DISCOVERY_GROUP, interface) {
            Ok(()) => return None,
            Err(e) => last_error = Some(e),
        }
    }
    let why = last_error.map_or_else(String::new, |e| format!(": {e}"));
    Some(format!(
        "DDS discovery: no multicast on this machine (joining {DISCOVERY_GROUP}{why}): ROS 2 nodes \
         on other machines (edge cameras, the robot's driver) cannot discover this cell; nodes on this \
         machine still can, over loopback. Give the cell-network interface multicast \
         (docs/integrator.md, troubleshooting)."
    ))
}

/// The DDS participant's network scope from `[ros]` and the ROS 2 environment variables
/// (`ROS_AUTOMATIC_DISCOVERY_RANGE`, `ROS_STATIC_PEERS`, `ROS_LOCALHOST_ONLY`).
pub(super) fn network_scope(
    ros: &RosConfig,
) -> anyhow::Result<ergocell_bridge::scope::NetworkScope> {
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
    use super::*;
    use ergocell_bridge::scope::{DiscoveryRange, NetworkScope, ScopeEnv};
    use std::net::Ipv4Addr;

    fn scope(range: DiscoveryRange, interfaces: Option<&[Ipv4Addr]>) -> NetworkScope {
        let env = ScopeEnv {
            automatic_discovery_range: None,
            static_peers: None,
            localhost_only: None,
        };
        NetworkScope::resolve(Some(range), interfaces, &env).expect("a valid scope")
    }

    #[test]
    fn multicast_note_only_where_discovery_should_leave_the_machine() {
        // An interface this machine does not have (TEST-NET-1, RFC 5737): no join can succeed.
        let absent = [Ipv4Addr::new(192, 0, 2, 1)];
        let note = multicast_note(&scope(DiscoveryRange::Subnet, Some(&absent)))
            .expect("a join on an absent interface fails");
        assert!(note.starts_with("DDS discovery: no multicast"), "{note}");
        assert!(
            note.contains("239.255.0.1") && !note.contains('\n'),
            "{note}"
        );
        // Discovery kept on this machine, or off: nothing to say.
        assert_eq!(
            multicast_note(&scope(DiscoveryRange::Localhost, None)),
            None
        );
        assert_eq!(multicast_note(&scope(DiscoveryRange::Off, None)), None);
    }
}

/// At start-up: the classes whose locked trajectory verifies now (with who approved it), and those
/// that do not, whose operators the robot will not serve.
#[derive(Debug, PartialEq)]
struct ApprovalSummary {
    approved: Vec<(ergocell_robot::TrajectoryClass, Vec<String>)>,
    /// The classes that cannot run, and why in a few words.
    refused: Vec<(ergocell_robot::TrajectoryClass, ergocell_approvals::Refusal)>,
}

impl ApprovalSummary {
    fn of(provider: &mut dyn ergocell_cell::session::TrajectoryProvider) -> Self {
        let mut out = Self {
            approved: Vec::new(),
            refused: Vec::new(),
        };
        for class in ergocell_robot::TrajectoryClass::ALL {
            match provider.verify(class) {
                Ok(a) => out.approved.push((
                    class,
                    a.approvals()
                        .iter()
                        .map(|x| x.approved_by.clone())
                        .collect(),
                )),
                Err(e) => out.refused.push((class, e.refusal())),
            }
        }
        out
    }
}

impl std::fmt::Display for ApprovalSummary {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let approved: Vec<String> = self
            .approved
            .iter()
            .map(|(class, by)| format!("{class} (approved by {})", by.join(", ")))
            .collect();
        // The refused classes grouped by why: "c1, c2, c3: not approved (…)".
        let mut why: Vec<(ergocell_approvals::Refusal, Vec<String>)> = Vec::new();
        for (class, refusal) in &self.refused {
            match why.iter_mut().find(|(r, _)| r == refusal) {
                Some((_, classes)) => classes.push(class.to_string()),
                None => why.push((*refusal, vec![class.to_string()])),
            }
        }
        let why = why
            .iter()
            .map(|(r, classes)| format!("{}: {r}", classes.join(", ")))
            .collect::<Vec<_>>()
            .join("; ");
        match (approved.is_empty(), self.refused.is_empty()) {
            (_, true) => write!(f, "robot: every class is approved: {}", approved.join(", ")),
            (true, false) => write!(
                f,
                "robot: no class can run, the robot will not move for any operator: {why} \
                 (`ergocell trajectories verify` says more)"
            ),
            (false, false) => write!(
                f,
                "robot: {}; the robot will not move for an operator of {why} \
                 (`ergocell trajectories verify` says more)",
                approved.join(", "),
            ),
        }
    }
}

#[cfg(test)]
mod approval_summary_tests {
    use super::*;
    use ergocell_cell::session::{ProviderError, TrajectoryProvider};
    use ergocell_robot::{ApprovedTrajectory, TrajectoryClass};

    /// A cell whose approvals are all missing.
    struct Unapproved(Vec<TrajectoryClass>);

    impl TrajectoryProvider for Unapproved {
        fn verify(&mut self, class: TrajectoryClass) -> Result<ApprovedTrajectory, ProviderError> {
            self.0.push(class);
            Err(ProviderError::NotVerified {
                failure: ergocell_robot::lock::VerifyFailure {
                    class,
                    problems: vec![ergocell_robot::RobotError::NotApproved {
                        class: class.to_string(),
                        lock_sha256: String::new(),
                        detail: "no approvals file".to_owned(),
                    }],
                },
                witness: None,
            })
        }
        fn stature_bounds_m(&mut self, _: TrajectoryClass) -> Result<(f64, f64), ProviderError> {
            Ok((1.5, 2.0))
        }
    }

    #[test]
    fn refused_classes_are_grouped_by_their_reason() {
        use ergocell_approvals::Refusal;
        let summary = ApprovalSummary {
            approved: vec![(TrajectoryClass::C2, vec!["alice@plant.example".to_owned()])],
            refused: vec![
                (TrajectoryClass::C1, Refusal::NotApproved),
                (TrajectoryClass::C3, Refusal::NotApproved),
            ],
        };
        assert_eq!(
            summary.to_string(),
            format!(
                "robot: c2 (approved by alice@plant.example); the robot will not move for an \
                 operator of c1, c3: {} (`ergocell trajectories verify` says more)",
                Refusal::NotApproved
            )
        );
        let none = ApprovalSummary {
            approved: Vec::new(),
            refused: vec![
                (TrajectoryClass::C1, Refusal::NotApproved),
                (TrajectoryClass::C2, Refusal::RolledBack),
                (TrajectoryClass::C3, Refusal::NotApproved),
            ],
        };
        assert_eq!(
            none.to_string(),
            format!(
                "robot: no class can run, the robot will not move for any operator: c1, c3: {}; \
                 c2: {} (`ergocell trajectories verify` says more)",
                Refusal::NotApproved,
                Refusal::RolledBack
            )
        );
    }

    #[test]
    fn every_class_is_asked_and_the_unapproved_are_named() {
        let mut cell = Unapproved(Vec::new());
        let summary = ApprovalSummary::of(&mut cell);
        assert_eq!(cell.0, TrajectoryClass::ALL.to_vec());
        assert_eq!(
            summary,
            ApprovalSummary {
                approved: Vec::new(),
                refused: TrajectoryClass::ALL
                    .iter()
                    .map(|&c| (c, ergocell_approvals::Refusal::NotApproved))
                    .collect(),
            }
        );
    }
}
