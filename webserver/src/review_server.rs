//! The offline review's local web server, shared by `ergocell review` and the fuzz target of its
//! request handling (`fuzz/`, through [`serve_io`]).
//!
//! It serves exactly four things, all from memory — the page, its script, its stylesheet and the
//! recording's analysis — and never reads a path from a request. On loopback it answers only requests
//! whose `Host` is an address it was given (a page on another site cannot reach it through DNS
//! rebinding), and only GET and HEAD.
//!
//! It bounds what a client can hold, so that slow, idle or half-open connections cannot starve it
//! (nor exhaust its file descriptors: at `ulimit -n 128` it keeps serving):
//! - **header timeout** ([`Limits::header_timeout`], 10 s in `review`): a request's head must arrive in
//!   full within it of the connection opening or of the previous response (also the idle keep-alive
//!   timeout). Then the connection is closed.
//! - **stall timeout** ([`Limits::stall_timeout`], 30 s): a connection on which no byte moved either
//!   way for that long is closed, whatever it is doing (a client that stopped reading its response).
//! - **at most [`MAX_CONNECTIONS`] connections** at a time. The next one is not refused: the open
//!   connection that has gone longest without a request under way is closed to make room. Only when
//!   all are answering requests does the new one wait (in the kernel's accept queue). An event stream
//!   (the operator display's `GET /events`) is resumable — the page reconnects by itself — and counts
//!   as no request under way once its headers are out: open pages cannot keep the next one out.
//!
//! When `stop` resolves, [`serve`] stops accepting, closes the connections with no request under way
//! (a half-sent request is not waited for), and gives responses under way up to
//! [`Limits::shutdown_grace`] to finish.

use std::collections::HashMap;
use std::convert::Infallible;
use std::future::Future;
use std::net::SocketAddr;
use std::pin::{pin, Pin};
use std::sync::atomic::{AtomicBool, AtomicU64, AtomicUsize, Ordering};
use std::sync::{Arc, Mutex, PoisonError};
use std::task::{Context, Poll};
use std::time::Duration;

use axum::extract::{ConnectInfo, Request, State};
use axum::http::{header, HeaderValue, Method, StatusCode};
use axum::middleware::Next;
use axum::response::{IntoResponse, Response};
use axum::routing::get;
use axum::Router;
use ergocell_review::page;
use hyper::body::{Frame, Incoming, SizeHint};
use hyper::service::Service as _;
use hyper_util::rt::{TokioIo, TokioTimer};
use hyper_util::service::TowerToHyperService;
use tokio::io::{AsyncRead, AsyncWrite, ReadBuf};
use tokio::net::TcpListener;
use tokio::sync::{watch, Notify, Semaphore};
use tokio::task::JoinSet;
use tokio::time::Instant;

/// What the server holds: everything it can ever answer with.
#[derive(Debug)]
pub struct Served {
    /// Shared, not copied, per request.
    page: axum::body::Bytes,
    json: axum::body::Bytes,
    rules: Arc<HostRules>,
}

/// Who may ask: the `Host` values accepted, from loopback peers only; `None` when asked to serve
/// the network. Shared by the review and the operator display ([`crate::display`]).
#[derive(Debug, Clone)]
pub struct HostRules {
    pub allowed_hosts: Option<Vec<String>>,
    /// The server's name in a refusal ("review server", "operator display").
    pub server: &'static str,
}

/// `router` behind the Host and method rules (GET and HEAD only) and the security headers.
pub fn with_host_rules(router: Router, rules: Arc<HostRules>) -> Router {
    router.layer(axum::middleware::from_fn_with_state(rules, guard))
}

impl Served {
    /// The page and its analysis JSON; `allowed_hosts` the `Host` values accepted (`None`: any host,
    /// from any peer, for a server bound to the network on request).
    pub fn new(
        page: impl Into<axum::body::Bytes>,
        json: impl Into<axum::body::Bytes>,
        allowed_hosts: Option<Vec<String>>,
    ) -> Self {
        Self {
            page: page.into(),
            json: json.into(),
            rules: Arc::new(HostRules {
                allowed_hosts,
                server: "review server",
            }),
        }
    }
}

/// The routes: the page, its script and stylesheet, the analysis JSON, behind the Host and method guard.
pub fn router(served: Arc<Served>) -> Router {
    let rules = served.rules.clone();
    let app = Router::new()
        .route("/", get(index))
        .route("/assets/review.js", get(script))
        .route("/assets/review.css", get(stylesheet))
        .route("/api/review.json", get(review_json))
        .route("/favicon.ico", get(|| async { StatusCode::NO_CONTENT }))
        .fallback(not_found)
        .with_state(served);
    with_host_rules(app, rules)
}

/// Connections open at a time (see the module docs).
pub const MAX_CONNECTIONS: usize = 64;
/// How long responses under way may take to finish once a stop signal arrived.
pub const SHUTDOWN_GRACE: Duration = Duration::from_secs(1);
/// Pause before accepting again after `accept` failed for want of descriptors or memory.
const ACCEPT_BACKOFF: Duration = Duration::from_millis(100);

/// What a client can hold of the server (see the module docs).
#[derive(Debug, Clone, Copy)]
pub struct Limits {
    /// A request's head must arrive within this of the connection opening or the previous response.
    pub header_timeout: Duration,
    /// A connection on which no byte moved for this long is closed.
    pub stall_timeout: Duration,
    /// Connections open at a time ([`MAX_CONNECTIONS`] in `review`).
    pub max_connections: usize,
    /// How long responses under way may take to finish once stopped ([`SHUTDOWN_GRACE`]).
    pub shutdown_grace: Duration,
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
    /// `None` for an event stream (never "under way": see [`serve_connection`]).
    _busy: Option<Busy>,
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
struct Watched<S> {
    stream: S,
    conn: Arc<Conn>,
}

impl<S: AsyncRead + Unpin> AsyncRead for Watched<S> {
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

impl<S: AsyncWrite + Unpin> AsyncWrite for Watched<S> {
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
/// docs) and returns what `stop` resolved to.
pub async fn serve<T>(
    listener: TcpListener,
    app: Router,
    limits: Limits,
    stop: impl Future<Output = T>,
) -> T {
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
    drop(listener);
    stopping.send_replace(true);
    let _ = tokio::time::timeout(limits.shutdown_grace, async {
        while tasks.join_next().await.is_some() {}
    })
    .await;
    tasks.abort_all();
    signal
}

/// Serves one connection over any byte stream (`stream`, from `peer`) until it closes or times out,
/// as [`serve`] serves each accepted socket. The fuzz target of the request handling feeds it an
/// in-memory pipe.
pub async fn serve_io<S>(stream: S, peer: SocketAddr, app: Router, limits: Limits)
where
    S: AsyncRead + AsyncWrite + Unpin + Send + 'static,
{
    let conn = Arc::new(Conn::new(Instant::now()));
    let (_stopping, stop_rx) = watch::channel(false);
    serve_connection(stream, peer, conn, app, limits, stop_rx).await;
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
async fn serve_connection<S>(
    stream: S,
    peer: SocketAddr,
    conn: Arc<Conn>,
    app: Router,
    limits: Limits,
    mut stop: watch::Receiver<bool>,
) where
    S: AsyncRead + AsyncWrite + Unpin + Send + 'static,
{
    let routed = TowerToHyperService::new(app);
    let counted = conn.clone();
    let service = hyper::service::service_fn(move |mut request: axum::http::Request<Incoming>| {
        // What `into_make_service_with_connect_info` would add: the peer, for `guard`.
        request.extensions_mut().insert(ConnectInfo(peer));
        let busy = Busy::new(counted.clone());
        let response = routed.call(request);
        async move {
            let response = response.await?;
            // An event stream (server-sent events: the operator display's pages) is under way for as
            // long as the page is open, and resumable: EventSource reconnects by itself. It counts as
            // no request under way once its headers are out, so that many open (or idle) pages cannot
            // keep a new one out: the longest-open one is closed to make room.
            let streaming = response
                .headers()
                .get(header::CONTENT_TYPE)
                .is_some_and(|v| v.as_bytes().starts_with(b"text/event-stream"));
            let busy = (!streaming).then_some(busy);
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
    State(rules): State<Arc<HostRules>>,
    ConnectInfo(peer): ConnectInfo<SocketAddr>,
    request: Request,
    next: Next,
) -> Response {
    if request.headers().get_all(header::HOST).iter().count() > 1 {
        // RFC 9112 §3.2: more than one Host is a bad request.
        return (StatusCode::BAD_REQUEST, "more than one Host header").into_response();
    }
    if let Some(allowed) = &rules.allowed_hosts {
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
                    "forbidden: this {} answers only on {}",
                    rules.server,
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
