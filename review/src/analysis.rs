//! The recording's messages → the review's numbers ([`ReviewData`], the page's JSON, `version` 1).
//!
//! Frames are the recorded `OperatorPose` messages; each is joined with the `ErgonomicState` of the
//! same log time (the session records both from one fused frame). Strain per landmark is the RULA
//! band of the body region the landmark belongs to, scaled to 0..1 by that region's score range
//! (shoulders → upper arm 1–6, elbows → lower arm 1–3, wrists and hands → wrist 1–4, face → neck 1–6,
//! hips → trunk 1–6, knees, ankles and feet → legs 1–2). Angles are turned into degrees here, the
//! report boundary.

use ergocell_bridge::msg::{ErgonomicState, RulaSide, SessionState};
use ergocell_skeleton::{Landmark, LANDMARK_COUNT};
use serde::Serialize;

use crate::read::{Recording, Stamped};

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
    pub trajectory_sha256: Option<String>,
    pub approved_by: Vec<String>,
    pub states: Vec<StateChange>,
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
    /// 33 numbers per frame in 0..1 (0 lowest strain); `None` where the region was not scored.
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
}

/// The robot as recorded (`/ergocell/robot_markers`).
#[derive(Debug, Clone, Default, PartialEq, Serialize)]
pub struct Robot {
    pub tcp: Option<TcpTrack>,
    pub handover_point: Option<[f64; 3]>,
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
    pub action_level: u8,
    pub message: String,
}

/// One body region's scores over the scored frames.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct RegionStats {
    pub name: &'static str,
    /// "left", "right", or "" for the neck, trunk and legs (scored the same on both sides).
    pub side: &'static str,
    pub max_score: u8,
    /// Mean score; `None` when never scored.
    pub mean: Option<f64>,
    /// Share of the scored frames at score 1..=max_score.
    pub time_share: Vec<f64>,
    pub samples: usize,
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

/// MediaPipe's `POSE_CONNECTIONS`: the lines drawn between BlazePose landmarks.
pub const DRAWN_BONES: [[usize; 2]; 35] = [
    [0, 1],
    [1, 2],
    [2, 3],
    [3, 7],
    [0, 4],
    [4, 5],
    [5, 6],
    [6, 8],
    [9, 10],
    [11, 12],
    [11, 13],
    [13, 15],
    [15, 17],
    [15, 19],
    [15, 21],
    [17, 19],
    [12, 14],
    [14, 16],
    [16, 18],
    [16, 20],
    [16, 22],
    [18, 20],
    [11, 23],
    [12, 24],
    [23, 24],
    [23, 25],
    [24, 26],
    [25, 27],
    [26, 28],
    [27, 29],
    [28, 30],
    [29, 31],
    [30, 32],
    [27, 31],
    [28, 32],
];

/// A RULA body region of one side's worksheet.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Region {
    UpperArm,
    LowerArm,
    Wrist,
    WristTwist,
    Neck,
    Trunk,
    Legs,
    Grand,
}

impl Region {
    pub const ALL: [Region; 8] = [
        Region::UpperArm,
        Region::LowerArm,
        Region::Wrist,
        Region::WristTwist,
        Region::Neck,
        Region::Trunk,
        Region::Legs,
        Region::Grand,
    ];

    pub fn name(self) -> &'static str {
        match self {
            Region::UpperArm => "upper arm",
            Region::LowerArm => "lower arm",
            Region::Wrist => "wrist",
            Region::WristTwist => "wrist twist",
            Region::Neck => "neck",
            Region::Trunk => "trunk",
            Region::Legs => "legs",
            Region::Grand => "grand score",
        }
    }

    /// The highest score RULA gives this region (McAtamney & Corlett 1993, with every adjustment).
    pub fn max_score(self) -> u8 {
        match self {
            Region::UpperArm | Region::Neck | Region::Trunk => 6,
            Region::LowerArm => 3,
            Region::Wrist => 4,
            Region::WristTwist | Region::Legs => 2,
            Region::Grand => 7,
        }
    }

    /// Scored the same for both sides (one body part).
    fn is_central(self) -> bool {
        matches!(self, Region::Neck | Region::Trunk | Region::Legs)
    }

    fn score(self, s: &RulaSide) -> u8 {
        match self {
            Region::UpperArm => s.upper_arm_score,
            Region::LowerArm => s.lower_arm_score,
            Region::Wrist => s.wrist_score,
            Region::WristTwist => s.wrist_twist_score,
            Region::Neck => s.neck_score,
            Region::Trunk => s.trunk_score,
            Region::Legs => s.legs_score,
            Region::Grand => s.final_score,
        }
    }
}

/// Which side's worksheet a landmark's strain comes from.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Sides {
    Left,
    Right,
    /// The worse of the two (neck, trunk, legs).
    Both,
}

/// The region (and side) whose score colours `landmark`.
fn region_of(landmark: Landmark) -> (Region, Sides) {
    let i = landmark.index();
    // BlazePose: 1–3, 7, 9 are the left of the face; from 11 on, odd indices are the left side.
    let left = if i <= 10 {
        matches!(i, 1..=3 | 7 | 9)
    } else {
        i % 2 == 1
    };
    let side = match (i, left) {
        (0, _) => Sides::Both,
        (_, true) => Sides::Left,
        (_, false) => Sides::Right,
    };
    let region = match i {
        0..=10 => Region::Neck,
        11 | 12 => Region::UpperArm,
        13 | 14 => Region::LowerArm,
        15..=22 => Region::Wrist,
        23 | 24 => Region::Trunk,
        _ => Region::Legs,
    };
    if region.is_central() {
        (region, Sides::Both)
    } else {
        (region, side)
    }
}

/// The strain of a region score, 0 (score 1) .. 1 (the region's maximum).
fn strain_of(region: Region, score: u8) -> Option<f64> {
    if score == 0 {
        return None;
    }
    let max = f64::from(region.max_score());
    Some(((f64::from(score) - 1.0) / (max - 1.0)).clamp(0.0, 1.0))
}

fn scored(s: &RulaSide) -> Option<&RulaSide> {
    s.scored.then_some(s)
}

/// Strain of every landmark in one frame.
fn frame_strain(e: Option<&ErgonomicState>) -> Vec<Option<f64>> {
    Landmark::ALL
        .iter()
        .map(|&lm| {
            let e = e?;
            let (region, sides) = region_of(lm);
            let of = |s: &RulaSide| scored(s).and_then(|s| strain_of(region, region.score(s)));
            match sides {
                Sides::Left => of(&e.left),
                Sides::Right => of(&e.right),
                Sides::Both => match (of(&e.left), of(&e.right)) {
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
fn round_to(v: f64, decimals: u8) -> f64 {
    let k = 10f64.powi(i32::from(decimals));
    (v * k).round() / k
}

/// Seconds of `t` after `t0`.
fn secs(t: u64, t0: u64) -> f64 {
    t.saturating_sub(t0) as f64 * 1e-9
}

fn finite(x: f64) -> Option<f64> {
    x.is_finite().then_some(x)
}

/// Analyses one recording; `label` names it on the page (usually the file name).
pub fn analyse(rec: &Recording, label: &str) -> SessionReview {
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
    let mut poses: Vec<_> = rec.poses.iter().collect();
    poses.sort_by_key(|p| stamp(&p.message.header));
    poses.dedup_by_key(|p| stamp(&p.message.header));
    let mut frames = Frames::default();
    let mut malformed = 0usize;
    let mut implausible_angles = 0usize;
    let mut angle_samples: Vec<(String, Vec<f64>)> = Vec::new();
    for p in poses {
        let m = &p.message;
        if m.x.len() != LANDMARK_COUNT || m.y.len() != LANDMARK_COUNT || m.z.len() != LANDMARK_COUNT
        {
            malformed += 1;
            continue;
        }
        let t = stamp(&m.header);
        let e = ergonomics_at(t);
        frames.t.push(round_to(secs(t, t0), 6));
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
                .map(|v| v.map(|v| round_to(v, 3)))
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
        let uncertain = |s: Option<&RulaSide>| s.and_then(scored).is_some_and(|s| s.uncertain);
        frames.uncertain_left.push(uncertain(e.map(|e| &e.left)));
        frames.uncertain_right.push(uncertain(e.map(|e| &e.right)));
        if m.angle_names.len() == m.angle_rad.len() {
            // Kept in the recorder's order, whether or not an angle was observed in this frame.
            for (name, &v) in m.angle_names.iter().zip(&m.angle_rad) {
                let k = if let Some(k) = angle_samples.iter().position(|(n, _)| n == name) {
                    k
                } else {
                    angle_samples.push((name.clone(), Vec::new()));
                    angle_samples.len() - 1
                };
                match finite(v).map(f64::to_degrees) {
                    Some(deg) if deg.abs() <= MAX_ANGLE_DEG => angle_samples[k].1.push(deg),
                    Some(_) => implausible_angles += 1,
                    None => {}
                }
            }
        } else {
            malformed += 1;
        }
    }
    if implausible_angles > 0 {
        problems.push(format!(
            "{implausible_angles} joint angle value(s) beyond ±{MAX_ANGLE_DEG}° left out of the distributions (damaged data)"
        ));
    }
    if malformed > 0 {
        problems.push(format!(
            "{malformed} operator pose message(s) skipped: not 33 landmarks, or angle names and values of different lengths"
        ));
    }

    // Regions over the scored frames of the recording (every ErgonomicState, whether or not its
    // pose was recorded).
    let mut regions = Vec::new();
    for region in Region::ALL {
        let sides: &[(&'static str, bool)] = if region.is_central() {
            &[("", true)]
        } else {
            &[("left", true), ("right", false)]
        };
        for &(side_name, left) in sides {
            let scores: Vec<u8> = ergonomics
                .iter()
                .filter_map(|e| {
                    let e = &e.message;
                    let s = if region.is_central() {
                        scored(&e.right).or_else(|| scored(&e.left))
                    } else if left {
                        scored(&e.left)
                    } else {
                        scored(&e.right)
                    }?;
                    let v = region.score(s);
                    (v >= 1).then_some(v)
                })
                .collect();
            regions.push(region_stats(region, side_name, &scores));
        }
    }

    let angles = angle_samples
        .into_iter()
        .filter(|(_, samples)| !samples.is_empty())
        .map(|(name, samples)| angle_stats(&name, &samples))
        .collect();

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
        bones: DRAWN_BONES.to_vec(),
        up: [0.0, 0.0, 1.0],
        frames,
        robot: robot(rec, t0),
        warnings: rec
            .warnings
            .iter()
            .map(|w| Warning {
                // The frame the warning was raised on (its header), on the frames' clock.
                t: secs(header_or_log_time(&w.message.header, w.log_time_nanos), t0),
                kind: w.message.kind.clone(),
                region: w.message.region.clone(),
                side: w.message.side.clone(),
                score: w.message.region_score,
                action_level: w.message.action_level,
                message: w.message.message.clone(),
            })
            .collect(),
        regions,
        angles,
    }
}

/// A message's header stamp, or its log time when the header has none.
fn header_or_log_time(h: &ergocell_bridge::msg::Header, log_time_nanos: u64) -> u64 {
    u64::try_from(h.stamp.to_nanos())
        .ok()
        .filter(|&t| t > 0)
        .unwrap_or(log_time_nanos)
}

fn region_stats(region: Region, side: &'static str, scores: &[u8]) -> RegionStats {
    let max = region.max_score();
    let n = scores.len();
    let mut counts = vec![0usize; usize::from(max)];
    for &s in scores {
        let i = usize::from(s.clamp(1, max) - 1);
        counts[i] += 1;
    }
    RegionStats {
        name: region.name(),
        side,
        max_score: max,
        mean: (n > 0).then(|| scores.iter().map(|&s| f64::from(s)).sum::<f64>() / n as f64),
        time_share: counts
            .iter()
            .map(|&c| if n == 0 { 0.0 } else { c as f64 / n as f64 })
            .collect(),
        samples: n,
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
    let locked = last(&|s| !s.trajectory_sha256.is_empty());
    Facts {
        height_m: measured.map(|s| s.message.height_m),
        height_uncertainty_m: measured.and_then(|s| finite(s.message.height_uncertainty_m)),
        height_class: decided.map(|s| s.message.height_class.clone()),
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
    }
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
    Robot {
        tcp: (!tcp.t.is_empty()).then_some(tcp),
        handover_point: handover,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_landmark_belongs_to_the_region_of_its_body_part() {
        use Landmark as L;
        assert_eq!(region_of(L::LeftShoulder), (Region::UpperArm, Sides::Left));
        assert_eq!(
            region_of(L::RightShoulder),
            (Region::UpperArm, Sides::Right)
        );
        assert_eq!(region_of(L::LeftElbow), (Region::LowerArm, Sides::Left));
        assert_eq!(region_of(L::RightWrist), (Region::Wrist, Sides::Right));
        assert_eq!(region_of(L::LeftPinky), (Region::Wrist, Sides::Left));
        assert_eq!(region_of(L::RightThumb), (Region::Wrist, Sides::Right));
        assert_eq!(region_of(L::Nose), (Region::Neck, Sides::Both));
        assert_eq!(region_of(L::LeftHip), (Region::Trunk, Sides::Both));
        assert_eq!(region_of(L::RightFootIndex), (Region::Legs, Sides::Both));
        // Left/right by BlazePose's index parity (odd = left from 11 on).
        for lm in Landmark::ALL {
            let (_, side) = region_of(lm);
            if lm.index() >= 11 && side != Sides::Both {
                assert_eq!(side == Sides::Left, lm.name().starts_with("left"), "{lm:?}");
            }
        }
    }

    #[test]
    fn strain_spans_zero_to_one_over_each_regions_score_range() {
        for r in Region::ALL {
            assert_eq!(strain_of(r, 1), Some(0.0));
            assert_eq!(strain_of(r, r.max_score()), Some(1.0));
            assert_eq!(strain_of(r, 0), None);
        }
        assert_eq!(strain_of(Region::LowerArm, 2), Some(0.5));
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
    fn region_shares_sum_to_one_and_mean_is_the_mean() {
        let r = region_stats(Region::UpperArm, "left", &[1, 2, 2, 3]);
        assert_eq!(r.time_share.len(), 6);
        assert!((r.time_share.iter().sum::<f64>() - 1.0).abs() < 1e-12);
        assert_eq!(r.time_share[1], 0.5);
        assert_eq!(r.mean, Some(2.0));
        let empty = region_stats(Region::Neck, "", &[]);
        assert_eq!(empty.mean, None);
        assert_eq!(empty.samples, 0);
    }
}
