//! The report's first page: what an ergonomist reads before the details.
//!
//! - **Time at each action level**: RULA's action level of the worse side (1 acceptable … 4
//!   investigate and change now), in seconds of scored time, from the session summary (every frame,
//!   also in a long recording's overview).
//! - **The worst moments**: up to three frames, the highest action level first, then the highest
//!   grand score. One stretch at a level is one moment: once a frame is chosen, the frames around it
//!   at its action level or more (until a gap of more than [`STRETCH_GAP_S`]) and those within
//!   [`MOMENT_SPACING_S`] of it are not chosen again. Each comes with the regions at or above their
//!   warning score at that instant; the page draws the skeleton of each.
//! - **Per region** (per side for the arms), what was found and what to do, in the method's own
//!   terms: the time at or above the region's warning score ([`WarningConfig::warn_at`], the score at
//!   which the operator is warned), the longest stretch there, the warnings raised, and the advice the
//!   warnings give ([`Advice`]) for the region's worst posture: the posture of its highest raised
//!   warning, else of its frame with the highest score (the direction of its flexion decides: an
//!   arm reaching back, a neck bent back; a forearm at 3 or more is across the body or out to the
//!   side, as RULA's elbow bands alone reach 2).
//!
//! The warning scores and the dwell are the shipped warning settings ([`WarningConfig::default`]):
//! a recording does not carry its cell's settings. The findings say which they used.
//!
//! A region's verdict: **change** when it was held at or above its warning score for at least the
//! warnings' dwell time ([`WarningConfig::dwell_nanos`], 2 s) or raised a warning; **brief** when it
//! reached that score only for shorter moments; **acceptable** when it never did.

use ergocell_ergonomics::assess::BodyRegion;
use ergocell_ergonomics::rula::RulaScores;
use ergocell_ergonomics::summary::SessionSummary;
use ergocell_ergonomics::warnings::{Advice, WarningConfig};
use ergocell_skeleton::Side;
use serde::Serialize;

use crate::analysis::Warning;

/// Worst moments closer than this (seconds) are one moment.
pub const MOMENT_SPACING_S: f64 = 10.0;

/// How many worst moments the first page shows.
pub const MOMENTS: usize = 3;

/// Frames further apart than this (seconds) are not one stretch (a gap in the recording, or an
/// overview's frames between its worst moments).
pub const STRETCH_GAP_S: f64 = 1.0;

/// The first page's numbers.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Findings {
    /// Scored seconds at RULA action level 1, 2, 3 and 4 (the worse side).
    pub action_level_secs: [f64; 4],
    /// Seconds without a score (the operator out of view, a side unseen).
    pub unscored_secs: f64,
    /// The worst moments, the worst first; empty when no frame reached action level 2.
    pub worst_moments: Vec<WorstMoment>,
    /// Per region, in [`BodyRegion::ALL`] order, left before right: what was found, what to do.
    pub regions: Vec<RegionFinding>,
    /// How long a posture must hold before the operator is warned (the settings used), seconds.
    pub dwell_s: f64,
}

/// One of the worst moments.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct WorstMoment {
    /// Seconds on the frames' clock (the page's `frames.t`).
    pub t: f64,
    pub action_level: u8,
    pub grand_left: Option<u8>,
    pub grand_right: Option<u8>,
    /// The regions at or above their warning score at that instant, the highest score first.
    pub regions: Vec<RegionScore>,
}

/// A region's score at one instant.
#[derive(Debug, Clone, PartialEq, Eq, Serialize)]
pub struct RegionScore {
    /// In words: "upper arm".
    pub region: &'static str,
    /// "left", "right", or "" for neck, trunk and legs.
    pub side: &'static str,
    pub score: u8,
}

/// What a region's time came to.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Verdict {
    /// Never scored.
    NotScored,
    /// Never at its warning score.
    Acceptable,
    /// At its warning score only for moments shorter than the warnings' dwell time.
    Brief,
    /// Held at its warning score for the dwell time or longer, or warned: change the work.
    Change,
}

/// One region's finding.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct RegionFinding {
    pub region: &'static str,
    pub side: &'static str,
    pub verdict: Verdict,
    /// The score at which the operator is warned for this region.
    pub warn_at: u8,
    /// The highest score reached; `None` when never scored.
    pub highest: Option<u8>,
    /// The top of the region's scale.
    pub top: u8,
    /// Share of the region's scored time at or above `warn_at`.
    pub share_at_warn: f64,
    /// Seconds at or above `warn_at`, in how many stretches, the longest.
    pub secs_at_warn: f64,
    pub episodes_at_warn: usize,
    pub longest_at_warn_secs: f64,
    /// Warnings raised for this region in the session.
    pub warnings_raised: usize,
    /// What to do; `None` when the verdict is acceptable (or not scored).
    pub advice: Option<Advice>,
    /// `advice` in words.
    pub advice_text: Option<&'static str>,
}

/// One page frame, as the worst moments are chosen from.
#[derive(Debug, Clone, Copy)]
pub(crate) struct FrameBrief {
    pub(crate) t: f64,
    pub(crate) action_level: u8,
    pub(crate) left: Option<RulaScores>,
    pub(crate) right: Option<RulaScores>,
    /// The flexions the advice turns on, degrees, as recorded: upper arm left and right, neck,
    /// trunk (`None`: not observed).
    pub(crate) flexion_deg: Flexions,
}

/// A frame's flexion angles, degrees.
#[derive(Debug, Clone, Copy, Default)]
pub(crate) struct Flexions {
    pub(crate) upper_arm: [Option<f64>; 2],
    pub(crate) neck: Option<f64>,
    pub(crate) trunk: Option<f64>,
}

impl Flexions {
    /// From a recorded pose's angle names and values (radians).
    pub(crate) fn from_recorded(names: &[String], rad: &[f64]) -> Self {
        let mut f = Self::default();
        for (name, &v) in names.iter().zip(rad) {
            let deg = Some(v.to_degrees()).filter(|d| d.is_finite());
            match name.as_str() {
                "left_upper_arm_flexion" => f.upper_arm[0] = deg,
                "right_upper_arm_flexion" => f.upper_arm[1] = deg,
                "neck_flexion" => f.neck = deg,
                "trunk_flexion" => f.trunk = deg,
                _ => {}
            }
        }
        f
    }

    fn of(&self, region: BodyRegion, side: Option<Side>) -> Option<f64> {
        match (region, side) {
            (BodyRegion::UpperArm, Some(Side::Left)) => self.upper_arm[0],
            (BodyRegion::UpperArm, Some(Side::Right)) => self.upper_arm[1],
            (BodyRegion::Neck, _) => self.neck,
            (BodyRegion::Trunk, _) => self.trunk,
            _ => None,
        }
    }
}

/// The region's score in a frame: its side's, or for neck, trunk and legs the worse worksheet's.
fn score_in(f: &FrameBrief, region: BodyRegion, side: Option<Side>) -> Option<u8> {
    match side {
        Some(Side::Left) => f.left.map(|s| region.score(&s)),
        Some(Side::Right) => f.right.map(|s| region.score(&s)),
        None => [f.left, f.right]
            .into_iter()
            .flatten()
            .map(|s| region.score(&s))
            .max(),
    }
}

/// The findings of one session.
pub(crate) fn findings(
    summary: &SessionSummary,
    frames: &[FrameBrief],
    warnings: &[Warning],
    config: &WarningConfig,
) -> Findings {
    let scored_secs = summary.duration_secs * (1.0 - summary.unscored_share).clamp(0.0, 1.0);
    Findings {
        action_level_secs: summary.action_level_share.map(|s| scored_secs * s),
        unscored_secs: summary.duration_secs - scored_secs,
        worst_moments: worst_moments(frames, config),
        regions: region_findings(summary, frames, warnings, config),
        dwell_s: config.dwell_nanos as f64 * 1e-9,
    }
}

/// Up to [`MOMENTS`] frames at action level 2 or more, the worst first, one per stretch and
/// [`MOMENT_SPACING_S`] apart. `frames` are in time order.
fn worst_moments(frames: &[FrameBrief], config: &WarningConfig) -> Vec<WorstMoment> {
    let grand = |f: &FrameBrief| {
        [f.left, f.right]
            .iter()
            .flatten()
            .map(|s| s.final_score)
            .max()
            .unwrap_or(0)
    };
    let mut order: Vec<usize> = (0..frames.len())
        .filter(|&i| frames[i].action_level >= 2)
        .collect();
    // Worst first; among equals the earliest (a stable sort keeps time order).
    order.sort_by_key(|&i| std::cmp::Reverse((frames[i].action_level, grand(&frames[i]))));
    let mut taken = vec![false; frames.len()];
    let mut chosen: Vec<usize> = Vec::new();
    for i in order {
        if chosen.len() == MOMENTS {
            break;
        }
        if taken[i]
            || chosen
                .iter()
                .any(|&c| (frames[c].t - frames[i].t).abs() < MOMENT_SPACING_S)
        {
            continue;
        }
        chosen.push(i);
        // Its stretch at this level or more, both ways, is this moment.
        let level = frames[i].action_level;
        let mut k = i;
        while k > 0
            && frames[k - 1].action_level >= level
            && frames[k].t - frames[k - 1].t <= STRETCH_GAP_S
        {
            k -= 1;
            taken[k] = true;
        }
        let mut k = i;
        while k + 1 < frames.len()
            && frames[k + 1].action_level >= level
            && frames[k + 1].t - frames[k].t <= STRETCH_GAP_S
        {
            k += 1;
            taken[k] = true;
        }
    }
    chosen
        .into_iter()
        .map(|i| {
            let f = &frames[i];
            let mut regions = Vec::new();
            for region in BodyRegion::ALL {
                for &side in region.sides() {
                    let Some(score) = score_in(f, region, side) else {
                        continue;
                    };
                    if score >= config.warn_at_of(region) {
                        regions.push(RegionScore {
                            region: region.words(),
                            side: side.map_or("", Side::name),
                            score,
                        });
                    }
                }
            }
            regions.sort_by_key(|r| std::cmp::Reverse(r.score));
            WorstMoment {
                t: f.t,
                action_level: f.action_level,
                grand_left: f.left.map(|s| s.final_score),
                grand_right: f.right.map(|s| s.final_score),
                regions,
            }
        })
        .collect()
}

fn region_findings(
    summary: &SessionSummary,
    frames: &[FrameBrief],
    warnings: &[Warning],
    config: &WarningConfig,
) -> Vec<RegionFinding> {
    let dwell_s = config.dwell_nanos as f64 * 1e-9;
    let mut out = Vec::new();
    for region in BodyRegion::ALL {
        for &side in region.sides() {
            let warn_at = config.warn_at_of(region);
            let words = region.words();
            let side_name = side.map_or("", Side::name);
            let share = summary.region(region, side);
            let highest = share.and_then(|r| r.share_by_score.iter().map(|(s, _)| *s).max());
            let share_at_warn: f64 = share.map_or(0.0, |r| {
                r.share_by_score
                    .iter()
                    .filter(|(s, _)| *s >= warn_at)
                    .map(|(_, x)| x)
                    .sum()
            });
            let exposure = share.and_then(|r| r.exposure.iter().find(|e| e.at_least == warn_at));
            // The region's warnings, by the names the recorder writes (`upper_arm`, `left`).
            let raised: Vec<&Warning> = warnings
                .iter()
                .filter(|w| {
                    w.kind == "raised"
                        && w.region == region.name()
                        && (w.side == side_name || (side.is_none() && w.side.is_empty()))
                })
                .collect();
            let longest = exposure.map_or(0.0, |e| e.longest_secs);
            let verdict = match (share, highest) {
                (None, _) | (_, None) => Verdict::NotScored,
                _ if !raised.is_empty() || longest >= dwell_s => Verdict::Change,
                _ if share_at_warn > 0.0 => Verdict::Brief,
                _ => Verdict::Acceptable,
            };
            // The worst posture: the highest raised warning's, else the first frame at the
            // region's highest score on the page.
            let worst_warning = raised.iter().max_by_key(|w| w.score);
            let mut worst_frame: Option<(u8, &FrameBrief)> = None;
            for f in frames {
                if let Some(s) = score_in(f, region, side) {
                    if worst_frame.is_none_or(|(w, _)| s > w) {
                        worst_frame = Some((s, f));
                    }
                }
            }
            let angle = worst_warning
                .and_then(|w| w.angle_deg)
                .or_else(|| worst_frame.and_then(|(_, f)| f.flexion_deg.of(region, side)));
            let score = worst_warning
                .map(|w| w.score)
                .or(worst_frame.map(|(s, _)| s))
                .or(highest);
            let advice = matches!(verdict, Verdict::Change | Verdict::Brief)
                .then(|| Advice::for_score(region, angle, score.unwrap_or(0)));
            out.push(RegionFinding {
                region: words,
                side: side_name,
                verdict,
                warn_at,
                highest,
                top: region.max_score(),
                share_at_warn,
                secs_at_warn: exposure.map_or(0.0, |e| e.total_secs),
                episodes_at_warn: exposure.map_or(0, |e| e.episodes),
                longest_at_warn_secs: longest,
                warnings_raised: raised.len(),
                advice,
                advice_text: advice.map(Advice::text),
            });
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use ergocell_ergonomics::summary::{ScoredSide, SummaryBuilder, DEFAULT_MAX_FRAME_NANOS};

    /// A side with the given trunk, neck and upper-arm scores, the others at 1.
    fn scores(trunk: u8, neck: u8, upper_arm: u8, grand: u8) -> RulaScores {
        RulaScores {
            upper_arm_score: upper_arm,
            lower_arm_score: 1,
            wrist_score: 1,
            wrist_twist_score: 1,
            posture_score_a: 1,
            score_c_wrist_arm: 1,
            neck_score: neck,
            trunk_score: trunk,
            legs_score: 1,
            posture_score_b: 1,
            score_d_neck_trunk_legs: 1,
            final_score: grand,
            action_level: ergocell_ergonomics::rula::action_level(grand),
        }
    }

    fn warning(region: &str, side: &str, score: u8, angle_deg: f64) -> Warning {
        Warning {
            t: 1.0,
            kind: "raised".to_owned(),
            region: region.to_owned(),
            side: side.to_owned(),
            score,
            angle_deg: Some(angle_deg),
            action_level: 2,
            message: String::new(),
            band_probability: None,
            near_limit: false,
        }
    }

    #[test]
    fn a_region_held_past_its_warning_score_is_changed_a_moment_is_brief_the_rest_acceptable() {
        // 10 Hz, the left side only: trunk at 3 for 3 s (past the 2 s dwell), then the neck at 3
        // for 0.5 s, the rest of 10 s at 1; the upper arm at 2 throughout (below its warning at 3).
        let mut b = SummaryBuilder::new(DEFAULT_MAX_FRAME_NANOS);
        for k in 0..100 {
            let trunk = if k < 30 { 3 } else { 1 };
            let neck = if (50..55).contains(&k) { 3 } else { 1 };
            let side = ScoredSide {
                scores: scores(trunk, neck, 2, 3),
                uncertain: false,
                reba: None,
                posture_cost: None,
            };
            b.add_scores(k * 100_000_000, Some(side), None);
        }
        let summary = b.finish();
        // A warning raised for the left lower arm at 3, though its score never reached 3 in the
        // summary: the operator was warned, so the finding says change; a forearm at 3 is across
        // the body or out to the side (the elbow bands alone reach 2).
        let warnings = [warning("lower_arm", "left", 3, 130.0)];
        let f = findings(&summary, &[], &warnings, &WarningConfig::default());
        let of = |region: &str, side: &str| {
            f.regions
                .iter()
                .find(|r| r.region == region && r.side == side)
                .unwrap()
        };
        let trunk = of("trunk", "");
        assert_eq!(trunk.verdict, Verdict::Change);
        assert_eq!((trunk.highest, trunk.top, trunk.warn_at), (Some(3), 6, 3));
        assert!(
            (trunk.share_at_warn - 0.3).abs() < 1e-9,
            "{}",
            trunk.share_at_warn
        );
        assert!((trunk.longest_at_warn_secs - 3.0).abs() < 1e-9);
        assert_eq!(trunk.advice, Some(Advice::TrunkRaiseOrCloser));
        let neck = of("neck", "");
        assert_eq!(neck.verdict, Verdict::Brief);
        assert!((neck.longest_at_warn_secs - 0.5).abs() < 1e-9);
        assert_eq!(neck.advice, Some(Advice::RaiseWorkPiece));
        let arm = of("upper arm", "left");
        assert_eq!((arm.verdict, arm.advice), (Verdict::Acceptable, None));
        assert_eq!(of("upper arm", "right").verdict, Verdict::NotScored);
        let forearm = of("lower arm", "left");
        assert_eq!(
            (forearm.verdict, forearm.warnings_raised, forearm.advice),
            (Verdict::Change, 1, Some(Advice::ForearmInFront))
        );
        // Every region per side, in order.
        assert_eq!(f.regions.len(), 9);
        // The time at each action level adds up to the scored time (grand 3: level 2 throughout).
        assert!((f.action_level_secs[1] - summary.duration_secs).abs() < 1e-9);
        assert_eq!(f.unscored_secs, 0.0);
    }

    #[test]
    fn a_warning_for_an_arm_reaching_back_advises_bringing_the_work_in_front() {
        let mut b = SummaryBuilder::new(DEFAULT_MAX_FRAME_NANOS);
        for k in 0..10 {
            let side = ScoredSide {
                scores: scores(1, 1, 2, 3),
                uncertain: false,
                reba: None,
                posture_cost: None,
            };
            b.add_scores(k * 100_000_000, None, Some(side));
        }
        let warnings = [warning("upper_arm", "right", 3, -35.0)];
        let f = findings(&b.finish(), &[], &warnings, &WarningConfig::default());
        let arm = f
            .regions
            .iter()
            .find(|r| r.region == "upper arm" && r.side == "right")
            .unwrap();
        assert_eq!(arm.advice, Some(Advice::BringInFront));
        assert_eq!(arm.advice_text, Some(Advice::BringInFront.text()));
    }

    #[test]
    fn worst_moments_are_the_worst_frames_ten_seconds_apart() {
        let frame = |t: f64, grand: u8, trunk: u8| FrameBrief {
            t,
            action_level: ergocell_ergonomics::rula::action_level(grand),
            left: Some(scores(trunk, 1, 1, grand)),
            right: None,
            flexion_deg: Flexions::default(),
        };
        let frames = [
            frame(0.0, 2, 1),
            frame(3.0, 6, 4),
            frame(5.0, 7, 5),  // the worst
            frame(12.0, 6, 4), // 7 s from it: the same moment
            frame(16.0, 5, 3),
            frame(40.0, 6, 2),
            frame(60.0, 3, 1),
        ];
        let m = worst_moments(&frames, &WarningConfig::default());
        let times: Vec<f64> = m.iter().map(|m| m.t).collect();
        assert_eq!(times, [5.0, 40.0, 16.0]);
        assert_eq!(m[0].action_level, 4);
        assert_eq!(
            m[0].regions,
            [RegionScore {
                region: "trunk",
                side: "",
                score: 5
            }]
        );
        assert_eq!((m[0].grand_left, m[0].grand_right), (Some(7), None));
        // Nothing past action level 1: no worst moment.
        assert!(worst_moments(&frames[..1], &WarningConfig::default()).is_empty());
    }

    #[test]
    fn one_stretch_is_one_moment_however_long() {
        // 10 Hz: 40 s at action level 4 (grand 7), then 20 s at level 1, then 5 s at level 3.
        let mut frames = Vec::new();
        for k in 0..650 {
            let t = f64::from(k) * 0.1;
            let grand = if t < 40.0 {
                7
            } else if t < 60.0 {
                2
            } else {
                5
            };
            frames.push(FrameBrief {
                t,
                action_level: ergocell_ergonomics::rula::action_level(grand),
                left: Some(scores(4, 1, 1, grand)),
                right: None,
                flexion_deg: Flexions::default(),
            });
        }
        let m = worst_moments(&frames, &WarningConfig::default());
        let levels: Vec<(f64, u8)> = m.iter().map(|m| (m.t, m.action_level)).collect();
        // The long stretch once (its first frame), the later one once.
        assert_eq!(levels, [(0.0, 4), (60.0, 3)]);
    }

    #[test]
    fn without_a_warning_the_advice_follows_the_worst_frames_direction() {
        // The neck at 4 (bent back) for half a second, forward at 2 otherwise: brief, and the
        // advice is for the neck bent back, whatever the rest of the session.
        let mut b = SummaryBuilder::new(DEFAULT_MAX_FRAME_NANOS);
        let mut frames = Vec::new();
        for k in 0..100 {
            let back = (40..45).contains(&k);
            let s = scores(1, if back { 4 } else { 2 }, 1, 3);
            b.add_scores(
                i64::from(k) * 100_000_000,
                Some(ScoredSide {
                    scores: s,
                    uncertain: false,
                    reba: None,
                    posture_cost: None,
                }),
                None,
            );
            frames.push(FrameBrief {
                t: f64::from(k) * 0.1,
                action_level: 2,
                left: Some(s),
                right: None,
                flexion_deg: Flexions {
                    neck: Some(if back { -12.0 } else { 15.0 }),
                    ..Flexions::default()
                },
            });
        }
        let f = findings(&b.finish(), &frames, &[], &WarningConfig::default());
        let neck = f.regions.iter().find(|r| r.region == "neck").unwrap();
        assert_eq!(neck.verdict, Verdict::Brief);
        assert_eq!(neck.advice, Some(Advice::NeckLowerOrInFront));
        assert_eq!(f.dwell_s, 2.0);
    }
}
