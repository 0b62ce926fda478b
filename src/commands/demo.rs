//! `ergocell demo`: a whole simulated session in one process, no ROS needed.
//!
//! The digital twin (`ergocell_sim`) plays an operator who walks in, stands, does handover cycles and
//! walks out, seen by the reference cell's six cameras (`config/rig.toml`) with pose-estimator noise.
//! The real session state machine fuses the views, measures the height, decides the class, verifies
//! and locks the class's trajectory and runs RULA; the twin's joint trajectory controller and KUKA
//! driver (`ergocell_sim::controller`) follow it under the cell's own execution watch.
//! Two faults are injected while working (one camera silent, then every camera) to show the degrade
//! and the hold. After the first handover the operator picks up a dropped part from low down (trunk
//! bent far forward for 4 s, the robot not involved), so a RULA posture warning is raised and cleared
//! (`--no-floor-pick` leaves it out). The session is recorded to MCAP (Foxglove, rosbag2).
//!
//! The simulated session lasts as long as its script (walk in, height, the handover cycles, the floor
//! pick, walk out) plus a margin for the robot's way home; a session still running then is stopped
//! with the robot held and says so. Ctrl-C and SIGTERM stop it the same way (exit 130 / 143; a
//! session that had already failed on the robot side or an output exits 1, as `run` does).
//!
//! The recording is never written over an existing file unless asked (`--force`): an existing
//! `--out` is a usage error, and the default `ergocell-demo.mcap` moves on to the next free
//! `ergocell-demo-N.mcap`.
//!
//! The shipped locks carry no approvals (a person signs them off on site), so the demo approves the
//! current locks in a **temporary** folder, labelled as a demo approval; `trajectories/approvals/` is
//! never written.

use super::{parse_operator, parse_start_time};
use ergocell_bridge::session_info::OperatorId;
use std::path::{Path, PathBuf};

use anyhow::Context as _;
use ergocell::recording::{self, McapRecorder, Recording};
use ergocell::robot_markers::RobotGeometry;
use ergocell::session::provider::FileTrajectories;
use ergocell::session::{
    trajectory_class, CellLoop, CellOutputs, Driver, DriverError, ExitStatus, Interruption,
    Outcome, OutputError, ReportEffect, RobotReport, SessionEnd, SessionEvent, SessionMachine,
};
use ergocell::shipped;
use ergocell_cell::CellSettings;
use ergocell_ergonomics::height::ClassThresholds;
use ergocell_ergonomics::HeightClass;
use ergocell_formats::rig_file::parse_rig;
use ergocell_host::scratch::ScratchDir;
use ergocell_perception::{CameraRig, View2};
use ergocell_robot::{LockFile, TrajectoryClass};
use ergocell_ros_backend::console;
use ergocell_ros_backend::twin_recording;
use ergocell_sim::controller::{SimController, TwinRobot};
use ergocell_sim::demo::{self, BadBump};
use ergocell_sim::faults::{FaultPlayer, FaultSchedule};
use ergocell_sim::source::SimSource;
use ergocell_sim::station::{
    ClassHandover, TwinHooks, TwinOutputs, TwinStation, JOINT_STATE_PERIOD_NANOS,
    JOINT_STATE_TIMEOUT_S,
};
use ergocell_sim::{FloorPick, Operator, SimConfig, Simulation};
use ergocell_web::display::{DisplayStartError, DisplayThread};
use nalgebra::Point3;
use std::time::Duration;

use super::signals::{StopFlag, Stopped};
use super::{output, UsageError};

/// The default recording (with a number added when it exists: `ergocell-demo-2.mcap`, …).
pub const DEFAULT_OUT: &str = "ergocell-demo.mcap";

/// Most handover cycles (about 48 hours of simulated session: several shifts, for `--soak-report`).
pub const MAX_CYCLES: usize = 10_000;

#[derive(Debug, clap::Args)]
#[command(
    after_help = "Exit codes: 0 the session ended normally; 1 it did not (e.g. the time limit \
    of the script + 30 s was reached: robot held); 2 bad input (an existing --out without --force); \
    130 stopped by Ctrl-C (SIGINT), 143 stopped by SIGTERM — in both the robot is held and the \
    recording closed with its summary and footer."
)]
pub struct Args {
    /// Camera rig (ergocell rig TOML). Default: the reference cell's `config/rig.toml`, shipped in
    /// the binary.
    #[arg(long)]
    pub rig: Option<PathBuf>,
    /// Cell configuration (`config/cell.toml`: robot, station, session, pipeline, assessment, task).
    /// Default: the shipped one (with its URDF).
    #[arg(long)]
    pub cell: Option<PathBuf>,
    /// Folder of the trajectory files and `locks/`. Default: the shipped `trajectories/`.
    #[arg(long)]
    pub trajectories: Option<PathBuf>,
    /// The simulated operator's stature, metres (default 1 cm above the c1/c2 boundary: served
    /// across the boundary, with the decision's probability and expected RULA cost).
    #[arg(long, default_value_t = 1.69)]
    pub stature_m: f64,
    /// Handover cycles (0..=10000; 1655 ≈ an 8-hour shift). The session may run for the script's duration (walk in, height,
    /// cycles × 17.4 s: the robot's round trip per part, floor pick, walk out) plus 30 s; then it is stopped with the robot held.
    #[arg(long, default_value_t = 3)]
    pub cycles: usize,
    /// Simulation seed (same seed, same session).
    #[arg(long, default_value_t = 42)]
    pub seed: u64,
    /// The MCAP recording to write; an existing file is refused unless --force. Default
    /// `ergocell-demo.mcap`, or when it exists the next free `ergocell-demo-N.mcap` (printed).
    #[arg(long)]
    pub out: Option<PathBuf>,
    /// Overwrite an existing recording (--out, or without it `ergocell-demo.mcap`) or --outcome file.
    #[arg(long)]
    pub force: bool,
    /// How the session ended, as JSON for a program (CI, a script): the exit code, the typed end,
    /// every command sent to the robot with its typed reason, the summary.
    #[arg(long, value_name = "FILE")]
    pub outcome: Option<PathBuf>,
    /// The operator's pseudonymous id written into the recording (letters, digits, '-', '_', '.';
    /// never a name). Default: `demo-<seed>`.
    #[arg(long, value_name = "ID", value_parser = parse_operator)]
    pub operator: Option<OperatorId>,
    /// When the session starts, RFC 3339 (e.g. `2026-11-30T06:00:00Z`); default now. The recording's
    /// times, and the day and week `ergocell exposure` files it under, follow from it.
    #[arg(long, value_name = "TIME", value_parser = parse_start_time)]
    pub start_time: Option<i64>,
    /// Camera frame rate, Hz (the seed paper's cameras: 10 Hz).
    #[arg(long, default_value_t = 10.0)]
    pub fps: f64,
    /// Do not inject the camera faults (the supervisor's class change request stays).
    #[arg(long, conflicts_with = "faults")]
    pub no_faults: bool,
    /// The faults to play, a TOML schedule (`ergocell_sim::faults`: silent cameras, class change
    /// requests and the robot side's faults, timed from the robot starting to work or arriving with a
    /// part; `sim/faults/robot-*.toml` has a path deviation, a stall, the driver stopping and an
    /// e-stop). Default: one camera
    /// silent 5.5 s into work, a class change request 2 s in, every camera silent 0.3 s after the
    /// robot brought the second part.
    #[arg(long)]
    pub faults: Option<PathBuf>,
    /// Leave out the floor pick (after the first handover cycle the operator bends down for a dropped
    /// part, 0.40 m above the floor: a bad posture that raises a RULA warning).
    #[arg(long)]
    pub no_floor_pick: bool,
    /// The station's other tasks between the handovers: a task mix (TOML, the format of
    /// `sim/tasks/default.toml`) or `default` for the shipped one (low bin, high shelf, reading a
    /// label, side table, long reach, fastening, kneeling: postures that deserve a warning). Its
    /// tasks are placed among `--cycles` handovers; its own handover count is not used.
    #[arg(long, value_name = "MIX")]
    pub tasks: Option<String>,
    /// Bump this camera (its id, e.g. `s2_left`) out of its calibration mid-session: from
    /// `--bump-at-s` on it sees the scene panned by `--bump-deg` while the rig stays as calibrated.
    /// The session must find it by its reprojection residuals, leave it out and ask for a
    /// recalibration.
    #[arg(long, value_name = "CAMERA")]
    pub bump_camera: Option<String>,
    /// The bump's angle, degrees (a pan about the camera's vertical image axis).
    #[arg(long, default_value_t = 1.5, requires = "bump_camera")]
    pub bump_deg: f64,
    /// When the bump happens, seconds after the session starts.
    #[arg(long, default_value_t = 12.0, requires = "bump_camera")]
    pub bump_at_s: f64,
    /// A soak's figures: every `--soak-report` minutes of simulated time (and at the end) the
    /// process's resident memory and the wall time of the session steps (p50, p99, max) over that
    /// span, to see memory flat and no drift in timing over a long shift (e.g. `--cycles 1756`).
    #[arg(long, value_name = "MINUTES", value_parser = clap::value_parser!(u64).range(1..=1440))]
    pub soak_report: Option<u64>,
    /// Serve the operator display on this address (e.g. `127.0.0.1:8090`; port 0 picks a free
    /// one, printed) and run the session in real time so the page shows it as it happens. Only
    /// loopback `Host`s are answered unless the address is not a loopback one.
    #[arg(long, value_name = "ADDR")]
    pub display: Option<std::net::SocketAddr>,
}

/// Wall-clock time at the binary's clock boundary (the session itself runs on the simulator's clock).
#[allow(clippy::disallowed_methods)]
fn wall_clock_nanos() -> i64 {
    std::time::SystemTime::now()
        .duration_since(std::time::UNIX_EPOCH)
        .map_or(0, |d| i64::try_from(d.as_nanos()).unwrap_or(i64::MAX))
}

/// Resident memory of this process, MiB (Linux `/proc/self/status`; `None` elsewhere).
fn rss_mib() -> Option<f64> {
    let status = std::fs::read_to_string("/proc/self/status").ok()?;
    let line = status.lines().find(|l| l.starts_with("VmRSS:"))?;
    let kib: f64 = line.split_whitespace().nth(1)?.parse().ok()?;
    Some(kib / 1024.0)
}

/// Monotonic instant at the binary's clock boundary, for the soak's step timing.
#[allow(clippy::disallowed_methods)]
fn instant() -> std::time::Instant {
    std::time::Instant::now()
}

/// The recording's path: `--out` (refused if it exists, unless `--force`) or the default, numbered
/// when it exists (unless `--force`); and whether the default was moved on to a numbered name.
fn output_path(args: &Args) -> anyhow::Result<(PathBuf, bool)> {
    let mut inputs: Vec<(&str, &Path)> = Vec::new();
    if let Some(rig) = &args.rig {
        inputs.push(("--rig", rig));
    }
    if let Some(cell) = &args.cell {
        inputs.push(("--cell", cell));
    }
    if let Some(faults) = &args.faults {
        inputs.push(("--faults", faults));
    }
    // Every file the cell reads is an input, not only the ones named by a flag.
    let trajectories = ergocell_robot::TrajectoryLayout::new(
        args.trajectories
            .as_deref()
            .unwrap_or(Path::new(ergocell_robot::TrajectoryLayout::DEFAULT_DIR)),
    );
    let read = ergocell::session::provider::with_shipped_defaults(
        args.cell.as_deref(),
        args.trajectories.as_deref(),
        trajectories.approvals_dir(),
    )
    .input_files();
    inputs.extend(read.iter().map(|p| ("a file the cell reads:", p.as_path())));
    let (path, moved) = if let Some(out) = &args.out {
        output::check("--out", out, args.force, &inputs)?;
        (out.clone(), false)
    } else {
        let default = PathBuf::from(DEFAULT_OUT);
        output::check("--out", &default, true, &inputs)?;
        if args.force {
            (default, false)
        } else {
            let path = output::next_free(&default)?;
            let moved = path != default;
            (path, moved)
        }
    };
    // The outcome is neither an input nor the recording chosen (named or the default).
    if let Some(outcome) = &args.outcome {
        inputs.push(("the recording", path.as_path()));
        super::outcome::check(outcome, args.force, &inputs)?;
    }
    Ok((path, moved))
}

/// The demo's outputs: the console (every session event, a status line), the operator display and
/// the recording, in that order for every step.
struct DemoOutputs {
    recording: Recording,
    display: Option<DisplayThread>,
    /// Each class's robot geometry (the recording's TCP and handover markers).
    geometries: Vec<(TrajectoryClass, RobotGeometry)>,
    start: i64,
    /// The newest frame's RULA, for the status line.
    rula: String,
}

impl CellOutputs for DemoOutputs {
    fn session_step(
        &mut self,
        now: i64,
        machine: &SessionMachine,
        events: &[SessionEvent],
    ) -> Result<(), OutputError> {
        for line in console::demo_event_lines(events, console::elapsed_s(now, self.start)) {
            println!("{line}");
        }
        if let Some(d) = &self.display {
            d.display().update(machine, events);
        }
        for e in events {
            if let SessionEvent::Frame {
                assessment: Some(a),
                ..
            } = e
            {
                self.rula = console::rula_status(a);
            }
        }
        self.recording
            .with(|rec| recording::record_events(rec, machine, now, events));
        self.recording.new_failure().map_or(Ok(()), Err)
    }

    fn take_failure(&mut self) -> Option<OutputError> {
        self.recording.new_failure()
    }
}

/// The twin's frames, reports and joint states recorded as a real cell's: the cameras' messages,
/// the controller's events and the driver's readiness, the joint states and the robot's markers.
impl TwinOutputs for DemoOutputs {
    fn views(&mut self, rig: &CameraRig, now: i64, views: &[View2]) {
        twin_recording::record_views(&mut self.recording, rig, now, views);
    }

    fn robot_report(&mut self, t: i64, report: &RobotReport, effect: &ReportEffect) {
        twin_recording::record_robot_report(&mut self.recording, t, report, effect);
    }

    fn robot_state(&mut self, now: i64, class: TrajectoryClass, joints: &[String], at: Vec<f64>) {
        let geometry = self.geometries.iter().find(|(c, _)| *c == class);
        let geometry = geometry.map(|(_, g)| g);
        twin_recording::record_robot_state(&mut self.recording, now, geometry, joints, at);
    }

    fn rula_status(&self) -> String {
        self.rula.clone()
    }
}

/// Each class's handover point (the station frame of its lock, put in the world by the cell's
/// `[station]`, as the session puts it) and robot geometry.
struct Handover {
    class: TrajectoryClass,
    point: Point3<f64>,
    geometry: RobotGeometry,
    lock: LockFile,
}

#[allow(non_snake_case)]
fn handovers(
    provider: &FileTrajectories,
    T_world_station: &nalgebra::Isometry3<f64>,
) -> anyhow::Result<Vec<Handover>> {
    TrajectoryClass::ALL
        .into_iter()
        .map(|class| {
            let text = provider.lock_text(class).map_err(|e| anyhow::anyhow!(e))?;
            let lock = LockFile::from_toml_str(class, &text)
                .map_err(|e| anyhow::anyhow!("lock of {class}: {e}"))?;
            let point =
                ergocell_robot::handover_world(T_world_station, lock.summary.handover_station_m);
            let geometry = ergocell_ros_backend::robot_markers::robot_geometry(provider, class)
                .map_err(|e| anyhow::anyhow!(e))?;
            Ok(Handover {
                class,
                point,
                geometry,
                lock,
            })
        })
        .collect()
}

fn check_args(args: &Args) -> Result<(), UsageError> {
    if !(1.3..=2.2).contains(&args.stature_m) {
        return Err(UsageError(format!(
            "--stature-m {:?} is outside 1.3..=2.2 m",
            args.stature_m
        )));
    }
    if !(1.0..=120.0).contains(&args.fps) {
        return Err(UsageError(format!(
            "--fps {:?} is outside 1..=120 Hz",
            args.fps
        )));
    }
    if args.cycles > MAX_CYCLES {
        return Err(UsageError(format!(
            "--cycles {} is more than {MAX_CYCLES}",
            args.cycles
        )));
    }
    Ok(())
}

fn read_rig(args: &Args) -> anyhow::Result<CameraRig> {
    let (rig_text, rig_label) = match &args.rig {
        Some(path) => (
            ergocell::input::read_text(path, ergocell::input::Kind::Config)?,
            path.display().to_string(),
        ),
        None => (
            shipped::file(Path::new(shipped::RIG))
                .context("the shipped rig is missing from the binary")?
                .to_owned(),
            shipped::label(shipped::RIG),
        ),
    };
    Ok(parse_rig(&rig_text, &rig_label)
        .map_err(|e| UsageError(e.to_string()))?
        .0)
}

fn fault_schedule(args: &Args, rig: &CameraRig) -> Result<FaultSchedule, UsageError> {
    let mut schedule = match &args.faults {
        Some(path) => {
            let text = ergocell::input::read_text(path, ergocell::input::Kind::Config)
                .map_err(|e| UsageError(format!("--faults: {e}")))?;
            let names: Vec<&str> = rig.cameras().iter().map(|c| c.id.as_str()).collect();
            FaultSchedule::from_toml_str(&text, &path.display().to_string(), &names)
                .map_err(|e| UsageError(e.to_string()))?
        }
        None => FaultSchedule::demo(),
    };
    if args.no_faults {
        schedule
            .faults
            .retain(|f| f.kind != ergocell_sim::faults::FaultKind::CamerasSilent);
    }
    Ok(schedule)
}

/// The provider on the shipped (or given) files with demo approvals in `approvals_dir`, said loudly.
fn demo_provider(
    args: &Args,
    approvals_dir: &Path,
    start: i64,
) -> anyhow::Result<FileTrajectories> {
    // A throwaway Ed25519 key derived from the demo's seed (same seed, same demo locks); the run
    // trusts it alone.
    let seed = ergocell_robot::signing::derived_seed("ergocell demo approval key v1", args.seed);
    let provider = ergocell::session::provider::with_shipped_defaults(
        args.cell.as_deref(),
        args.trajectories.as_deref(),
        approvals_dir,
    )
    .with_demo_key(&seed)
    // The cell's or the trajectories' files could not be read or used: bad input.
    .map_err(|e| UsageError(format!("demo approvals: {e}")))?;
    // Whose files: the reference cell's (embedded) unless the user named their own.
    let cell_name = match (&args.cell, &args.rig) {
        (None, None) => "the reference cell".to_owned(),
        (Some(cell), _) => format!("the cell of {}", cell.display()),
        (None, Some(rig)) => format!("the reference cell with the rig {}", rig.display()),
    };
    let (trajectories, lock_kind) = match &args.trajectories {
        None => ("the shipped trajectories".to_owned(), "shipped"),
        Some(dir) => (format!("the trajectories in {}", dir.display()), "on-disk"),
    };
    println!("ergocell demo — a simulated session on {cell_name} (no ROS needed)");
    println!(
        "  DEMO APPROVAL: {trajectories} are re-locked and approved for this run only, in {},",
        approvals_dir.display()
    );
    println!(
        "  signed by a throwaway Ed25519 key derived from seed {} ({}), the only key this run trusts",
        args.seed,
        ergocell::session::provider::DEMO_PRINCIPAL
    );
    for lock in provider.demo_locks() {
        println!(
            "  {}: demo lock {} = the {lock_kind} lock {}, same samples, re-locked under the demo key",
            lock.class, lock.lock_sha256, lock.reviewed_sha256
        );
    }
    println!("  (a simulator-only sign-off; a real cell trusts its engineers' keys in config/approvers/ and needs `ergocell trajectories approve`)");
    let stamp = ergocell_robot::signing::rfc3339_utc(start.div_euclid(1_000_000_000))
        .map_err(|e| anyhow::anyhow!(e))?;
    for class in TrajectoryClass::ALL {
        ergocell::session::provider::approve_for_demo(&provider, class, &stamp)
            .map_err(|e| anyhow::anyhow!("{class}: {e}"))?;
    }
    Ok(provider)
}

fn sim_config(args: &Args, rig: &CameraRig, start: i64) -> anyhow::Result<SimConfig> {
    let mut sim_config = SimConfig::new(args.seed);
    sim_config.frame_period_nanos = demo::frame_period_nanos(args.fps);
    sim_config.start_nanos = start;
    if let Some(name) = &args.bump_camera {
        let camera = rig.index_of_name(name).ok_or_else(|| {
            UsageError(format!("--bump-camera {name}: no such camera in the rig"))
        })?;
        let bump = demo::camera_bump(camera, start, args.bump_at_s, args.bump_deg);
        sim_config.bump = Some(bump.map_err(|e| match e {
            BadBump::Angle { deg } => UsageError(format!("--bump-deg {deg}: {e}")),
            BadBump::Time { at_s } => UsageError(format!("--bump-at-s {at_s}: {e}")),
        })?);
    }
    Ok(sim_config)
}

/// The demo's session before it is played: the cell, the twin and what the console says of them.
struct Prepared {
    rig: CameraRig,
    schedule: FaultSchedule,
    machine: SessionMachine,
    robot: TwinRobot,
    sim: Simulation,
    handovers: Vec<Handover>,
    true_class: TrajectoryClass,
    joints: Vec<String>,
    /// The session's time limit: the script and its tasks, then the robot's way home.
    limit_secs: f64,
    floor_pick: Option<FloorPick>,
    tasks: Vec<&'static str>,
    task_secs: f64,
}

/// The cell (its files, the demo approvals in `approvals_dir`), the simulated operator and the twin
/// robot, from `args`.
fn prepare(args: &Args, approvals_dir: &Path, start: i64) -> anyhow::Result<Prepared> {
    let rig = read_rig(args)?;
    let schedule = fault_schedule(args, &rig)?;
    let provider = demo_provider(args, approvals_dir, start)?;
    let cell_text = provider
        .cell_text()
        .map_err(|e| UsageError(e.to_string()))?;
    let settings = CellSettings::from_toml_str(&cell_text, &provider.cell_label())
        .map_err(|e| UsageError(e.to_string()))?;
    // The simulated operator reaches for the handover point of their true class (the session itself
    // measures the height and decides the class from the cameras); near a boundary the cell may
    // serve them with the neighbouring class (validated for their stature), and they then reach
    // where that class's robot brings the part.
    let true_class = trajectory_class(HeightClass::of(args.stature_m, &ClassThresholds::default()));
    let handovers = handovers(&provider, &settings.session.T_world_station)?;
    let own = handovers
        .iter()
        .find(|h| h.class == true_class)
        .context("no handover for the operator's class")?;
    let leg_s = own.lock.trajectory.point.last().map_or(0.0, |p| p.time_s);
    let script = demo::demo_script(
        own.point,
        args.cycles,
        leg_s,
        settings.session.next_part_after_nanos,
        args.no_floor_pick,
        &settings.session.T_world_station,
    );
    let tasks = match &args.tasks {
        Some(spec) => super::sim_warnings::load_mix(spec)?.draw_between(args.seed, args.cycles),
        None => Vec::new(),
    };
    let task_secs = ergocell_sim::tasks::total_secs(&tasks);
    let limit_secs = demo::time_limit_secs(&script, &tasks);
    let floor_pick = script.floor_pick;
    let task_names = tasks.iter().map(|t| t.kind.name()).collect();
    let sim = Simulation::with_tasks(
        rig.clone(),
        Operator::new(args.stature_m)?,
        script,
        sim_config(args, &rig, start)?,
        tasks,
    )?;
    let joints = own.lock.trajectory.joint_names.clone();
    let robot = twin_robot(&own.lock, &schedule)?;
    let machine = SessionMachine::from_settings(rig.clone(), &settings, Box::new(provider))
        .map_err(|e| UsageError(e.to_string()))?;
    Ok(Prepared {
        rig,
        schedule,
        machine,
        robot,
        sim,
        handovers,
        true_class,
        joints,
        limit_secs,
        floor_pick,
        tasks: task_names,
        task_secs,
    })
}

/// The twin's controller and KUKA driver under the cell's execution watch, its joint states at a
/// KUKA driver's 250 Hz, starting at `lock`'s home. The newest command is all the demo reads back
/// (the blackout waits for a leg's arrival). Each robot fault of `schedule` is checked against it.
fn twin_robot(lock: &LockFile, schedule: &FaultSchedule) -> anyhow::Result<TwinRobot> {
    let joints = lock.trajectory.joint_names.clone();
    let home = lock
        .trajectory
        .point
        .first()
        .map(|p| p.positions_rad.clone())
        .context("lock file without points")?;
    let controller = SimController::new(joints, home).keeping_last(1);
    for f in schedule.faults.iter().filter_map(|f| f.robot.as_ref()) {
        controller
            .check(f)
            .map_err(|e| UsageError(format!("--faults: {e}")))?;
    }
    Ok(TwinRobot::new(
        controller,
        JOINT_STATE_PERIOD_NANOS,
        JOINT_STATE_TIMEOUT_S,
    ))
}

/// The recording, created: `--out`, or the default name taken when the file is created (a demo
/// started meanwhile in this folder may have taken the one chosen at the start, and then this one
/// moves on to the next); and whether the default was moved on to a numbered name.
fn open_recording(
    args: &Args,
    out: PathBuf,
    moved: bool,
) -> anyhow::Result<(McapRecorder, PathBuf, bool)> {
    let (file, out, moved) = if args.out.is_none() && !args.force {
        let (file, path) = output::create_next_free(Path::new(DEFAULT_OUT))?;
        let moved = path != Path::new(DEFAULT_OUT);
        (file, path, moved)
    } else {
        (output::create("--out", &out, args.force)?, out, moved)
    };
    let mut rec = McapRecorder::from_file(file)?;
    let operator = match &args.operator {
        Some(id) => id.clone(),
        None => OperatorId::new(&format!("demo-{}", args.seed))?,
    };
    rec.write_operator(&operator)?;
    Ok((rec, out, moved))
}

/// What the demo is about to play.
fn print_plan(args: &Args, p: &Prepared, out: &Path, moved: bool) {
    if moved {
        println!(
            "  {DEFAULT_OUT} exists (kept): recording into {} (--out names the file, --force overwrites)",
            out.display()
        );
    }
    println!(
        "  operator {:.2} m, {} handover cycles, {} cameras, seed {}; recording {}",
        args.stature_m,
        args.cycles,
        p.rig.len(),
        args.seed,
        out.display()
    );
    if p.schedule.faults.is_empty() {
        println!("  faults: none");
    } else {
        let list: Vec<String> = p.schedule.faults.iter().map(ToString::to_string).collect();
        println!("  faults: {}", list.join("; "));
    }
    if !p.tasks.is_empty() {
        println!(
            "  tasks between the handovers ({:.0} s): {}",
            p.task_secs,
            p.tasks.join(", ")
        );
    }
    if let Some(pick) = &p.floor_pick {
        println!(
            "  floor pick after handover cycle {}: the operator bends down for a dropped part {:.2} m above the floor (robot not involved)",
            pick.after_cycle,
            pick.target_m.z
        );
    }
    println!();
}

/// The operator display on its own thread, said.
fn start_display(addr: Option<std::net::SocketAddr>) -> anyhow::Result<Option<DisplayThread>> {
    let Some(addr) = addr else {
        return Ok(None);
    };
    let d = DisplayThread::start(addr).map_err(|e| match e {
        // the address is the user's to change
        DisplayStartError::Bind { .. } => UsageError(format!("--display: {e}")).into(),
        e => anyhow::Error::new(e),
    })?;
    println!(
        "  operator display: http://{}/ (the session runs in real time)",
        d.bound()
    );
    Ok(Some(d))
}

pub fn run(args: &Args) -> anyhow::Result<()> {
    // First of all: a stop signal from here on holds the robot and closes the recording.
    let stop = StopFlag::install()?;
    check_args(args)?;
    let (out, moved) = output_path(args)?;
    // Demo approvals in a temporary folder, clearly labelled; never trajectories/approvals/.
    let demo_dir = ScratchDir::create(&std::env::temp_dir(), "ergocell-demo", "approvals")?;
    let start = args.start_time.unwrap_or_else(wall_clock_nanos);
    let prepared = prepare(args, &demo_dir.path().join("approvals"), start)?;
    let (rec, out, moved) = open_recording(args, out, moved)?;
    print_plan(args, &prepared, &out, moved);
    let true_class = prepared.true_class;
    let (outcome, now, cell) = play(args, prepared, rec, start, &stop)?;
    let (machine, robot, outputs) = cell.into_parts();
    drop(outputs.display);
    let messages = outputs.recording.close()?;
    // A simulator that failed ended the session held; its error is the demo's.
    let status = super::outcome::written(
        outcome,
        args.outcome.as_deref(),
        args.force,
        machine.summary(),
        robot.monitor_holds > 0,
    )?
    .status;
    drop(demo_dir);
    print!(
        "{}",
        console::demo_summary(
            &machine,
            args.stature_m,
            true_class,
            console::elapsed_s(now, start)
        )
    );
    println!(
        "  recording:      {} ({} messages, {}-compressed chunks; open in Foxglove or `ros2 bag info`)",
        out.display(),
        messages.map_or("n/a".to_owned(), |m| m.to_string()),
        recording::COMPRESSION
    );
    let (recording, report) = (shell_word(&out), shell_word(&out.with_extension("html")));
    println!("  review it:      ergocell review {recording}   (in the browser)");
    println!(
        "  report:         ergocell report {recording} --out {report}   (one HTML file to keep)"
    );
    exit_of(status, &machine, &out)
}

type DemoLoop = CellLoop<TwinRobot, DemoOutputs>;

/// The session played on the twin: the cell loop with the demo's outputs and deadline, the twin's
/// station, one session by the cell's rules (the session driver's; the twin's station is ready at
/// once). Returns the outcome, the simulator's clock at the end and the cell.
fn play(
    args: &Args,
    p: Prepared,
    rec: McapRecorder,
    start: i64,
    stop: &StopFlag,
) -> anyhow::Result<(Result<Outcome, DriverError>, i64, DemoLoop)> {
    let display = start_display(args.display)?;
    let real_time = display.is_some();
    let outputs = DemoOutputs {
        recording: Recording::new(Some(rec)),
        display,
        geometries: p
            .handovers
            .iter()
            .map(|h| (h.class, h.geometry.clone()))
            .collect(),
        start,
        rula: "RULA -".to_owned(),
    };
    let mut cell = CellLoop::new(p.machine, p.robot, outputs)
        .with_time_limit(start, p.limit_secs)
        .with_driver_state();
    if args.outcome.is_some() {
        cell = cell.with_command_log();
    }
    let hooks = TwinHooks {
        say: Box::new(|line| println!("{line}")),
        wall: Box::new(instant),
        sleep: real_time.then(|| Box::new(std::thread::sleep) as Box<dyn Fn(Duration)>),
        soak: args.soak_report.map(|minutes| {
            let every = Duration::from_secs(minutes.saturating_mul(60));
            (every, Box::new(rss_mib) as Box<dyn Fn() -> Option<f64>>)
        }),
    };
    let handovers = p
        .handovers
        .iter()
        .map(|h| ClassHandover {
            class: h.class,
            point: h.point,
        })
        .collect();
    let mut twin = TwinStation::new(
        SimSource::new(p.sim),
        FaultPlayer::new(p.schedule),
        handovers,
        p.true_class,
        p.joints,
        &p.rig,
        start,
        demo::frame_period_nanos(args.fps),
        hooks,
    );
    let mut driver = Driver::new(cell, Some(1));
    let outcome = futures::executor::block_on(driver.run(&mut twin, stop));
    if let Some(line) = twin.soak_last_line() {
        println!("{line}");
    }
    Ok((outcome, twin.now(), driver.into_cell()))
}

/// The demo's result from the session's exit status by the cell's rule.
fn exit_of(status: ExitStatus, machine: &SessionMachine, out: &Path) -> anyhow::Result<()> {
    let s = machine.summary();
    match status {
        ExitStatus::Done => Ok(()),
        ExitStatus::Stopped(signal) => Err(Stopped {
            signal: signal.into(),
            what: format!("robot held, recording {} closed", out.display()),
        }
        .into()),
        ExitStatus::NeedsAPerson => {
            if let Some(SessionEnd::Interrupted {
                by: Interruption::TimeLimit { limit_s },
            }) = &s.end
            {
                anyhow::bail!(
                    "the session did not end normally: the demo's time limit was reached: \
                     {limit_s:.1} s of simulated time (the script's {:.1} s + {:.0} s for \
                     the robot's way home)",
                    limit_s - demo::MARGIN_SECS,
                    demo::MARGIN_SECS
                );
            }
            anyhow::bail!("the session did not end normally: {}", s.end_reason)
        }
    }
}

/// `path` as one word for a POSIX shell: as it is when it holds only characters no shell treats
/// specially, else in single quotes (a quote inside written `'\''`), so a printed command can be
/// pasted as it stands.
fn shell_word(path: &Path) -> String {
    let text = path.display().to_string();
    let plain = !text.is_empty()
        && text
            .chars()
            .all(|c| c.is_ascii_alphanumeric() || "/._-+,:@%".contains(c));
    if plain {
        text
    } else {
        format!("'{}'", text.replace('\'', "'\\''"))
    }
}

#[cfg(test)]
mod tests {
    use super::shell_word;
    use std::path::Path;

    /// A plain path is printed as it is; one with a space, a quote or a `$` is one quoted word that
    /// `sh` reads back as the same path.
    #[test]
    fn a_path_is_printed_as_one_shell_word() {
        assert_eq!(shell_word(Path::new("/tmp/a-b_c.mcap")), "/tmp/a-b_c.mcap");
        for path in ["/tmp/my run.mcap", "/tmp/it's.mcap", "/tmp/$HOME;x.mcap"] {
            let word = shell_word(Path::new(path));
            let out = std::process::Command::new("sh")
                .arg("-c")
                .arg(format!("printf %s {word}"))
                .output()
                .unwrap();
            assert_eq!(String::from_utf8(out.stdout).unwrap(), path, "{word}");
        }
    }
}
