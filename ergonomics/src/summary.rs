//! A session's RULA summary: for how much of the time each action level, body-region score and
//! grand score held, and REBA's score and action level beside it when the frames carry REBA.
//!
//! This is the one computation of those shares. `ergocell rula track` feeds it the frames it assesses
//! ([`SummaryBuilder::add`]); the offline review (`ergocell_review`) feeds it the scores read back
//! from a recording ([`SummaryBuilder::add_scores`]). So one session gives the same numbers in both.
//!
//! How time is counted — what an ergonomist reads as "share of the time":
//! - **Time-weighted**, not frame-counted: each frame stands for the time until the next frame, so a
//!   stretch recorded at a higher frame rate does not weigh more.
//! - **Gaps do not count.** An interval longer than `max_frame_nanos` ([`DEFAULT_MAX_FRAME_NANOS`],
//!   1 s) is a gap in the recording (tracking lost, nothing recorded): the frame before it stands for
//!   the typical frame interval (the median of the intervals that are not gaps), as the last frame
//!   does — never for the gap.
//! - A region's shares are of the time **that region was scored**: a side that could not be scored
//!   is not "safe" and is not in the denominator. Time with no score at all is reported on its own
//!   ([`SessionSummary::unscored_share`]).
//! - The arm regions are per side; neck, trunk and legs (scored once for the body) and the action
//!   level are the headline side's ([`crate::assess::headline_side`]: the worse one).

use std::collections::BTreeMap;

use serde::Serialize;

use crate::assess::{headline_side, BodyRegion, FrameAssessment, SideAssessment};
use crate::rula::RulaScores;
use crate::static_posture::{static_postures, PostureAngles, StaticPostureSummary};
use crate::Side;

/// Default gap threshold: an interval between frames longer than 1 s is a gap, not frame time.
pub const DEFAULT_MAX_FRAME_NANOS: i64 = 1_000_000_000;

/// One scored side of one frame, as the summary reads it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ScoredSide {
    pub scores: RulaScores,
    /// The score rests on low-confidence landmarks or held inputs.
    pub uncertain: bool,
    /// The side's REBA of the same frame, when there is one (a recording made before REBA has none).
    pub reba: Option<RebaBrief>,
    /// The side's continuous posture cost ([`crate::posture_cost`]: the grand score plus how far
    /// its angles lie into their bands), when its angles are known.
    pub posture_cost: Option<f64>,
}

/// What the summary reads of one side's REBA.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct RebaBrief {
    /// 1..=15.
    pub reba_score: u8,
    /// 0..=4.
    pub action_level: u8,
    pub uncertain: bool,
}

impl From<&SideAssessment> for ScoredSide {
    fn from(s: &SideAssessment) -> Self {
        Self {
            scores: s.scores,
            uncertain: s.uncertain,
            reba: Some(RebaBrief {
                reba_score: s.reba.scores.reba_score,
                action_level: s.reba.scores.action_level,
                uncertain: s.reba.uncertain,
            }),
            posture_cost: observed_cost(s),
        }
    }
}

/// The side's posture cost when its five angles were observed in this frame (not held, not the
/// conservative wrist): the same frames a recording can cost from the angles it kept
/// ([`crate::posture_cost::cost_from_angles`]), so `rula track` and the review agree.
fn observed_cost(s: &SideAssessment) -> Option<f64> {
    const ANGLES: [&str; 5] = [
        "upper_arm_flexion_deg",
        "lower_arm_flexion_deg",
        "wrist_flexion_deg",
        "neck_flexion_deg",
        "trunk_flexion_deg",
    ];
    let observed = ANGLES
        .iter()
        .all(|name| s.source(name) == Some(crate::assess::InputSource::Observed));
    if !observed {
        return None;
    }
    crate::posture_cost::posture_cost(&s.input)
        .ok()
        .map(|c| c.cost())
}

/// How a score at or above a level was held over time: how often it started, its longest unbroken
/// stretch and its total time. A stretch is broken by a frame below the level, a frame in which the
/// score is missing, or a gap in the recording (see the module docs).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Exposure {
    /// The level: a score (or action level) at least this counts.
    pub at_least: u8,
    /// Separate stretches at or above the level.
    pub episodes: usize,
    /// The longest of them, seconds.
    pub longest_secs: f64,
    /// All of them together, seconds.
    pub total_secs: f64,
}

/// Time shares of one region's scores.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct RegionShare {
    pub region: BodyRegion,
    /// The side for the arm regions; `None` for neck, trunk and legs.
    pub side: Option<Side>,
    /// `(score, share of scored time)`, by ascending score; only the scores that occurred.
    pub share_by_score: Vec<(u8, f64)>,
    /// Frames in which the region was scored.
    pub frames: usize,
    /// For each score above the region's lowest (2 up to the highest that occurred): its episodes.
    pub exposure: Vec<Exposure>,
}

impl RegionShare {
    /// The time-weighted mean score; `None` when no scored time.
    pub fn mean_score(&self) -> Option<f64> {
        mean_score(&self.share_by_score)
    }
}

/// Time shares of one side's grand score.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct GrandScoreShare {
    pub side: Side,
    /// `(grand score, share of the time the side was scored)`, by ascending score.
    pub share_by_score: Vec<(u8, f64)>,
    /// Frames in which the side was scored.
    pub frames: usize,
}

impl GrandScoreShare {
    /// The time-weighted mean grand score; `None` when no scored time.
    pub fn mean_score(&self) -> Option<f64> {
        mean_score(&self.share_by_score)
    }
}

/// The time-weighted mean of `(score, share)` pairs; `None` when no share.
pub fn mean_score(share_by_score: &[(u8, f64)]) -> Option<f64> {
    let total: f64 = share_by_score.iter().map(|(_, x)| x).sum();
    (total > 0.0).then(|| {
        share_by_score
            .iter()
            .map(|&(s, x)| f64::from(s) * x)
            .sum::<f64>()
            / total
    })
}

/// Summary of a session: time share per action level (of the headline side), per region score and
/// per grand score of each side.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct SessionSummary {
    pub frames: usize,
    pub scored_frames: usize,
    pub uncertain_frames: usize,
    /// The time the frames stand for, gaps not counted.
    pub duration_secs: f64,
    /// Share of scored time at action level 1..=4.
    pub action_level_share: [f64; 4],
    /// The headline side's action level at least 2, 3 and 4: episodes, longest stretch, total time.
    pub action_level_exposure: Vec<Exposure>,
    /// Share of the whole time with no score.
    pub unscored_share: f64,
    /// The regions that were scored at least once, in [`BodyRegion`] order, left before right.
    pub regions: Vec<RegionShare>,
    /// Each side that was scored at least once, left before right.
    pub grand_score: Vec<GrandScoreShare>,
    /// REBA, when the frames carry it: each side's REBA score shares (1..=15), left before right.
    pub reba_score: Vec<GrandScoreShare>,
    /// Share of REBA-scored time at REBA action level 0..=4 (the side with the higher REBA score).
    pub reba_action_level_share: [f64; 5],
    /// The REBA-scored time, seconds (the denominator of those shares).
    pub reba_scored_secs: f64,
    /// That side's REBA action level at least 2 (medium), 3 (high) and 4 (very high): episodes,
    /// longest stretch, total time.
    pub reba_action_level_exposure: Vec<Exposure>,
    /// The task segments (the frames' phases, e.g. walking, floor pick, handover), in order of first
    /// appearance; empty when no frame had one.
    pub phases: Vec<PhaseSummary>,
    /// Trunk, neck and upper-arm postures held outside ISO 11226's acceptable zone
    /// ([`crate::static_posture`]); a part no frame observed is left out.
    pub static_postures: Vec<StaticPostureSummary>,
    /// The headline side's continuous posture cost, time-weighted over the scored time whose
    /// angles are known ([`PostureCostTime`]).
    pub posture_cost: PostureCostTime,
}

/// A continuous posture cost over time: beside RULA's integer shares, how far into their bands
/// the postures lay.
#[derive(Debug, Clone, Copy, Default, PartialEq, Serialize)]
pub struct PostureCostTime {
    /// The time with a known cost, seconds.
    pub secs: f64,
    /// The cost integrated over that time, RULA points × seconds: sums over sessions divided by
    /// the summed `secs` give their mean.
    pub point_secs: f64,
}

impl PostureCostTime {
    fn add(&mut self, cost: Option<f64>, dt_nanos: f64) {
        if let Some(c) = cost {
            self.secs += dt_nanos * 1e-9;
            self.point_secs += c * dt_nanos * 1e-9;
        }
    }

    /// The time-weighted mean cost; `None` without any time with a cost.
    pub fn mean(&self) -> Option<f64> {
        (self.secs > 0.0).then(|| self.point_secs / self.secs)
    }
}

/// One task segment of a session: its time and its exposure.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct PhaseSummary {
    pub phase: String,
    pub frames: usize,
    /// Separate stretches of this phase.
    pub episodes: usize,
    /// The time in this phase, seconds (gaps not counted).
    pub duration_secs: f64,
    /// Its share of the session's time.
    pub time_share: f64,
    /// Share of the phase's time with no RULA score.
    pub unscored_share: f64,
    /// Share of the phase's scored time at action level 1..=4 (the worse side).
    pub action_level_share: [f64; 4],
    /// Stretches at action level 2, 3, 4 or more within the phase (leaving the phase ends one).
    pub action_level_exposure: Vec<Exposure>,
    /// Share of the phase's REBA-scored time at REBA action level 0..=4 (all zero without REBA).
    pub reba_action_level_share: [f64; 5],
    /// The phase's REBA-scored time, seconds.
    pub reba_scored_secs: f64,
    /// The highest grand score (either side) in the phase; `None` when never scored.
    pub peak_grand_score: Option<u8>,
    /// The headline side's posture cost over the segment's time with one.
    pub posture_cost: PostureCostTime,
}

/// Everything the summary reads of one frame (see [`SummaryBuilder::push`]).
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct SummaryFrame {
    pub stamp_nanos: i64,
    /// `None`: the side was not scored.
    pub left: Option<ScoredSide>,
    pub right: Option<ScoredSide>,
    /// The task segment the frame belongs to; `None`: not labelled.
    pub phase: Option<&'static str>,
    /// Trunk and neck flexion as observed (smoothed as scored, not held over gaps) and each upper
    /// arm's elevation from vertical (`[left,
    /// right]`), radians, for [`crate::static_posture`]; `None`: not observed.
    pub trunk_flexion_rad: Option<f64>,
    pub neck_flexion_rad: Option<f64>,
    pub upper_arm_elevation_rad: [Option<f64>; 2],
}

impl SessionSummary {
    /// One region's shares (`side` `None` for neck, trunk and legs); `None` when never scored.
    pub fn region(&self, region: BodyRegion, side: Option<Side>) -> Option<&RegionShare> {
        self.regions
            .iter()
            .find(|r| r.region == region && r.side == side)
    }

    /// One side's grand-score shares; `None` when never scored.
    pub fn grand(&self, side: Side) -> Option<&GrandScoreShare> {
        self.grand_score.iter().find(|g| g.side == side)
    }

    /// One side's REBA score shares; `None` when never scored with REBA.
    pub fn reba(&self, side: Side) -> Option<&GrandScoreShare> {
        self.reba_score.iter().find(|g| g.side == side)
    }
}

type Entry = SummaryFrame;

impl Entry {
    fn side(&self, side: Side) -> Option<&ScoredSide> {
        match side {
            Side::Left => self.left.as_ref(),
            Side::Right => self.right.as_ref(),
        }
    }

    fn headline(&self) -> Option<&ScoredSide> {
        let key = |s: &ScoredSide| (s.scores.final_score, s.uncertain);
        headline_side(self.left.as_ref().map(key), self.right.as_ref().map(key))
            .and_then(|side| self.side(side))
    }

    /// The side with the higher REBA score (the same tie rule as RULA's headline).
    fn reba_headline(&self) -> Option<RebaBrief> {
        let reba = |side: Side| self.side(side).and_then(|s| s.reba);
        let key = |r: RebaBrief| (r.reba_score, r.uncertain);
        headline_side(reba(Side::Left).map(key), reba(Side::Right).map(key)).and_then(reba)
    }
}

/// Accumulates a [`SessionSummary`] frame by frame (see the module docs for how time is counted).
/// Frames may come in any order; they are put in time order when the summary is made.
#[derive(Debug, Clone)]
pub struct SummaryBuilder {
    max_frame_nanos: i64,
    entries: Vec<Entry>,
    trunk_supported: bool,
}

/// Time and frame count per score, and the stretches at or above each score.
#[derive(Debug, Clone, Default)]
struct Tally {
    time_by_score: BTreeMap<u8, f64>,
    frames: usize,
    runs: Runs,
}

/// Stretches at or above levels 2..=[`Runs::MAX_LEVEL`], frame by frame (time in nanoseconds).
#[derive(Debug, Clone, Default)]
struct Runs {
    /// Per level: (episodes, longest, total, the current stretch's length if one is under way).
    levels: BTreeMap<u8, (usize, f64, f64, Option<f64>)>,
    highest: u8,
}

impl Runs {
    /// RULA's largest region score (upper arm 6) and grand score (7).
    const MAX_LEVEL: u8 = 7;

    /// One frame of `dt` at `value`; `None` (not scored) or `broken` (a gap before it) ends every
    /// stretch under way.
    fn add(&mut self, value: Option<u8>, dt: f64, broken: bool) {
        self.highest = self.highest.max(value.unwrap_or(0));
        for level in 2..=Self::MAX_LEVEL {
            let e = self.levels.entry(level).or_insert((0, 0.0, 0.0, None));
            if broken {
                e.3 = None;
            }
            if value.is_some_and(|v| v >= level) {
                let run = e.3.get_or_insert_with(|| {
                    e.0 += 1;
                    0.0
                });
                *run += dt;
                e.1 = e.1.max(*run);
                e.2 += dt;
            } else {
                e.3 = None;
            }
        }
    }

    /// The levels 2..=`up_to` (seconds).
    fn exposure(&self, up_to: u8) -> Vec<Exposure> {
        self.levels
            .iter()
            .filter(|(&l, _)| l <= up_to)
            .map(|(&at_least, &(episodes, longest, total, _))| Exposure {
                at_least,
                episodes,
                longest_secs: longest * 1e-9,
                total_secs: total * 1e-9,
            })
            .collect()
    }
}

impl Tally {
    fn add(&mut self, score: u8, dt: f64) {
        *self.time_by_score.entry(score).or_default() += dt;
        self.frames += 1;
    }

    fn shares(&self) -> Vec<(u8, f64)> {
        let sum: f64 = self.time_by_score.values().sum();
        self.time_by_score
            .iter()
            .map(|(&s, &t)| (s, share(t, sum)))
            .collect()
    }
}

/// One frame of one region: its score (`None`: not scored, which ends its stretches) into the
/// region's tally. A region never scored gets no tally entry with frames.
fn add_region(
    regions: &mut BTreeMap<(BodyRegion, Option<Side>), Tally>,
    key: (BodyRegion, Option<Side>),
    score: Option<u8>,
    dt: f64,
    broken: bool,
) {
    match score {
        Some(s) => {
            let t = regions.entry(key).or_default();
            t.add(s, dt);
            t.runs.add(Some(s), dt, broken);
        }
        None => {
            if let Some(t) = regions.get_mut(&key) {
                t.runs.add(None, dt, broken);
            }
        }
    }
}

fn share(x: f64, of: f64) -> f64 {
    if of > 0.0 {
        x / of
    } else {
        0.0
    }
}

/// One task segment's time, levels and stretches.
#[derive(Debug, Clone, Default)]
struct PhaseTally {
    frames: usize,
    episodes: usize,
    time: f64,
    unscored: f64,
    level: [f64; 4],
    reba_level: [f64; 5],
    reba_scored: f64,
    peak: Option<u8>,
    runs: Runs,
    cost: PostureCostTime,
}

impl PhaseTally {
    /// One frame of `dt` in this phase; `starts` when the phase starts again here (after another
    /// phase or a gap).
    fn add(&mut self, e: &Entry, dt: f64, starts: bool) {
        self.frames += 1;
        self.episodes += usize::from(starts || self.frames == 1);
        self.time += dt;
        let head = e.headline();
        self.runs
            .add(head.map(|h| h.scores.action_level.clamp(1, 4)), dt, starts);
        match head {
            Some(h) => self.level[usize::from(h.scores.action_level.clamp(1, 4) - 1)] += dt,
            None => self.unscored += dt,
        }
        self.cost.add(head.and_then(|h| h.posture_cost), dt);
        for side in Side::BOTH {
            if let Some(s) = e.side(side) {
                self.peak = Some(
                    self.peak
                        .map_or(s.scores.final_score, |p| p.max(s.scores.final_score)),
                );
            }
        }
        if let Some(r) = e.reba_headline() {
            self.reba_scored += dt;
            self.reba_level[usize::from(r.action_level.min(4))] += dt;
        }
    }

    fn finish(self, phase: &str, total: f64) -> PhaseSummary {
        let scored = self.time - self.unscored;
        PhaseSummary {
            phase: phase.to_owned(),
            frames: self.frames,
            episodes: self.episodes,
            duration_secs: self.time * 1e-9,
            time_share: share(self.time, total),
            unscored_share: share(self.unscored, self.time),
            action_level_share: self.level.map(|x| share(x, scored)),
            action_level_exposure: self.runs.exposure(4),
            reba_action_level_share: self.reba_level.map(|x| share(x, self.reba_scored)),
            reba_scored_secs: self.reba_scored * 1e-9,
            peak_grand_score: self.peak,
            posture_cost: self.cost,
        }
    }
}

impl SummaryBuilder {
    /// `max_frame_nanos`: intervals between frames longer than this are gaps (see the module docs);
    /// usually [`DEFAULT_MAX_FRAME_NANOS`].
    pub fn new(max_frame_nanos: i64) -> Self {
        Self {
            max_frame_nanos,
            entries: Vec::new(),
            trunk_supported: false,
        }
    }

    /// The task has the trunk fully supported (a backrest): a held trunk extension is acceptable in
    /// the static postures ([`crate::static_posture`]). Default: not supported.
    #[must_use]
    pub fn trunk_supported(mut self, supported: bool) -> Self {
        self.trunk_supported = supported;
        self
    }

    /// Adds one assessed frame (its scores, REBA and the trunk, neck and upper-arm angles as observed) in the task
    /// segment `phase` (`None`: not labelled).
    pub fn add(&mut self, frame: &FrameAssessment, phase: Option<&'static str>) {
        self.push(SummaryFrame {
            stamp_nanos: frame.stamp_nanos,
            left: frame.left.as_ref().map(ScoredSide::from),
            right: frame.right.as_ref().map(ScoredSide::from),
            phase,
            trunk_flexion_rad: frame.angles.trunk_flexion_rad,
            neck_flexion_rad: frame.angles.neck_flexion_rad,
            upper_arm_elevation_rad: [
                frame.angles.left.upper_arm_elevation_rad,
                frame.angles.right.upper_arm_elevation_rad,
            ],
        });
    }

    /// Adds one frame as the summary reads it.
    pub fn push(&mut self, frame: SummaryFrame) {
        self.entries.push(frame);
    }

    /// Adds one frame given by its scores, e.g. read back from a recording; `None` for a side that
    /// was not scored.
    pub fn add_scores(
        &mut self,
        stamp_nanos: i64,
        left: Option<ScoredSide>,
        right: Option<ScoredSide>,
    ) {
        self.entries.push(Entry {
            stamp_nanos,
            left,
            right,
            ..SummaryFrame::default()
        });
    }

    /// The time each frame stands for, nanoseconds, for frames in time order.
    fn frame_times(&self, entries: &[Entry]) -> Vec<i64> {
        let intervals: Vec<i64> = entries
            .windows(2)
            .map(|w| w[1].stamp_nanos.saturating_sub(w[0].stamp_nanos).max(0))
            .collect();
        let is_gap = |d: i64| d > self.max_frame_nanos;
        let mut normal: Vec<i64> = intervals.iter().copied().filter(|&d| !is_gap(d)).collect();
        normal.sort_unstable();
        let typical = normal.get(normal.len() / 2).copied().unwrap_or(1).max(1);
        let mut times: Vec<i64> = intervals
            .into_iter()
            .map(|d| if is_gap(d) { typical } else { d })
            .collect();
        if !entries.is_empty() {
            times.push(typical);
        }
        times
    }

    pub fn finish(&self) -> SessionSummary {
        let mut entries = self.entries.clone();
        entries.sort_by_key(|e| e.stamp_nanos);
        let times = self.frame_times(&entries);
        let total: f64 = times.iter().map(|&t| t as f64).sum();
        let mut level = [0.0; 4];
        let mut scored = 0.0;
        let mut unscored = 0.0;
        let mut regions: BTreeMap<(BodyRegion, Option<Side>), Tally> = BTreeMap::new();
        let mut grand: BTreeMap<Side, Tally> = BTreeMap::new();
        let mut scored_frames = 0;
        let mut uncertain_frames = 0;
        let mut level_runs = Runs::default();
        let mut reba: BTreeMap<Side, Tally> = BTreeMap::new();
        let mut reba_level = [0.0; 5];
        let mut reba_scored = 0.0;
        let mut reba_runs = Runs::default();
        let mut cost = PostureCostTime::default();
        let mut phases: Vec<(&'static str, PhaseTally)> = Vec::new();
        let mut previous_phase: Option<&'static str> = None;
        let mut previous: Option<i64> = None;
        for (e, &dt) in entries.iter().zip(&times) {
            // a gap in the recording before this frame ends every stretch
            let broken = previous.is_some_and(|p| e.stamp_nanos - p > self.max_frame_nanos);
            previous = Some(e.stamp_nanos);
            let dt = dt as f64;
            let head = e.headline();
            cost.add(head.and_then(|h| h.posture_cost), dt);
            level_runs.add(head.map(|h| h.scores.action_level.clamp(1, 4)), dt, broken);
            match head {
                Some(h) => {
                    scored_frames += 1;
                    uncertain_frames += usize::from(h.uncertain);
                    scored += dt;
                    level[usize::from(h.scores.action_level.clamp(1, 4) - 1)] += dt;
                }
                None => unscored += dt,
            }
            for region in BodyRegion::ALL {
                if region.is_sided() {
                    for side in Side::BOTH {
                        let score = e.side(side).map(|s| region.score(&s.scores));
                        add_region(&mut regions, (region, Some(side)), score, dt, broken);
                    }
                } else {
                    let score = head.map(|h| region.score(&h.scores));
                    add_region(&mut regions, (region, None), score, dt, broken);
                }
            }
            for side in Side::BOTH {
                if let Some(s) = e.side(side) {
                    grand.entry(side).or_default().add(s.scores.final_score, dt);
                    if let Some(r) = s.reba {
                        reba.entry(side).or_default().add(r.reba_score, dt);
                    }
                }
            }
            if let Some(phase) = e.phase {
                let k = if let Some(k) = phases.iter().position(|(p, _)| *p == phase) {
                    k
                } else {
                    phases.push((phase, PhaseTally::default()));
                    phases.len() - 1
                };
                let tally = &mut phases[k].1;
                tally.add(e, dt, broken || previous_phase != Some(phase));
            }
            // every other phase's stretches end here
            for (p, tally) in &mut phases {
                if Some(*p) != e.phase {
                    tally.runs.add(None, dt, true);
                }
            }
            previous_phase = e.phase;
            let reba_head = e.reba_headline();
            reba_runs.add(reba_head.map(|r| r.action_level.min(4)), dt, broken);
            if let Some(r) = reba_head {
                reba_scored += dt;
                reba_level[usize::from(r.action_level.min(4))] += dt;
            }
        }
        SessionSummary {
            frames: entries.len(),
            scored_frames,
            uncertain_frames,
            duration_secs: total * 1e-9,
            action_level_share: level.map(|x| share(x, scored)),
            action_level_exposure: level_runs.exposure(4),
            unscored_share: share(unscored, total),
            regions: regions
                .into_iter()
                .filter(|(_, t)| t.frames > 0)
                .map(|((region, side), t)| RegionShare {
                    region,
                    side,
                    share_by_score: t.shares(),
                    frames: t.frames,
                    exposure: t.runs.exposure(t.runs.highest),
                })
                .collect(),
            grand_score: grand
                .into_iter()
                .map(|(side, t)| GrandScoreShare {
                    side,
                    share_by_score: t.shares(),
                    frames: t.frames,
                })
                .collect(),
            reba_score: reba
                .into_iter()
                .map(|(side, t)| GrandScoreShare {
                    side,
                    share_by_score: t.shares(),
                    frames: t.frames,
                })
                .collect(),
            reba_action_level_share: reba_level.map(|x| share(x, reba_scored)),
            reba_scored_secs: reba_scored * 1e-9,
            reba_action_level_exposure: if reba_scored > 0.0 {
                reba_runs.exposure(4)
            } else {
                Vec::new()
            },
            phases: phases
                .into_iter()
                .map(|(phase, t)| t.finish(phase, total))
                .collect(),
            static_postures: {
                let angles: Vec<PostureAngles> = entries
                    .iter()
                    .map(|e| PostureAngles {
                        stamp_nanos: e.stamp_nanos,
                        trunk_flexion_rad: e.trunk_flexion_rad,
                        neck_flexion_rad: e.neck_flexion_rad,
                        upper_arm_elevation_rad: e.upper_arm_elevation_rad,
                    })
                    .collect();
                static_postures(&angles, self.max_frame_nanos, self.trunk_supported)
            },
            posture_cost: cost,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::rula::{score_worksheet, RulaInput};

    const MS: i64 = 1_000_000;

    fn side(upper_arm_flexion_deg: f64, neck_flexion_deg: f64) -> ScoredSide {
        let input = RulaInput {
            upper_arm_flexion_deg,
            neck_flexion_deg,
            ..RulaInput::neutral()
        };
        ScoredSide {
            scores: score_worksheet(&input).unwrap().scores,
            uncertain: false,
            reba: None,
            posture_cost: None,
        }
    }

    #[test]
    fn the_posture_cost_is_time_weighted_over_the_frames_that_have_one() {
        // 10 Hz: 1 s at cost 3.2, 1 s without a cost (not counted), 0.5 s at 3.8, in one phase
        let at = |cost: Option<f64>| ScoredSide {
            posture_cost: cost,
            ..side(30.0, 5.0)
        };
        let mut b = SummaryBuilder::new(DEFAULT_MAX_FRAME_NANOS);
        let mut t = 0;
        for (n, cost) in [(10, Some(3.2)), (10, None), (5, Some(3.8))] {
            for _ in 0..n {
                b.push(SummaryFrame {
                    stamp_nanos: t * 100 * MS,
                    left: Some(at(cost)),
                    phase: Some("handover"),
                    ..SummaryFrame::default()
                });
                t += 1;
            }
        }
        let s = b.finish();
        let expected = (3.2 * 1.0 + 3.8 * 0.5) / 1.5;
        for c in [s.posture_cost, s.phases[0].posture_cost] {
            assert!((c.secs - 1.5).abs() < 1e-9, "{c:?}");
            assert!((c.mean().unwrap() - expected).abs() < 1e-9, "{c:?}");
        }
        assert_eq!(PostureCostTime::default().mean(), None);
    }

    #[test]
    fn each_phase_has_its_time_levels_and_stretches() {
        // 10 Hz: 1 s walking at action level 1, 0.5 s floor pick at level 2 (grand 3), 1 s walking,
        // 0.5 s floor pick at level 2.
        let low = side(0.0, 5.0);
        let high = side(60.0, 25.0);
        assert_eq!((low.scores.action_level, high.scores.action_level), (1, 2));
        let mut b = SummaryBuilder::new(DEFAULT_MAX_FRAME_NANOS);
        let mut t = 0;
        for (phase, n, s) in [
            ("walking", 10, low),
            ("floor pick", 5, high),
            ("walking", 10, low),
            ("floor pick", 5, high),
        ] {
            for _ in 0..n {
                b.push(SummaryFrame {
                    stamp_nanos: t * 100 * MS,
                    left: Some(s),
                    phase: Some(phase),
                    ..SummaryFrame::default()
                });
                t += 1;
            }
        }
        let s = b.finish();
        let names: Vec<&str> = s.phases.iter().map(|p| p.phase.as_str()).collect();
        assert_eq!(names, ["walking", "floor pick"]);
        let (walk, pick) = (&s.phases[0], &s.phases[1]);
        assert_eq!((walk.frames, walk.episodes), (20, 2));
        assert!((walk.duration_secs - 2.0).abs() < 1e-9);
        assert!((walk.time_share - 2.0 / 3.0).abs() < 1e-9);
        assert_eq!(walk.action_level_share, [1.0, 0.0, 0.0, 0.0]);
        assert_eq!(pick.action_level_share, [0.0, 1.0, 0.0, 0.0]);
        assert_eq!(pick.peak_grand_score, Some(high.scores.final_score));
        // Two separate stretches at level ≥ 2: walking in between ends the first.
        let e = pick
            .action_level_exposure
            .iter()
            .find(|e| e.at_least == 2)
            .unwrap();
        assert_eq!(e.episodes, 2);
        assert!((e.longest_secs - 0.5).abs() < 1e-9 && (e.total_secs - 1.0).abs() < 1e-9);
        // No angles given: no static postures; no phases given: none.
        assert!(s.static_postures.is_empty());
        let mut b = SummaryBuilder::new(DEFAULT_MAX_FRAME_NANOS);
        b.add_scores(0, Some(low), None);
        assert!(b.finish().phases.is_empty());
    }

    #[test]
    fn reba_shares_are_time_weighted_and_take_the_worse_side() {
        let with_reba = |mut s: ScoredSide, reba_score: u8, action_level: u8| {
            s.reba = Some(RebaBrief {
                reba_score,
                action_level,
                uncertain: false,
            });
            s
        };
        let mut b = SummaryBuilder::new(DEFAULT_MAX_FRAME_NANOS);
        // 300 ms at REBA 3 (left) / 5 (right), then 3 frames of 100 ms at 9 (left) / 2 (right).
        let low = side(0.0, 5.0);
        b.add_scores(0, Some(with_reba(low, 3, 1)), Some(with_reba(low, 5, 2)));
        for t in [300, 400, 500] {
            b.add_scores(
                t * MS,
                Some(with_reba(low, 9, 3)),
                Some(with_reba(low, 2, 1)),
            );
        }
        let s = b.finish();
        let near = |a: f64, b: f64| (a - b).abs() < 1e-12;
        // the worse side: right (level 2) for 300 ms, left (level 3) for 300 ms
        assert!(near(s.reba_action_level_share[2], 0.5), "{s:?}");
        assert!(near(s.reba_action_level_share[3], 0.5), "{s:?}");
        assert_eq!(
            s.reba(Side::Left).unwrap().share_by_score,
            vec![(3, 0.5), (9, 0.5)]
        );
        let at_least_3 = s
            .reba_action_level_exposure
            .iter()
            .find(|e| e.at_least == 3)
            .unwrap();
        assert_eq!(at_least_3.episodes, 1);
        assert!((at_least_3.total_secs - 0.3).abs() < 1e-9);
        // frames without REBA (an older recording): no REBA rows at all
        let mut b = SummaryBuilder::new(DEFAULT_MAX_FRAME_NANOS);
        b.add_scores(0, Some(low), None);
        let s = b.finish();
        assert!(s.reba_score.is_empty() && s.reba_action_level_exposure.is_empty());
        assert_eq!(s.reba_action_level_share, [0.0; 5]);
    }

    #[test]
    fn shares_are_time_weighted_not_frame_counted() {
        // Upper arm score 1 for one frame standing for 300 ms, then score 3 for three frames of 100 ms.
        let mut b = SummaryBuilder::new(DEFAULT_MAX_FRAME_NANOS);
        let low = side(0.0, 5.0);
        let high = side(60.0, 5.0);
        for (t, s) in [(0, low), (300, high), (400, high), (500, high)] {
            b.add_scores(t * MS, Some(s), None);
        }
        let s = b.finish();
        let ua = s.region(BodyRegion::UpperArm, Some(Side::Left)).unwrap();
        // The last frame stands for the median interval (100 ms): 300 of 600 ms at score 1.
        assert_eq!(ua.share_by_score, vec![(1, 0.5), (3, 0.5)]);
        assert_eq!(ua.frames, 4);
        assert_eq!(ua.mean_score(), Some(2.0));
        assert!((s.duration_secs - 0.6).abs() < 1e-12);
        assert!(s.region(BodyRegion::UpperArm, Some(Side::Right)).is_none());
    }

    #[test]
    fn a_gap_counts_for_nothing() {
        // 10 Hz, with 5 s of nothing after the second frame: that frame stands for 100 ms, not 5 s
        // (nor the 1 s cap).
        let mut b = SummaryBuilder::new(DEFAULT_MAX_FRAME_NANOS);
        let low = side(0.0, 5.0);
        let high = side(60.0, 25.0);
        b.add_scores(0, Some(low), Some(low));
        b.add_scores(100 * MS, Some(high), Some(high));
        b.add_scores(5_100 * MS, Some(low), Some(low));
        b.add_scores(5_200 * MS, Some(low), Some(low));
        let s = b.finish();
        assert!((s.duration_secs - 0.4).abs() < 1e-12, "{}", s.duration_secs);
        let neck = s.region(BodyRegion::Neck, None).unwrap();
        assert_eq!(neck.share_by_score, vec![(1, 0.75), (3, 0.25)]);
        let g = s.grand(Side::Right).unwrap();
        assert_eq!(g.frames, 4);
        assert!((g.share_by_score.iter().map(|(_, x)| x).sum::<f64>() - 1.0).abs() < 1e-12);
    }

    #[test]
    fn unscored_time_is_outside_the_region_shares_and_frames_may_come_in_any_order() {
        let mut b = SummaryBuilder::new(DEFAULT_MAX_FRAME_NANOS);
        let low = side(0.0, 5.0);
        b.add_scores(200 * MS, None, None);
        b.add_scores(0, Some(low), Some(low));
        b.add_scores(100 * MS, Some(low), None);
        b.add_scores(300 * MS, None, None);
        let s = b.finish();
        assert_eq!(s.frames, 4);
        assert_eq!(s.scored_frames, 2);
        assert_eq!(s.unscored_share, 0.5);
        assert_eq!(s.action_level_share[0], 1.0);
        let right = s.region(BodyRegion::Wrist, Some(Side::Right)).unwrap();
        assert_eq!((right.frames, right.share_by_score.len()), (1, 1));
        assert_eq!(right.share_by_score[0].1, 1.0);
    }

    #[test]
    fn the_central_regions_are_the_headline_sides() {
        // Left worse (grand score), so neck and trunk come from the left worksheet.
        let mut b = SummaryBuilder::new(DEFAULT_MAX_FRAME_NANOS);
        b.add_scores(0, Some(side(100.0, 25.0)), Some(side(0.0, 5.0)));
        let s = b.finish();
        let neck = s.region(BodyRegion::Neck, None).unwrap();
        assert_eq!(neck.share_by_score, vec![(3, 1.0)]);
        assert!(s
            .regions
            .windows(2)
            .all(|w| (w[0].region, w[0].side) < (w[1].region, w[1].side)));
    }

    #[test]
    fn nothing_in_gives_zeros_not_nan() {
        let s = SummaryBuilder::new(DEFAULT_MAX_FRAME_NANOS).finish();
        assert_eq!(s.frames, 0);
        assert_eq!(s.duration_secs, 0.0);
        assert_eq!(s.unscored_share, 0.0);
        assert!(s.regions.is_empty() && s.grand_score.is_empty());
        // A negative gap threshold makes every interval a gap, without panicking.
        let mut b = SummaryBuilder::new(-1);
        b.add_scores(0, Some(side(0.0, 5.0)), None);
        b.add_scores(MS, Some(side(0.0, 5.0)), None);
        assert_eq!(
            b.finish()
                .region(BodyRegion::UpperArm, Some(Side::Left))
                .unwrap()
                .frames,
            2
        );
    }

    #[test]
    fn episodes_longest_stretch_and_total_at_or_above_a_level() {
        // 10 Hz: upper arm 3 for 0.3 s, 1 for 0.2 s, 3 for 0.5 s, then a 5 s gap, 3 for 0.2 s, one
        // frame unscored, 3 for 0.1 s. Four stretches at >= 3 (the gap and the unscored frame break
        // them), the longest 0.5 s, 1.1 s in all; at >= 2 the same; nothing at >= 4.
        let mut b = SummaryBuilder::new(DEFAULT_MAX_FRAME_NANOS);
        let low = side(0.0, 5.0);
        let high = side(60.0, 5.0);
        let mut t = 0;
        let push = |n: usize, s: Option<ScoredSide>, b: &mut SummaryBuilder, t: &mut i64| {
            for _ in 0..n {
                b.add_scores(*t * MS, s, None);
                *t += 100;
            }
        };
        push(3, Some(high), &mut b, &mut t);
        push(2, Some(low), &mut b, &mut t);
        push(5, Some(high), &mut b, &mut t);
        t += 5_000;
        push(2, Some(high), &mut b, &mut t);
        push(1, None, &mut b, &mut t);
        push(1, Some(high), &mut b, &mut t);
        let s = b.finish();
        let ua = s.region(BodyRegion::UpperArm, Some(Side::Left)).unwrap();
        let at = |l: u8| *ua.exposure.iter().find(|e| e.at_least == l).unwrap();
        assert_eq!(ua.exposure.len(), 2, "levels 2 and 3: {:?}", ua.exposure);
        for l in [2, 3] {
            let e = at(l);
            assert_eq!(e.episodes, 4, "{e:?}");
            assert!((e.longest_secs - 0.5).abs() < 1e-9, "{e:?}");
            assert!((e.total_secs - 1.1).abs() < 1e-9, "{e:?}");
        }
        // the action level: upper arm 3 makes level 2 here (grand score 3 or 4)
        let al2 = s.action_level_exposure[0];
        assert_eq!(al2.at_least, 2);
        assert_eq!(s.action_level_exposure.len(), 3);
        assert!(al2.total_secs <= 1.1 + 1e-9 && al2.episodes <= 4, "{al2:?}");
        assert_eq!(s.action_level_exposure[2].episodes, 0);
    }
}
