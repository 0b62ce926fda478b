//! A command's private scratch folder (the demo's approvals of its own locks): `<prefix>-<pid>` in
//! the temporary folder, only this user can enter it (0700), removed on every way out, a panic
//! included. The folders of runs killed outright (kill -9 leaves no chance to clean up) are removed
//! by the next run: `<prefix>-<pid>` whose process is gone and which holds nothing but the one
//! entry the command makes there. Only where `/proc` tells which processes live.

use std::fs;
use std::path::{Path, PathBuf};

/// Why the scratch folder cannot be made.
#[derive(Debug, thiserror::Error)]
pub enum ScratchError {
    /// Something that is not our folder (a symlink, a file: another user's trap) is there.
    #[error("{} exists and is not a directory of ours: refusing to use it", path.display())]
    NotOurs { path: PathBuf },
    /// The file system failed while `what` was being done.
    #[error("{what} {}", path.display())]
    Io {
        what: &'static str,
        path: PathBuf,
        #[source]
        source: std::io::Error,
    },
}

/// The scratch folder, removed when dropped.
#[derive(Debug)]
pub struct ScratchDir(PathBuf);

impl ScratchDir {
    /// `<prefix>-<pid>` in `tmp`, made new and private; first the stale ones of killed runs are
    /// removed (those holding nothing but `only_entry`). One left by an earlier process with this
    /// pid is replaced.
    pub fn create(tmp: &Path, prefix: &str, only_entry: &str) -> Result<Self, ScratchError> {
        remove_stale(tmp, prefix, only_entry);
        let path = tmp.join(format!("{prefix}-{}", std::process::id()));
        private_dir(&path)?;
        Ok(Self(path))
    }

    /// Where it is.
    pub fn path(&self) -> &Path {
        &self.0
    }
}

impl Drop for ScratchDir {
    fn drop(&mut self) {
        let _ = fs::remove_dir_all(&self.0);
    }
}

fn io(what: &'static str, path: &Path) -> impl FnOnce(std::io::Error) -> ScratchError {
    let path = path.to_owned();
    move |source| ScratchError::Io { what, path, source }
}

/// Creates `path` as a new directory only this user can enter (0700). One already there is replaced
/// if it is a directory; a symlink or a file there is refused.
fn private_dir(path: &Path) -> Result<(), ScratchError> {
    let mut builder = fs::DirBuilder::new();
    #[cfg(unix)]
    {
        use std::os::unix::fs::DirBuilderExt;
        builder.mode(0o700);
    }
    match builder.create(path) {
        Ok(()) => Ok(()),
        Err(e) if e.kind() == std::io::ErrorKind::AlreadyExists => {
            let meta = fs::symlink_metadata(path).map_err(io("inspecting", path))?;
            if meta.file_type().is_symlink() || !meta.is_dir() {
                return Err(ScratchError::NotOurs {
                    path: path.to_owned(),
                });
            }
            fs::remove_dir_all(path).map_err(io("removing the stale", path))?;
            builder.create(path).map_err(io("creating", path))
        }
        Err(e) => Err(io("creating", path)(e)),
    }
}

/// Removes `<prefix>-<pid>` folders in `tmp` whose process is gone and which hold nothing but
/// `only_entry`.
fn remove_stale(tmp: &Path, prefix: &str, only_entry: &str) {
    if !Path::new("/proc/self").exists() {
        return;
    }
    let Ok(entries) = fs::read_dir(tmp) else {
        return;
    };
    let prefix = format!("{prefix}-");
    for entry in entries.flatten() {
        let name = entry.file_name();
        let Some(pid) = name
            .to_str()
            .and_then(|n| n.strip_prefix(prefix.as_str()))
            .and_then(|p| p.parse::<u32>().ok())
        else {
            continue;
        };
        if pid == std::process::id() || Path::new(&format!("/proc/{pid}")).exists() {
            continue;
        }
        let path = entry.path();
        let only = fs::read_dir(&path)
            .is_ok_and(|mut it| it.all(|f| f.is_ok_and(|f| f.file_name() == only_entry)));
        if only {
            let _ = fs::remove_dir_all(&path);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The folder is private and goes when dropped; a stale one of a dead process holding only the
    /// expected entry is removed, one holding anything else is kept; a symlink in its place is
    /// refused.
    #[test]
    fn the_scratch_folder_is_private_removed_and_never_a_symlink() {
        let tmp = std::env::temp_dir().join(format!("ergocell-scratch-{}", std::process::id()));
        let _ = fs::remove_dir_all(&tmp);
        fs::create_dir_all(&tmp).unwrap();
        // pid 2^22 + 1 is above Linux's largest: no such process
        let stale = tmp.join("demo-4194305");
        fs::create_dir_all(stale.join("approvals")).unwrap();
        let kept = tmp.join("demo-4194306");
        fs::create_dir_all(kept.join("mine")).unwrap();
        let dir = ScratchDir::create(&tmp, "demo", "approvals").unwrap();
        let path = dir.path().to_owned();
        #[cfg(unix)]
        {
            use std::os::unix::fs::PermissionsExt as _;
            let mode = fs::metadata(&path).unwrap().permissions().mode();
            assert_eq!(mode & 0o777, 0o700);
        }
        if Path::new("/proc/self").exists() {
            assert!(!stale.exists());
        }
        assert!(kept.exists());
        drop(dir);
        assert!(!path.exists());
        #[cfg(unix)]
        {
            std::os::unix::fs::symlink(&kept, &path).unwrap();
            let e = ScratchDir::create(&tmp, "demo", "approvals").unwrap_err();
            assert!(matches!(e, ScratchError::NotOurs { .. }), "{e}");
        }
        let _ = fs::remove_dir_all(&tmp);
    }
}
