//! `ergocell sim`'s runs, from the inputs the binary read to what it prints and writes: one of the
//! paper's experiments on one seed, or once per seed of a range and summarised over them
//! ([`crate::seeds`]), each as its JSON value, the setup it ran on and its report
//! ([`crate::report`]: text and figures); the classes' handover-RULA curves and their file; the
//! detector fitted to a real one and judged on other seeds. Progress goes to the caller's callback
//! ([`Progress`]).
//!
//! No I/O: the binary reads the rig, the detector, the handover points and the classes' curves,
//! shows the progress, and prints and writes what these return.

use std::ops::RangeInclusive;
use std::path::Path;

use ergocell_anthropometry::ansur::{self, AnsurError, Person, Split};
use ergocell_ergonomics::height::HandoverRula;
use ergocell_perception::detector_error::DetectorErrorReport;
use ergocell_perception::CameraRig;
use serde::Serialize;
use serde_json::{Map, Value};

use crate::detector::DetectorNoise;
use crate::detector_fit::{self, FitSettings};
use crate::experiments::{
    self, noise_sweep, operator_statures, AdaptationBodies, Handovers, HeightOptions, Progress,
    Setup,
};
use crate::report::{self, CurvesTomlError, FigureError, Report};
use crate::seeds;
use crate::SimError;

/// Why a run failed.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum RunError {
    /// The simulation or an experiment failed.
    #[error(transparent)]
    Sim(#[from] SimError),
    /// The detector fit refused the real detector's error or the rig: bad input
    /// ([`RunError::is_bad_input`]).
    #[error(transparent)]
    FitRefused(SimError),
    /// ANSUR II's people could not be read.
    #[error(transparent)]
    People(#[from] AnsurError),
    /// A figure could not be drawn.
    #[error(transparent)]
    Figure(#[from] FigureError),
    /// A result could not be turned into JSON.
    #[error(transparent)]
    Json(#[from] serde_json::Error),
    /// The classes' curves could not be written as TOML.
    #[error(transparent)]
    CurvesToml(#[from] CurvesTomlError),
}

impl RunError {
    /// The inputs were refused (the user's to fix), as opposed to a run that failed.
    pub fn is_bad_input(&self) -> bool {
        matches!(self, RunError::FitRefused(_))
    }
}

/// Whose bodies the adaptation experiment's operators have.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Bodies {
    /// Drillis & Contini's proportions at exactly each height (the robot's planning model).
    Proportions,
    /// At each height one of ANSUR II's reporting half (people never fitted) within 1 cm, drawn by
    /// the seed ([`experiments::person_near`]).
    Measured,
}

impl Bodies {
    /// The people these bodies are drawn from: ANSUR II's reporting half for `Measured`, nobody for
    /// `Proportions`.
    pub fn people(self) -> Result<Vec<Person>, AnsurError> {
        Ok(match self {
            Bodies::Measured => ansur::people()?
                .into_iter()
                .filter(|p| p.split() == Split::Report)
                .collect(),
            Bodies::Proportions => Vec::new(),
        })
    }

    /// The adaptation's bodies, drawn from `people` ([`Bodies::people`]).
    fn of(self, people: &[Person]) -> AdaptationBodies<'_> {
        match self {
            Bodies::Measured => AdaptationBodies::Measured(people),
            Bodies::Proportions => AdaptationBodies::Proportions,
        }
    }
}

/// One of the paper's experiments, with what only it takes.
#[derive(Debug, Clone, PartialEq)]
pub enum Experiment {
    /// The paper's Table 1 ([`experiments::table1`]).
    Table1,
    /// The paper's Figs. 7–9 ([`experiments::adaptation`]) on operators of these bodies.
    Adaptation { bodies: Bodies },
    /// Stature and class from the cameras ([`experiments::height`]).
    Height(HeightOptions),
    /// Per-frame RULA agreement ([`experiments::rula_agreement_with`]) on the pipeline with this
    /// fixed lag; `detector_label` names the simulated detector in the summary's title
    /// ([`report::detector_label`]).
    RulaAgreement {
        fixed_lag_s: Option<f64>,
        detector_label: String,
    },
}

impl Experiment {
    /// The name its files are written under.
    pub fn name(&self) -> &'static str {
        match self {
            Experiment::Table1 => "table1",
            Experiment::Adaptation { .. } => "adaptation",
            Experiment::Height(_) => "height",
            Experiment::RulaAgreement { .. } => "rula_agreement",
        }
    }
}

/// The half-widths of the height decision's interval, in σ, the height experiment accepts.
pub const DECISION_SIGMAS: RangeInclusive<f64> = 1.0..=4.0;

/// A decision interval's half-width outside [`DECISION_SIGMAS`] (or not a number).
#[derive(Debug, Clone, Copy, PartialEq, thiserror::Error)]
#[error("{0}: expected 1 to 4")]
pub struct BadDecisionSigmas(pub f64);

/// The height experiment's options: `operators` of ANSUR II's reporting half (default 60), each
/// standing idle 12 s, after `calibration_sessions`; the classes' `rula` curves; the decision's
/// half-width `decision_sigmas` (default the cell's), refused outside [`DECISION_SIGMAS`].
pub fn height_options(
    operators: Option<usize>,
    calibration_sessions: usize,
    rula: Option<HandoverRula>,
    decision_sigmas: Option<f64>,
) -> Result<HeightOptions, BadDecisionSigmas> {
    if let Some(k) = decision_sigmas {
        if !(k.is_finite() && DECISION_SIGMAS.contains(&k)) {
            return Err(BadDecisionSigmas(k));
        }
    }
    Ok(HeightOptions {
        count: operators.unwrap_or(60),
        idle_secs: 12.0,
        calibration_sessions,
        rula,
        decision_sigmas,
    })
}

/// Runs `run` once per seed of `seeds`, in order, calling `progress(seeds done, seeds)` after each;
/// the first error stops it. Each seed's sessions are independent of the others'.
pub fn each_seed<T, E>(
    seeds: &[u64],
    progress: Progress<'_>,
    mut run: impl FnMut(u64) -> Result<T, E>,
) -> Result<Vec<T>, E> {
    let mut runs = Vec::with_capacity(seeds.len());
    for (i, &seed) in seeds.iter().enumerate() {
        runs.push(run(seed)?);
        progress(i + 1, seeds.len());
    }
    Ok(runs)
}

/// An experiment over seeds: `run` once per seed ([`each_seed`], with `progress`), the runs
/// summarised by `summarise` and the summary reported by `tell`. Returns the summary as JSON and
/// the report.
pub fn summarised<T, S: Serialize>(
    seeds: &[u64],
    progress: Progress<'_>,
    run: impl FnMut(u64) -> Result<T, SimError>,
    summarise: impl FnOnce(&[u64], &[T]) -> S,
    tell: impl FnOnce(&[T], &S) -> Result<Report, FigureError>,
) -> Result<(Value, Report), RunError> {
    let runs = each_seed(seeds, progress, run)?;
    let sum = summarise(seeds, &runs);
    let report = tell(&runs, &sum)?;
    Ok((serde_json::to_value(&sum)?, report))
}

/// One of the paper's experiments and what it runs on, as the binary read them.
#[derive(Debug, Clone)]
pub struct Run {
    pub experiment: Experiment,
    pub rig: CameraRig,
    pub noise: DetectorNoise,
    pub handovers: Handovers,
    /// The rig as the user named it (a file or a count), for the setup's record.
    pub cameras: String,
    /// Operators to simulate; `None`: Table 1's 5, RULA agreement's 6 (the height experiment's
    /// count is its options', [`HeightOptions::count`]; the adaptation's its heights).
    pub operators: Option<usize>,
    /// Handover cycles per operator.
    pub cycles: usize,
}

/// What a run gives: its result (or its summary over seeds) as JSON, the setup it ran on, and its
/// report.
#[derive(Debug, Clone, PartialEq)]
pub struct Outcome {
    pub value: Value,
    pub setup: Value,
    pub report: Report,
}

impl Run {
    /// What the sessions of `seed` run on.
    pub fn setup(&self, seed: u64) -> Setup {
        Setup {
            rig: self.rig.clone(),
            noise: self.noise,
            seed,
        }
    }

    fn statures(&self, default_count: usize) -> Vec<f64> {
        operator_statures(self.operators.unwrap_or(default_count))
    }

    /// The experiment on `seed` (`progress(sessions done, sessions)`): its result, its setup
    /// (`seed`, the rig, the noise, the cycles, the handover points) and its table and figures.
    pub fn one(&self, seed: u64, progress: Progress<'_>) -> Result<Outcome, RunError> {
        let setup = self.setup(seed);
        let h = &self.handovers;
        let (value, report) = match &self.experiment {
            Experiment::Table1 => {
                let r = experiments::table1(&setup, h, &self.statures(5), self.cycles, progress)?;
                let figures = report::table1_figures(&r)?;
                let text = report::table1_text(&r);
                (serde_json::to_value(&r)?, Report { text, figures })
            }
            Experiment::Adaptation { bodies } => {
                let people = bodies.people()?;
                let heights = experiments::adaptation_heights();
                let bodies = bodies.of(&people);
                let r =
                    experiments::adaptation(&setup, h, &heights, bodies, self.cycles, progress)?;
                let figures = report::adaptation_figures(&r)?;
                let text = report::adaptation_text(&r);
                (serde_json::to_value(&r)?, Report { text, figures })
            }
            Experiment::Height(options) => {
                let people = ansur::people()?;
                let r = experiments::height(&setup, h, &people, options, progress)?;
                let figures = report::height_figures(&r)?;
                let text = report::height_text(&r);
                (serde_json::to_value(&r)?, Report { text, figures })
            }
            Experiment::RulaAgreement { fixed_lag_s, .. } => {
                self.one_rula_agreement(&setup, *fixed_lag_s, progress)?
            }
        };
        let setup = self.setup_json("seed", seed.into())?;
        Ok(Outcome {
            value,
            setup,
            report,
        })
    }

    /// RULA agreement on one seed, and the same sessions at other pixel-noise levels
    /// ([`noise_sweep`]: how agreement depends on the detector), in its JSON as `noise_sweep`.
    fn one_rula_agreement(
        &self,
        setup: &Setup,
        lag: Option<f64>,
        progress: Progress<'_>,
    ) -> Result<(Value, Report), RunError> {
        let (h, cycles) = (&self.handovers, self.cycles);
        let operators = self.statures(6);
        let r = experiments::rula_agreement_with(setup, h, &operators, cycles, lag, progress)?;
        let sweep = noise_sweep::sweep(setup, h, &operators, cycles, lag)?;
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

    /// The experiment once per seed of `seeds` (`progress(seeds done, seeds)`), summarised
    /// ([`crate::seeds`]): the summary, its setup (`seeds`, the rig, the noise, the cycles, the
    /// handover points) and its table and figures.
    pub fn over_seeds(&self, seeds: &[u64], progress: Progress<'_>) -> Result<Outcome, RunError> {
        let (h, cycles) = (&self.handovers, self.cycles);
        let (value, report) = match &self.experiment {
            Experiment::Table1 => {
                let operators = self.statures(5);
                summarised(
                    seeds,
                    progress,
                    |s| experiments::table1(&self.setup(s), h, &operators, cycles, &mut |_, _| {}),
                    seeds::table1,
                    |runs, sum| report::table1_seeds(seeds, runs, sum),
                )?
            }
            Experiment::Adaptation { bodies } => {
                let (heights, people) = (experiments::adaptation_heights(), bodies.people()?);
                summarised(
                    seeds,
                    progress,
                    |s| {
                        let (setup, bodies) = (self.setup(s), bodies.of(&people));
                        experiments::adaptation(&setup, h, &heights, bodies, cycles, &mut |_, _| {})
                    },
                    seeds::adaptation,
                    |_, sum| report::adaptation_seeds(seeds, sum),
                )?
            }
            Experiment::Height(options) => {
                let people = ansur::people()?;
                summarised(
                    seeds,
                    progress,
                    |s| experiments::height(&self.setup(s), h, &people, options, &mut |_, _| {}),
                    seeds::height,
                    |_, sum| report::height_seeds(seeds, sum),
                )?
            }
            Experiment::RulaAgreement {
                fixed_lag_s,
                detector_label,
            } => {
                let (operators, lag) = (self.statures(6), *fixed_lag_s);
                summarised(
                    seeds,
                    progress,
                    |s| {
                        let setup = self.setup(s);
                        let quiet = &mut |_: usize, _: usize| {};
                        experiments::rula_agreement_with(&setup, h, &operators, cycles, lag, quiet)
                    },
                    seeds::rula_agreement,
                    |_, sum| report::rula_agreement_seeds(seeds, sum, detector_label),
                )?
            }
        };
        let setup = self.setup_json("seeds", seeds.into())?;
        Ok(Outcome {
            value,
            setup,
            report,
        })
    }

    /// The setup's record: `key` (`seed` or `seeds`) and the rig, the noise, the cycles and the
    /// handover points.
    fn setup_json(&self, key: &str, seeds: Value) -> Result<Value, serde_json::Error> {
        let mut setup = Map::new();
        setup.insert(key.to_owned(), seeds);
        setup.insert("cameras".into(), self.cameras.clone().into());
        setup.insert("camera_count".into(), self.rig.len().into());
        setup.insert("noise".into(), serde_json::to_value(self.noise)?);
        setup.insert("cycles".into(), self.cycles.into());
        setup.insert("handovers_m".into(), serde_json::to_value(self.handovers)?);
        Ok(Value::Object(setup))
    }
}

/// The seeds of the classes' RULA curves when none are given.
pub const HANDOVER_RULA_SEEDS: [u64; 4] = [1, 2, 3, 4];

/// The classes' RULA-versus-stature curves ([`experiments::handover_rula`] at
/// [`experiments::handover_rula_statures`]) over `seeds` (default [`HANDOVER_RULA_SEEDS`]), and the
/// text of `handover_rula.toml` ([`report::handover_rula_file`]).
pub fn handover_rula(
    rig: &CameraRig,
    handovers: &Handovers,
    cycles: usize,
    seeds: Option<&[u64]>,
    progress: Progress<'_>,
) -> Result<(HandoverRula, String), RunError> {
    let seeds = seeds.unwrap_or(&HANDOVER_RULA_SEEDS);
    let statures = experiments::handover_rula_statures();
    let rula = experiments::handover_rula(rig, handovers, &statures, cycles, seeds, progress)?;
    let file = report::handover_rula_file(&rula, cycles, seeds)?;
    Ok((rula, file))
}

/// The seeds a fitted detector is judged on when none are given.
pub const FIT_REPORT_SEEDS: RangeInclusive<u64> = 101..=120;

/// `sim fit-detector`: the twin's detector fitted to a real one measured view against view.
#[derive(Debug, Clone)]
pub struct DetectorFitRun<'a> {
    /// The real detector's error, read from `real_path`.
    pub real: &'a DetectorErrorReport,
    pub real_path: &'a Path,
    /// The cameras the real error was measured on, and how the user named them.
    pub rig: &'a CameraRig,
    pub cameras: &'a str,
    pub settings: FitSettings,
    /// The seed fitted on.
    pub seed: u64,
    /// The seeds the fit is judged on; `None`: [`FIT_REPORT_SEEDS`].
    pub report_seeds: Option<&'a [u64]>,
    /// The independent pixel noise compared with, pixels.
    pub noise_px: f64,
}

/// What a detector fit gives: the model's file (`detector.toml`), the text `sim fit-detector`
/// prints, and `detector_fit.json`'s record and setup.
#[derive(Debug, Clone, PartialEq)]
pub struct FittedDetector {
    pub model_toml: String,
    pub text: String,
    pub record: Value,
    pub setup: Value,
}

impl DetectorFitRun<'_> {
    /// Fits the model on `seed` ([`detector_fit::fit`]: a refusal is [`RunError::FitRefused`]),
    /// names what it was fitted to, and judges it on the report seeds beside the independent noise
    /// ([`detector_fit::evaluate`]).
    pub fn run(&self) -> Result<FittedDetector, RunError> {
        let (real, rig, settings) = (self.real, self.rig, &self.settings);
        let report_seeds: Vec<u64> = self
            .report_seeds
            .map_or_else(|| FIT_REPORT_SEEDS.collect(), <[u64]>::to_vec);
        let mut fit =
            detector_fit::fit(real, rig, settings, self.seed).map_err(RunError::FitRefused)?;
        let label = self.real_path.display().to_string();
        let (cameras, count) = (self.cameras, rig.len());
        fit.model.fitted_to =
            detector_fit::fitted_to(&label, real, cameras, count, self.seed, settings);
        let independent = DetectorNoise {
            pixel_sigma_px: self.noise_px,
            ..DetectorNoise::default()
        };
        let evaluation =
            detector_fit::evaluate(real, rig, &fit.model, settings, &report_seeds, &independent)?;
        let mut setup = Map::new();
        setup.insert("cameras".into(), cameras.into());
        setup.insert("real".into(), serde_json::to_value(self.real_path)?);
        setup.insert("camera_count".into(), count.into());
        Ok(FittedDetector {
            model_toml: fit.model.to_toml()?,
            text: report::detector_fit_text(&label, real, &evaluation, self.seed, self.noise_px),
            record: serde_json::to_value(detector_fit::record(&fit, self.seed, real, &evaluation))?,
            setup: Value::Object(setup),
        })
    }
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)]
    use super::*;
    use crate::{ring_rig, RingRigConfig};

    fn handovers() -> Handovers {
        let cell =
            ergocell_robot::CellConfig::from_toml_str(include_str!("../../config/cell.toml"))
                .unwrap();
        let specs = [
            include_str!("../../trajectories/c1.toml"),
            include_str!("../../trajectories/c2.toml"),
            include_str!("../../trajectories/c3.toml"),
        ]
        .map(|t| ergocell_robot::TrajectorySpec::from_toml_str(t).unwrap());
        Handovers::from_cell(&cell, &specs, [0.41, -0.10, 1.055])
    }

    #[test]
    fn each_seed_runs_in_order_reports_progress_and_stops_at_the_first_error() {
        let mut seen = Vec::new();
        let runs: Result<Vec<u64>, String> =
            each_seed(&[7, 8, 9], &mut |done, n| seen.push((done, n)), |s| {
                Ok(s * 10)
            });
        assert_eq!(runs.unwrap(), vec![70, 80, 90]);
        assert_eq!(seen, vec![(1, 3), (2, 3), (3, 3)]);
        let mut seen = Vec::new();
        let mut ran = Vec::new();
        let failed: Result<Vec<u64>, String> =
            each_seed(&[1, 2, 3], &mut |done, n| seen.push((done, n)), |s| {
                ran.push(s);
                if s == 2 {
                    Err(format!("seed {s}"))
                } else {
                    Ok(s)
                }
            });
        assert_eq!(failed.unwrap_err(), "seed 2");
        assert_eq!(ran, vec![1, 2], "nothing runs after the first error");
        assert_eq!(seen, vec![(1, 3)], "a failed seed is not counted as done");
    }

    #[test]
    fn height_options_default_to_sixty_operators_and_refuse_a_decision_outside_1_to_4_sigma() {
        let o = height_options(None, 5, None, None).unwrap();
        assert_eq!(
            (o.count, o.idle_secs, o.calibration_sessions),
            (60, 12.0, 5)
        );
        assert_eq!(o.decision_sigmas, None);
        assert_eq!(height_options(Some(7), 0, None, None).unwrap().count, 7);
        for k in [1.0, 2.5, 4.0] {
            let o = height_options(None, 0, None, Some(k)).unwrap();
            assert_eq!(o.decision_sigmas, Some(k));
        }
        for k in [0.99, 4.01, -2.0, f64::NAN, f64::INFINITY] {
            let e = height_options(None, 0, None, Some(k)).unwrap_err();
            assert_eq!(e.to_string(), format!("{k}: expected 1 to 4"));
        }
    }

    #[test]
    fn measured_bodies_are_the_reporting_half_and_proportions_are_nobody() {
        assert!(Bodies::Proportions.people().unwrap().is_empty());
        let measured = Bodies::Measured.people().unwrap();
        assert!(measured.len() > 1000, "{}", measured.len());
        assert!(measured.iter().all(|p| p.split() == Split::Report));
    }

    #[test]
    fn the_handover_rula_seeds_default_to_1_to_4_and_the_fit_is_judged_on_101_to_120() {
        assert_eq!(HANDOVER_RULA_SEEDS, [1, 2, 3, 4]);
        assert_eq!(FIT_REPORT_SEEDS.count(), 20);
        assert_eq!(
            (*FIT_REPORT_SEEDS.start(), *FIT_REPORT_SEEDS.end()),
            (101, 120)
        );
    }

    /// Over seeds, each seed's values are the one-seed run's, and the setup records the seeds.
    #[test]
    fn a_seeds_summary_holds_each_seeds_own_run() {
        let run = Run {
            experiment: Experiment::Table1,
            rig: ring_rig(4, &RingRigConfig::default()).unwrap(),
            noise: DetectorNoise::default(),
            handovers: handovers(),
            cameras: "4".to_owned(),
            operators: Some(1),
            cycles: 1,
        };
        assert_eq!(run.experiment.name(), "table1");
        let mut sessions = 0;
        let one = run.one(4, &mut |_, _| sessions += 1).unwrap();
        assert!(sessions > 0);
        assert_eq!(one.setup["seed"], 4);
        assert_eq!(one.setup["camera_count"], 4);
        assert_eq!(one.setup["cameras"], "4");
        assert!(!one.report.text.is_empty() && !one.report.figures.is_empty());
        let mut done = Vec::new();
        let over = run
            .over_seeds(&[3, 4], &mut |d, n| done.push((d, n)))
            .unwrap();
        assert_eq!(done, vec![(1, 2), (2, 2)]);
        assert_eq!(over.setup["seeds"], serde_json::json!([3, 4]));
        let single = one.value["rmse_m"]["default_fusion"].as_array().unwrap();
        let summary = over.value["default_rmse_m"].as_array().unwrap();
        assert_eq!(single.len(), summary.len());
        for (s, sum) in single.iter().zip(summary) {
            let (Some(s), Some(per_seed)) = (s.as_f64(), sum["per_seed"][1].as_f64()) else {
                continue;
            };
            assert!((s - per_seed).abs() < 1e-6, "{s} vs {per_seed}");
        }
        for goal in over.value["goals"].as_array().unwrap() {
            assert_eq!(goal["seeds"], 2);
        }
    }
}
