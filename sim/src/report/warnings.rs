//! What `ergocell sim warnings` prints: the operator's warnings per body region over the seeds
//! (recall of the clear postures, precision, false warnings, latency, the goals), how sure the
//! stated band probabilities are (the reliability table) and, when asked for, the confidence model
//! fitted to the seeds' samples.
//!
//! The numbers are [`crate::warning_trust`]'s and [`crate::band_reliability`]'s; this only lays them
//! out, as text the binary prints (no I/O). A module of its own beside [`super`] because the
//! warnings' tables are the widest of the twin's reports.

use std::fmt::Write as _;

use ergocell_ergonomics::confidence::ANGLED_REGIONS;

use crate::band_reliability::{ConfidenceFit, Reliability, FIT_STRIDE, MIN_BIN_SAMPLES};
use crate::tasks::TaskMix;
use crate::warning_trust::{task_names, RegionWarnings, WarningTrustSeeds};

/// A share as a percentage in five columns, or a dash for none (NaN).
fn pct(x: f64) -> String {
    if x.is_nan() {
        "    —".to_owned()
    } else {
        format!("{:5.1}", 100.0 * x)
    }
}

/// One region's line of the warnings table.
fn region_row(out: &mut String, r: &RegionWarnings) {
    let _ = writeln!(
        out,
        "  {:<10} {:>6} {:>6} {:>6} {} {:>6} {:>6} {}",
        r.region,
        r.truth_raised,
        r.clear,
        r.clear_caught,
        pct(r.recall),
        r.raised,
        r.confirmed,
        pct(r.precision)
    );
}

/// The warnings over the seeds with `detector` (its label) on sessions of `mix`: what was run, the
/// table per region then all together, the unmatched and false warnings and the latency, and each
/// goal seed by seed.
pub fn summary_text(sum: &WarningTrustSeeds, detector: &str, mix: &TaskMix) -> String {
    let mut out = String::new();
    let _ = writeln!(
        out,
        "Warnings over seeds {:?} with {}; tasks {} ({} handovers, {} tasks a session); {:.2} h of sessions",
        sum.seeds,
        detector,
        task_names(mix).join(", "),
        mix.handovers,
        mix.occurrences(),
        sum.hours
    );
    let _ = writeln!(
        out,
        "  {:<10} {:>6} {:>6} {:>6} {:>5} {:>6} {:>6} {:>5}",
        "region", "truth", "clear", "caught", "rec.%", "raised", "conf.", "prec.%"
    );
    for r in sum.regions.iter().chain([&sum.all]) {
        region_row(&mut out, r);
    }
    let _ = writeln!(
        out,
        "  unmatched warnings: {}, of which false (the truth's posture below the warned level): {} ({:.2} per hour); latency from the posture to the warning: p50 {:.2} s, p95 {:.2} s, max {:.2} s (goal p95 ≤ {:.2} s)",
        sum.unmatched_warnings,
        sum.false_warnings,
        sum.false_per_hour,
        sum.latency_p50_s,
        sum.latency_p95_s,
        sum.latency_max_s,
        sum.latency_bound_s
    );
    out.push_str(&super::goals_text(&sum.goals));
    out
}

/// The reliability table of the stated band probabilities (pooled over the seeds): each bin with
/// samples, its mean stated probability against the share right and whether it is calibrated; the
/// samples stated at least 90 % sure; and the share right per angled region.
pub fn reliability_text(r: &Reliability) -> String {
    let mut out = String::new();
    let _ = writeln!(
        out,
        "  How sure the bands are: stated probability against the share right (region × side × frame at the station; judged from {MIN_BIN_SAMPLES} samples)"
    );
    let _ = writeln!(
        out,
        "  {:<9} {:>9} {:>7} {:>8}",
        "stated", "samples", "mean", "observed"
    );
    for b in r.bins.iter().filter(|b| b.samples > 0) {
        let _ = writeln!(
            out,
            "  {:.1}–{:.1}  {:>9} {:>7.3} {:>8.3}{}",
            b.lo,
            b.hi,
            b.samples,
            b.stated(),
            b.observed(),
            match b.calibrated() {
                Some(true) => "",
                Some(false) => "  off by more than 5 points",
                None => "  (too few to judge)",
            }
        );
    }
    let _ = writeln!(
        out,
        "  stated ≥ 90 % sure: {} samples, {:.1} % right",
        r.sure,
        100.0 * r.sure_share()
    );
    let shares: Vec<String> = ANGLED_REGIONS
        .iter()
        .zip(r.region_samples.iter().zip(&r.region_right))
        .map(|(region, (n, right))| {
            format!(
                "{} {:.1} %",
                region.name().replace('_', " "),
                100.0 * *right as f64 / *n as f64
            )
        })
        .collect();
    let _ = writeln!(out, "  band right, per region: {}", shares.join(", "));
    out
}

/// The confidence model fitted to the seeds' samples, region by region as `ConfidenceModel`'s
/// default holds it (scale, floor in degrees, recalibration points), with each region's samples
/// and reading error.
pub fn confidence_fit_text(fit: &ConfidenceFit) -> String {
    let mut out = String::new();
    let _ = writeln!(
        out,
        "  Confidence model fitted to these seeds (every {FIT_STRIDE}th sample):"
    );
    let model = &fit.model;
    for (i, region) in ANGLED_REGIONS.iter().enumerate() {
        let points: Vec<String> = model.recalibration[i]
            .iter()
            .map(|[m, s]| format!("[{m:.4}, {s:.4}]"))
            .collect();
        let _ = writeln!(
            out,
            "    {:<10} scale {:.2}, floor {:.2}° ({} samples, reading error RMS {}); recalibration [{}]",
            region.name(),
            model.scale[i],
            model.floor_rad[i].to_degrees(),
            fit.counts.get(i).copied().unwrap_or(0),
            fit.read_error_rms_deg[i].map_or("—".to_owned(), |e| format!("{e:.2}°")),
            points.join(", ")
        );
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::band_reliability::fit_confidence;
    use crate::seeds::Goal;
    use ergocell_ergonomics::assess::BodyRegion;
    use ergocell_ergonomics::confidence::ConfidenceModel;

    fn region(
        name: &str,
        clear: usize,
        caught: usize,
        raised: usize,
        confirmed: usize,
    ) -> RegionWarnings {
        RegionWarnings {
            region: name.to_owned(),
            truth_raised: clear,
            clear,
            clear_caught: caught,
            recall: if clear > 0 {
                caught as f64 / clear as f64
            } else {
                f64::NAN
            },
            raised,
            confirmed,
            precision: confirmed as f64 / raised as f64,
            latencies_s: Vec::new(),
        }
    }

    #[test]
    fn a_share_is_a_percentage_or_a_dash() {
        assert_eq!(pct(0.953), " 95.3");
        assert_eq!(pct(1.0), "100.0");
        assert_eq!(pct(f64::NAN), "    —");
    }

    #[test]
    fn the_summary_has_a_row_per_region_then_all_then_the_goals() {
        let sum = WarningTrustSeeds {
            seeds: vec![301, 302],
            regions: vec![region("neck", 20, 19, 25, 24), region("legs", 0, 0, 0, 0)],
            all: region("all", 20, 19, 25, 24),
            unmatched_warnings: 1,
            false_warnings: 0,
            false_per_hour: 0.0,
            hours: 1.234,
            latency_p50_s: 1.0,
            latency_p95_s: 2.0,
            latency_max_s: 3.0,
            latency_bound_s: 2.55,
            goals: vec![Goal {
                goal: "precision ≥ 90 %".to_owned(),
                holds_on: 2,
                seeds: 2,
                fails: Vec::new(),
            }],
            reliability: Reliability::default(),
            per_seed: Vec::new(),
        };
        let mix = TaskMix::default_mix().unwrap();
        let text = summary_text(&sum, "3 px", &mix);
        let lines: Vec<&str> = text.lines().collect();
        assert!(lines[0].starts_with("Warnings over seeds [301, 302] with 3 px; tasks "));
        assert!(lines[0].ends_with("; 1.23 h of sessions"), "{}", lines[0]);
        assert_eq!(lines.len(), 7);
        assert_eq!(
            lines[2],
            "  neck           20     20     19  95.0     25     24  96.0"
        );
        // a region without a clear posture or a warning: dashes, not NaN
        assert_eq!(
            lines[3],
            "  legs            0      0      0     —      0      0     —"
        );
        assert!(lines[4].starts_with("  all "));
        assert!(lines[5].contains("p95 2.00 s, max 3.00 s (goal p95 ≤ 2.55 s)"));
        assert_eq!(lines[6], "goal: precision ≥ 90 % — holds on 2 of 2 seeds");
    }

    #[test]
    fn the_reliability_table_skips_empty_bins_and_says_which_are_judged() {
        let mut r = Reliability::default();
        for k in 0..600 {
            r.add(BodyRegion::Neck, 0.95, k < 540);
        }
        for k in 0..10 {
            r.add(BodyRegion::Trunk, 0.35, k < 5);
        }
        let text = reliability_text(&r);
        let lines: Vec<&str> = text.lines().collect();
        // title, header, two bins with samples, the sure line, the regions
        assert_eq!(lines.len(), 6, "{text}");
        assert_eq!(
            lines[2],
            "  0.3–0.4         10   0.350    0.500  (too few to judge)"
        );
        assert_eq!(lines[3], "  0.9–1.0        600   0.950    0.900");
        assert_eq!(lines[4], "  stated ≥ 90 % sure: 600 samples, 90.0 % right");
        assert!(
            lines[5].contains("neck 90.0 %, trunk 50.0 %"),
            "{}",
            lines[5]
        );
        // a region without samples has no share to state
        assert!(lines[5].starts_with("  band right, per region: upper arm NaN %"));
    }

    #[test]
    fn the_fit_states_the_floor_in_degrees_and_a_dash_without_samples() {
        let mut start = ConfidenceModel::default();
        start.floor_rad[0] = 2.5f64.to_radians();
        let text = confidence_fit_text(&fit_confidence(&[], &start));
        let lines: Vec<&str> = text.lines().collect();
        assert_eq!(lines.len(), 1 + ANGLED_REGIONS.len());
        assert!(lines[0].contains(&format!("every {FIT_STRIDE}th sample")));
        assert!(
            lines[1].contains("floor 2.50° (0 samples, reading error RMS —)"),
            "{}",
            lines[1]
        );
        assert_eq!(
            lines[1].matches("], [").count(),
            8,
            "nine recalibration points"
        );
    }
}
