//! `ergocell sim warnings`: the operator's warnings on sessions of the station's tasks, measured by
//! `ergocell_sim::warning_trust` (the numbers and the goals are computed there, the tables laid out
//! by `ergocell_sim::report::warnings`; this reads the task mix, runs the seeds, prints the tables
//! and writes `warnings[_seeds].json` and the latency figure).

use std::path::PathBuf;

use anyhow::Context;
use ergocell_cell::PipelineConfig;
use ergocell_sim::band_reliability::{self, ConfidenceFit};
use ergocell_sim::experiments::{self, Handovers, Setup};
use ergocell_sim::report;
use ergocell_sim::tasks::{TaskMix, DEFAULT_MIX_NAME};
use ergocell_sim::warning_trust::{self, WarningTrust};
use ergocell_sim::DetectorNoise;

use super::sim::{
    detector_label, detector_noise, load_handovers, load_rig, seeds_bar, write_figure,
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

/// What every seed's sessions run on.
struct Sessions {
    mix: TaskMix,
    rig: ergocell_perception::CameraRig,
    noise: DetectorNoise,
    handovers: Handovers,
    config: PipelineConfig,
    operators: Vec<f64>,
    transport_delay_nanos: i64,
}

/// Reads and checks what the sessions run on (`--tasks`, `--cameras`, the detector, the handover
/// points, `--fixed-lag-s`, `--operators`, `--transport-delay-ms`).
fn sessions(c: &Common) -> anyhow::Result<Sessions> {
    let mix = load_mix(&c.tasks)?;
    let rig = load_rig(&c.cameras)?;
    let noise = detector_noise(c)?;
    noise.validate().map_err(|e| UsageError(e.to_string()))?;
    let handovers = load_handovers(c)?;
    let config = warning_trust::pipeline_config(c.fixed_lag_s)?;
    let transport_delay_nanos = warning_trust::transport_delay_nanos(c.transport_delay_ms)
        .map_err(|e| UsageError(format!("--transport-delay-ms {e}")))?;
    Ok(Sessions {
        mix,
        rig,
        noise,
        handovers,
        config,
        operators: experiments::operator_statures(c.operators.unwrap_or(20)),
        transport_delay_nanos,
    })
}

/// Each seed's sessions measured, with a progress bar.
fn run_each(s: &Sessions, seeds: &[u64]) -> anyhow::Result<Vec<WarningTrust>> {
    let pb = seeds_bar("warnings", seeds.len());
    let mut runs = Vec::with_capacity(seeds.len());
    for &seed in seeds {
        let setup = Setup {
            rig: s.rig.clone(),
            noise: s.noise,
            seed,
        };
        runs.push(warning_trust::warning_trust(
            &setup,
            &s.handovers,
            &s.operators,
            &s.mix,
            &s.config,
            s.transport_delay_nanos,
            &mut |_, _| {},
        )?);
        pb.inc(1);
    }
    pb.finish_and_clear();
    Ok(runs)
}

pub fn run(c: &Common) -> anyhow::Result<()> {
    let s = sessions(c)?;
    let (seeds, file_stem) = match &c.seeds {
        Some(SeedRange(seeds)) => (seeds.clone(), "warnings_seeds"),
        None => (vec![c.seed], "warnings"),
    };
    std::fs::create_dir_all(&c.out_dir)
        .with_context(|| format!("creating {}", c.out_dir.display()))?;
    let runs = run_each(&s, &seeds)?;
    let fitted: Option<ConfidenceFit> = c.fit_confidence.then(|| {
        let samples: Vec<_> = runs
            .iter()
            .flat_map(|r| r.band_samples.iter().copied())
            .collect();
        band_reliability::fit_confidence(&samples, &s.config.assessment.confidence)
    });
    let sum = warning_trust::over_seeds(&seeds, runs);
    let label = detector_label(c);
    if !c.json {
        print!("{}", report::warnings::summary_text(&sum, &label, &s.mix));
        print!("{}", report::warnings::reliability_text(&sum.reliability));
        if let Some(fit) = &fitted {
            print!("{}", report::warnings::confidence_fit_text(fit));
        }
    }
    let latency =
        report::warning_latency_figure(&format!("{file_stem}_latency.svg"), &sum, &label)?;
    let figure = write_figure(&c.out_dir, &latency)?;
    let setup_json = serde_json::json!({
        "seeds": seeds,
        "cameras": c.cameras,
        "camera_count": s.rig.len(),
        "noise": s.noise,
        "tasks": c.tasks,
        "mix": s.mix,
        "handovers_m": s.handovers,
        "operators_m": s.operators,
        "transport_delay_ms": c.transport_delay_ms,
        "confidence_model": s.config.assessment.confidence,
    });
    write_result(
        c,
        file_stem,
        serde_json::to_value(&sum)?,
        setup_json,
        &[figure],
    )
}
