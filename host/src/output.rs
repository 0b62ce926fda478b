//! Files the user names as outputs (`--out`, `--record`): an existing file is never overwritten
//! unless asked (`--force`), and an output that is one of the command's inputs is refused, `--force`
//! or not. Both checks run before the command does any work; the file itself is then created with
//! [`create`], which without `--force` refuses a file that appeared in the meantime.
//!
//! Only a regular file or a path that does not exist yet is an output: a device (`/dev/full`,
//! `/dev/sda`), a named pipe or a socket is refused, `--force` or not. A forced write replaces the
//! path by a new file, so as root it would have replaced the device node itself.

use std::fs::File;
use std::io::Write as _;
use std::path::Path;

/// Why an output cannot be written.
#[derive(Debug, thiserror::Error)]
pub enum OutputError {
    /// The output is refused (it exists, it is an input, a device, a folder, …): the user's to
    /// change, as bad input is (the binary's exit code 2).
    #[error("{0}")]
    Refused(String),
    /// The file system failed while `what` was being done.
    #[error("{what}")]
    Io {
        what: String,
        #[source]
        source: std::io::Error,
    },
}

impl OutputError {
    fn io(what: String, source: std::io::Error) -> Self {
        Self::Io { what, source }
    }

    /// The output was refused (bad input), not failed.
    pub fn is_refusal(&self) -> bool {
        matches!(self, Self::Refused(_))
    }
}

/// Shorthand for this module's results.
pub type Result<T, E = OutputError> = std::result::Result<T, E>;

/// Checks the output `out` (given with `flag`, e.g. `--out`) against `inputs` (`(flag, path)`) and,
/// unless `force`, against an existing file.
pub fn check(flag: &str, out: &Path, force: bool, inputs: &[(&str, &Path)]) -> Result<()> {
    check_file(flag, out, force, inputs, true)
}

/// [`check`] for a file in a folder the command creates itself (`exposure --out FOLDER`): its
/// folder need not exist yet.
pub fn check_in_new_folder(
    flag: &str,
    out: &Path,
    force: bool,
    inputs: &[(&str, &Path)],
) -> Result<()> {
    check_file(flag, out, force, inputs, false)
}

fn check_file(
    flag: &str,
    out: &Path,
    force: bool,
    inputs: &[(&str, &Path)],
    folder_must_exist: bool,
) -> Result<()> {
    for (input_flag, input) in inputs {
        if same_file(out, input) {
            return Err(OutputError::Refused(format!(
                "{flag} {} is also an input ({input_flag} {}): writing it would destroy the input, --force or not; choose another output file",
                out.display(),
                input.display()
            )));
        }
    }
    not_a_regular_file(flag, out)?;
    // A new file in a folder that does not exist: said now, as bad input, not when the work is done.
    if let Some(parent) = out
        .parent()
        .filter(|p| folder_must_exist && !p.as_os_str().is_empty())
    {
        if std::fs::metadata(out).is_err() && !parent.is_dir() {
            return Err(OutputError::Refused(format!(
                "{flag} {}: the folder {} does not exist; create it first (mkdir -p {})",
                out.display(),
                parent.display(),
                parent.display()
            )));
        }
    }
    match std::fs::metadata(out) {
        Ok(m) if m.is_dir() => Err(OutputError::Refused(format!(
            "{flag} {} is a folder, not a file",
            out.display()
        ))),
        Ok(_) if !force => Err(OutputError::Refused(format!(
            "{flag} {}: the file already exists; pass --force to overwrite it, or choose another file",
            out.display()
        ))),
        _ => Ok(()),
    }
}

/// Refuses an existing output that is not a regular file (or a folder, which [`check`] names):
/// a device, a named pipe, a socket — through a symlink too.
fn not_a_regular_file(flag: &str, out: &Path) -> Result<()> {
    use std::os::unix::fs::FileTypeExt as _;
    let Ok(meta) = std::fs::metadata(out) else {
        return Ok(());
    };
    let t = meta.file_type();
    let what = if t.is_char_device() || t.is_block_device() {
        "a device"
    } else if t.is_fifo() {
        "a named pipe"
    } else if t.is_socket() {
        "a socket"
    } else {
        return Ok(());
    };
    Err(OutputError::Refused(format!(
        "{flag} {} is {what}, not a file: only a regular file or a new path is an output, --force or not",
        out.display()
    )))
}

/// True if `a` and `b` name the same file, existing or not: the same existing file
/// ([`same_file`]), or the same name in the same (existing) folder (`r.html` and `./r.html`, or
/// `out/../r.html`). For two outputs of one command, neither of which need exist yet.
pub fn same_path(a: &Path, b: &Path) -> bool {
    if same_file(a, b) {
        return true;
    }
    let key = |p: &Path| {
        let name = p.file_name()?;
        let parent = match p.parent() {
            Some(d) if !d.as_os_str().is_empty() => d,
            _ => Path::new("."),
        };
        Some(std::fs::canonicalize(parent).ok()?.join(name))
    };
    match (key(a), key(b)) {
        (Some(x), Some(y)) => x == y,
        _ => a == b,
    }
}

/// True if `a` and `b` name the same existing file (canonical paths, or on Unix the same device
/// and inode: a hard link or a symlink to it).
pub fn same_file(a: &Path, b: &Path) -> bool {
    if let (Ok(x), Ok(y)) = (std::fs::canonicalize(a), std::fs::canonicalize(b)) {
        if x == y {
            return true;
        }
    }
    #[cfg(unix)]
    {
        use std::os::unix::fs::MetadataExt as _;
        if let (Ok(x), Ok(y)) = (std::fs::metadata(a), std::fs::metadata(b)) {
            return x.dev() == y.dev() && x.ino() == y.ino();
        }
    }
    false
}

/// Creates the output file: truncates an existing one only with `force`, and otherwise refuses a
/// file that exists now (created since [`check`]).
pub fn create(flag: &str, out: &Path, force: bool) -> Result<File> {
    use std::os::unix::fs::OpenOptionsExt as _;
    not_a_regular_file(flag, out)?;
    let mut options = std::fs::OpenOptions::new();
    // Non-blocking: a named pipe put there since the check is not waited on (and refused below).
    options
        .write(true)
        .custom_flags(crate::input::nonblocking_flag());
    if force {
        options.create(true).truncate(true);
    } else {
        options.create_new(true);
    }
    let file = options.open(out).map_err(|e| {
        if e.kind() == std::io::ErrorKind::AlreadyExists {
            OutputError::Refused(format!(
                "{flag} {}: the file already exists; pass --force to overwrite it, or choose another file",
                out.display()
            ))
        } else {
            OutputError::io(format!("cannot create {}", out.display()), e)
        }
    })?;
    let meta = file
        .metadata()
        .map_err(|e| OutputError::io(format!("cannot create {}", out.display()), e))?;
    if !meta.is_file() {
        return Err(OutputError::Refused(format!(
            "{flag} {} is not a regular file: only a regular file or a new path is an output",
            out.display()
        )));
    }
    crate::input::set_blocking(&file)
        .map_err(|e| OutputError::io(format!("cannot create {}", out.display()), e))?;
    Ok(file)
}

/// An output written piece by piece into a temporary file beside it (`.<name>.partial-<pid>`),
/// which [`Partial::finish`] moves onto the output: until then an existing output is untouched,
/// and a run that fails or is stopped leaves no half-written file (the temporary one is removed
/// when dropped unfinished). Without `force`, an output that appeared meanwhile is not replaced.
#[derive(Debug)]
pub struct Partial {
    flag: String,
    out: std::path::PathBuf,
    temp: std::path::PathBuf,
    file: Option<std::io::BufWriter<File>>,
    force: bool,
}

impl Partial {
    /// Creates the temporary file (and checks, as [`create`] does, that without `force` the output
    /// does not exist yet).
    pub fn create(flag: &str, out: &Path, force: bool) -> Result<Self> {
        not_a_regular_file(flag, out)?;
        if !force && std::fs::symlink_metadata(out).is_ok() {
            return Err(OutputError::Refused(format!(
                "{flag} {}: the file already exists; pass --force to overwrite it, or choose another file",
                out.display()
            )));
        }
        let name = out
            .file_name()
            .map_or_else(|| "output".into(), |n| n.to_string_lossy().into_owned());
        let temp = out.with_file_name(format!(".{name}.partial-{}", std::process::id()));
        let file = std::fs::OpenOptions::new()
            .write(true)
            .create_new(true)
            .open(&temp)
            .map_err(|e| OutputError::io(format!("cannot create {}", temp.display()), e))?;
        Ok(Self {
            flag: flag.to_owned(),
            out: out.to_owned(),
            temp,
            file: Some(std::io::BufWriter::new(file)),
            force,
        })
    }

    /// Appends bytes.
    pub fn write(&mut self, bytes: &[u8]) -> Result<()> {
        match self.file.as_mut() {
            Some(f) => f
                .write_all(bytes)
                .map_err(|e| OutputError::io(format!("cannot write {}", self.temp.display()), e)),
            None => Ok(()),
        }
    }

    /// Flushes and moves the temporary file onto the output.
    pub fn finish(mut self) -> Result<()> {
        let Some(file) = self.file.take() else {
            return Ok(());
        };
        let file = file.into_inner().map_err(|e| {
            OutputError::io(
                format!("cannot write {}", self.temp.display()),
                e.into_error(),
            )
        })?;
        file.sync_all()
            .map_err(|e| OutputError::io(format!("cannot write {}", self.temp.display()), e))?;
        drop(file);
        if self.force {
            // A device or pipe put at the output meantime is not replaced by the rename.
            if let Err(e) = not_a_regular_file(&self.flag, &self.out) {
                let _ = std::fs::remove_file(&self.temp);
                return Err(e);
            }
            std::fs::rename(&self.temp, &self.out).map_err(|e| {
                OutputError::io(
                    format!("cannot move the output to {}", self.out.display()),
                    e,
                )
            })?;
        } else {
            // a hard link fails if the output appeared meanwhile: never replaced unasked
            if let Err(e) = std::fs::hard_link(&self.temp, &self.out) {
                let _ = std::fs::remove_file(&self.temp);
                if e.kind() == std::io::ErrorKind::AlreadyExists {
                    return Err(OutputError::Refused(format!(
                        "{} {}: the file appeared while it was being written; pass --force to overwrite it, or choose another file",
                        self.flag,
                        self.out.display()
                    )));
                }
                return Err(OutputError::io(
                    format!("cannot create {}", self.out.display()),
                    e,
                ));
            }
            let _ = std::fs::remove_file(&self.temp);
        }
        sync_parent(&self.out)
    }

    /// Removes the temporary file; the output stays as it was.
    pub fn discard(&mut self) {
        if self.file.take().is_some() {
            let _ = std::fs::remove_file(&self.temp);
        }
    }
}

impl Drop for Partial {
    fn drop(&mut self) {
        self.discard();
    }
}

/// Writes `bytes` to the output file atomically ([`Partial`]: a temporary file beside it, synced,
/// then moved onto it, and the folder synced): a full disk, a kill or a power cut leaves the previous
/// file as it was, never a cut one.
pub fn write(flag: &str, out: &Path, force: bool, bytes: &[u8]) -> Result<()> {
    let mut partial = Partial::create(flag, out, force)?;
    partial.write(bytes)?;
    partial.finish()
}

/// Replaces the project file `path` (a lock, an approvals file) with `bytes` atomically, as
/// [`write()`] does with `--force`: the previous file stays whole until the new one is complete.
pub fn replace(path: &Path, bytes: &[u8]) -> Result<()> {
    write("", path, true, bytes)
}

/// Syncs the folder of `path`, so that a rename into it survives a power cut.
fn sync_parent(path: &Path) -> Result<()> {
    let dir = match path.parent() {
        Some(d) if !d.as_os_str().is_empty() => d,
        _ => Path::new("."),
    };
    File::open(dir)
        .and_then(|d| d.sync_all())
        .map_err(|e| OutputError::io(format!("cannot sync the folder {}", dir.display()), e))
}

/// `default_name`'s stem and its extension with the dot (`ergocell-demo`, `.mcap`), for the
/// numbered names `<stem>-2<ext>`, ….
fn stem_and_ext(default_name: &Path) -> (String, String) {
    let stem = default_name
        .file_stem()
        .map_or_else(String::new, |s| s.to_string_lossy().into_owned());
    let ext = default_name
        .extension()
        .map(|e| format!(".{}", e.to_string_lossy()))
        .unwrap_or_default();
    (stem, ext)
}

/// Creates the first free name of `default_name` in its folder — itself, then `<stem>-2.<ext>`, … —
/// with `create_new`, so that two commands started together never take the same name (one that
/// appears between the look and the creation is passed over): the file and its path.
pub fn create_next_free(default_name: &Path) -> Result<(File, std::path::PathBuf)> {
    let (stem, ext) = stem_and_ext(default_name);
    for n in 1..10_000 {
        let candidate = if n == 1 {
            default_name.to_owned()
        } else {
            default_name.with_file_name(format!("{stem}-{n}{ext}"))
        };
        match std::fs::OpenOptions::new()
            .write(true)
            .create_new(true)
            .open(&candidate)
        {
            Ok(file) => return Ok((file, candidate)),
            Err(e) if e.kind() == std::io::ErrorKind::AlreadyExists => {}
            Err(e) => {
                return Err(OutputError::io(
                    format!("cannot create {}", candidate.display()),
                    e,
                ))
            }
        }
    }
    Err(OutputError::Refused(format!(
        "{} and {stem}-2{ext} … {stem}-9999{ext} all exist: name the file with --out",
        default_name.display()
    )))
}

/// The first free name of `default_name` in its folder: itself, then `<stem>-2.<ext>`, `-3`, … (the
/// demo's default recording, so running the README's first command twice keeps the first session).
pub fn next_free(default_name: &Path) -> Result<std::path::PathBuf> {
    if std::fs::symlink_metadata(default_name).is_err() {
        return Ok(default_name.to_owned());
    }
    let (stem, ext) = stem_and_ext(default_name);
    for n in 2..10_000 {
        let candidate = default_name.with_file_name(format!("{stem}-{n}{ext}"));
        if std::fs::symlink_metadata(&candidate).is_err() {
            return Ok(candidate);
        }
    }
    Err(OutputError::Refused(format!(
        "{} and {stem}-2{ext} … {stem}-9999{ext} all exist: name the recording with --out",
        default_name.display()
    )))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A device or a named pipe is never an output, `--force` or not, and is left as it was.
    #[test]
    fn a_device_or_a_pipe_is_not_an_output() {
        for force in [false, true] {
            assert!(check("--out", Path::new("/dev/null"), force, &[]).is_err());
            assert!(Partial::create("--out", Path::new("/dev/null"), force).is_err());
            assert!(create("--out", Path::new("/dev/null"), force).is_err());
            assert!(write("--out", Path::new("/dev/full"), force, b"x").is_err());
        }
        assert!(std::fs::metadata("/dev/null").is_ok_and(|m| !m.is_file()));
        let dir = std::env::temp_dir().join(format!("ergocell-out-fifo-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).unwrap();
        let fifo = dir.join("pipe");
        if std::process::Command::new("mkfifo")
            .arg(&fifo)
            .status()
            .is_ok_and(|s| s.success())
        {
            // create() used to block here waiting for a reader; write() used to replace the pipe.
            assert!(create("--out", &fifo, true).is_err());
            assert!(write("--out", &fifo, true, b"x").is_err());
            let kind = std::fs::metadata(&fifo).unwrap().file_type();
            assert!(std::os::unix::fs::FileTypeExt::is_fifo(&kind));
        }
        // A regular file and a new path still are.
        let file = dir.join("r.html");
        write("--out", &file, false, b"a").unwrap();
        write("--out", &file, true, b"b").unwrap();
        assert_eq!(std::fs::read(&file).unwrap(), b"b");
        let _ = std::fs::remove_dir_all(&dir);
    }

    /// Two commands that both looked and found the default free still get two files: the second
    /// creation moves on to the next name.
    #[test]
    fn the_next_free_name_is_taken_atomically() {
        let dir = std::env::temp_dir().join(format!("ergocell-next-free-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).unwrap();
        let default = dir.join("ergocell-demo.mcap");
        assert_eq!(next_free(&default).unwrap(), default);
        let (_a, first) = create_next_free(&default).unwrap();
        let (_b, second) = create_next_free(&default).unwrap();
        let (_c, third) = create_next_free(&default).unwrap();
        assert_eq!(first, default);
        assert_eq!(second, dir.join("ergocell-demo-2.mcap"));
        assert_eq!(third, dir.join("ergocell-demo-3.mcap"));
        let _ = std::fs::remove_dir_all(&dir);
    }
}
