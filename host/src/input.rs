//! Files the commands read, read one way: bounded, whole, and named in every error.
//!
//! A path given as an input may be anything: a folder, a device that never ends (`/dev/zero`), a
//! pipe, a file far larger than any real one of its kind. Each read here says what kind of file it
//! expects ([`Kind`], with the largest such file ergocell accepts), refuses folders and devices by
//! name, and reads at most one byte past the limit, so a wrong path costs an error, never the
//! machine's memory. Text must be UTF-8. A missing or unreadable file is bad input (exit code 2 in
//! the binary), as a malformed one is.
//!
//! Every input is opened by [`open`], never by `File::open`: a named pipe (FIFO) blocks in `open`
//! until a writer appears, so a command given one would hang there, deaf to Ctrl-C and SIGTERM. It
//! is opened non-blocking, its kind checked on the open file (`fstat`, so a path swapped between the
//! look and the open is caught), and then read as usual: a pipe that somebody writes into is read,
//! one that nobody writes into reads as empty at once.

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
    /// A list of files (`--images`) that names none, or cannot be one.
    #[error("`{spec}`: {why}")]
    NoFiles { spec: String, why: &'static str },
    /// Detections that cannot be used ([`crate::detections`]).
    #[error(transparent)]
    Detections(Box<crate::detections::DetectionsError>),
    /// A recording that cannot be reviewed as asked ([`crate::recordings`]).
    #[error(transparent)]
    Recording(Box<crate::recordings::RecordingError>),
}

impl InputError {
    /// The file is not there (as opposed to there and unreadable).
    pub fn is_not_found(&self) -> bool {
        matches!(self, InputError::Io { error, .. } if error.kind() == std::io::ErrorKind::NotFound)
    }
}

/// What a file of this type is, if it is not a file ergocell reads.
fn not_a_file(file_type: fs::FileType) -> Option<&'static str> {
    use std::os::unix::fs::FileTypeExt as _;
    if file_type.is_dir() {
        Some("a folder")
    } else if file_type.is_char_device() || file_type.is_block_device() {
        Some("a device")
    } else if file_type.is_socket() {
        Some("a socket")
    } else {
        None
    }
}

/// Opens `path` for reading without ever blocking in `open` (see the module docs): folders,
/// devices and sockets refused by name, before the open (a device is never opened) and again on the
/// open file. Returns the file, in blocking mode, and its metadata.
pub fn open(path: &Path) -> Result<(fs::File, fs::Metadata), InputError> {
    use std::os::unix::fs::OpenOptionsExt as _;
    let io = |error| InputError::Io {
        path: path.to_owned(),
        error,
    };
    let refuse = |what| InputError::NotAFile {
        path: path.to_owned(),
        what,
    };
    if let Some(what) = not_a_file(fs::metadata(path).map_err(io)?.file_type()) {
        return Err(refuse(what));
    }
    let file = fs::OpenOptions::new()
        .read(true)
        .custom_flags(nonblocking_flag())
        .open(path)
        .map_err(io)?;
    let meta = file.metadata().map_err(io)?;
    if let Some(what) = not_a_file(meta.file_type()) {
        return Err(refuse(what));
    }
    // Blocking again: a pipe with a writer is read as it comes; with none, read() says end of file.
    set_blocking(&file).map_err(io)?;
    Ok((file, meta))
}

/// `O_NONBLOCK` as `OpenOptionsExt::custom_flags` takes it: how inputs and outputs are opened, so
/// that a named pipe never blocks the open.
pub fn nonblocking_flag() -> i32 {
    i32::try_from(rustix::fs::OFlags::NONBLOCK.bits()).unwrap_or(0)
}

/// `O_NOFOLLOW`, for `OpenOptionsExt::custom_flags`: a symlink at the path is refused, not
/// followed.
pub fn nofollow_flag() -> i32 {
    i32::try_from(rustix::fs::OFlags::NOFOLLOW.bits()).unwrap_or(0)
}

/// Clears `O_NONBLOCK` on a file opened with [`nonblocking_flag`], once its kind is checked.
pub fn set_blocking(file: &fs::File) -> std::io::Result<()> {
    let flags = rustix::fs::fcntl_getfl(file)?;
    rustix::fs::fcntl_setfl(file, flags.difference(rustix::fs::OFlags::NONBLOCK))?;
    Ok(())
}

/// Reads `path` whole as `kind` (see the module docs).
pub fn read(path: &Path, kind: Kind) -> Result<Vec<u8>, InputError> {
    let io = |error| InputError::Io {
        path: path.to_owned(),
        error,
    };
    let (file, meta) = open(path)?;
    let limit = kind.limit_bytes();
    let too_large = || InputError::TooLarge {
        path: path.to_owned(),
        limit_mib: limit >> 20,
        noun: kind.noun(),
    };
    if meta.len() > limit {
        return Err(too_large());
    }
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

/// The images of `spec`: a folder (its .jpg/.jpeg/.png files), a pattern with `*` (any run) and `?`
/// (one character) in the file name (`data/left*.jpg`; brackets are literal), or one file; sorted by name. A spec that names
/// nothing, no image, or has wildcards in its folder is an [`InputError::NoFiles`].
pub fn list_images(spec: &str) -> Result<Vec<PathBuf>, InputError> {
    let path = Path::new(spec);
    let none = |why| InputError::NoFiles {
        spec: spec.to_owned(),
        why,
    };
    let listing = |dir: &Path| {
        fs::read_dir(dir).map_err(|error| InputError::Io {
            path: dir.to_owned(),
            error,
        })
    };
    let is_image = |p: &Path| {
        p.extension()
            .and_then(|e| e.to_str())
            .is_some_and(|e| matches!(e.to_ascii_lowercase().as_str(), "jpg" | "jpeg" | "png"))
    };
    let mut out: Vec<PathBuf> = if path.is_dir() {
        listing(path)?
            .filter_map(|e| e.ok().map(|e| e.path()))
            .filter(|p| p.is_file() && is_image(p))
            .collect()
    } else if spec.contains(['*', '?']) {
        let dir = path.parent().filter(|d| !d.as_os_str().is_empty());
        let dir = dir.unwrap_or_else(|| Path::new("."));
        if dir.to_string_lossy().contains(['*', '?']) {
            return Err(none("wildcards are supported in the file name only"));
        }
        let name = path.file_name().map(|n| n.to_string_lossy().into_owned());
        // `*` and `?` only: brackets are literal, a run of stars is one star.
        let mut literal = String::new();
        for c in name.unwrap_or_default().chars() {
            match c {
                '[' => literal.push_str("[[]"),
                ']' => literal.push_str("[]]"),
                '*' if literal.ends_with('*') => {}
                c => literal.push(c),
            }
        }
        let pattern =
            glob::Pattern::new(&literal).map_err(|_| none("not a valid wildcard pattern"))?;
        listing(dir)?
            .filter_map(|e| e.ok().map(|e| e.path()))
            .filter(|p| {
                p.is_file()
                    && p.file_name()
                        .is_some_and(|n| pattern.matches(&n.to_string_lossy()))
            })
            .collect()
    } else if path.is_file() {
        vec![path.to_path_buf()]
    } else {
        return Err(none("no such folder or file"));
    };
    out.sort();
    if out.is_empty() {
        return Err(none("no images found"));
    }
    Ok(out)
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
    fn a_pipe_nobody_writes_into_reads_as_empty_at_once() {
        let dir = std::env::temp_dir().join(format!("ergocell-input-fifo0-{}", std::process::id()));
        fs::create_dir_all(&dir).unwrap();
        let fifo = dir.join("silent");
        let made = std::process::Command::new("mkfifo")
            .arg(&fifo)
            .status()
            .is_ok_and(|s| s.success());
        if !made {
            eprintln!("skipped: mkfifo is not available");
            return;
        }
        // Before, open() blocked here until a writer came: forever.
        let (done, got) = std::sync::mpsc::channel();
        let path = fifo.clone();
        std::thread::spawn(move || {
            let _ = done.send(read_text(&path, Kind::Config).map_err(|e| e.to_string()));
        });
        let text = got
            .recv_timeout(std::time::Duration::from_secs(20))
            .expect("reading a FIFO with no writer must not block");
        assert_eq!(text, Ok(String::new()));
        fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn a_pipe_that_never_ends_stops_at_the_limit() {
        // /dev/zero through a pipe, named as a shell's process substitution names one
        // (`<(cat /dev/zero)`: /dev/fd/N, a pipe whose writer is already there): no length to
        // check up front.
        use std::os::fd::AsRawFd as _;
        let (reader, mut writer) = std::io::pipe().unwrap();
        let path = PathBuf::from(format!("/proc/self/fd/{}", reader.as_raw_fd()));
        let writing = std::thread::spawn(move || {
            use std::io::Write as _;
            let block = vec![0_u8; 1 << 20];
            while writer.write_all(&block).is_ok() {}
        });
        let e = read(&path, Kind::Config).unwrap_err();
        assert!(e.to_string().contains("larger than 64 MiB"), "{e}");
        drop(reader);
        writing.join().unwrap();
    }

    /// A pattern matches file names as a shell does; a folder with wildcards, or a pattern that
    /// matches nothing, is refused by name.
    #[test]
    fn images_are_listed_by_folder_pattern_or_name() {
        let dir = std::env::temp_dir().join(format!("ergocell-images-{}", std::process::id()));
        let _ = fs::remove_dir_all(&dir);
        fs::create_dir_all(&dir).unwrap();
        for name in ["left01.jpg", "left02.png", "right01.jpg", "notes.txt"] {
            fs::write(dir.join(name), b"x").unwrap();
        }
        let spec = |s: &str| format!("{}/{s}", dir.display());
        let names = |v: Vec<PathBuf>| -> Vec<String> {
            v.iter()
                .map(|p| p.file_name().unwrap().to_string_lossy().into_owned())
                .collect()
        };
        assert_eq!(
            names(list_images(&spec("left*")).unwrap()),
            ["left01.jpg", "left02.png"]
        );
        assert_eq!(
            names(list_images(&spec("l?ft0*.jpg")).unwrap()),
            ["left01.jpg"]
        );
        assert_eq!(
            names(list_images(&spec("left**.jpg")).unwrap()),
            ["left01.jpg"]
        );
        assert_eq!(
            names(list_images(&dir.display().to_string()).unwrap()),
            ["left01.jpg", "left02.png", "right01.jpg"]
        );
        fs::write(dir.join("img[1].png"), b"x").unwrap();
        assert_eq!(
            names(list_images(&spec("img[1]*")).unwrap()),
            ["img[1].png"]
        );
        for (bad, why) in [
            ("left?.jpg", "no images found"),
            (
                "*/left01.jpg",
                "wildcards are supported in the file name only",
            ),
            ("missing.jpg", "no such folder or file"),
        ] {
            let e = list_images(&spec(bad)).unwrap_err();
            assert!(
                matches!(e, InputError::NoFiles { why: w, .. } if w == why),
                "{e}"
            );
        }
        let _ = fs::remove_dir_all(&dir);
    }
}
