//! The port through which the provider reads the cell's files and keeps its witness: the binary
//! implements it on the file system (with the files shipped in the binary as a fallback), tests
//! in memory ([`MemoryFiles`]). The rules (what must be there, who must own the trust anchor, what
//! the witness may record) stay on this side of it, so they are tested with no disk at all.

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::sync::{Arc, Mutex};

/// Which folder of the cell a file belongs to: an implementation may serve a folder from
/// elsewhere (the binary serves the reference cell's from the files compiled into it).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum FileKind {
    /// The cell file, its URDF, the approvers' files and the authority's signature beside them.
    Cell,
    /// The trajectory files, their locks and the classes' RULA curves.
    Trajectories,
    /// The approvals files.
    Approvals,
}

/// A cause from the implementation (an I/O error, a size limit), shared so that errors stay
/// `Clone`.
pub type Cause = Arc<dyn std::error::Error + Send + Sync>;

/// Why a file could not be read.
#[derive(Debug, Clone, thiserror::Error)]
#[non_exhaustive]
pub enum FileError {
    /// There is no such file.
    #[error("{} does not exist", path.display())]
    Missing { path: PathBuf },
    /// The file is there and cannot be read (not a file, too large, not text, an I/O error). The
    /// cause names the path.
    #[error("{cause}")]
    Unreadable {
        path: PathBuf,
        #[source]
        cause: Cause,
    },
    /// Larger than a file of its kind can be.
    #[error("{} is larger than {limit} bytes", path.display())]
    TooLarge { path: PathBuf, limit: u64 },
}

impl FileError {
    /// The file's path.
    pub fn path(&self) -> &Path {
        match self {
            Self::Missing { path }
            | Self::Unreadable { path, .. }
            | Self::TooLarge { path, .. } => path,
        }
    }
}

/// The owner and mode of a file or folder, as the file system reports them.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Ownership {
    pub path: PathBuf,
    /// The owner's numeric user id (root is 0).
    pub uid: u32,
    /// The permission bits (`st_mode & 0o7777`).
    pub mode: u32,
    /// A regular file (for the file itself; folders above it are folders).
    pub regular_file: bool,
}

/// A trust-anchor file as read from **one** open file: the ownership of it and of every folder above
/// the path it was opened at, the file first and `/` last, and its bytes (at most `max_bytes` + 1),
/// read only when the chain passed the caller's rule. Checking one path and reading it again would
/// let a symbolic link flip between the check and the read; reading before the check would let a
/// file nobody vouches for (on a file system that can block) hang the cell.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct AnchorFile {
    pub bytes: Vec<u8>,
    pub chain: Vec<Ownership>,
}

/// The cell's files, read and (the witness only) appended to.
pub trait CellFiles: std::fmt::Debug + Send + Sync {
    /// The text of a file of the cell.
    fn read(&self, kind: FileKind, path: &Path) -> Result<String, FileError>;

    /// A trust-anchor file, with its ownership chain; its bytes only if `allowed(chain)`. A path
    /// that is not a regular file is not opened: its chain is its own entry alone.
    fn read_anchor(
        &self,
        path: &Path,
        max_bytes: u64,
        allowed: &dyn Fn(&[Ownership]) -> bool,
    ) -> Result<AnchorFile, FileError>;

    /// The witness's bytes; empty when there is no witness yet.
    fn read_witness(&self, path: &Path) -> Result<Vec<u8>, FileError>;

    /// Appends one line to the witness, durably.
    fn append_witness(&self, path: &Path, line: &str) -> Result<(), FileError>;

    /// How a file is named in messages (a file served from elsewhere says so).
    fn label(&self, _kind: FileKind, path: &Path) -> String {
        path.display().to_string()
    }

    /// `path` made absolute as the cell names it, links **not** resolved: the witness's key.
    fn absolute(&self, path: &Path) -> PathBuf;

    /// `path` with the links of its folder resolved, when that can be done (the witness checks
    /// this name too).
    fn resolved(&self, path: &Path) -> Option<PathBuf>;
}

/// The cell's files in memory: a test fixture and the reference of the port's behaviour.
#[derive(Debug, Clone, Default)]
pub struct MemoryFiles {
    files: Arc<Mutex<BTreeMap<PathBuf, Vec<u8>>>>,
    anchors: Arc<Mutex<BTreeMap<PathBuf, AnchorFile>>>,
    /// The witness can be neither read nor appended to ([`MemoryFiles::fail_witness`]).
    witness_fails: Arc<Mutex<bool>>,
}

/// A failure a test injected.
#[derive(Debug, thiserror::Error)]
#[error("cannot read {}: injected I/O error", .0.display())]
struct Injected(PathBuf);

/// A memory file that is not text.
#[derive(Debug, thiserror::Error)]
#[error("{} is not UTF-8 text", .0.display())]
struct NotText(PathBuf);

impl MemoryFiles {
    /// Empty.
    pub fn new() -> Self {
        Self::default()
    }

    /// Puts (or replaces) a file.
    pub fn put(&self, path: impl Into<PathBuf>, text: impl Into<Vec<u8>>) {
        self.lock_files().insert(path.into(), text.into());
    }

    /// Removes a file.
    pub fn remove(&self, path: &Path) {
        self.lock_files().remove(path);
    }

    /// A file's bytes, if it is there.
    pub fn get(&self, path: &Path) -> Option<Vec<u8>> {
        self.lock_files().get(path).cloned()
    }

    /// From now on the witness can be neither read nor appended to (`true`), or can again.
    pub fn fail_witness(&self, fails: bool) {
        *self
            .witness_fails
            .lock()
            .unwrap_or_else(std::sync::PoisonError::into_inner) = fails;
    }

    /// Puts a trust-anchor file with its ownership chain.
    pub fn put_anchor(&self, path: impl Into<PathBuf>, file: AnchorFile) {
        self.anchors
            .lock()
            .unwrap_or_else(std::sync::PoisonError::into_inner)
            .insert(path.into(), file);
    }

    /// The injected failure of the witness, if one is set ([`MemoryFiles::fail_witness`]).
    fn witness_usable(&self, path: &Path) -> Result<(), FileError> {
        if *self
            .witness_fails
            .lock()
            .unwrap_or_else(std::sync::PoisonError::into_inner)
        {
            return Err(FileError::Unreadable {
                path: path.to_owned(),
                cause: Arc::new(Injected(path.to_owned())),
            });
        }
        Ok(())
    }

    fn lock_files(&self) -> std::sync::MutexGuard<'_, BTreeMap<PathBuf, Vec<u8>>> {
        self.files
            .lock()
            .unwrap_or_else(std::sync::PoisonError::into_inner)
    }
}

impl CellFiles for MemoryFiles {
    fn read(&self, _: FileKind, path: &Path) -> Result<String, FileError> {
        let bytes = self.get(path).ok_or_else(|| FileError::Missing {
            path: path.to_owned(),
        })?;
        String::from_utf8(bytes).map_err(|_| FileError::Unreadable {
            path: path.to_owned(),
            cause: Arc::new(NotText(path.to_owned())),
        })
    }

    fn read_anchor(
        &self,
        path: &Path,
        max_bytes: u64,
        allowed: &dyn Fn(&[Ownership]) -> bool,
    ) -> Result<AnchorFile, FileError> {
        let mut file = self
            .anchors
            .lock()
            .unwrap_or_else(std::sync::PoisonError::into_inner)
            .get(path)
            .cloned()
            .ok_or_else(|| FileError::Missing {
                path: path.to_owned(),
            })?;
        if allowed(&file.chain) {
            file.bytes
                .truncate(usize::try_from(max_bytes.saturating_add(1)).unwrap_or(usize::MAX));
        } else {
            file.bytes.clear();
        }
        Ok(file)
    }

    fn read_witness(&self, path: &Path) -> Result<Vec<u8>, FileError> {
        self.witness_usable(path)?;
        Ok(self.get(path).unwrap_or_default())
    }

    fn append_witness(&self, path: &Path, line: &str) -> Result<(), FileError> {
        self.witness_usable(path)?;
        self.lock_files()
            .entry(path.to_owned())
            .or_default()
            .extend_from_slice(line.as_bytes());
        Ok(())
    }

    fn absolute(&self, path: &Path) -> PathBuf {
        Path::new("/").join(path)
    }

    fn resolved(&self, _: &Path) -> Option<PathBuf> {
        None
    }
}
