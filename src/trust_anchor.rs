//! Where the site's approvers authority is installed, and the check that the cell's own account
//! could not have put it there.
//!
//! The approvers' files in the project folder count only under the authority's signature
//! ([`ergocell_robot::authority`]); the authority's public key is the trust anchor, so it must live
//! where neither the cell's service account nor anyone who can write the project folder can change
//! it. The rule, OpenSSH's `StrictModes` for `authorized_keys` made stricter: the key file and every
//! folder above it (symbolic links resolved) are owned by root, and none is writable by group or
//! others, except a folder with the sticky bit (`/tmp`), where no one but an entry's owner can
//! rename or delete it. A non-root account can then neither edit the anchor nor swap it for its own.
//! (An account that is root can change anything: run the cell under an account of its own.)
//!
//! The folder is [`DEFAULT_ANCHOR_DIR`] (`/etc/ergocell` unless the integrator built the binary with
//! `ERGOCELL_TRUST_ANCHOR_DIR` set), or the `ERGOCELL_TRUST_ANCHOR_DIR` environment variable: naming
//! another folder gains nothing, as it must pass the same ownership check.

use std::fs;
use std::io::Read as _;
use std::path::{Path, PathBuf};

use ergocell_robot::authority::{self, Authority, APPROVERS_SIGNATURE};
use ergocell_robot::TrustedSigners;

/// The environment variable that names the anchor's folder at run time.
pub const ANCHOR_DIR_ENV: &str = "ERGOCELL_TRUST_ANCHOR_DIR";

/// The anchor's folder when the environment names none: `/etc/ergocell`, or the folder the binary
/// was built with (`ERGOCELL_TRUST_ANCHOR_DIR=… cargo build`).
pub const DEFAULT_ANCHOR_DIR: &str = match option_env!("ERGOCELL_TRUST_ANCHOR_DIR") {
    Some(dir) => dir,
    None => "/etc/ergocell",
};

/// The authority's public key(s) in the anchor's folder (one OpenSSH ssh-ed25519 key a line).
pub const AUTHORITY_FILE: &str = "approvers-authority.pub";

/// Revocations that hold whatever the project folder says, in the anchor's folder (optional).
pub const ANCHOR_REVOKED: &str = "revoked_keys";

/// The most an anchor file or a signature may hold: they are a few lines.
const MAX_BYTES: u64 = 64 * 1024;

/// The anchor's folder: the environment's, else [`DEFAULT_ANCHOR_DIR`].
pub fn anchor_dir() -> PathBuf {
    std::env::var_os(ANCHOR_DIR_ENV)
        .filter(|d| !d.is_empty())
        .map_or_else(|| PathBuf::from(DEFAULT_ANCHOR_DIR), PathBuf::from)
}

/// The wall clock in whole seconds since the Unix epoch (0 if the clock is before it), for the
/// approvals' time check: a calendar date is compared, so it is the wall clock, read here at the
/// binary's edge.
#[allow(clippy::disallowed_methods)]
pub fn now_unix() -> i64 {
    std::time::SystemTime::now()
        .duration_since(std::time::UNIX_EPOCH)
        .map_or(0, |d| i64::try_from(d.as_secs()).unwrap_or(i64::MAX))
}

/// Why the anchor cannot be used.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum AnchorError {
    /// The authority's key file is not there.
    #[error("{} does not exist (root installs the site's authority key there)", .0.display())]
    Missing(PathBuf),
    /// A file or folder on the way could be changed by someone other than root.
    #[error("{} {why}: the trust anchor must be root's alone", path.display())]
    Unsafe { path: PathBuf, why: String },
    /// A file could not be read.
    #[error("cannot read {}: {source}", path.display())]
    Read {
        path: PathBuf,
        source: std::io::Error,
    },
    /// A file is not what it should be (too large, not UTF-8, not keys).
    #[error("{}: {why}", path.display())]
    Bad { path: PathBuf, why: String },
}

/// Reads `path` (a file) after checking that it and every folder above it are root's alone (see
/// the module docs), **on the file it reads**: the file is opened once, its owner and mode taken
/// from the open descriptor (`fstat`), the folders above it from the path the descriptor was opened
/// at (`/proc/self/fd`), and the text read from the same descriptor. Checking one path and reading
/// it again let a symlink flipping between root's key and another account's pass the check with
/// root's and be read as the other (an unprivileged account's self-made authority was accepted on
/// the second try).
pub fn read_root_owned(path: &Path) -> Result<String, AnchorError> {
    use std::os::fd::AsRawFd as _;
    use std::os::unix::fs::MetadataExt as _;
    let read_err = |p: &Path, source: std::io::Error| AnchorError::Read {
        path: p.to_owned(),
        source,
    };
    let unsafe_ = |p: &Path, why: String| AnchorError::Unsafe {
        path: p.to_owned(),
        why,
    };
    let (file, file_meta) = crate::input::open(path).map_err(|e| match e {
        crate::input::InputError::Io { error, .. }
            if error.kind() == std::io::ErrorKind::NotFound =>
        {
            AnchorError::Missing(path.to_owned())
        }
        crate::input::InputError::NotAFile { what, .. } => {
            unsafe_(path, format!("is {what}, not a regular file"))
        }
        other => AnchorError::Bad {
            path: path.to_owned(),
            why: other.to_string(),
        },
    })?;
    let real = fs::read_link(format!("/proc/self/fd/{}", file.as_raw_fd()))
        .map_err(|source| read_err(path, source))?;
    if !file_meta.is_file() {
        return Err(unsafe_(&real, "is not a regular file".to_owned()));
    }
    for (i, p) in real.ancestors().enumerate() {
        let m = if i == 0 {
            file_meta.clone()
        } else {
            fs::metadata(p).map_err(|source| read_err(p, source))?
        };
        if m.uid() != 0 {
            return Err(unsafe_(p, format!("is owned by uid {}, not root", m.uid())));
        }
        let writable_by_others = m.mode() & 0o022 != 0;
        let sticky_folder = i > 0 && m.mode() & 0o1000 != 0;
        if writable_by_others && !sticky_folder {
            return Err(unsafe_(
                p,
                format!(
                    "is writable by group or others (mode {:o})",
                    m.mode() & 0o7777
                ),
            ));
        }
    }
    read_all(path, file)
}

/// Reads an open file whole, refusing anything over [`MAX_BYTES`] or not UTF-8.
fn read_all(path: &Path, file: fs::File) -> Result<String, AnchorError> {
    let bad = |why: String| AnchorError::Bad {
        path: path.to_owned(),
        why,
    };
    let mut bytes = Vec::new();
    file.take(MAX_BYTES + 1)
        .read_to_end(&mut bytes)
        .map_err(|source| AnchorError::Read {
            path: path.to_owned(),
            source,
        })?;
    if bytes.len() as u64 > MAX_BYTES {
        return Err(bad(format!("larger than {MAX_BYTES} bytes")));
    }
    String::from_utf8(bytes).map_err(|_| bad("is not UTF-8 text".to_owned()))
}

/// Reads a small text file whole (not an anchor file: no ownership rule).
fn read_small(path: &Path) -> Result<String, AnchorError> {
    let (file, _) = crate::input::open(path).map_err(|e| AnchorError::Bad {
        path: path.to_owned(),
        why: e.to_string(),
    })?;
    read_all(path, file)
}

/// Loads the site's approvers authority from the anchor folder `dir`: the key file (and the
/// revocation list, when there is one) read by [`read_root_owned`].
pub fn load_authority(dir: &Path) -> Result<Authority, AnchorError> {
    let key_path = dir.join(AUTHORITY_FILE);
    let keys = read_root_owned(&key_path)?;
    let revoked_path = dir.join(ANCHOR_REVOKED);
    let revoked = match read_root_owned(&revoked_path) {
        Ok(text) => text,
        Err(AnchorError::Missing(_)) => String::new(),
        Err(e) => return Err(e),
    };
    Authority::parse(&keys, &revoked).map_err(|e| AnchorError::Bad {
        path: key_path,
        why: e.to_string(),
    })
}

/// The authority's signature beside the approvers' files in `cell_dir`, if there is one.
pub fn read_signature(cell_dir: &Path) -> Result<Option<String>, AnchorError> {
    let path = cell_dir.join(APPROVERS_SIGNATURE);
    match fs::symlink_metadata(&path) {
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => Ok(None),
        _ => read_small(&path).map(Some),
    }
}

/// Why the cell's approvers are not trusted ([`trusted_signers`]).
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum TrustListError {
    /// The approvers' files themselves do not parse.
    #[error("{0}")]
    Files(#[source] ergocell_robot::RobotError),
    /// The authority's signature beside them cannot be read.
    #[error("{0}")]
    Signature(#[source] AnchorError),
    /// The files are not signed by the site's authority, or the authority cannot be used.
    #[error("{0}")]
    Authority(#[source] authority::AuthorityError),
}

/// The approvers the cell trusts: the project's files (`allowed`, `revoked`, read by the caller
/// from `cell_dir/approvers/`) under the authority installed in `anchor_dir`. A list that trusts no
/// key needs no authority. The error says why the keys are not trusted.
pub fn trusted_signers(
    cell_dir: &Path,
    allowed: &str,
    revoked: &str,
    anchor_dir: &Path,
) -> Result<TrustedSigners, TrustListError> {
    let listed = TrustedSigners::parse(allowed, revoked).map_err(TrustListError::Files)?;
    if listed.keys().is_empty() {
        return Ok(listed);
    }
    let signature = read_signature(cell_dir).map_err(TrustListError::Signature)?;
    // The authority's check names why the anchor could not be loaded, in its own words.
    let loaded = load_authority(anchor_dir).map_err(|e| e.to_string());
    authority::anchored_signers(
        allowed,
        revoked,
        signature.as_deref(),
        loaded.as_ref().map_err(String::as_str),
    )
    .map_err(TrustListError::Authority)
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::os::unix::fs::PermissionsExt as _;

    fn is_root() -> bool {
        use std::os::unix::fs::MetadataExt as _;
        // /proc/self is owned by the process's effective uid.
        fs::metadata("/proc/self").is_ok_and(|m| m.uid() == 0)
    }

    fn folder(name: &str) -> PathBuf {
        let dir =
            std::env::temp_dir().join(format!("ergocell-anchor-{name}-{}", std::process::id()));
        let _ = fs::remove_dir_all(&dir);
        fs::create_dir_all(&dir).unwrap();
        fs::set_permissions(&dir, fs::Permissions::from_mode(0o755)).unwrap();
        dir
    }

    #[test]
    fn a_missing_anchor_says_where_it_looked() {
        let dir = folder("missing");
        let e = load_authority(&dir).unwrap_err();
        assert!(matches!(e, AnchorError::Missing(_)), "{e}");
        assert!(e.to_string().contains(AUTHORITY_FILE), "{e}");
        fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn an_anchor_anyone_else_could_change_is_refused() {
        if !is_root() {
            eprintln!("skipped: only root can make a root-owned anchor (CI runs as root)");
            return;
        }
        let dir = folder("modes");
        let key = dir.join(AUTHORITY_FILE);
        let site = ergocell_robot::signing::key_from_seed(&[90; 32], "site");
        fs::write(
            &key,
            ergocell_robot::signing::public_key_openssh(&site).unwrap(),
        )
        .unwrap();
        fs::set_permissions(&key, fs::Permissions::from_mode(0o644)).unwrap();
        load_authority(&dir).unwrap();

        fs::set_permissions(&key, fs::Permissions::from_mode(0o666)).unwrap();
        let e = load_authority(&dir).unwrap_err().to_string();
        assert!(e.contains("writable by group or others"), "{e}");
        fs::set_permissions(&key, fs::Permissions::from_mode(0o644)).unwrap();

        // The folder writable by others (no sticky bit): the file could be swapped.
        fs::set_permissions(&dir, fs::Permissions::from_mode(0o777)).unwrap();
        let e = load_authority(&dir).unwrap_err().to_string();
        assert!(e.contains("writable by group or others (mode 777)"), "{e}");
        fs::set_permissions(&dir, fs::Permissions::from_mode(0o755)).unwrap();

        // Owned by another account.
        std::os::unix::fs::chown(&key, Some(1000), None).unwrap();
        let e = load_authority(&dir).unwrap_err().to_string();
        assert!(e.contains("owned by uid 1000, not root"), "{e}");
        std::os::unix::fs::chown(&key, Some(0), None).unwrap();

        // A symbolic link is followed and its target checked.
        let elsewhere = folder("modes-target");
        let target = elsewhere.join("key.pub");
        fs::copy(&key, &target).unwrap();
        std::os::unix::fs::chown(&target, Some(1000), None).unwrap();
        fs::remove_file(&key).unwrap();
        std::os::unix::fs::symlink(&target, &key).unwrap();
        let e = load_authority(&dir).unwrap_err().to_string();
        assert!(e.contains("owned by uid 1000"), "{e}");
        fs::remove_dir_all(&dir).unwrap();
        fs::remove_dir_all(&elsewhere).unwrap();
    }

    /// The anchor named through a symlink that flips between root's key and another account's,
    /// as fast as a thread can: every load is root's authority or an error, never the other's. The
    /// check and the read were two opens of the path; they are now one open file.
    #[test]
    fn a_symlink_flipping_between_roots_key_and_anothers_never_loads_the_other() {
        if !is_root() {
            eprintln!("skipped: only root can make a root-owned anchor (CI runs as root)");
            return;
        }
        let roots = folder("race-root");
        let root_key = roots.join("root.pub");
        let site = ergocell_robot::signing::key_from_seed(&[90; 32], "site");
        let evil = ergocell_robot::signing::key_from_seed(&[66; 32], "evil");
        fs::write(
            &root_key,
            ergocell_robot::signing::public_key_openssh(&site).unwrap(),
        )
        .unwrap();
        fs::set_permissions(&root_key, fs::Permissions::from_mode(0o644)).unwrap();
        let theirs = folder("race-theirs");
        let evil_key = theirs.join("evil.pub");
        fs::write(
            &evil_key,
            ergocell_robot::signing::public_key_openssh(&evil).unwrap(),
        )
        .unwrap();
        fs::set_permissions(&evil_key, fs::Permissions::from_mode(0o644)).unwrap();
        std::os::unix::fs::chown(&evil_key, Some(65534), None).unwrap();
        let link = theirs.join(AUTHORITY_FILE);
        std::os::unix::fs::symlink(&root_key, &link).unwrap();
        let roots_fingerprints = load_authority(&theirs).unwrap().fingerprints();
        let stop = std::sync::Arc::new(std::sync::atomic::AtomicBool::new(false));
        let flipper = {
            let (stop, link, root_key, evil_key, theirs) = (
                stop.clone(),
                link.clone(),
                root_key.clone(),
                evil_key.clone(),
                theirs.clone(),
            );
            std::thread::spawn(move || {
                let tmp = theirs.join("flip.tmp");
                let mut k = 0u64;
                while !stop.load(std::sync::atomic::Ordering::Relaxed) {
                    let target = if k.is_multiple_of(2) {
                        &evil_key
                    } else {
                        &root_key
                    };
                    let _ = fs::remove_file(&tmp);
                    if std::os::unix::fs::symlink(target, &tmp).is_ok() {
                        let _ = fs::rename(&tmp, &link);
                    }
                    k += 1;
                }
            })
        };
        let (mut roots_loaded, mut refused) = (0, 0);
        for _ in 0..3000 {
            match load_authority(&theirs) {
                Ok(a) => {
                    assert_eq!(a.fingerprints(), roots_fingerprints, "the other key loaded");
                    roots_loaded += 1;
                }
                Err(_) => refused += 1,
            }
        }
        stop.store(true, std::sync::atomic::Ordering::Relaxed);
        flipper.join().unwrap();
        assert!(roots_loaded + refused == 3000);
        fs::remove_dir_all(&roots).unwrap();
        fs::remove_dir_all(&theirs).unwrap();
    }
}
