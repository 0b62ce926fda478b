//! Where the site's approvers authority is installed on this machine, and its files read as the
//! trust anchor's rule needs them ([`ergocell_approvals::anchor`]: root's alone, every folder above
//! included).
//!
//! The folder is [`DEFAULT_ANCHOR_DIR`] (`/etc/ergocell` unless the integrator built the binary with
//! `ERGOCELL_TRUST_ANCHOR_DIR` set), or the `ERGOCELL_TRUST_ANCHOR_DIR` environment variable: naming
//! another folder gains nothing, as it must pass the same ownership check.

use std::fs;
use std::io::Read as _;
use std::path::{Path, PathBuf};
use std::sync::Arc;

pub use ergocell_approvals::anchor::{
    AnchorError, NotRootAlone, TrustListError, ANCHOR_REVOKED, AUTHORITY_FILE,
};
use ergocell_approvals::files::{AnchorFile, FileError, Ownership};
use ergocell_robot::authority::Authority;
use ergocell_robot::TrustedSigners;

/// The environment variable that names the anchor's folder at run time.
pub const ANCHOR_DIR_ENV: &str = "ERGOCELL_TRUST_ANCHOR_DIR";

/// The anchor's folder when the environment names none: `/etc/ergocell`, or the folder the binary
/// was built with (`ERGOCELL_TRUST_ANCHOR_DIR=… cargo build`).
pub const DEFAULT_ANCHOR_DIR: &str = match option_env!("ERGOCELL_TRUST_ANCHOR_DIR") {
    Some(dir) => dir,
    None => "/etc/ergocell",
};

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

/// Reads an anchor file as **one** open file: opened once (never blocking, refusing folders and
/// devices unopened), its owner and mode taken from the open descriptor (`fstat`), the folders above
/// it from the path the descriptor was opened at (`/proc/self/fd`), and its bytes read from the same
/// descriptor only when `allowed(chain)`. Checking one path and reading it again let a symlink
/// flipping between root's key and another account's pass the check with root's and be read as the
/// other.
pub fn read_anchor_file(
    path: &Path,
    max_bytes: u64,
    allowed: &dyn Fn(&[Ownership]) -> bool,
) -> Result<AnchorFile, FileError> {
    use std::os::fd::AsRawFd as _;
    use std::os::unix::fs::MetadataExt as _;
    // An I/O error, with the path it happened on.
    let unreadable = |p: &Path, error: std::io::Error| FileError::Unreadable {
        path: p.to_owned(),
        cause: Arc::new(crate::input::InputError::Io {
            path: p.to_owned(),
            error,
        }),
    };
    let owned = |p: &Path, m: &fs::Metadata| Ownership {
        path: p.to_owned(),
        uid: m.uid(),
        mode: m.mode() & 0o7777,
        regular_file: m.is_file(),
    };
    let (file, file_meta) = match crate::input::open(path) {
        Ok(opened) => opened,
        Err(e) if e.is_not_found() => {
            return Err(FileError::Missing {
                path: path.to_owned(),
            })
        }
        Err(crate::input::InputError::NotAFile { .. }) => {
            // Never opened: the rule refuses it as not a regular file.
            let m = fs::metadata(path).map_err(|e| unreadable(path, e))?;
            return Ok(AnchorFile {
                bytes: Vec::new(),
                chain: vec![owned(path, &m)],
            });
        }
        Err(e) => {
            return Err(FileError::Unreadable {
                path: path.to_owned(),
                cause: Arc::new(e),
            })
        }
    };
    let real = fs::read_link(format!("/proc/self/fd/{}", file.as_raw_fd()))
        .map_err(|e| unreadable(path, e))?;
    let mut chain = vec![owned(&real, &file_meta)];
    for p in real.ancestors().skip(1) {
        chain.push(owned(p, &fs::metadata(p).map_err(|e| unreadable(p, e))?));
    }
    let mut bytes = Vec::new();
    if allowed(&chain) {
        file.take(max_bytes.saturating_add(1))
            .read_to_end(&mut bytes)
            .map_err(|e| unreadable(path, e))?;
    }
    Ok(AnchorFile { bytes, chain })
}

/// Loads the site's approvers authority from the anchor folder `dir` on this machine.
pub fn load_authority(dir: &Path) -> Result<Authority, AnchorError> {
    ergocell_approvals::anchor::load_authority(&crate::provider::OsFiles::disk(), dir)
}

/// The approvers the cell trusts ([`ergocell_approvals::anchor::trusted_signers`]) on this
/// machine's files.
pub fn trusted_signers(
    cell_dir: &Path,
    allowed: &str,
    revoked: &str,
    anchor_dir: &Path,
) -> Result<TrustedSigners, TrustListError> {
    ergocell_approvals::anchor::trusted_signers(
        &crate::provider::OsFiles::disk(),
        cell_dir,
        allowed,
        revoked,
        anchor_dir,
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::os::unix::fs::PermissionsExt as _;

    fn is_root() -> bool {
        use std::os::unix::fs::MetadataExt as _;
        // /proc/self is owned by the process's effective uid.
        let root = fs::metadata("/proc/self").is_ok_and(|m| m.uid() == 0);
        assert!(
            root || std::env::var_os("ERGOCELL_REQUIRE_ANCHOR").is_none(),
            "ERGOCELL_REQUIRE_ANCHOR is set but the tests do not run as root"
        );
        root
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
        let e = load_authority(&dir).unwrap_err();
        assert!(
            matches!(
                e,
                AnchorError::Unsafe {
                    problem: NotRootAlone::Writable { mode: 0o666 },
                    ..
                }
            ),
            "{e}"
        );
        fs::set_permissions(&key, fs::Permissions::from_mode(0o644)).unwrap();

        // The folder writable by others (no sticky bit): the file could be swapped.
        fs::set_permissions(&dir, fs::Permissions::from_mode(0o777)).unwrap();
        let e = load_authority(&dir).unwrap_err();
        assert!(
            matches!(&e, AnchorError::Unsafe { path, problem: NotRootAlone::Writable { mode: 0o777 } } if *path == dir),
            "{e}"
        );
        fs::set_permissions(&dir, fs::Permissions::from_mode(0o755)).unwrap();

        // Owned by another account.
        std::os::unix::fs::chown(&key, Some(1000), None).unwrap();
        let e = load_authority(&dir).unwrap_err();
        assert!(
            matches!(
                e,
                AnchorError::Unsafe {
                    problem: NotRootAlone::Owner { uid: 1000 },
                    ..
                }
            ),
            "{e}"
        );
        std::os::unix::fs::chown(&key, Some(0), None).unwrap();

        // A symbolic link is followed and its target checked.
        let elsewhere = folder("modes-target");
        let target = elsewhere.join("key.pub");
        fs::copy(&key, &target).unwrap();
        std::os::unix::fs::chown(&target, Some(1000), None).unwrap();
        fs::remove_file(&key).unwrap();
        std::os::unix::fs::symlink(&target, &key).unwrap();
        let e = load_authority(&dir).unwrap_err();
        assert!(
            matches!(&e, AnchorError::Unsafe { path, problem: NotRootAlone::Owner { uid: 1000 } } if *path == target),
            "{e}"
        );
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
            std::thread::spawn(move || -> u64 {
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
                k
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
        let flips = flipper.join().unwrap();
        // The link flipped while the loads ran (else the race was never tried), and every load
        // was root's key or a refusal.
        assert!(flips > 100, "the link flipped only {flips} times");
        assert!(
            roots_loaded > 0,
            "root's key never loaded ({refused} refused)"
        );
        fs::remove_dir_all(&roots).unwrap();
        fs::remove_dir_all(&theirs).unwrap();
    }
}
