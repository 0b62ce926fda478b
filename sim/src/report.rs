//! The twin's reports: what `ergocell sim` prints and draws for each experiment's result, as text
//! tables and SVG figures held in strings. The experiments ([`crate::experiments`]) and their
//! summaries over seeds ([`crate::seeds`]) compute the numbers; this module only lays them out.
//!
//! No I/O here: the binary prints [`Report::text`] and writes each [`Figure`] under its file name
//! into the folder the user chose. The figures are plotters' SVG without system fonts (its naive
//! text layout), so that CI needs no font packages; the same result gives the same bytes.

use std::fmt::Write as _;

use plotters::prelude::*;

use crate::detector_fit::{decay_time_s, Evaluation, FIT_GAP_GOAL};
use crate::experiments::{Adaptation, HeightResult, RulaAgreement, Table1};
use crate::seeds::{self, Goal, Spread};
use crate::warning_trust::WarningTrustSeeds;
use ergocell_ergonomics::height::HandoverRula;
use ergocell_perception::detector_error::DetectorErrorReport;

pub mod warnings;

/// One figure: its file name (for example `adaptation_grand_score.svg`) and the SVG document.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Figure {
    pub file_name: String,
    pub svg: String,
}

impl Figure {
    fn new(file_name: &str, svg: String) -> Self {
        Self {
            file_name: file_name.to_owned(),
            svg,
        }
    }
}

/// What one experiment's run reports: the text the terminal shows and its figures.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Report {
    pub text: String,
    pub figures: Vec<Figure>,
}

/// A figure that could not be drawn (plotters' own error, as it describes it).
#[derive(Debug, thiserror::Error)]
#[error("drawing the figure {file_name}: {detail}")]
pub struct FigureError {
    pub file_name: String,
    pub detail: String,
}

fn fail<E: std::fmt::Debug>(file_name: &str, e: &E) -> FigureError {
    FigureError {
        file_name: file_name.to_owned(),
        detail: format!("{e:?}"),
    }
}

/// A length in metres as centimetres in a six-wide column, or a dash where there is none.
fn cm(x: Option<f64>) -> String {
    x.map_or_else(|| "   —  ".to_owned(), |v| format!("{:6.2}", v * 100.0))
}

/// The series colours the twin's figures share (the design's and the warnings' figures too).
pub const COLORS: [RGBColor; 6] = [
    RGBColor(120, 144, 156),
    RGBColor(158, 158, 158),
    RGBColor(189, 189, 189),
    RGBColor(239, 108, 0),
    RGBColor(21, 101, 192),
    RGBColor(46, 125, 50),
];

// ---------------------------------------------------------------------------------------------
// One run

pub fn table1_text(r: &Table1) -> String {
    let mut out = String::new();
    let _ = writeln!(
        out,
        "RMSE per landmark, cm ({} frames, operators {:?} m)",
        r.frames, r.statures_m
    );
    let methods: Vec<&String> = r.rmse_m.keys().filter(|k| !k.ends_with("fusion")).collect();
    let _ = write!(out, "{:<16}", "landmark");
    for m in &methods {
        let _ = write!(out, " {m:>6}");
    }
    let _ = writeln!(out, " {:>6} {:>6}", "paper", "default");
    for (i, lm) in r.landmarks.iter().enumerate() {
        let _ = write!(out, "{lm:<16}");
        for m in &methods {
            let _ = write!(out, " {}", cm(r.rmse_m[*m][i]));
        }
        let _ = writeln!(
            out,
            " {} {}",
            cm(r.rmse_m["paper_fusion"][i]),
            cm(r.rmse_m["default_fusion"][i])
        );
    }
    let best = r.best_pair();
    let paper: Vec<Option<f64>> = r.rmse_m["paper_fusion"].clone();
    let _ = writeln!(
        out,
        "default fusion beats the best single pair on {}/12 landmarks and the paper fusion on {}/12; \
         the paper fusion beats the best single pair on {}/12",
        r.wins("default_fusion", &best),
        r.wins("default_fusion", &paper),
        r.wins("paper_fusion", &best)
    );
    out
}

pub fn adaptation_text(r: &Adaptation) -> String {
    let mut out = String::new();
    let _ = writeln!(
        out,
        "mean RULA grand score while holding the part (noisy pipeline; ground truth in brackets)"
    );
    let _ = writeln!(out, "{:>8} {:>16} {:>16}", "height", "before", "after");
    for i in 0..r.heights_m.len() {
        let after = match r.not_served_after.get(i).and_then(Option::as_ref) {
            Some(why) => format!("not served: {why}"),
            None => format!(
                "{:>8.2} [{:4.2}]",
                r.mean_grand_score_after[i], r.true_mean_grand_score_after[i]
            ),
        };
        let _ = writeln!(
            out,
            "{:>6.2} m {:>8.2} [{:4.2}] {after}",
            r.heights_m[i], r.mean_grand_score_before[i], r.true_mean_grand_score_before[i],
        );
    }
    let _ = writeln!(out, "mean posture cost while holding the part (grand score + how far into the bands; truth in brackets)");
    for i in 0..r.heights_m.len() {
        let _ = writeln!(
            out,
            "{:>6.2} m {:>8.3} [{:5.3}] {:>8.3} [{:5.3}]",
            r.heights_m[i],
            r.mean_posture_cost_before[i],
            r.true_mean_posture_cost_before[i],
            r.mean_posture_cost_after[i],
            r.true_mean_posture_cost_after[i],
        );
    }
    let _ = writeln!(
        out,
        "mean region scores over the heights served after adaptation (before → after):"
    );
    for (j, region) in r.region_names.iter().enumerate() {
        let m = |v: &Vec<Vec<f64>>| {
            let x: Vec<f64> = v
                .iter()
                .zip(&r.not_served_after)
                .filter(|(_, why)| why.is_none())
                .map(|(x, _)| x[j])
                .collect();
            x.iter().sum::<f64>() / x.len().max(1) as f64
        };
        let _ = writeln!(
            out,
            "  {region:<10} {:.2} → {:.2}",
            m(&r.mean_region_scores_before),
            m(&r.mean_region_scores_after)
        );
    }
    out
}

pub fn height_text(r: &HeightResult) -> String {
    let mut out = String::new();
    let o = &r.calibration;
    let _ = writeln!(
        out,
        "ear offset: {:+.1} ± {:.1} mm ({}); the detector's true offset {:+.1} mm",
        o.offset_m * 1e3,
        o.sigma_m * 1e3,
        o.calibrated_sessions
            .map_or("uncalibrated".to_owned(), |n| format!(
                "calibrated on {n} sessions"
            )),
        r.detector_ear_offset_m * 1e3
    );
    let _ = writeln!(
        out,
        "decided after standing at the station: median {:.2} s, p95 {:.2} s; RULA cost of the decision: {}",
        r.decision_time_median_s,
        r.decision_time_p95_s,
        match (r.rula_cost_mean, r.rula_cost_worst) {
            (Some(m), Some(w)) => format!("mean {m:.3}, worst {w:.3}"),
            _ => "no curves".to_owned(),
        }
    );
    let _ = writeln!(
        out,
        "{} operators: MAE {:.2} cm; class accuracy {:.1}% overall, {:.1}% beyond 2 cm of a boundary; \
         {} undecided, {} confidently wrong, {} given the neighbouring class across a boundary",
        r.operators.len(),
        r.mae_m * 100.0,
        r.class_accuracy * 100.0,
        r.class_accuracy_beyond_2cm * 100.0,
        r.undecided,
        r.confidently_wrong,
        r.wrong_across_boundary
    );
    out
}

pub fn agreement_text(r: &RulaAgreement) -> String {
    let mut out = String::new();
    let _ = writeln!(
        out,
        "{} frames: grand score exact {:.3}, κ {:.3}; action level exact {:.3}, κ {:.3} \
         (Kinect anchor: Po 0.96, κ 0.84)",
        r.frames,
        r.grand_score.exact,
        r.grand_score.kappa,
        r.action_level.exact,
        r.action_level.kappa
    );
    let _ = writeln!(
        out,
        "per region: exact agreement, mean difference (pipeline − truth), \
         confusion truth→pipeline (scores that occur)"
    );
    for (j, name) in r.region_names.iter().enumerate() {
        let confusion: Vec<String> = r
            .region_confusion
            .get(j)
            .into_iter()
            .flat_map(|m| m.iter().enumerate())
            .flat_map(|(t, row)| {
                row.iter()
                    .enumerate()
                    .filter(|(_, n)| **n > 0)
                    .map(move |(e, n)| format!("{}→{}: {n}", t + 1, e + 1))
            })
            .collect();
        let _ = writeln!(
            out,
            "  {name:<10} {:.3} {:+.3}  {}",
            r.region_exact[j],
            r.region_mean_difference[j],
            confusion.join(", ")
        );
    }
    let _ = writeln!(
        out,
        "grand score differs with every region score equal (muscle use differs): {} frames",
        r.grand_differs_with_regions_equal
    );
    let _ = writeln!(
        out,
        "marked uncertain by the assessor: {} of {} frames; grand score exact {:.3} there, {:.3} elsewhere",
        r.uncertain_frames, r.frames, r.grand_exact_uncertain, r.grand_exact_certain
    );
    let _ = writeln!(
        out,
        "posture warnings raised: {:.2} per minute (on the truth's assessments {:.2}); of the truth's {}, {} also raised by the pipeline (same region and side, within the dwell time); of the pipeline's {}, {} also raised by the truth",
        r.warnings_per_min,
        r.true_warnings_per_min,
        r.true_warnings_raised,
        r.true_warnings_caught,
        r.warnings_raised,
        r.warnings_confirmed
    );
    out
}

/// The RULA agreement's noise sweep ([`crate::experiments::noise_sweep`]): a line per pixel-noise
/// level, the grand score's and the action level's exact agreement and κ.
pub fn noise_sweep_text(sweep: &[(f64, RulaAgreement)]) -> String {
    let mut out = String::new();
    let _ = writeln!(
        out,
        "noise sweep (σ px: grand exact / κ, action level exact / κ):"
    );
    for (n, a) in sweep {
        let _ = writeln!(
            out,
            "  {n:>4.1} px: {:.3} / {:.3}, {:.3} / {:.3}",
            a.grand_score.exact, a.grand_score.kappa, a.action_level.exact, a.action_level.kappa
        );
    }
    out
}

/// The simulated detector in words, for titles: `detector <file name>` for a fitted model's file
/// (`detector_file`), else `<noise_px> px`; then the filter RULA ran on: the causal one
/// (`fixed_lag_s` 0), a fixed-lag smoother of `fixed_lag_s`, or the controller's default lag.
pub fn detector_label(
    detector_file: Option<&str>,
    noise_px: f64,
    fixed_lag_s: Option<f64>,
) -> String {
    let detector = match detector_file {
        Some(name) => format!("detector {name}"),
        None => format!("{noise_px} px"),
    };
    match fixed_lag_s {
        Some(0.0) => format!("{detector}, the causal filter (no fixed lag)"),
        Some(w) => format!("{detector}, a fixed-lag smoother of ±{w} s"),
        None => format!(
            "{detector}, the controller's fixed lag of ±{} s",
            ergocell_cell::pipeline::DEFAULT_FIXED_LAG_S
        ),
    }
}

// ---------------------------------------------------------------------------------------------
// Figures

pub fn table1_figures(r: &Table1) -> Result<Vec<Figure>, FigureError> {
    let name = "table1_rmse.svg";
    let methods: Vec<String> = r
        .rmse_m
        .keys()
        .filter(|k| !k.ends_with("fusion"))
        .cloned()
        .chain(["paper_fusion".to_owned(), "default_fusion".to_owned()])
        .collect();
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, (1200, 900)).into_drawing_area();
        root.fill(&WHITE).map_err(|e| fail(name, &e))?;
        let panels = root.split_evenly((2, 1));
        for (panel, (title, values)) in panels.iter().zip([
            (
                "Table 1 on the digital twin: RMSE per landmark, cm (log scale; lower is better)",
                &r.rmse_m,
            ),
            ("Median error per landmark, cm (log scale)", &r.median_m),
        ]) {
            let max = values
                .values()
                .flatten()
                .flatten()
                .fold(0.0f64, |a, b| a.max(*b))
                * 100.0
                * 2.0;
            let floor = 0.1;
            let n = r.landmarks.len();
            let mut chart = ChartBuilder::on(panel)
                .caption(title, ("sans-serif", 18))
                .margin(15)
                .x_label_area_size(40)
                .y_label_area_size(60)
                .build_cartesian_2d(0.0..n as f64, (floor..max.max(1.0)).log_scale())
                .map_err(|e| fail(name, &e))?;
            let names = r.landmarks.clone();
            chart
                .configure_mesh()
                .disable_x_mesh()
                .x_labels(2 * n + 1)
                .x_label_formatter(&|x| {
                    let i = x.floor() as usize;
                    if (x - i as f64 - 0.5).abs() < 0.01 && i < names.len() {
                        names[i].replace("left_", "L ").replace("right_", "R ")
                    } else {
                        String::new()
                    }
                })
                .y_label_formatter(&|y| format!("{y}"))
                .y_desc("cm")
                .draw()
                .map_err(|e| fail(name, &e))?;
            let width = 0.85 / methods.len() as f64;
            for (m, method) in methods.iter().enumerate() {
                let color =
                    COLORS[(m + COLORS.len() - methods.len().min(COLORS.len())) % COLORS.len()];
                let Some(v) = values.get(method) else {
                    continue;
                };
                chart
                    .draw_series(v.iter().enumerate().filter_map(|(i, v)| {
                        v.map(|v| {
                            let x0 = i as f64 + 0.075 + m as f64 * width;
                            Rectangle::new(
                                [(x0, floor), (x0 + width * 0.9, (v * 100.0).max(floor))],
                                color.filled(),
                            )
                        })
                    }))
                    .map_err(|e| fail(name, &e))?
                    .label(method.clone())
                    .legend(move |(x, y)| {
                        Rectangle::new([(x, y - 5), (x + 12, y + 5)], color.filled())
                    });
            }
            chart
                .configure_series_labels()
                .background_style(WHITE.mix(0.9))
                .border_style(BLACK)
                .position(SeriesLabelPosition::UpperRight)
                .draw()
                .map_err(|e| fail(name, &e))?;
        }
        root.present().map_err(|e| fail(name, &e))?;
    }
    Ok(vec![Figure::new(name, svg)])
}

/// One line chart, 900 × 520 px, as figure `file_name`: each series is `(label, y per x, colour,
/// dashed)`; non-finite values (a seed without the quantity) are left out of their line; the legend
/// sits lower left.
#[allow(clippy::too_many_arguments)]
pub fn line_chart(
    file_name: &str,
    title: &str,
    x_desc: &str,
    y_desc: &str,
    x: &[f64],
    series: &[(&str, &[f64], RGBColor, bool)],
    y_range: (f64, f64),
) -> Result<Figure, FigureError> {
    let name = file_name;
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, (900, 520)).into_drawing_area();
        root.fill(&WHITE).map_err(|e| fail(name, &e))?;
        let (x0, x1) = (
            x.first().copied().unwrap_or(0.0),
            x.last().copied().unwrap_or(1.0),
        );
        let mut chart = ChartBuilder::on(&root)
            .caption(title, ("sans-serif", 18))
            .margin(15)
            .x_label_area_size(45)
            .y_label_area_size(55)
            .build_cartesian_2d(
                x0 - 0.02 * (x1 - x0)..x1 + 0.02 * (x1 - x0),
                y_range.0..y_range.1,
            )
            .map_err(|e| fail(name, &e))?;
        chart
            .configure_mesh()
            .x_desc(x_desc)
            .y_desc(y_desc)
            .draw()
            .map_err(|e| fail(name, &e))?;
        for (label, ys, color, dashed) in series {
            let color = *color;
            let pts: Vec<(f64, f64)> = x
                .iter()
                .zip(ys.iter())
                .filter(|(_, y)| y.is_finite())
                .map(|(a, b)| (*a, *b))
                .collect();
            // Solid: the noisy pipeline; dashed: the ground truth (the legend draws the same).
            if *dashed {
                chart
                    .draw_series(DashedLineSeries::new(
                        pts.clone(),
                        7,
                        5,
                        color.stroke_width(2),
                    ))
                    .map_err(|e| fail(name, &e))?
                    .label(*label)
                    .legend(move |(x, y)| {
                        EmptyElement::at((x, y))
                            + PathElement::new(vec![(0, 0), (6, 0)], color.stroke_width(2))
                            + PathElement::new(vec![(10, 0), (16, 0)], color.stroke_width(2))
                    });
            } else {
                chart
                    .draw_series(LineSeries::new(pts.clone(), color.stroke_width(3)))
                    .map_err(|e| fail(name, &e))?
                    .label(*label)
                    .legend(move |(x, y)| {
                        PathElement::new(vec![(x, y), (x + 16, y)], color.stroke_width(3))
                    });
            }
            chart
                .draw_series(pts.iter().map(|p| Circle::new(*p, 3, color.filled())))
                .map_err(|e| fail(name, &e))?;
        }
        chart
            .configure_series_labels()
            .background_style(WHITE.mix(0.9))
            .border_style(BLACK)
            .position(SeriesLabelPosition::LowerLeft)
            .draw()
            .map_err(|e| fail(name, &e))?;
        root.present().map_err(|e| fail(name, &e))?;
    }
    Ok(Figure::new(name, svg))
}

pub fn adaptation_figures(r: &Adaptation) -> Result<Vec<Figure>, FigureError> {
    let grand = line_chart(
        "adaptation_grand_score.svg",
        "Mean RULA grand score while holding the part: before vs after adaptation",
        "operator stature, m",
        "mean RULA grand score (worse side)",
        &r.heights_m,
        &[
            (
                "before (noisy pipeline)",
                &r.mean_grand_score_before,
                COLORS[3],
                false,
            ),
            (
                "after (noisy pipeline)",
                &r.mean_grand_score_after,
                COLORS[4],
                false,
            ),
            (
                "before (ground truth)",
                &r.true_mean_grand_score_before,
                COLORS[3],
                true,
            ),
            (
                "after (ground truth)",
                &r.true_mean_grand_score_after,
                COLORS[4],
                true,
            ),
        ],
        (1.0, 7.0),
    )?;
    let mut out = vec![grand];
    // Region scores: one line chart per region would be many files; one chart, before dashed.
    let per_region = |v: &Vec<Vec<f64>>, j: usize| v.iter().map(|x| x[j]).collect::<Vec<f64>>();
    let before: Vec<Vec<f64>> = (0..6)
        .map(|j| per_region(&r.mean_region_scores_before, j))
        .collect();
    let after: Vec<Vec<f64>> = (0..6)
        .map(|j| per_region(&r.mean_region_scores_after, j))
        .collect();
    let palette = [
        RGBColor(239, 108, 0),
        RGBColor(21, 101, 192),
        RGBColor(46, 125, 50),
        RGBColor(142, 36, 170),
        RGBColor(198, 40, 40),
        RGBColor(96, 125, 139),
    ];
    let labels_before: Vec<String> = r
        .region_names
        .iter()
        .map(|n| format!("{n} before"))
        .collect();
    let labels_after: Vec<String> = r
        .region_names
        .iter()
        .map(|n| format!("{n} after"))
        .collect();
    let mut series: Vec<(&str, &[f64], RGBColor, bool)> = Vec::new();
    for j in 0..6 {
        series.push((&labels_before[j], &before[j], palette[j], true));
        series.push((&labels_after[j], &after[j], palette[j], false));
    }
    let regions = line_chart(
        "adaptation_regions.svg",
        "Mean RULA score per body region (thin: before, thick: after adaptation)",
        "operator stature, m",
        "mean region score",
        &r.heights_m,
        &series,
        (0.5, 5.0),
    )?;
    out.push(regions);
    let before: Vec<Vec<f64>> = (0..4)
        .map(|j| per_region(&r.mean_angles_deg_before, j))
        .collect();
    let after: Vec<Vec<f64>> = (0..4)
        .map(|j| per_region(&r.mean_angles_deg_after, j))
        .collect();
    let labels_before: Vec<String> = r
        .angle_names
        .iter()
        .map(|n| format!("{n} before"))
        .collect();
    let labels_after: Vec<String> = r.angle_names.iter().map(|n| format!("{n} after")).collect();
    let mut series: Vec<(&str, &[f64], RGBColor, bool)> = Vec::new();
    for j in 0..4 {
        series.push((&labels_before[j], &before[j], palette[j], true));
        series.push((&labels_after[j], &after[j], palette[j], false));
    }
    let angles = line_chart(
        "adaptation_angles.svg",
        "True joint angles while holding the part (thin: before, thick: after adaptation)",
        "operator stature, m",
        "angle, degrees",
        &r.heights_m,
        &series,
        (-10.0, 90.0),
    )?;
    out.push(angles);
    Ok(out)
}

pub fn height_figures(r: &HeightResult) -> Result<Vec<Figure>, FigureError> {
    let name = "height_estimates.svg";
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, (800, 640)).into_drawing_area();
        root.fill(&WHITE).map_err(|e| fail(name, &e))?;
        let mut chart = ChartBuilder::on(&root)
            .caption(
                format!(
                    "Stature from the noisy cameras: MAE {:.2} cm, {} undecided, {} wrong",
                    r.mae_m * 100.0,
                    r.undecided,
                    r.confidently_wrong
                ),
                ("sans-serif", 18),
            )
            .margin(15)
            .x_label_area_size(45)
            .y_label_area_size(60)
            .build_cartesian_2d(1.38..2.08, -4.0..4.0)
            .map_err(|e| fail(name, &e))?;
        chart
            .configure_mesh()
            .x_desc("true stature, m")
            .y_desc("estimate − truth, cm")
            .draw()
            .map_err(|e| fail(name, &e))?;
        for b in [1.68, 1.82] {
            chart
                .draw_series(LineSeries::new(vec![(b, -4.0), (b, 4.0)], BLACK.mix(0.4)))
                .map_err(|e| fail(name, &e))?;
        }
        for (label, color, pick) in [
            ("class correct", COLORS[5], 0),
            ("undecided", COLORS[3], 1),
            ("class wrong", RED, 2),
        ] {
            let pts: Vec<(f64, f64)> = r
                .operators
                .iter()
                .filter(|o| match pick {
                    0 => o.decided_class == Some(o.true_class),
                    1 => o.decided_class.is_none(),
                    _ => o.decided_class.is_some_and(|c| c != o.true_class),
                })
                .filter_map(|o| {
                    o.estimated_m
                        .map(|e| (o.true_m, ((e - o.true_m) * 100.0).clamp(-3.9, 3.9)))
                })
                .collect();
            chart
                .draw_series(pts.iter().map(|p| Circle::new(*p, 4, color.filled())))
                .map_err(|e| fail(name, &e))?
                .label(label)
                .legend(move |(x, y)| Circle::new((x + 6, y), 4, color.filled()));
        }
        chart
            .configure_series_labels()
            .background_style(WHITE.mix(0.9))
            .border_style(BLACK)
            .position(SeriesLabelPosition::UpperLeft)
            .draw()
            .map_err(|e| fail(name, &e))?;
        root.present().map_err(|e| fail(name, &e))?;
    }
    Ok(vec![Figure::new(name, svg)])
}

pub fn noise_sweep_figure(sweep: &[(f64, RulaAgreement)]) -> Result<Figure, FigureError> {
    let xs: Vec<f64> = sweep.iter().map(|(n, _)| *n).collect();
    let pick =
        |f: &dyn Fn(&RulaAgreement) -> f64| sweep.iter().map(|(_, a)| f(a)).collect::<Vec<f64>>();
    let ge = pick(&|a| a.grand_score.exact);
    let gk = pick(&|a| a.grand_score.kappa);
    let le = pick(&|a| a.action_level.exact);
    let lk = pick(&|a| a.action_level.kappa);
    let anchor_po = vec![0.96; xs.len()];
    let anchor_k = vec![0.84; xs.len()];
    line_chart(
        "rula_agreement_noise.svg",
        "RULA agreement with ground truth vs detector pixel noise",
        "pixel noise σ, px",
        "agreement",
        &xs,
        &[
            ("grand score exact", &ge, COLORS[4], false),
            ("grand score κ", &gk, COLORS[3], false),
            ("action level exact", &le, COLORS[5], false),
            ("action level κ", &lk, RGBColor(142, 36, 170), false),
            ("Kinect anchor Po 0.96", &anchor_po, COLORS[0], true),
            ("Kinect anchor κ 0.84", &anchor_k, COLORS[1], true),
        ],
        (0.0, 1.0),
    )
}

pub fn agreement_figures(r: &RulaAgreement) -> Result<Vec<Figure>, FigureError> {
    let name = "rula_agreement.svg";
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, (1100, 560)).into_drawing_area();
        root.fill(&WHITE).map_err(|e| fail(name, &e))?;
        let panels = root.split_evenly((1, 2));
        for (panel, (title, a)) in panels.iter().zip([
            ("grand score", &r.grand_score),
            ("action level", &r.action_level),
        ]) {
            let k = a.confusion.len();
            let max = a
                .confusion
                .iter()
                .flatten()
                .copied()
                .max()
                .unwrap_or(1)
                .max(1) as f64;
            let mut chart = ChartBuilder::on(panel)
                .caption(
                    format!("{title}: exact {:.3}, κ {:.3}", a.exact, a.kappa),
                    ("sans-serif", 17),
                )
                .margin(15)
                .x_label_area_size(45)
                .y_label_area_size(45)
                .build_cartesian_2d(0.5..k as f64 + 0.5, 0.5..k as f64 + 0.5)
                .map_err(|e| fail(name, &e))?;
            chart
                .configure_mesh()
                .disable_mesh()
                .x_labels(k)
                .y_labels(k)
                .x_label_formatter(&|x| format!("{x:.0}"))
                .y_label_formatter(&|y| format!("{y:.0}"))
                .x_desc("noisy pipeline")
                .y_desc("ground truth")
                .draw()
                .map_err(|e| fail(name, &e))?;
            for (t, row) in a.confusion.iter().enumerate() {
                for (e, count) in row.iter().enumerate() {
                    let (x, y) = (e as f64 + 1.0, t as f64 + 1.0);
                    let shade = *count as f64 / max;
                    let color = RGBColor(
                        (255.0 - 234.0 * shade) as u8,
                        (255.0 - 154.0 * shade) as u8,
                        (255.0 - 63.0 * shade) as u8,
                    );
                    chart
                        .draw_series(std::iter::once(Rectangle::new(
                            [(x - 0.5, y - 0.5), (x + 0.5, y + 0.5)],
                            color.filled(),
                        )))
                        .map_err(|e| fail(name, &e))?;
                    if *count > 0 {
                        let text_color = if shade > 0.5 { WHITE } else { BLACK };
                        chart
                            .draw_series(std::iter::once(Text::new(
                                count.to_string(),
                                (x - 0.15, y + 0.1),
                                ("sans-serif", 14).into_font().color(&text_color),
                            )))
                            .map_err(|e| fail(name, &e))?;
                    }
                }
            }
        }
        root.present().map_err(|e| fail(name, &e))?;
    }
    Ok(vec![Figure::new(name, svg)])
}

// ---------------------------------------------------------------------------------------------
// Over seeds

/// `mean ± s.d. (worst … on seed …)` of a spread over seeds, scaled (100 for centimetres), or a dash.
pub fn spread_text(s: Option<&Spread>, scale: f64, digits: usize) -> String {
    s.map_or_else(
        || "—".to_owned(),
        |s| {
            format!(
                "{:.d$} ± {:.d$} (worst {:.d$} on seed {})",
                s.mean * scale,
                s.sd * scale,
                s.worst * scale,
                s.worst_seed,
                d = digits
            )
        },
    )
}

/// Each goal's line (on how many seeds it holds) and, under it, each failing seed with why.
pub fn goals_text(goals: &[Goal]) -> String {
    let mut out = String::new();
    for g in goals {
        let _ = writeln!(
            out,
            "goal: {} — holds on {} of {} seeds",
            g.goal, g.holds_on, g.seeds
        );
        for (seed, why) in &g.fails {
            let _ = writeln!(out, "  seed {seed}: {why}");
        }
    }
    out
}

/// Table 1 over seeds: per landmark, the default fusion against the best pair and the paper's fusion;
/// one figure with a point per seed.
pub fn table1_seeds(
    seeds: &[u64],
    runs: &[Table1],
    sum: &seeds::Table1Seeds,
) -> Result<Report, FigureError> {
    let mut out = String::new();
    let _ = writeln!(
        out,
        "Table 1 over seeds {seeds:?}: RMSE per landmark, cm, mean ± s.d. (worst seed)"
    );
    for (i, lm) in sum.landmarks.iter().enumerate() {
        let _ = writeln!(
            out,
            "  {lm:<16} default {}  best pair {}  paper {}",
            spread_text(sum.default_rmse_m[i].as_ref(), 100.0, 2),
            spread_text(sum.best_pair_rmse_m[i].as_ref(), 100.0, 1),
            spread_text(sum.paper_rmse_m[i].as_ref(), 100.0, 1)
        );
    }
    out.push_str(&goals_text(&sum.goals));

    let worst = |v: &[Option<f64>], hi: bool| {
        let it = v.iter().flatten().copied();
        100.0
            * if hi {
                it.fold(f64::NAN, f64::max)
            } else {
                it.fold(f64::NAN, f64::min)
            }
    };
    let x: Vec<f64> = seeds.iter().map(|s| *s as f64).collect();
    let default_worst: Vec<f64> = runs
        .iter()
        .map(|r| worst(r.rmse_m.get("default_fusion").map_or(&[][..], |v| v), true))
        .collect();
    let pair_best: Vec<f64> = runs.iter().map(|r| worst(&r.best_pair(), false)).collect();
    let paper_best: Vec<f64> = runs
        .iter()
        .map(|r| worst(r.rmse_m.get("paper_fusion").map_or(&[][..], |v| v), false))
        .collect();
    let top = pair_best
        .iter()
        .chain(&paper_best)
        .chain(&default_worst)
        .copied()
        .filter(|v| v.is_finite())
        .fold(1.0, f64::max);
    let path = line_chart(
        "table1_seeds.svg",
        "Table 1 per seed: the default fusion's worst landmark vs the others' best, cm",
        "seed",
        "RMSE, cm",
        &x,
        &[
            (
                "default fusion, worst landmark",
                &default_worst,
                COLORS[5],
                false,
            ),
            (
                "best single pair, best landmark",
                &pair_best,
                COLORS[3],
                false,
            ),
            ("paper fusion, best landmark", &paper_best, COLORS[4], false),
        ],
        (0.0, top * 1.1),
    )?;
    Ok(Report {
        text: out,
        figures: vec![path],
    })
}

/// The adaptation over seeds: grand score and posture cost per stature, before and after.
pub fn adaptation_seeds(
    seeds: &[u64],
    sum: &seeds::AdaptationSeeds,
) -> Result<Report, FigureError> {
    let mut out = String::new();
    let _ = writeln!(out, "adaptation over seeds {seeds:?}: mean grand score while holding the part, mean ± s.d. (worst seed)");
    for (i, h) in sum.heights_m.iter().enumerate() {
        let _ = writeln!(
            out,
            "  {h:.2} m  before {}  after {}  truth after {}",
            spread_text(sum.before[i].as_ref(), 1.0, 2),
            spread_text(sum.after[i].as_ref(), 1.0, 2),
            spread_text(sum.true_after[i].as_ref(), 1.0, 2)
        );
    }
    let _ = writeln!(
        out,
        "posture cost while holding the part, truth, mean ± s.d. (worst seed)"
    );
    for (i, h) in sum.heights_m.iter().enumerate() {
        let _ = writeln!(
            out,
            "  {h:.2} m  before {}  after {}",
            spread_text(sum.true_cost_before[i].as_ref(), 1.0, 3),
            spread_text(sum.true_cost_after[i].as_ref(), 1.0, 3),
        );
    }
    out.push_str(&goals_text(&sum.goals));

    let col = |v: &[Option<Spread>], f: fn(&Spread) -> f64| -> Vec<f64> {
        v.iter().map(|s| s.as_ref().map_or(f64::NAN, f)).collect()
    };
    let goal = vec![seeds::ADAPTATION_MAX_AFTER; sum.heights_m.len()];
    let path = line_chart(
        "adaptation_seeds.svg",
        &format!(
            "Adaptation over {} seeds: mean grand score while holding the part",
            seeds.len()
        ),
        "operator stature, m",
        "mean RULA grand score",
        &sum.heights_m,
        &[
            (
                "before, mean over seeds",
                &col(&sum.before, |s| s.mean),
                COLORS[0],
                false,
            ),
            (
                "after, mean over seeds",
                &col(&sum.after, |s| s.mean),
                COLORS[5],
                false,
            ),
            (
                "after, worst seed",
                &col(&sum.after, |s| s.max),
                COLORS[4],
                false,
            ),
            (
                "truth after, worst seed",
                &col(&sum.true_after, |s| s.max),
                COLORS[4],
                true,
            ),
            ("goal ≤ 3.00", &goal, RED, true),
        ],
        (2.0, 4.5),
    )?;
    let cost_path = line_chart(
        "adaptation_seeds_cost.svg",
        &format!(
            "Adaptation over {} seeds: posture cost while holding the part (truth)",
            seeds.len()
        ),
        "operator stature, m",
        "mean posture cost (RULA points)",
        &sum.heights_m,
        &[
            (
                "before, mean over seeds",
                &col(&sum.true_cost_before, |s| s.mean),
                COLORS[0],
                false,
            ),
            (
                "after, mean over seeds",
                &col(&sum.true_cost_after, |s| s.mean),
                COLORS[5],
                false,
            ),
            (
                "after, worst seed",
                &col(&sum.true_cost_after, |s| s.max),
                COLORS[4],
                true,
            ),
        ],
        (2.5, 4.5),
    )?;
    Ok(Report {
        text: out,
        figures: vec![path, cost_path],
    })
}

/// The height experiment over seeds: error, coverage, decision time and cost; two figures with a
/// point per seed.
pub fn height_seeds(seeds: &[u64], sum: &seeds::HeightSeeds) -> Result<Report, FigureError> {
    let mut out = String::new();
    let _ = writeln!(
        out,
        "height over seeds {seeds:?} (mean ± s.d., worst seed):"
    );
    let _ = writeln!(
        out,
        "  MAE               {} cm",
        spread_text(sum.mae_m.as_ref(), 100.0, 2)
    );
    let _ = writeln!(
        out,
        "  right beyond 2 cm {}",
        spread_text(sum.class_accuracy_beyond_2cm.as_ref(), 1.0, 3)
    );
    let _ = writeln!(
        out,
        "  undecided         {}",
        spread_text(sum.undecided.as_ref(), 1.0, 1)
    );
    let _ = writeln!(
        out,
        "  coverage ±kσ      {}",
        spread_text(sum.coverage.as_ref(), 1.0, 3)
    );
    let _ = writeln!(
        out,
        "  coverage ±1σ      {}",
        spread_text(sum.coverage_1sigma.as_ref(), 1.0, 3)
    );
    let _ = writeln!(
        out,
        "  coverage pooled   ±kσ {:.3}, ±1σ {:.3} over all {} operators",
        sum.coverage_pooled, sum.coverage_1sigma_pooled, sum.operators_total
    );
    let _ = writeln!(
        out,
        "  decided after     median {} s, p95 {} s",
        spread_text(sum.decision_time_median_s.as_ref(), 1.0, 2),
        spread_text(sum.decision_time_p95_s.as_ref(), 1.0, 2)
    );
    let _ = writeln!(
        out,
        "  RULA cost         mean {}, worst {}",
        spread_text(sum.rula_cost_mean.as_ref(), 1.0, 3),
        spread_text(sum.rula_cost_worst.as_ref(), 1.0, 3)
    );
    let _ = writeln!(
        out,
        "  calibrated offset {} mm",
        spread_text(sum.calibrated_offset_m.as_ref(), 1000.0, 1)
    );
    let _ = writeln!(
        out,
        "  not servable      {} (no trajectory serves their stature)",
        spread_text(sum.not_servable.as_ref(), 1.0, 1)
    );
    let [c1, c2, c3] = sum.decided_per_class_total;
    let _ = writeln!(
        out,
        "  confidently wrong {} of {} operators; the neighbouring class across a boundary: {} \
         ({} within 2 cm of a boundary); decided c1 {c1}, c2 {c2}, c3 {c3}",
        sum.confidently_wrong_total,
        sum.operators_total,
        sum.wrong_across_boundary_total,
        sum.near_boundary_total
    );
    out.push_str(&goals_text(&sum.goals));

    let x: Vec<f64> = seeds.iter().map(|s| *s as f64).collect();
    let per = |s: Option<&Spread>, scale: f64| -> Vec<f64> {
        s.map_or_else(
            || vec![f64::NAN; x.len()],
            |s| s.per_seed.iter().map(|v| v * scale).collect(),
        )
    };
    let mae = line_chart(
        "height_seeds_mae.svg",
        "Stature per seed: mean absolute error and undecided operators",
        "seed",
        "MAE, cm  |  undecided operators / 10",
        &x,
        &[
            ("MAE, cm", &per(sum.mae_m.as_ref(), 100.0), COLORS[5], false),
            (
                "undecided / 10",
                &per(sum.undecided.as_ref(), 0.1),
                COLORS[3],
                false,
            ),
            ("goal MAE ≤ 1.5 cm", &vec![1.5; x.len()], RED, true),
        ],
        (0.0, 2.0),
    )?;
    let cov = line_chart(
        "height_seeds_coverage.svg",
        "Coverage of the stated stature interval per seed (share of operators whose truth lies inside)",
        "seed",
        "coverage",
        &x,
        &[
            ("±kσ (k = 2)", &per(sum.coverage.as_ref(), 1.0), COLORS[5], false),
            ("±1σ", &per(sum.coverage_1sigma.as_ref(), 1.0), COLORS[3], false),
            ("nominal 2σ 0.954", &vec![seeds::NOMINAL_2SIGMA; x.len()], RED, true),
            ("nominal 1σ 0.683", &vec![0.6827; x.len()], COLORS[0], true),
        ],
        (0.0, 1.05),
    )?;
    Ok(Report {
        text: out,
        figures: vec![mae, cov],
    })
}

/// RULA agreement over seeds with `detector` (its label): per seed and pooled, and the figure.
pub fn rula_agreement_seeds(
    seeds: &[u64],
    sum: &seeds::RulaSeeds,
    detector: &str,
) -> Result<Report, FigureError> {
    let mut out = String::new();
    let _ = writeln!(
        out,
        "RULA agreement over seeds {seeds:?} with {detector} (mean ± s.d., worst seed):"
    );
    let _ = writeln!(
        out,
        "  grand score exact  {}",
        spread_text(sum.grand_exact.as_ref(), 1.0, 3)
    );
    let _ = writeln!(
        out,
        "  grand score κ      {}",
        spread_text(sum.grand_kappa.as_ref(), 1.0, 3)
    );
    let _ = writeln!(
        out,
        "  action level exact {}",
        spread_text(sum.action_level_exact.as_ref(), 1.0, 3)
    );
    let _ = writeln!(
        out,
        "  action level κ     {}",
        spread_text(sum.action_level_kappa.as_ref(), 1.0, 3)
    );
    for (j, r) in sum.region_names.iter().enumerate() {
        let _ = writeln!(
            out,
            "  {r:<10} exact  {}",
            spread_text(sum.region_exact[j].as_ref(), 1.0, 3)
        );
    }
    let _ = writeln!(
        out,
        "  warnings raised per minute {}; on the truth {}",
        spread_text(sum.warnings_per_min.as_ref(), 1.0, 2),
        spread_text(sum.true_warnings_per_min.as_ref(), 1.0, 2)
    );
    let w = &sum.warnings_pooled;
    let _ = writeln!(out,
        "  warnings over all seeds: {} in {:.1} min ({:.2} per minute; the truth {}, {:.2} per minute: {}); \
         the truth's also raised by the pipeline (same region and side, within the dwell time): {:.0} %; \
         the pipeline's also raised by the truth: {:.0} %",
        w.raised,
        w.minutes,
        w.per_min,
        w.true_raised,
        w.true_per_min,
        if w.rate_goal_holds() {
            "at most the truth's + 20 %"
        } else {
            "more than the truth's + 20 %"
        },
        100.0 * w.caught_share,
        100.0 * w.confirmed_share
    );
    out.push_str(&goals_text(&sum.goals));

    let x: Vec<f64> = seeds.iter().map(|s| *s as f64).collect();
    let per = |s: Option<&Spread>| -> Vec<f64> {
        s.map_or_else(|| vec![f64::NAN; x.len()], |s| s.per_seed.clone())
    };
    let path = line_chart(
        "rula_agreement_seeds.svg",
        &format!("RULA agreement with ground truth per seed ({detector})"),
        "seed",
        "agreement",
        &x,
        &[
            (
                "grand score exact",
                &per(sum.grand_exact.as_ref()),
                COLORS[5],
                false,
            ),
            (
                "grand score κ",
                &per(sum.grand_kappa.as_ref()),
                COLORS[4],
                false,
            ),
            (
                "action level κ",
                &per(sum.action_level_kappa.as_ref()),
                COLORS[3],
                false,
            ),
            (
                "goal exact ≥ 0.90",
                &vec![seeds::RULA_EXACT_GOAL; x.len()],
                RED,
                true,
            ),
            (
                "goal κ > 0.84",
                &vec![seeds::RULA_KAPPA_GOAL; x.len()],
                COLORS[0],
                true,
            ),
        ],
        (0.5, 1.0),
    )?;
    Ok(Report {
        text: out,
        figures: vec![path],
    })
}

// ---------------------------------------------------------------------------------------------
// The warnings' latency and the height decision's curves

/// The latency's cumulative distribution, pooled over the seeds, against the goal.
pub fn warning_latency_figure(
    file_name: &str,
    sum: &WarningTrustSeeds,
    detector: &str,
) -> Result<Figure, FigureError> {
    let mut sorted = sum.all.latencies_s.clone();
    sorted.sort_by(f64::total_cmp);
    let x: Vec<f64> = (0..=60).map(|k| f64::from(k) * 0.1).collect();
    let n = sorted.len().max(1) as f64;
    let share: Vec<f64> = x
        .iter()
        .map(|t| sorted.partition_point(|v| v <= t) as f64 / n)
        .collect();
    let bound: Vec<f64> = x
        .iter()
        .map(|t| if *t >= sum.latency_bound_s { 1.0 } else { 0.0 })
        .collect();
    line_chart(
        file_name,
        &format!("Posture to warning, share of clear postures warned by then ({detector})"),
        "seconds after the posture crossed the band edge",
        "share warned",
        &x,
        &[
            ("warned", &share, COLORS[4], false),
            ("95 %", &vec![0.95; x.len()], COLORS[0], true),
            ("dwell + lag + 0.5 s", &bound, RED, true),
        ],
        (0.0, 1.0),
    )
}

/// Each class's RULA-versus-stature curve (`handover_rula.toml`, what the height decision reads).
pub fn handover_rula_figure(rula: &HandoverRula) -> Result<Figure, FigureError> {
    line_chart(
        "handover_rula.svg",
        "Each class's mean RULA grand score at its handover point, per stature (truth)",
        "stature, m",
        "mean RULA grand score while holding",
        &rula.statures_m,
        &[
            ("c1", &rula.c1, COLORS[0], false),
            ("c2", &rula.c2, COLORS[1], false),
            ("c3", &rula.c3, COLORS[2], false),
        ],
        (1.0, 7.0),
    )
}

/// The RULA curves could not be written as TOML (the TOML writer's own error).
#[derive(Debug, thiserror::Error)]
#[error("writing the RULA curves as TOML: {0}")]
pub struct CurvesTomlError(#[from] pub toml::ser::Error);

/// `handover_rula.toml` as `sim handover-rula` writes it: a header saying what the curves are, how
/// they were measured (`cycles` handover cycles, `seeds`) and how to regenerate them, then the
/// curves.
pub fn handover_rula_file(
    rula: &HandoverRula,
    cycles: usize,
    seeds: &[u64],
) -> Result<String, CurvesTomlError> {
    let seeds_text: Vec<String> = seeds.iter().map(u64::to_string).collect();
    Ok(format!(
        "# Each class's RULA-versus-stature curve at its handover point: the mean true RULA grand score\n\
         # (worse side) of an operator of each stature (Drillis & Contini's proportions) holding the part at\n\
         # the class's handover point, over {} handover cycles and seeds {}. The height decision reads it:\n\
         # across a class boundary it chooses the class with the lowest expected score. Regenerate after\n\
         # changing a handover point (review the diff):\n\
         #   ergocell sim handover-rula --seeds {}..{} --out-dir trajectories\n{}",
        cycles,
        seeds_text.join(", "),
        seeds.first().copied().unwrap_or(1),
        seeds.last().copied().unwrap_or(1),
        toml::to_string(rula)?
    ))
}

/// What `sim fit-detector` prints: the fitted model's error against the real recording's
/// (`real_label` names it) group by group, seed by seed and pooled, the views' structure and how
/// long an error lasts; `independent_px` is the default noise compared with, `fit_seed` the seed fitted on.
pub fn detector_fit_text(
    real_label: &str,
    real: &DetectorErrorReport,
    e: &Evaluation,
    fit_seed: u64,
    independent_px: f64,
) -> String {
    let mut out = String::new();
    let pct = |q: &ergocell_perception::detector_error::Quantiles| {
        format!("{:>5.2} {:>5.2}", 100.0 * q.p50, 100.0 * q.p90)
    };
    let _ = writeln!(out,
        "detector fit to {} (% of the person's image height, median p90), twin over seeds {}..{} pooled:",
        real_label,
        e.seeds.first().copied().unwrap_or_default(),
        e.seeds.last().copied().unwrap_or_default(),
    );
    let _ = writeln!(
        out,
        "  {:<16} {:>11} {:>11}   {:>11} {:>11}   {:>11} {:>11}   {:>11}",
        "group",
        "real total",
        "twin total",
        "real pers.",
        "twin pers.",
        "real jit.",
        "twin jit.",
        "independent"
    );
    for (row, ind) in e.pooled.rows.iter().zip(&e.independent) {
        if row.real.total.count == 0 {
            let _ = writeln!(
                out,
                "  {:<16} not measured in the real recording",
                row.group
            );
            continue;
        }
        let _ = writeln!(
            out,
            "  {:<16} {} {}   {} {}   {} {}   {}",
            row.group,
            pct(&row.real.total),
            pct(&row.twin.total),
            pct(&row.real.persistent),
            pct(&row.twin.persistent),
            pct(&row.real.jitter),
            pct(&row.twin.jitter),
            pct(&ind.twin.total)
        );
    }
    let _ =
        writeln!(out,
        "  pooled: every measured group's median and p90 within {:.0} % of the real ({:.0} % asked)",
        100.0 * e.pooled_gap,
        100.0 * FIT_GAP_GOAL
    );
    let _ = writeln!(out,
        "  seed by seed (one rig-worth of offsets each): within {:.0} % on {} of {} seeds; worst {:.0} % on seed {}; fitted on seeds from {}",
        100.0 * FIT_GAP_GOAL,
        e.seeds_within,
        e.per_seed.len(),
        100.0 * e.worst_seed.1,
        e.worst_seed.0,
        fit_seed
    );
    let (r, t) = (&real.view_structure, &e.pooled.twin_structure);
    let _ = writeln!(
        out,
        "  the views' persistent offsets, real / twin (not fitted but the shift):"
    );
    let _ = writeln!(out,
        "    shared shift {} / {}   scale error {} / {}   rotation {:.1} {:.1} / {:.1} {:.1}°   left per landmark {} / {}",
        pct(&r.shift),
        pct(&t.shift),
        pct(&r.scale_error),
        pct(&t.scale_error),
        r.rotation_deg.p50,
        r.rotation_deg.p90,
        t.rotation_deg.p50,
        t.rotation_deg.p90,
        pct(&r.remainder),
        pct(&t.remainder)
    );
    let lags = |rows: &[ergocell_perception::detector_error::LagRow]| {
        rows.iter()
            .map(|l| format!("{:.2}", l.correlation))
            .collect::<Vec<_>>()
            .join(" ")
    };
    let _ = writeln!(
        out,
        "  how long a landmark's own error lasts, correlation at lags {} s, real / twin:",
        real.persistence
            .iter()
            .map(|l| format!("{}", l.lag_s))
            .collect::<Vec<_>>()
            .join(" ")
    );
    let _ = writeln!(
        out,
        "    {} / {}   (decay time {} / {} s)",
        lags(&real.persistence),
        lags(
            &e.pooled
                .twin_persistence
                .iter()
                .filter(|t| real.persistence.iter().any(|r| r.lag_s == t.lag_s))
                .copied()
                .collect::<Vec<_>>()
        ),
        decay_time_s(&real.persistence).map_or_else(|| "-".to_owned(), |t| format!("{t:.2}")),
        decay_time_s(&e.pooled.twin_persistence)
            .map_or_else(|| "-".to_owned(), |t| format!("{t:.2}"))
    );
    let _ = writeln!(out,
        "  (independent: the default model, {} px per coordinate, measured the same way on seed {})",
        independent_px,
        e.seeds.first().copied().unwrap_or_default()
    );
    out
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)]
    use super::*;

    #[test]
    fn a_spread_is_scaled_and_names_its_worst_seed() {
        let s = seeds::spread(&[7, 8, 9], &[0.010, 0.012, 0.017], seeds::Worse::Higher);
        assert_eq!(
            spread_text(s.as_ref(), 100.0, 2),
            "1.30 ± 0.36 (worst 1.70 on seed 9)"
        );
        assert_eq!(spread_text(None, 100.0, 2), "—");
    }

    #[test]
    fn each_goal_has_a_line_and_each_failing_seed_one_under_it() {
        let goals = [
            Goal {
                goal: "a".to_owned(),
                holds_on: 1,
                seeds: 3,
                fails: vec![(302, "x".to_owned()), (303, "y".to_owned())],
            },
            Goal {
                goal: "b".to_owned(),
                holds_on: 3,
                seeds: 3,
                fails: Vec::new(),
            },
        ];
        assert_eq!(
            goals_text(&goals),
            "goal: a — holds on 1 of 3 seeds\n  seed 302: x\n  seed 303: y\n\
             goal: b — holds on 3 of 3 seeds\n"
        );
    }

    #[test]
    fn a_line_chart_draws_each_finite_point_and_is_the_same_every_time() {
        let x = [1.0, 2.0, 3.0, 4.0];
        let y = [1.0, f64::NAN, 3.0, 2.0];
        let draw = || {
            line_chart(
                "t.svg",
                "title",
                "x",
                "y",
                &x,
                &[("y", &y, COLORS[0], false)],
                (0.0, 4.0),
            )
        };
        let figure = draw().unwrap();
        assert_eq!(figure.file_name, "t.svg");
        assert!(figure.svg.starts_with("<svg"));
        // One marker per finite point: the NaN (a seed without the quantity) is left out.
        assert_eq!(figure.svg.matches("<circle").count(), 3);
        assert_eq!(draw().unwrap(), figure);
    }

    #[test]
    fn the_noise_sweep_has_a_line_per_level_in_order() {
        use crate::experiments::noise_sweep::tests::agreement;
        let sweep = [
            (0.5, agreement([0.9123, 0.8], [0.95, 0.85])),
            (6.0, agreement([0.5, 0.4], [0.7, 0.6])),
        ];
        assert_eq!(
            noise_sweep_text(&sweep),
            "noise sweep (σ px: grand exact / κ, action level exact / κ):\n\
             \x20  0.5 px: 0.912 / 0.800, 0.950 / 0.850\n\
             \x20  6.0 px: 0.500 / 0.400, 0.700 / 0.600\n"
        );
    }

    #[test]
    fn the_detector_label_names_the_model_file_or_the_noise_and_the_filter() {
        assert_eq!(
            detector_label(None, 3.0, None),
            format!(
                "3 px, the controller's fixed lag of ±{} s",
                ergocell_cell::pipeline::DEFAULT_FIXED_LAG_S
            )
        );
        assert_eq!(
            detector_label(Some("mediapipe.toml"), 3.0, Some(0.0)),
            "detector mediapipe.toml, the causal filter (no fixed lag)"
        );
        assert_eq!(
            detector_label(None, 1.5, Some(0.25)),
            "1.5 px, a fixed-lag smoother of ±0.25 s"
        );
    }

    #[test]
    fn the_curves_file_is_commented_then_the_curves_read_back() {
        let rula = HandoverRula {
            statures_m: vec![1.5, 1.6],
            c1: vec![3.0, 3.25],
            c2: vec![3.5, 3.0],
            c3: vec![4.0, 3.5],
        };
        let text = handover_rula_file(&rula, 5, &[1, 2, 3, 4]).unwrap();
        let (header, body): (Vec<&str>, Vec<&str>) = text.lines().partition(|l| l.starts_with('#'));
        assert_eq!(header.len(), 6);
        assert!(
            text.starts_with(&header.join("\n")),
            "the header comes first"
        );
        assert!(header[2].contains("over 5 handover cycles and seeds 1, 2, 3, 4."));
        assert_eq!(
            header[5],
            "#   ergocell sim handover-rula --seeds 1..4 --out-dir trajectories"
        );
        let back: HandoverRula = toml::from_str(&body.join("\n")).unwrap();
        assert_eq!(back, rula);
    }
}
