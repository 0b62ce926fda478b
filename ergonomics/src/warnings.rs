//! Posture warnings an operator can trust: per body region, with hysteresis and a minimum dwell time.
//!
//! RULA's band edges are sharp (neck 19.9° scores 2, 20° scores 3) while measured angles jitter by a
//! few degrees. The scorer does not bend the method; this module keeps the *warnings* from
//! flickering:
//!
//! - Each region (upper arm, lower arm and wrist per side; neck, trunk, legs) has a reported score
//!   `L`, and the angle `a_L` at which `L` was last set. Every frame gives two candidate scores:
//!   `hi`, the region's RULA score at the measured angle `x`, and `lo`, the score at `x` moved towards
//!   `a_L` by the hysteresis margin (default 5°, never past `a_L`). So a posture has to be the margin
//!   inside a lower band before the level may fall: a neck warning raised at 35° clears only below
//!   15°, an extension warning only from +5°. Regions without an angle (legs) have `lo = hi`.
//! - A warning rises to a band only when the posture is past its edge by the rise margin (default
//!   3°, [`WarningConfig::rise_margin_rad`]): `hi` is then the lowest score within the margin of
//!   `x` either way. A measured angle jitters by a few degrees; a posture 1° past an edge is as
//!   likely measured 1° short of it, and a warning the operator cannot reproduce teaches them to
//!   ignore the display. The yes/no adjustments with an angle behind them (a wrist deviated past
//!   10°, a neck or trunk twisted or bent sideways, an arm abducted) are edges too: for `hi`, an
//!   adjustment that applies by less than the margin counts as not present
//!   ([`crate::assess::AdjustmentMargins`]).
//! - `L` rises to the highest level `v > L` for which `hi ≥ v` has held continuously for the dwell
//!   time (default 2 s); it falls to the lowest level `v < L` for which `lo ≤ v` has held for the
//!   dwell time. Each level keeps its own clock, so a posture that passes through a band on its way
//!   to a worse one (an arm raised through 20–45° to 100°) warns one dwell after it crossed the
//!   warning's edge, not one dwell per band it passed. A value that dithers around an edge moves
//!   neither way: each excursion restarts that edge's clock.
//! - A region warns while `L` reaches its threshold ([`WarningConfig::warn_at`]). Events are emitted
//!   when a warning is raised, changes level or clears, in plain words with the angle, the advice and
//!   the frame's RULA action level. Wrist warnings say that wrist scores are the least reliable part
//!   of RULA (raters agree poorly, weighted κ ≈ 0.15–0.17).
//! - A wrist that was never observed (a keypoint layout without hand points) is scored
//!   conservatively ([`crate::assess::UNOBSERVED_WRIST_FLEXION_DEG`]) but raises no warning: a warning
//!   states the angle and what to change, and nobody saw this wrist. Its score still counts in the
//!   frame's grand score and action level, and the frame is uncertain.
//!
//! Time comes from the frames' `stamp_nanos`; nothing here reads a clock. The tracker knows nothing
//! of the robot, so warnings keep running after a trajectory is locked.

use std::collections::BTreeMap;

use serde::{Deserialize, Serialize};

use crate::assess::{BodyRegion, FrameAssessment, InputSource, SideAssessment};
use crate::confidence::SURE_PROBABILITY;
use crate::rula::{
    action_level_meaning, legs_score, lower_arm_score, neck_score, trunk_score, upper_arm_score,
    wrist_score, RulaInput,
};
use crate::Side;

/// Warning behaviour.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct WarningConfig {
    /// How far inside a lower band a posture must be before a warning falls (default 5°).
    pub hysteresis_rad: f64,
    /// How far past a band's edge a posture must be before a warning rises to that band, and how
    /// far past its threshold a yes/no adjustment's angle must be to count for the rise (default
    /// 3°, chosen on the twin's task sessions, seeds 1–20: false warnings 5.6 → 1.2 per hour with
    /// every clear posture still warned; on the adjustments too, 0.32 → 0.16 per hour). The score
    /// is never changed; only when the warning comes.
    pub rise_margin_rad: f64,
    /// How long a change must hold before it is reported (default 2 s).
    pub dwell_nanos: i64,
    /// Region score at which each region warns, in [`BodyRegion::ALL`] order
    /// (default: upper arm 3, lower arm 3, wrist 3, neck 3, trunk 3, legs 2).
    pub warn_at: [u8; 6],
}

impl WarningConfig {
    /// The score at which `region` warns ([`WarningConfig::warn_at`]).
    pub fn warn_at_of(&self, region: BodyRegion) -> u8 {
        let k = BodyRegion::ALL
            .iter()
            .position(|r| *r == region)
            .unwrap_or(0);
        self.warn_at[k]
    }
}

impl Default for WarningConfig {
    fn default() -> Self {
        Self {
            hysteresis_rad: 5f64.to_radians(),
            rise_margin_rad: 3f64.to_radians(),
            dwell_nanos: 2_000_000_000,
            warn_at: [3, 3, 3, 3, 3, 2],
        }
    }
}

/// What happened to a warning.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum WarningKind {
    Raised,
    Changed,
    Cleared,
}

/// One warning event.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct WarningEvent {
    pub stamp_nanos: i64,
    pub kind: WarningKind,
    pub region: BodyRegion,
    pub side: Option<Side>,
    /// The reported region score after the event.
    pub region_score: u8,
    /// The region's angle at the event, degrees (none for the legs).
    pub angle_deg: Option<f64>,
    /// RULA action level of the frame's headline side.
    pub action_level: u8,
    /// Whether the frame's score was uncertain (low confidence or held inputs).
    pub uncertain: bool,
    /// The probability that the region's band at the event is right (its angle's, from the fused
    /// skeleton's spread, [`crate::confidence`]); `None` for the legs and an angle not measured.
    pub band_probability: Option<f64>,
    /// A warning raised or changed while its band is less than
    /// [`crate::confidence::SURE_PROBABILITY`] sure: the posture is near the band's limit, and the
    /// operator is told so.
    pub near_limit: bool,
    pub message: String,
}

/// The highest region score (the upper arm's 6, with both adjustments).
const MAX_LEVEL: usize = 7;

#[derive(Debug, Clone, Copy, Default)]
struct RegionState {
    level: u8,
    /// The angle at which `level` was last set.
    level_angle: Option<f64>,
    /// `up[v]`: since when `hi ≥ v` has held (levels above `level`).
    up: [Option<i64>; MAX_LEVEL + 1],
    /// `down[v]`: since when `lo ≤ v` has held (levels below `level`).
    down: [Option<i64>; MAX_LEVEL + 1],
}

/// Turns the per-frame assessments into warning events.
#[derive(Debug, Clone)]
pub struct WarningTracker {
    config: WarningConfig,
    states: BTreeMap<(BodyRegion, Option<Side>), RegionState>,
}

/// `x` moved `margin` towards `anchor`, never past it.
fn toward(x: f64, anchor: f64, margin: f64) -> f64 {
    if anchor >= x {
        (x + margin).min(anchor)
    } else {
        (x - margin).max(anchor)
    }
}

/// The worksheets a frame's warning for `region` is judged on, with their side: each scored side for
/// a sided region, the headline side's for the neck, trunk and legs; a wrist never observed (scored
/// conservatively) is not judged. The one rule for the tracker and for whoever measures it.
pub fn judged(
    frame: &FrameAssessment,
    region: BodyRegion,
) -> Vec<(Option<Side>, &crate::assess::SideAssessment)> {
    let sides: Vec<(Option<Side>, &crate::assess::SideAssessment)> = if region.is_sided() {
        Side::BOTH
            .iter()
            .filter_map(|s| frame.side(*s).map(|a| (Some(*s), a)))
            .collect()
    } else {
        frame.headline().map(|h| (None, h)).into_iter().collect()
    };
    sides
        .into_iter()
        .filter(|(_, a)| {
            !(region == BodyRegion::Wrist
                && a.source("wrist_flexion_deg") == Some(InputSource::Conservative))
        })
        .collect()
}

/// The region's angle in a worksheet (none for the legs).
pub fn region_angle(region: BodyRegion, i: &RulaInput) -> Option<f64> {
    match region {
        BodyRegion::UpperArm => Some(i.upper_arm_flexion_deg),
        BodyRegion::LowerArm => Some(i.lower_arm_flexion_deg),
        BodyRegion::Wrist => Some(i.wrist_flexion_deg),
        BodyRegion::Neck => Some(i.neck_flexion_deg),
        BodyRegion::Trunk => Some(i.trunk_flexion_deg),
        BodyRegion::Legs => None,
    }
}

/// The worksheet with the region's angle replaced by `angle_deg` (unchanged for the legs, which
/// have none).
pub fn with_region_angle(region: BodyRegion, i: &RulaInput, angle_deg: f64) -> RulaInput {
    let mut out = *i;
    match region {
        BodyRegion::UpperArm => out.upper_arm_flexion_deg = angle_deg,
        BodyRegion::LowerArm => out.lower_arm_flexion_deg = angle_deg,
        BodyRegion::Wrist => out.wrist_flexion_deg = angle_deg,
        BodyRegion::Neck => out.neck_flexion_deg = angle_deg,
        BodyRegion::Trunk => out.trunk_flexion_deg = angle_deg,
        BodyRegion::Legs => {}
    }
    out
}

/// The region's RULA score (with the worksheet's adjustments) with its angle replaced by `angle`.
pub fn region_score_at(region: BodyRegion, i: &RulaInput, angle: Option<f64>) -> u8 {
    let a = angle.or_else(|| region_angle(region, i)).unwrap_or(0.0);
    match region {
        BodyRegion::UpperArm => upper_arm_score(
            a,
            i.shoulder_raised,
            i.upper_arm_abducted,
            i.arm_supported_or_leaning,
        ),
        BodyRegion::LowerArm => lower_arm_score(a, i.lower_arm_across_midline_or_out_to_side),
        BodyRegion::Wrist => wrist_score(a, i.wrist_bent_from_midline),
        BodyRegion::Neck => neck_score(a, i.neck_twisted, i.neck_side_bending),
        BodyRegion::Trunk => trunk_score(
            a,
            i.trunk_seated_well_supported,
            i.trunk_twisted,
            i.trunk_side_bending,
        ),
        BodyRegion::Legs => legs_score(i.legs_supported_and_balanced),
    }
}

/// The score a warning may rise to: the region's lowest score within `margin_rad` of its angle
/// either way, with each yes/no adjustment that applies by less than `margin_rad` taken as not
/// present ([`crate::assess::AdjustmentMargins::settled`]). A warning rises to a band only once the
/// posture is that far past the band's edge, whether the edge is the angle's or an adjustment's.
/// The score itself when the margin is 0.
fn rise_score(region: BodyRegion, a: &SideAssessment, margin_rad: f64) -> u8 {
    let i = &a.input;
    let angle = region_angle(region, i);
    if margin_rad <= 0.0 {
        return region_score_at(region, i, angle);
    }
    let settled = a.adjustment_margins.settled(i, margin_rad);
    let at = region_score_at(region, &settled, angle);
    let margin_deg = margin_rad.to_degrees();
    match angle {
        Some(x) => [x - margin_deg, x + margin_deg]
            .iter()
            .map(|v| region_score_at(region, &settled, Some(*v)))
            .fold(at, u8::min),
        None => at,
    }
}

/// What to change for a region's posture: the advice a warning gives, and the report's
/// recommendation for the region (one wording for both).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Advice {
    /// An upper arm reaching back.
    BringInFront,
    /// An upper arm raised.
    LowerOrCloser,
    /// An upper arm raised with the shoulder lifted.
    LowerAndRelaxShoulder,
    /// A forearm across the body or out to the side.
    ForearmInFront,
    /// An elbow outside 60–100°.
    ElbowCloser,
    /// A bent wrist.
    StraightenWrist,
    /// A neck bent forward.
    RaiseWorkPiece,
    /// A neck bent back.
    NeckLowerOrInFront,
    /// A trunk bent forward.
    TrunkRaiseOrCloser,
    /// A trunk twisted (and not bent sideways).
    TurnFeet,
    /// Weight on one leg or a foot off the floor.
    BothFeet,
}

impl Advice {
    /// The advice in the operator's words.
    pub const fn text(self) -> &'static str {
        match self {
            Advice::BringInFront | Advice::ForearmInFront => "bring the work in front of you",
            Advice::LowerOrCloser => "lower the work piece or bring it closer",
            Advice::LowerAndRelaxShoulder => "lower the work piece and relax the shoulder",
            Advice::ElbowCloser => "keep the elbow between 60° and 100°: bring the work closer",
            Advice::StraightenWrist => "straighten the wrist: change the grip or the tool angle",
            Advice::RaiseWorkPiece => "raise the work piece",
            Advice::NeckLowerOrInFront => "lower the work piece or bring it in front of you",
            Advice::TrunkRaiseOrCloser => "raise the work or bring it closer",
            Advice::TurnFeet => "turn your feet towards the work",
            Advice::BothFeet => "stand on both feet",
        }
    }

    /// The advice for a region in a posture (what [`describe`] says).
    pub fn for_posture(region: BodyRegion, i: &RulaInput) -> Self {
        match region {
            BodyRegion::UpperArm if i.upper_arm_flexion_deg < 0.0 => Advice::BringInFront,
            BodyRegion::UpperArm if i.shoulder_raised => Advice::LowerAndRelaxShoulder,
            BodyRegion::UpperArm => Advice::LowerOrCloser,
            BodyRegion::LowerArm if i.lower_arm_across_midline_or_out_to_side => {
                Advice::ForearmInFront
            }
            BodyRegion::LowerArm => Advice::ElbowCloser,
            BodyRegion::Wrist => Advice::StraightenWrist,
            BodyRegion::Neck if i.neck_flexion_deg < 0.0 => Advice::NeckLowerOrInFront,
            BodyRegion::Neck => Advice::RaiseWorkPiece,
            BodyRegion::Trunk if i.trunk_twisted && !i.trunk_side_bending => Advice::TurnFeet,
            BodyRegion::Trunk => Advice::TrunkRaiseOrCloser,
            BodyRegion::Legs => Advice::BothFeet,
        }
    }

    /// The advice for a region known only by its main angle (degrees, the region's flexion as a
    /// warning records it; `None` when not known) and its score: what a report recommends for a
    /// region whose worst posture it knows that far. A forearm at 3 or more is across the body or
    /// out to the side (RULA's elbow bands alone reach 2); a lifted shoulder or a twist cannot be
    /// told from the score, and gets the region's main advice.
    pub fn for_score(region: BodyRegion, angle_deg: Option<f64>, score: u8) -> Self {
        let back = angle_deg.is_some_and(|a| a < 0.0);
        match region {
            BodyRegion::UpperArm if back => Advice::BringInFront,
            BodyRegion::UpperArm => Advice::LowerOrCloser,
            BodyRegion::LowerArm if score >= 3 => Advice::ForearmInFront,
            BodyRegion::LowerArm => Advice::ElbowCloser,
            BodyRegion::Wrist => Advice::StraightenWrist,
            BodyRegion::Neck if back => Advice::NeckLowerOrInFront,
            BodyRegion::Neck => Advice::RaiseWorkPiece,
            BodyRegion::Trunk => Advice::TrunkRaiseOrCloser,
            BodyRegion::Legs => Advice::BothFeet,
        }
    }
}

/// Plain-words description and advice for a region in a posture.
pub fn describe(region: BodyRegion, side: Option<Side>, i: &RulaInput) -> String {
    let who = |part: &str| match side {
        Some(s) => format!("{} {part}", capitalise(s.name())),
        None => capitalise(part),
    };
    let advice = Advice::for_posture(region, i).text();
    match region {
        BodyRegion::UpperArm => {
            let a = i.upper_arm_flexion_deg;
            if a < 0.0 {
                format!("{} reaching back {:.0}° — {advice}", who("upper arm"), -a)
            } else if i.shoulder_raised {
                format!(
                    "{} raised {a:.0}° with the shoulder lifted — {advice}",
                    who("upper arm")
                )
            } else {
                format!("{} raised {a:.0}° — {advice}", who("upper arm"))
            }
        }
        BodyRegion::LowerArm => {
            let a = i.lower_arm_flexion_deg;
            if i.lower_arm_across_midline_or_out_to_side {
                format!(
                    "{} working across the body or out to the side (elbow {a:.0}°) — {advice}",
                    who("forearm")
                )
            } else {
                format!("{} at {a:.0}° — {advice}", who("elbow"))
            }
        }
        BodyRegion::Wrist => format!(
            "{} bent {:.0}°{} — {advice} (wrist scores are the least reliable part of RULA)",
            who("wrist"),
            i.wrist_flexion_deg.abs(),
            if i.wrist_bent_from_midline {
                " and to the side"
            } else {
                ""
            }
        ),
        BodyRegion::Neck => {
            let a = i.neck_flexion_deg;
            let extra = match (i.neck_twisted, i.neck_side_bending) {
                (true, true) => ", twisted and tilted",
                (true, false) => ", twisted",
                (false, true) => ", tilted to the side",
                (false, false) => "",
            };
            if a < 0.0 {
                format!("Neck bent back {:.0}°{extra} — {advice}", -a)
            } else {
                format!("Neck bent forward {a:.0}°{extra} — {advice}")
            }
        }
        BodyRegion::Trunk => {
            let a = i.trunk_flexion_deg.max(0.0);
            // A twist alone: the advice is to turn the feet (said after the twist, as before).
            let extra = match (i.trunk_twisted, i.trunk_side_bending) {
                (true, true) => ", twisted and leaning sideways",
                (true, false) => ", twisted",
                (false, true) => ", leaning sideways",
                (false, false) => "",
            };
            if matches!(Advice::for_posture(region, i), Advice::TurnFeet) {
                format!(
                    "Trunk bent forward {a:.0}°{extra} — {advice}; {}",
                    Advice::TrunkRaiseOrCloser.text()
                )
            } else {
                format!("Trunk bent forward {a:.0}°{extra} — {advice}")
            }
        }
        BodyRegion::Legs => format!("Weight on one leg or a foot off the floor — {advice}"),
    }
}

fn lowercase_first(s: &str) -> String {
    let mut c = s.chars();
    c.next().map_or_else(String::new, |f| {
        f.to_lowercase().collect::<String>() + c.as_str()
    })
}

fn capitalise(s: &str) -> String {
    let mut c = s.chars();
    match c.next() {
        Some(f) => f.to_uppercase().chain(c).collect(),
        None => String::new(),
    }
}

impl WarningTracker {
    pub fn new(config: WarningConfig) -> Self {
        Self {
            config,
            states: BTreeMap::new(),
        }
    }

    /// The currently reported score of a region (1 before anything was reported).
    pub fn level(&self, region: BodyRegion, side: Option<Side>) -> u8 {
        self.states
            .get(&(region, side))
            .map_or(1, |s| s.level.max(1))
    }

    /// Feeds one frame; returns the events it caused.
    pub fn update(&mut self, frame: &FrameAssessment) -> Vec<WarningEvent> {
        let mut events = Vec::new();
        let Some(head) = frame.headline() else {
            return events;
        };
        let action_level = head.scores.action_level;
        let margin_deg = self.config.hysteresis_rad.to_degrees();
        for (ri, region) in BodyRegion::ALL.iter().enumerate() {
            for (side, assessment) in judged(frame, *region) {
                let input = &assessment.input;
                let angle = region_angle(*region, input);
                let warn_at = self.config.warn_at[ri];
                let state = self.states.entry((*region, side)).or_default();
                let hi = rise_score(*region, assessment, self.config.rise_margin_rad);
                let lo = match (angle, state.level_angle) {
                    (Some(x), Some(anchor)) => {
                        region_score_at(*region, input, Some(toward(x, anchor, margin_deg)))
                    }
                    _ => hi,
                };
                let before = state.level.max(1);
                step(
                    state,
                    frame.stamp_nanos,
                    hi,
                    lo,
                    angle,
                    self.config.dwell_nanos,
                );
                let after = state.level.max(1);
                let (was, is) = (before >= warn_at, after >= warn_at);
                let kind = match (was, is) {
                    (false, true) => Some(WarningKind::Raised),
                    (true, false) => Some(WarningKind::Cleared),
                    (true, true) if before != after => Some(WarningKind::Changed),
                    _ => None,
                };
                if let Some(kind) = kind {
                    let label = match side {
                        Some(s) => format!(
                            "{} {}",
                            capitalise(s.name()),
                            region.name().replace('_', " ")
                        ),
                        None => capitalise(&region.name().replace('_', " ")),
                    };
                    let message = match kind {
                        WarningKind::Cleared => format!("{label} back within limits"),
                        // Stepping down one level at a time (hysteresis): say so, with the posture
                        // now, not the advice for the posture that raised the warning.
                        WarningKind::Changed if after < before => {
                            let now = describe(*region, side, &assessment.input);
                            let now = now.split(" — ").next().unwrap_or(&now);
                            let now = now.strip_prefix(label.as_str()).map_or_else(
                                || lowercase_first(now),
                                |rest| rest.trim_start().to_owned(),
                            );
                            format!(
                                "{label} easing: now {now}; the warning clears once the posture stays within limits"
                            )
                        }
                        _ => format!(
                            "{} (action level {action_level}: {})",
                            describe(*region, side, &assessment.input),
                            action_level_meaning(action_level)
                        ),
                    };
                    let band_probability =
                        assessment.confidence.get(*region).map(|c| c.probability);
                    events.push(WarningEvent {
                        stamp_nanos: frame.stamp_nanos,
                        kind,
                        region: *region,
                        side,
                        region_score: after,
                        angle_deg: angle,
                        action_level,
                        uncertain: assessment.uncertain,
                        band_probability,
                        near_limit: kind != WarningKind::Cleared
                            && band_probability.is_some_and(|p| p < SURE_PROBABILITY),
                        message,
                    });
                }
            }
        }
        events
    }
}

/// One step of the hysteresis/dwell state machine (see the module docs).
fn step(state: &mut RegionState, stamp: i64, hi: u8, lo: u8, angle: Option<f64>, dwell_nanos: i64) {
    let level = usize::from(state.level.max(1));
    let (hi, lo) = (usize::from(hi), usize::from(lo));
    let held = |since: Option<i64>| since.is_some_and(|s| stamp.saturating_sub(s) >= dwell_nanos);
    for v in 1..=MAX_LEVEL {
        state.up[v] = if v > level && hi >= v {
            Some(state.up[v].unwrap_or(stamp))
        } else {
            None
        };
    }
    if let Some(v) = (level + 1..=MAX_LEVEL).rev().find(|v| held(state.up[*v])) {
        state.level = u8::try_from(v).unwrap_or(u8::MAX);
        state.level_angle = angle;
        // Levels above keep their clocks: a worse band entered meanwhile follows one dwell after
        // it was entered.
        for u in &mut state.up[..=v] {
            *u = None;
        }
        state.down = [None; MAX_LEVEL + 1];
        return;
    }
    for v in 1..=MAX_LEVEL {
        state.down[v] = if v < level && lo <= v {
            Some(state.down[v].unwrap_or(stamp))
        } else {
            None
        };
    }
    if let Some(v) = (1..level).find(|v| held(state.down[*v])) {
        state.level = u8::try_from(v).unwrap_or(u8::MAX);
        state.level_angle = angle;
        for d in &mut state.down[v..] {
            *d = None;
        }
        state.up = [None; MAX_LEVEL + 1];
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The warning's words and the report's recommendation come from one place: every description
    /// carries its posture's advice, and the advice follows the posture's direction.
    #[test]
    fn each_warning_says_the_advice_its_posture_gets() {
        let mut back = RulaInput::neutral();
        back.upper_arm_flexion_deg = -30.0;
        back.neck_flexion_deg = -15.0;
        let mut forward = RulaInput::neutral();
        forward.upper_arm_flexion_deg = 70.0;
        forward.neck_flexion_deg = 25.0;
        forward.trunk_flexion_deg = 40.0;
        let mut twisted = forward;
        twisted.trunk_twisted = true;
        // Across the body with the elbow outside 60–100°: 3, where the forearm warns.
        let mut across = forward;
        across.lower_arm_across_midline_or_out_to_side = true;
        across.lower_arm_flexion_deg = 130.0;
        let mut lifted = forward;
        lifted.shoulder_raised = true;
        let cases = [
            (BodyRegion::UpperArm, &back, Advice::BringInFront),
            (BodyRegion::UpperArm, &forward, Advice::LowerOrCloser),
            (BodyRegion::UpperArm, &lifted, Advice::LowerAndRelaxShoulder),
            (BodyRegion::Neck, &back, Advice::NeckLowerOrInFront),
            (BodyRegion::Neck, &forward, Advice::RaiseWorkPiece),
            (BodyRegion::Trunk, &forward, Advice::TrunkRaiseOrCloser),
            (BodyRegion::Trunk, &twisted, Advice::TurnFeet),
            (BodyRegion::LowerArm, &forward, Advice::ElbowCloser),
            (BodyRegion::LowerArm, &across, Advice::ForearmInFront),
            (BodyRegion::Wrist, &forward, Advice::StraightenWrist),
            (BodyRegion::Legs, &forward, Advice::BothFeet),
        ];
        for (region, input, advice) in cases {
            assert_eq!(Advice::for_posture(region, input), advice, "{region:?}");
            let words = describe(region, Some(Side::Right), input);
            assert!(words.contains(advice.text()), "{words}");
            // From the main angle and the score the same, except what needs an adjustment the
            // score cannot show (the twist, the lifted shoulder): then the region's main advice.
            let angle = region_angle(region, input);
            let score = region_score_at(region, input, angle);
            let expected = match advice {
                Advice::TurnFeet => Advice::TrunkRaiseOrCloser,
                Advice::LowerAndRelaxShoulder => Advice::LowerOrCloser,
                a => a,
            };
            assert_eq!(
                Advice::for_score(region, angle, score),
                expected,
                "{region:?}"
            );
        }
    }
}
