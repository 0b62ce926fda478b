//! The operator display: a page on the cell's screen that says, large and plain, whether the posture
//! is safe — the current warning per body region with its advice, the action level as colour, the
//! session's state (and why the robot is held), and the skeleton — pushed as it happens.
//!
//! The session loop calls [`Display::update`] after every step with the step's events; the display
//! keeps the current picture (a [`Snapshot`]) and sends it to every open page as a server-sent event
//! (`GET /events`, one JSON snapshot per update). A page that connects — first time, after a reload,
//! or after the server restarted (the browser's `EventSource` reconnects by itself) — gets the current
//! snapshot at once, so nothing depends on having seen earlier events. No polling, no files.
//!
//! Served by [`crate::review_server::serve`] (its connection limits) behind the same Host and method
//! rules as the review ([`crate::review_server::with_host_rules`]). Each snapshot carries its send time
//! (`sent_unix_ms`), so a page can measure event-to-screen latency.

use std::collections::BTreeMap;
use std::convert::Infallible;
use std::sync::{Arc, Mutex, PoisonError};
use std::time::Duration;

use axum::http::{header, StatusCode};
use axum::response::sse::{Event, KeepAlive, Sse};
use axum::response::IntoResponse;
use axum::routing::get;
use axum::Router;
use ergocell_cell::session::{SessionEvent, SessionMachine, SessionState};
use ergocell_ergonomics::warnings::WarningKind;
use ergocell_ergonomics::WarningEvent;
use serde::Serialize;
use tokio::sync::broadcast;

use crate::review_server::{with_host_rules, HostRules};

/// One region's active warning, as the page shows it.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ShownWarning {
    /// The stamp of the frame that raised it (or last changed it), milliseconds on the session
    /// clock: on `run`, the cameras' capture stamps (Unix time), so a page on the same machine can
    /// measure capture-to-screen latency.
    pub stamp_ms: f64,
    pub region: String,
    pub side: Option<String>,
    pub region_score: u8,
    pub action_level: u8,
    pub angle_deg: Option<f64>,
    /// The warning's plain words with its advice.
    pub message: String,
    /// The probability that the warning's band is right (`None`: not known).
    pub band_probability: Option<f64>,
    /// The band is less than 90 % sure: the page says "near the limit".
    pub near_limit: bool,
}

/// Everything the page shows, as of one update.
#[derive(Debug, Clone, PartialEq, Serialize, Default)]
pub struct Snapshot {
    /// Updates sent so far (the page shows a gap as a reconnect).
    pub seq: u64,
    /// Wall-clock send time, Unix milliseconds.
    pub sent_unix_ms: f64,
    /// The session state's snake-case name.
    pub state: String,
    /// Why the robot is held, when it is, in the operator's terms with what to do
    /// (`HoldReason::for_operator`).
    pub held_reason: Option<String>,
    /// The same hold in the integrator's words (the hold command's reason).
    pub held_detail: Option<String>,
    /// The decided height class (`c1`…), once decided.
    pub class: Option<String>,
    /// The probability that `class` is the operator's true class, once decided.
    pub class_probability: Option<f64>,
    /// Whether the stature interval straddled a class boundary (the operator was served by the
    /// class with the lower expected RULA, or the more probable one), once decided.
    pub across_boundary: Option<bool>,
    /// The worse side's RULA action level of the latest assessed frame.
    pub action_level: Option<u8>,
    pub grand_score: Option<u8>,
    /// Active warnings, one per region and side.
    pub warnings: Vec<ShownWarning>,
    /// The latest fused skeleton (world frame, metres), `null` per unseen landmark.
    pub skeleton: Vec<Option<[f64; 3]>>,
    /// The latest warning raised (for the page to flash), with its update's `seq`.
    pub latest_raised: Option<(u64, String)>,
}

/// The active warnings by (region, side).
type ActiveWarnings = BTreeMap<(String, Option<String>), ShownWarning>;

/// The display's state and its subscribers.
#[derive(Debug)]
pub struct Display {
    snapshot: Mutex<(Snapshot, ActiveWarnings)>,
    tx: broadcast::Sender<Arc<str>>,
}

impl Display {
    pub fn new() -> Arc<Self> {
        let (tx, _) = broadcast::channel(64);
        Arc::new(Self {
            snapshot: Mutex::new((
                Snapshot {
                    state: SessionState::WaitingForOperator.name().to_owned(),
                    ..Snapshot::default()
                },
                BTreeMap::new(),
            )),
            tx,
        })
    }

    /// Folds one session step's events into the picture and pushes it to every page (when anything
    /// the page shows changed).
    pub fn update(&self, machine: &SessionMachine, events: &[SessionEvent]) {
        if events.is_empty() {
            return;
        }
        self.push(machine, events);
    }

    /// A new session's machine took over (`run` serves one operator after another): the page shows
    /// its state at once, not the last session's end until the next operator is tracked.
    pub fn next_session(&self, machine: &SessionMachine) {
        self.push(machine, &[]);
    }

    fn push(&self, machine: &SessionMachine, events: &[SessionEvent]) {
        let mut guard = self.snapshot.lock().unwrap_or_else(PoisonError::into_inner);
        let (snap, active) = &mut *guard;
        fold_events(snap, active, events);
        machine.state().name().clone_into(&mut snap.state);
        let held = (machine.state() == SessionState::Held)
            .then(|| machine.held_for())
            .flatten();
        snap.held_reason = held.map(|h| h.for_operator().to_owned());
        snap.held_detail = held.map(ToString::to_string);
        snap.class = machine.summary().class.map(|c| c.to_string());
        snap.class_probability = machine.decision().map(|d| d.probability);
        snap.across_boundary = machine
            .decision()
            .map(|d| d.basis != ergocell_ergonomics::height::DecisionBasis::Interval);
        snap.warnings = active.values().cloned().collect();
        snap.seq += 1;
        snap.sent_unix_ms = unix_ms();
        if let Ok(json) = serde_json::to_string(&*snap) {
            // no page open: nobody to send to, which is fine
            let _ = self.tx.send(json.into());
        }
    }

    /// The current picture as JSON (what a page gets first).
    pub fn snapshot_json(&self) -> String {
        let guard = self.snapshot.lock().unwrap_or_else(PoisonError::into_inner);
        let mut snap = guard.0.clone();
        snap.sent_unix_ms = unix_ms();
        serde_json::to_string(&snap).unwrap_or_else(|_| "{}".to_owned())
    }
}

/// Folds a step's events into the picture. A session's end clears what was the operator's: their
/// active warnings and posture (a machine's warnings are not cleared when it ends, and the next
/// session's operator must not see them).
fn fold_events(snap: &mut Snapshot, active: &mut ActiveWarnings, events: &[SessionEvent]) {
    for e in events {
        match e {
            SessionEvent::Warning(w) => {
                let key = (
                    w.region.name().to_owned(),
                    w.side.map(|s| s.name().to_owned()),
                );
                match w.kind {
                    WarningKind::Cleared => {
                        active.remove(&key);
                    }
                    WarningKind::Raised | WarningKind::Changed => {
                        if w.kind == WarningKind::Raised {
                            snap.latest_raised = Some((snap.seq + 1, w.message.clone()));
                        }
                        active.insert(key, shown(w));
                    }
                }
            }
            SessionEvent::Frame {
                skeleton,
                assessment,
                ..
            } => {
                snap.skeleton = skeleton
                    .slots()
                    .iter()
                    .map(|s| s.map(|e| [e.position_m.x, e.position_m.y, e.position_m.z]))
                    .collect();
                if let Some(h) = assessment.as_ref().and_then(|a| a.headline()) {
                    snap.action_level = Some(h.scores.action_level);
                    snap.grand_score = Some(h.scores.final_score);
                }
            }
            SessionEvent::StateChanged {
                to: SessionState::SessionEnded,
                ..
            } => {
                active.clear();
                snap.action_level = None;
                snap.grand_score = None;
                snap.skeleton.clear();
            }
            _ => {}
        }
    }
}

fn shown(w: &WarningEvent) -> ShownWarning {
    ShownWarning {
        stamp_ms: w.stamp_nanos as f64 / 1e6,
        region: w.region.name().to_owned(),
        side: w.side.map(|s| s.name().to_owned()),
        region_score: w.region_score,
        action_level: w.action_level,
        angle_deg: w.angle_deg,
        message: w.message.clone(),
        band_probability: w.band_probability,
        near_limit: w.near_limit,
    }
}

// the display's wall clock, for the latency figure only
#[allow(clippy::disallowed_methods)]
fn unix_ms() -> f64 {
    std::time::SystemTime::now()
        .duration_since(std::time::UNIX_EPOCH)
        .map_or(0.0, |d| d.as_secs_f64() * 1e3)
}

const PAGE: &str = include_str!("display/index.html");
const SCRIPT: &str = include_str!("display/display.js");

/// The routes: the page, its script, the event stream, behind the Host and method rules.
pub fn router(display: Arc<Display>, rules: Arc<HostRules>) -> Router {
    let app = Router::new()
        .route(
            "/",
            get(|| async { ([(header::CONTENT_TYPE, "text/html; charset=utf-8")], PAGE) }),
        )
        .route(
            "/display.js",
            get(|| async {
                (
                    [(header::CONTENT_TYPE, "text/javascript; charset=utf-8")],
                    SCRIPT,
                )
            }),
        )
        .route("/events", get(move || std::future::ready(events(&display))))
        .route("/favicon.ico", get(|| async { StatusCode::NO_CONTENT }))
        .fallback(|| async { (StatusCode::NOT_FOUND, "not found").into_response() });
    with_host_rules(app, rules)
}

fn events(display: &Display) -> axum::response::Response {
    let first = display.snapshot_json();
    let rx = display.tx.subscribe();
    let stream = futures::stream::unfold((Some(first), rx), |(first, mut rx)| async move {
        if let Some(json) = first {
            return Some((Ok::<_, Infallible>(Event::default().data(json)), (None, rx)));
        }
        loop {
            match rx.recv().await {
                Ok(json) => return Some((Ok(Event::default().data(&*json)), (None, rx))),
                // a page too slow for the updates skips to the newest: each one is the whole picture
                Err(broadcast::error::RecvError::Lagged(_)) => {}
                Err(broadcast::error::RecvError::Closed) => return None,
            }
        }
    });
    let mut response = Sse::new(stream)
        .keep_alive(KeepAlive::new().interval(Duration::from_secs(5)))
        .into_response();
    response.headers_mut().insert(
        header::CACHE_CONTROL,
        header::HeaderValue::from_static("no-store"),
    );
    response
}

/// Binds the display's address (port 0: a free one); the caller prints the URL.
pub fn bind(
    addr: std::net::SocketAddr,
) -> std::io::Result<(std::net::TcpListener, std::net::SocketAddr)> {
    let listener = std::net::TcpListener::bind(addr)?;
    listener.set_nonblocking(true)?;
    let bound = listener.local_addr()?;
    Ok((listener, bound))
}

/// Serves the display on `listener` (from [`bind`]) until `stop` resolves, with the review server's
/// connection limits; on a loopback address only its own `Host` values are answered.
pub async fn serve(
    listener: std::net::TcpListener,
    display: Arc<Display>,
    stop: impl std::future::Future<Output = ()>,
) -> std::io::Result<()> {
    let bound = listener.local_addr()?;
    let listener = tokio::net::TcpListener::from_std(listener)?;
    let rules = Arc::new(HostRules {
        allowed_hosts: bound
            .ip()
            .to_canonical()
            .is_loopback()
            .then(|| vec![bound.to_string(), format!("localhost:{}", bound.port())]),
        server: "operator display",
    });
    let limits = crate::review_server::Limits {
        header_timeout: Duration::from_secs(10),
        stall_timeout: Duration::from_secs(30),
        max_connections: crate::review_server::MAX_CONNECTIONS,
        shutdown_grace: crate::review_server::SHUTDOWN_GRACE,
    };
    crate::review_server::serve(listener, router(display, rules), limits, stop).await;
    Ok(())
}

/// The display served on a thread of its own, for a caller whose loop is synchronous (`ergocell
/// demo`): its own single-threaded runtime, stopped and joined when this is dropped.
pub struct DisplayThread {
    display: Arc<Display>,
    bound: std::net::SocketAddr,
    stop: Option<tokio::sync::oneshot::Sender<()>>,
    thread: Option<std::thread::JoinHandle<()>>,
}

/// Why the display's thread did not start.
#[derive(Debug, thiserror::Error)]
pub enum DisplayStartError {
    /// The address cannot be listened on (taken, not this machine's, not allowed).
    #[error("cannot listen on {addr}: {error}")]
    Bind {
        addr: std::net::SocketAddr,
        // Not `source`: the message says it, and `{:#}` would print it twice.
        error: std::io::Error,
    },
    /// The display's runtime could not be built.
    #[error("tokio runtime for the display")]
    Runtime(#[source] std::io::Error),
    /// The display's thread could not be spawned.
    #[error("display thread")]
    Thread(#[source] std::io::Error),
}

impl DisplayThread {
    /// Listens on `addr` and serves a new display there until dropped.
    pub fn start(addr: std::net::SocketAddr) -> Result<Self, DisplayStartError> {
        let display = Display::new();
        let (listener, bound) =
            bind(addr).map_err(|error| DisplayStartError::Bind { addr, error })?;
        let runtime = tokio::runtime::Builder::new_current_thread()
            .enable_all()
            .build()
            .map_err(DisplayStartError::Runtime)?;
        let (stop, stopped) = tokio::sync::oneshot::channel::<()>();
        let served = display.clone();
        let thread = std::thread::Builder::new()
            .name("display".to_owned())
            .spawn(move || {
                let result = runtime.block_on(serve(listener, served, async {
                    let _ = stopped.await;
                }));
                if let Err(e) = result {
                    tracing::error!("operator display: {e}");
                }
            })
            .map_err(DisplayStartError::Thread)?;
        Ok(Self {
            display,
            bound,
            stop: Some(stop),
            thread: Some(thread),
        })
    }

    /// The display to update.
    pub fn display(&self) -> &Display {
        &self.display
    }

    /// The address it listens on (the port chosen when `addr`'s was 0).
    pub fn bound(&self) -> std::net::SocketAddr {
        self.bound
    }
}

impl Drop for DisplayThread {
    fn drop(&mut self) {
        if let Some(stop) = self.stop.take() {
            let _ = stop.send(());
        }
        if let Some(t) = self.thread.take() {
            let _ = t.join();
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use ergocell_ergonomics::assess::BodyRegion;
    use ergocell_ergonomics::Side;

    fn warning(kind: WarningKind) -> SessionEvent {
        SessionEvent::Warning(WarningEvent {
            stamp_nanos: 0,
            kind,
            region: BodyRegion::Trunk,
            side: None::<Side>,
            region_score: 4,
            angle_deg: Some(70.0),
            action_level: 3,
            uncertain: false,
            band_probability: Some(0.99),
            near_limit: false,
            message: "Trunk bent forward 70°".to_owned(),
        })
    }

    fn ended(to: SessionState) -> SessionEvent {
        SessionEvent::StateChanged {
            stamp_nanos: 1,
            from: SessionState::Working,
            to,
            reason: "operator left".to_owned(),
        }
    }

    #[test]
    fn a_session_end_clears_its_operators_warnings_and_posture() {
        let mut snap = Snapshot {
            action_level: Some(3),
            grand_score: Some(6),
            skeleton: vec![Some([0.0, 0.0, 1.0])],
            ..Snapshot::default()
        };
        let mut active = ActiveWarnings::new();
        fold_events(&mut snap, &mut active, &[warning(WarningKind::Raised)]);
        assert_eq!(active.len(), 1);
        // held, not ended: the warning stays on screen
        fold_events(&mut snap, &mut active, &[ended(SessionState::Held)]);
        assert_eq!(active.len(), 1);
        assert_eq!(snap.action_level, Some(3));
        fold_events(&mut snap, &mut active, &[ended(SessionState::SessionEnded)]);
        assert!(
            active.is_empty(),
            "the last operator's warning outlived the session"
        );
        assert_eq!((snap.action_level, snap.grand_score), (None, None));
        assert!(snap.skeleton.is_empty());
    }
}
