//! The session recordings `ergocell review` and `ergocell report` read on this machine: a
//! recording read whole, bounded as a [`Kind::Recording`], or a long one streamed twice from disk
//! into an overview ([`ergocell_review::overview`]: its numbers over every frame, its page the worst
//! moments and a thinned rest), which of the two by what was asked and the file's size.
//!
//! Reading, sessions and analysis are `ergocell_review`'s (no I/O there); here are the files. What
//! a review says about its recording is handed back ([`Loaded`]) for the caller to tell; a
//! recording that cannot be reviewed as asked is an [`InputError::Recording`], bad input.

use std::fs::File;
use std::io::BufReader;
use std::path::{Path, PathBuf};

use ergocell_review::overview::{self, Budget};
use ergocell_review::read::{holds_session, pick_session};
use ergocell_review::{analyse, read_recording, text, Recording, ReviewError, SessionReview};

use crate::input::{self, InputError, Kind};

/// [`PageFrames::Auto`] shows the overview from this size of recording on (about 50 minutes of a
/// session).
pub const OVERVIEW_FROM_BYTES: u64 = 256 << 20;

/// Which frames a review's page holds.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum PageFrames {
    /// The overview from [`OVERVIEW_FROM_BYTES`] on or with windows, else every frame.
    Auto,
    /// Every frame (the recording read whole).
    All,
    /// The overview.
    Overview,
}

/// One recording to review.
#[derive(Debug, Clone)]
pub struct Request<'a> {
    pub path: &'a Path,
    /// The operator session, 1-based.
    pub session: usize,
    pub frames: PageFrames,
    /// The overview's frames.
    pub budget: Budget,
    /// Spans kept whole in the overview, seconds on the page's clock (`FROM..TO`).
    pub windows: &'a [[f64; 2]],
}

/// A recording's session reviewed.
#[derive(Debug)]
pub struct Loaded {
    pub review: SessionReview,
    /// The session's messages, when the recording was read whole (not for an overview).
    pub recording: Option<Recording>,
    /// How the overview thinned the page, when it did.
    pub thinned: Option<Thinned>,
}

/// The frames an overview's page holds of those recorded.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Thinned {
    pub kept: usize,
    pub recorded: usize,
}

/// Why a recording cannot be reviewed as asked (inside [`InputError::Recording`]: bad input).
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum RecordingError {
    /// Not a recording `ergocell_review` can read.
    #[error("{}: {error}", path.display())]
    Unreadable { path: PathBuf, error: ReviewError },
    /// `--session` names a session the recording does not hold.
    #[error("{}: --session {session}: the recording holds {count} operator session(s)", path.display())]
    NoSuchSession {
        path: PathBuf,
        session: usize,
        count: usize,
    },
    /// Windows of an overview asked for with every frame.
    #[error("--window keeps a span of an overview whole: not with --page-frames all (which keeps every frame)")]
    WindowWithAllFrames,
    /// An overview of what cannot be read twice.
    #[error("{}: --page-frames overview reads the recording twice: it must be a regular file", path.display())]
    OverviewNotAFile { path: PathBuf },
}

impl From<RecordingError> for InputError {
    fn from(e: RecordingError) -> Self {
        Self::Recording(Box::new(e))
    }
}

/// Reads the recording of `request` and analyses its session: as an overview when
/// [`overview_wanted`] (and somebody was seen in it), else read whole.
pub fn load(request: &Request<'_>) -> Result<Loaded, InputError> {
    if let Some(loaded) = load_overview(request)? {
        return Ok(loaded);
    }
    let path = request.path;
    let recording = read_recording(&input::read(path, Kind::Recording)?)
        .map_err(|error| unreadable(path, error))?;
    let (label, recording) = pick_session(recording, request.session, &file_name(path))
        .map_err(|count| no_such_session(request, count))?;
    Ok(Loaded {
        review: analyse(&recording, &label),
        recording: Some(recording),
        thinned: None,
    })
}

/// Whether `request` asks for an overview: `all` never (and not with windows), `overview` always,
/// `auto` with windows or from [`OVERVIEW_FROM_BYTES`] on. An overview of what is not a regular
/// file is refused; one of a file over the recordings' size limit is left to the whole-file
/// reader, which says so.
pub fn overview_wanted(request: &Request<'_>) -> Result<bool, RecordingError> {
    let meta = std::fs::metadata(request.path)
        .ok()
        .filter(std::fs::Metadata::is_file);
    let windows = !request.windows.is_empty();
    let wanted = match request.frames {
        PageFrames::All if windows => return Err(RecordingError::WindowWithAllFrames),
        PageFrames::All => false,
        PageFrames::Overview => true,
        PageFrames::Auto => {
            windows
                || meta
                    .as_ref()
                    .is_some_and(|m| m.len() >= OVERVIEW_FROM_BYTES)
        }
    };
    if !wanted {
        return Ok(false);
    }
    let Some(meta) = meta else {
        return Err(RecordingError::OverviewNotAFile {
            path: request.path.to_owned(),
        });
    };
    Ok(meta.len() <= Kind::Recording.limit_bytes())
}

/// The overview of the session (read twice, streamed), when [`overview_wanted`]; `None` when the
/// recording is to be read whole, or when nobody was seen in it (nothing to thin, and the
/// whole-file reader says what the file holds).
fn load_overview(request: &Request<'_>) -> Result<Option<Loaded>, InputError> {
    if !overview_wanted(request)? {
        return Ok(None);
    }
    let path = request.path;
    let open = || -> Result<BufReader<File>, InputError> {
        let (file, _) = input::open(path)?;
        Ok(BufReader::with_capacity(1 << 20, file))
    };
    let plan = overview::plan(open()?, request.session, request.budget, request.windows)
        .map_err(|error| unreadable(path, error))?;
    let count = plan.sessions();
    if count == 0 {
        return Ok(None);
    }
    if !holds_session(count, request.session) {
        return Err(no_such_session(request, count).into());
    }
    let (label, note) = text::session_page(&file_name(path), request.session, count, || {
        text::briefs_listing(plan.briefs())
    });
    let thinned = Thinned {
        kept: plan.frames_kept(),
        recorded: plan.frames_recorded(),
    };
    let review = overview::analyse_planned(open()?, plan, &label, note)
        .map_err(|error| unreadable(path, error))?;
    Ok(Some(Loaded {
        thinned: review.overview.is_some().then_some(thinned),
        review,
        recording: None,
    }))
}

fn unreadable(path: &Path, error: ReviewError) -> RecordingError {
    RecordingError::Unreadable {
        path: path.to_owned(),
        error,
    }
}

fn no_such_session(request: &Request<'_>, count: usize) -> RecordingError {
    RecordingError::NoSuchSession {
        path: request.path.to_owned(),
        session: request.session,
        count,
    }
}

/// The recording's file name, its page's label.
fn file_name(path: &Path) -> String {
    path.file_name().map_or_else(
        || path.display().to_string(),
        |n| n.to_string_lossy().into_owned(),
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::fs;

    fn request<'a>(path: &'a Path, frames: PageFrames, windows: &'a [[f64; 2]]) -> Request<'a> {
        Request {
            path,
            session: 1,
            frames,
            budget: Budget::default(),
            windows,
        }
    }

    /// Why a recording was refused.
    fn why(e: &InputError) -> &RecordingError {
        match e {
            InputError::Recording(why) => why,
            _ => panic!("not a refusal of a recording: {e}"),
        }
    }

    fn folder(name: &str) -> PathBuf {
        let dir =
            std::env::temp_dir().join(format!("ergocell-recordings-{name}-{}", std::process::id()));
        let _ = fs::remove_dir_all(&dir);
        fs::create_dir_all(&dir).unwrap();
        dir
    }

    /// `all` never thins (and refuses windows), `overview` always (of a regular file only),
    /// `auto` with windows or from the size on.
    #[test]
    fn the_overview_is_wanted_as_asked_and_only_of_a_regular_file() {
        let dir = folder("wanted");
        let small = dir.join("small.mcap");
        fs::write(&small, b"x").unwrap();
        let window = [[1.0, 2.0]];
        let wanted = |path: &Path, frames, windows: &[[f64; 2]]| {
            overview_wanted(&request(path, frames, windows))
        };
        assert!(!wanted(&small, PageFrames::All, &[]).unwrap());
        assert!(matches!(
            wanted(&small, PageFrames::All, &window),
            Err(RecordingError::WindowWithAllFrames)
        ));
        assert!(wanted(&small, PageFrames::Overview, &[]).unwrap());
        assert!(!wanted(&small, PageFrames::Auto, &[]).unwrap());
        assert!(wanted(&small, PageFrames::Auto, &window).unwrap());
        let big = dir.join("big.mcap");
        // A sparse file: its length, not its blocks, is what counts.
        fs::File::create(&big)
            .unwrap()
            .set_len(OVERVIEW_FROM_BYTES)
            .unwrap();
        assert!(wanted(&big, PageFrames::Auto, &[]).unwrap());
        assert!(!wanted(&dir.join("missing.mcap"), PageFrames::Auto, &[]).unwrap());
        for not_a_file in [dir.clone(), dir.join("missing.mcap")] {
            let e = wanted(&not_a_file, PageFrames::Overview, &[]).unwrap_err();
            assert!(e.to_string().ends_with("it must be a regular file"), "{e}");
        }
        let _ = fs::remove_dir_all(&dir);
    }

    /// What is not a recording, and a session a recording does not hold, are bad input naming the
    /// file; a recording cut short is read whole up to the cut.
    #[test]
    fn a_recording_is_read_whole_or_refused_by_name() {
        let dir = folder("load");
        let text_file = dir.join("notes.mcap");
        fs::write(&text_file, b"not a recording").unwrap();
        let e = load(&request(&text_file, PageFrames::All, &[])).unwrap_err();
        assert!(matches!(why(&e), RecordingError::Unreadable { .. }), "{e}");
        assert!(
            e.to_string()
                .starts_with(&format!("{}: ", text_file.display())),
            "{e}"
        );
        let e = load(&request(&dir.join("missing.mcap"), PageFrames::All, &[])).unwrap_err();
        assert!(e.is_not_found(), "{e}");
        // The first 64 kB of a demo recording: one complete chunk, then the cut.
        let cut = Path::new(concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/../fuzz/corpus/mcap_recording/seed_demo_prefix_64k.mcap"
        ));
        let loaded = load(&request(cut, PageFrames::All, &[])).unwrap();
        assert!(loaded.thinned.is_none());
        assert!(loaded.recording.is_some_and(|r| !r.complete));
        let second = Request {
            session: 2,
            ..request(cut, PageFrames::All, &[])
        };
        let e = load(&second).unwrap_err();
        assert!(
            matches!(why(&e), RecordingError::NoSuchSession { session: 2, .. }),
            "{e}"
        );
        let _ = fs::remove_dir_all(&dir);
    }
}
