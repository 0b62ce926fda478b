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
//! The server bounds what a client can hold, so that slow, idle or half-open connections cannot
//! starve it (nor exhaust its file descriptors: at `ulimit -n 128` it keeps serving):
//! - **header timeout**, 10 s: a request's head (request line and headers) must arrive in full within
//!   10 s of the connection opening or of the previous response; the clock restarts after each
//!   response, so this is also the idle keep-alive timeout. Then the connection is closed.
//! - **stall timeout**, 30 s: a connection on which no byte moved either way for 30 s is closed,
//!   whatever it is doing (a client that stopped reading its response).
//! - **at most 64 connections** at a time. The 65th is not refused: the open connection that has gone
//!   longest without a request under way (idle keep-alive, or a head still coming) is closed to make
//!   room, so a browser's request is answered at once even while others hold connections open
//!   without asking anything. Only when all 64 are answering requests does the new one wait (in the
//!   kernel's accept queue) for one of them to finish.
//!
//! Ctrl-C (SIGINT) and SIGTERM stop the server the same way: it stops accepting, closes the
//! connections with no request under way (a half-sent request is not waited for), gives responses
//! under way up to 1 s to finish, and exits 0.

use std::collections::HashMap;
use std::convert::Infallible;
use std::future::Future;
use std::io::Write as _;
use std::net::{IpAddr, Ipv4Addr, SocketAddr};
use std::path::{Path, PathBuf};
use std::pin::{pin, Pin};
use std::sync::atomic::{AtomicBool, AtomicU64, AtomicUsize, Ordering};
use std::sync::{Arc, Mutex, PoisonError};
use std::task::{Context, Poll};
use std::time::Duration;

use anyhow::Context as _;
use axum::extract::{ConnectInfo, Request, State};
use axum::http::{header, HeaderValue, Method, StatusCode};
use axum::middleware::Next;
use axum::response::{IntoResponse, Response};
use axum::routing::get;
use axum::Router;
use ergocell_review::read::split_sessions;
use ergocell_review::{analyse, page, read_recording, ReviewData, SessionReview};
use hyper::body::{Frame, Incoming, SizeHint};
use hyper::service::Service as _;
use hyper_util::rt::{TokioIo, TokioTimer};
use hyper_util::service::TowerToHyperService;
use tokio::io::{AsyncRead, AsyncWrite, ReadBuf};
use tokio::net::{TcpListener, TcpStream};
use tokio::sync::{watch, Notify, Semaphore};
use tokio::task::JoinSet;
use tokio::time::Instant;

use super::{output, signals, UsageError};

/// `println!` that ignores a closed stdout: `ergocell review x.mcap | head -1` (or a test that reads
/// only the URL line) must not bring the server down.
macro_rules! say {
    ($($t:tt)*) => {{
        let mut out = std::io::stdout();
        let _ = writeln!(out, $($t)*);
        let _ = out.flush();
    }};
}

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
    /// Overwrite an existing --out file.
    #[arg(long)]
    pub force: bool,
}

/// Reads one recording and analyses its operator session `session` (1-based); what is wrong with it
/// goes to stderr and onto the page.
fn load(path: &Path, session: usize) -> anyhow::Result<SessionReview> {
    let bytes = std::fs::read(path).with_context(|| format!("cannot read {}", path.display()))?;
    let recording =
        read_recording(&bytes).map_err(|e| UsageError(format!("{}: {e}", path.display())))?;
    let mut parts = split_sessions(&recording);
    let count = parts.len();
    if session == 0 || session > count.max(1) {
        return Err(UsageError(format!(
            "{}: --session {session}: the recording holds {count} operator session(s)",
            path.display()
        ))
        .into());
    }
    let name = path.file_name().map_or_else(
        || path.display().to_string(),
        |n| n.to_string_lossy().into_owned(),
    );
    let (label, mut recording) = if count > 1 {
        let listing = parts
            .iter()
            .map(|p| format!("{}: {}", p.number, describe_part(&p.recording)))
            .collect::<Vec<_>>()
            .join("; ");
        let mut chosen = parts.swap_remove(session - 1).recording;
        chosen.problems.push(format!(
            "this recording holds {count} operator sessions ({listing}); this page shows session {session} (--session N picks another)"
        ));
        (format!("{name} · session {session}/{count}"), chosen)
    } else {
        (name, parts.pop().map_or(recording, |p| p.recording))
    };
    recording.problems.dedup();
    let review = analyse(&recording, &label);
    for p in &review.source.problems {
        let _ = writeln!(std::io::stderr(), "warning: {}: {p}", path.display());
    }
    Ok(review)
}

/// One line on an operator session: frames, class and height, duration.
fn describe_part(r: &ergocell_review::Recording) -> String {
    let t0 = r.first_log_time_nanos.unwrap_or(0);
    let secs = r
        .last_log_time_nanos
        .map_or(0.0, |t| t.saturating_sub(t0) as f64 * 1e-9);
    let decided = r
        .states
        .iter()
        .rev()
        .find(|s| !s.message.height_class.is_empty());
    let class = decided.map_or_else(
        || "no class decided".to_owned(),
        |s| format!("{} at {:.3} m", s.message.height_class, s.message.height_m),
    );
    format!("{} frames, {class}, {secs:.0} s", r.poses.len())
}

fn load_all(input: &Input) -> anyhow::Result<ReviewData> {
    let mut sessions = vec![load(&input.recording, input.session)?];
    if let Some(other) = &input.compare {
        sessions.push(load(other, input.compare_session)?);
    }
    Ok(ReviewData::new(sessions))
}

fn summary(data: &ReviewData) -> String {
    data.sessions
        .iter()
        .map(|s| {
            format!(
                "{}: {} frames over {:.1} s, {} warnings, height {}, class {}{}",
                s.label,
                s.frames.t.len(),
                s.frames.t.last().copied().unwrap_or(0.0),
                s.warnings.iter().filter(|w| w.kind == "raised").count(),
                s.facts
                    .height_m
                    .map_or("not measured".to_owned(), |h| format!("{h:.3} m")),
                s.facts.height_class.as_deref().unwrap_or("none"),
                if s.source.complete {
                    ""
                } else {
                    " (incomplete file)"
                }
            )
        })
        .collect::<Vec<_>>()
        .join("\n")
}

pub fn report(args: &ReportArgs) -> anyhow::Result<()> {
    let mut inputs = vec![("<recording>", args.input.recording.as_path())];
    if let Some(other) = &args.input.compare {
        inputs.push(("--compare", other.as_path()));
    }
    output::check("--out", &args.out, args.force, &inputs)?;
    let data = load_all(&args.input)?;
    let html = page::report_page(&data).context("serialising the review")?;
    output::write("--out", &args.out, args.force, html.as_bytes())?;
    say!("{}", summary(&data));
    say!(
        "report: {} ({:.1} MB, self-contained: opens offline in any browser)",
        args.out.display(),
        html.len() as f64 / 1e6
    );
    Ok(())
}

/// What the server holds: everything it can ever answer with.
struct Served {
    /// Shared, not copied, per request.
    page: axum::body::Bytes,
    json: axum::body::Bytes,
    /// `Host` values accepted; `None` when asked to serve the network.
    allowed_hosts: Option<Vec<String>>,
}

pub fn run(args: &Args) -> anyhow::Result<()> {
    let data = load_all(&args.input)?;
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
        let served = Arc::new(Served {
            page: page::served_page(&data).into(),
            json: json.into(),
            allowed_hosts,
        });
        let app = Router::new()
            .route("/", get(index))
            .route("/assets/review.js", get(script))
            .route("/assets/review.css", get(stylesheet))
            .route("/api/review.json", get(review_json))
            .route("/favicon.ico", get(|| async { StatusCode::NO_CONTENT }))
            .fallback(not_found)
            .layer(axum::middleware::from_fn_with_state(served.clone(), guard))
            .with_state(served);
        say!("{}", summary(&data));
        let shown = if addr.ip().is_unspecified() {
            SocketAddr::new(IpAddr::V4(Ipv4Addr::LOCALHOST), addr.port())
        } else {
            addr
        };
        say!("review: http://{shown}/");
        if !loopback {
            say!("  serving on {addr} to the network, as asked (--bind)");
        }
        say!("  Ctrl-C (or SIGTERM) stops the server");
        let limits = Limits {
            header_timeout: Duration::from_millis(args.header_timeout_ms),
            stall_timeout: Duration::from_millis(args.stall_timeout_ms),
            max_connections: MAX_CONNECTIONS,
            shutdown_grace: SHUTDOWN_GRACE,
        };
        serve(listener, app, limits, stop).await;
        anyhow::Ok(())
    })
}

/// Connections open at a time (see the module docs).
const MAX_CONNECTIONS: usize = 64;
/// How long responses under way may take to finish once a stop signal arrived.
const SHUTDOWN_GRACE: Duration = Duration::from_secs(1);
/// Pause before accepting again after `accept` failed for want of descriptors or memory.
const ACCEPT_BACKOFF: Duration = Duration::from_millis(100);

/// What a client can hold of the server (see the module docs).
#[derive(Debug, Clone, Copy)]
struct Limits {
    header_timeout: Duration,
    stall_timeout: Duration,
    max_connections: usize,
    shutdown_grace: Duration,
}

/// One open connection, as its task and the accept loop see it. Times are milliseconds since
/// `epoch` (the runtime's monotonic clock).
struct Conn {
    epoch: Instant,
    /// Requests read whose response hyper has not finished with (it drops the response body once it
    /// has been written, or when the connection closes).
    busy: AtomicUsize,
    /// Since when no request has been under way: accepted, or its last response sent.
    free_since_ms: AtomicU64,
    /// When a byte was last read or written.
    last_io_ms: AtomicU64,
    /// Chosen to make room for a new connection (and not chosen twice).
    evicted: AtomicBool,
    close: Notify,
}

impl Conn {
    fn new(epoch: Instant) -> Self {
        let now = ms_since(epoch);
        Self {
            epoch,
            busy: AtomicUsize::new(0),
            free_since_ms: AtomicU64::new(now),
            last_io_ms: AtomicU64::new(now),
            evicted: AtomicBool::new(false),
            close: Notify::new(),
        }
    }

    fn touch(&self) {
        self.last_io_ms
            .store(ms_since(self.epoch), Ordering::Relaxed);
    }
}

fn ms_since(epoch: Instant) -> u64 {
    u64::try_from(epoch.elapsed().as_millis()).unwrap_or(u64::MAX)
}

/// The open connections, by id.
type Conns = Arc<Mutex<HashMap<u64, Arc<Conn>>>>;

/// Removes a connection from [`Conns`] when its task ends (or is aborted).
struct Registered {
    conns: Conns,
    id: u64,
}

impl Drop for Registered {
    fn drop(&mut self) {
        self.conns
            .lock()
            .unwrap_or_else(PoisonError::into_inner)
            .remove(&self.id);
    }
}

/// Asks the connection that has gone longest without a request under way to close; false when every
/// connection is answering a request.
fn evict_longest_free(conns: &Conns) -> bool {
    let conns = conns.lock().unwrap_or_else(PoisonError::into_inner);
    let victim = conns
        .values()
        .filter(|c| c.busy.load(Ordering::SeqCst) == 0 && !c.evicted.load(Ordering::SeqCst))
        .min_by_key(|c| c.free_since_ms.load(Ordering::SeqCst));
    victim.is_some_and(|c| {
        c.evicted.store(true, Ordering::SeqCst);
        c.close.notify_one();
        true
    })
}

/// A request under way on a connection, from the moment hyper hands it over until its response body
/// is dropped.
struct Busy(Arc<Conn>);

impl Busy {
    fn new(conn: Arc<Conn>) -> Self {
        conn.busy.fetch_add(1, Ordering::SeqCst);
        Self(conn)
    }
}

impl Drop for Busy {
    fn drop(&mut self) {
        let c = &self.0;
        if c.busy.fetch_sub(1, Ordering::SeqCst) == 1 {
            c.free_since_ms.store(ms_since(c.epoch), Ordering::SeqCst);
        }
    }
}

/// A response body that keeps its request counted as under way until hyper is done with it.
struct Tracked {
    body: axum::body::Body,
    _busy: Busy,
}

impl axum::body::HttpBody for Tracked {
    type Data = axum::body::Bytes;
    type Error = axum::Error;

    fn poll_frame(
        self: Pin<&mut Self>,
        cx: &mut Context<'_>,
    ) -> Poll<Option<Result<Frame<Self::Data>, Self::Error>>> {
        Pin::new(&mut self.get_mut().body).poll_frame(cx)
    }

    fn is_end_stream(&self) -> bool {
        self.body.is_end_stream()
    }

    fn size_hint(&self) -> SizeHint {
        self.body.size_hint()
    }
}

/// The connection's socket, noting when bytes move (for the stall timeout).
struct Watched {
    stream: TcpStream,
    conn: Arc<Conn>,
}

impl AsyncRead for Watched {
    fn poll_read(
        self: Pin<&mut Self>,
        cx: &mut Context<'_>,
        buf: &mut ReadBuf<'_>,
    ) -> Poll<std::io::Result<()>> {
        let this = self.get_mut();
        let before = buf.filled().len();
        let polled = Pin::new(&mut this.stream).poll_read(cx, buf);
        if buf.filled().len() > before {
            this.conn.touch();
        }
        polled
    }
}

impl AsyncWrite for Watched {
    fn poll_write(
        self: Pin<&mut Self>,
        cx: &mut Context<'_>,
        buf: &[u8],
    ) -> Poll<std::io::Result<usize>> {
        let this = self.get_mut();
        let polled = Pin::new(&mut this.stream).poll_write(cx, buf);
        if matches!(polled, Poll::Ready(Ok(n)) if n > 0) {
            this.conn.touch();
        }
        polled
    }

    fn poll_write_vectored(
        self: Pin<&mut Self>,
        cx: &mut Context<'_>,
        bufs: &[std::io::IoSlice<'_>],
    ) -> Poll<std::io::Result<usize>> {
        let this = self.get_mut();
        let polled = Pin::new(&mut this.stream).poll_write_vectored(cx, bufs);
        if matches!(polled, Poll::Ready(Ok(n)) if n > 0) {
            this.conn.touch();
        }
        polled
    }

    fn is_write_vectored(&self) -> bool {
        self.stream.is_write_vectored()
    }

    fn poll_flush(self: Pin<&mut Self>, cx: &mut Context<'_>) -> Poll<std::io::Result<()>> {
        Pin::new(&mut self.get_mut().stream).poll_flush(cx)
    }

    fn poll_shutdown(self: Pin<&mut Self>, cx: &mut Context<'_>) -> Poll<std::io::Result<()>> {
        Pin::new(&mut self.get_mut().stream).poll_shutdown(cx)
    }
}

/// Resolves once no byte has moved on the connection for `limit`.
async fn stalled(conn: &Conn, limit: Duration) {
    loop {
        let last = Duration::from_millis(conn.last_io_ms.load(Ordering::Relaxed));
        let quiet = conn.epoch.elapsed().saturating_sub(last);
        if quiet >= limit {
            return;
        }
        tokio::time::sleep(limit.saturating_sub(quiet)).await;
    }
}

/// Serves `app` on `listener` within `limits` until `stop` resolves, then shuts down (see the module
/// docs).
async fn serve(
    listener: TcpListener,
    app: Router,
    limits: Limits,
    stop: impl Future<Output = signals::Signal>,
) {
    let epoch = Instant::now();
    let slots = Arc::new(Semaphore::new(limits.max_connections));
    let conns = Conns::default();
    let (stopping, stop_rx) = watch::channel(false);
    let mut tasks = JoinSet::new();
    let mut stop = pin!(stop);
    let mut next_id = 0_u64;
    let signal = loop {
        let (stream, peer) = tokio::select! {
            signal = &mut stop => break signal,
            Some(_) = tasks.join_next(), if !tasks.is_empty() => continue,
            accepted = listener.accept() => match accepted {
                Ok(accepted) => accepted,
                Err(e) if is_connection_error(&e) => continue,
                Err(e) => {
                    // EMFILE, ENFILE, ENOBUFS: wait a little rather than spin.
                    tracing::warn!("review server: cannot accept a connection: {e}");
                    tokio::select! {
                        signal = &mut stop => break signal,
                        () = tokio::time::sleep(ACCEPT_BACKOFF) => continue,
                    }
                }
            },
        };
        let permit = if let Ok(permit) = slots.clone().try_acquire_owned() {
            permit
        } else {
            evict_longest_free(&conns);
            tokio::select! {
                signal = &mut stop => break signal,
                permit = slots.clone().acquire_owned() => match permit {
                    Ok(permit) => permit,
                    Err(_) => continue, // never closed
                },
            }
        };
        let conn = Arc::new(Conn::new(epoch));
        next_id += 1;
        conns
            .lock()
            .unwrap_or_else(PoisonError::into_inner)
            .insert(next_id, conn.clone());
        let registered = Registered {
            conns: conns.clone(),
            id: next_id,
        };
        let (app, stop_rx) = (app.clone(), stop_rx.clone());
        tasks.spawn(async move {
            let _slot = permit;
            let _registered = registered;
            serve_connection(stream, peer, conn, app, limits, stop_rx).await;
        });
    };
    say!("review: stopped by {}", signal.name());
    drop(listener);
    stopping.send_replace(true);
    let _ = tokio::time::timeout(limits.shutdown_grace, async {
        while tasks.join_next().await.is_some() {}
    })
    .await;
    tasks.abort_all();
}

/// Errors of one incoming connection, not of the listener.
fn is_connection_error(e: &std::io::Error) -> bool {
    use std::io::ErrorKind::{ConnectionAborted, ConnectionRefused, ConnectionReset, Interrupted};
    matches!(
        e.kind(),
        ConnectionAborted | ConnectionRefused | ConnectionReset | Interrupted
    )
}

/// Serves one connection until it closes, times out (header or stall timeout), is evicted, or the
/// server stops: then at once if no request is under way, else after its response (the caller cuts
/// that short after the grace).
async fn serve_connection(
    stream: TcpStream,
    peer: SocketAddr,
    conn: Arc<Conn>,
    app: Router,
    limits: Limits,
    mut stop: watch::Receiver<bool>,
) {
    let routed = TowerToHyperService::new(app);
    let counted = conn.clone();
    let service = hyper::service::service_fn(move |mut request: axum::http::Request<Incoming>| {
        // What `into_make_service_with_connect_info` would add: the peer, for `guard`.
        request.extensions_mut().insert(ConnectInfo(peer));
        let busy = Busy::new(counted.clone());
        let response = routed.call(request);
        async move {
            let response = response.await?;
            Ok::<_, Infallible>(response.map(|body| Tracked { body, _busy: busy }))
        }
    });
    let io = TokioIo::new(Watched {
        stream,
        conn: conn.clone(),
    });
    let mut http = hyper::server::conn::http1::Builder::new();
    http.timer(TokioTimer::new())
        .header_read_timeout(limits.header_timeout);
    let mut served = pin!(http.serve_connection(io, service));
    let mut stall = pin!(stalled(&conn, limits.stall_timeout));
    let mut stopping = false;
    loop {
        tokio::select! {
            // Done, or failed (header timeout, reset by the peer): closed either way.
            _ = served.as_mut() => return,
            () = &mut stall => return,
            () = conn.close.notified() => return,
            _ = stop.changed(), if !stopping => {
                stopping = true;
                if conn.busy.load(Ordering::SeqCst) == 0 {
                    return;
                }
                served.as_mut().graceful_shutdown();
            }
        }
    }
}

/// Refuses other hosts (peer not on loopback, or a `Host` that is not the printed address) unless the
/// server was bound elsewhere on request, and anything but GET/HEAD. Adds the security headers.
async fn guard(
    State(served): State<Arc<Served>>,
    ConnectInfo(peer): ConnectInfo<SocketAddr>,
    request: Request,
    next: Next,
) -> Response {
    if request.headers().get_all(header::HOST).iter().count() > 1 {
        // RFC 9112 §3.2: more than one Host is a bad request.
        return (StatusCode::BAD_REQUEST, "more than one Host header").into_response();
    }
    if let Some(allowed) = &served.allowed_hosts {
        let host = request
            .headers()
            .get(header::HOST)
            .and_then(|h| h.to_str().ok())
            .unwrap_or("");
        if !peer.ip().to_canonical().is_loopback()
            || !allowed.iter().any(|a| a.eq_ignore_ascii_case(host))
        {
            return (
                StatusCode::FORBIDDEN,
                format!(
                    "forbidden: this review server answers only on {}",
                    allowed.join(", ")
                ),
            )
                .into_response();
        }
    }
    if request.method() != Method::GET && request.method() != Method::HEAD {
        return StatusCode::METHOD_NOT_ALLOWED.into_response();
    }
    let mut response = next.run(request).await;
    let h = response.headers_mut();
    h.insert(
        header::CONTENT_SECURITY_POLICY,
        HeaderValue::from_static(
            "default-src 'none'; script-src 'self'; style-src 'self' 'unsafe-inline'; \
             img-src 'self' data: blob:; connect-src 'self'; frame-ancestors 'none'; \
             base-uri 'none'; form-action 'none'",
        ),
    );
    h.insert(
        header::X_CONTENT_TYPE_OPTIONS,
        HeaderValue::from_static("nosniff"),
    );
    h.insert(header::CACHE_CONTROL, HeaderValue::from_static("no-store"));
    response
}

fn with_type(content_type: &'static str, body: impl Into<axum::body::Body>) -> Response {
    ([(header::CONTENT_TYPE, content_type)], body.into()).into_response()
}

async fn index(State(s): State<Arc<Served>>) -> Response {
    with_type("text/html; charset=utf-8", s.page.clone())
}

async fn script() -> Response {
    with_type("text/javascript; charset=utf-8", page::REVIEW_JS)
}

async fn stylesheet() -> Response {
    with_type("text/css; charset=utf-8", page::REVIEW_CSS)
}

async fn review_json(State(s): State<Arc<Served>>) -> Response {
    with_type("application/json", s.json.clone())
}

async fn not_found() -> Response {
    (
        StatusCode::NOT_FOUND,
        "not found: this server serves only the review page of the recording it was started with",
    )
        .into_response()
}
