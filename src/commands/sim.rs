//! `ergocell sim`: the seed paper's experiments on the digital twin (`ergocell_sim`).
//!
//! ```text
//! ergocell sim table1|adaptation|height|rula-agreement [--seed 1] [--cameras config/rig.toml | N]
//!              [--noise-px 3] [--json] [--out-dir sim-out] [--cell config/cell.toml]
//!              [--trajectories trajectories] [--operators N] [--cycles N]
//!              [--before-handover 0.410,-0.100,1.055]
//! ```
//!
//! Each experiment prints a table (or, with `--json`, one JSON object on stdout) and writes
//! `<experiment>.json` and its SVG figures into `--out-dir`. The same seed gives byte-identical JSON.
//! The runs, tables and figures are `ergocell_sim::runs`' and `ergocell_sim::report`'s; this module
//! reads the inputs, shows the progress and writes what they return.
//! The handover points come from `trajectories/c1..c3.toml` (station frame) placed in the world with
//! `config/cell.toml`'s `[station]`. "Before adaptation" is one point for everyone, set for a 1.75 m
//! operator: (0.410, −0.100, 1.055) m, the middle of the Grandjean band (upper arm 10–15°) for c2's
//! statures, which was c2's handover until c2 moved to its band's top edge. It is
//! fixed here so that moving a class's point does not move the baseline it is compared with.

use std::io::Write;
use std::path::{Path, PathBuf};

use anyhow::Context;
use ergocell_formats::rig_file::parse_rig;
use ergocell_perception::detector_error::DetectorErrorReport;
use ergocell_perception::CameraRig;
use ergocell_robot::{CellConfig, TrajectoryClass, TrajectoryLayout, TrajectorySpec};
use ergocell_sim::cameras::check_z_up;
use ergocell_sim::detector_fit::{DetectorModel, FitSettings};
use ergocell_sim::experiments::{Handovers, HeightOptions};
use ergocell_sim::report::{self, Figure, Report};
use ergocell_sim::runs;
use ergocell_sim::{ring_rig, DetectorNoise, RingRigConfig};
use indicatif::{ProgressBar, ProgressStyle};

use super::UsageError;
use ergocell::session::provider::HANDOVER_RULA_FILE;

/// Arguments of `ergocell sim`.
#[derive(Debug, clap::Args)]
pub struct Args {
    #[command(subcommand)]
    pub experiment: Experiment,
    #[command(flatten)]
    pub common: Common,
}

/// The experiments.
#[derive(Debug, Clone, Copy, clap::Subcommand)]
pub enum Experiment {
    /// The paper's Table 1: RMSE of 12 landmarks per stereo pair, paper fusion, default fusion.
    Table1,
    /// The paper's Figs. 7–9: RULA per height before and after the class-specific handover.
    Adaptation,
    /// Stature and height class from the noisy cameras for a population of operators.
    Height,
    /// Per-frame RULA agreement (exact and Cohen's κ), noisy pipeline vs ground truth.
    RulaAgreement,
    /// The operator's warnings on sessions of the station's tasks (`--tasks`): recall of the
    /// postures that clearly deserve a warning, precision, false warnings per hour and the latency
    /// from the posture to the warning, per body region, the controller's pipeline vs the truth.
    Warnings,
    /// Each class's RULA-versus-stature curve at its handover point (the truth, averaged over the
    /// seeds of `--seeds`, default 1..4): writes `handover_rula.toml` into `--out-dir`, the data the
    /// height decision reads from the trajectories folder.
    HandoverRula,
    /// Fit the twin's pose-estimator model to a real detector measured view against view (`--real`,
    /// written by `triangulate --detector-error` on the same cameras, `--cameras`): fits on `--seed`,
    /// reports on `--seeds` (default 101..120), writes `detector.toml` and `detector_fit.json`.
    FitDetector,
}

/// Whose bodies the adaptation experiment's operators have (`--bodies`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum Bodies {
    Proportions,
    Measured,
}

impl From<Bodies> for runs::Bodies {
    fn from(bodies: Bodies) -> Self {
        match bodies {
            Bodies::Proportions => runs::Bodies::Proportions,
            Bodies::Measured => runs::Bodies::Measured,
        }
    }
}

/// Options every experiment takes.
#[derive(Debug, clap::Args)]
pub struct Common {
    /// Seed of every random draw: the same seed gives byte-identical JSON.
    #[arg(long, global = true, default_value_t = 1)]
    pub seed: u64,
    /// Run the experiment once per seed of `A..B` (both included) or of `1..N` for a count `N`, and
    /// report each quantity's mean, standard deviation and worst seed and on how many seeds each
    /// goal holds: `<experiment>_seeds.json` and `<experiment>_seeds*.svg`. Overrides `--seed`.
    #[arg(long, global = true, value_parser = parse_seed_range)]
    pub seeds: Option<SeedRange>,
    /// The camera rig: a calibration file (world z up, floor z = 0) or a number of cameras placed in
    /// stereo pairs around the station.
    #[arg(long, global = true, default_value = "config/rig.toml")]
    pub cameras: String,
    /// Pixel noise σ of the simulated pose estimator, pixels.
    #[arg(long, global = true, default_value_t = 3.0)]
    pub noise_px: f64,
    /// The simulated pose estimator: a model fitted to a real detector (`sim fit-detector`'s
    /// `detector.toml`, e.g. `sim/detectors/mediapipe-pose2sim.toml`) in place of `--noise-px`'s
    /// independent pixel noise.
    #[arg(long, global = true)]
    pub detector: Option<PathBuf>,
    /// fit-detector: the real detector's error (`triangulate --detector-error`'s JSON).
    #[arg(long, global = true)]
    pub real: Option<PathBuf>,
    /// fit-detector: every landmark's persistent offset its own (no offset shared by a view's
    /// landmarks), as the first fitted model had it.
    #[arg(long, global = true)]
    pub independent_offsets: bool,
    /// fit-detector: how alike two cameras' offsets are by the angle between them, degrees (0:
    /// independent). A rig of cameras far apart cannot measure it.
    #[arg(long, global = true, default_value_t = 0.0)]
    pub view_correlation_deg: f64,
    /// rula-agreement: the controller's fixed-lag smoother with this many seconds either side
    /// (`[pipeline] fixed_lag_s`, default 0.55: each frame scored on the fused skeleton's mean over
    /// the window centred on it, at that latency); 0: the causal One-Euro filter instead.
    #[arg(long, global = true, value_name = "SECONDS")]
    pub fixed_lag_s: Option<f64>,
    /// warnings: the task mix, a TOML file (`sim/tasks/default.toml` documents the format) or
    /// `default` for the shipped one.
    #[arg(long, global = true, default_value = ergocell_sim::tasks::DEFAULT_MIX_NAME)]
    pub tasks: String,
    /// warnings: also fit the confidence model (each region's scale and floor of its angle's
    /// stated spread) to these seeds' samples and print it. Fit on tuning seeds only.
    #[arg(long, global = true)]
    pub fit_confidence: bool,
    /// Print the numbers as one JSON object on stdout instead of a table.
    #[arg(long, global = true)]
    pub json: bool,
    /// Where `<experiment>.json` and the figures (SVG) are written.
    #[arg(long, global = true, default_value = "sim-out")]
    pub out_dir: PathBuf,
    /// Cell configuration (the operator station's place in the world).
    #[arg(long, global = true, default_value = "config/cell.toml")]
    pub cell: PathBuf,
    /// Folder with the class trajectories `c1.toml`, `c2.toml`, `c3.toml`.
    #[arg(long, global = true, default_value = TrajectoryLayout::DEFAULT_DIR)]
    pub trajectories: PathBuf,
    /// Operators to simulate (default per experiment: table1 5, height 60, rula-agreement 6).
    #[arg(long, global = true)]
    pub operators: Option<usize>,
    /// Handover cycles per operator (default 5).
    #[arg(long, global = true, default_value_t = 5)]
    pub cycles: usize,
    /// The handover point before adaptation, station frame `forward,lateral,height` (metres); also
    /// where the operators of `height` and `rula-agreement` stand and reach. Default: the point the
    /// cell used for everyone, set for a 1.75 m operator.
    #[arg(long, global = true, value_parser = parse_point, default_value = BEFORE_HANDOVER)]
    pub before_handover: [f64; 3],
    /// adaptation: whose bodies the operators have: `proportions`, Drillis & Contini's proportions
    /// at exactly the height (the robot's planning model and the paper's protocol); or `measured`,
    /// at each height one of ANSUR II's reporting half (people never fitted) within 1 cm, drawn by
    /// the seed: real bodies, which differ more than the seeds' habits. Only `adaptation` reads it;
    /// `--record-height` records an operator of the proportions.
    #[arg(long, global = true, value_enum, default_value_t = Bodies::Proportions)]
    pub bodies: Bodies,
    /// adaptation: also record an operator of this stature (metres) before and after as two session
    /// recordings, `adaptation_<h>m_before.mcap` / `_after.mcap` in `--out-dir`, for
    /// `ergocell report <before> --compare <after>`.
    #[arg(long, global = true)]
    pub record_height: Option<f64>,
    /// height: calibration sessions (people of the fitting half of ANSUR II) before the operators,
    /// as `ergocell height calibrate` runs them; 0 = an uncalibrated cell.
    #[arg(long, global = true, default_value_t = 5)]
    pub calibration_sessions: usize,
    /// height: how far above the tragion the simulated detector puts the ear landmarks, metres.
    #[arg(long, global = true, default_value_t = 0.0, allow_hyphen_values = true)]
    pub ear_offset_m: f64,
    /// height: the decision interval's half-width in σ (default: the cell's, 2); wider trades
    /// confident mistakes for more operators decided across a boundary.
    #[arg(long, global = true)]
    pub decision_sigmas: Option<f64>,
    /// warnings: how long after its capture each frame's views reach the cell, milliseconds (the
    /// edge's inference and the network); the fixed lag's frames are released on the clock, so the
    /// newest of that time's frames (up to 0.1 s of them) are left out of each window.
    #[arg(long, global = true, default_value_t = 0.0)]
    pub transport_delay_ms: f64,
}

/// The seeds of `--seeds`.
#[derive(Debug, Clone)]
pub struct SeedRange(pub Vec<u64>);

fn parse_seed_range(text: &str) -> Result<SeedRange, ergocell_sim::seeds::BadSeeds> {
    ergocell_sim::seeds::parse_seeds(text).map(SeedRange)
}

pub(super) fn load_rig(spec: &str) -> anyhow::Result<CameraRig> {
    if let Ok(count) = spec.parse::<usize>() {
        return ring_rig(count, &RingRigConfig::default())
            .map_err(|e| UsageError(e.to_string()).into());
    }
    let path = PathBuf::from(spec);
    let (text, label) = ergocell::shipped::read_or_shipped(&path)?;
    let (rig, _) = parse_rig(&text, &label).map_err(|e| UsageError(e.to_string()))?;
    check_z_up(&rig).map_err(|e| UsageError(format!("{spec}: {e}")))?;
    Ok(rig)
}

/// The simulated detector: `--detector`'s fitted model, or `--noise-px`'s independent noise; the
/// ear offset of `--ear-offset-m` either way.
pub(super) fn detector_noise(c: &Common) -> anyhow::Result<DetectorNoise> {
    let base = DetectorNoise {
        pixel_sigma_px: c.noise_px,
        ear_offset_m: c.ear_offset_m,
        ..DetectorNoise::default()
    };
    let Some(path) = &c.detector else {
        return Ok(base);
    };
    let text = ergocell::input::read_text(path, ergocell::input::Kind::Config)?;
    let model = DetectorModel::from_toml_str(&text)
        .map_err(|e| UsageError(format!("{}: {e}", path.display())))?;
    Ok(model.apply(base))
}

/// The simulated detector in words, for titles (`ergocell_sim::report::detector_label`): `3 px` or
/// the model file's name, and the filter.
pub(super) fn detector_label(c: &Common) -> String {
    let file = c.detector.as_ref().map(|path| {
        path.file_name().map_or_else(
            || path.display().to_string(),
            |n| n.to_string_lossy().into_owned(),
        )
    });
    report::detector_label(file.as_deref(), c.noise_px, c.fixed_lag_s)
}

/// `--real`: the real detector's error, as `triangulate --detector-error` measured it.
fn read_real(c: &Common) -> anyhow::Result<(&Path, DetectorErrorReport)> {
    let Some(real_path) = &c.real else {
        return Err(UsageError(
            "fit-detector needs --real <detector-error.json> (from `triangulate --detector-error` on the same cameras)"
                .to_owned(),
        )
        .into());
    };
    let text = ergocell::input::read_text(real_path, ergocell::input::Kind::Data)?;
    let real = serde_json::from_str(&text)
        .map_err(|e| UsageError(format!("{}: {e}", real_path.display())))?;
    Ok((real_path.as_path(), real))
}

/// `sim fit-detector`: the twin's detector fitted to `--real` on `--cameras`
/// (`ergocell_sim::runs::DetectorFitRun`), reported on other seeds beside the independent noise.
fn run_fit_detector(c: &Common) -> anyhow::Result<()> {
    let (real_path, real) = read_real(c)?;
    let rig = load_rig(&c.cameras)?;
    let fit = runs::DetectorFitRun {
        real: &real,
        real_path,
        rig: &rig,
        cameras: &c.cameras,
        settings: FitSettings {
            view_shift: !c.independent_offsets,
            view_correlation_deg: c.view_correlation_deg,
            ..FitSettings::default()
        },
        seed: c.seed,
        report_seeds: c.seeds.as_ref().map(|s| s.0.as_slice()),
        noise_px: c.noise_px,
    };
    let pb = progress_bar("fit-detector");
    let fitted = fit.run().map_err(|e| -> anyhow::Error {
        if e.is_bad_input() {
            UsageError(e.to_string()).into()
        } else {
            e.into()
        }
    })?;
    pb.finish_and_clear();
    if !c.json {
        print!("{}", fitted.text);
    }
    create_out_dir(c)?;
    let model_path = c.out_dir.join("detector.toml");
    super::output::replace(&model_path, fitted.model_toml.as_bytes())?;
    println!("wrote {}", model_path.display());
    write_result(c, "detector_fit", fitted.record, fitted.setup, &[])
}

/// The unadapted cell's one handover point, station frame `forward,lateral,height` (metres): the
/// twin's "before" and the point `trajectories design` asks c1's and c3's points to improve on.
pub(crate) const BEFORE_HANDOVER: &str = "0.410,-0.100,1.055";

/// `forward,lateral,height` in metres, three finite numbers.
pub(crate) fn parse_point(text: &str) -> Result<[f64; 3], String> {
    let values: Vec<f64> = text
        .split(',')
        .map(|v| v.trim().parse::<f64>().map_err(|e| format!("{v:?}: {e}")))
        .collect::<Result<_, _>>()?;
    match values.as_slice() {
        [f, l, h] if values.iter().all(|v| v.is_finite()) => Ok([*f, *l, *h]),
        _ => Err(format!(
            "expected three finite numbers forward,lateral,height (metres), got {text:?}"
        )),
    }
}

/// The handover points of `--cell`'s station and `--trajectories`' classes, with
/// `--before-handover` (see `Handovers::from_cell`).
pub(super) fn load_handovers(common: &Common) -> anyhow::Result<Handovers> {
    let (cell_text, cell_label) = ergocell::shipped::read_or_shipped(&common.cell)?;
    let cell = CellConfig::from_toml_str(&cell_text)
        .map_err(|e| UsageError(format!("{cell_label}: {e}")))?;
    let layout = TrajectoryLayout::new(&common.trajectories);
    let spec =
        |class: TrajectoryClass| -> anyhow::Result<TrajectorySpec> {
            let (text, label) = ergocell::shipped::read_or_shipped(&layout.spec(class))?;
            Ok(TrajectorySpec::from_toml_str(&text)
                .map_err(|e| UsageError(format!("{label}: {e}")))?)
        };
    // One file after the other, in class order: the first that fails is the one reported.
    let [c1, c2, c3] = TrajectoryClass::ALL;
    let specs = [spec(c1)?, spec(c2)?, spec(c3)?];
    Ok(Handovers::from_cell(&cell, &specs, common.before_handover))
}

/// The height experiment's options (`ergocell_sim::runs::height_options`), with the classes' curves
/// as the cell reads them (the approvals crate's provider).
fn height_options(c: &Common) -> anyhow::Result<HeightOptions> {
    let rula = ergocell::session::provider::on_disk(
        &c.cell,
        &c.trajectories,
        &c.trajectories.join("approvals"),
    )
    .handover_rula()
    .map_err(|e| UsageError(e.to_string()))?;
    runs::height_options(c.operators, c.calibration_sessions, rula, c.decision_sigmas)
        .map_err(|e| UsageError(format!("--decision-sigmas {e}")).into())
}

/// `sim handover-rula`: each class's RULA curve over `--seeds` (default 1..4), written as
/// `handover_rula.toml` (and its figure, unless `--json`) into `--out-dir`.
fn run_handover_rula(c: &Common) -> anyhow::Result<()> {
    let seeds = c.seeds.as_ref().map(|s| s.0.as_slice());
    let rig = load_rig(&c.cameras)?;
    let handovers = load_handovers(c)?;
    let pb = progress_bar("handover_rula");
    let (rula, text) = runs::handover_rula(&rig, &handovers, c.cycles, seeds, &mut tick(&pb))?;
    pb.finish_and_clear();
    create_out_dir(c)?;
    let path = c.out_dir.join(HANDOVER_RULA_FILE);
    std::fs::write(&path, text).with_context(|| format!("writing {}", path.display()))?;
    if !c.json {
        let plot = write_figure(&c.out_dir, &report::handover_rula_figure(&rula)?)?;
        println!("wrote {}", path.display());
        println!("wrote {}", plot.display());
    }
    Ok(())
}

/// `--out-dir`, made if it is not there.
fn create_out_dir(c: &Common) -> anyhow::Result<()> {
    std::fs::create_dir_all(&c.out_dir).with_context(|| format!("creating {}", c.out_dir.display()))
}

pub(super) fn progress_bar(what: &str) -> ProgressBar {
    let pb = ProgressBar::new(0);
    if let Ok(style) =
        ProgressStyle::with_template("{msg} [{bar:30}] {pos}/{len} sessions {elapsed}")
    {
        pb.set_style(style);
    }
    pb.set_message(what.to_owned());
    pb
}

/// A progress bar of `what` over `n` seeds.
pub(super) fn seeds_bar(what: &str, n: usize) -> ProgressBar {
    let pb = ProgressBar::new(n as u64);
    if let Ok(style) = ProgressStyle::with_template("{msg} [{bar:30}] {pos}/{len} seeds {elapsed}")
    {
        pb.set_style(style);
    }
    pb.set_message(what.to_owned());
    pb
}

/// The progress callback that shows `(done, total)` on `pb`.
fn tick(pb: &ProgressBar) -> impl FnMut(usize, usize) + '_ {
    move |done, total| {
        pb.set_length(total as u64);
        pb.set_position(done as u64);
    }
}

pub fn run(args: &Args) -> anyhow::Result<()> {
    check(args)?;
    let c = &args.common;
    match args.experiment {
        Experiment::HandoverRula => run_handover_rula(c),
        Experiment::FitDetector => run_fit_detector(c),
        Experiment::Warnings => super::sim_warnings::run(c),
        Experiment::Table1 => run_paper(c, |_| Ok(runs::Experiment::Table1)),
        Experiment::Adaptation => run_paper(c, |c| {
            Ok(runs::Experiment::Adaptation {
                bodies: c.bodies.into(),
            })
        }),
        Experiment::Height => run_paper(c, |c| Ok(runs::Experiment::Height(height_options(c)?))),
        Experiment::RulaAgreement => run_paper(c, |c| {
            Ok(runs::Experiment::RulaAgreement {
                fixed_lag_s: c.fixed_lag_s,
                detector_label: detector_label(c),
            })
        }),
    }
}

/// The options that apply to some experiments only, and their ranges: usage errors, found before
/// anything runs (an experiment takes a while).
fn check(args: &Args) -> anyhow::Result<()> {
    let c = &args.common;
    let warnings = matches!(args.experiment, Experiment::Warnings);
    if !(c.noise_px.is_finite() && c.noise_px >= 0.0) {
        return Err(
            UsageError(format!("--noise-px {} must be finite and >= 0", c.noise_px)).into(),
        );
    }
    if c.transport_delay_ms != 0.0 && !warnings {
        return Err(UsageError("--transport-delay-ms applies to warnings only".to_owned()).into());
    }
    if c.fit_confidence && !warnings {
        return Err(UsageError("--fit-confidence applies to warnings only".to_owned()).into());
    }
    if let Some(w) = c.fixed_lag_s {
        if !(warnings || matches!(args.experiment, Experiment::RulaAgreement)) {
            return Err(UsageError(
                "--fixed-lag-s applies to rula-agreement and warnings only".to_owned(),
            )
            .into());
        }
        if w != 0.0 {
            ergocell_perception::fixed_lag::half_window_nanos(w)
                .map_err(|e| UsageError(format!("--fixed-lag-s: {e} (0: the causal filter)")))?;
        }
    }
    if let Some(h) = c.record_height {
        if !matches!(args.experiment, Experiment::Adaptation) || c.seeds.is_some() {
            return Err(UsageError(
                "--record-height applies to adaptation on one seed only".to_owned(),
            )
            .into());
        }
        if !(1.3..=2.2).contains(&h) {
            return Err(UsageError(format!("--record-height {h} is outside 1.3..=2.2 m")).into());
        }
    }
    Ok(())
}

/// One of the paper's experiments (`ergocell_sim::runs`) on `--seed`, or on every seed of `--seeds`
/// summarised: its table (unless `--json`), `<experiment>[_seeds].json` and its figures; with
/// `--record-height`, that operator's two recordings.
fn run_paper(
    c: &Common,
    experiment: impl FnOnce(&Common) -> anyhow::Result<runs::Experiment>,
) -> anyhow::Result<()> {
    let rig = load_rig(&c.cameras)?;
    let noise = detector_noise(c)?;
    noise.validate().map_err(|e| UsageError(e.to_string()))?;
    let handovers = load_handovers(c)?;
    create_out_dir(c)?;
    let run = runs::Run {
        experiment: experiment(c)?,
        rig,
        noise,
        handovers,
        cameras: c.cameras.clone(),
        operators: c.operators,
        cycles: c.cycles,
    };
    let name = run.experiment.name();
    let (outcome, file_stem) = if let Some(SeedRange(seeds)) = &c.seeds {
        let pb = seeds_bar(name, seeds.len());
        let outcome = run.over_seeds(seeds, &mut tick(&pb))?;
        pb.finish_and_clear();
        (outcome, format!("{name}_seeds"))
    } else {
        let pb = progress_bar(name);
        let outcome = run.one(c.seed, &mut tick(&pb))?;
        pb.finish_and_clear();
        if let Some(height) = c.record_height {
            record(&run, c, height)?;
        }
        (outcome, name.to_owned())
    };
    let figures = show(c, &outcome.report)?;
    write_result(c, &file_stem, outcome.value, outcome.setup, &figures)
}

/// `--record-height`: an operator of that stature recorded before and after adaptation
/// (`ergocell::sim_record`), the two recordings named on standard error.
fn record(run: &runs::Run, c: &Common, height: f64) -> anyhow::Result<()> {
    let setup = run.setup(c.seed);
    let [before, after] =
        ergocell::sim_record::record_both(&setup, &run.handovers, height, c.cycles, &c.out_dir)?;
    eprintln!(
        "recorded {} and {}: ergocell report {} --compare {}",
        before.display(),
        after.display(),
        before.display(),
        after.display()
    );
    Ok(())
}

/// Adds `setup` to `doc`, writes `<file_stem>.json` into `--out-dir` and prints the JSON (`--json`)
/// or the files written.
pub(super) fn write_result(
    c: &Common,
    file_stem: &str,
    mut doc: serde_json::Value,
    setup: serde_json::Value,
    figures: &[PathBuf],
) -> anyhow::Result<()> {
    if let Some(obj) = doc.as_object_mut() {
        obj.insert("setup".into(), setup);
    }
    let text = serde_json::to_string(&doc)?;
    let json_path = c.out_dir.join(format!("{file_stem}.json"));
    std::fs::write(&json_path, format!("{text}\n"))
        .with_context(|| format!("writing {}", json_path.display()))?;
    if c.json {
        // A closed pipe (`| head`) is not an error worth a panic.
        let mut out = std::io::stdout().lock();
        if let Err(e) = writeln!(out, "{text}") {
            if e.kind() != std::io::ErrorKind::BrokenPipe {
                return Err(e).context("writing to stdout");
            }
        }
    } else {
        println!("wrote {}", json_path.display());
        for f in figures {
            println!("wrote {}", f.display());
        }
    }
    Ok(())
}

/// Prints `report`'s text (unless `--json`) and writes its figures into `--out-dir`: the paths.
pub(super) fn show(c: &Common, report: &Report) -> anyhow::Result<Vec<PathBuf>> {
    if !c.json {
        print!("{}", report.text);
    }
    report
        .figures
        .iter()
        .map(|f| write_figure(&c.out_dir, f))
        .collect()
}

/// Writes `figure` into `dir` under its own name: the path.
pub(super) fn write_figure(dir: &Path, figure: &Figure) -> anyhow::Result<PathBuf> {
    let path = dir.join(&figure.file_name);
    std::fs::write(&path, &figure.svg).with_context(|| format!("writing {}", path.display()))?;
    Ok(path)
}
