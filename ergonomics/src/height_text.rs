//! The text of `ergocell height` and `ergocell height calibrate`: the stature estimate with each
//! estimator, the class decision with the classes it weighed, or why the class is still undecided;
//! and the calibration's sessions and ear offset (text and `--json`).
//!
//! A layout of [`crate::height`]'s facts, kept beside them so the binary only prints: the numbers are
//! the estimator's and the calibration's, converted here only into the units a person reads
//! (millimetres); no I/O.

use std::fmt::Write as _;

use crate::height::{
    CalibrationSession, DecisionBasis, EarOffset, HeightDecision, HeightEstimate, RecordingHeight,
};
use crate::HeightStatus;

/// Metres as millimetres.
pub fn mm(m: f64) -> f64 {
    m * 1e3
}

/// ", expected RULA cost +0.02" for a class decision's expected cost, or nothing without one.
pub fn rula_cost_clause(cost: Option<f64>) -> String {
    cost.map_or(String::new(), |c| format!(", expected RULA cost {c:+.2}"))
}

/// The estimate (each line ending in a newline): the stature with its 1σ, the ear offset used
/// (calibrated or the default), each estimator.
pub fn estimate_text(e: &HeightEstimate) -> String {
    let mut out = String::new();
    let _ = writeln!(
        out,
        "stature: {:.3} m ± {:.3} m (1σ), from {} upright frames",
        e.height_m, e.uncertainty_m, e.frames_used
    );
    let o = &e.ear_offset;
    if let Some(n) = o.calibrated_sessions {
        let _ = writeln!(
            out,
            "  ear landmark offset {:+.4} ± {:.4} m, calibrated on {n} sessions",
            o.offset_m, o.sigma_m
        );
    } else {
        let _ = writeln!(
            out,
            "  ear landmark offset uncalibrated: {:+.4} ± {:.4} m assumed (`ergocell height calibrate` measures it)",
            o.offset_m, o.sigma_m
        );
    }
    for x in &e.estimators {
        let _ = writeln!(
            out,
            "  {:<14} {:.3} m ± {:.3} m ({} frames)",
            x.name, x.height_m, x.sigma_m, x.frames
        );
    }
    out
}

/// Why the class was decided as it was: the interval and how it lies against the classes.
pub fn basis_text(d: &HeightDecision) -> String {
    let [lo, hi] = d.interval_m;
    match d.basis {
        DecisionBasis::Interval => format!(
            "the ±{}σ interval {lo:.3}–{hi:.3} m lies inside the class",
            d.sigmas
        ),
        DecisionBasis::ExpectedRula => format!(
            "the ±{}σ interval {lo:.3}–{hi:.3} m straddles a boundary: the lowest expected RULA",
            d.sigmas
        ),
        DecisionBasis::MostProbable => format!(
            "the ±{}σ interval {lo:.3}–{hi:.3} m straddles a boundary: the most probable class",
            d.sigmas
        ),
    }
}

/// A decided class (lines ending in a newline): the estimate it was decided on, the class and
/// why, each class weighed, the expected cost, and the estimate over the whole recording when more
/// frames came after the decision.
fn decided_text(d: &HeightDecision, r: &RecordingHeight) -> String {
    let mut out = estimate_text(&d.estimate);
    let _ = writeln!(
        out,
        "class: {} (decided at frame {}: {})",
        d.class.name(),
        r.decided_at_frame
            .map_or_else(|| "?".to_owned(), |i| i.to_string()),
        basis_text(d)
    );
    for o in &d.options {
        let _ = writeln!(
            out,
            "  {}: probability {:.3}{}{}",
            o.class.name(),
            o.probability,
            o.expected_rula
                .map_or(String::new(), |r| format!(", expected RULA {r:.2}")),
            if o.served {
                ""
            } else {
                ", its trajectory does not serve this interval"
            }
        );
    }
    if let Some(cost) = d.expected_rula_cost {
        let _ = writeln!(
            out,
            "expected cost against the true class: {cost:+.3} RULA grand score"
        );
    }
    if let Some(now) = &r.final_estimate {
        if now.frames_used > d.estimate.frames_used {
            let _ = writeln!(
                out,
                "over the whole recording: {:.3} m ± {:.3} m from {} upright frames",
                now.height_m, now.uncertainty_m, now.frames_used
            );
        }
    }
    out
}

/// `ergocell height`'s text after its first line (each line ending in a newline): the decision
/// ([`estimate_text`], the class and the classes weighed) or the estimate so far and why the class
/// is undecided, then the posture-independent segment estimate.
pub fn recording_text(r: &RecordingHeight) -> String {
    let mut out = match &r.status {
        HeightStatus::Decided(d) => decided_text(d, r),
        HeightStatus::Measuring {
            estimate,
            why,
            frames_seen,
            upright_frames,
        } => {
            let mut out = estimate.as_ref().map(estimate_text).unwrap_or_default();
            let _ = writeln!(
                out,
                "class: undecided — still measuring ({upright_frames} upright of {frames_seen} frames): {why}"
            );
            out
        }
    };
    if let Some(seg) = &r.segments {
        let _ = writeln!(
            out,
            "segment lengths (any posture, never decides the class): {:.3} m ± {:.3} m (1σ) over {} frames",
            seg.height_m, seg.sigma_m, seg.frames
        );
    }
    out
}

/// `ergocell height calibrate`'s text (each line ending in a newline): each session's measured and
/// uncalibrated estimated stature and the difference in millimetres, then the offset measured from
/// `sessions` sessions.
pub fn calibration_text(
    rows: &[CalibrationSession],
    offset: &EarOffset,
    sessions: usize,
) -> String {
    let mut out = String::new();
    for r in rows {
        let s = &r.sample;
        let _ = writeln!(
            out,
            "  {}: measured {:.3} m, estimated {:.3} m uncalibrated ({:+.1} mm)",
            r.session,
            s.measured_m,
            s.estimated_m,
            mm(s.error_m())
        );
    }
    let _ = writeln!(
        out,
        "ear landmark offset: {:+.1} ± {:.1} mm (1σ) from {sessions} sessions",
        mm(offset.offset_m),
        mm(offset.sigma_m)
    );
    out
}

/// `ergocell height calibrate --json`: the offset, each session, and whether the configuration was
/// written.
pub fn calibration_json(
    rows: &[CalibrationSession],
    offset: &EarOffset,
    written: bool,
) -> serde_json::Value {
    let sessions: Vec<serde_json::Value> = rows
        .iter()
        .map(|r| {
            serde_json::json!({
                "session": r.session,
                "measured_m": r.sample.measured_m,
                "estimated_m": r.sample.estimated_m,
                "upright_frames": r.upright_frames,
            })
        })
        .collect();
    serde_json::json!({ "ear_offset": offset, "sessions": sessions, "written": written })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::height::CalibrationSample;

    #[test]
    fn metres_are_a_thousand_millimetres() {
        assert_eq!(mm(1.0), 1000.0);
        assert_eq!(mm(-0.0125), -12.5);
        assert_eq!(mm(0.0), 0.0);
    }

    #[test]
    fn a_cost_clause_only_with_a_cost() {
        assert_eq!(rula_cost_clause(None), "");
        assert_eq!(rula_cost_clause(Some(0.02)), ", expected RULA cost +0.02");
        assert_eq!(rula_cost_clause(Some(-0.5)), ", expected RULA cost -0.50");
    }

    fn row(session: &str, estimated_m: f64, measured_m: f64) -> CalibrationSession {
        CalibrationSession {
            session: session.to_owned(),
            sample: CalibrationSample {
                estimated_m,
                measured_m,
                slope: 1.05,
            },
            upright_frames: 40,
        }
    }

    #[test]
    fn each_calibration_session_reads_its_error_in_millimetres() {
        let rows = [row("a.json", 1.7125, 1.7), row("b.json", 1.650, 1.655)];
        let offset = EarOffset {
            offset_m: 0.0034,
            sigma_m: 0.0021,
            calibrated_sessions: Some(2),
        };
        let text = calibration_text(&rows, &offset, 2);
        let errors_mm: Vec<f64> = text
            .lines()
            .filter_map(|l| l.split_once('(')?.1.strip_suffix(" mm)")?.parse().ok())
            .collect();
        assert_eq!(errors_mm, [12.5, -5.0]);
        assert_eq!(text.lines().count(), 3);
        let json = calibration_json(&rows, &offset, false);
        assert_eq!(json["written"].as_bool(), Some(false));
        assert_eq!(json["sessions"][1]["measured_m"].as_f64(), Some(1.655));
        assert_eq!(json["sessions"][0]["upright_frames"].as_u64(), Some(40));
        assert_eq!(json["ear_offset"]["offset_m"].as_f64(), Some(0.0034));
    }
}
