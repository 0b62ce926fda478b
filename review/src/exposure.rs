//! Exposure over many sessions: per operator, per day and ISO week, per task segment and robot
//! class — the RULA and REBA action levels as time, ISO 11226's static holds, the peak grand score
//! and the parts handed over.
//!
//! A recording is read front to back once ([`crate::read::stream_recording`]); each operator session
//! in it is summarised as the review summarises it (the same [`SessionSummary`], so a session's
//! numbers here are the report's) and handed on as a few [`SegmentRow`]s — one for the whole session
//! and one per task segment. Nothing of a session is kept after its rows: memory does not grow with
//! the number of recordings. [`ExposureTable`] adds the rows up per group.
//!
//! Rows carry **seconds**, not shares: shares of several sessions are their seconds added up and
//! divided ([`ExposureRow::rula_share`]), so any engine that sums the columns (the Parquet store,
//! DuckDB) gets the same shares. The operator is the recording's pseudonymous id
//! ([`ergocell_bridge::session_info`]); no landmark or angle leaves this module.
//!
//! Days and weeks are those of the session's first message in UTC.

use std::collections::{BTreeMap, BTreeSet};
use std::io::Read;

use ergocell_bridge::msg::{
    ControllerEvent, ControllerEventKind, JointTrajectory, OperatorPose, SessionState,
};
use ergocell_ergonomics::activity::{Activity, ActivityConfig, ActivityTracker};
use ergocell_ergonomics::summary::{RebaBrief, SessionSummary};
use ergocell_ergonomics::UpVector;

use crate::analysis::{
    frame_facts, handover_spans_of, phase_of, robot_legs, scored_side, secs, skeleton_of,
    summarise, FrameFacts, ScoredFrame,
};
use crate::legacy::legacy_part_from_reason;
use crate::read::{stream_recording, topics, Decoded, ReadStats, Stamped, Visit};
use crate::ReviewError;

/// The segment name of a whole session's row.
pub const ALL: &str = "all";

/// Poses are put back in capture order within this many messages before the activity tracker
/// reads them (the review sorts a whole recording; a stream sorts a window).
pub const REORDER_WINDOW: usize = 64;

/// One session's exposure in one task segment (or the whole session, [`ALL`]): the facts a store
/// keeps and any engine can add up.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct SegmentRow {
    /// The operator's pseudonymous id; `None` when the recording names none.
    pub operator: Option<String>,
    /// The recording it came from (as the user named it).
    pub file: String,
    /// The session's number in its recording, from 1.
    pub session: u32,
    /// The session's first message, nanoseconds since the Unix epoch (UTC).
    pub start_unix_nanos: i64,
    /// Its UTC day, `YYYY-MM-DD`.
    pub day: String,
    /// Its ISO week, `YYYY-Www`.
    pub week: String,
    /// The robot class that served the operator (`c1`, `c2`, `c3`); `None` when none was decided.
    pub class: Option<String>,
    /// [`ALL`] or a task segment ([`crate::analysis::PHASES`]).
    pub segment: String,
    /// Time in the segment, seconds (gaps not counted).
    pub duration_s: f64,
    /// Of it, RULA-scored.
    pub rula_scored_s: f64,
    /// RULA-scored time at action level 1, 2, 3, 4 (the worse side), seconds.
    pub rula_al_s: [f64; 4],
    /// REBA-scored time.
    pub reba_scored_s: f64,
    /// REBA-scored time at REBA action level 0..=4, seconds.
    pub reba_al_s: [f64; 5],
    /// The longest unbroken stretch at RULA action level 3 or more, seconds.
    pub rula_al3_longest_s: f64,
    /// The highest grand score (either side); 0 when never scored.
    pub peak_grand_score: u8,
    /// RULA-scored time whose continuous posture cost is known (the worse side's angles recorded),
    /// seconds, and the cost integrated over it (RULA points × seconds): summed over any group and
    /// divided, their mean.
    pub posture_cost_s: f64,
    pub posture_cost_point_s: f64,
    /// ISO 11226 static holds (trunk, neck, upper arms) and of them those ISO 11226 does not accept;
    /// whole sessions only (0 in a segment's row).
    pub static_holds: u32,
    pub static_holds_exceeded: u32,
    /// Parts the operator took; whole sessions only (0 in a segment's row).
    pub parts_taken: u32,
}

/// The UTC day and ISO week of an instant.
pub fn day_and_week(unix_nanos: i64) -> (String, String) {
    use chrono::Datelike;
    let t = chrono::DateTime::from_timestamp_nanos(unix_nanos);
    let w = t.iso_week();
    (
        t.format("%Y-%m-%d").to_string(),
        format!("{}-W{:02}", w.year(), w.week()),
    )
}

/// The rows of one session's summary.
fn rows_of(
    s: &SessionAccumulator,
    number: u32,
    file: &str,
    summary: &SessionSummary,
) -> Vec<SegmentRow> {
    let start = i64::try_from(s.first_log.unwrap_or(0)).unwrap_or(i64::MAX);
    let (day, week) = day_and_week(start);
    let al3_longest = |exposure: &[ergocell_ergonomics::summary::Exposure]| {
        exposure
            .iter()
            .find(|e| e.at_least == 3)
            .map_or(0.0, |e| e.longest_secs)
    };
    let row = |segment: &str,
               duration_s: f64,
               unscored_share: f64,
               al: [f64; 4],
               reba_scored_s: f64,
               reba: [f64; 5],
               longest: f64,
               peak: u8,
               cost: ergocell_ergonomics::summary::PostureCostTime| {
        let scored = duration_s * (1.0 - unscored_share);
        SegmentRow {
            operator: s.operator.clone(),
            file: file.to_owned(),
            session: number,
            start_unix_nanos: start,
            day: day.clone(),
            week: week.clone(),
            class: s.class.clone(),
            segment: segment.to_owned(),
            duration_s,
            rula_scored_s: scored,
            rula_al_s: al.map(|x| x * scored),
            reba_scored_s,
            reba_al_s: reba.map(|x| x * reba_scored_s),
            rula_al3_longest_s: longest,
            peak_grand_score: peak,
            posture_cost_s: cost.secs,
            posture_cost_point_s: cost.point_secs,
            static_holds: 0,
            static_holds_exceeded: 0,
            parts_taken: 0,
        }
    };
    let peak = summary
        .grand_score
        .iter()
        .filter_map(|g| g.share_by_score.iter().map(|&(score, _)| score).max())
        .max()
        .unwrap_or(0);
    let mut whole = row(
        ALL,
        summary.duration_secs,
        summary.unscored_share,
        summary.action_level_share,
        summary.reba_scored_secs,
        summary.reba_action_level_share,
        al3_longest(&summary.action_level_exposure),
        peak,
        summary.posture_cost,
    );
    let count = |f: fn(&ergocell_ergonomics::static_posture::StaticPostureSummary) -> usize| {
        u32::try_from(summary.static_postures.iter().map(f).sum::<usize>()).unwrap_or(u32::MAX)
    };
    whole.static_holds = count(|p| p.static_holds);
    whole.static_holds_exceeded = count(|p| p.exceeded);
    whole.parts_taken = u32::try_from(s.parts.len()).unwrap_or(u32::MAX);
    let mut rows = vec![whole];
    for p in &summary.phases {
        rows.push(row(
            &p.phase,
            p.duration_secs,
            p.unscored_share,
            p.action_level_share,
            p.reba_scored_secs,
            p.reba_action_level_share,
            al3_longest(&p.action_level_exposure),
            p.peak_grand_score.unwrap_or(0),
            p.posture_cost,
        ));
    }
    rows
}

/// One operator session being read: only what its summary needs, each frame reduced to its scores
/// and its pose's facts as it arrives.
#[derive(Default)]
pub(crate) struct SessionAccumulator {
    operator: Option<String>,
    pub(crate) first_log: Option<u64>,
    /// A `session_ended` state was seen: the next operator's frame or leg starts a new session.
    ended: bool,
    /// Poses not yet read by the activity tracker, by capture stamp.
    pending_poses: BTreeMap<u64, OperatorPose>,
    last_pose_stamp: Option<u64>,
    activity: Option<ActivityTracker>,
    /// Per capture stamp: the pose's activity and facts (its phase set at the end).
    pub(crate) facts: BTreeMap<u64, (Option<Activity>, FrameFacts)>,
    /// RULA per frame (REBA attached at the end), in arrival order.
    frames: Vec<(u64, ScoredFrame)>,
    reba: BTreeMap<u64, [Option<RebaBrief>; 2]>,
    trajectories: Vec<Stamped<JointTrajectory>>,
    controller_events: Vec<Stamped<ControllerEvent>>,
    class: Option<String>,
    parts: BTreeSet<u32>,
    /// Poses that came later than the reorder window allows (read out of order).
    pub(crate) late_poses: usize,
}

fn stamp_of(h: &ergocell_bridge::msg::Header) -> u64 {
    u64::try_from(h.stamp.to_nanos()).unwrap_or(0)
}

impl SessionAccumulator {
    pub(crate) fn new(operator: Option<String>) -> Self {
        Self {
            operator,
            activity: ActivityTracker::new(ActivityConfig::default(), &UpVector::z()).ok(),
            ..Self::default()
        }
    }

    fn seen_operator(&self) -> bool {
        !self.frames.is_empty() || !self.facts.is_empty() || !self.pending_poses.is_empty()
    }

    fn read_pose(&mut self, m: &OperatorPose) {
        let t = stamp_of(&m.header);
        let act =
            skeleton_of(m, t).and_then(|sk| self.activity.as_mut().and_then(|a| a.update(&sk)));
        self.facts.insert(t, (act, frame_facts(m, None)));
        self.last_pose_stamp = Some(t);
    }

    fn pose(&mut self, m: OperatorPose) {
        let t = stamp_of(&m.header);
        if self.last_pose_stamp.is_some_and(|last| t <= last) {
            // Already read (a repeat) or later than the window: the review would have sorted it in.
            self.late_poses += usize::from(!self.facts.contains_key(&t));
            return;
        }
        self.pending_poses.entry(t).or_insert(m);
        while self.pending_poses.len() > REORDER_WINDOW {
            if let Some((_, p)) = self.pending_poses.pop_first() {
                self.read_pose(&p);
            }
        }
    }

    fn state(&mut self, m: &SessionState) {
        if !m.height_class.is_empty() {
            self.class = Some(m.height_class.clone());
        }
        let part = if m.parts_taken > 0 {
            Some(m.parts_taken)
        } else {
            legacy_part_from_reason(&m.reason).map(|(p, _, _)| p)
        };
        self.parts.extend(part);
        if m.state == SessionState::SESSION_ENDED {
            self.ended = true;
        }
    }

    /// The session's summary (the review's computation).
    fn finish(mut self, number: u32, file: &str) -> (Vec<SegmentRow>, usize) {
        let summary = self.summarise();
        (rows_of(&self, number, file, &summary), self.late_poses)
    }

    /// The summary of what was read (the review's computation); afterwards `facts` holds each
    /// pose's task segment.
    pub(crate) fn summarise(&mut self) -> SessionSummary {
        while let Some((_, p)) = self.pending_poses.pop_first() {
            self.read_pose(&p);
        }
        let t0 = self.first_log.unwrap_or(0);
        let (legs, _, _) = robot_legs(&self.trajectories, &self.controller_events, t0);
        let handovers = handover_spans_of(&legs);
        for (t, (act, facts)) in &mut self.facts {
            facts.phase = phase_of(*act, secs(*t, t0), &handovers);
        }
        let mut frames = std::mem::take(&mut self.frames);
        frames.sort_by_key(|(t, _)| *t);
        let reba = &self.reba;
        summarise(
            frames.into_iter().map(|(t, mut f)| {
                let r = reba.get(&t);
                for (k, side) in [&mut f.left, &mut f.right].into_iter().enumerate() {
                    if let Some(s) = side {
                        s.reba = r.and_then(|r| r[k]);
                    }
                }
                (t, f)
            }),
            |t| self.facts.get(&t).map(|(_, f)| *f).unwrap_or_default(),
        )
    }
}

/// Reads one recording's sessions (see the module docs).
struct SessionStream<'a> {
    file: &'a str,
    operator: Option<String>,
    current: SessionAccumulator,
    number: u32,
    late_poses: usize,
    each: &'a mut dyn FnMut(SegmentRow),
}

impl SessionStream<'_> {
    fn close(&mut self) {
        let done = std::mem::replace(
            &mut self.current,
            SessionAccumulator::new(self.operator.clone()),
        );
        if done.seen_operator() {
            self.number += 1;
            let (rows, late) = done.finish(self.number, self.file);
            self.late_poses += late;
            for row in rows {
                (self.each)(row);
            }
        }
    }

    /// A message of the next session (an operator's frame, a leg sent, a state other than the end):
    /// after a `session_ended`, it starts a new session.
    fn next_operator(&mut self) {
        if self.current.ended {
            self.close();
        }
    }
}

impl Visit for SessionStream<'_> {
    fn wants(&self, topic: &str) -> bool {
        !matches!(topic, topics::ROBOT_MARKERS | topics::WARNINGS)
    }

    fn metadata(&mut self, name: &str, entries: &BTreeMap<String, String>) {
        if name == ergocell_bridge::session_info::METADATA_NAME {
            if let Ok(Some(id)) = ergocell_bridge::session_info::operator_of(entries) {
                self.operator = Some(id.to_string());
                self.current.operator = self.operator.clone();
            }
        }
    }

    fn message(&mut self, message: Decoded) {
        let log_time = message.log_time_nanos();
        match &message {
            Decoded::Pose(_) | Decoded::Ergonomics(_) => self.next_operator(),
            Decoded::Trajectory(m) if !m.message.points.is_empty() => self.next_operator(),
            Decoded::ControllerEvent(m)
                if m.message.event_kind() == Some(ControllerEventKind::GoalSent) =>
            {
                self.next_operator();
            }
            Decoded::State(m) if m.message.state != SessionState::SESSION_ENDED => {
                self.next_operator();
            }
            _ => {}
        }
        self.current.take(message, log_time);
    }
}

impl SessionAccumulator {
    /// Reads one message of the session, logged at `log_time`.
    pub(crate) fn take(&mut self, message: Decoded, log_time: u64) {
        let s = self;
        s.first_log = Some(s.first_log.map_or(log_time, |f| f.min(log_time)));
        match message {
            Decoded::Pose(m) => s.pose(m.message),
            Decoded::Ergonomics(m) => {
                let e = &m.message;
                s.frames.push((
                    stamp_of(&e.header),
                    ScoredFrame {
                        stamp_nanos: e.header.stamp.to_nanos(),
                        left: scored_side(&e.left, None),
                        right: scored_side(&e.right, None),
                    },
                ));
            }
            Decoded::Reba(m) => {
                let r = &m.message;
                let brief = |side: &ergocell_bridge::msg::RebaSide| {
                    side.scored.then_some(RebaBrief {
                        reba_score: side.reba_score,
                        action_level: side.action_level,
                        uncertain: side.uncertain,
                    })
                };
                s.reba
                    .entry(stamp_of(&r.header))
                    .or_insert([brief(&r.left), brief(&r.right)]);
            }
            Decoded::State(m) => s.state(&m.message),
            Decoded::Trajectory(m) => s.trajectories.push(m),
            Decoded::ControllerEvent(m) => s.controller_events.push(m),
            Decoded::Warning(_) | Decoded::RobotMarkers(_) => {}
        }
    }
}

/// What reading one recording's sessions found.
#[derive(Debug, Clone, PartialEq)]
pub struct StreamedRecording {
    pub stats: ReadStats,
    /// Operator sessions read.
    pub sessions: u32,
    /// Poses that arrived later than the reorder window (not read by the activity tracker).
    pub late_poses: usize,
}

/// Streams one recording (see the module docs), handing each session's rows to `each` as the
/// session completes.
///
/// # Errors
/// As [`stream_recording`].
pub fn stream_sessions<R: Read + Send>(
    source: R,
    file: &str,
    each: &mut dyn FnMut(SegmentRow),
) -> Result<StreamedRecording, ReviewError> {
    let mut stream = SessionStream {
        file,
        operator: None,
        current: SessionAccumulator::new(None),
        number: 0,
        late_poses: 0,
        each,
    };
    let stats = stream_recording(source, &mut stream)?;
    stream.close();
    Ok(StreamedRecording {
        stats,
        sessions: stream.number,
        late_poses: stream.late_poses,
    })
}

/// The groups a row adds to: per day and per week, its class and all classes, its segment.
#[derive(Debug, Clone, PartialEq, Eq, PartialOrd, Ord, serde::Serialize)]
pub struct GroupKey {
    pub operator: String,
    /// `day` or `week`.
    pub period: &'static str,
    /// `YYYY-MM-DD` or `YYYY-Www`.
    pub period_start: String,
    /// `c1`, `c2`, `c3`, `-` (none decided) or `all`.
    pub class: String,
    /// [`ALL`] or a task segment.
    pub segment: String,
}

/// One group's sums (seconds, counts, maxima).
#[derive(Debug, Clone, Default, PartialEq, serde::Serialize)]
pub struct ExposureRow {
    pub sessions: u32,
    pub duration_s: f64,
    pub rula_scored_s: f64,
    pub rula_al_s: [f64; 4],
    pub reba_scored_s: f64,
    pub reba_al_s: [f64; 5],
    pub rula_al3_longest_s: f64,
    pub peak_grand_score: u8,
    pub posture_cost_s: f64,
    pub posture_cost_point_s: f64,
    pub static_holds: u32,
    pub static_holds_exceeded: u32,
    pub parts_taken: u32,
}

impl ExposureRow {
    /// The time-weighted mean posture cost of the worse side; `None` when never known.
    pub fn mean_posture_cost(&self) -> Option<f64> {
        (self.posture_cost_s > 0.0).then(|| self.posture_cost_point_s / self.posture_cost_s)
    }

    fn add(&mut self, r: &SegmentRow) {
        self.sessions += 1;
        self.duration_s += r.duration_s;
        self.rula_scored_s += r.rula_scored_s;
        for (a, b) in self.rula_al_s.iter_mut().zip(r.rula_al_s) {
            *a += b;
        }
        self.reba_scored_s += r.reba_scored_s;
        for (a, b) in self.reba_al_s.iter_mut().zip(r.reba_al_s) {
            *a += b;
        }
        self.rula_al3_longest_s = self.rula_al3_longest_s.max(r.rula_al3_longest_s);
        self.peak_grand_score = self.peak_grand_score.max(r.peak_grand_score);
        self.posture_cost_s += r.posture_cost_s;
        self.posture_cost_point_s += r.posture_cost_point_s;
        self.static_holds += r.static_holds;
        self.static_holds_exceeded += r.static_holds_exceeded;
        self.parts_taken += r.parts_taken;
    }

    /// Share of RULA-scored time at action level `at_least` or more (1..=4); `None` when never
    /// scored.
    pub fn rula_share(&self, at_least: u8) -> Option<f64> {
        let from = usize::from(at_least.clamp(1, 4)) - 1;
        (self.rula_scored_s > 0.0)
            .then(|| self.rula_al_s[from..].iter().sum::<f64>() / self.rula_scored_s)
    }

    /// Share of RULA-scored time at exactly action level `level` (1..=4); `None` when never scored.
    pub fn rula_level_share(&self, level: u8) -> Option<f64> {
        let k = usize::from(level.clamp(1, 4)) - 1;
        (self.rula_scored_s > 0.0).then(|| self.rula_al_s[k] / self.rula_scored_s)
    }

    /// Share of REBA-scored time at REBA action level `at_least` or more (0..=4).
    pub fn reba_share(&self, at_least: u8) -> Option<f64> {
        let from = usize::from(at_least.min(4));
        (self.reba_scored_s > 0.0)
            .then(|| self.reba_al_s[from..].iter().sum::<f64>() / self.reba_scored_s)
    }
}

/// Sums per group ([`GroupKey`]); holds one small row per group, whatever the number of sessions.
#[derive(Debug, Clone, Default)]
pub struct ExposureTable {
    pub groups: BTreeMap<GroupKey, ExposureRow>,
}

impl ExposureTable {
    /// Adds one session-segment row to each group it belongs to.
    pub fn add(&mut self, r: &SegmentRow) {
        let operator = r.operator.clone().unwrap_or_else(|| "-".to_owned());
        let class = r.class.clone().unwrap_or_else(|| "-".to_owned());
        for (period, period_start) in [("day", &r.day), ("week", &r.week)] {
            for class in [class.as_str(), ALL] {
                let key = GroupKey {
                    operator: operator.clone(),
                    period,
                    period_start: period_start.clone(),
                    class: class.to_owned(),
                    segment: r.segment.clone(),
                };
                self.groups.entry(key).or_default().add(r);
            }
        }
    }
}

/// The files `ergocell exposure` writes into its folder, in this order: the groups' CSV
/// ([`crate::exposure_csv::groups_csv`]), the sessions' CSV ([`crate::exposure_csv::sessions_csv`]),
/// the sessions as Parquet ([`crate::store`]) and the page ([`page`]).
pub const FILES: [&str; 4] = [
    "exposure.csv",
    "sessions.csv",
    "sessions.parquet",
    "exposure.html",
];

/// Many recordings read one after another (`ergocell exposure`): the groups' sums, every session's
/// rows, how many recordings were read and left out, and the sessions found in them.
#[derive(Debug, Clone, Default)]
pub struct ExposureSet {
    pub table: ExposureTable,
    pub rows: Vec<SegmentRow>,
    /// Recordings read.
    pub recordings: usize,
    /// Operator sessions in them.
    pub sessions: u32,
    /// Recordings left out ([`ExposureSet::left_out`]).
    pub failed: usize,
}

impl ExposureSet {
    /// Streams one recording ([`stream_sessions`]; `label`: as the user named it), adding each
    /// session's rows as the session completes: a recording that fails part-way keeps the sessions
    /// read before, and is not counted as read (the caller says [`ExposureSet::left_out`]).
    ///
    /// # Errors
    /// As [`stream_sessions`].
    pub fn read<R: Read + Send>(
        &mut self,
        source: R,
        label: &str,
    ) -> Result<StreamedRecording, ReviewError> {
        let (table, rows) = (&mut self.table, &mut self.rows);
        let mut each = |row: SegmentRow| {
            table.add(&row);
            rows.push(row);
        };
        let read = stream_sessions(source, label, &mut each)?;
        self.recordings += 1;
        self.sessions = self.sessions.saturating_add(read.sessions);
        Ok(read)
    }

    /// Counts a recording that could not be opened or read.
    pub fn left_out(&mut self) {
        self.failed += 1;
    }

    /// The page of what was read ([`page`]).
    pub fn page(&self) -> String {
        page(&self.table, self.recordings, self.sessions)
    }
}

/// The page of an [`ExposureTable`]: one self-contained HTML file, no script and nothing fetched
/// (the report's Content-Security-Policy). Per operator, a table of its weeks and days (whole
/// sessions, all classes) with the RULA action-level shares as a bar, then each week's task segments.
/// `sources` and `sessions` are how many recordings and sessions were read.
pub fn page(table: &ExposureTable, sources: usize, sessions: u32) -> String {
    use crate::page::{escape_html as esc, REPORT_CSP};
    use std::fmt::Write as _;
    let pct = |x: Option<f64>| x.map_or_else(|| "–".to_owned(), |x| format!("{:.1} %", 100.0 * x));
    let bar = |g: &ExposureRow| -> String {
        if g.rula_share(1).is_none() {
            return "<span class=\"none\">not scored</span>".to_owned();
        }
        let mut out = String::from("<span class=\"bar\">");
        for level in 1..=4u8 {
            let share = g.rula_level_share(level).unwrap_or(0.0);
            let _ = write!(
                out,
                "<span class=\"al{level}\" style=\"width:{:.2}%\" title=\"action level {level}: {:.1} %\"></span>",
                100.0 * share,
                100.0 * share
            );
        }
        out.push_str("</span>");
        out
    };
    let row = |g: &ExposureRow, first: &str| {
        format!(
            "<tr><th>{}</th><td class=\"num\">{}</td><td class=\"num\">{:.2}</td><td>{}</td><td class=\"num\">{}</td><td class=\"num\">{}</td><td class=\"num\">{:.0}</td><td class=\"num\">{}</td><td class=\"num\">{}</td><td class=\"num\">{} ({})</td><td class=\"num\">{}</td></tr>",
            esc(first),
            g.sessions,
            g.duration_s / 3600.0,
            bar(g),
            pct(g.rula_share(3)),
            pct(g.reba_share(3)),
            g.rula_al3_longest_s,
            g.peak_grand_score,
            g.mean_posture_cost().map_or_else(|| "–".to_owned(), |c| format!("{c:.3}")),
            g.static_holds,
            g.static_holds_exceeded,
            g.parts_taken
        )
    };
    let head = "<tr><th></th><th>sessions</th><th>hours</th><th>RULA action level 1 · 2 · 3 · 4</th><th>RULA AL ≥ 3</th><th>REBA AL ≥ 3</th><th>longest AL ≥ 3, s</th><th>peak grand score</th><th>mean posture cost</th><th>static holds (exceeded)</th><th>parts</th></tr>";
    let mut body = String::new();
    let operators: BTreeSet<&str> = table.groups.keys().map(|k| k.operator.as_str()).collect();
    for op in operators {
        let _ = write!(body, "<h2>Operator {}</h2>", esc(op));
        for period in ["week", "day"] {
            let _ = write!(body, "<h3>By {period}</h3><table>{head}");
            for (k, g) in table.groups.iter().filter(|(k, _)| {
                k.operator == op && k.period == period && k.class == ALL && k.segment == ALL
            }) {
                body.push_str(&row(g, &k.period_start));
            }
            body.push_str("</table>");
        }
        let _ = write!(body, "<h3>By week and task segment</h3><table>{head}");
        for (k, g) in table.groups.iter().filter(|(k, _)| {
            k.operator == op && k.period == "week" && k.class == ALL && k.segment != ALL
        }) {
            body.push_str(&row(g, &format!("{} · {}", k.period_start, k.segment)));
        }
        body.push_str("</table>");
        let _ = write!(body, "<h3>By week and robot class</h3><table>{head}");
        for (k, g) in table.groups.iter().filter(|(k, _)| {
            k.operator == op && k.period == "week" && k.class != ALL && k.segment == ALL
        }) {
            body.push_str(&row(g, &format!("{} · class {}", k.period_start, k.class)));
        }
        body.push_str("</table>");
    }
    format!(
        "<!doctype html><html lang=\"en\"><head><meta charset=\"utf-8\">\
<meta http-equiv=\"Content-Security-Policy\" content=\"{REPORT_CSP}\">\
<title>Exposure: {sessions} sessions</title><style>\
body{{font:14px system-ui,sans-serif;margin:2em;color:#222}}table{{border-collapse:collapse;margin:.5em 0 1.5em}}\
th,td{{padding:.25em .6em;border-bottom:1px solid #ddd;text-align:left}}td.num{{text-align:right}}\
.bar{{display:inline-flex;width:16em;height:1em;background:#eee}}.bar span{{display:block;height:100%}}\
.al1{{background:#4caf50}}.al2{{background:#ffc107}}.al3{{background:#ff7043}}.al4{{background:#c62828}}.none{{color:#888}}\
</style></head><body><h1>Exposure</h1>\
<p>{sessions} operator session(s) from {sources} recording(s). Shares are of RULA-scored (REBA-scored) time, \
summed over the sessions: a week's share is its seconds at a level over its scored seconds. Days and weeks \
(ISO) are those of each session's start, in UTC. Operators are pseudonymous ids; the plant keeps the mapping.</p>\
{body}</body></html>\n"
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_recording_that_cannot_be_read_adds_nothing_and_is_not_counted_as_read() {
        let mut set = ExposureSet::default();
        let err = set.read(&b"junk"[..], "x.mcap");
        assert!(matches!(err, Err(ReviewError::NotMcap { .. })), "{err:?}");
        assert_eq!((set.recordings, set.sessions, set.failed), (0, 0, 0));
        assert!(set.rows.is_empty() && set.table.groups.is_empty());
        set.left_out();
        assert_eq!(set.failed, 1);
    }

    #[test]
    fn days_and_iso_weeks_are_utc() {
        // 2026-12-31 is a Thursday: ISO week 53 of 2026; 2027-01-04 is in week 1 of 2027.
        let at = |s: &str| {
            chrono::DateTime::parse_from_rfc3339(s)
                .unwrap()
                .timestamp_nanos_opt()
                .unwrap()
        };
        assert_eq!(
            day_and_week(at("2026-12-31T23:30:00Z")),
            ("2026-12-31".into(), "2026-W53".into())
        );
        assert_eq!(
            day_and_week(at("2027-01-04T00:10:00+01:00")),
            ("2027-01-03".into(), "2026-W53".into())
        );
        assert_eq!(day_and_week(at("2027-01-04T06:00:00Z")).1, "2027-W01");
    }

    fn row(operator: &str, day: &str, week: &str, scored: f64, al: [f64; 4]) -> SegmentRow {
        SegmentRow {
            operator: Some(operator.into()),
            file: "f".into(),
            session: 1,
            start_unix_nanos: 0,
            day: day.into(),
            week: week.into(),
            class: Some("c2".into()),
            segment: ALL.into(),
            duration_s: scored,
            rula_scored_s: scored,
            rula_al_s: al,
            reba_scored_s: 0.0,
            reba_al_s: [0.0; 5],
            rula_al3_longest_s: al[2],
            peak_grand_score: 5,
            // a cost of 3 plus the share at action level 3
            posture_cost_s: scored,
            posture_cost_point_s: 3.0 * scored + al[2],
            static_holds: 1,
            static_holds_exceeded: 0,
            parts_taken: 3,
        }
    }

    #[test]
    fn shares_over_sessions_are_summed_seconds_not_averaged_shares() {
        let mut t = ExposureTable::default();
        // A short session all at AL3 and a long one all at AL1: the week's share is 10/110.
        t.add(&row(
            "op-1",
            "2026-11-30",
            "2026-W49",
            10.0,
            [0.0, 0.0, 10.0, 0.0],
        ));
        t.add(&row(
            "op-1",
            "2026-12-01",
            "2026-W49",
            100.0,
            [100.0, 0.0, 0.0, 0.0],
        ));
        t.add(&row(
            "op-2",
            "2026-12-01",
            "2026-W49",
            50.0,
            [0.0, 0.0, 0.0, 50.0],
        ));
        let week = |op: &str, class: &str| {
            t.groups
                .get(&GroupKey {
                    operator: op.into(),
                    period: "week",
                    period_start: "2026-W49".into(),
                    class: class.into(),
                    segment: ALL.into(),
                })
                .unwrap()
                .clone()
        };
        let w = week("op-1", ALL);
        assert_eq!(w.sessions, 2);
        assert!((w.rula_share(3).unwrap() - 10.0 / 110.0).abs() < 1e-12);
        assert_eq!(w.parts_taken, 6);
        assert_eq!(week("op-1", "c2"), w);
        assert_eq!(week("op-2", ALL).rula_share(4), Some(1.0));
        // day, week × class, all: 4 groups per row's operator and period.
        // op-1: two days and one week, each for c2 and all; op-2: one day and one week.
        assert_eq!(t.groups.len(), (2 + 1) * 2 + (1 + 1) * 2);
        assert_eq!(ExposureRow::default().rula_share(1), None);
        // the mean cost is time-weighted: (4.0 × 10 s + 3.0 × 100 s) / 110 s, not (4 + 3) / 2
        assert!((w.mean_posture_cost().unwrap() - 340.0 / 110.0).abs() < 1e-12);
        assert_eq!(ExposureRow::default().mean_posture_cost(), None);
    }
}
