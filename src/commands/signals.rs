//! Stop signals: Ctrl-C (SIGINT) and SIGTERM (systemd, `docker stop`, `timeout`, `kill`) stop a
//! command the same way. `run` and `demo` hold the robot, close the recording (summary and footer)
//! and exit with 130 (SIGINT) or 143 (SIGTERM), 128 + the signal's number as a shell reports it;
//! `review` stops its server and exits 0.
//!
//! The handlers are installed when [`stop_signal`] is called, not when its future is first polled,
//! so a signal that arrives while a command is still setting up is not lost (nor fatal).

use std::future::Future;
use std::sync::atomic::{AtomicU8, Ordering};
use std::sync::Arc;

use tokio::signal::unix::{signal, SignalKind};

/// A stop signal.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Signal {
    /// SIGINT: Ctrl-C in the terminal.
    Interrupt,
    /// SIGTERM: a service manager, a container runtime or `timeout` asking the process to stop.
    Terminate,
}

impl Signal {
    /// The name shown in the output and recorded as the session's end reason.
    pub fn name(self) -> &'static str {
        self.stop().name()
    }

    /// The stop the session ends for.
    pub fn stop(self) -> ergocell_cell::session::StopSignal {
        match self {
            Self::Interrupt => ergocell_cell::session::StopSignal::Interrupt,
            Self::Terminate => ergocell_cell::session::StopSignal::Terminate,
        }
    }

    /// The exit code after the robot was held and the recording closed: 128 + the signal's number
    /// (the cell's rule, `ExitStatus::Stopped`).
    pub fn exit_code(self) -> u8 {
        ergocell_cell::session::ExitStatus::Stopped(self.stop()).code()
    }

    fn to_u8(self) -> u8 {
        match self {
            Self::Interrupt => 1,
            Self::Terminate => 2,
        }
    }

    fn from_u8(v: u8) -> Option<Self> {
        match v {
            1 => Some(Self::Interrupt),
            2 => Some(Self::Terminate),
            _ => None,
        }
    }
}

impl From<ergocell_cell::session::StopSignal> for Signal {
    fn from(s: ergocell_cell::session::StopSignal) -> Self {
        match s {
            ergocell_cell::session::StopSignal::Interrupt => Self::Interrupt,
            ergocell_cell::session::StopSignal::Terminate => Self::Terminate,
        }
    }
}

/// A command that was stopped by a signal after it held the robot and closed its recording; the exit
/// code is the signal's ([`Signal::exit_code`]).
#[derive(Debug, thiserror::Error)]
#[error("stopped by {}: {what}", signal.name())]
pub struct Stopped {
    pub signal: Signal,
    /// What was done on the way out, e.g. "robot held, recording closed".
    pub what: String,
}

/// Set once the first stop signal arrived (shared with the thread or task that waits for it).
#[derive(Debug, Clone, Default)]
pub struct StopFlag(Arc<AtomicU8>);

/// The session driver asks the flag.
impl ergocell_cell::session::StopRequest for StopFlag {
    fn requested(&self) -> Option<ergocell_cell::session::StopSignal> {
        self.get().map(Signal::stop)
    }
}

impl StopFlag {
    /// The signal that arrived, if any.
    pub fn get(&self) -> Option<Signal> {
        Signal::from_u8(self.0.load(Ordering::SeqCst))
    }

    /// Records `signal` (the first one wins).
    pub fn set(&self, signal: Signal) {
        let _ = self
            .0
            .compare_exchange(0, signal.to_u8(), Ordering::SeqCst, Ordering::SeqCst);
    }

    /// For synchronous commands (`demo`): installs the handlers now and waits for a signal on a
    /// thread of its own.
    pub fn install() -> anyhow::Result<Self> {
        use anyhow::Context as _;
        let runtime = tokio::runtime::Builder::new_current_thread()
            .enable_all()
            .build()
            .context("tokio runtime for the signal handlers")?;
        let wait = {
            let _context = runtime.enter();
            stop_signal().context("installing the SIGINT/SIGTERM handlers")?
        };
        let flag = Self::default();
        let f = flag.clone();
        std::thread::spawn(move || f.set(runtime.block_on(wait)));
        Ok(flag)
    }

    /// For commands on a tokio runtime (`run`): installs the handlers now and sets the flag from a
    /// task. Call inside the runtime's context.
    pub fn spawn() -> anyhow::Result<(Self, tokio::task::JoinHandle<()>)> {
        use anyhow::Context as _;
        let wait = stop_signal().context("installing the SIGINT/SIGTERM handlers")?;
        let flag = Self::default();
        let f = flag.clone();
        let task = tokio::spawn(async move { f.set(wait.await) });
        Ok((flag, task))
    }
}

/// Installs the SIGINT and SIGTERM handlers (inside a tokio runtime's context) and returns a future
/// that resolves to the first of them to arrive.
pub fn stop_signal() -> std::io::Result<impl Future<Output = Signal>> {
    let mut interrupt = signal(SignalKind::interrupt())?;
    let mut terminate = signal(SignalKind::terminate())?;
    Ok(async move {
        tokio::select! {
            Some(()) = interrupt.recv() => Signal::Interrupt,
            Some(()) = terminate.recv() => Signal::Terminate,
            else => std::future::pending::<Signal>().await,
        }
    })
}
