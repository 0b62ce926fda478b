//! Spreadsheet exports: one row per assessed frame, and one session summary, as CSV an ergonomist
//! opens in a spreadsheet. Every column's unit is in its name (`_s`, `_ns`, `_deg`, `_percent`;
//! scores and levels are plain integers, flags 0/1, an empty cell is "not scored").
//!
//! The writers take any [`std::io::Write`] (the binary hands them a file); this crate opens nothing.

use std::io::Write;

use crate::assess::{BodyRegion, FrameAssessment, SideAssessment};
use crate::summary::SessionSummary;
use crate::warnings::{WarningEvent, WarningKind};
use crate::{ErgonomicsError, Side};

/// The per-side columns of the frame CSV, each prefixed `left_` or `right_`.
pub const SIDE_COLUMNS: [&str; 30] = [
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
    "upper_arm_flexion_deg",
    "lower_arm_flexion_deg",
    "wrist_flexion_deg",
    "neck_flexion_deg",
    "trunk_flexion_deg",
    "shoulder_raised",
    "upper_arm_abducted",
    "neck_twisted_or_side_bending",
    "trunk_twisted_or_side_bending",
    "muscle_use_arm_wrist",
    "reba_score",
    "reba_action_level",
    "reba_uncertain",
    "reba_score_a",
    "reba_score_b",
    "reba_legs_score",
    // this side's knee as observed this frame (REBA scores the more flexed knee: `--json` has it)
    "knee_flexion_deg",
];

/// The frame CSV's header: `time_s`, `stamp_ns`, `worse_side`, the left then the right side's
/// [`SIDE_COLUMNS`], and `warnings` (the frame's warning events, `raised trunk; cleared left
/// upper_arm`).
pub fn frame_header() -> Vec<String> {
    let mut h = vec![
        "time_s".to_owned(),
        "stamp_ns".to_owned(),
        "worse_side".to_owned(),
    ];
    for side in ["left", "right"] {
        h.extend(SIDE_COLUMNS.iter().map(|c| format!("{side}_{c}")));
    }
    h.push("warnings".to_owned());
    h
}

/// A text cell as a spreadsheet reads it safely (OWASP, "CSV Injection"): a cell that begins with
/// `=`, `+`, `-`, `@`, a tab or a carriage return is a formula to Excel, LibreOffice and Google
/// Sheets, so it is prefixed with `'`, unless it is a number (`-3.5` stays a number). Every text
/// cell ergocell writes into a CSV goes through it: names and kinds read from a recording are
/// whatever the recording says.
pub fn csv_text(s: &str) -> std::borrow::Cow<'_, str> {
    let risky = s
        .chars()
        .next()
        .is_some_and(|c| matches!(c, '=' | '+' | '-' | '@' | '\t' | '\r'));
    // A lone "-" (ergocell's "not known") is no formula.
    if risky && s != "-" && s.parse::<f64>().is_err() {
        std::borrow::Cow::Owned(format!("'{s}"))
    } else {
        std::borrow::Cow::Borrowed(s)
    }
}

/// A CSV cell through [`csv_text`], as the `csv` writer takes it.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct CsvCell<'a>(pub std::borrow::Cow<'a, str>);

impl AsRef<[u8]> for CsvCell<'_> {
    fn as_ref(&self) -> &[u8] {
        self.0.as_bytes()
    }
}

/// [`csv_text`] as a cell for `csv::Writer::write_record`.
pub fn csv_cell<S: AsRef<str> + ?Sized>(s: &S) -> CsvCell<'_> {
    CsvCell(csv_text(s.as_ref()))
}

fn csv_error(e: &csv::Error) -> ErgonomicsError {
    ErgonomicsError::Export {
        reason: e.to_string(),
    }
}

/// Writes the frame CSV a row at a time (streamed: memory flat in the recording's length).
pub struct FrameCsv<W: Write> {
    writer: csv::Writer<W>,
    t0_nanos: Option<i64>,
}

impl<W: Write> FrameCsv<W> {
    /// Writes the header.
    pub fn new(out: W) -> Result<Self, ErgonomicsError> {
        let mut writer = csv::Writer::from_writer(out);
        writer
            .write_record(frame_header().iter().map(csv_cell))
            .map_err(|e| csv_error(&e))?;
        Ok(Self {
            writer,
            t0_nanos: None,
        })
    }

    /// One frame and the warning events it raised, changed or cleared. `time_s` counts from the
    /// first frame written.
    pub fn write(
        &mut self,
        frame: &FrameAssessment,
        warnings: &[WarningEvent],
    ) -> Result<(), ErgonomicsError> {
        let t0 = *self.t0_nanos.get_or_insert(frame.stamp_nanos);
        let mut row = vec![
            format!("{:.6}", (frame.stamp_nanos - t0) as f64 * 1e-9),
            frame.stamp_nanos.to_string(),
            frame
                .headline()
                .map_or(String::new(), |h| h.side.name().to_owned()),
        ];
        for side in [Side::Left, Side::Right] {
            row.extend(side_cells(
                frame.side(side),
                frame.angles.side(side).knee_flexion_rad,
            ));
        }
        row.push(
            warnings
                .iter()
                .map(warning_cell)
                .collect::<Vec<_>>()
                .join("; "),
        );
        self.writer
            .write_record(row.iter().map(csv_cell))
            .map_err(|e| csv_error(&e))
    }

    /// Flushes and hands the output back.
    pub fn finish(self) -> Result<W, ErgonomicsError> {
        self.writer
            .into_inner()
            .map_err(|e| ErgonomicsError::Export {
                reason: e.to_string(),
            })
    }
}

fn flag(b: bool) -> String {
    if b { "1" } else { "0" }.to_owned()
}

/// One side's cells; `knee_rad` is that side's knee flexion as observed this frame (empty when not).
fn side_cells(s: Option<&SideAssessment>, knee_rad: Option<f64>) -> Vec<String> {
    let Some(s) = s else {
        let mut cells = vec![String::new(); SIDE_COLUMNS.len()];
        cells[0] = flag(false);
        return cells;
    };
    let c = &s.scores;
    let i = &s.input;
    // Three decimals; a value that rounds to zero is written 0.000, not -0.000.
    let deg = |v: f64| secs(if v.abs() < 5e-4 { 0.0 } else { v });
    vec![
        flag(true),
        flag(s.uncertain),
        c.final_score.to_string(),
        c.action_level.to_string(),
        c.upper_arm_score.to_string(),
        c.lower_arm_score.to_string(),
        c.wrist_score.to_string(),
        c.wrist_twist_score.to_string(),
        c.neck_score.to_string(),
        c.trunk_score.to_string(),
        c.legs_score.to_string(),
        c.score_c_wrist_arm.to_string(),
        c.score_d_neck_trunk_legs.to_string(),
        deg(i.upper_arm_flexion_deg),
        deg(i.lower_arm_flexion_deg),
        deg(i.wrist_flexion_deg),
        deg(i.neck_flexion_deg),
        deg(i.trunk_flexion_deg),
        flag(i.shoulder_raised),
        flag(i.upper_arm_abducted),
        flag(i.neck_twisted || i.neck_side_bending),
        flag(i.trunk_twisted || i.trunk_side_bending),
        flag(i.muscle_use_arm_wrist),
        s.reba.scores.reba_score.to_string(),
        s.reba.scores.action_level.to_string(),
        flag(s.reba.uncertain),
        s.reba.scores.score_a.to_string(),
        s.reba.scores.score_b.to_string(),
        s.reba.scores.legs_score.to_string(),
        knee_rad.map_or(String::new(), |k| deg(k.to_degrees())),
    ]
}

/// The warnings raised per body region, in [`BodyRegion::ALL`] order (the summary CSV's last rows).
pub fn raised_per_region(warnings: &[WarningEvent]) -> Vec<(BodyRegion, usize)> {
    BodyRegion::ALL
        .iter()
        .map(|&region| {
            let n = warnings
                .iter()
                .filter(|e| e.region == region && e.kind == WarningKind::Raised)
                .count();
            (region, n)
        })
        .collect()
}

fn warning_cell(w: &WarningEvent) -> String {
    let kind = match w.kind {
        WarningKind::Raised => "raised",
        WarningKind::Changed => "changed",
        WarningKind::Cleared => "cleared",
    };
    match w.side {
        Some(side) => format!("{kind} {} {}", side.name(), w.region.name()),
        None => format!("{kind} {}", w.region.name()),
    }
}

/// The summary CSV's writer: one row per quantity.
struct SummaryRows<W: Write> {
    w: csv::Writer<W>,
    /// The phase column of the rows written now ("" for the whole session).
    phase: String,
}

impl<W: Write> SummaryRows<W> {
    fn row(
        &mut self,
        quantity: &str,
        side: &str,
        region: &str,
        score: &str,
        value: &str,
        unit: &str,
    ) -> Result<(), ErgonomicsError> {
        self.w
            .write_record([quantity, side, region, score, value, unit, &self.phase].map(csv_cell))
            .map_err(|e| csv_error(&e))
    }

    /// The worse side's continuous posture cost: its time-weighted mean, and the time it is known
    /// over (no rows when it is known for no time).
    fn posture_cost(&mut self, c: &crate::summary::PostureCostTime) -> Result<(), ErgonomicsError> {
        let Some(mean) = c.mean() else {
            return Ok(());
        };
        self.row(
            "posture_cost_mean",
            "worse",
            "",
            "",
            &format!("{mean:.3}"),
            "RULA points",
        )?;
        self.row("posture_cost_time", "worse", "", "", &secs(c.secs), "s")
    }

    /// Per level: how often it started, its longest stretch, its total.
    fn exposure(
        &mut self,
        side: &str,
        region: &str,
        exposure: &[crate::summary::Exposure],
    ) -> Result<(), ErgonomicsError> {
        for e in exposure {
            let level = e.at_least.to_string();
            let n = e.episodes.to_string();
            self.row("episodes_at_least", side, region, &level, &n, "episodes")?;
            let longest = secs(e.longest_secs);
            self.row(
                "longest_stretch_at_least",
                side,
                region,
                &level,
                &longest,
                "s",
            )?;
            let total = secs(e.total_secs);
            self.row("time_at_least", side, region, &level, &total, "s")?;
        }
        Ok(())
    }

    /// Shares by level, `first` the first level's number.
    fn shares(
        &mut self,
        quantity: &str,
        shares: &[f64],
        first: usize,
        unit: &str,
    ) -> Result<(), ErgonomicsError> {
        for (k, share) in shares.iter().enumerate() {
            self.row(
                quantity,
                "worse",
                "",
                &(k + first).to_string(),
                &pct(*share),
                unit,
            )?;
        }
        Ok(())
    }
}

fn pct(share: f64) -> String {
    secs(share * 100.0)
}

/// Three decimals, never `-0.000`.
fn secs(v: f64) -> String {
    format!("{:.3}", v + 0.0)
}

/// The session summary CSV, long format (one quantity a row, for a pivot table):
/// `quantity,side,region,score,value,unit,phase`. Rows for the whole session (`phase` empty): the
/// scored time and frames, the share of scored time per action level (worse side), per body-region
/// score and per grand score, the unscored share, the exposure over time per action level and region
/// score (`episodes_at_least`, `longest_stretch_at_least`, `time_at_least`: the level in the score
/// column), REBA's action level shares and exposure (region `reba_action_level`) and score shares
/// (`reba_score_share`) when the frames carry REBA, ISO 11226's static postures per body part
/// (`static_holds`, `static_holds_exceeding_iso11226`, `static_holds_limit_unknown`,
/// `longest_static_hold`, `static_hold_time`; the upper arms by side),
/// the worse side's mean posture cost and the time it is known over (`posture_cost_mean`,
/// `posture_cost_time`, after the action levels' exposure; none when never known), and the warnings
/// raised per region ([`raised_per_region`]). Then per task segment (`phase` its name):
/// `phase_duration`, its `posture_cost_mean` and `posture_cost_time`, `phase_time_share`,
/// `phase_episodes`, `phase_unscored_share`, `phase_peak_grand_score`, its action level shares and
/// exposure and its REBA action level shares.
pub fn write_summary<W: Write>(
    out: W,
    summary: &SessionSummary,
    warnings_raised: &[(BodyRegion, usize)],
) -> Result<W, ErgonomicsError> {
    let mut r = SummaryRows {
        w: csv::Writer::from_writer(out),
        phase: "phase".to_owned(),
    };
    r.row("quantity", "side", "region", "score", "value", "unit")?;
    r.phase.clear();
    r.row("duration", "", "", "", &secs(summary.duration_secs), "s")?;
    for (q, n) in [
        ("frames", summary.frames),
        ("scored_frames", summary.scored_frames),
        ("uncertain_frames", summary.uncertain_frames),
    ] {
        r.row(q, "", "", "", &n.to_string(), "frames")?;
    }
    r.row(
        "unscored_share",
        "",
        "",
        "",
        &pct(summary.unscored_share),
        "percent of time",
    )?;
    r.shares(
        "action_level_share",
        &summary.action_level_share,
        1,
        "percent of scored time",
    )?;
    r.exposure("worse", "action_level", &summary.action_level_exposure)?;
    // the worse side's posture cost beside RULA's levels
    r.posture_cost(&summary.posture_cost)?;
    for g in &summary.grand_score {
        for (score, share) in &g.share_by_score {
            r.row(
                "grand_score_share",
                g.side.name(),
                "",
                &score.to_string(),
                &pct(*share),
                "percent of the side's scored time",
            )?;
        }
    }
    for region in &summary.regions {
        let side = region.side.map_or("", Side::name);
        for (score, share) in &region.share_by_score {
            r.row(
                "region_score_share",
                side,
                region.region.name(),
                &score.to_string(),
                &pct(*share),
                "percent of the region's scored time",
            )?;
        }
        r.exposure(side, region.region.name(), &region.exposure)?;
    }
    if !summary.reba_score.is_empty() {
        r.shares(
            "reba_action_level_share",
            &summary.reba_action_level_share,
            0,
            "percent of REBA-scored time",
        )?;
        r.exposure(
            "worse",
            "reba_action_level",
            &summary.reba_action_level_exposure,
        )?;
        for g in &summary.reba_score {
            for (score, share) in &g.share_by_score {
                r.row(
                    "reba_score_share",
                    g.side.name(),
                    "",
                    &score.to_string(),
                    &pct(*share),
                    "percent of the side's REBA-scored time",
                )?;
            }
        }
    }
    for p in &summary.static_postures {
        let (part, side) = p.part.region_and_side();
        r.row(
            "static_holds",
            side,
            part,
            "",
            &p.static_holds.to_string(),
            "count",
        )?;
        let exceeded = p.exceeded.to_string();
        r.row(
            "static_holds_exceeding_iso11226",
            side,
            part,
            "",
            &exceeded,
            "count",
        )?;
        let unknown = p.limit_unknown.to_string();
        r.row(
            "static_holds_limit_unknown",
            side,
            part,
            "",
            &unknown,
            "count",
        )?;
        let longest = secs(p.longest_secs);
        r.row("longest_static_hold", side, part, "", &longest, "s")?;
        let total = secs(p.total_secs);
        r.row("static_hold_time", side, part, "", &total, "s")?;
    }
    for (region, raised) in warnings_raised {
        r.row(
            "warnings_raised",
            "",
            region.name(),
            "",
            &raised.to_string(),
            "count",
        )?;
    }
    for p in &summary.phases {
        r.phase.clone_from(&p.phase);
        r.row("phase_duration", "", "", "", &secs(p.duration_secs), "s")?;
        r.posture_cost(&p.posture_cost)?;
        r.row(
            "phase_time_share",
            "",
            "",
            "",
            &pct(p.time_share),
            "percent of time",
        )?;
        r.row(
            "phase_episodes",
            "",
            "",
            "",
            &p.episodes.to_string(),
            "count",
        )?;
        r.row(
            "phase_unscored_share",
            "",
            "",
            "",
            &pct(p.unscored_share),
            "percent of the phase's time",
        )?;
        let peak = p.peak_grand_score.map_or(String::new(), |x| x.to_string());
        r.row("phase_peak_grand_score", "", "", "", &peak, "score")?;
        r.shares(
            "action_level_share",
            &p.action_level_share,
            1,
            "percent of the phase's scored time",
        )?;
        r.exposure("worse", "action_level", &p.action_level_exposure)?;
        if !summary.reba_score.is_empty() {
            r.shares(
                "reba_action_level_share",
                &p.reba_action_level_share,
                0,
                "percent of the phase's REBA-scored time",
            )?;
        }
    }
    r.w.into_inner().map_err(|e| ErgonomicsError::Export {
        reason: e.to_string(),
    })
}

#[cfg(test)]
mod csv_text_tests {
    use super::*;

    #[test]
    fn formula_cells_are_neutralised_and_numbers_kept() {
        assert_eq!(csv_text("=cmd|' /C calc'!A0"), "'=cmd|' /C calc'!A0");
        assert_eq!(csv_text("@SUM(A1)"), "'@SUM(A1)");
        assert_eq!(csv_text("+1+2"), "'+1+2");
        assert_eq!(csv_text("-A1"), "'-A1");
        assert_eq!(csv_text("\t=1"), "'\t=1");
        assert_eq!(csv_text("-3.25"), "-3.25");
        assert_eq!(csv_text("-"), "-");
        assert_eq!(csv_text("neck"), "neck");
        assert_eq!(csv_text(""), "");
        assert_eq!(csv_cell("=1").as_ref(), b"'=1");
    }
}
