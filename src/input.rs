//! Files the commands read, read one way: bounded, whole, and named in every error.
//!
//! A path given as an input may be anything: a folder, a device that never ends (`/dev/zero`), a
//! pipe, a file far larger than any real one of its kind. Each read here says what kind of file it
//! expects ([`Kind`], with the largest such file ergocell accepts), refuses folders and devices by
//! name, and reads at most one byte past the limit, so a wrong path costs an error, never the
//! machine's memory. Text must be UTF-8. A missing or unreadable file is bad input (exit code 2 in
//! the binary), as a malformed one is.

use std::fs;
use std::io::Read as _;
use std::path::{Path, PathBuf};

/// What a file is expected to be, and so how large it may be.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Kind {
    /// A configuration, rig, calibration, trajectory, lock or approvals file, a URDF: 64 MiB.
    Config,
    /// Landmarks or detections (JSON, CSV, TRC, OpenPose JSON, caliscope CSV): 2 GiB.
    Data,
    /// A calibration image: 256 MiB.
    Image,
    /// An MCAP recording, read whole by `review`, `report` and `replay`: 8 GiB.
    Recording,
}

impl Kind {
    /// The largest file of this kind, in bytes.
    pub const fn limit_bytes(self) -> u64 {
        match self {
            Self::Config => 64 << 20,
            Self::Data => 2 << 30,
            Self::Image => 256 << 20,
            Self::Recording => 8 << 30,
        }
    }

    const fn noun(self) -> &'static str {
        match self {
            Self::Config => "a configuration file",
            Self::Data => "a data file",
            Self::Image => "an image",
            Self::Recording => "a recording",
        }
    }
}

/// Why an input cannot be read.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum InputError {
    /// The file cannot be opened or read.
    #[error("cannot read {}: {error}", path.display())]
    Io {
        path: PathBuf,
        // Not `source`: the message already says it, and `{:#}` would print it twice.
        error: std::io::Error,
    },
    /// A folder, or a device.
    #[error("{} is {what}, not a file", path.display())]
    NotAFile { path: PathBuf, what: &'static str },
    /// Larger than any file of its kind.
    #[error("{} is larger than {limit_mib} MiB, more than {noun} can be (is it the right file?)", path.display())]
    TooLarge {
        path: PathBuf,
        limit_mib: u64,
        noun: &'static str,
    },
    /// Text that is not UTF-8.
    #[error("{} is not UTF-8 text (byte {at})", path.display())]
    NotUtf8 { path: PathBuf, at: usize },
}

impl InputError {
    /// The file is not there (as opposed to there and unreadable).
    pub fn is_not_found(&self) -> bool {
        matches!(self, InputError::Io { error, .. } if error.kind() == std::io::ErrorKind::NotFound)
    }
}

/// Reads `path` whole as `kind` (see the module docs).
pub fn read(path: &Path, kind: Kind) -> Result<Vec<u8>, InputError> {
    use std::os::unix::fs::FileTypeExt as _;
    let io = |error| InputError::Io {
        path: path.to_owned(),
        error,
    };
    let meta = fs::metadata(path).map_err(io)?;
    let file_type = meta.file_type();
    let what = if file_type.is_dir() {
        Some("a folder")
    } else if file_type.is_char_device() || file_type.is_block_device() {
        Some("a device")
    } else if file_type.is_socket() {
        Some("a socket")
    } else {
        None
    };
    if let Some(what) = what {
        return Err(InputError::NotAFile {
            path: path.to_owned(),
            what,
        });
    }
    let limit = kind.limit_bytes();
    let too_large = || InputError::TooLarge {
        path: path.to_owned(),
        limit_mib: limit >> 20,
        noun: kind.noun(),
    };
    if meta.len() > limit {
        return Err(too_large());
    }
    let file = fs::File::open(path).map_err(io)?;
    let mut bytes = Vec::with_capacity(usize::try_from(meta.len()).unwrap_or(0));
    // A pipe has no length: the limit holds while reading.
    file.take(limit + 1).read_to_end(&mut bytes).map_err(io)?;
    if bytes.len() as u64 > limit {
        return Err(too_large());
    }
    Ok(bytes)
}

/// Reads `path` whole as UTF-8 text of `kind`.
pub fn read_text(path: &Path, kind: Kind) -> Result<String, InputError> {
    String::from_utf8(read(path, kind)?).map_err(|e| InputError::NotUtf8 {
        path: path.to_owned(),
        at: e.utf8_error().valid_up_to(),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_device_a_folder_and_a_missing_file_are_refused_by_name() {
        let e = read(Path::new("/dev/zero"), Kind::Recording).unwrap_err();
        assert!(e.to_string().contains("/dev/zero is a device"), "{e}");
        let e = read(Path::new("/"), Kind::Config).unwrap_err();
        assert!(e.to_string().contains("is a folder"), "{e}");
        let e = read(Path::new("/no/such/file"), Kind::Config).unwrap_err();
        assert!(matches!(e, InputError::Io { .. }), "{e}");
    }

    #[test]
    fn a_file_over_its_kinds_limit_is_refused_before_it_is_read() {
        let dir = std::env::temp_dir().join(format!("ergocell-input-{}", std::process::id()));
        fs::create_dir_all(&dir).unwrap();
        let path = dir.join("big.toml");
        let file = fs::File::create(&path).unwrap();
        // A sparse file: its length, not its blocks, is over the limit.
        file.set_len(Kind::Config.limit_bytes() + 1).unwrap();
        let e = read_text(&path, Kind::Config).unwrap_err();
        assert!(e.to_string().contains("larger than 64 MiB"), "{e}");
        fs::write(&path, b"ok = 1\n").unwrap();
        assert_eq!(read_text(&path, Kind::Config).unwrap(), "ok = 1\n");
        fs::write(&path, b"ok = \xff\n").unwrap();
        let e = read_text(&path, Kind::Config).unwrap_err();
        assert!(e.to_string().contains("not UTF-8 text (byte 5)"), "{e}");
        fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn a_pipe_that_never_ends_stops_at_the_limit() {
        // /dev/zero through a FIFO: no length to check up front.
        let dir = std::env::temp_dir().join(format!("ergocell-input-fifo-{}", std::process::id()));
        fs::create_dir_all(&dir).unwrap();
        let fifo = dir.join("zero");
        let made = std::process::Command::new("mkfifo")
            .arg(&fifo)
            .status()
            .is_ok_and(|s| s.success());
        if !made {
            eprintln!("skipped: mkfifo is not available");
            return;
        }
        let writer = std::thread::spawn({
            let fifo = fifo.clone();
            move || {
                use std::io::Write as _;
                let Ok(mut f) = fs::OpenOptions::new().write(true).open(&fifo) else {
                    return;
                };
                let block = vec![0_u8; 1 << 20];
                while f.write_all(&block).is_ok() {}
            }
        });
        let e = read(&fifo, Kind::Config).unwrap_err();
        assert!(e.to_string().contains("larger than 64 MiB"), "{e}");
        writer.join().unwrap();
        fs::remove_dir_all(&dir).unwrap();
    }
}
