//! The layout of a trajectories folder: the one place that knows where each class's files live.
//!
//! ```text
//! <dir>/<class>.toml                 trajectory spec (people, reviewed)
//! <dir>/locks/<class>.lock.toml      lock file (`ergocell trajectories lock`)
//! <dir>/approvals/<class>.toml       approvals (`ergocell trajectories approve`)
//! ```
//!
//! with `<class>` one of `c1`, `c2`, `c3` ([`TrajectoryClass::as_str`]). The approvals folder may be
//! moved elsewhere ([`TrajectoryLayout::with_approvals_dir`]: the run-time `--approvals`, the demo's
//! temporary folder); its files keep their names.
//!
//! [`TrajectoryLayout`] is path arithmetic only: like the rest of this crate it never reads, writes or
//! inspects the file system. It joins onto the folder it is given, so a relative folder (the default
//! `trajectories`) gives relative paths: `trajectories/locks/c2.lock.toml`, which is also how the
//! binary looks up the files it ships.

use std::path::{Path, PathBuf};

use crate::config::TrajectoryClass;

/// The three files a class has in a trajectories folder.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum TrajectoryFile {
    /// `<dir>/<class>.toml`: the trajectory spec ([`crate::TrajectorySpec`]).
    Spec,
    /// `<dir>/locks/<class>.lock.toml`: the lock ([`crate::LockFile`]).
    Lock,
    /// `<approvals dir>/<class>.toml`: the approvals ([`crate::lock::ApprovalsFile`]).
    Approvals,
}

impl TrajectoryFile {
    pub const ALL: [Self; 3] = [Self::Spec, Self::Lock, Self::Approvals];
}

/// Where the files of each class live, relative to a trajectories folder (see the [module
/// docs](self)). Builds paths, never touches the file system.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct TrajectoryLayout {
    dir: PathBuf,
    approvals_dir: PathBuf,
}

impl Default for TrajectoryLayout {
    /// The repository's layout, relative to its root: `trajectories/…`.
    fn default() -> Self {
        Self::new(Self::DEFAULT_DIR)
    }
}

impl TrajectoryLayout {
    /// The trajectories folder of the repository, relative to its root.
    pub const DEFAULT_DIR: &'static str = "trajectories";
    /// The lock files' folder, inside the trajectories folder.
    pub const LOCKS_DIR: &'static str = "locks";
    /// The approvals' folder, inside the trajectories folder (unless moved).
    pub const APPROVALS_DIR: &'static str = "approvals";
    /// A lock file's name: `<class>` + this.
    pub const LOCK_SUFFIX: &'static str = ".lock.toml";
    /// A spec's or an approvals file's name: `<class>` + this.
    pub const TOML_SUFFIX: &'static str = ".toml";

    /// The layout of the trajectories folder `dir`, approvals in `<dir>/approvals`.
    pub fn new(dir: impl Into<PathBuf>) -> Self {
        let dir = dir.into();
        let approvals_dir = dir.join(Self::APPROVALS_DIR);
        Self { dir, approvals_dir }
    }

    /// The same layout with the approvals read from and written to `approvals_dir` instead of
    /// `<dir>/approvals` (file names unchanged: `<approvals_dir>/<class>.toml`).
    #[must_use]
    pub fn with_approvals_dir(mut self, approvals_dir: impl Into<PathBuf>) -> Self {
        self.approvals_dir = approvals_dir.into();
        self
    }

    /// The trajectories folder, as given.
    pub fn dir(&self) -> &Path {
        &self.dir
    }

    /// `<dir>/<class>.toml`: the class's trajectory spec.
    pub fn spec(&self, class: TrajectoryClass) -> PathBuf {
        self.dir.join(format!("{class}{}", Self::TOML_SUFFIX))
    }

    /// `<dir>/locks`: the folder of the lock files.
    pub fn locks_dir(&self) -> PathBuf {
        self.dir.join(Self::LOCKS_DIR)
    }

    /// `<dir>/locks/<class>.lock.toml`: the class's lock file.
    pub fn lock(&self, class: TrajectoryClass) -> PathBuf {
        self.locks_dir()
            .join(format!("{class}{}", Self::LOCK_SUFFIX))
    }

    /// The folder of the approvals: `<dir>/approvals` unless moved with
    /// [`with_approvals_dir`](Self::with_approvals_dir).
    pub fn approvals_dir(&self) -> &Path {
        &self.approvals_dir
    }

    /// `<approvals dir>/<class>.toml`: the class's append-only approvals file.
    pub fn approvals(&self, class: TrajectoryClass) -> PathBuf {
        self.approvals_dir
            .join(format!("{class}{}", Self::TOML_SUFFIX))
    }

    /// The path of one of the class's files.
    pub fn path(&self, file: TrajectoryFile, class: TrajectoryClass) -> PathBuf {
        match file {
            TrajectoryFile::Spec => self.spec(class),
            TrajectoryFile::Lock => self.lock(class),
            TrajectoryFile::Approvals => self.approvals(class),
        }
    }

    /// Which file of which class `path` is in this layout, `None` if it is none of them. The inverse
    /// of [`path`](Self::path): `identify(&path(f, c)) == Some((f, c))`, and only those paths are
    /// identified (file names exactly `c2.toml`, `c2.lock.toml`, in exactly their folder).
    pub fn identify(&self, path: &Path) -> Option<(TrajectoryFile, TrajectoryClass)> {
        let name = path.file_name()?.to_str()?;
        let parent = path.parent()?;
        let (file, stem) = if parent == self.locks_dir() {
            (TrajectoryFile::Lock, name.strip_suffix(Self::LOCK_SUFFIX)?)
        } else if parent == self.approvals_dir {
            (
                TrajectoryFile::Approvals,
                name.strip_suffix(Self::TOML_SUFFIX)?,
            )
        } else if parent == self.dir {
            (TrajectoryFile::Spec, name.strip_suffix(Self::TOML_SUFFIX)?)
        } else {
            return None;
        };
        let class: TrajectoryClass = stem.parse().ok()?;
        // The class parser forgives case and spaces; a file name must be exactly the class's own.
        (self.path(file, class) == path).then_some((file, class))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_three_paths_of_each_class() {
        let layout = TrajectoryLayout::default();
        for (class, spec, lock, approvals) in [
            (
                TrajectoryClass::C1,
                "trajectories/c1.toml",
                "trajectories/locks/c1.lock.toml",
                "trajectories/approvals/c1.toml",
            ),
            (
                TrajectoryClass::C2,
                "trajectories/c2.toml",
                "trajectories/locks/c2.lock.toml",
                "trajectories/approvals/c2.toml",
            ),
            (
                TrajectoryClass::C3,
                "trajectories/c3.toml",
                "trajectories/locks/c3.lock.toml",
                "trajectories/approvals/c3.toml",
            ),
        ] {
            assert_eq!(layout.spec(class), Path::new(spec));
            assert_eq!(layout.lock(class), Path::new(lock));
            assert_eq!(layout.approvals(class), Path::new(approvals));
            assert_eq!(layout.path(TrajectoryFile::Spec, class), Path::new(spec));
            assert_eq!(layout.path(TrajectoryFile::Lock, class), Path::new(lock));
            assert_eq!(
                layout.path(TrajectoryFile::Approvals, class),
                Path::new(approvals)
            );
            // Relative in, relative out: what the binary's shipped-file lookup is keyed by.
            assert!(layout.lock(class).is_relative());
        }
        assert_eq!(layout.dir(), Path::new("trajectories"));
        assert_eq!(layout.locks_dir(), Path::new("trajectories/locks"));
        assert_eq!(layout.approvals_dir(), Path::new("trajectories/approvals"));
    }

    #[test]
    fn approvals_can_live_elsewhere_and_the_rest_stays() {
        let layout = TrajectoryLayout::new("/cell/trajectories").with_approvals_dir("/tmp/demo");
        let c2 = TrajectoryClass::C2;
        assert_eq!(layout.approvals_dir(), Path::new("/tmp/demo"));
        assert_eq!(layout.approvals(c2), Path::new("/tmp/demo/c2.toml"));
        assert_eq!(layout.spec(c2), Path::new("/cell/trajectories/c2.toml"));
        assert_eq!(
            layout.lock(c2),
            Path::new("/cell/trajectories/locks/c2.lock.toml")
        );
    }

    #[test]
    fn a_paths_file_name_identifies_its_class_and_file() {
        for layout in [
            TrajectoryLayout::default(),
            TrajectoryLayout::new("/abs/trajectories"),
            TrajectoryLayout::new("t").with_approvals_dir("elsewhere/approvals"),
        ] {
            for class in TrajectoryClass::ALL {
                for file in TrajectoryFile::ALL {
                    let path = layout.path(file, class);
                    assert_eq!(
                        layout.identify(&path),
                        Some((file, class)),
                        "{}",
                        path.display()
                    );
                }
            }
        }
    }

    #[test]
    fn other_paths_identify_as_nothing() {
        let layout = TrajectoryLayout::default();
        for path in [
            "trajectories/c4.toml",
            "trajectories/C2.toml",
            "trajectories/README.md",
            "trajectories/c2.lock.toml",
            "trajectories/locks/c2.toml",
            "trajectories/approvals/c2.lock.toml",
            "trajectories/other/c2.toml",
            "elsewhere/c2.toml",
            "c2.toml",
            "",
        ] {
            assert_eq!(layout.identify(Path::new(path)), None, "{path}");
        }
        // Paths are compared by component: a `./` in the middle changes nothing.
        assert_eq!(
            layout.identify(Path::new("trajectories/./locks/c2.lock.toml")),
            Some((TrajectoryFile::Lock, TrajectoryClass::C2))
        );
    }
}
