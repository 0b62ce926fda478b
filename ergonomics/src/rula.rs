//! The RULA worksheet (McAtamney & Corlett, Applied Ergonomics 24(2), 1993), one side at a time.
//!
//! [`RulaInput`] is the worksheet as an ergonomist fills it in: angles in **degrees** (this is the
//! one boundary where degrees live in code, because the method is written in degrees) and yes/no
//! adjustments. [`score_worksheet`] runs every step and returns the [`RulaScores`] breakdown plus
//! [`ScoringNote`]s about choices the method leaves open.
//!
//! # Steps
//! Group A (arm and wrist): upper arm (+1 shoulder raised, +1 abducted, −1 supported/leaning, clamped
//! to 1..=6), lower arm (+1 across the midline or out to the side, max 3), wrist (+1 bent from the
//! midline, max 4), wrist twist, Table A, + muscle use, + force/load → Score C. Group B: neck (+1
//! twisted, +1 side-bending, max 6), trunk (same adjustments, max 6), legs, Table B, + muscle use,
//! + force/load → Score D.
//!
//! Grand score = `Table C[min(C,8)][min(D,7)]`; action level from the grand score (1–2 → 1, 3–4 → 2,
//! 5–6 → 3, 7 → 4).
//!
//! # Band edges — the convention ergocell adopts (normative, `shared/reference/rula.md`)
//! No source defines the exact edges. An edge value belongs to the **higher** band ("20° or more",
//! "45° or more", "90° or more", "15° or more", "60° or more"), except where the paper's wording is
//! strict:
//! - upper-arm **extension** of exactly 20° scores 1 ("extension greater than 20°" scores 2);
//! - elbow flexion of exactly 60° and exactly 100° scores 1 (the 60°–100° range is inclusive).
//!
//! There is no hidden tolerance: wrist 0.5° scores 2 (only exactly 0° is neutral), neck −1° is
//! extension and scores 4, trunk 5° standing scores 2. Measurement noise is handled by filtering and by
//! hysteresis in the warnings ([`crate::warnings`]), never by bending the method.
//!
//! Trunk **extension** (negative flexion) is not scored by RULA; it is scored as the erect band and
//! reported as [`ScoringNote::TrunkExtensionScoredAsErect`].

use serde::{Deserialize, Serialize};

use crate::tables::rula_tables;
use crate::ErgonomicsError;

/// Wrist twist (pronation/supination), which cameras cannot see: it comes from the task config.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize, Default)]
#[serde(rename_all = "snake_case")]
pub enum WristTwist {
    /// Mainly in the mid-range of twist: scores 1.
    #[default]
    MidRange,
    /// At or near the end of the twisting range: scores 2.
    EndOfRange,
}

/// One side's RULA worksheet. Field names are the public input format of `ergocell rula score`.
// The worksheet's yes/no boxes are the paper's; they stay booleans in the public format.
#[allow(clippy::struct_excessive_bools)]
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RulaInput {
    /// Upper-arm flexion relative to the trunk, degrees; 0 = hanging, negative = extension.
    pub upper_arm_flexion_deg: f64,
    pub shoulder_raised: bool,
    pub upper_arm_abducted: bool,
    pub arm_supported_or_leaning: bool,
    /// Elbow flexion, degrees; 0 = straight.
    pub lower_arm_flexion_deg: f64,
    pub lower_arm_across_midline_or_out_to_side: bool,
    /// Wrist flexion (+) / extension (−), degrees; only the magnitude is scored.
    pub wrist_flexion_deg: f64,
    /// Radial or ulnar deviation.
    pub wrist_bent_from_midline: bool,
    pub wrist_twist: WristTwist,
    /// Group A posture mainly static (held > 1 min) or repeated ≥ 4 times a minute.
    pub muscle_use_arm_wrist: bool,
    /// Group A force/load score, 0..=3.
    pub force_load_score_arm_wrist: u8,
    /// Neck flexion relative to the trunk, degrees; negative = extension.
    pub neck_flexion_deg: f64,
    pub neck_twisted: bool,
    pub neck_side_bending: bool,
    /// Trunk flexion from the world's vertical, degrees; negative = extension.
    pub trunk_flexion_deg: f64,
    pub trunk_seated_well_supported: bool,
    pub trunk_twisted: bool,
    pub trunk_side_bending: bool,
    pub legs_supported_and_balanced: bool,
    /// Group B posture mainly static or repeated ≥ 4 times a minute.
    pub muscle_use_neck_trunk_legs: bool,
    /// Group B force/load score, 0..=3.
    pub force_load_score_neck_trunk_legs: u8,
}

impl RulaInput {
    /// The input field names, in the public order.
    pub const FIELDS: [&'static str; 21] = [
        "upper_arm_flexion_deg",
        "shoulder_raised",
        "upper_arm_abducted",
        "arm_supported_or_leaning",
        "lower_arm_flexion_deg",
        "lower_arm_across_midline_or_out_to_side",
        "wrist_flexion_deg",
        "wrist_bent_from_midline",
        "wrist_twist",
        "muscle_use_arm_wrist",
        "force_load_score_arm_wrist",
        "neck_flexion_deg",
        "neck_twisted",
        "neck_side_bending",
        "trunk_flexion_deg",
        "trunk_seated_well_supported",
        "trunk_twisted",
        "trunk_side_bending",
        "legs_supported_and_balanced",
        "muscle_use_neck_trunk_legs",
        "force_load_score_neck_trunk_legs",
    ];

    /// A neutral worksheet: everything at the lowest band, no load. Handy as a starting point.
    pub fn neutral() -> Self {
        Self {
            upper_arm_flexion_deg: 0.0,
            shoulder_raised: false,
            upper_arm_abducted: false,
            arm_supported_or_leaning: false,
            lower_arm_flexion_deg: 80.0,
            lower_arm_across_midline_or_out_to_side: false,
            wrist_flexion_deg: 0.0,
            wrist_bent_from_midline: false,
            wrist_twist: WristTwist::MidRange,
            muscle_use_arm_wrist: false,
            force_load_score_arm_wrist: 0,
            neck_flexion_deg: 5.0,
            neck_twisted: false,
            neck_side_bending: false,
            trunk_flexion_deg: 0.0,
            trunk_seated_well_supported: false,
            trunk_twisted: false,
            trunk_side_bending: false,
            legs_supported_and_balanced: true,
            muscle_use_neck_trunk_legs: false,
            force_load_score_neck_trunk_legs: 0,
        }
    }

    /// Checks what the types cannot: finite angles and force/load scores in 0..=3.
    pub fn validate(&self) -> Result<(), ErgonomicsError> {
        for (field, value) in [
            ("upper_arm_flexion_deg", self.upper_arm_flexion_deg),
            ("lower_arm_flexion_deg", self.lower_arm_flexion_deg),
            ("wrist_flexion_deg", self.wrist_flexion_deg),
            ("neck_flexion_deg", self.neck_flexion_deg),
            ("trunk_flexion_deg", self.trunk_flexion_deg),
        ] {
            if !value.is_finite() {
                return Err(ErgonomicsError::NonFinite { field, value });
            }
        }
        for (field, value) in [
            (
                "force_load_score_arm_wrist",
                self.force_load_score_arm_wrist,
            ),
            (
                "force_load_score_neck_trunk_legs",
                self.force_load_score_neck_trunk_legs,
            ),
        ] {
            if value > 3 {
                return Err(ErgonomicsError::OutOfRange {
                    field,
                    value: f64::from(value),
                    min: 0.0,
                    max: 3.0,
                });
            }
        }
        Ok(())
    }
}

/// One side's RULA breakdown. Field names and order are the public output format of
/// `ergocell rula score`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
pub struct RulaScores {
    pub upper_arm_score: u8,
    pub lower_arm_score: u8,
    pub wrist_score: u8,
    pub wrist_twist_score: u8,
    pub posture_score_a: u8,
    pub score_c_wrist_arm: u8,
    pub neck_score: u8,
    pub trunk_score: u8,
    pub legs_score: u8,
    pub posture_score_b: u8,
    pub score_d_neck_trunk_legs: u8,
    pub final_score: u8,
    pub action_level: u8,
}

/// Something the scorer decided that the method leaves open; reported next to the breakdown.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[serde(tag = "note", rename_all = "snake_case")]
pub enum ScoringNote {
    /// RULA does not score trunk extension; it was scored as the erect band (1 before adjustments).
    TrunkExtensionScoredAsErect { trunk_flexion_deg: f64 },
}

/// The breakdown and the notes of one scored worksheet.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct WorksheetResult {
    pub scores: RulaScores,
    pub notes: Vec<ScoringNote>,
}

/// Where the upper-arm band changes (flexion, degrees; negative = extension).
pub const UPPER_ARM_EDGES_DEG: [f64; 4] = [-20.0, 20.0, 45.0, 90.0];
/// Where the lower-arm band changes (elbow flexion, degrees): 60–100° inclusive scores 1.
pub const LOWER_ARM_EDGES_DEG: [f64; 2] = [60.0, 100.0];
/// Where the wrist band changes (flexion, degrees): below 15° either way scores 2 (exactly 0°, 1).
pub const WRIST_EDGES_DEG: [f64; 2] = [-15.0, 15.0];
/// Where the neck band changes (flexion, degrees; below 0 = extension scores 4).
pub const NECK_EDGES_DEG: [f64; 3] = [0.0, 10.0, 20.0];
/// Where the trunk band changes (flexion, degrees).
pub const TRUNK_EDGES_DEG: [f64; 3] = [0.0, 20.0, 60.0];

/// Step 1 before adjustments: upper-arm band from flexion (negative = extension), degrees.
pub fn upper_arm_band(flexion_deg: f64) -> u8 {
    let [ext, low, mid, high] = UPPER_ARM_EDGES_DEG;
    if flexion_deg < ext {
        2 // extension strictly greater than 20°
    } else if flexion_deg < low {
        1
    } else if flexion_deg < mid {
        2
    } else if flexion_deg < high {
        3
    } else {
        4
    }
}

/// Step 1: upper-arm score with adjustments, clamped to 1..=6.
pub fn upper_arm_score(flexion_deg: f64, raised: bool, abducted: bool, supported: bool) -> u8 {
    let s = i16::from(upper_arm_band(flexion_deg)) + i16::from(raised) + i16::from(abducted)
        - i16::from(supported);
    s.clamp(1, 6) as u8
}

/// Step 2 before adjustments: 60°–100° elbow flexion inclusive → 1, otherwise 2.
pub fn lower_arm_band(elbow_flexion_deg: f64) -> u8 {
    let [low, high] = LOWER_ARM_EDGES_DEG;
    if (low..=high).contains(&elbow_flexion_deg) {
        1
    } else {
        2
    }
}

/// Step 2: lower-arm score, +1 across the midline or out to the side, max 3.
pub fn lower_arm_score(elbow_flexion_deg: f64, across_or_out: bool) -> u8 {
    (lower_arm_band(elbow_flexion_deg) + u8::from(across_or_out)).min(3)
}

/// Step 3 before adjustments: exactly 0° → 1; 0 < |w| < 15° → 2; |w| ≥ 15° → 3.
pub fn wrist_band(wrist_flexion_deg: f64) -> u8 {
    let w = wrist_flexion_deg.abs();
    if w == 0.0 {
        1
    } else if w < WRIST_EDGES_DEG[1] {
        2
    } else {
        3
    }
}

/// Step 3: wrist score, +1 bent from the midline, max 4.
pub fn wrist_score(wrist_flexion_deg: f64, deviated: bool) -> u8 {
    (wrist_band(wrist_flexion_deg) + u8::from(deviated)).min(4)
}

/// Step 4: wrist twist score.
pub fn wrist_twist_score(twist: WristTwist) -> u8 {
    match twist {
        WristTwist::MidRange => 1,
        WristTwist::EndOfRange => 2,
    }
}

/// Step 9 before adjustments: extension (< 0°) → 4; 0 to < 10° → 1; 10 to < 20° → 2; ≥ 20° → 3.
pub fn neck_band(neck_flexion_deg: f64) -> u8 {
    let [ext, low, high] = NECK_EDGES_DEG;
    if neck_flexion_deg < ext {
        4
    } else if neck_flexion_deg < low {
        1
    } else if neck_flexion_deg < high {
        2
    } else {
        3
    }
}

/// Step 9: neck score, +1 twisted, +1 side-bending, max 6.
pub fn neck_score(neck_flexion_deg: f64, twisted: bool, side_bending: bool) -> u8 {
    (neck_band(neck_flexion_deg) + u8::from(twisted) + u8::from(side_bending)).min(6)
}

/// Step 10 before adjustments. Seated and well supported → 1; otherwise from flexion: ≤ 0° (erect,
/// or extension scored as erect) → 1; 0 < t < 20° → 2; 20 to < 60° → 3; ≥ 60° → 4.
pub fn trunk_band(trunk_flexion_deg: f64, seated_well_supported: bool) -> u8 {
    let [erect, low, high] = TRUNK_EDGES_DEG;
    if seated_well_supported || trunk_flexion_deg <= erect {
        1
    } else if trunk_flexion_deg < low {
        2
    } else if trunk_flexion_deg < high {
        3
    } else {
        4
    }
}

/// Step 10: trunk score, +1 twisted, +1 side-bending, max 6.
pub fn trunk_score(
    trunk_flexion_deg: f64,
    seated_well_supported: bool,
    twisted: bool,
    side_bending: bool,
) -> u8 {
    (trunk_band(trunk_flexion_deg, seated_well_supported)
        + u8::from(twisted)
        + u8::from(side_bending))
    .min(6)
}

/// Step 11: legs supported and weight evenly balanced → 1, otherwise 2.
pub fn legs_score(supported_and_balanced: bool) -> u8 {
    if supported_and_balanced {
        1
    } else {
        2
    }
}

/// The highest grand score (Table C's largest entry); the lowest is 1.
pub const GRAND_SCORE_MAX: u8 = 7;

/// Action level of a grand score: 1–2 → 1, 3–4 → 2, 5–6 → 3, 7 → 4.
pub fn action_level(final_score: u8) -> u8 {
    match final_score {
        0..=2 => 1,
        3 | 4 => 2,
        5 | 6 => 3,
        _ => 4,
    }
}

/// What an action level asks for, in plain words.
pub fn action_level_meaning(level: u8) -> &'static str {
    match level {
        0 | 1 => "acceptable",
        2 => "investigate; change may be needed",
        3 => "investigate and change soon",
        _ => "investigate and change now",
    }
}

/// The per-region scores (after adjustments) that the tables combine. Each field has a fixed range:
/// upper arm 1..=6, lower arm 1..=3, wrist 1..=4, twist 1..=2, muscle 0..=1, force 0..=3, neck
/// 1..=6, trunk 1..=6, legs 1..=2.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct RegionScores {
    pub upper_arm: u8,
    pub lower_arm: u8,
    pub wrist: u8,
    pub wrist_twist: u8,
    pub muscle_a: u8,
    pub force_a: u8,
    pub neck: u8,
    pub trunk: u8,
    pub legs: u8,
    pub muscle_b: u8,
    pub force_b: u8,
}

impl RegionScores {
    /// Upper bound (inclusive) of each field, in declaration order.
    pub const MAX: [u8; 11] = [6, 3, 4, 2, 1, 3, 6, 6, 2, 1, 3];
    /// Lower bound (inclusive) of each field, in declaration order.
    pub const MIN: [u8; 11] = [1, 1, 1, 1, 0, 0, 1, 1, 1, 0, 0];

    /// The fields as an array, in declaration order.
    pub fn to_array(self) -> [u8; 11] {
        [
            self.upper_arm,
            self.lower_arm,
            self.wrist,
            self.wrist_twist,
            self.muscle_a,
            self.force_a,
            self.neck,
            self.trunk,
            self.legs,
            self.muscle_b,
            self.force_b,
        ]
    }

    /// The inverse of [`RegionScores::to_array`].
    pub fn from_array(a: [u8; 11]) -> Self {
        Self {
            upper_arm: a[0],
            lower_arm: a[1],
            wrist: a[2],
            wrist_twist: a[3],
            muscle_a: a[4],
            force_a: a[5],
            neck: a[6],
            trunk: a[7],
            legs: a[8],
            muscle_b: a[9],
            force_b: a[10],
        }
    }

    /// Tables A, B, C: the full breakdown from region scores.
    pub fn combine(self) -> Result<RulaScores, ErgonomicsError> {
        let a = self.to_array();
        for (i, field) in REGION_FIELDS.iter().enumerate() {
            if a[i] < Self::MIN[i] || a[i] > Self::MAX[i] {
                return Err(ErgonomicsError::OutOfRange {
                    field,
                    value: f64::from(a[i]),
                    min: f64::from(Self::MIN[i]),
                    max: f64::from(Self::MAX[i]),
                });
            }
        }
        let t = rula_tables()?;
        let posture_score_a = t.table_a[usize::from(self.upper_arm - 1)]
            [usize::from(self.lower_arm - 1)][usize::from(self.wrist - 1)]
            [usize::from(self.wrist_twist - 1)];
        let score_c = posture_score_a + self.muscle_a + self.force_a;
        let posture_score_b = t.table_b[usize::from(self.neck - 1)][usize::from(self.trunk - 1)]
            [usize::from(self.legs - 1)];
        let score_d = posture_score_b + self.muscle_b + self.force_b;
        let final_score =
            t.table_c[usize::from(score_c.min(8) - 1)][usize::from(score_d.min(7) - 1)];
        Ok(RulaScores {
            upper_arm_score: self.upper_arm,
            lower_arm_score: self.lower_arm,
            wrist_score: self.wrist,
            wrist_twist_score: self.wrist_twist,
            posture_score_a,
            score_c_wrist_arm: score_c,
            neck_score: self.neck,
            trunk_score: self.trunk,
            legs_score: self.legs,
            posture_score_b,
            score_d_neck_trunk_legs: score_d,
            final_score,
            action_level: action_level(final_score),
        })
    }
}

const REGION_FIELDS: [&str; 11] = [
    "upper_arm_score",
    "lower_arm_score",
    "wrist_score",
    "wrist_twist_score",
    "muscle_use_arm_wrist",
    "force_load_score_arm_wrist",
    "neck_score",
    "trunk_score",
    "legs_score",
    "muscle_use_neck_trunk_legs",
    "force_load_score_neck_trunk_legs",
];

/// The region scores of a worksheet (steps 1–4, 6–7, 9–11, 13).
pub fn region_scores(input: &RulaInput) -> Result<RegionScores, ErgonomicsError> {
    input.validate()?;
    Ok(RegionScores {
        upper_arm: upper_arm_score(
            input.upper_arm_flexion_deg,
            input.shoulder_raised,
            input.upper_arm_abducted,
            input.arm_supported_or_leaning,
        ),
        lower_arm: lower_arm_score(
            input.lower_arm_flexion_deg,
            input.lower_arm_across_midline_or_out_to_side,
        ),
        wrist: wrist_score(input.wrist_flexion_deg, input.wrist_bent_from_midline),
        wrist_twist: wrist_twist_score(input.wrist_twist),
        muscle_a: u8::from(input.muscle_use_arm_wrist),
        force_a: input.force_load_score_arm_wrist,
        neck: neck_score(
            input.neck_flexion_deg,
            input.neck_twisted,
            input.neck_side_bending,
        ),
        trunk: trunk_score(
            input.trunk_flexion_deg,
            input.trunk_seated_well_supported,
            input.trunk_twisted,
            input.trunk_side_bending,
        ),
        legs: legs_score(input.legs_supported_and_balanced),
        muscle_b: u8::from(input.muscle_use_neck_trunk_legs),
        force_b: input.force_load_score_neck_trunk_legs,
    })
}

/// Scores one side's worksheet: every step, the tables, and the notes.
pub fn score_worksheet(input: &RulaInput) -> Result<WorksheetResult, ErgonomicsError> {
    let scores = region_scores(input)?.combine()?;
    let mut notes = Vec::new();
    if input.trunk_flexion_deg < 0.0 && !input.trunk_seated_well_supported {
        notes.push(ScoringNote::TrunkExtensionScoredAsErect {
            trunk_flexion_deg: input.trunk_flexion_deg,
        });
    }
    Ok(WorksheetResult { scores, notes })
}

/// Parses a JSON array of worksheets (the input of `ergocell rula score`) and validates each entry.
///
/// An error names the entry (0-based index) and the field: a missing or unknown field, a value of the
/// wrong type, or a value out of range.
pub fn parse_worksheets(json: &str) -> Result<Vec<RulaInput>, ErgonomicsError> {
    json_array(json)?
        .iter()
        .enumerate()
        .map(|(index, entry)| parse_entry(index, entry))
        .collect()
}

/// A JSON array of worksheet objects (RULA's or REBA's), each key given once.
pub(crate) fn json_array(json: &str) -> Result<Vec<serde_json::Value>, ErgonomicsError> {
    // A key given twice in one object is refused (serde_json's Value keeps the last one silently).
    let value = serde_json::from_str::<UniqueKeys>(json)
        .map_err(|e| ErgonomicsError::WorksheetJson {
            reason: e.to_string(),
        })?
        .0;
    let serde_json::Value::Array(entries) = value else {
        return Err(ErgonomicsError::WorksheetJson {
            reason: "expected a JSON array of worksheets".to_owned(),
        });
    };
    Ok(entries)
}

/// The largest |angle| a worksheet may state, degrees: anything beyond is not a posture.
pub const MAX_ABS_ANGLE_DEG: f64 = 360.0;

/// A JSON value whose objects never repeat a key (else a deserialization error naming it).
struct UniqueKeys(serde_json::Value);

impl<'de> serde::Deserialize<'de> for UniqueKeys {
    fn deserialize<D: serde::Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        struct V;
        impl<'de> serde::de::Visitor<'de> for V {
            type Value = UniqueKeys;
            fn expecting(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
                f.write_str("JSON")
            }
            fn visit_bool<E>(self, v: bool) -> Result<UniqueKeys, E> {
                Ok(UniqueKeys(v.into()))
            }
            fn visit_i64<E>(self, v: i64) -> Result<UniqueKeys, E> {
                Ok(UniqueKeys(v.into()))
            }
            fn visit_u64<E>(self, v: u64) -> Result<UniqueKeys, E> {
                Ok(UniqueKeys(v.into()))
            }
            fn visit_f64<E>(self, v: f64) -> Result<UniqueKeys, E> {
                Ok(UniqueKeys(v.into()))
            }
            fn visit_str<E>(self, v: &str) -> Result<UniqueKeys, E> {
                Ok(UniqueKeys(v.into()))
            }
            fn visit_string<E>(self, v: String) -> Result<UniqueKeys, E> {
                Ok(UniqueKeys(v.into()))
            }
            fn visit_unit<E>(self) -> Result<UniqueKeys, E> {
                Ok(UniqueKeys(serde_json::Value::Null))
            }
            fn visit_none<E>(self) -> Result<UniqueKeys, E> {
                Ok(UniqueKeys(serde_json::Value::Null))
            }
            fn visit_seq<A: serde::de::SeqAccess<'de>>(
                self,
                mut seq: A,
            ) -> Result<UniqueKeys, A::Error> {
                let mut out = Vec::new();
                while let Some(UniqueKeys(v)) = seq.next_element()? {
                    out.push(v);
                }
                Ok(UniqueKeys(serde_json::Value::Array(out)))
            }
            fn visit_map<A: serde::de::MapAccess<'de>>(
                self,
                mut map: A,
            ) -> Result<UniqueKeys, A::Error> {
                let mut out = serde_json::Map::new();
                while let Some(key) = map.next_key::<String>()? {
                    let UniqueKeys(v) = map.next_value()?;
                    if out.insert(key.clone(), v).is_some() {
                        return Err(serde::de::Error::custom(format!(
                            "key `{key}` is given twice in one object: which one is meant?"
                        )));
                    }
                }
                Ok(UniqueKeys(serde_json::Value::Object(out)))
            }
        }
        d.deserialize_any(V)
    }
}

fn entry_error(index: usize, field: &str, reason: impl Into<String>) -> ErgonomicsError {
    ErgonomicsError::Worksheet {
        index,
        field: field.to_owned(),
        reason: reason.into(),
    }
}

fn parse_entry(index: usize, entry: &serde_json::Value) -> Result<RulaInput, ErgonomicsError> {
    parse_worksheet_entry(
        index,
        entry,
        &RulaInput::FIELDS,
        |field, v| match field {
            "wrist_twist" => (
                matches!(v.as_str(), Some("mid_range" | "end_of_range")),
                "\"mid_range\" or \"end_of_range\"",
            ),
            f if f.ends_with("_deg") => (
                v.as_f64()
                    .is_some_and(|d| (-MAX_ABS_ANGLE_DEG..=MAX_ABS_ANGLE_DEG).contains(&d)),
                "a number of degrees within ±360 (a physically possible angle)",
            ),
            f if f.starts_with("force_load_score") => {
                (v.as_u64().is_some_and(|n| n <= 3), "an integer 0..=3")
            }
            _ => (v.is_boolean(), "true or false"),
        },
        RulaInput::validate,
    )
}

/// One worksheet of a JSON array (RULA's or REBA's): an object with exactly `fields`, each passing
/// `check` (which also says what it expects), deserialised and then validated; an error names the
/// entry and the field.
pub(crate) fn parse_worksheet_entry<T: serde::de::DeserializeOwned>(
    index: usize,
    entry: &serde_json::Value,
    fields: &[&str],
    check: impl Fn(&str, &serde_json::Value) -> (bool, &'static str),
    validate: impl Fn(&T) -> Result<(), ErgonomicsError>,
) -> Result<T, ErgonomicsError> {
    let Some(object) = entry.as_object() else {
        return Err(entry_error(index, "(entry)", "expected an object"));
    };
    for key in object.keys() {
        if !fields.contains(&key.as_str()) {
            return Err(entry_error(index, key, "unknown field"));
        }
    }
    for &field in fields {
        let Some(v) = object.get(field) else {
            return Err(entry_error(index, field, "missing"));
        };
        let (ok, expected) = check(field, v);
        if !ok {
            return Err(entry_error(
                index,
                field,
                format!("expected {expected}, got {v}"),
            ));
        }
    }
    let input: T = serde_json::from_value(entry.clone())
        .map_err(|e| entry_error(index, "(entry)", e.to_string()))?;
    validate(&input).map_err(|e| match e {
        ErgonomicsError::NonFinite { field, .. } | ErgonomicsError::OutOfRange { field, .. } => {
            entry_error(index, field, e.to_string())
        }
        other => other,
    })?;
    Ok(input)
}
