//! A recorded session as spreadsheet files (`ergocell report --csv/--summary-csv`): one row per
//! recorded frame, and the session summary in `ergocell rula track`'s layout
//! ([`ergocell_ergonomics::export::write_summary`]), so a recording and a landmark file of the same
//! frames give the same summary rows.
//!
//! The frame CSV's columns (units in the names; scores and levels plain integers, flags 0/1, an empty
//! cell is "not scored" or "not recorded"): `time_s` (from the recording's first message, as the
//! page's timeline), `stamp_ns` (the frame's capture stamp), `session_state` (the last state recorded
//! before the frame), `phase` (its task segment, [`crate::analysis::PHASES`]), `robot_leg` (the leg
//! under way, if any), `action_level` (worse side), `reba_action_level` (worse side), then per side
//! [`SIDE_COLUMNS`] prefixed `left_`/`right_`, then every joint angle the recording carries in degrees
//! (`trunk_flexion_deg`, `left_elbow_flexion_deg`, …), then `warnings` (the warning events of that
//! frame: `raised trunk; cleared left upper_arm`).
//!
//! Writers take any [`std::io::Write`]; the binary opens the files.

use std::collections::BTreeMap;
use std::io::Write;

use ergocell_bridge::msg::{RebaSide, RulaSide};
use ergocell_ergonomics::assess::BodyRegion;
use ergocell_ergonomics::export::csv_cell;

use crate::analysis::SessionReview;
use crate::read::Recording;
use crate::ReviewError;

/// The per-side columns of the recording's frame CSV, each prefixed `left_` or `right_`: the RULA
/// breakdown as recorded (`ergocell_msgs/RulaSide`) and the REBA score beside it.
pub const SIDE_COLUMNS: [&str; 16] = [
    "scored",
    "uncertain",
    "final_score",
    "action_level",
    "upper_arm_score",
    "lower_arm_score",
    "wrist_score",
    "wrist_twist_score",
    "neck_score",
    "trunk_score",
    "legs_score",
    "score_c_arm_wrist",
    "score_d_neck_trunk_legs",
    "reba_score",
    "reba_action_level",
    "reba_uncertain",
];

fn csv_error(e: &csv::Error) -> ReviewError {
    ReviewError::Export {
        reason: e.to_string(),
    }
}

fn flag(b: bool) -> String {
    if b { "1" } else { "0" }.to_owned()
}

fn side_cells(rula: Option<&RulaSide>, reba: Option<&RebaSide>) -> Vec<String> {
    let mut cells = vec![String::new(); SIDE_COLUMNS.len()];
    cells[0] = flag(false);
    if let Some(r) = rula.filter(|r| r.scored) {
        let scores = [
            r.final_score,
            r.action_level,
            r.upper_arm_score,
            r.lower_arm_score,
            r.wrist_score,
            r.wrist_twist_score,
            r.neck_score,
            r.trunk_score,
            r.legs_score,
            r.score_c_wrist_arm,
            r.score_d_neck_trunk_legs,
        ];
        cells[0] = flag(true);
        cells[1] = flag(r.uncertain);
        for (cell, score) in cells[2..13].iter_mut().zip(scores) {
            *cell = score.to_string();
        }
    }
    if let Some(r) = reba.filter(|r| r.scored) {
        cells[13] = r.reba_score.to_string();
        cells[14] = r.action_level.to_string();
        cells[15] = flag(r.uncertain);
    }
    cells
}

/// Writes the frame CSV of one analysed session: `review` must be [`crate::analyse`] of `rec`
/// (its frames are the rows, in the same order).
pub fn write_frames<W: Write>(
    out: W,
    rec: &Recording,
    review: &SessionReview,
) -> Result<W, ReviewError> {
    let stamp = |h: &ergocell_bridge::msg::Header| u64::try_from(h.stamp.to_nanos()).unwrap_or(0);
    let mut poses: Vec<_> = rec.poses.iter().collect();
    poses.sort_by_key(|p| stamp(&p.message.header));
    poses.dedup_by_key(|p| stamp(&p.message.header));
    poses.retain(|p| {
        let m = &p.message;
        let n = ergocell_skeleton::LANDMARK_COUNT;
        m.x.len() == n && m.y.len() == n && m.z.len() == n
    });
    let mut rula: Vec<_> = rec.ergonomics.iter().map(|e| &e.message).collect();
    rula.sort_by_key(|e| stamp(&e.header));
    let mut reba: Vec<_> = rec.reba.iter().map(|e| &e.message).collect();
    reba.sort_by_key(|e| stamp(&e.header));
    // The angle columns: every name the recording carries, in the order first seen.
    let mut angle_names: Vec<&str> = Vec::new();
    for p in &poses {
        for name in &p.message.angle_names {
            if !angle_names.contains(&name.as_str()) {
                angle_names.push(name);
            }
        }
    }
    let mut w = csv::Writer::from_writer(out);
    let mut header: Vec<String> = [
        "time_s",
        "stamp_ns",
        "session_state",
        "phase",
        "robot_leg",
        "action_level",
        "reba_action_level",
    ]
    .iter()
    .map(|&s| s.to_owned())
    .collect();
    for side in ["left", "right"] {
        header.extend(SIDE_COLUMNS.iter().map(|c| format!("{side}_{c}")));
    }
    header.extend(angle_names.iter().map(|n| format!("{n}_deg")));
    header.push("warnings".to_owned());
    w.write_record(header.iter().map(csv_cell))
        .map_err(|e| csv_error(&e))?;

    // The warning events by the frame they were raised on.
    let mut events: BTreeMap<u64, Vec<String>> = BTreeMap::new();
    for w in &rec.warnings {
        let m = &w.message;
        events
            .entry(stamp(&m.header))
            .or_default()
            .push(if m.side.is_empty() {
                format!("{} {}", m.kind, m.region)
            } else {
                format!("{} {} {}", m.kind, m.side, m.region)
            });
    }
    let mut states = rec.states.iter().peekable();
    let mut state = "";
    for (k, p) in poses.iter().enumerate() {
        let m = &p.message;
        let t = stamp(&m.header);
        while let Some(s) = states.next_if(|s| s.log_time_nanos <= p.log_time_nanos) {
            state = &s.message.state;
        }
        let e = rula
            .binary_search_by_key(&t, |e| stamp(&e.header))
            .ok()
            .map(|i| rula[i]);
        let r = reba
            .binary_search_by_key(&t, |e| stamp(&e.header))
            .ok()
            .map(|i| reba[i]);
        let time = review.frames.t.get(k).copied().unwrap_or(f64::NAN);
        let leg = review
            .robot
            .legs
            .iter()
            .find(|l| l.t_start <= time && time < l.t_end)
            .map_or("", |l| l.leg.as_str());
        let mut row = vec![
            format!("{time:.6}"),
            t.to_string(),
            state.to_owned(),
            review
                .frames
                .phase
                .get(k)
                .copied()
                .flatten()
                .unwrap_or("")
                .to_owned(),
            leg.to_owned(),
            // A frame neither side of which was scored carries level 0 in its message: an empty
            // cell ("not scored"), never a number (REBA's level 0 reads "negligible").
            e.filter(|e| e.left.scored || e.right.scored)
                .map_or(String::new(), |e| e.action_level.to_string()),
            r.filter(|r| r.left.scored || r.right.scored)
                .map_or(String::new(), |r| r.action_level.to_string()),
        ];
        row.extend(side_cells(e.map(|e| &e.left), r.map(|r| &r.left)));
        row.extend(side_cells(e.map(|e| &e.right), r.map(|r| &r.right)));
        for name in &angle_names {
            let v = m
                .angle_names
                .iter()
                .position(|n| n == name)
                .and_then(|i| m.angle_rad.get(i))
                .filter(|v| v.is_finite());
            row.push(v.map_or(String::new(), |v| {
                let deg = v.to_degrees();
                format!("{:.3}", if deg.abs() < 5e-4 { 0.0 } else { deg })
            }));
        }
        row.push(events.get(&t).map_or(String::new(), |e| e.join("; ")));
        w.write_record(row.iter().map(csv_cell))
            .map_err(|e| csv_error(&e))?;
    }
    w.into_inner().map_err(|e| ReviewError::Export {
        reason: e.to_string(),
    })
}

/// Writes the session summary CSV of one analysed session, in `ergocell rula track`'s layout; the
/// warnings raised per region are counted from the recorded ones.
pub fn write_summary<W: Write>(out: W, review: &SessionReview) -> Result<W, ReviewError> {
    let raised: Vec<(BodyRegion, usize)> = BodyRegion::ALL
        .iter()
        .map(|&region| {
            let n = review
                .warnings
                .iter()
                .filter(|w| {
                    w.kind == ergocell_bridge::msg::PostureWarning::RAISED
                        && w.region == region.name()
                })
                .count();
            (region, n)
        })
        .collect();
    ergocell_ergonomics::export::write_summary(out, &review.summary, &raised).map_err(|e| {
        ReviewError::Export {
            reason: e.to_string(),
        }
    })
}
