//! A long recording (a shift) reviewed in bounded memory: its numbers over every frame, its page
//! holding the overview and the worst moments.
//!
//! An 8-hour shift records about 860,000 frames. Holding them all, decoded, takes gigabytes, and a
//! page of every frame hundreds of megabytes that a browser parses before it shows anything. So the
//! recording is read twice, front to back, never whole:
//!
//! 1. [`plan`]: every message is reduced as it arrives to what the summary needs — the same
//!    computation as `ergocell exposure` (each pose's task segment and ISO 11226 angles, each frame's
//!    RULA and REBA) — plus every joint angle for the distributions and each frame's action level.
//!    From those it chooses the frames the page holds ([`Plan`]): every frame within the **worst
//!    moments** — each stretch at RULA action level 3 or more and each warning raised, ±
//!    [`WINDOW_MARGIN_S`] — worst first (the highest action level, then the longest) until
//!    [`WINDOW_FRAMES`] (the worst one always, centred, cut to the budget if it is longer);
//!    elsewhere the worst frame (highest action level, then grand score) of each bucket of time,
//!    [`OVERVIEW_FRAMES`] buckets over the recording (a [`Budget`] sets both). Spans the reader
//!    asks for are kept whole besides, outside the budget.
//! 2. [`analyse_planned`]: the chosen frames (and the robot's markers at the same density) are
//!    decoded and kept, the other frames' messages left undecoded, and the review is computed as
//!    for a short recording ([`crate::analysis`]), with the summary, the rows and the angle
//!    distributions of pass 1, i.e. over every frame. [`crate::analysis::Overview`] tells the page which frames it has.
//!
//! A recording with no more frames than the two budgets together keeps every frame. A recording of
//! several operator sessions (`ergocell run --record`) is reviewed one session at a time, numbered
//! and bounded as [`crate::read::split_sessions`] does for a recording read whole ([`plan`]'s
//! `session`).

use std::collections::{BTreeMap, HashSet};
use std::io::Read;

use ergocell_ergonomics::summary::{SessionSummary, DEFAULT_MAX_FRAME_NANOS};

use crate::analysis::{
    analyse_with, round_to, secs, AngleSamples, FrameFacts, Overview, WholeRecording,
};
use crate::exposure::SessionAccumulator;
use crate::read::{stream_recording, Decoded, ReadStats, Recording, Visit, LATE_EVENT_NANOS};
use crate::{ReviewError, SessionReview};

/// Frames outside the worst moments: one per bucket, this many buckets over the recording (at most
/// one per second).
pub const OVERVIEW_FRAMES: usize = 4_000;
/// Frames within the worst moments, at the recorded rate (about 27 minutes at 10 Hz). With
/// [`OVERVIEW_FRAMES`], about 20 MB of page (1 kB a frame).
pub const WINDOW_FRAMES: usize = 16_000;

/// How many frames a page holds ([`OVERVIEW_FRAMES`], [`WINDOW_FRAMES`] by default).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Budget {
    pub overview_frames: usize,
    pub window_frames: usize,
}

impl Default for Budget {
    fn default() -> Self {
        Self {
            overview_frames: OVERVIEW_FRAMES,
            window_frames: WINDOW_FRAMES,
        }
    }
}
/// Each worst moment is kept from this long before it to this long after it, seconds.
pub const WINDOW_MARGIN_S: f64 = 30.0;

fn stamp_of(h: &ergocell_bridge::msg::Header) -> u64 {
    u64::try_from(h.stamp.to_nanos()).unwrap_or(0)
}

/// What the first pass found, and the frames the page will hold.
pub struct Plan {
    stats: ReadStats,
    /// Each operator session of the recording.
    briefs: Vec<SessionBrief>,
    /// The wanted session's range of log time ([`Ranges`]); `None` when it has none (no such
    /// session).
    wanted_range: Option<usize>,
    /// The recording is one session: every message is the session's.
    whole_file: bool,
    /// The session's first and last log time (its page's clock starts at the first).
    session_log: (Option<u64>, Option<u64>),
    summary: SessionSummary,
    /// Each kept frame's facts, by capture stamp.
    facts: BTreeMap<u64, FrameFacts>,
    angles: Vec<crate::analysis::AngleStats>,
    problems: Vec<String>,
    frames_recorded: usize,
    /// Kept frames' capture stamps.
    kept: HashSet<u64>,
    /// Their messages, by topic and log time: pass 2 decodes no other frame message.
    kept_messages: HashSet<(FrameTopic, u64)>,
    /// Kept at the recorded rate: capture-stamp spans, in order, disjoint.
    windows: Vec<(u64, u64)>,
    bucket_nanos: u64,
}

impl Plan {
    /// Operator sessions in the recording, as [`crate::read::split_sessions`] counts them.
    pub fn sessions(&self) -> usize {
        self.briefs.len()
    }
    /// Each operator session: its frames, class and length.
    pub fn briefs(&self) -> &[SessionBrief] {
        &self.briefs
    }
    /// Frames (operator poses) recorded.
    pub fn frames_recorded(&self) -> usize {
        self.frames_recorded
    }
    /// Frames the page will hold.
    pub fn frames_kept(&self) -> usize {
        self.kept.len()
    }
}

/// Which operator session each message of a stream belongs to, as
/// [`crate::read::split_sessions`] divides a recording read whole: ranges of log time, each ending
/// with a `session_ended` (inclusive); a controller event about a leg within [`LATE_EVENT_NANOS`]
/// after an end, before the next leg is sent, is the ended range's (a late answer).
#[derive(Debug, Default)]
struct Ranges {
    /// The current range: the `session_ended` states before this message.
    index: usize,
    /// Each ended range's end (its `session_ended`'s log time).
    ends: Vec<u64>,
    leg_sent_since_end: bool,
}

impl Ranges {
    /// The range of `message`, logged at `t`.
    fn of(&mut self, message: &Decoded, t: u64) -> usize {
        match message {
            Decoded::Trajectory(m) if !m.message.points.is_empty() => {
                self.leg_sent_since_end = true;
            }
            Decoded::ControllerEvent(m)
                if m.message.event_kind()
                    == Some(ergocell_bridge::msg::ControllerEventKind::GoalSent) =>
            {
                self.leg_sent_since_end = true;
            }
            Decoded::ControllerEvent(m) => {
                let late = !m.message.leg.is_empty()
                    && !self.leg_sent_since_end
                    && self
                        .ends
                        .last()
                        .is_some_and(|&end| t <= end.saturating_add(LATE_EVENT_NANOS));
                if late {
                    return self.index - 1;
                }
            }
            _ => {}
        }
        self.index
    }

    /// After a message of the current range: a `session_ended` ends it.
    fn after(&mut self, ended_at: Option<u64>) {
        if let Some(t) = ended_at {
            self.ends.push(t);
            self.index += 1;
            self.leg_sent_since_end = false;
        }
    }
}

fn session_ended_at(message: &Decoded, t: u64) -> Option<u64> {
    match message {
        Decoded::State(m)
            if m.message.state == ergocell_bridge::msg::SessionState::SESSION_ENDED =>
        {
            Some(t)
        }
        _ => None,
    }
}

/// The topics of a frame's messages.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
enum FrameTopic {
    Pose,
    Ergonomics,
    Reba,
}

impl FrameTopic {
    fn of(topic: &str) -> Option<Self> {
        match topic {
            crate::read::topics::OPERATOR_POSE => Some(Self::Pose),
            crate::read::topics::ERGONOMICS => Some(Self::Ergonomics),
            crate::read::topics::REBA => Some(Self::Reba),
            _ => None,
        }
    }
}

/// One operator session of a recording, as the page lists them.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct SessionBrief {
    /// Operator poses recorded in it.
    pub frames: usize,
    /// The class last decided in it, and the height it was decided at, metres.
    pub class: Option<(String, f64)>,
    /// From its first message (after the previous session's end) to its last, seconds.
    pub secs: f64,
}

/// Pass 1's reader: the wanted session's summary accumulator, angles and each frame's action level.
struct FirstPass {
    acc: SessionAccumulator,
    angles: AngleSamples,
    pose_stamps: Vec<u64>,
    /// Per capture stamp of an `ErgonomicState`: (action level, the higher grand score).
    levels: BTreeMap<u64, (u8, u8)>,
    /// Each warning raised: its frame's capture stamp (or log time) and action level.
    raised: Vec<(u64, u8)>,
    /// Each frame message's (topic, capture stamp, log time): pass 2 decodes only the kept ones.
    frame_messages: Vec<(FrameTopic, u64, u64)>,
    ranges: Ranges,
    /// The session wanted, 1-based.
    want: usize,
    /// The range of each operator session, in order.
    operator_ranges: Vec<usize>,
    briefs: Vec<SessionBrief>,
    /// Messages of the current range before its first operator message: the wanted session's if
    /// an operator comes, or the one session's tail if none does after its end.
    pending: Vec<(Decoded, u64)>,
}

impl FirstPass {
    fn wanted_range(&self) -> Option<usize> {
        self.operator_ranges.get(self.want.checked_sub(1)?).copied()
    }

    /// Reads one message of the wanted session.
    fn take(&mut self, message: Decoded, log_time: u64) {
        // Pass 2 chooses a message before decoding it, by the log time the file has.
        let logged = message.logged_nanos();
        let frame = match &message {
            Decoded::Pose(m) => Some((FrameTopic::Pose, &m.message.header)),
            Decoded::Ergonomics(m) => Some((FrameTopic::Ergonomics, &m.message.header)),
            Decoded::Reba(m) => Some((FrameTopic::Reba, &m.message.header)),
            _ => None,
        };
        if let Some((topic, header)) = frame {
            self.frame_messages.push((topic, stamp_of(header), logged));
        }
        match &message {
            Decoded::Pose(m) => {
                // A pose of 33 landmarks is a frame; its angles are counted either way.
                let frame = self.angles.push(&m.message);
                if frame {
                    self.pose_stamps.push(stamp_of(&m.message.header));
                }
            }
            Decoded::Ergonomics(m) => {
                let e = &m.message;
                let grand = |s: &ergocell_bridge::msg::RulaSide| {
                    if s.scored {
                        s.final_score
                    } else {
                        0
                    }
                };
                self.levels.insert(
                    stamp_of(&e.header),
                    (e.action_level, grand(&e.left).max(grand(&e.right))),
                );
            }
            Decoded::Warning(m)
                if m.message.kind == ergocell_bridge::msg::PostureWarning::RAISED =>
            {
                let t = u64::try_from(m.message.header.stamp.to_nanos())
                    .ok()
                    .filter(|&t| t > 0)
                    .unwrap_or(log_time);
                self.raised.push((t, m.message.action_level));
            }
            _ => {}
        }
        match message {
            Decoded::Warning(_) | Decoded::RobotMarkers(_) => {}
            m => self.acc.take(m, log_time),
        }
    }
}

impl Visit for FirstPass {
    fn message(&mut self, message: Decoded) {
        let t = message.log_time_nanos();
        let r = self.ranges.of(&message, t);
        let ended_at = session_ended_at(&message, t);
        let current = r == self.ranges.index;
        if matches!(message, Decoded::Pose(_) | Decoded::Ergonomics(_))
            && current
            && self.operator_ranges.last() != Some(&r)
        {
            // The first operator message of this range: a session.
            self.operator_ranges.push(r);
            self.briefs.push(SessionBrief::default());
            if self.wanted_range() == Some(r) {
                for (m, t) in std::mem::take(&mut self.pending) {
                    self.take(m, t);
                }
            }
            self.pending.clear();
        }
        if let Some(k) = self.operator_ranges.iter().rposition(|&x| x == r) {
            let brief = &mut self.briefs[k];
            match &message {
                Decoded::Pose(_) => brief.frames += 1,
                Decoded::State(m) if !m.message.height_class.is_empty() => {
                    brief.class = Some((m.message.height_class.clone(), m.message.height_m));
                }
                _ => {}
            }
        }
        if self.wanted_range() == Some(r) {
            self.take(message, t);
        } else if current && self.operator_ranges.last() != Some(&r) {
            // No operator in this range yet. Robot markers are not read in pass 1.
            if !matches!(message, Decoded::RobotMarkers(_)) {
                self.pending.push((message, t));
            }
        }
        if ended_at.is_some() {
            self.pending.clear();
        }
        self.ranges.after(ended_at);
    }
}

/// Pass 1 (see the module docs): reads `source` through and plans a page of operator session
/// `session` (1-based, as [`crate::read::split_sessions`] numbers them; the whole recording when it
/// holds one) of at most `budget`'s frames, and besides them every frame within `keep_s` (spans in
/// seconds from the session's first message, the page's clock).
///
/// # Errors
/// As [`stream_recording`].
pub fn plan<R: Read + Send>(
    source: R,
    session: usize,
    budget: Budget,
    keep_s: &[[f64; 2]],
) -> Result<Plan, ReviewError> {
    let mut first = FirstPass {
        acc: SessionAccumulator::new(None),
        angles: AngleSamples::default(),
        pose_stamps: Vec::new(),
        levels: BTreeMap::new(),
        raised: Vec::new(),
        frame_messages: Vec::new(),
        ranges: Ranges::default(),
        want: session,
        operator_ranges: Vec::new(),
        briefs: Vec::new(),
        pending: Vec::new(),
    };
    let stats = stream_recording(source, &mut first)?;
    let wanted_range = first.wanted_range();
    // One session, then nothing but the robot and the states after its end: the whole recording
    // is the session (as split_sessions reads it).
    let whole_file = first.operator_ranges.is_empty()
        || first.ranges.ends.is_empty()
        || (first.ranges.ends.len() == 1 && first.operator_ranges == [0]);
    if whole_file && wanted_range.is_some() {
        for (m, t) in std::mem::take(&mut first.pending) {
            first.take(m, t);
        }
    }
    let ends = std::mem::take(&mut first.ranges.ends);
    let range_log = |r: usize| {
        (
            r.checked_sub(1)
                .and_then(|k| ends.get(k))
                .map_or(stats.first_log_time_nanos, |&end| Some(end + 1)),
            ends.get(r).copied().or(stats.last_log_time_nanos),
        )
    };
    let mut briefs = std::mem::take(&mut first.briefs);
    for (brief, &r) in briefs.iter_mut().zip(&first.operator_ranges) {
        let (a, b) = if whole_file {
            (stats.first_log_time_nanos, stats.last_log_time_nanos)
        } else {
            range_log(r)
        };
        brief.secs = secs(b.unwrap_or(0), a.unwrap_or(0));
    }
    let (session_first_log, session_last_log) = match wanted_range {
        Some(r) if !whole_file => range_log(r),
        _ => (stats.first_log_time_nanos, stats.last_log_time_nanos),
    };
    let FirstPass {
        mut acc,
        angles,
        mut pose_stamps,
        levels,
        raised,
        frame_messages,
        ..
    } = first;
    // The review's clock: seconds from the session's first message.
    acc.first_log = session_first_log.or(acc.first_log);
    let summary = acc.summarise();
    let mut problems = angles.problems();
    if acc.late_poses > 0 {
        problems.push(format!(
            "{} operator pose(s) arrived more than {} messages out of capture order and were left out of the task segments",
            acc.late_poses,
            crate::exposure::REORDER_WINDOW
        ));
    }
    let angles = angles.stats();
    pose_stamps.sort_unstable();
    pose_stamps.dedup();
    let t0 = session_first_log.unwrap_or(0);
    let at = |s: f64| t0.saturating_add((s.max(0.0) * 1e9) as u64);
    let forced: Vec<(u64, u64)> = keep_s
        .iter()
        .filter(|[a, b]| a.is_finite() && b.is_finite() && a <= b)
        .fold(Vec::new(), |spans, &[a, b]| merge(&spans, (at(a), at(b))));
    let (kept, windows, bucket_nanos) = choose(&pose_stamps, &levels, &raised, budget, &forced);
    let facts = std::mem::take(&mut acc.facts)
        .into_iter()
        .filter(|(t, _)| kept.contains(t))
        .map(|(t, (_, f))| (t, f))
        .collect();
    let kept_messages = frame_messages
        .into_iter()
        .filter(|(_, stamp, _)| kept.contains(stamp))
        .map(|(topic, _, log)| (topic, log))
        .collect();
    Ok(Plan {
        kept_messages,
        stats,
        briefs,
        wanted_range,
        whole_file,
        session_log: (session_first_log, session_last_log),
        summary,
        facts,
        angles,
        problems,
        frames_recorded: pose_stamps.len(),
        kept,
        windows,
        bucket_nanos,
    })
}

/// The frames to keep (capture stamps), the windows kept at the recorded rate, the bucket length.
fn choose(
    stamps: &[u64],
    levels: &BTreeMap<u64, (u8, u8)>,
    raised: &[(u64, u8)],
    budget: Budget,
    forced: &[(u64, u64)],
) -> (HashSet<u64>, Vec<(u64, u64)>, u64) {
    let (Some(&first), Some(&last)) = (stamps.first(), stamps.last()) else {
        return (HashSet::new(), Vec::new(), 0);
    };
    if stamps.len() <= budget.overview_frames.saturating_add(budget.window_frames) {
        return (stamps.iter().copied().collect(), vec![(first, last)], 0);
    }
    // The worst moments: stretches at action level >= 3 (a gap the summary does not bridge ends
    // one), and warnings; (peak level, length, start, end).
    let mut moments: Vec<(u8, u64, u64, u64)> = Vec::new();
    let mut run: Option<(u64, u64, u8)> = None;
    for (&t, &(level, _)) in levels {
        run = match run {
            Some((a, b, peak))
                if level >= 3 && t.saturating_sub(b) <= DEFAULT_MAX_FRAME_NANOS as u64 =>
            {
                Some((a, t, peak.max(level)))
            }
            previous => {
                if let Some((a, b, peak)) = previous {
                    moments.push((peak, b - a, a, b));
                }
                (level >= 3).then_some((t, t, level))
            }
        };
    }
    if let Some((a, b, peak)) = run {
        moments.push((peak, b - a, a, b));
    }
    moments.extend(raised.iter().map(|&(t, level)| (level, 0, t, t)));
    moments.sort_by(|x, y| y.0.cmp(&x.0).then(y.1.cmp(&x.1)).then(x.2.cmp(&y.2)));
    let margin = (WINDOW_MARGIN_S * 1e9) as u64;
    let frames_in = |spans: &[(u64, u64)]| -> usize {
        spans
            .iter()
            .map(|&(a, b)| stamps.partition_point(|&t| t <= b) - stamps.partition_point(|&t| t < a))
            .sum()
    };
    // The spans asked for first, outside the budget.
    let asked = frames_in(forced);
    let mut windows: Vec<(u64, u64)> = forced.to_vec();
    let mut any_moment = false;
    for (_, _, a, b) in moments {
        let span = (a.saturating_sub(margin), b.saturating_add(margin));
        let merged = merge(&windows, span);
        if frames_in(&merged) <= budget.window_frames.saturating_add(asked) {
            windows = merged;
            any_moment = true;
        } else if !any_moment {
            any_moment = true;
            // The worst moment is always on the page: as much of it, centred, as the budget holds.
            let mid = u64::midpoint(a, b);
            let (mut lo, mut hi) = (0u64, (b - a) / 2 + margin);
            while hi - lo > 1_000_000 {
                let h = lo + (hi - lo) / 2;
                if frames_in(&[(mid.saturating_sub(h), mid.saturating_add(h))])
                    <= budget.window_frames
                {
                    lo = h;
                } else {
                    hi = h;
                }
            }
            windows = merge(&windows, (mid.saturating_sub(lo), mid.saturating_add(lo)));
        }
    }
    let mut kept: HashSet<u64> = HashSet::new();
    for &(a, b) in &windows {
        let (i, j) = (
            stamps.partition_point(|&t| t < a),
            stamps.partition_point(|&t| t <= b),
        );
        kept.extend(&stamps[i..j]);
    }
    // Elsewhere the worst frame of each bucket.
    // At most `overview_frames` buckets from the first frame to the last, none under a second.
    let bucket = (last - first + 1)
        .div_ceil(budget.overview_frames.max(1) as u64)
        .max(1_000_000_000);
    let mut best: BTreeMap<u64, (u8, u8, std::cmp::Reverse<u64>)> = BTreeMap::new();
    for &t in stamps {
        let (level, grand) = levels.get(&t).copied().unwrap_or((0, 0));
        let key = (level, grand, std::cmp::Reverse(t));
        let slot = best.entry((t - first) / bucket).or_insert(key);
        if key > *slot {
            *slot = key;
        }
    }
    kept.extend(best.values().map(|&(_, _, std::cmp::Reverse(t))| t));
    (kept, windows, bucket)
}

/// `spans` (disjoint, in order) with `span` added, overlapping spans joined.
fn merge(spans: &[(u64, u64)], span: (u64, u64)) -> Vec<(u64, u64)> {
    let mut all: Vec<(u64, u64)> = spans.to_vec();
    all.push(span);
    all.sort_unstable();
    let mut out: Vec<(u64, u64)> = Vec::with_capacity(all.len());
    for (a, b) in all {
        match out.last_mut() {
            Some(last) if a <= last.1 => last.1 = last.1.max(b),
            _ => out.push((a, b)),
        }
    }
    out
}

/// Pass 2's reader: of the planned session, the planned frames and the robot's markers at their
/// density, all else whole.
struct SecondPass<'a> {
    plan: &'a Plan,
    rec: Recording,
    last_marker: Option<u64>,
    ranges: Ranges,
}

impl SecondPass<'_> {
    /// Whether a robot marker at `t` is kept: inside a window kept at the recorded rate, or a
    /// bucket after the last one kept.
    fn marker_due(&mut self, t: u64) -> bool {
        let in_window = self.plan.windows.iter().any(|&(a, b)| a <= t && t <= b);
        let due = self
            .last_marker
            .is_none_or(|last| t >= last.saturating_add(self.plan.bucket_nanos));
        if in_window || due {
            self.last_marker = Some(t);
        }
        in_window || due
    }
}

impl Visit for SecondPass<'_> {
    fn wants_at(&mut self, topic: &str, log_time_nanos: u64) -> bool {
        if let Some(frame) = FrameTopic::of(topic) {
            return self.plan.kept_messages.contains(&(frame, log_time_nanos));
        }
        if topic == crate::read::topics::ROBOT_MARKERS {
            // Where the clock disagreed, a marker's time is known only once decoded: all are
            // decoded and thinned in `message`.
            return self.plan.stats.clock_disagreements > 0 || self.marker_due(log_time_nanos);
        }
        true
    }

    fn metadata(&mut self, name: &str, entries: &BTreeMap<String, String>) {
        self.rec.metadata(name, entries);
    }

    fn message(&mut self, message: Decoded) {
        let t = message.log_time_nanos();
        let r = self.ranges.of(&message, t);
        self.ranges.after(session_ended_at(&message, t));
        if !self.plan.whole_file && self.plan.wanted_range != Some(r) {
            return;
        }
        // `wants_at` chose by log time; one session step can log two fused frames at the same
        // time, so a frame is kept by its capture stamp.
        let keep = match &message {
            Decoded::Pose(m) => self.plan.kept.contains(&stamp_of(&m.message.header)),
            Decoded::Ergonomics(m) => self.plan.kept.contains(&stamp_of(&m.message.header)),
            Decoded::Reba(m) => self.plan.kept.contains(&stamp_of(&m.message.header)),
            Decoded::RobotMarkers(_) if self.plan.stats.clock_disagreements > 0 => {
                self.marker_due(t)
            }
            _ => true,
        };
        if keep {
            self.rec.message(message);
        }
    }
}

/// Pass 2 (see the module docs): reads `source` (the same recording as [`plan`]'s) again and
/// analyses it; `label` names it on the page.
///
/// # Errors
/// As [`stream_recording`].
pub fn analyse_planned<R: Read + Send>(
    source: R,
    plan: Plan,
    label: &str,
    note: Option<String>,
) -> Result<SessionReview, ReviewError> {
    let mut second = SecondPass {
        plan: &plan,
        rec: Recording::default(),
        last_marker: None,
        ranges: Ranges::default(),
    };
    stream_recording(source, &mut second)?;
    let mut rec = second.rec;
    // What the file holds and what is wrong with it as pass 1 read it, decoding every message
    // (pass 2 leaves the frames it does not keep undecoded).
    let stats = &plan.stats;
    rec.bytes = stats.bytes;
    rec.messages = stats.messages;
    rec.complete = stats.complete;
    let own_problems = std::mem::take(&mut rec.problems);
    rec.problems = stats
        .problems
        .iter()
        .cloned()
        .chain(own_problems)
        .chain(note)
        .collect();
    (rec.first_log_time_nanos, rec.last_log_time_nanos) = plan.session_log;
    rec.channels = stats.channels.clone();
    let t0 = rec.first_log_time_nanos.unwrap_or(0);
    let Plan {
        summary,
        facts,
        angles,
        problems,
        frames_recorded,
        kept,
        windows,
        bucket_nanos,
        ..
    } = plan;
    let whole = WholeRecording {
        summary,
        facts,
        angles,
        problems,
        // Every frame kept: the page is the whole recording's, as for a short one.
        overview: (kept.len() < frames_recorded).then(|| Overview {
            frames_recorded,
            frames_kept: kept.len(),
            bucket_s: bucket_nanos as f64 * 1e-9,
            windows: windows
                .iter()
                .map(|&(a, b)| [round_to(secs(a, t0), 6), round_to(secs(b, t0), 6)])
                .collect(),
        }),
    };
    Ok(analyse_with(&rec, label, Some(whole)))
}

#[cfg(test)]
mod tests {
    use super::*;

    const S: u64 = 1_000_000_000;

    /// 10 Hz frames over `secs` seconds, at action level 1 (grand score 2).
    fn frames(secs: u64) -> (Vec<u64>, BTreeMap<u64, (u8, u8)>) {
        let stamps: Vec<u64> = (0..secs * 10).map(|k| 1_000 * S + k * S / 10).collect();
        let levels = stamps.iter().map(|&t| (t, (1, 2))).collect();
        (stamps, levels)
    }

    #[test]
    fn a_short_recording_keeps_every_frame() {
        let (stamps, levels) = frames(60);
        let (kept, windows, _) = choose(&stamps, &levels, &[], Budget::default(), &[]);
        assert_eq!(kept.len(), stamps.len());
        assert_eq!(windows, vec![(stamps[0], stamps[599])]);
    }

    #[test]
    fn the_worst_moments_at_the_recorded_rate_and_the_worst_of_each_bucket_elsewhere() {
        let (stamps, mut levels) = frames(3_600);
        let at = |secs: u64| 1_000 * S + secs * S;
        // A stretch at action level 4 (10 s), one at 3 (5 s) and a warning at level 3.
        for t in stamps.iter().filter(|&&t| t >= at(600) && t < at(610)) {
            levels.insert(*t, (4, 7));
        }
        for t in stamps.iter().filter(|&&t| t >= at(2_000) && t < at(2_005)) {
            levels.insert(*t, (3, 5));
        }
        // One frame at level 2 in the middle of an hour otherwise at 1: its bucket's pick.
        levels.insert(at(3_000) + 3 * S / 10, (2, 3));
        let raised = [(at(1_200), 3)];
        let budget = Budget {
            overview_frames: 100,
            window_frames: 1_500,
        };
        let (kept, windows, bucket) = choose(&stamps, &levels, &raised, budget, &[]);
        assert_eq!(
            (stamps[35_999] - stamps[0]) / bucket,
            99,
            "an hour in 100 buckets"
        );
        // Level 4 first (70 s = 701 frames), then the longer level-3 stretch (65 s, 651), and the
        // warning's 60 s would pass the budget: left out.
        assert_eq!(
            windows,
            vec![
                (at(570), at(639) + 9 * S / 10),
                (at(1_970), at(2_034) + 9 * S / 10)
            ]
        );
        for &(a, b) in &windows {
            assert!(stamps
                .iter()
                .filter(|&&t| a <= t && t <= b)
                .all(|t| kept.contains(t)));
        }
        let in_windows = |t: u64| windows.iter().any(|&(a, b)| a <= t && t <= b);
        assert!(!in_windows(at(1_200)), "over the budget");
        // Elsewhere one frame per bucket, the worst.
        let outside: Vec<u64> = kept.iter().copied().filter(|&t| !in_windows(t)).collect();
        let mut buckets: Vec<u64> = outside.iter().map(|t| (t - stamps[0]) / bucket).collect();
        buckets.sort_unstable();
        let n = buckets.len();
        buckets.dedup();
        assert_eq!(buckets.len(), n, "one frame per bucket outside the windows");
        assert!(
            kept.contains(&(at(3_000) + 3 * S / 10)),
            "the bucket's worst frame"
        );
        assert!(kept.len() <= 100 + 1 + 1_500);
    }

    #[test]
    fn the_worst_moment_is_kept_even_when_longer_than_the_budget() {
        let (stamps, mut levels) = frames(600);
        let at = |secs: u64| 1_000 * S + secs * S;
        for t in stamps.iter().filter(|&&t| t >= at(100) && t < at(300)) {
            levels.insert(*t, (3, 6));
        }
        let budget = Budget {
            overview_frames: 10,
            window_frames: 500,
        };
        let (kept, windows, _) = choose(&stamps, &levels, &[], budget, &[]);
        assert_eq!(windows.len(), 1);
        let (a, b) = windows[0];
        let inside = stamps.iter().filter(|&&t| a <= t && t <= b).count();
        assert!((490..=500).contains(&inside), "{inside} frames");
        assert!(a >= at(100) && b < at(300), "within the stretch, centred");
        assert!(kept.len() <= 500 + 10);
    }

    #[test]
    fn spans_merge_where_they_overlap() {
        assert_eq!(merge(&[(0, 10), (20, 30)], (5, 22)), vec![(0, 30)]);
        assert_eq!(merge(&[(0, 10)], (11, 12)), vec![(0, 10), (11, 12)]);
        assert_eq!(merge(&[], (3, 4)), vec![(3, 4)]);
    }
}
