//! What `ergocell rula track` prints for each frame: both sides' breakdowns as a line of text (the
//! reasons a side is uncertain or unscored on a `why` line when they change, then the frame's
//! warnings) or as JSON, and the `--json` document around them. The session summary under the frames
//! is [`crate::summary_text`].
//!
//! A layout of [`FrameAssessment`]'s facts, kept beside the types it lays out so the binary only
//! prints: nothing is scored here and there is no I/O. Times are seconds from the recording's first
//! frame.

use std::fmt::Write as _;

use crate::assess::{FrameAssessment, SideAssessment};
use crate::summary::SessionSummary;
use crate::warnings::WarningEvent;

/// The lines `rula track` prints above the frames (each ending in a newline): the columns, the
/// fixed-lag window when one smoothed the landmarks (`fixed_lag_s`, seconds either side), and where
/// each input comes from.
pub fn header_text(fixed_lag_s: Option<f64>) -> String {
    let mut out = String::new();
    out.push_str("# time_s  left: final AL (regions) REBA score AL | right: ... ; UA upper arm, LA lower arm, WR wrist, TW twist, N neck, T trunk, L legs; REBA (Hignett & McAtamney 2000) from the same angles plus the knees\n");
    if let Some(seconds) = fixed_lag_s {
        let _ = writeln!(
            out,
            "# scored on a fixed-lag mean of the landmarks over ±{seconds} s of each frame (a gap in the file ends the window), the legs below the hips as recorded"
        );
    }
    out.push_str("# configured (task config): force/load, wrist twist, arm supported, seated; muscle use: from the time series; the rest observed (\"uncertain\": an input held, not observed, scored conservatively or of low confidence; the reasons follow on a \"why\" line when they change; --json lists each input's source)\n");
    out
}

/// One side's breakdown in one line: RULA's grand score and action level, the region scores, then
/// REBA's score and action level; "not scored" for a side that was not.
pub fn side_text(s: Option<&SideAssessment>) -> String {
    let Some(a) = s else {
        return "not scored".to_owned();
    };
    let c = &a.scores;
    format!(
        "{} AL{} (UA{} LA{} WR{} TW{} A{} C{} | N{} T{} L{} B{} D{}){} REBA {} AL{}{}",
        c.final_score,
        c.action_level,
        c.upper_arm_score,
        c.lower_arm_score,
        c.wrist_score,
        c.wrist_twist_score,
        c.posture_score_a,
        c.score_c_wrist_arm,
        c.neck_score,
        c.trunk_score,
        c.legs_score,
        c.posture_score_b,
        c.score_d_neck_trunk_legs,
        if a.uncertain { " uncertain" } else { "" },
        a.reba.scores.reba_score,
        a.reba.scores.action_level,
        if a.reba.uncertain && !a.uncertain {
            " (REBA uncertain)"
        } else {
            ""
        }
    )
}

/// One side's breakdown as JSON: the scores, the worksheet that was scored, and where each input came
/// from (observed, held, not observed, conservative, configured, time series) with the reasons a score
/// is uncertain.
pub fn side_json(s: &SideAssessment) -> serde_json::Value {
    let sources: serde_json::Map<String, serde_json::Value> = s
        .sources
        .iter()
        .map(|(name, source)| ((*name).to_owned(), serde_json::json!(source)))
        .collect();
    serde_json::json!({
        "scores": s.scores,
        "uncertain": s.uncertain,
        "uncertain_reasons": s.uncertain_reasons,
        "notes": s.notes,
        "input": s.input,
        "sources": sources,
        "reba": s.reba,
    })
}

/// One frame as `--json` lists it: its stamp, both sides ([`side_json`]), the reasons it was not
/// scored and the worse side.
pub fn frame_json(frame: &FrameAssessment) -> serde_json::Value {
    serde_json::json!({
        "stamp_nanos": frame.stamp_nanos,
        "left": frame.left.as_ref().map(side_json),
        "right": frame.right.as_ref().map(side_json),
        "unscored_reasons": frame.unscored_reasons,
        "headline": frame.headline().map(|h| h.side),
    })
}

/// The whole `--json` document: the frames ([`frame_json`]), every warning event, the session
/// summary and the fixed-lag window (`null` without one).
pub fn document_json(
    frames: &[serde_json::Value],
    events: &[WarningEvent],
    summary: &SessionSummary,
    fixed_lag_s: Option<f64>,
) -> serde_json::Value {
    let fixed_lag = fixed_lag_s.map(|s| serde_json::json!({ "half_window_s": s }));
    serde_json::json!({ "frames": frames, "warnings": events, "summary": summary, "fixed_lag": fixed_lag })
}

/// Seconds from `t0_nanos` to `stamp_nanos`.
pub fn secs_since(stamp_nanos: i64, t0_nanos: i64) -> f64 {
    stamp_nanos.saturating_sub(t0_nanos) as f64 * 1e-9
}

/// The frames of one recording as text, in order: remembers the reasons last printed, so a `why`
/// line appears only when they change.
#[derive(Debug, Clone, Default)]
pub struct FrameText {
    /// The first frame's stamp: times are seconds from it.
    t0_nanos: i64,
    /// The reasons last printed: each side's uncertain reasons, the frame's unscored ones.
    last_why: [Vec<String>; 3],
}

impl FrameText {
    /// Frames timed from `t0_nanos` (the recording's first frame).
    pub fn new(t0_nanos: i64) -> Self {
        Self {
            t0_nanos,
            last_why: Default::default(),
        }
    }

    /// One frame's lines (each ending in a newline): the scores per side and the worse side, the
    /// reasons where they changed since the last frame, the warnings raised, changed or cleared.
    pub fn frame(&mut self, frame: &FrameAssessment, events: &[WarningEvent]) -> String {
        let t = secs_since(frame.stamp_nanos, self.t0_nanos);
        let mut out = String::new();
        let head = frame.headline().map_or("-", |h| h.side.name());
        let _ = writeln!(
            out,
            "{t:8.3}  left: {}  right: {}  worse: {head}",
            side_text(frame.left.as_ref()),
            side_text(frame.right.as_ref())
        );
        let why_uncertain =
            |s: Option<&SideAssessment>| s.map(|a| a.uncertain_reasons.clone()).unwrap_or_default();
        let why = [
            ("left uncertain", why_uncertain(frame.left.as_ref())),
            ("right uncertain", why_uncertain(frame.right.as_ref())),
            ("not scored", frame.unscored_reasons.clone()),
        ];
        for ((label, reasons), last) in why.into_iter().zip(self.last_why.iter_mut()) {
            if reasons != *last {
                if !reasons.is_empty() {
                    let _ = writeln!(out, "{t:8.3}  why {label}: {}", reasons.join("; "));
                }
                *last = reasons;
            }
        }
        for e in events {
            let _ = writeln!(
                out,
                "{t:8.3}  WARNING {:?}: {}{}",
                e.kind,
                e.message,
                if e.uncertain {
                    " [uncertain tracking]"
                } else {
                    ""
                }
            );
        }
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::pose::PoseSpec;
    use crate::{AssessmentConfig, RulaAssessor, UpVector};

    fn assessed(spec: &PoseSpec) -> FrameAssessment {
        let up = UpVector::new(spec.up()).unwrap();
        let mut assessor = RulaAssessor::new(AssessmentConfig::new(up)).unwrap();
        assessor.assess(&spec.skeleton()).unwrap()
    }

    #[test]
    fn times_are_seconds_from_the_first_frame() {
        assert_eq!(secs_since(1_500_000_000, 500_000_000), 1.0);
        assert_eq!(secs_since(7, 7), 0.0);
        assert!((secs_since(2_250_000_000, 0) - 2.25).abs() < 1e-12);
        // No overflow on stamps far apart.
        assert!(secs_since(i64::MAX, i64::MIN) > 0.0);
    }

    #[test]
    fn a_frame_is_timed_from_the_first_and_a_why_line_comes_only_when_the_reasons_change() {
        let spec = PoseSpec::reaching();
        let mut frame = assessed(&spec);
        frame.stamp_nanos = 2_500_000_000;
        frame.unscored_reasons = vec!["a reason".to_owned()];
        let mut text = FrameText::new(500_000_000);
        let first = text.frame(&frame, &[]);
        let time: Vec<f64> = first
            .lines()
            .map(|l| l.split_whitespace().next().unwrap().parse().unwrap())
            .collect();
        assert!(time.iter().all(|&t| t == 2.0), "{first}");
        let why_lines = |s: &str| s.lines().filter(|l| l.contains(" why not scored")).count();
        assert_eq!(why_lines(&first), 1);
        // The same reasons again: no new line; none any more: no line either, but remembered.
        assert_eq!(why_lines(&text.frame(&frame, &[])), 0);
        frame.unscored_reasons.clear();
        assert_eq!(text.frame(&frame, &[]).lines().count(), 1);
        frame.unscored_reasons = vec!["a reason".to_owned()];
        assert_eq!(why_lines(&text.frame(&frame, &[])), 1);
    }

    #[test]
    fn a_side_line_carries_its_scores_and_an_unscored_side_says_so() {
        let frame = assessed(&PoseSpec::reaching());
        assert_eq!(side_text(None), "not scored");
        let right = frame.right.as_ref().unwrap();
        let line = side_text(Some(right));
        let grand: u8 = line.split_whitespace().next().unwrap().parse().unwrap();
        assert_eq!(grand, right.scores.final_score);
        let json = side_json(right);
        assert_eq!(
            json["scores"]["final_score"].as_u64(),
            Some(u64::from(right.scores.final_score))
        );
        assert_eq!(json["uncertain"].as_bool(), Some(right.uncertain));
        let doc = frame_json(&frame);
        assert_eq!(doc["stamp_nanos"].as_i64(), Some(frame.stamp_nanos));
    }

    #[test]
    fn the_header_names_the_fixed_lag_window_only_when_one_was_used() {
        assert_eq!(header_text(None).lines().count(), 2);
        assert_eq!(header_text(Some(0.55)).lines().count(), 3);
        let doc = document_json(
            &[],
            &[],
            &crate::summary::SummaryBuilder::new(crate::summary::DEFAULT_MAX_FRAME_NANOS).finish(),
            Some(0.55),
        );
        assert_eq!(doc["fixed_lag"]["half_window_s"].as_f64(), Some(0.55));
        assert!(doc["frames"].as_array().unwrap().is_empty());
    }
}
