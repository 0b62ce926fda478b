//! What `ergocell review`, `ergocell report` and `ergocell exposure` say on the console and on a page
//! about the recordings: one line per session reviewed, the other sessions of a recording of several,
//! the report written, each recording `exposure` read and what it wrote.
//!
//! Kept beside the types they describe ([`ReviewData`], [`Recording`], [`SessionBrief`],
//! [`StreamedRecording`]) so the binary only prints them; the few conversions (nanoseconds to
//! seconds, bytes to megabytes) are made here. No I/O.

use ergocell_bridge::msg::PostureWarning;
use ergocell_ergonomics::height_text::rula_cost_clause;

use crate::analysis::{secs, ReviewData, SessionReview};
use crate::exposure::{ExposureSet, StreamedRecording};
use crate::overview::SessionBrief;
use crate::read::{Recording, SessionPart};

/// The label of session `session` of a recording of `count` sessions, the file called `name`.
pub fn session_label(name: &str, session: usize, count: usize) -> String {
    format!("{name} · session {session}/{count}")
}

/// What a page of one of several sessions says about the others (`listing`: each session
/// described, [`parts_listing`] or [`briefs_listing`]).
pub fn sessions_note(count: usize, listing: &str, session: usize) -> String {
    format!(
        "this recording holds {count} operator sessions ({listing}); this page shows session {session} (--session N picks another)"
    )
}

/// The label and the note of the page of session `session` of a recording of `count` sessions,
/// the file called `name`: the name alone for a recording of one session, else [`session_label`]
/// and [`sessions_note`] (`listing` describes the sessions: [`parts_listing`] or
/// [`briefs_listing`]).
pub fn session_page(
    name: &str,
    session: usize,
    count: usize,
    listing: impl FnOnce() -> String,
) -> (String, Option<String>) {
    if count > 1 {
        let note = sessions_note(count, &listing(), session);
        (session_label(name, session, count), Some(note))
    } else {
        (name.to_owned(), None)
    }
}

/// One line on an operator session: frames, class and height (metres), duration (seconds).
pub fn describe_session(frames: usize, class: Option<(&str, f64)>, secs: f64) -> String {
    let class = class.map_or_else(
        || "no class decided".to_owned(),
        |(c, h)| format!("{c} at {h:.3} m"),
    );
    format!("{frames} frames, {class}, {secs:.0} s")
}

/// The duration of a recording (or a session of one, read whole), seconds: from its first
/// message's log time to its last; 0 when it has none.
pub fn recording_secs(r: &Recording) -> f64 {
    let t0 = r.first_log_time_nanos.unwrap_or(0);
    r.last_log_time_nanos.map_or(0.0, |t| secs(t, t0))
}

/// [`describe_session`] of a session read whole: its poses, the class last decided in it, its
/// duration.
pub fn describe_recording(r: &Recording) -> String {
    let decided = r
        .states
        .iter()
        .rev()
        .find(|s| !s.message.height_class.is_empty())
        .map(|s| (s.message.height_class.as_str(), s.message.height_m));
    describe_session(r.poses.len(), decided, recording_secs(r))
}

/// The sessions of a recording read whole, each numbered and described: `1: …; 2: …`.
pub fn parts_listing(parts: &[SessionPart]) -> String {
    parts
        .iter()
        .map(|p| format!("{}: {}", p.number, describe_recording(&p.recording)))
        .collect::<Vec<_>>()
        .join("; ")
}

/// The sessions of an overview's plan, numbered from 1 and described: `1: …; 2: …`.
pub fn briefs_listing(briefs: &[SessionBrief]) -> String {
    briefs
        .iter()
        .enumerate()
        .map(|(k, b)| {
            let class = b.class.as_ref().map(|(c, h)| (c.as_str(), *h));
            format!("{}: {}", k + 1, describe_session(b.frames, class, b.secs))
        })
        .collect::<Vec<_>>()
        .join("; ")
}

/// The warnings raised in a session (not those changed or cleared).
pub fn warnings_raised(s: &SessionReview) -> usize {
    s.warnings
        .iter()
        .filter(|w| w.kind == PostureWarning::RAISED)
        .count()
}

/// One session reviewed in a line: frames recorded (and those the page holds, for an overview),
/// duration, warnings raised, the mean posture cost, height, class and how it was decided, and
/// whether the file was complete.
pub fn session_line(s: &SessionReview) -> String {
    format!(
        "{}: {} frames over {:.1} s{}, {} warnings{}, height {}, class {}{}{}",
        s.label,
        s.overview
            .as_ref()
            .map_or(s.frames.t.len(), |o| o.frames_recorded),
        s.frames.t.last().copied().unwrap_or(0.0),
        s.overview.as_ref().map_or(String::new(), |o| format!(
            " (the page holds {}: the overview)",
            o.frames_kept
        )),
        warnings_raised(s),
        s.summary
            .posture_cost
            .mean()
            .map_or(String::new(), |c| format!(", mean posture cost {c:.3}")),
        s.facts
            .height_m
            .map_or("not measured".to_owned(), |h| format!("{h:.3} m")),
        s.facts.height_class.as_deref().unwrap_or("none"),
        match (&s.facts.decision_basis, s.facts.class_probability) {
            (Some(b), Some(p)) => format!(
                " ({b}, probability {p:.2}{})",
                rula_cost_clause(s.facts.expected_rula_cost)
            ),
            _ => String::new(),
        },
        if s.source.complete {
            ""
        } else {
            " (incomplete file)"
        }
    )
}

/// Every session of the page, a [`session_line`] each, one per line (no newline at the end).
pub fn summary_text(data: &ReviewData) -> String {
    data.sessions
        .iter()
        .map(session_line)
        .collect::<Vec<_>>()
        .join("\n")
}

/// Bytes as megabytes (10⁶ bytes).
pub fn megabytes(bytes: usize) -> f64 {
    bytes as f64 / 1e6
}

/// The line `ergocell report` ends with: the file written (`out`) and its size.
pub fn report_line(out: &str, html_bytes: usize) -> String {
    format!(
        "report: {out} ({:.1} MB, self-contained: opens offline in any browser)",
        megabytes(html_bytes)
    )
}

/// `ergocell exposure`'s line on a recording read (`label`: as the user named it): its sessions,
/// its messages, and whether it was complete.
pub fn recording_read_line(label: &str, r: &StreamedRecording) -> String {
    format!(
        "  {label}: {} session(s), {} messages{}",
        r.sessions,
        r.stats.messages,
        if r.stats.complete {
            ""
        } else {
            " (incomplete)"
        }
    )
}

/// What `ergocell exposure` warns of about a recording read: each problem of the file, and the poses
/// that came too late for the task segments.
pub fn recording_notes(r: &StreamedRecording) -> Vec<String> {
    let mut notes: Vec<String> = r
        .stats
        .problems
        .iter()
        .map(|p| format!("    {p}"))
        .collect();
    if r.late_poses > 0 {
        notes.push(format!(
            "    {} operator pose(s) arrived more than {} messages out of capture order and were not read for the task segments",
            r.late_poses,
            crate::exposure::REORDER_WINDOW
        ));
    }
    notes
}

/// The line `ergocell exposure` ends with: what was read and left out, and where each file went
/// (`files`: the paths of [`crate::exposure::FILES`], in that order).
pub fn exposure_done_line(set: &ExposureSet, files: &[String; 4]) -> String {
    format!(
        "exposure: {} recording(s), {} session(s){}; {} groups → {} (and {}), {} session rows → {} and {}",
        set.recordings,
        set.sessions,
        if set.failed > 0 {
            format!(", {} left out", set.failed)
        } else {
            String::new()
        },
        set.table.groups.len(),
        files[0],
        files[3],
        set.rows.len(),
        files[1],
        files[2]
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_recording_lasts_from_its_first_message_to_its_last() {
        let r = Recording {
            first_log_time_nanos: Some(2_000_000_000),
            last_log_time_nanos: Some(14_500_000_000),
            ..Recording::default()
        };
        assert!((recording_secs(&r) - 12.5).abs() < 1e-12);
        let empty = Recording::default();
        assert_eq!(recording_secs(&empty), 0.0);
        // Without a first time, from the epoch of the log clock.
        let no_first = Recording {
            last_log_time_nanos: Some(3_000_000_000),
            ..Recording::default()
        };
        assert!((recording_secs(&no_first) - 3.0).abs() < 1e-12);
    }

    #[test]
    fn megabytes_are_a_million_bytes() {
        assert_eq!(megabytes(0), 0.0);
        assert_eq!(megabytes(2_500_000), 2.5);
        assert_eq!(megabytes(1), 1e-6);
    }

    #[test]
    fn an_overview_plan_lists_its_sessions_numbered_from_one() {
        let briefs = [
            SessionBrief {
                frames: 10,
                class: Some(("c2".to_owned(), 1.7)),
                secs: 12.4,
            },
            SessionBrief::default(),
        ];
        let listing = briefs_listing(&briefs);
        let numbers: Vec<usize> = listing
            .split("; ")
            .map(|item| item.split_once(':').unwrap().0.parse().unwrap())
            .collect();
        assert_eq!(numbers, [1, 2]);
        assert_eq!(
            listing,
            "1: 10 frames, c2 at 1.700 m, 12 s; 2: 0 frames, no class decided, 0 s"
        );
    }
}
