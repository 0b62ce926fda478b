//! The cell crate's errors: the core's ([`CellError`]) and a backend's ([`BackendError`]). The
//! trajectory provider's ([`ProviderError`]) is the approvals crate's, re-exported.

/// Everything that can go wrong in the cell's core: a bad configuration, a pipeline that cannot be
/// built on the given rig, a backend or trajectory provider that failed.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum CellError {
    /// The cell configuration is malformed or holds an impossible value. `file` names the file (or
    /// what stands for it, e.g. "config/cell.toml (shipped in the binary)"); `reason` names the key
    /// and the value.
    #[error("{file}: {reason}")]
    Config { file: String, reason: String },
    /// The rig cannot carry a session (e.g. it has no `up` vector).
    #[error("rig: {0}")]
    Rig(String),
    /// The perception stage could not be built.
    #[error("perception: {0}")]
    Perception(#[from] ergocell_perception::PerceptionError),
    /// The ergonomics stage could not be built.
    #[error("ergonomics: {0}")]
    Ergonomics(#[from] ergocell_ergonomics::ErgonomicsError),
}

/// A backend (landmark source, robot sink) failed, with the facts of each way as fields.
#[derive(Debug, Clone, thiserror::Error)]
#[non_exhaustive]
pub enum BackendError {
    /// The transport did not take a message (`channel`: "ROS 2 joint trajectory", …); `detail` is
    /// the transport's own report, whose error type is not ours to keep.
    #[error("{channel}: {detail}")]
    Transport {
        channel: &'static str,
        detail: String,
    },
    /// The leg does not carry one positive path tolerance per joint: it is not sent.
    #[error(
        "execution monitor: the leg carries path tolerances {given:?}, not one positive tolerance \
         per joint ({joints})"
    )]
    PathTolerances { given: Vec<f64>, joints: usize },
    /// The leg's monitor limits are out of range, or the watch cannot take the leg: it is not sent.
    #[error("execution monitor: the leg cannot be watched: {cause}")]
    Monitor {
        #[source]
        cause: ergocell_robot::monitor::MonitorError,
    },
    /// The execution monitor's task failed (its state poisoned by a panic).
    #[error("execution monitor: the monitor task failed")]
    MonitorTaskFailed,
    /// The FollowJointTrajectory task is gone: nothing can be sent to the controller.
    #[error("ROS 2 FollowJointTrajectory: the controller task has stopped")]
    ControllerTaskStopped,
    /// The simulator behind a simulated backend failed.
    #[error("simulator: {cause}")]
    Simulator {
        #[source]
        cause: Cause,
    },
}

/// A cause from outside the cell's crates (a transport, the simulator), shared so that errors stay
/// `Clone`.
pub type Cause = std::sync::Arc<dyn std::error::Error + Send + Sync>;

pub use ergocell_approvals::ProviderError;

/// An error and its sources, joined as one line ("a: b: c"), a source already said by the one
/// above it not repeated.
pub fn chain(error: &(dyn std::error::Error + 'static)) -> String {
    let mut text = error.to_string();
    let mut source = error.source();
    while let Some(s) = source {
        let said = s.to_string();
        if !text.contains(&said) {
            text = format!("{text}: {said}");
        }
        source = s.source();
    }
    text
}

/// Serialises a [`Cause`] as its [`chain`] (the outcome file, the recording's end).
pub(crate) fn serialize_cause<S: serde::Serializer>(
    cause: &Cause,
    s: S,
) -> Result<S::Ok, S::Error> {
    s.serialize_str(&chain(cause.as_ref()))
}
