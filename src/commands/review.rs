//! `ergocell review` and `ergocell report`: a session recording for the ergonomics expert.
//!
//! `review` serves the review page of one recording on a local web server: loopback by default, and
//! then it answers only requests whose `Host` is the loopback address it printed (a page on another
//! site cannot reach it through DNS rebinding). It serves exactly four things, all from memory —
//! the page, its script, its stylesheet and the recording's analysis — and never reads a path from a
//! request, so nothing but the given recording can be served. `--bind` serves elsewhere on request.
//!
//! `report` writes the same page as one self-contained HTML file (data, three.js, uPlot inlined)
//! that opens offline and can be mailed; `--compare` puts a second session beside the first. It never
//! writes over an existing file unless asked (`--force`), and never over one of its recordings.
//!
//! The server itself (its routes, Host rules and connection limits: 10 s header timeout, 30 s stall
//! timeout, 64 connections) is `ergocell_web::review_server`. Ctrl-C (SIGINT) and SIGTERM stop it the
//! same way: no new connections, idle ones closed, responses under way get up to 1 s, exit 0.

use std::net::{IpAddr, Ipv4Addr, SocketAddr};
use std::path::{Path, PathBuf};
use std::sync::Arc;
use std::time::Duration;

use anyhow::Context as _;
use ergocell::recordings::{self, Loaded};
use ergocell_review::{page, text, ReviewData};
use ergocell_web::review_server::{self, Limits, Served, MAX_CONNECTIONS, SHUTDOWN_GRACE};
use tokio::net::TcpListener;

use super::{output, signals, UsageError};

/// The recordings to review (both commands).
#[derive(Debug, clap::Args)]
pub struct Input {
    /// The session recording (`.mcap`, from `ergocell demo`, `ergocell run --record` or
    /// `ergocell sim adaptation --record-height`).
    pub recording: PathBuf,
    /// A second recording shown beside the first (e.g. before vs after the robot's adaptation).
    #[arg(long)]
    pub compare: Option<PathBuf>,
    /// Which operator session of the recording (1-based): `ergocell run --record` writes one after
    /// another into one file.
    #[arg(long, default_value_t = 1)]
    pub session: usize,
    /// Which operator session of the `--compare` recording (1-based).
    #[arg(long, default_value_t = 1)]
    pub compare_session: usize,
    /// Which frames the page holds: `all`, or `overview` (every frame of the worst moments, the
    /// worst frame of each few seconds elsewhere; the summary, rows and distributions still over
    /// every frame, in bounded memory). `auto`: the overview for a recording of 256 MiB or more
    /// (about 50 minutes of a session), or when `--window` is given.
    #[arg(long, value_enum, default_value_t = PageFrames::Auto)]
    pub page_frames: PageFrames,
    /// Also every frame from FROM to TO, seconds on the page's clock (from the recording's first
    /// message), e.g. `--window 12300..12420` to see two minutes of a shift's overview at the
    /// recorded rate (repeatable; implies the overview).
    #[arg(long = "window", value_name = "FROM..TO", value_parser = parse_window)]
    pub windows: Vec<[f64; 2]>,
    /// The overview's frames outside the worst moments; hidden, for the tests.
    #[arg(long, hide = true, default_value_t = ergocell_review::overview::OVERVIEW_FRAMES)]
    pub overview_frames: usize,
    /// The overview's frames within the worst moments; hidden, for the tests.
    #[arg(long, hide = true, default_value_t = ergocell_review::overview::WINDOW_FRAMES)]
    pub window_frames: usize,
}

/// `FROM..TO` in seconds, FROM ≤ TO.
fn parse_window(text: &str) -> Result<[f64; 2], String> {
    let (a, b) = text
        .split_once("..")
        .ok_or_else(|| format!("{text:?}: expected FROM..TO in seconds, e.g. 120..180"))?;
    let secs = |s: &str| -> Result<f64, String> {
        s.trim()
            .parse::<f64>()
            .ok()
            .filter(|v| v.is_finite() && *v >= 0.0)
            .ok_or_else(|| format!("{s:?}: not a time in seconds (0 or more)"))
    };
    let (a, b) = (secs(a)?, secs(b)?);
    if a > b {
        return Err(format!("{text:?}: FROM is after TO"));
    }
    Ok([a, b])
}

impl Input {
    fn budget(&self) -> ergocell_review::overview::Budget {
        ergocell_review::overview::Budget {
            overview_frames: self.overview_frames,
            window_frames: self.window_frames,
        }
    }
}

/// See [`Input::page_frames`] ([`recordings::PageFrames`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum PageFrames {
    Auto,
    All,
    Overview,
}

impl From<PageFrames> for recordings::PageFrames {
    fn from(frames: PageFrames) -> Self {
        match frames {
            PageFrames::Auto => Self::Auto,
            PageFrames::All => Self::All,
            PageFrames::Overview => Self::Overview,
        }
    }
}

#[derive(Debug, clap::Args)]
#[command(
    after_help = "Exit codes: 0 the server was stopped by Ctrl-C (SIGINT) or SIGTERM (responses \
    under way get up to 1 s to finish); 2 bad input (a recording that cannot be read, an address \
    that cannot be listened on)."
)]
pub struct Args {
    #[command(flatten)]
    pub input: Input,
    /// Address to listen on. Loopback by default; any other address serves the recording to the
    /// network (and then accepts any Host header).
    #[arg(long, default_value_t = IpAddr::V4(Ipv4Addr::LOCALHOST))]
    pub bind: IpAddr,
    /// Port (0 = any free port; the URL is printed).
    #[arg(long, default_value_t = 8765)]
    pub port: u16,
    /// Also accept this `Host` (repeatable), e.g. `localhost:9000` for a browser reaching the
    /// server through `ssh -L 9000:localhost:8765`. The server still listens on loopback only.
    #[arg(long = "allow-host", value_name = "HOST:PORT")]
    pub allow_hosts: Vec<String>,
    /// The header timeout in milliseconds (see the module docs); hidden, for the tests.
    #[arg(
        long = "header-timeout-ms",
        hide = true,
        default_value_t = 10_000,
        value_parser = clap::value_parser!(u64).range(1..)
    )]
    pub header_timeout_ms: u64,
    /// The stall timeout in milliseconds (see the module docs); hidden, for the tests.
    #[arg(
        long = "stall-timeout-ms",
        hide = true,
        default_value_t = 30_000,
        value_parser = clap::value_parser!(u64).range(1..)
    )]
    pub stall_timeout_ms: u64,
}

#[derive(Debug, clap::Args)]
pub struct ReportArgs {
    #[command(flatten)]
    pub input: Input,
    /// The HTML file to write; an existing file is refused unless --force, and a recording of the
    /// report always.
    #[arg(long, default_value = "report.html")]
    pub out: PathBuf,
    /// Also write the session's frames as CSV (a row per recorded frame: time, session state, task
    /// segment, robot leg, each side's RULA breakdown and REBA score, every joint angle in degrees,
    /// the warning events), for a spreadsheet. Of the first recording's session.
    #[arg(long, value_name = "FILE")]
    pub csv: Option<PathBuf>,
    /// Also write the session summary as CSV (`ergocell rula track --summary-csv`'s layout: time
    /// shares, exposure, REBA, ISO 11226 static postures, task segments, warnings). Of the first
    /// recording's session.
    #[arg(long, value_name = "FILE")]
    pub summary_csv: Option<PathBuf>,
    /// Overwrite existing output files.
    #[arg(long)]
    pub force: bool,
}

/// Reads one recording and analyses its operator session `session` (1-based,
/// [`recordings::load`]); what is wrong with it goes to stderr (and onto the page), as does how an
/// overview thinned the page.
fn load(input: &Input, path: &Path, session: usize, frames: PageFrames) -> anyhow::Result<Loaded> {
    let loaded = recordings::load(&recordings::Request {
        path,
        session,
        frames: frames.into(),
        budget: input.budget(),
        windows: &input.windows,
    })?;
    if let Some(t) = &loaded.thinned {
        eprintln!(
            "note: {}: the page holds {} of {} frames (the worst moments at the recorded rate, the worst frame of each few seconds elsewhere); the numbers are over every frame",
            path.display(),
            t.kept,
            t.recorded
        );
    }
    for p in &loaded.review.source.problems {
        eprintln!("warning: {}: {p}", path.display());
    }
    Ok(loaded)
}

/// The page's data, and the first session's recording when it was read whole (for the frames CSV).
fn load_all(
    input: &Input,
    first_frames: PageFrames,
) -> anyhow::Result<(ReviewData, Option<ergocell_review::Recording>)> {
    let first = load(input, &input.recording, input.session, first_frames)?;
    let mut sessions = vec![first.review];
    if let Some(other) = &input.compare {
        sessions.push(load(input, other, input.compare_session, input.page_frames)?.review);
    }
    Ok((ReviewData::new(sessions), first.recording))
}

/// Every output of `report`, checked before any work: never an input, never another output, no
/// overwrite without --force. Gives the first recording's frames: all of them for `--csv`.
fn check_report_outputs(args: &ReportArgs) -> anyhow::Result<PageFrames> {
    let mut inputs = vec![("<recording>", args.input.recording.as_path())];
    if let Some(other) = &args.input.compare {
        inputs.push(("--compare", other.as_path()));
    }
    output::check("--out", &args.out, args.force, &inputs)?;
    inputs.push(("--out", args.out.as_path()));
    for (flag, path) in [("--csv", &args.csv), ("--summary-csv", &args.summary_csv)] {
        if let Some(path) = path {
            for (other, p) in &inputs {
                if other.starts_with("--") && output::same_path(p, path) {
                    return Err(UsageError(format!(
                        "{flag} {} is also {other}: choose another file",
                        path.display()
                    ))
                    .into());
                }
            }
            output::check(flag, path, args.force, &inputs)?;
            inputs.push((flag, path.as_path()));
        }
    }
    // The frames CSV has a row per recorded frame: the first recording is then read whole.
    match (args.csv.is_some(), args.input.page_frames) {
        (false, frames) => Ok(frames),
        (true, PageFrames::Overview) => Err(UsageError(
            "--csv writes every frame: it needs --page-frames all (or auto)".to_owned(),
        )
        .into()),
        (true, _) => Ok(PageFrames::All),
    }
}

pub fn report(args: &ReportArgs) -> anyhow::Result<()> {
    let first_frames = check_report_outputs(args)?;
    let (data, recording) = load_all(&args.input, first_frames)?;
    let html = page::report_page(&data).context("serialising the review")?;
    let first = &data.sessions[0];
    let frames_csv = match (&args.csv, &recording) {
        (Some(_), Some(recording)) => Some(ergocell_review::export::write_frames(
            Vec::new(),
            recording,
            first,
        )?),
        _ => None,
    };
    let summary_csv = match &args.summary_csv {
        Some(_) => Some(ergocell_review::export::write_summary(Vec::new(), first)?),
        None => None,
    };
    output::write("--out", &args.out, args.force, html.as_bytes())?;
    if let (Some(path), Some(bytes)) = (&args.csv, frames_csv) {
        output::write("--csv", path, args.force, &bytes)?;
        println!(
            "frames CSV: {} ({} rows)",
            path.display(),
            first.frames.t.len()
        );
    }
    if let (Some(path), Some(bytes)) = (&args.summary_csv, summary_csv) {
        output::write("--summary-csv", path, args.force, &bytes)?;
        println!("summary CSV: {}", path.display());
    }
    println!("{}", text::summary_text(&data));
    println!(
        "{}",
        text::report_line(&args.out.display().to_string(), html.len())
    );
    Ok(())
}

/// What the server holds: everything it can ever answer with.
pub fn run(args: &Args) -> anyhow::Result<()> {
    let (data, _) = load_all(&args.input, args.input.page_frames)?;
    let json = serde_json::to_string(&data).context("serialising the review")?;
    let runtime = tokio::runtime::Builder::new_multi_thread()
        .worker_threads(2)
        .enable_all()
        .build()
        .context("tokio runtime")?;
    runtime.block_on(async {
        // Installed before the server listens: SIGTERM (systemd, docker) stops it like Ctrl-C.
        let stop = signals::stop_signal().context("installing the SIGINT/SIGTERM handlers")?;
        let listener = TcpListener::bind(SocketAddr::new(args.bind, args.port))
            .await
            .map_err(|e| {
                UsageError(format!("cannot listen on {}:{}: {e}", args.bind, args.port))
            })?;
        let addr = listener.local_addr()?;
        // An IPv4-mapped loopback (::ffff:127.0.0.1) is loopback too.
        let loopback = args.bind.to_canonical().is_loopback();
        // The Host values a browser sends for the printed URL (and `localhost`), nothing else.
        let allowed_hosts = loopback.then(|| {
            let mut hosts = vec![addr.to_string(), format!("localhost:{}", addr.port())];
            hosts.extend(args.allow_hosts.iter().cloned());
            hosts
        });
        let served = Arc::new(Served::new(page::served_page(&data), json, allowed_hosts));
        let app = review_server::router(served);
        println!("{}", text::summary_text(&data));
        let shown = if addr.ip().is_unspecified() {
            SocketAddr::new(IpAddr::V4(Ipv4Addr::LOCALHOST), addr.port())
        } else {
            addr
        };
        println!("review: http://{shown}/");
        if !loopback {
            println!("  serving on {addr} to the network, as asked (--bind)");
        }
        println!("  Ctrl-C (or SIGTERM) stops the server");
        let limits = Limits {
            header_timeout: Duration::from_millis(args.header_timeout_ms),
            stall_timeout: Duration::from_millis(args.stall_timeout_ms),
            max_connections: MAX_CONNECTIONS,
            shutdown_grace: SHUTDOWN_GRACE,
        };
        let signal = review_server::serve(listener, app, limits, stop).await;
        println!("review: stopped by {}", signal.name());
        anyhow::Ok(())
    })
}
