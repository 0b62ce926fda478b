//! The safety engineer's review files on this machine (`ergocell trajectories`): the cell, its
//! robot and the approvers' files read for review ([`ReviewCell`]); a class's approvals file read
//! with its chain checked; the approvals folder's lock that `approve` and `withdraw` hold while they
//! write ([`ApprovalsLock`]), under which the temporary files of writes that never finished are
//! removed; the signers' private keys; locks and approvals replaced atomically, messages and
//! signatures written only as new files; and the wall clock as an approval records it.
//!
//! What the files mean (a lock's integrity, an approval's signature, the verdict) is
//! `ergocell_robot`'s and `ergocell_approvals`'; here only where they are and how they are read
//! and written. Nothing here prints: what a command waits for or removed is handed back to it.

use std::fmt;
use std::fs;
use std::io::Write as _;
use std::path::{Path, PathBuf};

use ergocell_robot::lock::{ApprovalsFile, VerifyInputs};
use ergocell_robot::signing::{self, PrivateKey};
use ergocell_robot::{
    CellConfig, InputHashes, PlanInputs, RobotError, RobotModel, TrajectoryClass, TrajectoryLayout,
    TrajectorySpec, TrustFiles, TrustedSigners,
};

use crate::input::{self, InputError};
use crate::output::OutputError;

/// A review file that cannot be used: bad input either way.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum ReviewFileError {
    /// It cannot be read; `what` says which file, and where a relative one was looked for.
    #[error("{what}")]
    Unreadable {
        what: String,
        #[source]
        cause: InputError,
    },
    /// It reads, but is not what it must be (`file` names it, or them).
    #[error("{file}: {reason}")]
    Malformed { file: String, reason: String },
}

impl ReviewFileError {
    fn malformed(path: &Path, reason: String) -> Self {
        Self::Malformed {
            file: path.display().to_string(),
            reason,
        }
    }
}

/// Reads a file of the cell or the trajectories folder. The review commands work on the files on
/// disk only (they write locks and approvals beside them), so a missing relative path says where it
/// was looked for.
pub fn read_text(path: &Path) -> Result<String, ReviewFileError> {
    input::read_text(path, input::Kind::Config).map_err(|cause| {
        let what = if path.is_relative() {
            format!(
                "cannot read {} (relative to {}: run from the cell's folder, or pass --cell and \
                 --trajectories-dir)",
                path.display(),
                crate::shipped::working_dir()
            )
        } else {
            format!("cannot read {}", path.display())
        };
        ReviewFileError::Unreadable { what, cause }
    })
}

/// An OpenSSH private key file.
pub fn read_private_key(path: &Path) -> Result<PrivateKey, ReviewFileError> {
    signing::private_key_from_openssh(&read_text(path)?)
        .map_err(|e| ReviewFileError::malformed(path, e.to_string()))
}

/// The class's approvals file at `path`, its chain checked; a missing file is an empty chain.
pub fn read_approvals(path: &Path) -> Result<ApprovalsFile, ReviewFileError> {
    if !path.exists() {
        return Ok(ApprovalsFile::default());
    }
    ApprovalsFile::from_toml_str(&read_text(path)?)
        .and_then(|f| f.check_chain().map(|()| f))
        .map_err(|e| ReviewFileError::malformed(path, e.to_string()))
}

/// The cell as the review commands read it: the cell file, its robot and the approvers' files
/// beside it, and whether the site's approvers authority trusts them.
#[derive(Debug, Clone)]
pub struct ReviewCell {
    pub cell: CellConfig,
    pub urdf_text: String,
    pub model: RobotModel,
    /// The folder of the cell file (the approvers' files are in its `approvers/`).
    pub cell_dir: PathBuf,
    /// The approvers' files' texts: allowed signers, revoked keys.
    pub allowed_signers: String,
    pub revoked_keys: String,
    /// The approvers trusted under the site's authority; none when they are not (`trust_problem`).
    pub trusted: TrustedSigners,
    /// Why the approvers' files are not trusted, when they are not.
    pub trust_problem: Option<String>,
}

impl ReviewCell {
    /// Reads the cell file at `cell_path`, the URDF it names and the approvers' files, in that
    /// order (the first that fails is the one reported), and checks the approvers' files against
    /// the trust anchor installed on this machine ([`crate::trust_anchor`]).
    pub fn load(cell_path: &Path) -> Result<Self, ReviewFileError> {
        let cell = CellConfig::from_toml_str(&read_text(cell_path)?)
            .map_err(|e| ReviewFileError::malformed(cell_path, e.to_string()))?;
        let dir = cell_path.parent().unwrap_or_else(|| Path::new("."));
        let urdf_path = dir.join(&cell.robot.urdf);
        let urdf_text = read_text(&urdf_path)?;
        let robot = &cell.robot;
        let model = RobotModel::from_urdf_str(&urdf_text, &robot.base_link, &robot.flange_link)
            .map_err(|e| ReviewFileError::malformed(&urdf_path, e.to_string()))?;
        let allowed_path = dir.join(signing::ALLOWED_SIGNERS);
        let revoked_path = dir.join(signing::REVOKED_KEYS);
        let allowed = read_text(&allowed_path)?;
        let revoked = read_text(&revoked_path)?;
        TrustedSigners::parse(&allowed, &revoked).map_err(|e| ReviewFileError::Malformed {
            file: format!("{} / {}", allowed_path.display(), revoked_path.display()),
            reason: e.to_string(),
        })?;
        let anchor = crate::trust_anchor::anchor_dir();
        let anchored = crate::trust_anchor::trusted_signers(dir, &allowed, &revoked, &anchor);
        let (trusted, trust_problem) = match anchored {
            Ok(t) => (t, None),
            Err(why) => (TrustedSigners::default(), Some(why.to_string())),
        };
        Ok(Self {
            cell,
            urdf_text,
            model,
            cell_dir: dir.to_owned(),
            allowed_signers: allowed,
            revoked_keys: revoked,
            trusted,
            trust_problem,
        })
    }

    /// The class's trajectory file in `layout`, read and parsed (it must declare `class`), the
    /// hashes of the inputs a lock of it records (`version`: the binary's), and its text.
    pub fn read_spec(
        &self,
        layout: &TrajectoryLayout,
        class: TrajectoryClass,
        version: &str,
    ) -> Result<(TrajectorySpec, InputHashes, String), ReviewFileError> {
        let path = layout.spec(class);
        let text = read_text(&path)?;
        let spec = TrajectorySpec::from_toml_str(&text)
            .map_err(|e| ReviewFileError::malformed(&path, e.to_string()))?;
        if spec.class != class {
            let why = format!("file declares class {}, expected {class}", spec.class);
            return Err(ReviewFileError::malformed(&path, why));
        }
        let trust = TrustFiles {
            allowed_signers: self.allowed_signers.as_bytes(),
            revoked_keys: self.revoked_keys.as_bytes(),
        };
        let hashes = InputHashes::new(
            text.as_bytes(),
            self.urdf_text.as_bytes(),
            &self.cell,
            trust,
            version,
        );
        Ok((spec, hashes, text))
    }

    /// What planning `spec` needs: the robot, the cell and the inputs' hashes.
    pub fn plan_inputs<'a>(
        &'a self,
        spec: &'a TrajectorySpec,
        hashes: &'a InputHashes,
    ) -> PlanInputs<'a> {
        PlanInputs {
            model: &self.model,
            cell: &self.cell,
            spec,
            hashes,
        }
    }

    /// What verifying the class's lock `lock_toml` (and its approvals, if read) needs.
    pub fn verify_inputs<'a>(
        &'a self,
        class: TrajectoryClass,
        lock_toml: &'a str,
        current_inputs: &'a InputHashes,
        approvals_toml: Option<&'a str>,
    ) -> VerifyInputs<'a> {
        VerifyInputs {
            class,
            lock_toml,
            current_inputs,
            model: &self.model,
            approvals_toml,
            trusted: &self.trusted,
        }
    }
}

/// The approvals folder's lock file's name.
pub const APPROVALS_LOCK: &str = ".approvals.lock";

/// The approvals folder's lock, held by `approve` and `withdraw` from reading the approvals file to
/// recording in the witness, so two engineers approving at once both land, one after the other
/// (each reads what the other wrote). Released when dropped.
#[derive(Debug)]
pub struct ApprovalsLock {
    _file: fs::File,
}

/// The approvals folder's lock could not be taken: what was being done, and why.
#[derive(Debug, thiserror::Error)]
#[error("{what}")]
pub struct LockError {
    pub what: String,
    #[source]
    pub source: std::io::Error,
}

/// A temporary file of an approvals write that never finished (`.<name>.partial-<pid>`, left by a
/// command killed mid-write), found under the lock.
#[derive(Debug)]
pub enum Leftover {
    /// Removed.
    Removed(PathBuf),
    /// Still there: it could not be removed.
    Kept {
        path: PathBuf,
        error: std::io::Error,
    },
}

impl fmt::Display for Leftover {
    /// The note a command gives of it.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Leftover::Removed(path) => write!(
                f,
                "note: removed {}, left by an approve or withdraw that was stopped mid-write",
                path.display()
            ),
            Leftover::Kept { path, error } => write!(
                f,
                "note: {} is left by a write that was stopped; cannot remove it: {error}",
                path.display()
            ),
        }
    }
}

impl ApprovalsLock {
    /// Takes the lock of the approvals folder `dir` (made if it is not there). When another
    /// command holds it, `on_wait` is told the lock file's path and this waits for it. Holding the
    /// lock, no other command is writing, so a temporary file beside the approvals is one a killed
    /// command left behind: each is removed and returned.
    pub fn take(
        dir: &Path,
        on_wait: impl FnOnce(&Path),
    ) -> Result<(Self, Vec<Leftover>), LockError> {
        let fail = |what: String| move |source| LockError { what, source };
        fs::create_dir_all(dir).map_err(fail(format!("cannot create {}", dir.display())))?;
        let lock_path = dir.join(APPROVALS_LOCK);
        // Non-blocking and not through a symlink: a pipe or a device put there is refused below,
        // never waited on or written to.
        let file = {
            use std::os::unix::fs::OpenOptionsExt as _;
            fs::OpenOptions::new()
                .create(true)
                .truncate(false)
                .write(true)
                .custom_flags(input::nonblocking_flag() | input::nofollow_flag())
                .open(&lock_path)
                .map_err(fail(format!(
                    "cannot open the lock {}",
                    lock_path.display()
                )))?
        };
        let regular = file.metadata().is_ok_and(|m| m.is_file());
        if !regular {
            return Err(fail(format!(
                "cannot open the lock {}",
                lock_path.display()
            ))(std::io::Error::other("not a regular file")));
        }
        let cannot_lock = || fail(format!("cannot lock {}", lock_path.display()));
        match file.try_lock() {
            Ok(()) => {}
            Err(fs::TryLockError::WouldBlock) => {
                on_wait(&lock_path);
                file.lock().map_err(cannot_lock())?;
            }
            Err(fs::TryLockError::Error(e)) => return Err(cannot_lock()(e)),
        }
        Ok((Self { _file: file }, remove_leftovers(dir)))
    }
}

/// Removes the temporary files of approvals writes that never finished in `dir`: what it found.
fn remove_leftovers(dir: &Path) -> Vec<Leftover> {
    let Ok(entries) = fs::read_dir(dir) else {
        return Vec::new();
    };
    let mut found = Vec::new();
    for entry in entries.flatten() {
        let name = entry.file_name();
        let name = name.to_string_lossy();
        if name.starts_with('.') && name.contains(".partial-") {
            let path = entry.path();
            found.push(match fs::remove_file(&path) {
                Ok(()) => Leftover::Removed(path),
                Err(error) => Leftover::Kept { path, error },
            });
        }
    }
    found
}

/// Replaces a lock or an approvals file with `text` atomically ([`crate::output::replace`]), its
/// folder made if it is not there: a full disk or a kill leaves the previous file whole, never cut
/// mid-signature.
pub fn replace(path: &Path, text: &str) -> Result<(), OutputError> {
    if let Some(dir) = path.parent() {
        fs::create_dir_all(dir).map_err(|source| OutputError::Io {
            what: format!("cannot create {}", dir.display()),
            source,
        })?;
    }
    crate::output::replace(path, text.as_bytes())
}

/// Writes `text` to a file that must not exist yet (never overwritten: the user's data is kept).
pub fn write_new(path: &Path, text: &str) -> Result<(), OutputError> {
    let io = |what: String| move |source| OutputError::Io { what, source };
    let mut f = fs::OpenOptions::new()
        .write(true)
        .create_new(true)
        .open(path)
        .map_err(io(format!(
            "cannot create {} (it must not exist yet)",
            path.display()
        )))?;
    f.write_all(text.as_bytes())
        .map_err(io(format!("cannot write {}", path.display())))
}

/// `--signed <message>`'s signature file when none is named: `<message>.sig`, as `ssh-keygen -Y
/// sign` writes it.
pub fn signature_beside(message: &Path) -> PathBuf {
    let mut name = message.as_os_str().to_owned();
    name.push(".sig");
    PathBuf::from(name)
}

/// The wall clock as RFC 3339 UTC, as an approval records its time.
pub fn now_rfc3339() -> Result<String, RobotError> {
    signing::rfc3339_utc(crate::trust_anchor::now_unix())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A fresh folder for one test.
    fn scratch(name: &str) -> PathBuf {
        let dir = std::env::temp_dir().join(format!(
            "ergocell-review-files-{}-{name}",
            std::process::id()
        ));
        let _ = fs::remove_dir_all(&dir);
        fs::create_dir_all(&dir).unwrap();
        dir
    }

    /// A second taker waits (and is told so) until the first lets go; leftovers of killed writes
    /// are removed under the lock, and nothing else.
    #[test]
    fn the_lock_makes_a_second_taker_wait_and_removes_only_leftovers() {
        let dir = scratch("lock").join("approvals");
        let (first, leftovers) = ApprovalsLock::take(&dir, |_| panic!("nobody holds it")).unwrap();
        assert!(leftovers.is_empty());
        assert!(dir.join(APPROVALS_LOCK).exists());
        fs::write(dir.join(".c2.toml.partial-99999"), "half a file").unwrap();
        fs::write(dir.join("c2.toml"), "# approvals\n").unwrap();
        fs::write(dir.join("c1.toml.partial-1"), "not ours: no leading dot").unwrap();
        let (told, heard) = std::sync::mpsc::channel();
        let second = std::thread::spawn({
            let dir = dir.clone();
            move || {
                ApprovalsLock::take(&dir, |path| told.send(path.to_owned()).unwrap())
                    .map(|(_, leftovers)| leftovers)
            }
        });
        let waited_on = heard.recv().unwrap();
        assert_eq!(waited_on, dir.join(APPROVALS_LOCK));
        drop(first);
        let leftovers = second.join().unwrap().unwrap();
        assert_eq!(leftovers.len(), 1);
        let Leftover::Removed(removed) = &leftovers[0] else {
            panic!("{}", leftovers[0]);
        };
        assert_eq!(removed, &dir.join(".c2.toml.partial-99999"));
        assert!(leftovers[0].to_string().contains("stopped mid-write"));
        assert!(!removed.exists());
        assert!(dir.join("c2.toml").exists() && dir.join("c1.toml.partial-1").exists());
        let _ = fs::remove_dir_all(dir.parent().unwrap());
    }

    #[test]
    fn a_new_file_is_never_overwritten_and_a_replaced_one_gets_its_folder() {
        let dir = scratch("writes");
        let message = dir.join("approval.txt");
        write_new(&message, "first").unwrap();
        let e = write_new(&message, "second").unwrap_err();
        assert!(!e.is_refusal());
        assert!(e.to_string().contains("it must not exist yet"), "{e}");
        assert_eq!(fs::read_to_string(&message).unwrap(), "first");
        let lock = dir.join("locks/c2.lock.toml");
        replace(&lock, "one").unwrap();
        replace(&lock, "two").unwrap();
        assert_eq!(fs::read_to_string(&lock).unwrap(), "two");
        assert_eq!(signature_beside(&message), dir.join("approval.txt.sig"));
        let _ = fs::remove_dir_all(&dir);
    }

    #[test]
    fn unreadable_and_malformed_files_are_told_apart_and_named() {
        let dir = scratch("reads");
        let e = read_text(Path::new("no/such/cell.toml")).unwrap_err();
        let ReviewFileError::Unreadable { what, cause } = &e else {
            panic!("{e}");
        };
        assert!(what.contains("no/such/cell.toml (relative to "), "{what}");
        assert!(cause.is_not_found());
        let missing = dir.join("missing.toml");
        let e = read_text(&missing).unwrap_err();
        assert_eq!(e.to_string(), format!("cannot read {}", missing.display()));
        let key = dir.join("key");
        fs::write(&key, "not a key").unwrap();
        let e = read_private_key(&key).unwrap_err();
        assert!(matches!(e, ReviewFileError::Malformed { .. }), "{e}");
        assert!(
            e.to_string().starts_with(&format!("{}: ", key.display())),
            "{e}"
        );
        // a missing approvals file is an empty chain; a malformed one is named
        let approvals = dir.join("c2.toml");
        assert!(read_approvals(&approvals).unwrap().approval.is_empty());
        fs::write(&approvals, "approval = 3").unwrap();
        let e = read_approvals(&approvals).unwrap_err();
        assert!(matches!(e, ReviewFileError::Malformed { .. }), "{e}");
        let cell = dir.join("cell.toml");
        fs::write(&cell, "[robot\n").unwrap();
        let e = ReviewCell::load(&cell).unwrap_err();
        assert!(
            e.to_string().starts_with(&format!("{}: ", cell.display())),
            "{e}"
        );
        let _ = fs::remove_dir_all(&dir);
    }

    /// The shipped cell and its classes; a class file that declares another class is refused.
    #[test]
    fn the_shipped_cell_loads_and_each_class_file_must_be_its_class() {
        let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
        let cell_path = root.join("config/cell.toml");
        let cell = ReviewCell::load(&cell_path).unwrap();
        assert_eq!(cell.cell_dir, cell_path.parent().unwrap());
        assert!(!cell.urdf_text.is_empty() && !cell.allowed_signers.is_empty());
        // Untrusted (no anchor on this machine, or not root's) means nobody is trusted.
        if cell.trust_problem.is_some() {
            assert_eq!(cell.trusted, TrustedSigners::default());
        }
        let shipped = TrajectoryLayout::new(root.join("trajectories"));
        let (spec, hashes, text) = cell.read_spec(&shipped, TrajectoryClass::C2, "1").unwrap();
        assert_eq!(spec.class, TrajectoryClass::C2);
        let (_, other_version, _) = cell.read_spec(&shipped, TrajectoryClass::C2, "2").unwrap();
        assert_ne!(
            hashes, other_version,
            "the version is one of the hashed inputs"
        );
        let inputs = cell.verify_inputs(TrajectoryClass::C2, "", &hashes, None);
        assert!(
            std::ptr::eq(inputs.model, &raw const cell.model)
                && std::ptr::eq(inputs.trusted, &raw const cell.trusted)
        );
        // c2's file saved as c1's
        let dir = scratch("specs");
        fs::write(dir.join("c1.toml"), &text).unwrap();
        let e = cell
            .read_spec(&TrajectoryLayout::new(&dir), TrajectoryClass::C1, "1")
            .unwrap_err();
        let c1 = dir.join("c1.toml");
        assert_eq!(
            e.to_string(),
            format!("{}: file declares class c2, expected c1", c1.display())
        );
        let _ = fs::remove_dir_all(&dir);
    }

    #[test]
    fn the_clock_reads_as_an_approval_records_it() {
        let now = now_rfc3339().unwrap();
        assert_eq!(now.len(), "2026-12-02T02:30:00Z".len(), "{now}");
        assert!(now.ends_with('Z') && now.as_bytes()[10] == b'T', "{now}");
    }
}
