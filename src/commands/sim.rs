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
//! The tables and figures are `ergocell_sim::report`'s; this module runs the experiments and writes
//! what it returns.
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
use ergocell_sim::detector_fit::{self, DetectorModel, FitSettings};
use ergocell_sim::experiments::{
    self, noise_sweep, operator_statures, Handovers, HeightOptions, Setup,
};
use ergocell_sim::report::{self, Figure, Report};
use ergocell_sim::seeds;
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

impl Experiment {
    fn name(self) -> &'static str {
        match self {
            Experiment::Table1 => "table1",
            Experiment::Adaptation => "adaptation",
            Experiment::Height => "height",
            Experiment::RulaAgreement => "rula_agreement",
            Experiment::Warnings => "warnings",
            Experiment::HandoverRula => "handover_rula",
            Experiment::FitDetector => "detector_fit",
        }
    }
}

/// Whose bodies the adaptation experiment's operators have (`--bodies`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum Bodies {
    Proportions,
    Measured,
}

/// The people `--bodies` stands the adaptation's operators for: ANSUR II's reporting half for
/// `measured`, nobody for `proportions`.
fn adaptation_people(bodies: Bodies) -> anyhow::Result<Vec<ergocell_anthropometry::ansur::Person>> {
    Ok(match bodies {
        Bodies::Measured => ergocell_anthropometry::ansur::people()?
            .into_iter()
            .filter(|p| p.split() == ergocell_anthropometry::ansur::Split::Report)
            .collect(),
        Bodies::Proportions => Vec::new(),
    })
}

fn adaptation_bodies(
    bodies: Bodies,
    people: &[ergocell_anthropometry::ansur::Person],
) -> experiments::AdaptationBodies<'_> {
    match bodies {
        Bodies::Measured => experiments::AdaptationBodies::Measured(people),
        Bodies::Proportions => experiments::AdaptationBodies::Proportions,
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

/// `sim fit-detector`: the twin's detector fitted to `--real` on `--cameras` (see
/// `ergocell_sim::detector_fit`), reported on other seeds beside the default independent noise.
fn run_fit_detector(c: &Common) -> anyhow::Result<()> {
    let (real_path, real) = read_real(c)?;
    let rig = load_rig(&c.cameras)?;
    let settings = FitSettings {
        view_shift: !c.independent_offsets,
        view_correlation_deg: c.view_correlation_deg,
        ..FitSettings::default()
    };
    let report_seeds: Vec<u64> = c
        .seeds
        .as_ref()
        .map_or_else(|| (101..=120).collect(), |s| s.0.clone());
    let pb = progress_bar("fit-detector");
    let mut fit =
        detector_fit::fit(&real, &rig, &settings, c.seed).map_err(|e| UsageError(e.to_string()))?;
    let real_label = real_path.display().to_string();
    fit.model.fitted_to =
        detector_fit::fitted_to(&real_label, &real, &c.cameras, rig.len(), c.seed, &settings);
    let independent = DetectorNoise {
        pixel_sigma_px: c.noise_px,
        ..DetectorNoise::default()
    };
    let evaluation = detector_fit::evaluate(
        &real,
        &rig,
        &fit.model,
        &settings,
        &report_seeds,
        &independent,
    )?;
    pb.finish_and_clear();
    if !c.json {
        let text = report::detector_fit_text(&real_label, &real, &evaluation, c.seed, c.noise_px);
        print!("{text}");
    }
    std::fs::create_dir_all(&c.out_dir)
        .with_context(|| format!("creating {}", c.out_dir.display()))?;
    let model_path = c.out_dir.join("detector.toml");
    super::output::replace(&model_path, fit.model.to_toml()?.as_bytes())?;
    let doc = serde_json::to_value(detector_fit::record(&fit, c.seed, &real, &evaluation))?;
    let setup =
        serde_json::json!({ "cameras": c.cameras, "real": real_path, "camera_count": rig.len() });
    println!("wrote {}", model_path.display());
    write_result(c, "detector_fit", doc, setup, &[])
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

fn height_options(c: &Common) -> anyhow::Result<HeightOptions> {
    Ok(HeightOptions {
        count: c.operators.unwrap_or(60),
        idle_secs: 12.0,
        calibration_sessions: c.calibration_sessions,
        // The classes' curves as the cell reads them (the approvals crate's provider).
        rula: ergocell::session::provider::on_disk(
            &c.cell,
            &c.trajectories,
            &c.trajectories.join("approvals"),
        )
        .handover_rula()
        .map_err(|e| UsageError(e.to_string()))?,
        decision_sigmas: match c.decision_sigmas {
            Some(k) if !(k.is_finite() && (1.0..=4.0).contains(&k)) => {
                anyhow::bail!(UsageError(format!(
                    "--decision-sigmas {k}: expected 1 to 4"
                )))
            }
            k => k,
        },
    })
}

/// `sim handover-rula`: each class's RULA curve over `--seeds` (default 1..4), written as
/// `handover_rula.toml` (and its figure, unless `--json`) into `--out-dir`.
fn run_handover_rula(c: &Common) -> anyhow::Result<()> {
    let seeds = c
        .seeds
        .as_ref()
        .map_or_else(|| vec![1, 2, 3, 4], |s| s.0.clone());
    let rig = load_rig(&c.cameras)?;
    let handovers = load_handovers(c)?;
    let pb = progress_bar("handover_rula");
    let statures = experiments::handover_rula_statures();
    let rula = experiments::handover_rula(
        &rig,
        &handovers,
        &statures,
        c.cycles,
        &seeds,
        &mut |done, total| {
            pb.set_length(total as u64);
            pb.set_position(done as u64);
        },
    )?;
    pb.finish_and_clear();
    std::fs::create_dir_all(&c.out_dir)
        .with_context(|| format!("creating {}", c.out_dir.display()))?;
    let text = report::handover_rula_file(&rula, c.cycles, &seeds)?;
    let path = c.out_dir.join(HANDOVER_RULA_FILE);
    std::fs::write(&path, text).with_context(|| format!("writing {}", path.display()))?;
    if !c.json {
        let plot = write_figure(&c.out_dir, &report::handover_rula_figure(&rula)?)?;
        println!("wrote {}", path.display());
        println!("wrote {}", plot.display());
    }
    Ok(())
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

pub fn run(args: &Args) -> anyhow::Result<()> {
    check(args)?;
    let c = &args.common;
    match args.experiment {
        Experiment::HandoverRula => run_handover_rula(c),
        Experiment::FitDetector => run_fit_detector(c),
        Experiment::Warnings => super::sim_warnings::run(c),
        Experiment::Table1
        | Experiment::Adaptation
        | Experiment::Height
        | Experiment::RulaAgreement => match &c.seeds {
            Some(SeedRange(seeds)) => run_seeds(args, seeds),
            None => run_one(args),
        },
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

/// What an experiment returns: its result (or its summary over seeds) as JSON, and its report.
type Outcome = (serde_json::Value, Report);

/// The experiment on `--seed`: its table and figures, `<experiment>.json`.
fn run_one(args: &Args) -> anyhow::Result<()> {
    let c = &args.common;
    let setup = Setup {
        rig: load_rig(&c.cameras)?,
        noise: detector_noise(c)?,
        seed: c.seed,
    };
    setup
        .noise
        .validate()
        .map_err(|e| UsageError(e.to_string()))?;
    let handovers = load_handovers(c)?;
    let name = args.experiment.name();
    let pb = progress_bar(name);
    let mut tick = |done: usize, total: usize| {
        pb.set_length(total as u64);
        pb.set_position(done as u64);
    };
    std::fs::create_dir_all(&c.out_dir)
        .with_context(|| format!("creating {}", c.out_dir.display()))?;
    let (value, report) = match args.experiment {
        Experiment::HandoverRula => return run_handover_rula(c),
        Experiment::FitDetector => return run_fit_detector(c),
        Experiment::Warnings => return super::sim_warnings::run(c),
        Experiment::Table1 => one_table1(c, &setup, &handovers, &mut tick, &pb)?,
        Experiment::Adaptation => one_adaptation(c, &setup, &handovers, &mut tick, &pb)?,
        Experiment::Height => one_height(c, &setup, &handovers, &mut tick, &pb)?,
        Experiment::RulaAgreement => one_rula_agreement(c, &setup, &handovers, &mut tick, &pb)?,
    };
    let setup_json = serde_json::json!({
        "seed": c.seed,
        "cameras": c.cameras,
        "camera_count": setup.rig.len(),
        "noise": setup.noise,
        "cycles": c.cycles,
        "handovers_m": handovers,
    });
    let figures = show(c, &report)?;
    write_result(c, name, value, setup_json, &figures)
}

/// Table 1 on one seed: the result and its table and figure.
fn one_table1(
    c: &Common,
    setup: &Setup,
    handovers: &Handovers,
    tick: &mut dyn FnMut(usize, usize),
    pb: &ProgressBar,
) -> anyhow::Result<Outcome> {
    let operators = operator_statures(c.operators.unwrap_or(5));
    let r = experiments::table1(setup, handovers, &operators, c.cycles, tick)?;
    pb.finish_and_clear();
    let report = Report {
        text: report::table1_text(&r),
        figures: report::table1_figures(&r)?,
    };
    Ok((serde_json::to_value(&r)?, report))
}

/// The adaptation on one seed: the result and its table and figures; with `--record-height`, that
/// operator's two recordings.
fn one_adaptation(
    c: &Common,
    setup: &Setup,
    handovers: &Handovers,
    tick: &mut dyn FnMut(usize, usize),
    pb: &ProgressBar,
) -> anyhow::Result<Outcome> {
    let people = adaptation_people(c.bodies)?;
    let r = experiments::adaptation(
        setup,
        handovers,
        &experiments::adaptation_heights(),
        adaptation_bodies(c.bodies, &people),
        c.cycles,
        tick,
    )?;
    pb.finish_and_clear();
    let report = Report {
        text: report::adaptation_text(&r),
        figures: report::adaptation_figures(&r)?,
    };
    if let Some(h) = c.record_height {
        let [before, after] =
            ergocell::sim_record::record_both(setup, handovers, h, c.cycles, &c.out_dir)?;
        eprintln!(
            "recorded {} and {}: ergocell report {} --compare {}",
            before.display(),
            after.display(),
            before.display(),
            after.display()
        );
    }
    Ok((serde_json::to_value(&r)?, report))
}

/// The height experiment on one seed: the result and its table and figure.
fn one_height(
    c: &Common,
    setup: &Setup,
    handovers: &Handovers,
    tick: &mut dyn FnMut(usize, usize),
    pb: &ProgressBar,
) -> anyhow::Result<Outcome> {
    let people = ergocell_anthropometry::ansur::people()?;
    let r = experiments::height(setup, handovers, &people, &height_options(c)?, tick)?;
    pb.finish_and_clear();
    let report = Report {
        text: report::height_text(&r),
        figures: report::height_figures(&r)?,
    };
    Ok((serde_json::to_value(&r)?, report))
}

/// RULA agreement on one seed, and the same sessions at other pixel-noise levels (how agreement
/// depends on the detector, `ergocell_sim::experiments::noise_sweep`): the result with its sweep,
/// and the figures.
fn one_rula_agreement(
    c: &Common,
    setup: &Setup,
    handovers: &Handovers,
    tick: &mut dyn FnMut(usize, usize),
    pb: &ProgressBar,
) -> anyhow::Result<Outcome> {
    let operators = operator_statures(c.operators.unwrap_or(6));
    let lag = c.fixed_lag_s;
    let r = experiments::rula_agreement_with(setup, handovers, &operators, c.cycles, lag, tick)?;
    let sweep = noise_sweep::sweep(setup, handovers, &operators, c.cycles, lag)?;
    pb.finish_and_clear();
    let text = report::agreement_text(&r) + &report::noise_sweep_text(&sweep);
    let mut value = serde_json::to_value(&r)?;
    if let Some(obj) = value.as_object_mut() {
        let rows = serde_json::to_value(noise_sweep::rows(&sweep))?;
        obj.insert("noise_sweep".into(), rows);
    }
    let mut figures = report::agreement_figures(&r)?;
    figures.push(report::noise_sweep_figure(&sweep)?);
    Ok((value, Report { text, figures }))
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

/// One run per seed; each seed's sessions are independent of the others'.
fn each<T>(
    seeds: &[u64],
    pb: &ProgressBar,
    mut f: impl FnMut(u64) -> Result<T, ergocell_sim::SimError>,
) -> anyhow::Result<Vec<T>> {
    let mut out = Vec::with_capacity(seeds.len());
    for &s in seeds {
        out.push(f(s)?);
        pb.inc(1);
    }
    Ok(out)
}

/// `--seeds`: the experiment once per seed, summarised (see `ergocell_sim::seeds`).
fn run_seeds(args: &Args, seeds: &[u64]) -> anyhow::Result<()> {
    let c = &args.common;
    let rig = load_rig(&c.cameras)?;
    let noise = detector_noise(c)?;
    noise.validate().map_err(|e| UsageError(e.to_string()))?;
    let handovers = load_handovers(c)?;
    let name = args.experiment.name();
    std::fs::create_dir_all(&c.out_dir)
        .with_context(|| format!("creating {}", c.out_dir.display()))?;
    let pb = seeds_bar(name, seeds.len());
    let setup = |seed: u64| Setup {
        rig: rig.clone(),
        noise,
        seed,
    };
    let (value, report) = match args.experiment {
        Experiment::HandoverRula => return run_handover_rula(c),
        Experiment::FitDetector => return run_fit_detector(c),
        Experiment::Table1 => seeds_table1(c, seeds, &setup, &handovers, &pb)?,
        Experiment::Adaptation => seeds_adaptation(c, seeds, &setup, &handovers, &pb)?,
        Experiment::Height => seeds_height(c, seeds, &setup, &handovers, &pb)?,
        Experiment::RulaAgreement => seeds_rula_agreement(c, seeds, &setup, &handovers, &pb)?,
        Experiment::Warnings => return super::sim_warnings::run(c),
    };
    let setup_json = serde_json::json!({
        "seeds": seeds,
        "cameras": c.cameras,
        "camera_count": rig.len(),
        "noise": noise,
        "cycles": c.cycles,
        "handovers_m": handovers,
    });
    let figures = show(c, &report)?;
    write_result(c, &format!("{name}_seeds"), value, setup_json, &figures)
}

/// Table 1 on every seed: the per-landmark RMSE summary and its figure.
fn seeds_table1(
    c: &Common,
    seeds: &[u64],
    setup: &dyn Fn(u64) -> Setup,
    handovers: &Handovers,
    pb: &ProgressBar,
) -> anyhow::Result<Outcome> {
    let operators = operator_statures(c.operators.unwrap_or(5));
    let runs = each(seeds, pb, |s| {
        experiments::table1(&setup(s), handovers, &operators, c.cycles, &mut |_, _| {})
    })?;
    pb.finish_and_clear();
    let sum = seeds::table1(seeds, &runs);
    let report = report::table1_seeds(seeds, &runs, &sum)?;
    Ok((serde_json::to_value(&sum)?, report))
}

/// The adaptation experiment on every seed: the summary and its figure.
fn seeds_adaptation(
    c: &Common,
    seeds: &[u64],
    setup: &dyn Fn(u64) -> Setup,
    handovers: &Handovers,
    pb: &ProgressBar,
) -> anyhow::Result<Outcome> {
    let heights = experiments::adaptation_heights();
    let people = adaptation_people(c.bodies)?;
    let runs = each(seeds, pb, |s| {
        experiments::adaptation(
            &setup(s),
            handovers,
            &heights,
            adaptation_bodies(c.bodies, &people),
            c.cycles,
            &mut |_, _| {},
        )
    })?;
    pb.finish_and_clear();
    let sum = seeds::adaptation(seeds, &runs);
    let report = report::adaptation_seeds(seeds, &sum)?;
    Ok((serde_json::to_value(&sum)?, report))
}

/// The height experiment on every seed: the summary and its two figures.
fn seeds_height(
    c: &Common,
    seeds: &[u64],
    setup: &dyn Fn(u64) -> Setup,
    handovers: &Handovers,
    pb: &ProgressBar,
) -> anyhow::Result<Outcome> {
    let people = ergocell_anthropometry::ansur::people()?;
    let options = height_options(c)?;
    let runs = each(seeds, pb, |s| {
        experiments::height(&setup(s), handovers, &people, &options, &mut |_, _| {})
    })?;
    pb.finish_and_clear();
    let sum = seeds::height(seeds, &runs);
    let report = report::height_seeds(seeds, &sum)?;
    Ok((serde_json::to_value(&sum)?, report))
}

/// RULA agreement on every seed: the summary and its figure.
fn seeds_rula_agreement(
    c: &Common,
    seeds: &[u64],
    setup: &dyn Fn(u64) -> Setup,
    handovers: &Handovers,
    pb: &ProgressBar,
) -> anyhow::Result<Outcome> {
    let operators = operator_statures(c.operators.unwrap_or(6));
    let lag = c.fixed_lag_s;
    let runs = each(seeds, pb, |s| {
        experiments::rula_agreement_with(
            &setup(s),
            handovers,
            &operators,
            c.cycles,
            lag,
            &mut |_, _| {},
        )
    })?;
    pb.finish_and_clear();
    let sum = seeds::rula_agreement(seeds, &runs);
    let report = report::rula_agreement_seeds(seeds, &sum, &detector_label(c))?;
    Ok((serde_json::to_value(&sum)?, report))
}
