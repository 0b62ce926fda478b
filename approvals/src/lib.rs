//! Approvals: whether a locked trajectory may move the robot, decided from the cell's files.
//!
//! * [`files`]: the port the files are read through ([`CellFiles`]): the binary's implementation is
//!   the file system, [`MemoryFiles`] is the tests'. This crate does no I/O of its own.
//! * [`anchor`]: the site's trust anchor, its ownership rule, and the trust list it makes of the
//!   approvers' files.
//! * [`witness_store`]: the witness of the approvals files, checked and extended on every read, so
//!   a file cut back (a deleted withdrawal, a rollback from a backup) is refused.
//! * [`provider`]: [`FileTrajectories`], which re-reads and re-verifies a class's lock, its
//!   approvals and their times on every call, on an injected clock.
//! * [`review`]: `trajectories verify`'s verdict on a class (the same rules, with the lock re-planned
//!   and the problems listed) and `sign-approvers`' check of the authority's signature, with
//!   their texts.
//!
//! The lock file, the SSH signatures and the approvals chain themselves are
//! [`ergocell_robot::lock`], [`ergocell_robot::signing`] and [`ergocell_robot::authority`].

pub mod anchor;
mod error;
pub mod files;
#[cfg(feature = "fixtures")]
pub mod fixture;
pub mod provider;
pub mod review;
pub mod witness_store;

pub use error::{ProviderError, Refusal};
pub use files::{CellFiles, FileError, FileKind, MemoryFiles};
pub use provider::FileTrajectories;
