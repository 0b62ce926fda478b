//! Static postures of the trunk, the neck and the upper arms against ISO 11226:2000 ("Ergonomics —
//! Evaluation of static working postures"): how long a posture outside the acceptable zone was held,
//! and whether the standard accepts that.
//!
//! # The limits used, and where they come from
//! The standard itself could not be read here (it is sold, not published). The numbers are the
//! standard's as two public summaries give them, and they agree:
//! - **Trunk inclination** (the trunk axis from vertical, forwards; ergocell's trunk flexion):
//!   0°–20° acceptable; 20°–60° acceptable for a **maximum holding time** falling from 4 min at 20°
//!   to 1 min at 60° ("20°: max. 4 minuten / 30°: max. 3'15 / 40°: max. 2'30 / 50°: max. 1'45 /
//!   60°: max. 1′", <https://www.ergonomiesite.be/iso11226/> — a straight line, 4.5 s less per
//!   degree, [`trunk_max_holding_secs`]); beyond 60° not acceptable; extension (below 0°) acceptable
//!   only with full support of the trunk (ibid.). Table 2 of an occupational-medicine study,
//!   "Evaluation guideline values according to ISO 11226 and DIN EN 1005–4"
//!   (<https://occup-med.biomedcentral.com/articles/10.1186/s12995-020-00286-9/tables/2>), gives the
//!   same zones: trunk "neutral 0°–20°, moderate 20°–60°, awkward < 0° & > 60°". A held extension
//!   (beyond [`EXTENSION_DEAD_BAND_DEG`], below) counts as not acceptable unless the task says the
//!   trunk is supported (`TaskConfig::seated_well_supported`: `ergocell rula track --task`); a
//!   recording does not carry the task, so the review treats the trunk as unsupported.
//! - **Neck flexion** (the head relative to the trunk; ergocell's neck flexion): 0°–25° acceptable;
//!   beyond 25° or any extension not acceptable ("Nekbuiging … < 0° (extensie) niet aanvaardbaar /
//!   0 – 25° OK / > 25 niet aanvaardbaar", ergonomiesite.be; "cervical spine flexion/extension:
//!   neutral 0°–25°, awkward < 0° & > 25°", the study's table 2).
//! - **Static**: a posture held for more than 4 s (EN 1005-4's definition, as
//!   <https://docs.spinewise.be/en/params/dynamic> quotes it: "a posture held for longer than four
//!   seconds").
//!
//! - **Upper arm elevation** (the upper arm from the world's vertical, any direction; per side):
//!   0°–20° acceptable, 20°–60° conditionally acceptable, beyond 60° not acceptable — EN 1005-4's
//!   zones as the posture table of a public 3DEXPERIENCE ergonomics help page reproduces them
//!   ("Acceptable - Upper arms angle | 0–20 degrees"; "20–60 degrees" acceptable or conditionally
//!   acceptable by frequency; "Not Acceptable - Upper arms angle | Greater than 60 degrees",
//!   <https://help-3dexperience.aesvietnam.com/English/DelMhtUserMap/mht-t-Fault_Monitor.htm>).
//!   ISO 11226 gives the 20°–60° zone a maximum holding time, but no readable source for its numbers
//!   was found (one open-source tool uses 3 min at 20° to 1 min at 60° without a source; a number
//!   from memory would be a guess): such holds are **reported with their durations and no verdict**
//!   ([`Limit::Unknown`]) — the ergonomist judges them — while a static hold beyond 60° is not
//!   acceptable.
//!
//! Not assessed: the **head inclination** (the head's axis from vertical, which the landmarks give
//! only through the face), the standard's **recovery time** (the two versions of the summary
//! disagree: an equally long rest, or one making the total 80 % of the maximum holding time), and
//! the rest of ISO 11226 that no readable source gave ergocell the numbers of: trunk and neck twist
//! and side bend, upper-arm retroflexion, adduction and shoulder raising, elbow and wrist extremes,
//! kneeling and squatting. RULA and REBA score several of those per frame; this module does not
//! judge them as static postures.
//!
//! # ergocell's own choices, and why
//! - **Extension dead band** ([`EXTENSION_DEAD_BAND_DEG`], 5°): trunk and neck extension count only
//!   beyond 5°. ergocell's neck angle is the line from the shoulder midpoint to the ear midpoint, and
//!   its trunk angle the hip-to-shoulder line; relaxed upright standing reads a few degrees either
//!   side of 0° on both (person to person and with the detector's noise), so without the band every
//!   4 s of neutral standing could read as a held, not acceptable extension.
//! - **Brief returns** ([`RETURN_MIN_SECS`], 1 s): a hold ends only when the angle has been back in
//!   the acceptable zone for 1 s; a shorter return (noise across a band edge, a glance) is part of
//!   the hold and its time counts. The same holds for a stretch in a zone not acceptable at all.
//! - **Occlusion**: frames in which the part was not seen neither end a hold nor end it early; their
//!   time counts when the hold goes on after them, and does not when it turns out to have ended.
//!
//! # How a hold is measured
//! A hold is a run of frames with the angle outside the acceptable zone, each frame standing for the
//! time to the next frame (time-weighted, as [`crate::summary`] counts); an interval longer than
//! `max_frame_nanos` (a gap in the recording) or a return to the acceptable zone of at least
//! [`RETURN_MIN_SECS`] ends it (see above for brief returns and occlusion). Band edges follow
//! ergocell's convention
//! ([`crate::rula`]): a shared edge belongs to the higher band, so 20° is in the time-limited zone,
//! 60° still in it ("beyond 60°" is strict), 25° of neck flexion acceptable ("0–25° OK", "> 25").
//! A static hold (longer than [`STATIC_MIN_SECS`]) is **not acceptable** when it stayed in a zone that
//! is not acceptable at all (trunk beyond 60° or extended, the neck outside 0°–25°) for longer than
//! [`STATIC_MIN_SECS`] at a stretch, or when it lasted longer than the maximum holding time at the
//! largest angle it reached within the time-limited zone (conservative: a hold acceptable at its
//! worst angle is acceptable throughout; a moment beyond 60° within a bend counts at 60°).

use serde::Serialize;

/// A posture held longer than this is static (EN 1005-4), seconds.
pub const STATIC_MIN_SECS: f64 = 4.0;
/// Trunk or neck extension counts only beyond this, degrees (ergocell's; see the module docs).
pub const EXTENSION_DEAD_BAND_DEG: f64 = 5.0;
/// A return to the acceptable zone this long ends a hold, seconds (ergocell's; see the module docs).
pub const RETURN_MIN_SECS: f64 = 1.0;

/// Trunk flexion at which the time-limited zone starts and ends, degrees (ISO 11226).
pub const TRUNK_ZONE_DEG: [f64; 2] = [20.0, 60.0];
/// The maximum holding times at the zone's two ends, seconds (4 min at 20°, 1 min at 60°).
pub const TRUNK_HOLDING_SECS: [f64; 2] = [240.0, 60.0];
/// Neck flexion beyond which a held posture is not acceptable, degrees (ISO 11226).
pub const NECK_ACCEPTABLE_MAX_DEG: f64 = 25.0;
/// Upper arm elevation at which the conditionally acceptable zone starts and ends, degrees (EN 1005-4,
/// ISO 11226).
pub const UPPER_ARM_ZONE_DEG: [f64; 2] = [20.0, 60.0];

/// How long a posture may be held.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[serde(tag = "kind", content = "secs", rename_all = "snake_case")]
pub enum Limit {
    /// Acceptable without a time limit.
    Unlimited,
    /// Acceptable for at most this long, seconds.
    Secs(f64),
    /// Time-limited, but no readable source gives the limit (see the module docs).
    Unknown,
    /// Not acceptable held at all (static).
    NotAcceptable,
}

/// The body parts assessed.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum BodyPart {
    Trunk,
    Neck,
    LeftUpperArm,
    RightUpperArm,
}

impl BodyPart {
    pub const ALL: [Self; 4] = [
        Self::Trunk,
        Self::Neck,
        Self::LeftUpperArm,
        Self::RightUpperArm,
    ];

    pub const fn name(self) -> &'static str {
        match self {
            Self::Trunk => "trunk",
            Self::Neck => "neck",
            Self::LeftUpperArm => "left upper arm",
            Self::RightUpperArm => "right upper arm",
        }
    }

    /// The part as a body region name and a side, as the summary CSV writes them
    /// (`("upper_arm", "left")`, `("trunk", "")`).
    pub const fn region_and_side(self) -> (&'static str, &'static str) {
        match self {
            Self::Trunk => ("trunk", ""),
            Self::Neck => ("neck", ""),
            Self::LeftUpperArm => ("upper_arm", "left"),
            Self::RightUpperArm => ("upper_arm", "right"),
        }
    }

    /// How long a posture at `deg` may be held (band edges: see the module docs).
    pub fn limit(self, deg: f64) -> Limit {
        match self {
            Self::Trunk | Self::Neck if (-EXTENSION_DEAD_BAND_DEG..0.0).contains(&deg) => {
                Limit::Unlimited
            }
            Self::Trunk => match trunk_max_holding_secs(deg) {
                None => Limit::NotAcceptable,
                Some(s) if s.is_infinite() => Limit::Unlimited,
                Some(s) => Limit::Secs(s),
            },
            Self::Neck if (0.0..=NECK_ACCEPTABLE_MAX_DEG).contains(&deg) => Limit::Unlimited,
            Self::Neck => Limit::NotAcceptable,
            Self::LeftUpperArm | Self::RightUpperArm => {
                let [lo, hi] = UPPER_ARM_ZONE_DEG;
                if deg < lo {
                    Limit::Unlimited
                } else if deg <= hi {
                    Limit::Unknown
                } else {
                    Limit::NotAcceptable
                }
            }
        }
    }
}

/// ISO 11226's maximum holding time of a trunk inclination, seconds: infinite from 0° to below 20°,
/// 240 s at 20° falling linearly to 60 s at 60°, `None` (not acceptable) beyond 60° and for extension.
pub fn trunk_max_holding_secs(flexion_deg: f64) -> Option<f64> {
    let [lo, hi] = TRUNK_ZONE_DEG;
    let [at_lo, at_hi] = TRUNK_HOLDING_SECS;
    if !(0.0..=hi).contains(&flexion_deg) {
        None
    } else if flexion_deg < lo {
        Some(f64::INFINITY)
    } else {
        Some(at_lo + (at_hi - at_lo) * (flexion_deg - lo) / (hi - lo))
    }
}

/// One static hold outside the acceptable zone.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct StaticHold {
    pub part: BodyPart,
    /// When it started (the frame's stamp), nanoseconds.
    pub start_nanos: i64,
    pub duration_secs: f64,
    /// The angle farthest from the acceptable zone it reached, degrees.
    pub peak_deg: f64,
    /// The maximum holding time at the largest angle it reached within the time-limited zone,
    /// seconds; `None` when it never was in one (every neck hold, a trunk extension) or the limit is
    /// not known (`limit_unknown`).
    pub limit_secs: Option<f64>,
    /// It was in a time-limited zone whose limit no readable source gives (the upper arm's 20°–60°):
    /// its duration is reported without a verdict on that part.
    pub limit_unknown: bool,
    /// Its longest unbroken stretch in a zone not acceptable at all, seconds (0 when none).
    pub not_acceptable_secs: f64,
    /// Static in a zone that is not acceptable, or held longer than `limit_secs`.
    pub exceeded: bool,
}

/// One body part's static holds over a session.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct StaticPostureSummary {
    pub part: BodyPart,
    /// Holds outside the acceptable zone longer than [`STATIC_MIN_SECS`].
    pub static_holds: usize,
    /// Of them, those ISO 11226 does not accept (too long, or in a zone not acceptable at all).
    pub exceeded: usize,
    /// Of them, those not exceeded but held in a zone whose time limit is not known (the upper
    /// arm's 20°–60°): for the ergonomist to judge.
    pub limit_unknown: usize,
    /// The longest static hold, seconds (0 when none).
    pub longest_secs: f64,
    /// All static holds together, seconds.
    pub total_secs: f64,
    /// Every static hold, in time order.
    pub holds: Vec<StaticHold>,
}

/// A hold under way.
#[derive(Debug, Clone, Copy)]
struct Run {
    start: i64,
    /// Its time up to its last frame outside the zone, seconds.
    duration: f64,
    /// Time since that frame (back in the zone, or not seen), not yet counted.
    pending: f64,
    /// Of `pending`, the time back in the acceptable zone.
    pending_inside: f64,
    peak: f64,
    /// The largest angle within the time-limited zone (trunk 20°–60°; a moment beyond 60° counts
    /// at 60°).
    limited_peak: Option<f64>,
    /// It was in a time-limited zone without a known limit.
    unknown: bool,
    /// The current and the longest stretch in a zone not acceptable at all; `bad_pending` the time
    /// since that stretch's last frame.
    bad_now: f64,
    bad_pending: f64,
    bad_longest: f64,
}

impl Run {
    /// `dt` out of the not-acceptable zone: a stretch under way ends after [`RETURN_MIN_SECS`].
    fn bad_pause(&mut self, dt: f64) {
        if self.bad_now > 0.0 {
            self.bad_pending += dt;
            if self.bad_pending >= RETURN_MIN_SECS - TIME_EPS {
                self.bad_now = 0.0;
                self.bad_pending = 0.0;
            }
        }
    }
}

/// Sums of frame times are compared with this slack, seconds (ten 0.1 s frames make 0.9999…).
const TIME_EPS: f64 = 1e-6;

/// One frame as [`holds_of`] reads it: its stamp, its angle in degrees (`None`: not seen) and the
/// time it stands for, seconds.
type Sample = (i64, Option<f64>, f64);

/// The holds of one part from its samples in time order (no gap among them).
fn holds_of(part: BodyPart, samples: &[Sample], trunk_supported: bool) -> StaticPostureSummary {
    // a trunk extension with the trunk fully supported is acceptable (ISO 11226, as summarised)
    let limit_of = |deg: f64| {
        if part == BodyPart::Trunk && trunk_supported && deg < 0.0 {
            Limit::Unlimited
        } else {
            part.limit(deg)
        }
    };
    let mut holds = Vec::new();
    let mut current: Option<Run> = None;
    let mut close = |run: Option<Run>| {
        if let Some(r) = run {
            if r.duration > STATIC_MIN_SECS {
                let limit = r.limited_peak.and_then(|deg| match limit_of(deg) {
                    Limit::Secs(s) => Some(s),
                    _ => None,
                });
                holds.push(StaticHold {
                    part,
                    start_nanos: r.start,
                    duration_secs: r.duration,
                    peak_deg: r.peak,
                    limit_secs: limit,
                    limit_unknown: r.unknown,
                    not_acceptable_secs: r.bad_longest,
                    exceeded: r.bad_longest > STATIC_MIN_SECS
                        || limit.is_some_and(|l| r.duration > l),
                });
            }
        }
    };
    for &(t, deg, dt) in samples {
        let Some(deg) = deg.filter(|&d| limit_of(d) != Limit::Unlimited) else {
            // back in the zone, or not seen: pending until the hold goes on or ends
            if let Some(r) = current.as_mut() {
                r.pending += dt;
                r.bad_pause(dt);
                if deg.is_some() {
                    r.pending_inside += dt;
                    if r.pending_inside >= RETURN_MIN_SECS - TIME_EPS {
                        close(current.take());
                    }
                }
            }
            continue;
        };
        let r = current.get_or_insert(Run {
            start: t,
            duration: 0.0,
            pending: 0.0,
            pending_inside: 0.0,
            peak: deg,
            limited_peak: None,
            unknown: false,
            bad_now: 0.0,
            bad_pending: 0.0,
            bad_longest: 0.0,
        });
        r.duration += r.pending + dt;
        r.pending = 0.0;
        r.pending_inside = 0.0;
        // the farthest from the zone: the largest flexion, or the deepest extension
        if (deg < 0.0 && deg < r.peak) || (deg >= 0.0 && deg > r.peak) {
            r.peak = deg;
        }
        let limit = limit_of(deg);
        if limit == Limit::NotAcceptable {
            r.bad_now += r.bad_pending + dt;
            r.bad_pending = 0.0;
            r.bad_longest = r.bad_longest.max(r.bad_now);
        } else {
            r.bad_pause(dt);
        }
        match limit {
            // a moment beyond the time-limited zone's top counts at its top
            Limit::NotAcceptable if part == BodyPart::Trunk && deg > TRUNK_ZONE_DEG[1] => {
                r.limited_peak = Some(
                    r.limited_peak
                        .map_or(TRUNK_ZONE_DEG[1], |p| p.max(TRUNK_ZONE_DEG[1])),
                );
            }
            Limit::Secs(_) => {
                r.limited_peak = Some(r.limited_peak.map_or(deg, |p| p.max(deg)));
            }
            Limit::Unknown => r.unknown = true,
            Limit::NotAcceptable | Limit::Unlimited => {}
        }
    }
    close(current.take());
    StaticPostureSummary {
        part,
        static_holds: holds.len(),
        exceeded: holds.iter().filter(|h| h.exceeded).count(),
        limit_unknown: holds
            .iter()
            .filter(|h| !h.exceeded && h.limit_unknown)
            .count(),
        longest_secs: holds.iter().map(|h| h.duration_secs).fold(0.0, f64::max),
        total_secs: holds
            .iter()
            .map(|h| h.duration_secs)
            .fold(0.0, |a, b| a + b),
        holds,
    }
}

/// One frame's angles as [`static_postures`] reads them, radians (`None` where not observed).
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct PostureAngles {
    pub stamp_nanos: i64,
    pub trunk_flexion_rad: Option<f64>,
    pub neck_flexion_rad: Option<f64>,
    /// `[left, right]` upper arm elevation from vertical.
    pub upper_arm_elevation_rad: [Option<f64>; 2],
}

impl PostureAngles {
    fn of(&self, part: BodyPart) -> Option<f64> {
        match part {
            BodyPart::Trunk => self.trunk_flexion_rad,
            BodyPart::Neck => self.neck_flexion_rad,
            BodyPart::LeftUpperArm => self.upper_arm_elevation_rad[0],
            BodyPart::RightUpperArm => self.upper_arm_elevation_rad[1],
        }
    }
}

/// The static holds of the trunk, the neck and each upper arm from the frames' angles in time order;
/// intervals longer than `max_frame_nanos` are gaps (see the module docs). A part never observed is
/// left out.
///
/// `trunk_supported`: the task has the trunk fully supported (a backrest), so a held extension is
/// acceptable (ISO 11226, as summarised).
pub fn static_postures(
    frames: &[PostureAngles],
    max_frame_nanos: i64,
    trunk_supported: bool,
) -> Vec<StaticPostureSummary> {
    // The frames' intervals, and the typical one a frame before a gap stands for: the same for
    // every part.
    let intervals: Vec<i64> = frames
        .windows(2)
        .map(|w| w[1].stamp_nanos.saturating_sub(w[0].stamp_nanos).max(0))
        .collect();
    let mut normal: Vec<i64> = intervals
        .iter()
        .copied()
        .filter(|&d| d <= max_frame_nanos)
        .collect();
    normal.sort_unstable();
    let typical = normal.get(normal.len() / 2).copied().unwrap_or(0) as f64 * 1e-9;
    BodyPart::ALL
        .iter()
        .filter(|&&part| frames.iter().any(|f| f.of(part).is_some()))
        .map(|&part| {
            // Split at gaps in the recording: each piece's holds separately.
            let mut summary: Option<StaticPostureSummary> = None;
            let mut piece: Vec<Sample> = Vec::new();
            let mut flush = |piece: &mut Vec<Sample>| {
                let s = holds_of(part, piece, trunk_supported);
                piece.clear();
                match summary.as_mut() {
                    None => summary = Some(s),
                    Some(acc) => {
                        acc.static_holds += s.static_holds;
                        acc.exceeded += s.exceeded;
                        acc.limit_unknown += s.limit_unknown;
                        acc.longest_secs = acc.longest_secs.max(s.longest_secs);
                        acc.total_secs += s.total_secs;
                        acc.holds.extend(s.holds);
                    }
                }
            };
            for (i, f) in frames.iter().enumerate() {
                let dt = intervals.get(i).copied();
                let gap = dt.is_some_and(|d| d > max_frame_nanos);
                let secs = match dt {
                    Some(d) if !gap => d as f64 * 1e-9,
                    _ => typical,
                };
                let deg = f.of(part).filter(|r| r.is_finite()).map(f64::to_degrees);
                piece.push((f.stamp_nanos, deg, secs));
                if gap {
                    flush(&mut piece);
                }
            }
            flush(&mut piece);
            summary.unwrap_or_else(|| holds_of(part, &[], trunk_supported))
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    const MS: i64 = 1_000_000;

    /// `secs` of frames at 10 Hz at `deg` each, from `t0_ms`.
    fn hold(t0_ms: i64, secs: f64, trunk_deg: f64, neck_deg: f64) -> Vec<PostureAngles> {
        arms(t0_ms, secs, trunk_deg, neck_deg, 0.0)
    }

    /// The same with the left arm elevated `arm_deg` (the right never observed).
    fn arms(
        t0_ms: i64,
        secs: f64,
        trunk_deg: f64,
        neck_deg: f64,
        arm_deg: f64,
    ) -> Vec<PostureAngles> {
        let n = (secs * 10.0).round() as i64;
        (0..n)
            .map(|k| PostureAngles {
                stamp_nanos: (t0_ms + k * 100) * MS,
                trunk_flexion_rad: Some(trunk_deg.to_radians()),
                neck_flexion_rad: Some(neck_deg.to_radians()),
                upper_arm_elevation_rad: [Some(arm_deg.to_radians()), None],
            })
            .collect()
    }

    #[test]
    fn the_trunk_limit_is_the_summarys_table() {
        // ergonomiesite.be: 20° 4', 30° 3'15, 40° 2'30, 50° 1'45, 60° 1'.
        for (deg, secs) in [
            (20.0, 240.0),
            (30.0, 195.0),
            (40.0, 150.0),
            (50.0, 105.0),
            (60.0, 60.0),
        ] {
            assert!(
                (trunk_max_holding_secs(deg).unwrap() - secs).abs() < 1e-9,
                "{deg}"
            );
        }
        assert_eq!(trunk_max_holding_secs(19.9), Some(f64::INFINITY));
        assert_eq!(trunk_max_holding_secs(60.01), None);
        assert_eq!(trunk_max_holding_secs(-0.5), None);
        assert_eq!(BodyPart::Neck.limit(25.0), Limit::Unlimited);
        assert_eq!(BodyPart::Neck.limit(25.1), Limit::NotAcceptable);
        assert_eq!(BodyPart::Neck.limit(-6.0), Limit::NotAcceptable);
        // within the extension dead band: upright
        assert_eq!(BodyPart::Neck.limit(-4.9), Limit::Unlimited);
        assert_eq!(BodyPart::Trunk.limit(-4.9), Limit::Unlimited);
        assert_eq!(BodyPart::Trunk.limit(-5.0), Limit::Unlimited);
        assert_eq!(BodyPart::Trunk.limit(-5.1), Limit::NotAcceptable);
        assert_eq!(BodyPart::Trunk.limit(30.0), Limit::Secs(195.0));
        let arm = BodyPart::RightUpperArm;
        assert_eq!(arm.limit(19.9), Limit::Unlimited);
        assert_eq!(
            (arm.limit(20.0), arm.limit(60.0)),
            (Limit::Unknown, Limit::Unknown)
        );
        assert_eq!(arm.limit(60.1), Limit::NotAcceptable);
    }

    #[test]
    fn a_hold_is_judged_by_its_length_against_the_limit_at_its_worst_angle() {
        // Upright 2 s, trunk 40° for 100 s (limit 150 s: fine), upright, 55° for 120 s (limit 82.5 s:
        // exceeded), upright, 70° for 3 s (not static), upright, 30° for 5 s then 70° for 2 s (one
        // static hold, its 2 s beyond 60° judged at 60°'s limit: fine), upright, 45° 1 s then 65° for 5 s (beyond 60°
        // for more than 4 s: not acceptable).
        let mut frames = hold(0, 2.0, 5.0, 10.0);
        frames.extend(hold(2_000, 100.0, 40.0, 10.0));
        frames.extend(hold(102_000, 2.0, 5.0, 10.0));
        frames.extend(hold(104_000, 120.0, 55.0, 10.0));
        frames.extend(hold(224_000, 2.0, 5.0, 10.0));
        frames.extend(hold(226_000, 3.0, 70.0, 10.0));
        frames.extend(hold(229_000, 2.0, 5.0, 10.0));
        frames.extend(hold(231_000, 5.0, 30.0, 10.0));
        frames.extend(hold(236_000, 2.0, 70.0, 10.0));
        frames.extend(hold(238_000, 2.0, 5.0, 10.0));
        frames.extend(hold(240_000, 1.0, 45.0, 10.0));
        frames.extend(hold(241_000, 5.0, 65.0, 10.0));
        frames.extend(hold(246_000, 2.0, 5.0, 10.0));
        let s = static_postures(&frames, 1_000_000_000, false);
        let trunk = &s[0];
        assert_eq!(trunk.part, BodyPart::Trunk);
        assert_eq!((trunk.static_holds, trunk.exceeded), (4, 2), "{trunk:?}");
        let [_, _, c, d] = [
            trunk.holds[0],
            trunk.holds[1],
            trunk.holds[2],
            trunk.holds[3],
        ];
        assert!((c.duration_secs - 7.0).abs() < 1e-6 && !c.exceeded, "{c:?}");
        assert_eq!(c.peak_deg.round(), 70.0);
        assert!(
            (c.limit_secs.unwrap() - 60.0).abs() < 1e-6,
            "70° counts at 60°"
        );
        assert!((c.not_acceptable_secs - 2.0).abs() < 1e-6);
        assert!(
            d.exceeded && (d.not_acceptable_secs - 5.0).abs() < 1e-6,
            "{d:?}"
        );
        let [a, b] = [trunk.holds[0], trunk.holds[1]];
        assert!((a.duration_secs - 100.0).abs() < 1e-6 && !a.exceeded);
        assert!((a.limit_secs.unwrap() - 150.0).abs() < 1e-9);
        assert!((b.duration_secs - 120.0).abs() < 1e-6 && b.exceeded);
        assert_eq!(b.start_nanos, 104_000 * MS);
        assert!((trunk.longest_secs - 120.0).abs() < 1e-6);
        // The neck stayed at 10°: acceptable, no holds.
        assert_eq!(s[1].static_holds, 0);
    }

    #[test]
    fn a_held_neck_beyond_25_degrees_or_extended_is_not_acceptable() {
        let mut frames = hold(0, 5.0, 5.0, 35.0);
        frames.extend(hold(5_000, 1.0, 5.0, 10.0));
        frames.extend(hold(6_000, 6.0, 5.0, -8.0));
        let neck = &static_postures(&frames, 1_000_000_000, false)[1];
        assert_eq!((neck.static_holds, neck.exceeded), (2, 2));
        assert_eq!(neck.holds[0].peak_deg.round(), 35.0);
        assert_eq!(neck.holds[1].peak_deg.round(), -8.0);
        assert_eq!(neck.holds[1].limit_secs, None);
    }

    #[test]
    fn a_held_arm_is_reported_without_a_verdict_below_60_and_not_acceptable_beyond() {
        // Left arm: 45° for 30 s (time-limited, limit unknown), down, 80° for 5 s (not acceptable).
        let mut frames = arms(0, 30.0, 5.0, 10.0, 45.0);
        frames.extend(arms(30_000, 1.0, 5.0, 10.0, 5.0));
        frames.extend(arms(31_000, 5.0, 5.0, 10.0, 80.0));
        let s = static_postures(&frames, 1_000_000_000, false);
        let parts: Vec<BodyPart> = s.iter().map(|p| p.part).collect();
        assert_eq!(
            parts,
            [BodyPart::Trunk, BodyPart::Neck, BodyPart::LeftUpperArm],
            "the right arm was never observed"
        );
        let arm = &s[2];
        assert_eq!(
            (arm.static_holds, arm.exceeded, arm.limit_unknown),
            (2, 1, 1)
        );
        assert!(arm.holds[0].limit_unknown && !arm.holds[0].exceeded);
        assert_eq!(arm.holds[0].limit_secs, None);
        assert!(arm.holds[1].exceeded);
    }

    #[test]
    fn a_supported_trunk_may_lean_back() {
        let frames = hold(0, 10.0, -12.0, 10.0);
        let unsupported = &static_postures(&frames, 1_000_000_000, false)[0];
        assert_eq!((unsupported.static_holds, unsupported.exceeded), (1, 1));
        let supported = &static_postures(&frames, 1_000_000_000, true)[0];
        assert_eq!(supported.static_holds, 0);
    }

    #[test]
    fn a_brief_return_or_an_occlusion_does_not_end_a_hold() {
        // Neck at 30° for 3 s, back at 20° for 0.5 s (noise across the edge), 30° for 3 s: one hold
        // of 6.5 s. Then 1 s at 20° ends it.
        let mut frames = hold(0, 3.0, 5.0, 30.0);
        frames.extend(hold(3_000, 0.5, 5.0, 20.0));
        frames.extend(hold(3_500, 3.0, 5.0, 30.0));
        frames.extend(hold(6_500, 1.0, 5.0, 20.0));
        frames.extend(hold(7_500, 3.0, 5.0, 30.0));
        let neck = &static_postures(&frames, 1_000_000_000, false)[1];
        assert_eq!(neck.static_holds, 1, "{neck:?}");
        assert!((neck.holds[0].duration_secs - 6.5).abs() < 1e-6, "{neck:?}");
        // Trunk at 50° for 3 s, 1.5 s not seen, 50° for 3 s: one hold of 7.5 s, the occlusion
        // bridged; not seen for 1.5 s and then upright: the hold ends before the occlusion.
        let occluded = |k: i64| PostureAngles {
            stamp_nanos: (3_000 + k * 100) * MS,
            ..PostureAngles::default()
        };
        let mut frames = hold(0, 3.0, 50.0, 10.0);
        frames.extend((0..15).map(occluded));
        frames.extend(hold(4_500, 3.0, 50.0, 10.0));
        let trunk = &static_postures(&frames, 1_000_000_000, false)[0];
        assert_eq!(trunk.static_holds, 1);
        assert!(
            (trunk.holds[0].duration_secs - 7.5).abs() < 1e-6,
            "{trunk:?}"
        );
        let mut frames = hold(0, 4.5, 50.0, 10.0);
        frames.extend((15..30).map(occluded));
        frames.extend(hold(6_000, 2.0, 5.0, 10.0));
        let trunk = &static_postures(&frames, 1_000_000_000, false)[0];
        assert!(
            (trunk.holds[0].duration_secs - 4.5).abs() < 1e-6,
            "{trunk:?}"
        );
    }

    #[test]
    fn gaps_and_unobserved_frames() {
        // 3 s bent, a 5 s gap (no frames), 3 s bent: two 3 s holds, neither static.
        let mut frames = hold(0, 3.0, 45.0, 10.0);
        frames.extend(hold(8_000, 3.0, 45.0, 10.0));
        assert_eq!(
            static_postures(&frames, 1_000_000_000, false)[0].static_holds,
            0
        );
        // 3 s bent, 0.5 s not observed, 3 s bent: one hold of 6.5 s (the unobserved frames skipped).
        let mut frames = hold(0, 3.0, 45.0, 10.0);
        frames.extend((0..5).map(|k| PostureAngles {
            stamp_nanos: (3_000 + k * 100) * MS,
            ..PostureAngles::default()
        }));
        frames.extend(hold(3_500, 3.0, 45.0, 10.0));
        let trunk = &static_postures(&frames, 1_000_000_000, false)[0];
        assert_eq!(trunk.static_holds, 1);
        assert!((trunk.longest_secs - 6.5).abs() < 1e-6, "{trunk:?}");
        // Nothing observed: no holds, no panic.
        assert!(static_postures(&[], 1_000_000_000, false)
            .iter()
            .all(|s| s.static_holds == 0));
    }
}
