//! `ergocell`: the robot-cell controller's command line.
//!
//! The library crates do the work; files, the clock and the network are read here and in the ROS 2
//! backend (`ergocell_bridge`, `ergocell_ros_backend`: the DDS participant, the session clock, the
//! recording). Each subcommand lives in a module under `commands/` (`report` beside `review` in
//! `review.rs`).

/// The commands' `println!`: a closed stdout (`ergocell trajectories lock | head -1`) drops the line
/// and the command finishes its work (every lock written, every file closed); std's macro panics
/// with "failed printing to stdout" halfway through. Shadows std's in every command module.
macro_rules! println {
    () => {{
        use std::io::Write as _;
        let _ = writeln!(std::io::stdout());
    }};
    ($($t:tt)*) => {{
        use std::io::Write as _;
        let _ = writeln!(std::io::stdout(), $($t)*);
    }};
}

/// The commands' `print!`, as [`println!`].
macro_rules! print {
    ($($t:tt)*) => {{
        use std::io::Write as _;
        let _ = write!(std::io::stdout(), $($t)*);
    }};
}

/// The commands' `eprintln!`: a closed stderr drops the line, as [`println!`].
macro_rules! eprintln {
    () => {{
        use std::io::Write as _;
        let _ = writeln!(std::io::stderr());
    }};
    ($($t:tt)*) => {{
        use std::io::Write as _;
        let _ = writeln!(std::io::stderr(), $($t)*);
    }};
}

mod commands;

use clap::{Parser, Subcommand};

/// ergocell: protects the people who work beside industrial robots.
#[derive(Debug, Parser)]
#[command(name = "ergocell", version, about, long_about = None)]
struct Cli {
    /// Log filter (tracing `EnvFilter` syntax), e.g. `info`, `ergocell=debug` or `rustdds=debug`
    /// (default `warn`, `error` for `demo`, which prints every session event itself; both without
    /// ros2-client's "ROS_DISTRO is not set" note).
    #[arg(long, global = true)]
    log: Option<String>,
    #[command(subcommand)]
    command: Command,
}

#[derive(Debug, Subcommand)]
enum Command {
    /// The whole cell in one process on the simulator (no ROS): operator, height, locked trajectory, RULA, recording.
    Demo(commands::demo::Args),
    /// The cell controller on ROS 2: camera landmarks in, robot commands and session state out.
    Run(commands::run::Args),
    /// Replay a recording's camera landmarks over ROS 2 (`--ros`), as the camera nodes would publish them.
    Replay(commands::replay::ReplayArgs),
    /// Triangulate and fuse 2D detections from calibrated cameras into 3D landmarks.
    Triangulate(commands::triangulate::Args),
    /// Camera and stereo calibration from checkerboard images, written as a rig file.
    Calibrate(commands::calibrate::Args),
    /// RULA: score worksheets (`score`) or every frame of a 3D landmark recording (`track`).
    Rula(commands::rula::Args),
    /// REBA (whole body): score worksheets (`score`).
    Reba(commands::reba::Args),
    /// Estimate the operator's stature and height class from a 3D landmark recording.
    Height(commands::height::Args),
    /// Validate, lock, approve and verify the class handover trajectories (safety engineer's review).
    Trajectories(commands::trajectories::Args),
    /// Offline ergonomics review of a session recording in the browser (local web server).
    Review(commands::review::Args),
    /// The offline review as one self-contained HTML file (`--compare` for two sessions).
    Report(commands::review::ReportArgs),
    /// Exposure over many recordings: per operator, day and week, task segment and robot class.
    Exposure(commands::exposure::Args),
    /// The seed paper's experiments on the digital twin: table1, adaptation, height, rula-agreement.
    Sim(commands::sim::Args),
    /// DDS Security (SROS2): create the cell's keystore and enclaves.
    Security(commands::security::Args),
}

fn main() -> std::process::ExitCode {
    let cli = Cli::parse();
    let default_log = if matches!(cli.command, Command::Demo(_)) {
        "error"
    } else {
        "warn"
    };
    // A dependency's notes stay out of the default console: ros2-client's "ROS_DISTRO is not set"
    // (no ROS install is the normal case here). RustDDS keeps its warnings (a QoS mismatch shows
    // only there); its per-message ones without multicast are debug in the vendored copy, and `run`
    // says what a missing multicast route means once (`multicast_note`).
    let default_log = format!("{default_log},ros2_client::distributions=error");
    let filter = tracing_subscriber::EnvFilter::try_new(cli.log.as_deref().unwrap_or(&default_log))
        .unwrap_or_else(|_| tracing_subscriber::EnvFilter::new("warn"));
    // Colour only for a person at a terminal: a redirected stderr (a log file, journald, a pipe) gets
    // plain text.
    tracing_subscriber::fmt()
        .with_env_filter(filter)
        .with_writer(std::io::stderr)
        .with_ansi(std::io::IsTerminal::is_terminal(&std::io::stderr()))
        // A closed stderr (`ergocell run 2>&1 | head`) drops the event: tracing-subscriber would
        // report the failed write with std's `eprintln!`, which panics on the same closed stream
        // and took `run` down mid-session (exit 101) instead of holding the robot on Ctrl-C.
        .log_internal_errors(false)
        .init();
    let result = match cli.command {
        Command::Demo(args) => commands::demo::run(&args),
        Command::Run(args) => commands::run::run(&args),
        Command::Replay(args) => commands::replay::replay(&args),
        Command::Triangulate(args) => commands::triangulate::run(&args),
        Command::Calibrate(args) => commands::calibrate::run(&args),
        Command::Rula(args) => commands::rula::run(&args),
        Command::Reba(args) => commands::reba::run(&args),
        Command::Height(args) => commands::height::run(&args),
        Command::Trajectories(args) => commands::trajectories::run(&args),
        Command::Sim(args) => commands::sim::run(&args),
        Command::Review(args) => commands::review::run(&args),
        Command::Report(args) => commands::review::report(&args),
        Command::Exposure(args) => commands::exposure::run(&args),
        Command::Security(args) => commands::security::run(&args),
    };
    match result {
        Ok(()) => std::process::ExitCode::SUCCESS,
        Err(err) => {
            if err
                .chain()
                .any(<dyn std::error::Error>::is::<commands::signals::Stopped>)
            {
                // Not a failure of ours: the robot was held and the recording closed.
                eprintln!("ergocell: {err:#}");
            } else {
                eprintln!("error: {err:#}");
            }
            std::process::ExitCode::from(commands::exit_code(&err))
        }
    }
}
