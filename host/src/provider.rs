//! The locked trajectories on this machine: [`ergocell_approvals::FileTrajectories`] over the file
//! system ([`OsFiles`]), with the reference cell's files shipped in the binary as a fallback, the
//! trust anchor where the site installed it, the witness in the cell's state folder, and the wall
//! clock.

use std::path::{Path, PathBuf};
use std::sync::Arc;

use ergocell_approvals::files::{AnchorFile, CellFiles, FileError, FileKind, Ownership};
pub use ergocell_approvals::provider::{
    check_approval_times, DemoLock, FileTrajectories, DEMO_PRINCIPAL, HANDOVER_RULA_FILE,
};
use ergocell_robot::{TrajectoryClass, TrajectoryLayout};

use ergocell_cell::session::ProviderError;

/// The cell's files on this machine's file system; the cell folder or the trajectories folder may
/// be served from the files shipped in the binary ([`crate::shipped`]).
#[derive(Debug, Clone, Copy, Default)]
pub struct OsFiles {
    /// The cell file, its URDF and the approvers' files are the shipped ones.
    cell_shipped: bool,
    /// The trajectory files, their locks and the RULA curves are the shipped ones.
    trajectories_shipped: bool,
}

impl OsFiles {
    /// Every file from the disk.
    pub fn disk() -> Self {
        Self::default()
    }

    fn shipped(self, kind: FileKind) -> bool {
        match kind {
            FileKind::Cell => self.cell_shipped,
            FileKind::Trajectories => self.trajectories_shipped,
            FileKind::Approvals => false,
        }
    }
}

impl CellFiles for OsFiles {
    fn read(&self, kind: FileKind, path: &Path) -> Result<String, FileError> {
        if self.shipped(kind) {
            return crate::shipped::file(path)
                .map(str::to_owned)
                .ok_or_else(|| FileError::Missing {
                    path: path.to_owned(),
                });
        }
        crate::input::read_text(path, crate::input::Kind::Config).map_err(|e| {
            if e.is_not_found() {
                FileError::Missing {
                    path: path.to_owned(),
                }
            } else {
                FileError::Unreadable {
                    path: path.to_owned(),
                    cause: Arc::new(e),
                }
            }
        })
    }

    fn label(&self, kind: FileKind, path: &Path) -> String {
        if self.shipped(kind) {
            crate::shipped::label(&path.to_string_lossy())
        } else {
            path.display().to_string()
        }
    }

    fn read_anchor(
        &self,
        path: &Path,
        max_bytes: u64,
        allowed: &dyn Fn(&[Ownership]) -> bool,
    ) -> Result<AnchorFile, FileError> {
        crate::trust_anchor::read_anchor_file(path, max_bytes, allowed)
    }

    fn read_witness(&self, path: &Path) -> Result<Vec<u8>, FileError> {
        match crate::input::read(path, crate::input::Kind::Config) {
            Ok(bytes) => Ok(bytes),
            Err(e) if e.is_not_found() => Ok(Vec::new()),
            Err(e) => Err(FileError::Unreadable {
                path: path.to_owned(),
                cause: Arc::new(e),
            }),
        }
    }

    fn append_witness(&self, path: &Path, line: &str) -> Result<(), FileError> {
        crate::witness::append(path, line).map_err(|e| FileError::Unreadable {
            path: path.to_owned(),
            cause: Arc::new(e),
        })
    }

    fn absolute(&self, path: &Path) -> PathBuf {
        std::path::absolute(path).unwrap_or_else(|_| path.to_owned())
    }

    fn resolved(&self, path: &Path) -> Option<PathBuf> {
        let (dir, name) = (path.parent()?, path.file_name()?);
        let dir = if dir.as_os_str().is_empty() {
            Path::new(".")
        } else {
            dir
        };
        std::fs::canonicalize(dir).ok().map(|d| d.join(name))
    }
}

/// The provider for the cell file `cell_path` and the trajectories in `trajectories_dir`, approvals
/// in `approvals_dir` (normally `<trajectories_dir>/approvals`). A relative cell path or
/// trajectories folder that is not in the working directory but names a shipped one is read from
/// the binary ([`crate::shipped::falls_back`]).
pub fn on_disk(
    cell_path: &Path,
    trajectories_dir: &Path,
    approvals_dir: &Path,
) -> FileTrajectories {
    let files = OsFiles {
        cell_shipped: crate::shipped::falls_back(cell_path),
        trajectories_shipped: crate::shipped::dir_falls_back(trajectories_dir),
    };
    provider(files, cell_path, trajectories_dir, approvals_dir)
}

/// `cell_path` / `trajectories_dir` of `None` are the files shipped in the binary; approvals are
/// always read from `approvals_dir` on disk.
pub fn with_shipped_defaults(
    cell_path: Option<&Path>,
    trajectories_dir: Option<&Path>,
    approvals_dir: &Path,
) -> FileTrajectories {
    let files = OsFiles {
        cell_shipped: cell_path.is_none(),
        trajectories_shipped: trajectories_dir.is_none(),
    };
    provider(
        files,
        cell_path.unwrap_or_else(|| Path::new(crate::shipped::CELL)),
        // Shipped: the relative `trajectories/…` paths are the keys of `crate::shipped::FILES`.
        trajectories_dir.unwrap_or_else(|| Path::new(crate::shipped::TRAJECTORIES)),
        approvals_dir,
    )
}

fn provider(
    files: OsFiles,
    cell_path: &Path,
    trajectories_dir: &Path,
    approvals_dir: &Path,
) -> FileTrajectories {
    FileTrajectories::new(
        Arc::new(files),
        cell_path,
        TrajectoryLayout::new(trajectories_dir).with_approvals_dir(approvals_dir),
        &crate::trust_anchor::anchor_dir(),
        &crate::witness::witness_path(approvals_dir),
        crate::trust_anchor::now_unix,
    )
}

/// Writes a **demo** approval of the class's current lock into the provider's approvals folder
/// ([`FileTrajectories::demo_approval`]), a new folder made as needed. Returns the lock's hash.
pub fn approve_for_demo(
    provider: &FileTrajectories,
    class: TrajectoryClass,
    stamp_utc: &str,
) -> Result<String, ProviderError> {
    let approval = provider.demo_approval(class, stamp_utc)?;
    let write = |path: &Path, e: std::io::Error| ProviderError::Write {
        path: path.to_owned(),
        cause: Arc::new(e),
    };
    let dir = provider.layout().approvals_dir();
    std::fs::create_dir_all(dir).map_err(|e| write(dir, e))?;
    std::fs::write(&approval.path, &approval.text).map_err(|e| write(&approval.path, e))?;
    Ok(approval.lock_sha256)
}
