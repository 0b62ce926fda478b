//! The trust anchor: the site's approvers authority, installed where the cell's own account could
//! not have put it, and the trust list it makes of the approvers' files.
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
//! The rule is [`check_root_alone`], over the ownership chain the [`CellFiles`] port reports for
//! the one open file it read.

use std::path::{Path, PathBuf};

use ergocell_robot::authority::{self, Authority, APPROVERS_SIGNATURE};
use ergocell_robot::{RobotError, TrustedSigners};

use crate::files::{AnchorFile, Cause, CellFiles, FileError, FileKind, Ownership};

/// The authority's public key(s) in the anchor's folder (one OpenSSH ssh-ed25519 key a line).
pub const AUTHORITY_FILE: &str = "approvers-authority.pub";

/// Revocations that hold whatever the project folder says, in the anchor's folder (optional).
pub const ANCHOR_REVOKED: &str = "revoked_keys";

/// The most an anchor file may hold: it is a few lines.
pub const MAX_BYTES: u64 = 64 * 1024;

/// Why a file or folder on the way to the anchor could be changed by someone other than root.
#[derive(Debug, Clone, Copy, PartialEq, Eq, thiserror::Error)]
pub enum NotRootAlone {
    /// The anchor is a folder, a device or a pipe.
    #[error("is not a regular file")]
    NotRegularFile,
    /// Owned by another account.
    #[error("is owned by uid {uid}, not root")]
    Owner { uid: u32 },
    /// Writable by group or others (and not a sticky folder).
    #[error("is writable by group or others (mode {mode:o})")]
    Writable { mode: u32 },
    /// The folders above it were not all reported (a chain that does not climb to `/` one parent
    /// at a time): who could replace it is unknown.
    #[error("has folders above it whose owners are unknown")]
    UnknownFolders,
}

/// Why the anchor cannot be used.
#[derive(Debug, Clone, thiserror::Error)]
#[non_exhaustive]
pub enum AnchorError {
    /// The authority's key file is not there.
    #[error("{} does not exist (root installs the site's authority key there)", .0.display())]
    Missing(PathBuf),
    /// A file or folder on the way could be changed by someone other than root.
    #[error("{} {problem}: the trust anchor must be root's alone", path.display())]
    Unsafe {
        path: PathBuf,
        problem: NotRootAlone,
    },
    /// A file could not be read. The cause names the path.
    #[error("{cause}")]
    Read {
        path: PathBuf,
        #[source]
        cause: Cause,
    },
    /// Not UTF-8 text.
    #[error("{} is not UTF-8 text", path.display())]
    NotText { path: PathBuf },
    /// Larger than an anchor file can be ([`MAX_BYTES`]).
    #[error("{} is larger than {limit} bytes", path.display())]
    TooLarge { path: PathBuf, limit: u64 },
    /// Not the authority's keys.
    #[error("{}: {cause}", path.display())]
    Keys {
        path: PathBuf,
        #[source]
        cause: Box<RobotError>,
    },
}

/// The anchor's rule over the ownership of a file and the folders above it (the file first, then
/// each parent, `/` last): a regular file, each owned by root, none writable by group or others
/// except a sticky folder.
pub fn check_root_alone(chain: &[Ownership]) -> Result<(), AnchorError> {
    let unsafe_ = |o: &Ownership, problem| AnchorError::Unsafe {
        path: o.path.clone(),
        problem,
    };
    let Some(file) = chain.first() else {
        return Err(AnchorError::Unsafe {
            path: PathBuf::new(),
            problem: NotRootAlone::UnknownFolders,
        });
    };
    if !file.regular_file {
        return Err(unsafe_(file, NotRootAlone::NotRegularFile));
    }
    let climbs = chain
        .windows(2)
        .all(|w| w[0].path.parent() == Some(w[1].path.as_path()))
        && chain
            .last()
            .is_some_and(|o| o.path.parent().is_none() && o.path.has_root());
    if !climbs {
        return Err(unsafe_(file, NotRootAlone::UnknownFolders));
    }
    for (i, o) in chain.iter().enumerate() {
        if o.uid != 0 {
            return Err(unsafe_(o, NotRootAlone::Owner { uid: o.uid }));
        }
        let writable_by_others = o.mode & 0o022 != 0;
        let sticky_folder = i > 0 && o.mode & 0o1000 != 0;
        if writable_by_others && !sticky_folder {
            return Err(unsafe_(
                o,
                NotRootAlone::Writable {
                    mode: o.mode & 0o7777,
                },
            ));
        }
    }
    Ok(())
}

/// An anchor file's text, when it and every folder above it are root's alone.
pub fn read_root_owned(files: &dyn CellFiles, path: &Path) -> Result<String, AnchorError> {
    let allowed = |chain: &[Ownership]| check_root_alone(chain).is_ok();
    let AnchorFile { bytes, chain } =
        files
            .read_anchor(path, MAX_BYTES, &allowed)
            .map_err(|e| match e {
                FileError::Missing { path } => AnchorError::Missing(path),
                FileError::Unreadable { path, cause } => AnchorError::Read { path, cause },
                FileError::TooLarge { path, limit } => AnchorError::TooLarge { path, limit },
            })?;
    check_root_alone(&chain)?;
    if bytes.len() as u64 > MAX_BYTES {
        return Err(AnchorError::TooLarge {
            path: path.to_owned(),
            limit: MAX_BYTES,
        });
    }
    String::from_utf8(bytes).map_err(|_| AnchorError::NotText {
        path: path.to_owned(),
    })
}

/// The site's approvers authority from the anchor folder `dir`: the key file (and the revocation
/// list, when there is one), each read by [`read_root_owned`].
pub fn load_authority(files: &dyn CellFiles, dir: &Path) -> Result<Authority, AnchorError> {
    let key_path = dir.join(AUTHORITY_FILE);
    let keys = read_root_owned(files, &key_path)?;
    let revoked = match read_root_owned(files, &dir.join(ANCHOR_REVOKED)) {
        Ok(text) => text,
        Err(AnchorError::Missing(_)) => String::new(),
        Err(e) => return Err(e),
    };
    Authority::parse(&keys, &revoked).map_err(|cause| AnchorError::Keys {
        path: key_path,
        cause: Box::new(cause),
    })
}

/// The authority's signature beside the approvers' files in `cell_dir`, if there is one (a few
/// lines: at most [`MAX_BYTES`]).
pub fn read_signature(files: &dyn CellFiles, cell_dir: &Path) -> Result<Option<String>, FileError> {
    let path = cell_dir.join(APPROVERS_SIGNATURE);
    match files.read(FileKind::Cell, &path) {
        Ok(text) if text.len() as u64 > MAX_BYTES => Err(FileError::TooLarge {
            path,
            limit: MAX_BYTES,
        }),
        Ok(text) => Ok(Some(text)),
        Err(FileError::Missing { .. }) => Ok(None),
        Err(e) => Err(e),
    }
}

/// Why the cell's approvers are not trusted ([`trusted_signers`]).
#[derive(Debug, Clone, thiserror::Error)]
#[non_exhaustive]
pub enum TrustListError {
    /// The approvers' files themselves do not parse.
    #[error("{0}")]
    Files(#[source] Box<RobotError>),
    /// The authority's signature beside them cannot be read.
    #[error("{0}")]
    Signature(#[source] FileError),
    /// The files are not signed by the site's authority, or the authority cannot be used.
    #[error("{0}")]
    Authority(#[source] authority::AuthorityError),
}

/// The approvers the cell trusts: the project's files (`allowed`, `revoked`, read by the caller
/// from `cell_dir/approvers/`) under the authority installed in `anchor_dir`. A list that trusts no
/// key needs no authority. The error says why the keys are not trusted.
pub fn trusted_signers(
    files: &dyn CellFiles,
    cell_dir: &Path,
    allowed: &str,
    revoked: &str,
    anchor_dir: &Path,
) -> Result<TrustedSigners, TrustListError> {
    let listed =
        TrustedSigners::parse(allowed, revoked).map_err(|e| TrustListError::Files(Box::new(e)))?;
    if listed.keys().is_empty() {
        return Ok(listed);
    }
    let signature = read_signature(files, cell_dir).map_err(TrustListError::Signature)?;
    // The authority's check names why the anchor could not be loaded, in its own words.
    let loaded = load_authority(files, anchor_dir).map_err(|e| e.to_string());
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

    fn owned(path: &str, uid: u32, mode: u32, regular_file: bool) -> Ownership {
        Ownership {
            path: PathBuf::from(path),
            uid,
            mode,
            regular_file,
        }
    }

    fn chain(file: Ownership) -> Vec<Ownership> {
        vec![
            file,
            owned("/etc/ergocell", 0, 0o755, false),
            owned("/etc", 0, 0o755, false),
            owned("/", 0, 0o755, false),
        ]
    }

    #[test]
    fn roots_own_file_in_roots_folders_is_accepted() {
        let key = owned("/etc/ergocell/approvers-authority.pub", 0, 0o644, true);
        assert!(check_root_alone(&chain(key)).is_ok());
    }

    #[test]
    fn a_file_another_account_owns_or_can_write_is_refused() {
        let path = "/etc/ergocell/approvers-authority.pub";
        let refused = |file: Ownership| match check_root_alone(&chain(file)) {
            Err(AnchorError::Unsafe { problem, .. }) => problem,
            other => panic!("{other:?}"),
        };
        assert_eq!(
            refused(owned(path, 1000, 0o644, true)),
            NotRootAlone::Owner { uid: 1000 }
        );
        assert_eq!(
            refused(owned(path, 0, 0o666, true)),
            NotRootAlone::Writable { mode: 0o666 }
        );
        assert_eq!(
            refused(owned(path, 0, 0o644, false)),
            NotRootAlone::NotRegularFile
        );
    }

    #[test]
    fn a_folder_above_others_can_write_is_refused_unless_sticky() {
        let key = owned("/tmp/anchor/approvers-authority.pub", 0, 0o644, true);
        let with = |tmp_mode| {
            vec![
                key.clone(),
                owned("/tmp/anchor", 0, 0o755, false),
                owned("/tmp", 0, tmp_mode, false),
                owned("/", 0, 0o755, false),
            ]
        };
        assert!(check_root_alone(&with(0o1777)).is_ok());
        match check_root_alone(&with(0o777)) {
            Err(AnchorError::Unsafe { path, problem }) => {
                assert_eq!(path, PathBuf::from("/tmp"));
                assert_eq!(problem, NotRootAlone::Writable { mode: 0o777 });
            }
            other => panic!("{other:?}"),
        }
        // The sticky bit on the file itself earns nothing.
        let mut sticky_file = key.clone();
        sticky_file.mode = 0o1666;
        assert!(check_root_alone(&chain(sticky_file)).is_err());
    }

    #[test]
    fn a_chain_that_skips_a_folder_or_stops_short_of_the_root_is_refused() {
        let key = owned("/etc/ergocell/approvers-authority.pub", 0, 0o644, true);
        let mut skips = chain(key.clone());
        skips.remove(1);
        let mut short = chain(key);
        short.pop();
        for c in [skips, short] {
            assert!(matches!(
                check_root_alone(&c),
                Err(AnchorError::Unsafe {
                    problem: NotRootAlone::UnknownFolders,
                    ..
                })
            ));
        }
    }

    #[test]
    fn an_anchor_file_of_no_known_owner_or_too_large_is_refused() {
        let files = crate::MemoryFiles::new();
        let path = Path::new("/etc/ergocell/approvers-authority.pub");
        files.put_anchor(
            path,
            AnchorFile {
                bytes: b"ssh-ed25519 AAAA".to_vec(),
                chain: Vec::new(),
            },
        );
        assert!(matches!(
            read_root_owned(&files, path),
            Err(AnchorError::Unsafe { .. })
        ));
        files.put_anchor(
            path,
            AnchorFile {
                bytes: vec![b'a'; usize::try_from(MAX_BYTES).unwrap() + 1],
                chain: chain(owned(path.to_str().unwrap(), 0, 0o644, true)),
            },
        );
        assert!(matches!(
            read_root_owned(&files, path),
            Err(AnchorError::TooLarge { .. })
        ));
        assert!(matches!(
            read_root_owned(&files, Path::new("/nowhere")),
            Err(AnchorError::Missing(_))
        ));
    }
}
