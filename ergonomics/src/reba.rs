//! The REBA worksheet (Hignett & McAtamney, "Rapid Entire Body Assessment (REBA)", Applied Ergonomics
//! 31(2), 2000, pp. 201–205), one side at a time.
//!
//! REBA extends RULA to the whole body: it scores the legs (weight bearing, knee flexion) and grades
//! the trunk and neck differently. [`RebaInput`] is the worksheet as an ergonomist fills it in, angles
//! in **degrees** (the method is written in degrees; this is one of the two boundaries where degrees
//! live in code, beside [`crate::rula`]) and the yes/no adjustments. [`score_worksheet`] runs every
//! step and returns the [`RebaScores`] breakdown.
//!
//! # Steps
//! Group A: trunk (+1 twisted or side-bent, max 5), neck (+1 twisted or side-bent, max 3), legs
//! (+1 knees 30°–60°, +2 beyond 60°, not when seated; max 4) → Table A, + load/force (< 5 kg 0,
//! 5–10 kg 1, > 10 kg 2; +1 shock or rapid build-up) → Score A. Group B: upper arm (+1 abducted or
//! rotated, +1 shoulder raised, −1 supported or leaning, clamped to 1..=6), lower arm, wrist (+1
//! deviated or twisted, max 3) → Table B, + coupling (good 0, fair 1, poor 2, unacceptable 3) →
//! Score B. Score C = `Table C[A][B]`; REBA score = C + activity (+1 each: a body part static for
//! more than a minute; small-range actions repeated more than 4 times a minute; rapid large changes
//! of posture or an unstable base), 1..=15. Risk and action level: 1 negligible (0, none); 2–3 low
//! (1, may be necessary); 4–7 medium (2, necessary); 8–10 high (3, necessary soon); 11–15 very high
//! (4, necessary now).
//!
//! The tables ([`TABLE_A`], [`TABLE_B`], [`TABLE_C`]) are the paper's, cell for cell as the published
//! REBA worksheet reproduces them.
//!
//! # Band edges — ergocell's convention (the one of [`crate::rula`], applied to REBA's wording)
//! The worksheet's ranges share their end points ("0°–20°", "20°–60°"). An edge value shared by two
//! ranges belongs to the **higher** band; where the wording is strict ("> 20°", "> 60°", "> 90°") the
//! edge stays in the lower band:
//! - trunk: exactly 0° is upright (1); flexion or extension up to 20° scores 2, except flexion of
//!   exactly 20° (shared with "20°–60°": 3); flexion above 20° up to 60° inclusive scores 3, extension
//!   above 20° scores 3; flexion above 60° scores 4;
//! - neck: 0° to 20° flexion inclusive scores 1; above 20° flexion, or any extension, 2;
//! - knees: 30° to 60° inclusive adds 1; above 60° adds 2;
//! - upper arm: 20° extension to below 20° flexion scores 1 (extension of exactly 20° included);
//!   20° to below 45° flexion, or extension above 20°, 2; 45° to 90° inclusive, 3; above 90°, 4;
//! - lower arm: 60° to 100° inclusive scores 1, otherwise 2;
//! - wrist: up to 15° inclusive scores 1, above 15° 2;
//! - load: below 5 kg 0, 5 kg to 10 kg inclusive 1, above 10 kg 2.
//!
//! There is no hidden tolerance (trunk 0.5° is 2): noise is the business of filtering and warnings.

use serde::{Deserialize, Serialize};

use crate::rula::{json_array, parse_worksheet_entry, MAX_ABS_ANGLE_DEG};
use crate::ErgonomicsError;

/// Table A: `[neck 1..=3][trunk 1..=5][legs 1..=4]`.
pub const TABLE_A: [[[u8; 4]; 5]; 3] = [
    [
        [1, 2, 3, 4],
        [2, 3, 4, 5],
        [2, 4, 5, 6],
        [3, 5, 6, 7],
        [4, 6, 7, 8],
    ],
    [
        [1, 2, 3, 4],
        [3, 4, 5, 6],
        [4, 5, 6, 7],
        [5, 6, 7, 8],
        [6, 7, 8, 9],
    ],
    [
        [3, 3, 5, 6],
        [4, 5, 6, 7],
        [5, 6, 7, 8],
        [6, 7, 8, 9],
        [7, 8, 9, 9],
    ],
];

/// Table B: `[upper arm 1..=6][lower arm 1..=2][wrist 1..=3]`.
pub const TABLE_B: [[[u8; 3]; 2]; 6] = [
    [[1, 2, 2], [1, 2, 3]],
    [[1, 2, 3], [2, 3, 4]],
    [[3, 4, 5], [4, 5, 5]],
    [[4, 5, 5], [5, 6, 7]],
    [[6, 7, 8], [7, 8, 8]],
    [[7, 8, 8], [8, 9, 9]],
];

/// Table C: `[score A 1..=12][score B 1..=12]`.
pub const TABLE_C: [[u8; 12]; 12] = [
    [1, 1, 1, 2, 3, 3, 4, 5, 6, 7, 7, 7],
    [1, 2, 2, 3, 4, 4, 5, 6, 6, 7, 7, 8],
    [2, 3, 3, 3, 4, 5, 6, 7, 7, 8, 8, 8],
    [3, 4, 4, 4, 5, 6, 7, 8, 8, 9, 9, 9],
    [4, 4, 4, 5, 6, 7, 8, 8, 9, 9, 9, 9],
    [6, 6, 6, 7, 8, 8, 9, 9, 10, 10, 10, 10],
    [7, 7, 7, 8, 9, 9, 9, 10, 10, 11, 11, 11],
    [8, 8, 8, 9, 10, 10, 10, 10, 10, 11, 11, 11],
    [9, 9, 9, 10, 10, 10, 11, 11, 11, 12, 12, 12],
    [10, 10, 10, 11, 11, 11, 11, 12, 12, 12, 12, 12],
    [11, 11, 11, 11, 12, 12, 12, 12, 12, 12, 12, 12],
    [12, 12, 12, 12, 12, 12, 12, 12, 12, 12, 12, 12],
];

/// How well the hand holds the load (REBA's coupling score).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize, Default)]
#[serde(rename_all = "snake_case")]
pub enum Coupling {
    /// A well-fitting handle and a mid-range power grip: 0.
    #[default]
    Good,
    /// An acceptable but not ideal hand hold, or coupling through another body part: 1.
    Fair,
    /// A hand hold not acceptable although possible: 2.
    Poor,
    /// Awkward, unsafe grip, no handles; coupling unacceptable using other body parts: 3.
    Unacceptable,
}

impl Coupling {
    pub const fn score(self) -> u8 {
        match self {
            Self::Good => 0,
            Self::Fair => 1,
            Self::Poor => 2,
            Self::Unacceptable => 3,
        }
    }
}

/// One side's REBA worksheet. Field names are the public input format of `ergocell reba score`.
// The worksheet's yes/no boxes are the paper's; they stay booleans in the public format.
#[allow(clippy::struct_excessive_bools)]
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RebaInput {
    /// Trunk flexion from the world's vertical, degrees; negative = extension.
    pub trunk_flexion_deg: f64,
    /// Trunk twisted or side-bent (+1).
    pub trunk_twisted_or_side_bent: bool,
    /// Neck flexion relative to the trunk, degrees; negative = extension.
    pub neck_flexion_deg: f64,
    /// Neck twisted or side-bent (+1).
    pub neck_twisted_or_side_bent: bool,
    /// Bilateral weight bearing, walking or sitting (1); false: unilateral, feather weight bearing or
    /// an unstable posture (2).
    pub legs_bilateral_walking_or_sitting: bool,
    /// Seated: the knee adjustment does not apply.
    pub seated: bool,
    /// Knee flexion, degrees; 0 = straight (the more flexed knee of the two).
    pub knee_flexion_deg: f64,
    /// The load handled, kilograms.
    pub load_kg: f64,
    /// Shock or rapid build-up of force (+1).
    pub load_shock_or_rapid_build_up: bool,
    /// Upper-arm flexion relative to the trunk, degrees; 0 = hanging, negative = extension.
    pub upper_arm_flexion_deg: f64,
    /// Arm abducted or rotated (+1).
    pub upper_arm_abducted_or_rotated: bool,
    /// Shoulder raised (+1).
    pub shoulder_raised: bool,
    /// Arm supported or person leaning (−1).
    pub arm_supported_or_leaning: bool,
    /// Elbow flexion, degrees; 0 = straight.
    pub lower_arm_flexion_deg: f64,
    /// Wrist flexion (+) / extension (−), degrees; only the magnitude is scored.
    pub wrist_flexion_deg: f64,
    /// Wrist deviated or twisted (+1).
    pub wrist_deviated_or_twisted: bool,
    pub coupling: Coupling,
    /// One or more body parts static, e.g. held for longer than a minute (+1).
    pub activity_static: bool,
    /// Repeated small-range actions, more than 4 times a minute (+1).
    pub activity_repeated: bool,
    /// Rapid large-range changes of posture or an unstable base (+1).
    pub activity_rapid_change_or_unstable: bool,
}

impl RebaInput {
    /// The input field names, in the public order.
    pub const FIELDS: [&'static str; 20] = [
        "trunk_flexion_deg",
        "trunk_twisted_or_side_bent",
        "neck_flexion_deg",
        "neck_twisted_or_side_bent",
        "legs_bilateral_walking_or_sitting",
        "seated",
        "knee_flexion_deg",
        "load_kg",
        "load_shock_or_rapid_build_up",
        "upper_arm_flexion_deg",
        "upper_arm_abducted_or_rotated",
        "shoulder_raised",
        "arm_supported_or_leaning",
        "lower_arm_flexion_deg",
        "wrist_flexion_deg",
        "wrist_deviated_or_twisted",
        "coupling",
        "activity_static",
        "activity_repeated",
        "activity_rapid_change_or_unstable",
    ];

    /// A neutral worksheet: standing upright on both legs, arms hanging, elbows at 80°, no load.
    pub fn neutral() -> Self {
        Self {
            trunk_flexion_deg: 0.0,
            trunk_twisted_or_side_bent: false,
            neck_flexion_deg: 10.0,
            neck_twisted_or_side_bent: false,
            legs_bilateral_walking_or_sitting: true,
            seated: false,
            knee_flexion_deg: 0.0,
            load_kg: 0.0,
            load_shock_or_rapid_build_up: false,
            upper_arm_flexion_deg: 0.0,
            upper_arm_abducted_or_rotated: false,
            shoulder_raised: false,
            arm_supported_or_leaning: false,
            lower_arm_flexion_deg: 80.0,
            wrist_flexion_deg: 0.0,
            wrist_deviated_or_twisted: false,
            coupling: Coupling::Good,
            activity_static: false,
            activity_repeated: false,
            activity_rapid_change_or_unstable: false,
        }
    }

    /// Every number finite, angles within ±360°, the load within 0..=1000 kg.
    pub fn validate(&self) -> Result<(), ErgonomicsError> {
        for (field, value) in [
            ("trunk_flexion_deg", self.trunk_flexion_deg),
            ("neck_flexion_deg", self.neck_flexion_deg),
            ("knee_flexion_deg", self.knee_flexion_deg),
            ("upper_arm_flexion_deg", self.upper_arm_flexion_deg),
            ("lower_arm_flexion_deg", self.lower_arm_flexion_deg),
            ("wrist_flexion_deg", self.wrist_flexion_deg),
            ("load_kg", self.load_kg),
        ] {
            if !value.is_finite() {
                return Err(ErgonomicsError::NonFinite { field, value });
            }
            let (min, max) = if field == "load_kg" {
                (0.0, MAX_LOAD_KG)
            } else {
                (-MAX_ABS_ANGLE_DEG, MAX_ABS_ANGLE_DEG)
            };
            if !(min..=max).contains(&value) {
                return Err(ErgonomicsError::OutOfRange {
                    field,
                    value,
                    min,
                    max,
                });
            }
        }
        Ok(())
    }
}

/// The highest REBA score (Table C's 12 plus three activity points).
pub const REBA_SCORE_MAX: u8 = 15;

/// The heaviest load a worksheet may state, kilograms: anything beyond is not a manual task.
pub const MAX_LOAD_KG: f64 = 1000.0;

/// One side's REBA breakdown. Field names and order are the public output format of
/// `ergocell reba score`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub struct RebaScores {
    pub trunk_score: u8,
    pub neck_score: u8,
    pub legs_score: u8,
    pub table_a: u8,
    pub load_force_score: u8,
    pub score_a: u8,
    pub upper_arm_score: u8,
    pub lower_arm_score: u8,
    pub wrist_score: u8,
    pub table_b: u8,
    pub coupling_score: u8,
    pub score_b: u8,
    pub table_c: u8,
    pub activity_score: u8,
    /// The REBA score, 1..=15.
    pub reba_score: u8,
    /// 0..=4 (see [`action_level`]).
    pub action_level: u8,
    /// "negligible", "low", "medium", "high", "very high".
    pub risk: &'static str,
}

/// Trunk: 1 upright (exactly 0°), 2 up to 20° flexion or extension, 3 flexion 20°–60° or extension
/// beyond 20°, 4 flexion beyond 60°.
pub fn trunk_band(flexion_deg: f64) -> u8 {
    if flexion_deg == 0.0 {
        1
    } else if flexion_deg < 0.0 {
        if flexion_deg >= -20.0 {
            2
        } else {
            3
        }
    } else if flexion_deg < 20.0 {
        2
    } else if flexion_deg <= 60.0 {
        3
    } else {
        4
    }
}

/// The trunk's score with its adjustment, 1..=5.
pub fn trunk_score(flexion_deg: f64, twisted_or_side_bent: bool) -> u8 {
    trunk_band(flexion_deg) + u8::from(twisted_or_side_bent)
}

/// Neck: 1 for 0°–20° flexion, 2 beyond 20° flexion or in extension.
pub fn neck_band(flexion_deg: f64) -> u8 {
    if (0.0..=20.0).contains(&flexion_deg) {
        1
    } else {
        2
    }
}

/// The neck's score with its adjustment, 1..=3.
pub fn neck_score(flexion_deg: f64, twisted_or_side_bent: bool) -> u8 {
    neck_band(flexion_deg) + u8::from(twisted_or_side_bent)
}

/// Legs: 1 bilateral weight bearing, walking or sitting, else 2; knees 30°–60° +1, beyond 60° +2
/// (not when seated). 1..=4.
pub fn legs_score(bilateral_walking_or_sitting: bool, seated: bool, knee_flexion_deg: f64) -> u8 {
    let base = if bilateral_walking_or_sitting { 1 } else { 2 };
    let knees = if seated || knee_flexion_deg < 30.0 {
        0
    } else if knee_flexion_deg <= 60.0 {
        1
    } else {
        2
    };
    base + knees
}

/// Load/force: below 5 kg 0, 5–10 kg 1, above 10 kg 2; +1 shock or rapid build-up.
pub fn load_force_score(load_kg: f64, shock_or_rapid: bool) -> u8 {
    let base = if load_kg < 5.0 {
        0
    } else if load_kg <= 10.0 {
        1
    } else {
        2
    };
    base + u8::from(shock_or_rapid)
}

/// Upper arm: 1 for 20° extension to below 20° flexion, 2 for 20°–45° flexion or extension beyond
/// 20°, 3 for 45°–90° flexion, 4 beyond 90°.
pub fn upper_arm_band(flexion_deg: f64) -> u8 {
    if flexion_deg < -20.0 {
        2
    } else if flexion_deg < 20.0 {
        1
    } else if flexion_deg < 45.0 {
        2
    } else if flexion_deg <= 90.0 {
        3
    } else {
        4
    }
}

/// The upper arm's score: +1 abducted or rotated, +1 shoulder raised, −1 supported or leaning;
/// clamped to 1..=6.
pub fn upper_arm_score(flexion_deg: f64, abducted: bool, raised: bool, supported: bool) -> u8 {
    let s = i16::from(upper_arm_band(flexion_deg)) + i16::from(abducted) + i16::from(raised)
        - i16::from(supported);
    // In 1..=6 after the clamp.
    s.clamp(1, 6) as u8
}

/// Lower arm: 1 for 60°–100° elbow flexion inclusive, else 2 (RULA's band, without RULA's
/// adjustment).
pub fn lower_arm_score(elbow_flexion_deg: f64) -> u8 {
    crate::rula::lower_arm_band(elbow_flexion_deg)
}

/// Wrist: 1 up to 15° flexion/extension, 2 beyond; +1 deviated or twisted. 1..=3.
pub fn wrist_score(flexion_deg: f64, deviated_or_twisted: bool) -> u8 {
    let band = if flexion_deg.abs() <= 15.0 { 1 } else { 2 };
    band + u8::from(deviated_or_twisted)
}

/// The action level of a REBA score: 1 → 0, 2–3 → 1, 4–7 → 2, 8–10 → 3, 11–15 → 4.
pub fn action_level(reba_score: u8) -> u8 {
    match reba_score {
        0 | 1 => 0,
        2 | 3 => 1,
        4..=7 => 2,
        8..=10 => 3,
        _ => 4,
    }
}

/// The risk named by an action level, and what it asks for.
pub fn risk(action_level: u8) -> (&'static str, &'static str) {
    match action_level {
        0 => ("negligible", "none necessary"),
        1 => ("low", "may be necessary"),
        2 => ("medium", "necessary"),
        3 => ("high", "necessary soon"),
        _ => ("very high", "necessary now"),
    }
}

fn lookup<const N: usize>(
    row: &[u8; N],
    score: u8,
    table: &'static str,
) -> Result<u8, ErgonomicsError> {
    usize::from(score)
        .checked_sub(1)
        .and_then(|i| row.get(i).copied())
        .ok_or(ErgonomicsError::TableShape {
            table,
            expected: "a score within the table's range",
        })
}

/// Scores one side's worksheet: every step and the tables.
pub fn score_worksheet(input: &RebaInput) -> Result<RebaScores, ErgonomicsError> {
    input.validate()?;
    let trunk = trunk_score(input.trunk_flexion_deg, input.trunk_twisted_or_side_bent);
    let neck = neck_score(input.neck_flexion_deg, input.neck_twisted_or_side_bent);
    let legs = legs_score(
        input.legs_bilateral_walking_or_sitting,
        input.seated,
        input.knee_flexion_deg,
    );
    let by_neck = TABLE_A
        .get(usize::from(neck) - 1)
        .ok_or(ErgonomicsError::TableShape {
            table: "REBA A",
            expected: "neck 1..=3",
        })?;
    let by_trunk = by_neck
        .get(usize::from(trunk) - 1)
        .ok_or(ErgonomicsError::TableShape {
            table: "REBA A",
            expected: "trunk 1..=5",
        })?;
    let table_a = lookup(by_trunk, legs, "REBA A")?;
    let load = load_force_score(input.load_kg, input.load_shock_or_rapid_build_up);
    let score_a = table_a + load;

    let upper = upper_arm_score(
        input.upper_arm_flexion_deg,
        input.upper_arm_abducted_or_rotated,
        input.shoulder_raised,
        input.arm_supported_or_leaning,
    );
    let lower = lower_arm_score(input.lower_arm_flexion_deg);
    let wrist = wrist_score(input.wrist_flexion_deg, input.wrist_deviated_or_twisted);
    let by_lower = TABLE_B
        .get(usize::from(upper) - 1)
        .and_then(|r| r.get(usize::from(lower) - 1))
        .ok_or(ErgonomicsError::TableShape {
            table: "REBA B",
            expected: "upper arm 1..=6, lower arm 1..=2",
        })?;
    let table_b = lookup(by_lower, wrist, "REBA B")?;
    let coupling = input.coupling.score();
    let score_b = table_b + coupling;

    let row = TABLE_C
        .get(usize::from(score_a) - 1)
        .ok_or(ErgonomicsError::TableShape {
            table: "REBA C",
            expected: "score A 1..=12",
        })?;
    let table_c = lookup(row, score_b, "REBA C")?;
    let activity = u8::from(input.activity_static)
        + u8::from(input.activity_repeated)
        + u8::from(input.activity_rapid_change_or_unstable);
    let reba_score = table_c + activity;
    let level = action_level(reba_score);
    Ok(RebaScores {
        trunk_score: trunk,
        neck_score: neck,
        legs_score: legs,
        table_a,
        load_force_score: load,
        score_a,
        upper_arm_score: upper,
        lower_arm_score: lower,
        wrist_score: wrist,
        table_b,
        coupling_score: coupling,
        score_b,
        table_c,
        activity_score: activity,
        reba_score,
        action_level: level,
        risk: risk(level).0,
    })
}

/// Parses a JSON array of REBA worksheets (the input of `ergocell reba score`) and validates each.
///
/// An error names the entry (0-based index) and the field: a missing, unknown or repeated field, a
/// value of the wrong type, or a value out of range.
pub fn parse_worksheets(json: &str) -> Result<Vec<RebaInput>, ErgonomicsError> {
    json_array(json)?
        .iter()
        .enumerate()
        .map(|(index, entry)| parse_entry(index, entry))
        .collect()
}

fn parse_entry(index: usize, entry: &serde_json::Value) -> Result<RebaInput, ErgonomicsError> {
    parse_worksheet_entry(
        index,
        entry,
        &RebaInput::FIELDS,
        |field, v| match field {
            "coupling" => (
                matches!(v.as_str(), Some("good" | "fair" | "poor" | "unacceptable")),
                "\"good\", \"fair\", \"poor\" or \"unacceptable\"",
            ),
            "load_kg" => (
                v.as_f64().is_some_and(|d| (0.0..=MAX_LOAD_KG).contains(&d)),
                "a mass in kilograms, 0..=1000",
            ),
            f if f.ends_with("_deg") => (
                v.as_f64()
                    .is_some_and(|d| (-MAX_ABS_ANGLE_DEG..=MAX_ABS_ANGLE_DEG).contains(&d)),
                "a number of degrees within ±360 (a physically possible angle)",
            ),
            _ => (v.is_boolean(), "true or false"),
        },
        RebaInput::validate,
    )
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)]
    use super::*;

    /// Every band edge of the written convention (module docs), both sides of each edge.
    #[test]
    fn every_band_edge() {
        let e = 1e-9;
        for (deg, band) in [
            (0.0, 1),
            (e, 2),
            (-e, 2),
            (-20.0, 2),
            (-20.0 - e, 3),
            (20.0 - e, 2),
            (20.0, 3),
            (60.0, 3),
            (60.0 + e, 4),
        ] {
            assert_eq!(trunk_band(deg), band, "trunk {deg}");
        }
        for (deg, band) in [(-e, 2), (0.0, 1), (20.0, 1), (20.0 + e, 2)] {
            assert_eq!(neck_band(deg), band, "neck {deg}");
        }
        for (deg, s) in [(30.0 - e, 1), (30.0, 2), (60.0, 2), (60.0 + e, 3)] {
            assert_eq!(legs_score(true, false, deg), s, "knee {deg}");
            assert_eq!(legs_score(true, true, deg), 1, "seated knee {deg}");
            assert_eq!(
                legs_score(false, false, deg),
                s + 1,
                "unilateral knee {deg}"
            );
        }
        for (kg, s) in [(5.0 - e, 0), (5.0, 1), (10.0, 1), (10.0 + e, 2)] {
            assert_eq!(load_force_score(kg, false), s, "load {kg}");
            assert_eq!(load_force_score(kg, true), s + 1, "load {kg} with shock");
        }
        for (deg, band) in [
            (-20.0 - e, 2),
            (-20.0, 1),
            (20.0 - e, 1),
            (20.0, 2),
            (45.0 - e, 2),
            (45.0, 3),
            (90.0, 3),
            (90.0 + e, 4),
        ] {
            assert_eq!(upper_arm_band(deg), band, "upper arm {deg}");
        }
        for (deg, s) in [(60.0 - e, 2), (60.0, 1), (100.0, 1), (100.0 + e, 2)] {
            assert_eq!(lower_arm_score(deg), s, "lower arm {deg}");
        }
        for (deg, s) in [(15.0, 1), (-15.0, 1), (15.0 + e, 2), (-15.0 - e, 2)] {
            assert_eq!(wrist_score(deg, false), s, "wrist {deg}");
            assert_eq!(wrist_score(deg, true), s + 1, "wrist {deg} twisted");
        }
        for (score, level) in [
            (1, 0),
            (2, 1),
            (3, 1),
            (4, 2),
            (7, 2),
            (8, 3),
            (10, 3),
            (11, 4),
            (15, 4),
        ] {
            assert_eq!(action_level(score), level, "score {score}");
        }
    }

    #[test]
    fn upper_arm_adjustments_clamp_to_one_and_six() {
        assert_eq!(upper_arm_score(0.0, false, false, true), 1);
        assert_eq!(upper_arm_score(100.0, true, true, false), 6);
        assert_eq!(upper_arm_score(100.0, true, true, true), 5);
    }

    /// The tables' corners and a few cells read off the published worksheet.
    #[test]
    fn tables_as_published() {
        assert_eq!(TABLE_A[0][0][0], 1);
        assert_eq!(TABLE_A[2][0], [3, 3, 5, 6]);
        assert_eq!(TABLE_A[2][4][3], 9);
        assert_eq!(TABLE_A[1][4], [6, 7, 8, 9]);
        assert_eq!(TABLE_B[0][0], [1, 2, 2]);
        assert_eq!(TABLE_B[5][1], [8, 9, 9]);
        assert_eq!(TABLE_B[3][1], [5, 6, 7]);
        assert_eq!(TABLE_C[0], [1, 1, 1, 2, 3, 3, 4, 5, 6, 7, 7, 7]);
        assert_eq!(TABLE_C[5][8], 10);
        assert_eq!(TABLE_C[11], [12; 12]);
        // Monotone: a worse posture never lowers a table's score.
        for n in TABLE_A {
            for (t, row) in n.iter().enumerate() {
                assert!(row.windows(2).all(|w| w[0] <= w[1]));
                if t > 0 {
                    assert!(row.iter().zip(&n[t - 1]).all(|(a, b)| a >= b));
                }
            }
        }
        for r in 0..12 {
            assert!(TABLE_C[r].windows(2).all(|w| w[0] <= w[1]));
            if r > 0 {
                assert!(TABLE_C[r].iter().zip(&TABLE_C[r - 1]).all(|(a, b)| a >= b));
            }
        }
    }

    #[test]
    fn the_neutral_posture_is_negligible_and_the_worst_is_fifteen() {
        let s = score_worksheet(&RebaInput::neutral()).unwrap();
        assert_eq!((s.reba_score, s.action_level, s.risk), (1, 0, "negligible"));
        let worst = RebaInput {
            trunk_flexion_deg: 80.0,
            trunk_twisted_or_side_bent: true,
            neck_flexion_deg: 30.0,
            neck_twisted_or_side_bent: true,
            legs_bilateral_walking_or_sitting: false,
            knee_flexion_deg: 90.0,
            load_kg: 20.0,
            load_shock_or_rapid_build_up: true,
            upper_arm_flexion_deg: 120.0,
            upper_arm_abducted_or_rotated: true,
            shoulder_raised: true,
            lower_arm_flexion_deg: 10.0,
            wrist_flexion_deg: 40.0,
            wrist_deviated_or_twisted: true,
            coupling: Coupling::Unacceptable,
            activity_static: true,
            activity_repeated: true,
            activity_rapid_change_or_unstable: true,
            ..RebaInput::neutral()
        };
        let s = score_worksheet(&worst).unwrap();
        assert_eq!(
            (
                s.trunk_score,
                s.neck_score,
                s.legs_score,
                s.table_a,
                s.score_a
            ),
            (5, 3, 4, 9, 12)
        );
        assert_eq!(
            (
                s.upper_arm_score,
                s.lower_arm_score,
                s.wrist_score,
                s.table_b,
                s.score_b
            ),
            (6, 2, 3, 9, 12)
        );
        assert_eq!((s.table_c, s.reba_score, s.action_level), (12, 15, 4));
    }
}
