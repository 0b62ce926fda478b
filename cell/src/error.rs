//! The cell crate's one error type.

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

/// A backend (landmark source, robot sink) failed.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("{backend}: {reason}")]
pub struct BackendError {
    pub backend: &'static str,
    pub reason: String,
}

/// The trajectory provider could not give a verified trajectory (files unreadable, the lock or its
/// approval does not verify). The text is the provider's, naming the file and the check that failed.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("{0}")]
pub struct ProviderError(pub String);
