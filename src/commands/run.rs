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

use ergocell::session::provider::FileTrajectories;
use ergocell::session::{
    CellLoop, CellOutputs, Driver, ExitStatus, Interruption, Outcome, OutputError, SessionEvent,
    SessionMachine,
};
use ergocell_bridge::scope::NetworkScope;
use ergocell_bridge::transport::{publish, CellTopics, RosConfig, RosNode};
use ergocell_cell::CellSettings;
use ergocell_formats::rig_file::parse_rig;
use ergocell_perception::video_geometry::VideoGeometry;
use ergocell_perception::CameraRig;
use ergocell_ros_backend::cameras::CameraInbox;
use ergocell_ros_backend::clock::{instant, SessionClock};
use ergocell_ros_backend::console::{self, CpuUse};
use ergocell_ros_backend::messages;
use ergocell_ros_backend::monitor::{monitor_task, Judge};
use ergocell_ros_backend::outputs::RosOutputs;
use ergocell_ros_backend::recording::{self, McapRecorder, Recording};
use ergocell_ros_backend::robot::{announce_driver, spawn_controller, RosRobot};
use ergocell_ros_backend::station::{RosCellOutputs, RosStation, StationHooks, StationInputs};
use ergocell_web::display::Display;

use super::ros_node::{runtime, say, StartedNode};
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

    /// What `run`'s station asks for: the next session's machine, the robot's geometry for the
    /// recording's markers (both from the files, read again), and the console.
    fn hooks(&self) -> StationHooks<'_> {
        StationHooks {
            next_machine: Box::new(|| self.new_machine().map_err(Into::into)),
            geometry: Box::new(|class| {
                ergocell_ros_backend::robot_markers::robot_geometry(&self.provider(), class)
                    .map_err(Into::into)
            }),
            say: Box::new(|line| println!("{line}")),
        }
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
    let setup = checked_setup(args)?;
    // The first session's machine before anything is started: a cell that cannot run is said now.
    let machine = setup.new_machine()?;
    // Which classes the robot can serve, said before anyone is measured.
    println!(
        "{}",
        ergocell_cell::session::approval_summary::ApprovalSummary::of(&mut setup.provider())
    );
    let runtime = runtime()?;
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
    let mut node = StartedNode::start(
        runtime,
        &setup.ros,
        &setup.ros.node_name,
        &args.config,
        args.keystore.as_deref(),
        "/ergocell/cell",
    )?;
    let display = start_display(args.display, &node.runtime)?;
    let result = node.runtime.block_on(serve(
        args,
        &setup,
        machine,
        (&mut node.node, &node.scope),
        &mut recording,
        display,
        &stop,
    ));
    stop_task.abort();
    node.shut_down();
    close_recording(recording, args, result)
}

/// The recording closed (summary and footer) on every way out: a normal end, a signal, an error;
/// `result` is the sessions' result, which comes first.
fn close_recording(
    recording: Option<Recording>,
    args: &Args,
    result: anyhow::Result<()>,
) -> anyhow::Result<()> {
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

/// The cell's files read, with `--record` and `--outcome` checked before anything is started: an
/// existing file without --force, or any input (named by a flag or read by the cell), is refused.
fn checked_setup(args: &Args) -> anyhow::Result<Setup> {
    let flagged = [
        ("--config", args.config.as_path()),
        ("--rig", args.rig.as_path()),
    ];
    if let Some(record) = &args.record {
        // Before anything is read: an existing file without --force, or a named input.
        output::check("--record", record, args.force, &flagged)?;
    }
    let setup = Setup::load(args)?;
    if args.record.is_none() && args.outcome.is_none() {
        return Ok(setup);
    }
    let read = setup.provider().input_files();
    let read = read.iter().map(|p| ("a file the cell reads:", p.as_path()));
    if let Some(record) = &args.record {
        // Every file the cell reads is an input, not only the ones named by a flag.
        let mut inputs = flagged.to_vec();
        inputs.extend(read.clone());
        output::check("--record", record, args.force, &inputs)?;
    }
    if let Some(path) = &args.outcome {
        let mut inputs = flagged.to_vec();
        inputs.extend(args.record.iter().map(|p| ("--record", p.as_path())));
        inputs.extend(read);
        super::outcome::check(path, args.force, &inputs)?;
    }
    Ok(setup)
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

impl RosCellOutputs for RunOutputs {
    fn ros(&self) -> &RosOutputs {
        &self.ros
    }
    fn ros_mut(&mut self) -> &mut RosOutputs {
        &mut self.ros
    }
    fn session_began(&self, machine: &SessionMachine) {
        if let Some(d) = &self.display {
            d.next_session(machine);
        }
    }
}

type RunLoop = CellLoop<RosRobot, RunOutputs>;

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
    (node, scope): (&mut RosNode, &NetworkScope),
    recording: &mut Option<Recording>,
    display: Option<Arc<Display>>,
    stop: &StopFlag,
) -> anyhow::Result<()> {
    let ros = &setup.ros;
    let topics = CellTopics::new(node, ros)?;
    let (action, reports) = spawn_controller(node, ros)?;
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
        cell = cell.with_time_limit(clock.now(), limit);
    }
    println!("{}", console::start_text(ros, topics.cameras.len(), scope));
    say(ergocell_bridge::scope::multicast_note(scope));
    if let Err(e) = announce_start(&mut cell, &clock).await {
        monitor.abort();
        let (_, _, outputs) = cell.into_parts();
        *recording = Some(outputs.ros.recording);
        return Err(e);
    }
    let inputs = StationInputs {
        cameras: &topics.cameras,
        driver: topics.driver.as_ref(),
        notes,
        reports,
    };
    let inbox = CameraInbox::new(setup.rig.clone(), setup.video_geometries.clone());
    let mut station = RosStation::new(inputs, inbox, clock, setup.hooks());
    let cpu0 = cpu_secs();
    let wall0 = instant();
    // The sessions, one after another, by the cell's rules (the session driver's).
    let mut driver = Driver::new(cell, args.sessions);
    let outcome = driver.run(&mut station, stop).await;
    monitor.abort();
    let cell = driver.into_cell();
    tokio::task::block_in_place(|| wait_delivered(&cell));
    if let Some(text) = stats
        .lock()
        .ok()
        .and_then(|s| console::monitor_text(cell.robot(), &s))
    {
        println!("{text}");
    }
    println!(
        "{}",
        console::session_summary(cell.machine(), station.rejected())
    );
    if args.latency_report {
        let cpu = cpu0.zip(cpu_secs()).map(|(a, b)| CpuUse {
            cpu_s: b - a,
            wall_s: wall0.elapsed().as_secs_f64(),
        });
        println!("{}", station.latency().report(cpu));
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
    exit_of(&outcome, &machine, args)
}

/// The session's first state, published on the session state and events topics.
async fn announce_start(cell: &mut RunLoop, clock: &SessionClock) -> anyhow::Result<()> {
    let first = messages::session_state_message(cell.machine(), clock.now(), "started");
    let p = &cell.outputs().ros.publishers;
    publish(&p.session_state, first.clone()).await?;
    publish(&p.session_events, first).await?;
    let readiness = cell.driver_readiness();
    say(announce_driver(cell, clock.now(), readiness));
    Ok(())
}

/// `run`'s result from the sessions' outcome: the exit status by the cell's rule.
fn exit_of(outcome: &Outcome, machine: &SessionMachine, args: &Args) -> anyhow::Result<()> {
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

/// User + system CPU seconds of this process (Linux `/proc/self/stat`, clock ticks of 100 Hz).
fn cpu_secs() -> Option<f64> {
    let stat = std::fs::read_to_string("/proc/self/stat").ok()?;
    let after = stat.rsplit_once(')')?.1;
    let fields: Vec<&str> = after.split_whitespace().collect();
    let utime: f64 = fields.get(11)?.parse().ok()?;
    let stime: f64 = fields.get(12)?.parse().ok()?;
    Some((utime + stime) / 100.0)
}
