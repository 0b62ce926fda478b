//! The recording's messages → the review's numbers ([`ReviewData`], the page's JSON, `version` 1).
//!
//! Frames are the recorded `OperatorPose` messages; each is joined with the `ErgonomicState` of the
//! same capture stamp (the session records both from one fused frame). Strain per landmark is the
//! RULA score of the body region the landmark stands for, on its own side
//! ([`BodyRegion::of_landmark`]), on one scale for every region: 0 for score 1 … 1 for score 7
//! (RULA's highest, [`GRAND_SCORE_MAX`]), so one colour means one score everywhere (legs at 2 are
//! not the red of an upper arm at 6). The lines drawn are the skeleton crate's [`DRAWN_BONES`]. The
//! per-region rows are `ergocell rula track`'s summary ([`ergocell_ergonomics::summary`]) of the
//! recorded scores: time-weighted, gaps not counted, so the two report the same numbers for one
//! session. Angles are turned into degrees here, the report boundary.
//!
//! The robot: its TCP from the recorded markers; each leg it was sent, its holds and the controller's
//! events from the joint trajectory topic and `/ergocell/controller_events` (see [`Robot`]; the
//! feedback folded into its leg); the parts the operator took from the session states' fields (in recordings made before those, their reasons).

use ergocell_bridge::msg::ControllerEventKind as EventKind;
use ergocell_bridge::msg::{
    ControllerEvent, ErgonomicState, JointTrajectory, RebaSide, RebaState, RulaSide, SessionState,
};
use ergocell_ergonomics::assess::BodyRegion;
use ergocell_ergonomics::posture_cost::{cost_from_angles, SideAngles};
use ergocell_ergonomics::rula::{RulaScores, GRAND_SCORE_MAX};
use ergocell_ergonomics::summary::{
    Exposure, GrandScoreShare, RebaBrief, RegionShare, ScoredSide, SessionSummary, SummaryBuilder,
    DEFAULT_MAX_FRAME_NANOS,
};
use std::collections::BTreeMap;

use ergocell_ergonomics::activity::{Activity, ActivityConfig, ActivityTracker};
use ergocell_ergonomics::summary::SummaryFrame;
use ergocell_ergonomics::UpVector;
use ergocell_skeleton::{Landmark, Side, Skeleton3, DRAWN_BONES, LANDMARK_COUNT};
use serde::Serialize;

pub use crate::findings::Findings;
use crate::findings::{findings, Flexions, FrameBrief};
use crate::read::{Recording, Stamped};
use ergocell_ergonomics::warnings::WarningConfig;

/// What the page renders: one session (`ergocell review`) or two side by side (`report --compare`).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ReviewData {
    pub version: u32,
    pub sessions: Vec<SessionReview>,
}

impl ReviewData {
    pub fn new(sessions: Vec<SessionReview>) -> Self {
        Self {
            version: 1,
            sessions,
        }
    }
}

/// One recording, analysed.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct SessionReview {
    pub label: String,
    pub source: Source,
    pub facts: Facts,
    /// The 33 BlazePose landmark names in index order.
    pub landmarks: Vec<&'static str>,
    /// Landmark index pairs drawn as lines.
    pub bones: Vec<[usize; 2]>,
    /// The world's up axis (the recorder's `world` frame is the cell frame, z up).
    pub up: [f64; 3],
    pub frames: Frames,
    pub robot: Robot,
    pub warnings: Vec<Warning>,
    pub regions: Vec<RegionStats>,
    pub angles: Vec<AngleStats>,
    /// The session summary the rows come from (`ergocell rula track`'s numbers for the same frames):
    /// action levels, regions, grand and REBA scores, exposure. `report --summary-csv` writes it.
    pub summary: SessionSummary,
    /// The report's first page: time at each action level, the worst moments, per region what was
    /// found and what to do ([`crate::findings`]).
    pub findings: Findings,
    /// Present when `frames` holds not every recorded frame (a long recording,
    /// [`crate::overview`]): which ones it holds. The summary, rows and distributions are still
    /// over every frame.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub overview: Option<Overview>,
}

/// Which frames a long recording's page holds: every frame within `windows` (the worst moments, at
/// the recorded rate) and, elsewhere, the worst frame of each `bucket_s` seconds.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Overview {
    /// Frames recorded (operator poses, by capture stamp).
    pub frames_recorded: usize,
    /// Of them, on the page.
    pub frames_kept: usize,
    /// Outside the windows, one frame (the highest action level, then grand score) per this many
    /// seconds.
    pub bucket_s: f64,
    /// Spans kept at the recorded rate, seconds from the recording's first message, in order.
    pub windows: Vec<[f64; 2]>,
}

/// Where the numbers come from.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Source {
    pub file: String,
    pub bytes: u64,
    pub messages: u64,
    pub complete: bool,
    pub problems: Vec<String>,
}

/// The session's facts, from its `SessionState` messages.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Facts {
    pub height_m: Option<f64>,
    pub height_uncertainty_m: Option<f64>,
    pub height_class: Option<String>,
    /// How the class was decided (`interval`, `expected_rula`, `most_probable`); `None` when not
    /// decided or recorded before the decision carried it.
    pub decision_basis: Option<String>,
    /// The probability that the class is the operator's true class.
    pub class_probability: Option<f64>,
    /// Expected RULA grand score with the class minus with the operator's true class.
    pub expected_rula_cost: Option<f64>,
    pub trajectory_sha256: Option<String>,
    pub approved_by: Vec<String>,
    pub states: Vec<StateChange>,
    /// The cell's cycle: each part the operator took at the handover point (from the states'
    /// fields; in recordings made before them, from their reasons), in order.
    pub parts_taken: Vec<PartTaken>,
}

/// One part the operator took from the robot at the handover point.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct PartTaken {
    pub t: f64,
    /// 1 for the session's first part.
    pub part: u32,
    /// "left" or "right"; `None` when the reason does not say.
    pub hand: Option<String>,
    /// How close that hand came to the handover point, metres.
    pub distance_m: Option<f64>,
    /// The state's reason, as recorded.
    pub reason: String,
}

/// One recorded session-state message.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct StateChange {
    pub t: f64,
    pub state: String,
    pub reason: String,
}

/// Per-frame series, all of the same length (`t.len()`).
#[derive(Debug, Clone, Default, PartialEq, Serialize)]
pub struct Frames {
    /// Seconds from the recording's first message.
    pub t: Vec<f64>,
    /// 99 numbers per frame (x, y, z of each landmark, metres); `None` where not fused.
    pub positions: Vec<Vec<Option<f64>>>,
    /// 33 numbers per frame in 0..1: the RULA score of the landmark's region, 0 for score 1 … 1 for
    /// score 7, one scale for every region; `None` where the region was not scored.
    pub strain: Vec<Vec<Option<f64>>>,
    pub grand_left: Vec<Option<u8>>,
    pub grand_right: Vec<Option<u8>>,
    pub action_left: Vec<Option<u8>>,
    pub action_right: Vec<Option<u8>>,
    /// The side's score rests on low-confidence landmarks or held inputs (never scored lower for
    /// it); false when not scored.
    pub uncertain_left: Vec<bool>,
    pub uncertain_right: Vec<bool>,
    /// The frame's headline action level (worse side), 0 when neither side was scored.
    pub action_level: Vec<u8>,
    /// The frame's task segment ([`PHASES`]); `None` when the skeleton had no hips or the frame was
    /// not assessed.
    pub phase: Vec<Option<&'static str>>,
    /// Each side's REBA score (1..=15) of the frame; `None` when not scored or not recorded.
    pub reba_left: Vec<Option<u8>>,
    pub reba_right: Vec<Option<u8>>,
    /// How sure each region's band is, per side and frame: the probability that the angle's band
    /// is right (two decimals), in the order upper arm, lower arm, wrist, neck, trunk; `None` where
    /// not known. An empty row when the side was not scored or the recording predates it.
    pub band_left: Vec<Vec<Option<f64>>>,
    pub band_right: Vec<Vec<Option<f64>>>,
}

/// The robot as recorded: its TCP and the handover point (`/ergocell/robot_markers`), the legs it was
/// sent and the holds (the joint trajectory topic), and what the robot side reported
/// (`/ergocell/controller_events`).
#[derive(Debug, Clone, Default, PartialEq, Serialize)]
pub struct Robot {
    pub tcp: Option<TcpTrack>,
    pub handover_point: Option<[f64; 3]>,
    /// Each leg sent (a `JointTrajectory` with points, or one FollowJointTrajectory goal), in order.
    pub legs: Vec<RobotLeg>,
    /// When the robot was held (an empty `JointTrajectory`), seconds.
    pub holds: Vec<f64>,
    /// The controller events, in order, without the feedback (folded into its leg).
    pub events: Vec<RobotEvent>,
}

/// One robot leg.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct RobotLeg {
    /// When it was sent, seconds.
    pub t_start: f64,
    /// When it ended: as reported (the controller's answer), cut short (a hold, the next leg), or,
    /// with `end_known` false, as planned (`t_start + planned_s`).
    pub t_end: f64,
    /// The trajectory's duration (its last point's time from start), seconds.
    pub planned_s: f64,
    /// "home → handover", "handover → home", or "" when it cannot be told (for people).
    pub leg: String,
    /// The same as `ControllerEvent::LEG_*` (`LEG_NONE` when it cannot be told).
    pub leg_id: u8,
    /// The controller's status at its end (succeeded, aborted, canceled, …), or rejected, failed,
    /// no_response; held or replaced when a hold or the next leg came before its planned end; sent
    /// when nothing reported its end.
    pub outcome: String,
    /// `t_end` was reported or seen (not only planned).
    pub end_known: bool,
    /// The controller's feedback messages for it; `None` when it reported none and no result.
    pub feedback_count: Option<u32>,
    /// The largest joint error its feedback reported, radians; `None` when not given.
    pub max_error: Option<f64>,
    /// The words on its end (the controller's error string, the failure), "" when none.
    pub text: String,
}

/// One controller event (not feedback).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct RobotEvent {
    pub t: f64,
    /// goal_sent | accepted | rejected | no_response | failed | finished | cancel_requested |
    /// monitor | driver
    pub kind: String,
    pub leg: String,
    pub status: String,
    pub error_code: i32,
    pub text: String,
    /// monitor: the largest deviation as a share of its tolerance; `None` when not known.
    pub max_error: Option<f64>,
}

/// The TCP position over time.
#[derive(Debug, Clone, Default, PartialEq, Serialize)]
pub struct TcpTrack {
    pub t: Vec<f64>,
    pub positions: Vec<[f64; 3]>,
}

/// One posture warning event.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Warning {
    pub t: f64,
    pub kind: String,
    pub region: String,
    pub side: String,
    pub score: u8,
    /// The region's angle when the warning was raised, changed or cleared, degrees; `None` when not
    /// finite (the legs have none).
    pub angle_deg: Option<f64>,
    pub action_level: u8,
    pub message: String,
    /// The probability that the warning's band was right when it was raised, changed or cleared;
    /// `None` when not known (the legs, a recording made before it).
    pub band_probability: Option<f64>,
    /// Raised or changed while the band was less than 90 % sure.
    pub near_limit: bool,
}

/// One body region's scores (or one side's grand score) over the time it was scored, from
/// [`ergocell_ergonomics::summary`].
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct RegionStats {
    /// The region's name in words ("upper arm"), or "grand score".
    pub name: String,
    /// "left", "right", or "" for the neck, trunk and legs (scored once for the body).
    pub side: &'static str,
    pub max_score: u8,
    /// Which scale the scores are on: the page colours RULA's on one scale for every row (score 1 …
    /// 7), the others each on its own.
    pub scale: ScoreScale,
    /// Time-weighted mean score; `None` when never scored.
    pub mean: Option<f64>,
    /// Share of the scored time at score 1..=max_score (time-weighted, gaps not counted).
    pub time_share: Vec<f64>,
    /// Frames in which it was scored.
    pub samples: usize,
    /// Exposure over time: for each score from 2 to the highest that occurred, the stretches at or
    /// above it (episodes, longest, total; [`ergocell_ergonomics::summary::Exposure`]).
    pub exposure: Vec<Exposure>,
}

/// The scale a row's scores are on.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum ScoreScale {
    /// A RULA region or grand score, 1..=7 at most.
    Rula,
    /// RULA's action level, 1..=4.
    ActionLevel,
    /// A REBA score, 1..=15.
    Reba,
}

/// The distribution of one joint angle, degrees.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct AngleStats {
    pub name: String,
    pub side: &'static str,
    pub unit: &'static str,
    pub bin_edges: Vec<f64>,
    pub counts: Vec<u64>,
    pub mean: Option<f64>,
    pub p95: Option<f64>,
    pub samples: usize,
    /// Where this angle's RULA contribution changes (band edges and adjustment thresholds, degrees),
    /// to draw over the distribution; empty when unknown.
    pub score_edges_deg: Vec<f64>,
}

/// The strain of a RULA score on the page's one scale: 0 (score 1) .. 1 (score 7, RULA's highest),
/// whatever the region; `None` for 0 (not scored).
fn strain_of(score: u8) -> Option<f64> {
    if score == 0 {
        return None;
    }
    let top = f64::from(GRAND_SCORE_MAX);
    Some(((f64::from(score) - 1.0) / (top - 1.0)).clamp(0.0, 1.0))
}

fn scored(s: &RulaSide) -> Option<&RulaSide> {
    s.scored.then_some(s)
}

/// A recorded side as the summary reads it, with its REBA when recorded; `None` when not scored.
pub(crate) fn scored_side(s: &RulaSide, reba: Option<&RebaSide>) -> Option<ScoredSide> {
    let reba = reba.filter(|r| r.scored).map(|r| RebaBrief {
        reba_score: r.reba_score,
        action_level: r.action_level,
        uncertain: r.uncertain,
    });
    scored(s).map(|s| ScoredSide {
        scores: RulaScores {
            upper_arm_score: s.upper_arm_score,
            lower_arm_score: s.lower_arm_score,
            wrist_score: s.wrist_score,
            wrist_twist_score: s.wrist_twist_score,
            posture_score_a: s.posture_score_a,
            score_c_wrist_arm: s.score_c_wrist_arm,
            neck_score: s.neck_score,
            trunk_score: s.trunk_score,
            legs_score: s.legs_score,
            posture_score_b: s.posture_score_b,
            score_d_neck_trunk_legs: s.score_d_neck_trunk_legs,
            final_score: s.final_score,
            action_level: s.action_level,
        },
        uncertain: s.uncertain,
        reba,
        // from the frame's pose, where [`summarise`] has it
        posture_cost: None,
    })
}

/// Strain of every landmark in one frame.
fn frame_strain(e: Option<&ErgonomicState>) -> Vec<Option<f64>> {
    let (left, right) = e.map_or((None, None), |e| {
        (scored_side(&e.left, None), scored_side(&e.right, None))
    });
    Landmark::ALL
        .iter()
        .map(|&lm| {
            let (region, side) = BodyRegion::of_landmark(lm);
            let of = |s: Option<ScoredSide>| s.and_then(|s| strain_of(region.score(&s.scores)));
            match side {
                Some(Side::Left) => of(left),
                Some(Side::Right) => of(right),
                // Scored once for the body: the worse of the two worksheets.
                None => match (of(left), of(right)) {
                    (Some(a), Some(b)) => Some(a.max(b)),
                    (a, b) => a.or(b),
                },
            }
        })
        .collect()
}

/// The page's resolution for positions, decimals of a metre: 1 mm (the fusion's error is ~1 cm). Rounding the JSON's
/// numbers to what they mean halves a recording's page (2.3 → ~1 KB a frame).
const MM: u8 = 3;

/// `v` rounded to `decimals` decimal places (scaled by an exact power of ten, then divided, so the
/// JSON prints `0.175`, not `0.17500000000000002`).
pub(crate) fn round_to(v: f64, decimals: u8) -> f64 {
    let k = 10f64.powi(i32::from(decimals));
    (v * k).round() / k
}

/// Seconds of `t` after `t0`.
pub(crate) fn secs(t: u64, t0: u64) -> f64 {
    t.saturating_sub(t0) as f64 * 1e-9
}

pub(crate) fn finite(x: f64) -> Option<f64> {
    x.is_finite().then_some(x)
}

/// Analyses one recording; `label` names it on the page (usually the file name).
pub fn analyse(rec: &Recording, label: &str) -> SessionReview {
    analyse_with(rec, label, None)
}

/// What a streamed pass measured over every frame of a recording of which the [`Recording`] given to
/// [`analyse_with`] holds only some frames ([`crate::overview`]): the summary, each kept frame's
/// facts (its task segment), the angle distributions and what was malformed.
pub(crate) struct WholeRecording {
    pub(crate) summary: SessionSummary,
    pub(crate) facts: BTreeMap<u64, FrameFacts>,
    pub(crate) angles: Vec<AngleStats>,
    /// What was wrong with the poses ([`AngleSamples::problems`]) and their order.
    pub(crate) problems: Vec<String>,
    /// `None` when every frame was kept.
    pub(crate) overview: Option<Overview>,
}

/// [`analyse`], with the numbers over all frames from `whole` when the recording holds only some.
pub(crate) fn analyse_with(
    rec: &Recording,
    label: &str,
    whole: Option<WholeRecording>,
) -> SessionReview {
    let t0 = rec.first_log_time_nanos.unwrap_or(0);
    let mut problems = rec.problems.clone();

    // Frames: poses joined with the ergonomics of the same log time.
    // Frames by their capture stamp (the header's): the log time is when the session processed
    // them, and one step can fuse two frames.
    let stamp = |h: &ergocell_bridge::msg::Header| u64::try_from(h.stamp.to_nanos()).unwrap_or(0);
    let mut ergonomics: Vec<&Stamped<ErgonomicState>> = rec.ergonomics.iter().collect();
    ergonomics.sort_by_key(|e| stamp(&e.message.header));
    let ergonomics_at = |t: u64| {
        ergonomics
            .binary_search_by_key(&t, |e| stamp(&e.message.header))
            .ok()
            .map(|i| &ergonomics[i].message)
    };
    let mut reba: Vec<&RebaState> = rec.reba.iter().map(|r| &r.message).collect();
    reba.sort_by_key(|r| stamp(&r.header));
    let reba_at = |t: u64| {
        reba.binary_search_by_key(&t, |r| stamp(&r.header))
            .ok()
            .map(|i| reba[i])
    };
    let mut poses: Vec<_> = rec.poses.iter().collect();
    poses.sort_by_key(|p| stamp(&p.message.header));
    poses.dedup_by_key(|p| stamp(&p.message.header));
    let robot = robot(rec, t0);
    // Task segments and the trunk and neck angles, by capture stamp (see `phase_of`).
    let (by_stamp, whole) = if let Some(mut w) = whole {
        (std::mem::take(&mut w.facts), Some(w))
    } else {
        let handovers = handover_spans(&robot);
        let mut activity = ActivityTracker::new(ActivityConfig::default(), &UpVector::z()).ok();
        let mut by_stamp: BTreeMap<u64, FrameFacts> = BTreeMap::new();
        for p in &poses {
            let m = &p.message;
            let t = stamp(&m.header);
            let act =
                skeleton_of(m, t).and_then(|sk| activity.as_mut().and_then(|a| a.update(&sk)));
            by_stamp.insert(t, frame_facts(m, phase_of(act, secs(t, t0), &handovers)));
        }
        (by_stamp, None)
    };
    let mut frames = Frames::default();
    let mut briefs: Vec<FrameBrief> = Vec::new();
    let mut angle_samples = AngleSamples::default();
    for p in poses {
        let m = &p.message;
        if !angle_samples.push(m) {
            continue;
        }
        let t = stamp(&m.header);
        let e = ergonomics_at(t);
        frames.t.push(round_to(secs(t, t0), 6));
        // Only an assessed frame is in a segment (the summary counts those), so the CSV's rows per
        // segment add up to the page's segment times.
        frames
            .phase
            .push(e.and_then(|_| by_stamp.get(&t)).and_then(|f| f.phase));
        frames.positions.push(
            (0..LANDMARK_COUNT)
                .flat_map(|i| {
                    let xyz = [m.x[i], m.y[i], m.z[i]];
                    let ok = xyz.iter().all(|v| v.is_finite());
                    xyz.map(|v| ok.then_some(round_to(v, MM)))
                })
                .collect(),
        );
        frames.strain.push(
            frame_strain(e)
                .into_iter()
                .map(|v| v.map(|v| round_to(v, 2)))
                .collect(),
        );
        let side = |s: Option<&RulaSide>, f: fn(&RulaSide) -> u8| s.and_then(scored).map(f);
        frames
            .grand_left
            .push(side(e.map(|e| &e.left), |s| s.final_score));
        frames
            .grand_right
            .push(side(e.map(|e| &e.right), |s| s.final_score));
        frames
            .action_left
            .push(side(e.map(|e| &e.left), |s| s.action_level));
        frames
            .action_right
            .push(side(e.map(|e| &e.right), |s| s.action_level));
        frames.action_level.push(e.map_or(0, |e| e.action_level));
        briefs.push(FrameBrief {
            t: secs(t, t0),
            action_level: e.map_or(0, |e| e.action_level),
            left: e.and_then(|e| scored_side(&e.left, None)).map(|s| s.scores),
            right: e
                .and_then(|e| scored_side(&e.right, None))
                .map(|s| s.scores),
            flexion_deg: Flexions::from_recorded(&m.angle_names, &m.angle_rad),
        });
        let r = reba_at(t);
        let reba_score = |s: Option<&RebaSide>| s.filter(|s| s.scored).map(|s| s.reba_score);
        frames.reba_left.push(reba_score(r.map(|r| &r.left)));
        frames.reba_right.push(reba_score(r.map(|r| &r.right)));
        let uncertain = |s: Option<&RulaSide>| s.and_then(scored).is_some_and(|s| s.uncertain);
        frames.uncertain_left.push(uncertain(e.map(|e| &e.left)));
        frames.uncertain_right.push(uncertain(e.map(|e| &e.right)));
        let bands = |p: Option<&Vec<f64>>| -> Vec<Option<f64>> {
            p.map_or_else(Vec::new, |p| {
                p.iter()
                    .map(|v| (v.is_finite() && (0.0..=1.0).contains(v)).then(|| round_to(*v, 2)))
                    .collect()
            })
        };
        frames
            .band_left
            .push(bands(e.map(|e| &e.left_band_probability)));
        frames
            .band_right
            .push(bands(e.map(|e| &e.right_band_probability)));
    }
    let (summary, angles, overview) = if let Some(w) = whole {
        problems.extend(w.problems);
        (w.summary, w.angles, w.overview)
    } else {
        // Regions over the scored time of the recording (every ErgonomicState, whether or not
        // its pose was recorded), summarised as `ergocell rula track` does.
        let summary = summarise(
            ergonomics.iter().map(|e| {
                let e = &e.message;
                let t = stamp(&e.header);
                let r = reba_at(t);
                (
                    t,
                    ScoredFrame {
                        stamp_nanos: e.header.stamp.to_nanos(),
                        left: scored_side(&e.left, r.map(|r| &r.left)),
                        right: scored_side(&e.right, r.map(|r| &r.right)),
                    },
                )
            }),
            |t| by_stamp.get(&t).copied().unwrap_or_default(),
        );
        problems.extend(angle_samples.problems());
        (summary, angle_samples.stats(), None)
    };
    let regions = region_rows(&summary);
    let warnings: Vec<Warning> = rec
        .warnings
        .iter()
        .map(|w| Warning {
            // The frame the warning was raised on (its header), on the frames' clock.
            t: secs(header_or_log_time(&w.message.header, w.log_time_nanos), t0),
            kind: w.message.kind.clone(),
            region: w.message.region.clone(),
            side: w.message.side.clone(),
            score: w.message.region_score,
            angle_deg: Some(w.message.angle_deg)
                .filter(|a| a.is_finite())
                .map(|a| round_to(a, 1)),
            action_level: w.message.action_level,
            message: w.message.message.clone(),
            band_probability: Some(w.message.band_probability)
                .filter(|p| p.is_finite() && (0.0..=1.0).contains(p))
                .map(|p| round_to(p, 3)),
            near_limit: w.message.near_limit,
        })
        .collect();
    let findings = findings(&summary, &briefs, &warnings, &WarningConfig::default());

    SessionReview {
        label: label.to_owned(),
        source: Source {
            file: label.to_owned(),
            bytes: rec.bytes,
            messages: rec.messages,
            complete: rec.complete,
            problems,
        },
        facts: facts(&rec.states, t0),
        landmarks: Landmark::ALL.iter().map(|l| l.name()).collect(),
        bones: DRAWN_BONES
            .iter()
            .map(|(a, b)| [a.index(), b.index()])
            .collect(),
        up: [0.0, 0.0, 1.0],
        frames,
        robot,
        warnings,
        regions,
        angles,
        summary,
        findings,
        overview,
    }
}

/// The joint angles of every pose, for their distributions, and the poses that could not be read.
#[derive(Debug, Clone, Default)]
pub(crate) struct AngleSamples {
    /// Per angle name, in the recorder's order: the values in degrees.
    samples: Vec<(String, Vec<f64>)>,
    malformed: usize,
    implausible: usize,
}

impl AngleSamples {
    /// Takes one pose's angles; `false` when the pose is not 33 landmarks (no frame).
    pub(crate) fn push(&mut self, m: &ergocell_bridge::msg::OperatorPose) -> bool {
        if m.x.len() != LANDMARK_COUNT || m.y.len() != LANDMARK_COUNT || m.z.len() != LANDMARK_COUNT
        {
            self.malformed += 1;
            return false;
        }
        if m.angle_names.len() != m.angle_rad.len() {
            self.malformed += 1;
            return true;
        }
        // Kept in the recorder's order, whether or not an angle was observed in this frame.
        for (name, &v) in m.angle_names.iter().zip(&m.angle_rad) {
            let k = if let Some(k) = self.samples.iter().position(|(n, _)| n == name) {
                k
            } else {
                self.samples.push((name.clone(), Vec::new()));
                self.samples.len() - 1
            };
            match finite(v).map(f64::to_degrees) {
                Some(deg) if deg.abs() <= MAX_ANGLE_DEG => self.samples[k].1.push(deg),
                Some(_) => self.implausible += 1,
                None => {}
            }
        }
        true
    }

    /// What was wrong with the poses, for a person.
    pub(crate) fn problems(&self) -> Vec<String> {
        let mut out = Vec::new();
        if self.implausible > 0 {
            out.push(format!(
                "{} joint angle value(s) beyond ±{MAX_ANGLE_DEG}° left out of the distributions (damaged data)",
                self.implausible
            ));
        }
        if self.malformed > 0 {
            out.push(format!(
                "{} operator pose message(s) skipped: not 33 landmarks, or angle names and values of different lengths",
                self.malformed
            ));
        }
        out
    }

    pub(crate) fn stats(self) -> Vec<AngleStats> {
        self.samples
            .into_iter()
            .filter(|(_, samples)| !samples.is_empty())
            .map(|(name, samples)| angle_stats(&name, &samples))
            .collect()
    }
}

/// One recorded frame's scores as the summary reads them (REBA attached to its side).
#[derive(Debug, Clone, Copy)]
pub(crate) struct ScoredFrame {
    pub(crate) stamp_nanos: i64,
    pub(crate) left: Option<ScoredSide>,
    pub(crate) right: Option<ScoredSide>,
}

/// The session summary of scored frames (by capture stamp, in time order), each with what its pose
/// says ([`FrameFacts`]): the one computation behind the review's rows and `ergocell exposure`.
pub(crate) fn summarise(
    frames: impl Iterator<Item = (u64, ScoredFrame)>,
    facts_at: impl Fn(u64) -> FrameFacts,
) -> SessionSummary {
    let mut summary = SummaryBuilder::new(DEFAULT_MAX_FRAME_NANOS);
    for (t, f) in frames {
        let facts = facts_at(t);
        // The recording keeps each side's scores and the angles they were scored from: the cost
        // of the worksheet they came from.
        let with_cost = |side: Option<ScoredSide>, angles: Option<SideAngles>| {
            side.map(|s| ScoredSide {
                posture_cost: s.posture_cost.or_else(|| {
                    // The cell has no seated task setting: the trunk is never "seated, well
                    // supported" in a recording (record the flag if one is added).
                    angles.and_then(|a| cost_from_angles(s.scores.final_score, &a, false))
                }),
                ..s
            })
        };
        summary.push(SummaryFrame {
            stamp_nanos: f.stamp_nanos,
            left: with_cost(f.left, facts.side_angles[0]),
            right: with_cost(f.right, facts.side_angles[1]),
            phase: facts.phase,
            trunk_flexion_rad: facts.trunk_flexion_rad,
            neck_flexion_rad: facts.neck_flexion_rad,
            upper_arm_elevation_rad: facts.upper_arm_elevation_rad,
        });
    }
    summary.finish()
}

/// A recorded pose's facts: its task segment and the angles ISO 11226 judges.
pub(crate) fn frame_facts(
    m: &ergocell_bridge::msg::OperatorPose,
    phase: Option<&'static str>,
) -> FrameFacts {
    let angle = |name: &str| {
        m.angle_names
            .iter()
            .position(|n| n == name)
            .and_then(|k| m.angle_rad.get(k).copied())
            .and_then(finite)
    };
    FrameFacts {
        phase,
        trunk_flexion_rad: angle("trunk_flexion"),
        neck_flexion_rad: angle("neck_flexion"),
        upper_arm_elevation_rad: [
            angle("left_upper_arm_elevation"),
            angle("right_upper_arm_elevation"),
        ],
        side_angles: ["left", "right"].map(|side| {
            let deg = |name: &str| angle(name).map(f64::to_degrees);
            Some(SideAngles {
                upper_arm_flexion_deg: deg(&format!("{side}_upper_arm_flexion"))?,
                lower_arm_flexion_deg: deg(&format!("{side}_elbow_flexion"))?,
                wrist_flexion_deg: deg(&format!("{side}_wrist_flexion"))?,
                neck_flexion_deg: deg("neck_flexion")?,
                trunk_flexion_deg: deg("trunk_flexion")?,
            })
        }),
    }
}

/// What a frame's pose says beyond its scores: its task segment and the angles ISO 11226 judges.
#[derive(Debug, Clone, Copy, Default)]
pub(crate) struct FrameFacts {
    pub(crate) phase: Option<&'static str>,
    pub(crate) trunk_flexion_rad: Option<f64>,
    pub(crate) neck_flexion_rad: Option<f64>,
    pub(crate) upper_arm_elevation_rad: [Option<f64>; 2],
    /// Each side's five angled regions as RULA scored them (left, right), for the posture cost;
    /// `None` where one of them was not observed.
    pub(crate) side_angles: [Option<SideAngles>; 2],
}

/// The task segment names of the review, in precedence order: walking and floor pick from the
/// skeleton, handover while the robot brings or holds a part, otherwise in place.
pub const PHASES: [&str; 4] = ["walking", "floor pick", "handover", "in place"];

/// A frame's task segment: walking and floor pick from the skeleton
/// ([`ergocell_ergonomics::activity`]); otherwise a handover while the robot brings a part or waits
/// with it (from a `home → handover` leg's start to the next leg's start), otherwise in place.
/// `None` when the skeleton had no hips.
pub(crate) fn phase_of(
    activity: Option<Activity>,
    t: f64,
    handovers: &[(f64, f64)],
) -> Option<&'static str> {
    Some(match activity? {
        Activity::Walking => PHASES[0],
        Activity::FloorPick => PHASES[1],
        Activity::InPlace if handovers.iter().any(|&(a, b)| a <= t && t < b) => PHASES[2],
        Activity::InPlace => PHASES[3],
    })
}

/// The times the robot brought a part and waited with it: each `home → handover` leg's start to the
/// start of the leg after it (or the leg's end when it is the last), seconds.
fn handover_spans(robot: &Robot) -> Vec<(f64, f64)> {
    handover_spans_of(&robot.legs)
}

/// [`handover_spans`] of a leg list.
pub(crate) fn handover_spans_of(legs: &[RobotLeg]) -> Vec<(f64, f64)> {
    legs.iter()
        .enumerate()
        .filter(|(_, l)| l.leg_id == ControllerEvent::LEG_TO_HANDOVER)
        .map(|(k, l)| {
            let end = legs
                .get(k + 1)
                .map_or(l.t_end, |next| next.t_start)
                .max(l.t_start);
            (l.t_start, end)
        })
        .collect()
}

/// The skeleton of a recorded pose (NaN landmarks left out), or `None` when it is malformed.
pub(crate) fn skeleton_of(m: &ergocell_bridge::msg::OperatorPose, t: u64) -> Option<Skeleton3> {
    if m.x.len() != LANDMARK_COUNT || m.y.len() != LANDMARK_COUNT || m.z.len() != LANDMARK_COUNT {
        return None;
    }
    let points: [Option<nalgebra::Point3<f64>>; LANDMARK_COUNT] = std::array::from_fn(|i| {
        let p = nalgebra::Point3::new(m.x[i], m.y[i], m.z[i]);
        p.iter().all(|v| v.is_finite()).then_some(p)
    });
    Skeleton3::from_optional_points(i64::try_from(t).ok()?, &points).ok()
}

/// A message's header stamp, or its log time when the header has none.
fn header_or_log_time(h: &ergocell_bridge::msg::Header, log_time_nanos: u64) -> u64 {
    u64::try_from(h.stamp.to_nanos())
        .ok()
        .filter(|&t| t > 0)
        .unwrap_or(log_time_nanos)
}

/// The page's rows: every body region (the arm regions per side), then each side's grand score,
/// whether or not scored (a row never scored has no mean and no shares).
fn region_rows(summary: &SessionSummary) -> Vec<RegionStats> {
    let side_name = |side: Option<Side>| side.map_or("", Side::name);
    let mut rows = Vec::new();
    for region in BodyRegion::ALL {
        for &side in region.sides() {
            let share = summary.region(region, side);
            rows.push(region_stats(
                region.words().to_owned(),
                side_name(side),
                region.max_score(),
                share.map_or(&[][..], |r| &r.share_by_score),
                share.map_or(0, |r| r.frames),
                share.and_then(RegionShare::mean_score),
                share.map_or_else(Vec::new, |r| r.exposure.clone()),
            ));
        }
    }
    for side in Side::BOTH {
        let share = summary.grand(side);
        rows.push(region_stats(
            "grand score".to_owned(),
            side.name(),
            GRAND_SCORE_MAX,
            share.map_or(&[][..], |g| &g.share_by_score),
            share.map_or(0, |g| g.frames),
            share.and_then(GrandScoreShare::mean_score),
            Vec::new(),
        ));
    }
    // The action level of the worse side, with its exposure over time.
    let levels: Vec<(u8, f64)> = (1u8..)
        .zip(summary.action_level_share)
        .filter(|(_, x)| *x > 0.0)
        .collect();
    rows.push(RegionStats {
        scale: ScoreScale::ActionLevel,
        ..region_stats(
            "action level".to_owned(),
            "",
            4,
            &levels,
            summary.scored_frames,
            ergocell_ergonomics::summary::mean_score(&levels),
            summary.action_level_exposure.clone(),
        )
    });
    // REBA beside RULA, per side (only when the recording has it).
    for side in Side::BOTH {
        if let Some(share) = summary.reba(side) {
            rows.push(RegionStats {
                scale: ScoreScale::Reba,
                ..region_stats(
                    "REBA score".to_owned(),
                    side.name(),
                    ergocell_ergonomics::reba::REBA_SCORE_MAX,
                    &share.share_by_score,
                    share.frames,
                    share.mean_score(),
                    Vec::new(),
                )
            });
        }
    }
    rows
}

/// One row: `share_by_score` (sparse, from the summary) spread over scores 1..=`max` (a score
/// outside the range, damaged data, is drawn at the nearest end).
fn region_stats(
    name: String,
    side: &'static str,
    max: u8,
    share_by_score: &[(u8, f64)],
    samples: usize,
    mean: Option<f64>,
    exposure: Vec<Exposure>,
) -> RegionStats {
    let mut time_share = vec![0.0; usize::from(max)];
    for &(score, share) in share_by_score {
        time_share[usize::from(score.clamp(1, max) - 1)] += share;
    }
    RegionStats {
        name,
        side,
        max_score: max,
        scale: ScoreScale::Rula,
        mean,
        time_share,
        samples,
        exposure,
    }
}

/// Splits `left_elbow_flexion` into ("elbow flexion", "left").
fn angle_label(name: &str) -> (String, &'static str) {
    let (rest, side) = if let Some(r) = name.strip_prefix("left_") {
        (r, "left")
    } else if let Some(r) = name.strip_prefix("right_") {
        (r, "right")
    } else {
        (name, "")
    };
    (rest.replace('_', " "), side)
}

/// No joint angle is larger than a full turn; a larger recorded value is damaged data.
pub const MAX_ANGLE_DEG: f64 = 360.0;

/// Histogram of `samples` (degrees, within ±[`MAX_ANGLE_DEG`]) in 10° bins covering them, with mean
/// and 95th percentile.
fn angle_stats(name: &str, samples: &[f64]) -> AngleStats {
    let (label, side) = angle_label(name);
    let mut sorted = samples.to_vec();
    sorted.sort_by(f64::total_cmp);
    let n = sorted.len();
    let (bin_edges, counts) = match (sorted.first(), sorted.last()) {
        (Some(&lo), Some(&hi)) if lo >= -MAX_ANGLE_DEG && hi <= MAX_ANGLE_DEG => {
            const BIN_DEG: f64 = 10.0;
            let lo = (lo / BIN_DEG).floor() * BIN_DEG;
            let hi = ((hi / BIN_DEG).floor() + 1.0) * BIN_DEG;
            let bins = ((hi - lo) / BIN_DEG).round() as usize;
            let edges: Vec<f64> = (0..=bins).map(|k| lo + k as f64 * BIN_DEG).collect();
            let mut counts = vec![0u64; bins];
            for &v in &sorted {
                let k = (((v - lo) / BIN_DEG).floor() as usize).min(bins.saturating_sub(1));
                counts[k] += 1;
            }
            (edges, counts)
        }
        _ => (Vec::new(), Vec::new()),
    };
    AngleStats {
        name: label,
        side,
        unit: "deg",
        bin_edges,
        counts,
        mean: (n > 0).then(|| sorted.iter().sum::<f64>() / n as f64),
        p95: percentile(&sorted, 0.95),
        samples: n,
        score_edges_deg: ergocell_ergonomics::assess::score_edges_deg(
            name,
            &ergocell_ergonomics::assess::Thresholds::default(),
        )
        .unwrap_or_default(),
    }
}

/// The `q` quantile of sorted values (nearest rank).
fn percentile(sorted: &[f64], q: f64) -> Option<f64> {
    if sorted.is_empty() {
        return None;
    }
    let rank = (q * sorted.len() as f64).ceil() as usize;
    sorted.get(rank.clamp(1, sorted.len()) - 1).copied()
}

fn facts(states: &[Stamped<SessionState>], t0: u64) -> Facts {
    let last = |f: &dyn Fn(&SessionState) -> bool| states.iter().rev().find(|s| f(&s.message));
    let measured = last(&|s| s.height_m.is_finite());
    let decided = last(&|s| !s.height_class.is_empty());
    let with_basis = decided.filter(|s| !s.message.height_decision_basis.is_empty());
    let locked = last(&|s| !s.trajectory_sha256.is_empty());
    Facts {
        height_m: measured.map(|s| s.message.height_m),
        height_uncertainty_m: measured.and_then(|s| finite(s.message.height_uncertainty_m)),
        height_class: decided.map(|s| s.message.height_class.clone()),
        // Without a basis the decision's numbers were not recorded (an older recording, or one
        // written without them): unknown, not zero.
        decision_basis: with_basis.map(|s| s.message.height_decision_basis.clone()),
        class_probability: with_basis.and_then(|s| finite(s.message.height_class_probability)),
        expected_rula_cost: with_basis.and_then(|s| finite(s.message.height_expected_rula_cost)),
        trajectory_sha256: locked.map(|s| s.message.trajectory_sha256.clone()),
        approved_by: locked.map_or_else(Vec::new, |s| s.message.trajectory_approved_by.clone()),
        states: states
            .iter()
            .map(|s| StateChange {
                t: secs(s.log_time_nanos, t0),
                state: s.message.state.clone(),
                reason: s.message.reason.clone(),
            })
            .collect(),
        parts_taken: parts_taken(states, t0),
    }
}

/// The parts taken, from the session states' fields (`parts_taken`, `last_part_hand`,
/// `last_part_closest_m`); each part once. A recording made before the states carried them has
/// only the state's reason for people ("part 2 taken: the operator's left hand came to 0.083 m of
/// the handover point …"): for those messages alone ([`crate::legacy::legacy_part_from_reason`]) it is read.
fn parts_taken(states: &[Stamped<SessionState>], t0: u64) -> Vec<PartTaken> {
    let mut parts: Vec<PartTaken> = Vec::new();
    for s in states {
        let m = &s.message;
        let taken = if m.parts_taken > 0 {
            Some((
                m.parts_taken,
                Some(m.last_part_hand.clone()).filter(|h| matches!(h.as_str(), "left" | "right")),
                finite(m.last_part_closest_m),
            ))
        } else {
            crate::legacy::legacy_part_from_reason(&m.reason)
        };
        let Some((part, hand, distance_m)) = taken else {
            continue;
        };
        if parts.iter().any(|p| p.part == part) {
            continue;
        }
        parts.push(PartTaken {
            t: secs(s.log_time_nanos, t0),
            part,
            hand,
            distance_m,
            reason: m.reason.clone(),
        });
    }
    parts
}

fn robot(rec: &Recording, t0: u64) -> Robot {
    let mut tcp = TcpTrack::default();
    let mut handover = None;
    for m in &rec.robot_markers {
        for marker in m.message.markers.iter().filter(|k| k.ns == "robot") {
            let p = &marker.pose.position;
            if ![p.x, p.y, p.z].iter().all(|v| v.is_finite()) {
                continue;
            }
            match marker.id {
                0 => {
                    tcp.t.push(round_to(secs(m.log_time_nanos, t0), 6));
                    tcp.positions.push([p.x, p.y, p.z].map(|v| round_to(v, MM)));
                }
                1 => handover = Some([p.x, p.y, p.z]),
                _ => {}
            }
        }
    }
    let (legs, holds, events) = robot_legs(&rec.trajectories, &rec.controller_events, t0);
    Robot {
        tcp: (!tcp.t.is_empty()).then_some(tcp),
        handover_point: handover,
        legs,
        holds,
        events,
    }
}

/// A leg's first or last point within this of home (each joint, radians) starts or ends there.
const HOME_TOLERANCE_RAD: f64 = 0.01;

/// A leg in words, from its constant (what the review shows).
fn leg_words(leg_id: u8) -> &'static str {
    match leg_id {
        ControllerEvent::LEG_TO_HANDOVER => "home → handover",
        ControllerEvent::LEG_TO_HOME => "handover → home",
        _ => "",
    }
}

fn near(a: &[f64], b: &[f64]) -> bool {
    !a.is_empty()
        && a.len() == b.len()
        && a.iter()
            .zip(b)
            .all(|(x, y)| (x - y).abs() <= HOME_TOLERANCE_RAD)
}

/// A leg being put together: times in nanoseconds (the recording's clock).
struct LegDraft {
    start: u64,
    planned_nanos: u64,
    leg_id: u8,
    /// Reported end: time, outcome, words.
    end: Option<(u64, String, String)>,
    /// Cut short before its planned end: time, outcome.
    cut: Option<(u64, &'static str)>,
    feedback_count: Option<u32>,
    max_error: Option<f64>,
}

/// The robot's legs, holds and events from its commands and the controller's events.
///
/// A leg is named by the `goal_sent` event recorded with it (same log time) when there is one, else
/// by its points: its first point at home (the first point of the session's first leg) → home →
/// handover, its last point at home → handover → home. It ends at its `finished` (or `rejected`,
/// `failed`, `no_response`) event; else at a hold or the next leg sent before its planned end; else
/// as planned (`end_known` false: nothing reported it, e.g. a controller on the topic interface). Feedback is
/// folded into its leg (count, largest error), not listed.
pub(crate) fn robot_legs(
    commands: &[Stamped<JointTrajectory>],
    events: &[Stamped<ControllerEvent>],
    t0: u64,
) -> (Vec<RobotLeg>, Vec<f64>, Vec<RobotEvent>) {
    let mut commands: Vec<&Stamped<JointTrajectory>> = commands.iter().collect();
    commands.sort_by_key(|c| c.log_time_nanos);
    let mut events: Vec<&Stamped<ControllerEvent>> = events.iter().collect();
    events.sort_by_key(|e| e.log_time_nanos);
    let event_time =
        |e: &Stamped<ControllerEvent>| header_or_log_time(&e.message.header, e.log_time_nanos);
    let home: Option<&[f64]> = commands
        .iter()
        .find_map(|c| c.message.points.first())
        .map(|p| p.positions.as_slice());

    let mut holds = Vec::new();
    let mut drafts: Vec<LegDraft> = Vec::new();
    let mut named = vec![false; events.len()];
    for (k, c) in commands.iter().enumerate() {
        let t = c.log_time_nanos;
        let points = &c.message.points;
        let Some(last) = points.last() else {
            holds.push(round_to(secs(t, t0), 6));
            continue;
        };
        let planned_nanos = (last.time_from_start.as_secs_f64().max(0.0) * 1e9) as u64;
        // The time first: this scans every event for every command (a shift: thousands of each),
        // and comparing times is cheaper than reading the kind's name.
        let sent = events.iter().enumerate().position(|(i, e)| {
            !named[i]
                && (e.log_time_nanos == t || event_time(e) == t)
                && e.message.event_kind()
                    == Some(ergocell_bridge::msg::ControllerEventKind::GoalSent)
        });
        let leg_id = if let Some(i) = sent {
            named[i] = true;
            events[i].message.leg_id
        } else {
            let at_home = |p: Option<&ergocell_bridge::msg::JointTrajectoryPoint>| {
                p.zip(home).is_some_and(|(p, h)| near(&p.positions, h))
            };
            if at_home(points.first()) {
                ControllerEvent::LEG_TO_HANDOVER
            } else if at_home(points.last()) {
                ControllerEvent::LEG_TO_HOME
            } else {
                ControllerEvent::LEG_NONE
            }
        };
        // Cut short by the next command (a hold or the next leg) sent before its planned end.
        let cut = commands.get(k + 1).and_then(|next| {
            let n = next.log_time_nanos;
            (n < t.saturating_add(planned_nanos)).then_some((
                n,
                if next.message.points.is_empty() {
                    "held"
                } else {
                    "replaced"
                },
            ))
        });
        drafts.push(LegDraft {
            start: t,
            planned_nanos,
            leg_id,
            end: None,
            cut,
            feedback_count: None,
            max_error: None,
        });
    }

    let mut listed = Vec::new();
    for e in &events {
        let m = &e.message;
        let kind = m.event_kind();
        let about_leg = m.leg_id != ControllerEvent::LEG_NONE
            && matches!(
                kind,
                Some(
                    EventKind::Feedback
                        | EventKind::Finished
                        | EventKind::Rejected
                        | EventKind::Failed
                        | EventKind::NoResponse
                )
            );
        if about_leg {
            // Its leg: the latest one sent before it, of its name, not yet ended; any such leg when
            // none has its name.
            let open = |d: &LegDraft| d.start <= e.log_time_nanos && d.end.is_none();
            let k = drafts
                .iter()
                .rposition(|d| open(d) && d.leg_id == m.leg_id)
                .or_else(|| drafts.iter().rposition(open));
            if let Some(d) = k.and_then(|k| drafts.get_mut(k)) {
                let count = matches!(kind, Some(EventKind::Feedback | EventKind::Finished))
                    .then_some(m.feedback_count);
                if let Some(count) = count {
                    d.feedback_count = Some(d.feedback_count.map_or(count, |c| c.max(count)));
                }
                if kind == Some(EventKind::Feedback) {
                    if let Some(err) = finite(m.max_error) {
                        d.max_error = Some(d.max_error.map_or(err, |x: f64| x.max(err)));
                    }
                } else {
                    let outcome = if kind == Some(EventKind::Finished) && !m.status.is_empty() {
                        m.status.as_str()
                    } else {
                        m.kind.as_str()
                    };
                    d.end = Some((
                        event_time(e).max(d.start),
                        outcome.to_owned(),
                        m.text.clone(),
                    ));
                }
            }
        }
        if kind == Some(EventKind::Feedback) {
            continue;
        }
        listed.push(RobotEvent {
            t: round_to(secs(event_time(e), t0), 6),
            kind: m.kind.clone(),
            leg: m.leg.clone(),
            status: m.status.clone(),
            error_code: m.error_code,
            text: m.text.clone(),
            max_error: finite(m.max_error),
        });
    }

    let legs = drafts
        .into_iter()
        .map(|d| {
            let planned_end = d.start.saturating_add(d.planned_nanos);
            let (end, outcome, end_known, text) = match (d.end, d.cut) {
                (Some((t, outcome, text)), _) => (t, outcome, true, text),
                (None, Some((t, outcome))) => (t, outcome.to_owned(), true, String::new()),
                (None, None) => (planned_end, "sent".to_owned(), false, String::new()),
            };
            RobotLeg {
                t_start: round_to(secs(d.start, t0), 6),
                t_end: round_to(secs(end, t0), 6),
                planned_s: round_to(d.planned_nanos as f64 * 1e-9, 6),
                leg: leg_words(d.leg_id).to_owned(),
                leg_id: d.leg_id,
                outcome,
                end_known,
                feedback_count: d.feedback_count,
                max_error: d.max_error,
                text,
            }
        })
        .collect();
    (legs, holds, listed)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A recorded side with every region at `score` (clamped to each region's range).
    fn side_at(score: u8, final_score: u8) -> RulaSide {
        RulaSide {
            scored: true,
            upper_arm_score: score.min(6),
            lower_arm_score: score.min(3),
            wrist_score: score.min(4),
            wrist_twist_score: 1,
            neck_score: score.min(6),
            trunk_score: score.min(6),
            legs_score: score.min(2),
            final_score,
            action_level: ergocell_ergonomics::rula::action_level(final_score),
            ..RulaSide::default()
        }
    }

    #[test]
    fn the_summary_costs_a_recorded_side_from_the_angles_it_was_scored_from() {
        // 10 frames at 10 Hz: the right side (grand 3) has its angles recorded in the first five
        // only; the left (grand 2) in all. The headline is the right side, so the cost is known
        // for the first 0.5 s (its fifth interval ends at the sixth frame).
        let angles = SideAngles {
            upper_arm_flexion_deg: 30.0,
            lower_arm_flexion_deg: 85.0,
            wrist_flexion_deg: 10.0,
            neck_flexion_deg: 12.0,
            trunk_flexion_deg: 5.0,
        };
        let pose = |k: u64| ergocell_bridge::msg::OperatorPose {
            angle_names: [
                "left_upper_arm_flexion",
                "left_elbow_flexion",
                "left_wrist_flexion",
                "right_upper_arm_flexion",
                "right_elbow_flexion",
                "right_wrist_flexion",
                "neck_flexion",
                "trunk_flexion",
            ]
            .map(str::to_owned)
            .to_vec(),
            angle_rad: [
                30.0,
                85.0,
                10.0,
                if k < 5 { 30.0 } else { f64::NAN },
                85.0,
                10.0,
                12.0,
                5.0,
            ]
            .map(f64::to_radians)
            .to_vec(),
            ..ergocell_bridge::msg::OperatorPose::default()
        };
        let facts: Vec<FrameFacts> = (0..10).map(|k| frame_facts(&pose(k), None)).collect();
        for side in facts[0].side_angles {
            let got = side.unwrap();
            assert!((got.upper_arm_flexion_deg - 30.0).abs() < 1e-9, "{got:?}");
            assert!((got.lower_arm_flexion_deg - 85.0).abs() < 1e-9, "{got:?}");
            assert!((got.neck_flexion_deg - 12.0).abs() < 1e-9, "{got:?}");
        }
        assert_eq!(facts[7].side_angles[1], None);
        let summary = summarise(
            (0..10u64).map(|k| {
                let stamp = i64::try_from(k).unwrap() * 100_000_000;
                (
                    k,
                    ScoredFrame {
                        stamp_nanos: stamp,
                        left: scored_side(&side_at(2, 2), None),
                        right: scored_side(&side_at(3, 3), None),
                    },
                )
            }),
            |t| facts[usize::try_from(t).unwrap()],
        );
        let expected = cost_from_angles(3, &angles, false).unwrap();
        assert!(expected > 3.0 && expected < 4.0, "{expected}");
        let c = summary.posture_cost;
        assert!((c.mean().unwrap() - expected).abs() < 1e-9, "{c:?}");
        assert!((c.secs - 0.5).abs() < 1e-9, "{c:?}");
    }

    #[test]
    fn each_landmark_shows_its_own_sides_score_and_the_body_the_worse_one() {
        // Left side at the lowest scores, right side at the highest.
        let e = ErgonomicState {
            left: side_at(1, 1),
            right: side_at(6, 7),
            ..ErgonomicState::default()
        };
        let strain = frame_strain(Some(&e));
        let at = |lm: Landmark| strain[lm.index()];
        for lm in [
            Landmark::LeftShoulder,
            Landmark::LeftElbow,
            Landmark::LeftThumb,
        ] {
            assert_eq!(at(lm), Some(0.0), "{lm}");
        }
        // One scale: score k is (k - 1) / 6 in every region, so each region's top shows its own
        // colour (upper arm 6, forearm 3, wrist 4).
        let of = |k: u8| Some((f64::from(k) - 1.0) / 6.0);
        assert_eq!(at(Landmark::RightShoulder), of(6));
        assert_eq!(at(Landmark::RightElbow), of(3));
        assert_eq!(at(Landmark::RightThumb), of(4));
        // Face, hips and legs: scored once for the body, shown at the worse worksheet.
        for lm in [Landmark::MouthLeft, Landmark::LeftEye, Landmark::LeftHip] {
            assert_eq!(at(lm), of(6), "{lm}");
        }
        assert_eq!(at(Landmark::LeftHeel), of(2));
        // An unscored side shows nothing; no ergonomics at all, nothing anywhere.
        let one_sided = ErgonomicState {
            left: RulaSide::default(),
            ..e
        };
        let strain = frame_strain(Some(&one_sided));
        assert_eq!(strain[Landmark::LeftWrist.index()], None);
        assert_eq!(strain[Landmark::Nose.index()], of(6));
        assert!(frame_strain(None).iter().all(Option::is_none));
    }

    #[test]
    fn strain_is_one_scale_from_score_1_to_rulas_highest() {
        assert_eq!(strain_of(1), Some(0.0));
        assert_eq!(strain_of(GRAND_SCORE_MAX), Some(1.0));
        assert_eq!(strain_of(0), None);
        // Legs at their top (2) are far from an upper arm at its top (6).
        let legs = strain_of(BodyRegion::Legs.max_score()).unwrap();
        let upper_arm = strain_of(BodyRegion::UpperArm.max_score()).unwrap();
        assert!((legs - 1.0 / 6.0).abs() < 1e-12 && (upper_arm - 5.0 / 6.0).abs() < 1e-12);
    }

    #[test]
    fn histogram_counts_every_sample_once_and_percentile_is_nearest_rank() {
        let samples: Vec<f64> = (0..100).map(|k| f64::from(k) * 0.5 - 5.0).collect(); // -5 .. 44.5
        let a = angle_stats("left_elbow_flexion", &samples);
        assert_eq!(a.name, "elbow flexion");
        assert_eq!(a.side, "left");
        assert_eq!(a.counts.iter().sum::<u64>(), 100);
        assert_eq!(a.bin_edges.first(), Some(&-10.0));
        assert_eq!(a.bin_edges.last(), Some(&50.0));
        assert_eq!(a.counts.len() + 1, a.bin_edges.len());
        assert_eq!(a.counts[0], 10); // -5.0 .. -0.5
        assert_eq!(a.p95, Some(42.0)); // the 95th of 100 sorted values
        assert_eq!(
            a.score_edges_deg,
            vec![60.0, 100.0],
            "RULA's lower-arm band"
        );
        assert!((a.mean.unwrap() - 19.75).abs() < 1e-12);
    }

    #[test]
    fn positions_are_rounded_to_the_millimetre_and_print_short() {
        let v = round_to(0.175_472_793_539_766, MM);
        assert_eq!(v, 0.175);
        assert_eq!(serde_json::to_string(&v).unwrap(), "0.175");
        assert_eq!(round_to(-0.002_228_775, MM), -0.002);
        assert_eq!(
            serde_json::to_string(&round_to(1.560_238_6, MM)).unwrap(),
            "1.56"
        );
    }

    #[test]
    fn damaged_angles_never_size_the_histogram() {
        // A recording with one flipped byte decoded to an angle of ~1e300 rad: that sized the
        // histogram to usize::MAX bins (capacity overflow). Out-of-range input gives no bins.
        let a = angle_stats("trunk_flexion", &[1e300, 5.0]);
        assert!(a.counts.is_empty() && a.bin_edges.is_empty());
        let b = angle_stats("trunk_flexion", &[-360.0, 359.0]);
        assert_eq!(b.counts.iter().sum::<u64>(), 2);
        assert_eq!(b.counts.len(), 72);
    }

    #[test]
    fn rows_are_every_region_per_side_then_the_grand_scores_with_the_summarys_shares() {
        let mut b = SummaryBuilder::new(DEFAULT_MAX_FRAME_NANOS);
        // Left scored 0.3 s at 2 and 0.1 s at 3 (10 Hz); the right never.
        // Its REBA: 6 for 0.2 s, then 9 (a recording with REBA beside RULA).
        for (k, (score, reba)) in [(2, 6), (2, 6), (2, 9), (3, 9)].into_iter().enumerate() {
            let t = k as i64 * 100_000_000;
            let reba = RebaSide {
                scored: true,
                reba_score: reba,
                action_level: ergocell_ergonomics::reba::action_level(reba),
                ..RebaSide::default()
            };
            b.add_scores(t, scored_side(&side_at(score, score), Some(&reba)), None);
        }
        let rows = region_rows(&b.finish());
        let names: Vec<String> = rows
            .iter()
            .map(|r| format!("{}|{}", r.name, r.side))
            .collect();
        assert_eq!(
            names,
            [
                "upper arm|left",
                "upper arm|right",
                "lower arm|left",
                "lower arm|right",
                "wrist|left",
                "wrist|right",
                "neck|",
                "trunk|",
                "legs|",
                "grand score|left",
                "grand score|right",
                "action level|",
                "REBA score|left"
            ]
        );
        let reba = &rows[12];
        assert_eq!((reba.max_score, reba.samples), (15, 4));
        assert_eq!(reba.time_share[5], 0.5);
        assert_eq!(reba.time_share[8], 0.5);
        // The worse side's action level (grand 2 → level 1, grand 3 → level 2), with its stretches.
        let level = &rows[11];
        assert_eq!(level.time_share, [0.75, 0.25, 0.0, 0.0]);
        assert_eq!(
            (level.exposure[0].at_least, level.exposure[0].episodes),
            (2, 1)
        );
        assert!((level.exposure[0].total_secs - 0.1).abs() < 1e-9);
        let ua = &rows[0];
        assert_eq!((ua.max_score, ua.samples), (6, 4));
        assert_eq!(ua.time_share, [0.0, 0.75, 0.25, 0.0, 0.0, 0.0]);
        assert!((ua.mean.unwrap() - 2.25).abs() < 1e-12);
        let right = &rows[1];
        assert_eq!((right.samples, right.mean), (0, None));
        assert!(right.time_share.iter().all(|&x| x == 0.0));
        // Legs top out at 2.
        assert_eq!(rows[8].time_share, [0.0, 1.0]);
        assert_eq!(rows[9].max_score, 7);
        assert!((rows[9].time_share.iter().sum::<f64>() - 1.0).abs() < 1e-12);
    }

    const S: u64 = 1_000_000_000;

    fn stamped<M>(t: u64, message: M) -> Stamped<M> {
        Stamped {
            log_time_nanos: t,
            logged_nanos: t,
            message,
        }
    }

    /// A leg through `knots` (joint positions, time from start in seconds).
    fn leg(knots: &[(&[f64], f64)]) -> JointTrajectory {
        JointTrajectory {
            joint_names: vec!["a1".to_owned(), "a2".to_owned()],
            points: knots
                .iter()
                .map(|&(q, t)| ergocell_bridge::msg::JointTrajectoryPoint {
                    positions: q.to_vec(),
                    time_from_start: ergocell_bridge::msg::Duration::from_secs_f64(t),
                    ..Default::default()
                })
                .collect(),
            ..JointTrajectory::default()
        }
    }

    const HOME: &[f64] = &[0.0, -1.5];
    const HANDOVER: &[f64] = &[0.6, -0.9];

    fn to_handover() -> JointTrajectory {
        leg(&[(HOME, 0.0), (&[0.3, -1.2], 1.0), (HANDOVER, 2.5)])
    }

    fn to_home() -> JointTrajectory {
        // Ends within the tolerance of home, not exactly on it.
        leg(&[
            (HANDOVER, 0.0),
            (&[0.3, -1.2], 1.5),
            (&[0.004, -1.497], 2.5),
        ])
    }

    /// An event about the leg named `leg` (its constant as `ergocell run` sets it).
    fn event(kind: &str, leg: &str) -> ControllerEvent {
        let leg_id = match leg {
            "home → handover" => ControllerEvent::LEG_TO_HANDOVER,
            "handover → home" => ControllerEvent::LEG_TO_HOME,
            _ => ControllerEvent::LEG_NONE,
        };
        ControllerEvent {
            kind: kind.to_owned(),
            leg: leg.to_owned(),
            leg_id,
            max_error: f64::NAN,
            ..ControllerEvent::default()
        }
    }

    #[test]
    fn legs_are_named_by_their_goal_or_by_where_they_start_and_end() {
        let commands = vec![
            stamped(S, to_handover()),
            stamped(5 * S, to_home()),
            stamped(10 * S, to_handover()),
            // Neither end at home: no name.
            stamped(20 * S, leg(&[(HANDOVER, 0.0), (&[0.5, -1.0], 1.0)])),
            // Named by its goal, whatever its points.
            stamped(30 * S, to_handover()),
        ];
        let events = vec![stamped(30 * S, event("goal_sent", "handover → home"))];
        let (legs, holds, listed) = robot_legs(&commands, &events, 0);
        let names: Vec<&str> = legs.iter().map(|l| l.leg.as_str()).collect();
        assert_eq!(
            names,
            [
                "home → handover",
                "handover → home",
                "home → handover",
                "",
                "handover → home"
            ]
        );
        assert!(holds.is_empty());
        assert_eq!(listed.len(), 1, "goal_sent is listed");
        assert_eq!((listed[0].t, listed[0].kind.as_str()), (30.0, "goal_sent"));
    }

    #[test]
    fn a_leg_ends_as_reported_else_when_cut_short_else_as_planned() {
        let commands = vec![
            stamped(S, to_handover()),
            stamped(5 * S, to_home()),
            // Held 1 s into the third leg, before its planned end.
            stamped(10 * S, to_handover()),
            stamped(11 * S, JointTrajectory::default()),
            stamped(20 * S, to_home()),
        ];
        let finished = ControllerEvent {
            status: "aborted".to_owned(),
            error_code: -4,
            text: "path tolerance violated".to_owned(),
            header: ergocell_bridge::msg::Header::new(7_200_000_000, ""),
            ..event("finished", "handover → home")
        };
        let events = vec![stamped(7_300_000_000, finished)];
        let (legs, holds, _) = robot_legs(&commands, &events, S);
        let ends: Vec<(f64, f64, &str, bool)> = legs
            .iter()
            .map(|l| (l.t_start, l.t_end, l.outcome.as_str(), l.end_known))
            .collect();
        assert_eq!(
            ends,
            [
                // Nothing reported: the planned end, open.
                (0.0, 2.5, "sent", false),
                // The controller's answer, at its stamp (the header's, not the log time).
                (4.0, 6.2, "aborted", true),
                (9.0, 10.0, "held", true),
                (19.0, 21.5, "sent", false),
            ]
        );
        assert_eq!(legs[1].text, "path tolerance violated");
        assert_eq!(legs[0].planned_s, 2.5);
        assert_eq!(holds, [10.0]);
    }

    #[test]
    fn feedback_is_folded_into_its_leg_and_not_listed() {
        let commands = vec![stamped(S, to_handover()), stamped(5 * S, to_home())];
        let feedback = |t: u64, leg: &str, count: u32, err: f64| {
            stamped(
                t,
                ControllerEvent {
                    feedback_count: count,
                    max_error: err,
                    ..event("feedback", leg)
                },
            )
        };
        let events = vec![
            stamped(S, event("goal_sent", "home → handover")),
            stamped(S + 10, event("accepted", "home → handover")),
            feedback(S + 20, "home → handover", 1, 0.002),
            feedback(2 * S, "home → handover", 25, f64::NAN),
            feedback(3 * S, "home → handover", 50, 0.004),
            stamped(
                3 * S + 600_000_000,
                ControllerEvent {
                    status: "succeeded".to_owned(),
                    feedback_count: 61,
                    ..event("finished", "home → handover")
                },
            ),
            stamped(5 * S, event("goal_sent", "handover → home")),
            // Feedback with no number for the error, and no result yet.
            feedback(6 * S, "handover → home", 1, f64::NAN),
        ];
        let (legs, _, listed) = robot_legs(&commands, &events, 0);
        assert_eq!(legs[0].feedback_count, Some(61), "the result's count");
        assert_eq!(legs[0].max_error, Some(0.004));
        assert_eq!(
            (legs[0].t_end, legs[0].outcome.as_str(), legs[0].end_known),
            (3.6, "succeeded", true)
        );
        assert_eq!(legs[1].feedback_count, Some(1));
        assert_eq!(legs[1].max_error, None, "NaN is no error value");
        assert_eq!(legs[1].outcome, "sent");
        let kinds: Vec<&str> = listed.iter().map(|e| e.kind.as_str()).collect();
        assert_eq!(kinds, ["goal_sent", "accepted", "finished", "goal_sent"]);
        // A leg without any answer has no count.
        let (legs, _, _) = robot_legs(&commands[..1], &[], 0);
        assert_eq!(legs[0].feedback_count, None);
    }

    /// (t, part, hand, distance) of each part taken.
    fn parts_of(f: &Facts) -> Vec<(f64, u32, Option<&str>, Option<f64>)> {
        f.parts_taken
            .iter()
            .map(|p| (p.t, p.part, p.hand.as_deref(), p.distance_m))
            .collect()
    }

    #[test]
    fn parts_taken_are_read_from_the_states_reasons_once_each() {
        let state = |reason: &str| SessionState {
            state: "working".to_owned(),
            reason: reason.to_owned(),
            ..SessionState::default()
        };
        let taken = |n: u32, hand: &str| {
            format!("part {n} taken: the operator's {hand} hand came to 0.083 m of the handover point and left it; robot going home for the next part")
        };
        let states = vec![
            stamped(S, state("trajectory sent: home → handover")),
            stamped(4 * S, state(&taken(1, "left"))),
            stamped(4 * S, state(&taken(1, "left"))),
            stamped(9 * S, state(&taken(2, "right"))),
            stamped(10 * S, state("part of the cell")),
        ];
        assert_eq!(
            parts_of(&facts(&states, S)),
            [
                (3.0, 1, Some("left"), Some(0.083)),
                (8.0, 2, Some("right"), Some(0.083))
            ]
        );
    }

    /// Today's states carry the part as fields: the review reads them, whatever the reason says.
    #[test]
    fn parts_taken_are_read_from_the_fields() {
        const S: u64 = 1_000_000_000;
        let state = |reason: &str| SessionState {
            state: "working".to_owned(),
            reason: reason.to_owned(),
            ..SessionState::default()
        };
        let taken = |part: u32, hand: &str, closest: f64, reason: &str| SessionState {
            parts_taken: part,
            last_part_hand: hand.into(),
            last_part_closest_m: closest,
            ..state(reason)
        };
        let states = vec![
            stamped(S, state("trajectory sent: home → handover")),
            stamped(4 * S, taken(1, "right", 0.021, "worded otherwise")),
            // Later states repeat the latest part: counted once.
            stamped(5 * S, taken(1, "right", 0.021, "state working → held")),
            stamped(
                9 * S,
                taken(
                    2,
                    "left",
                    0.004,
                    "part 7 taken: the operator's right hand came to 9 m",
                ),
            ),
        ];
        assert_eq!(
            parts_of(&facts(&states, S)),
            [
                (3.0, 1, Some("right"), Some(0.021)),
                (8.0, 2, Some("left"), Some(0.004))
            ]
        );
    }
}
