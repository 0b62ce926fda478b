//! `ergocell sim warnings`: the operator's warnings on sessions of the station's tasks, measured by
//! `ergocell_sim::warning_trust` (the numbers and the goals are computed there; this reads the task
//! mix, prints the table and writes `warnings[_seeds].json` and the latency figure).

use std::path::PathBuf;

use anyhow::Context;
use ergocell_cell::PipelineConfig;
use ergocell_ergonomics::confidence::{ConfidenceModel, ANGLED_REGIONS};
use ergocell_ergonomics::UpVector;
use ergocell_sim::band_reliability::{self, Reliability, FIT_STRIDE, MIN_BIN_SAMPLES};
use ergocell_sim::experiments::Setup;
use ergocell_sim::report;
use ergocell_sim::tasks::{TaskMix, DEFAULT_MIX_NAME};
use ergocell_sim::warning_trust::{self, RegionWarnings, WarningTrustSeeds};
use indicatif::{ProgressBar, ProgressStyle};
use nalgebra::Vector3;

use super::sim::{
    detector_label, detector_noise, load_handovers, load_rig, print_goals, statures, write_figure,
    write_result, Common, SeedRange,
};
use super::UsageError;

/// The task mix of `--tasks`: the shipped one by name, or a file.
pub fn load_mix(spec: &str) -> anyhow::Result<TaskMix> {
    if spec == DEFAULT_MIX_NAME {
        return Ok(TaskMix::default_mix()?);
    }
    let path = PathBuf::from(spec);
    let text = ergocell::input::read_text(&path, ergocell::input::Kind::Config)?;
    TaskMix::from_toml_str(&text).map_err(|e| UsageError(format!("{}: {e}", path.display())).into())
}

/// `--transport-delay-ms` checked: a time of 0 to 10 s.
fn transport_delay_nanos(ms: f64) -> Result<i64, UsageError> {
    if ms.is_finite() && (0.0..=10_000.0).contains(&ms) {
        Ok((ms * 1e6).round() as i64)
    } else {
        Err(UsageError(format!(
            "--transport-delay-ms {ms}: must be a time of 0 to 10000 ms"
        )))
    }
}

fn pct(x: f64) -> String {
    if x.is_nan() {
        "    —".to_owned()
    } else {
        format!("{:5.1}", 100.0 * x)
    }
}

fn print_row(r: &RegionWarnings) {
    println!(
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

pub fn run(c: &Common) -> anyhow::Result<()> {
    let mix = load_mix(&c.tasks)?;
    let rig = load_rig(&c.cameras)?;
    let noise = detector_noise(c)?;
    noise.validate().map_err(|e| UsageError(e.to_string()))?;
    let handovers = load_handovers(c)?;
    let mut config = PipelineConfig::new(UpVector::new(Vector3::z())?);
    match c.fixed_lag_s {
        Some(0.0) => config.fixed_lag_s = None,
        Some(w) => config.fixed_lag_s = Some(w),
        None => {}
    }
    let (seeds, file_stem) = match &c.seeds {
        Some(SeedRange(s)) => (s.clone(), "warnings_seeds"),
        None => (vec![c.seed], "warnings"),
    };
    let operators = statures(c.operators.unwrap_or(20));
    let transport_delay_nanos = transport_delay_nanos(c.transport_delay_ms)?;
    std::fs::create_dir_all(&c.out_dir)
        .with_context(|| format!("creating {}", c.out_dir.display()))?;
    let pb = ProgressBar::new(seeds.len() as u64);
    if let Ok(style) = ProgressStyle::with_template("{msg} [{bar:30}] {pos}/{len} seeds {elapsed}")
    {
        pb.set_style(style);
    }
    pb.set_message("warnings");
    let mut runs = Vec::with_capacity(seeds.len());
    for &seed in &seeds {
        let setup = Setup {
            rig: rig.clone(),
            noise,
            seed,
        };
        runs.push(warning_trust::warning_trust(
            &setup,
            &handovers,
            &operators,
            &mix,
            &config,
            transport_delay_nanos,
            &mut |_, _| {},
        )?);
        pb.inc(1);
    }
    pb.finish_and_clear();
    let fitted = c.fit_confidence.then(|| {
        let samples: Vec<_> = runs
            .iter()
            .flat_map(|r| r.band_samples.iter().copied())
            .collect();
        let (model, counts) = band_reliability::fit(&samples, &config.assessment.confidence);
        (
            model,
            counts,
            band_reliability::read_error_rms_deg(&samples),
        )
    });
    let sum = warning_trust::over_seeds(&seeds, runs);
    if !c.json {
        print_summary(c, &sum, &mix);
        print_reliability(&sum.reliability);
        if let Some((model, counts, read_error)) = &fitted {
            print_fit(model, counts, read_error);
        }
    }
    let figure = write_figure(
        &c.out_dir,
        &report::warning_latency_figure(
            &format!("{file_stem}_latency.svg"),
            &sum,
            &detector_label(c),
        )?,
    )?;
    let setup_json = serde_json::json!({
        "seeds": seeds,
        "cameras": c.cameras,
        "camera_count": rig.len(),
        "noise": noise,
        "tasks": c.tasks,
        "mix": mix,
        "handovers_m": handovers,
        "operators_m": operators,
        "transport_delay_ms": c.transport_delay_ms,
        "confidence_model": config.assessment.confidence,
    });
    write_result(
        c,
        file_stem,
        serde_json::to_value(&sum)?,
        setup_json,
        &[figure],
    )
}

fn print_summary(c: &Common, sum: &WarningTrustSeeds, mix: &TaskMix) {
    println!(
        "Warnings over seeds {:?} with {}; tasks {} ({} handovers, {} tasks a session); {:.2} h of sessions",
        sum.seeds,
        detector_label(c),
        warning_trust::task_names(mix).join(", "),
        mix.handovers,
        mix.occurrences(),
        sum.hours
    );
    println!(
        "  {:<10} {:>6} {:>6} {:>6} {:>5} {:>6} {:>6} {:>5}",
        "region", "truth", "clear", "caught", "rec.%", "raised", "conf.", "prec.%"
    );
    for r in &sum.regions {
        print_row(r);
    }
    print_row(&sum.all);
    println!(
        "  unmatched warnings: {}, of which false (the truth's posture below the warned level): {} ({:.2} per hour); latency from the posture to the warning: p50 {:.2} s, p95 {:.2} s, max {:.2} s (goal p95 ≤ {:.2} s)",
        sum.unmatched_warnings,
        sum.false_warnings,
        sum.false_per_hour,
        sum.latency_p50_s,
        sum.latency_p95_s,
        sum.latency_max_s,
        sum.latency_bound_s
    );
    print_goals(&sum.goals);
}

/// The reliability table of the stated band probabilities, pooled over the seeds.
fn print_reliability(r: &Reliability) {
    println!(
        "  How sure the bands are: stated probability against the share right (region × side × frame at the station; judged from {MIN_BIN_SAMPLES} samples)"
    );
    println!(
        "  {:<9} {:>9} {:>7} {:>8}",
        "stated", "samples", "mean", "observed"
    );
    for b in &r.bins {
        if b.samples == 0 {
            continue;
        }
        println!(
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
    println!(
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
    println!("  band right, per region: {}", shares.join(", "));
}

/// The fitted confidence model, as `ConfidenceModel`'s default would hold it.
fn print_fit(model: &ConfidenceModel, counts: &[usize], read_error_deg: &[Option<f64>; 5]) {
    println!("  Confidence model fitted to these seeds (every {FIT_STRIDE}th sample):");
    for (i, region) in ANGLED_REGIONS.iter().enumerate() {
        let points: Vec<String> = model.recalibration[i]
            .iter()
            .map(|[m, s]| format!("[{m:.4}, {s:.4}]"))
            .collect();
        println!(
            "    {:<10} scale {:.2}, floor {:.2}° ({} samples, reading error RMS {}); recalibration [{}]",
            region.name(),
            model.scale[i],
            model.floor_rad[i].to_degrees(),
            counts[i],
            read_error_deg[i].map_or("—".to_owned(), |e| format!("{e:.2}°")),
            points.join(", ")
        );
    }
}
