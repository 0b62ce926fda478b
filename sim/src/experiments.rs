//! The seed paper's experiments, reproduced on the digital twin with the real perception and
//! ergonomics code (only the world is simulated).
//!
//! - [`table1`]: the paper's Table 1 — RMSE of 12 landmarks for each stereo pair alone (DLT of that
//!   pair, [`FusionEngine::pair_estimates_of`]), the paper's graph-Laplacian fusion
//!   ([`FusionMethod::Paper`]) and ergocell's default fusion ([`FusionMethod::Default`]), per frame,
//!   no temporal filter, over every frame at the station (idle and handover cycles).
//! - [`adaptation`]: the paper's Figs. 7–9 — operators 1.50–2.00 m do the handover task before
//!   adaptation (one handover point for a 1.75 m operator) and after (their class's handover point;
//!   class from the true stature with the ergonomics crate's default thresholds). RULA on the noisy
//!   pipeline (default fusion → One-Euro filter → RULA assessor) over the frames where the hand holds
//!   the handover point, and the same on the ground truth.
//! - [`height`]: a population uniform in 1.50–2.00 m; stature and class from the noisy pipeline with
//!   the ergonomics height estimator during a long idle phase.
//! - [`rula_agreement`]: per-frame RULA grand score and action level from the noisy pipeline vs from
//!   ground truth: exact agreement `Po` and Cohen's κ; [`noise_sweep`]: the same at other
//!   pixel-noise levels.
//!
//! The noisy side of every experiment but Table 1 is the cell controller's own per-frame pipeline,
//! [`ergocell_cell::Pipeline`] with its defaults: views pushed as they arrive at their tick
//! (frame assembly, default fusion, the tracked gate, One-Euro filter, RULA with its smoothing, the
//! height estimator on the unfiltered skeleton until its first decision) — the same type the
//! session state machine runs, so these figures are the controller's. Each frame it releases is
//! compared with the ground truth of the tick nearest its stamp. Table 1 compares fusion methods
//! frame by frame, so it calls [`FusionEngine`] directly, without the filter.
//!
//! Each function takes the rig, the detector noise and a seed and returns plain values (no I/O); the
//! binary prints, plots and writes JSON. Each session gets its own seed derived from the experiment's
//! (`seed · 1000 + session`), so results are reproducible bit for bit and independent of run order.

use std::collections::BTreeMap;

use ergocell_anthropometry::ansur::{Person, Split};
use ergocell_cell::{Pipeline, PipelineConfig, TrackedFrame};
use ergocell_ergonomics::assess::BodyRegion;
use ergocell_ergonomics::height::{
    calibrate_ear_offset, serves_interval, CalibrationSample, DecisionBasis, EarOffset,
    HandoverRula, ServedStatures,
};
use ergocell_ergonomics::posture_cost::posture_cost;
use ergocell_ergonomics::rula::action_level;
use ergocell_ergonomics::{
    AssessmentConfig, FrameAssessment, HeightClass, HeightConfig, HeightStatus, RulaAssessor, Side,
    UpVector, WarningConfig, WarningEvent, WarningKind, WarningTracker,
};
use ergocell_perception::{CameraRig, FusionEngine, FusionMethod};
use ergocell_skeleton::Landmark;
use nalgebra::{Point3, Vector3};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use serde::Serialize;

use crate::body::Operator;
use crate::detector::DetectorNoise;
use crate::session::{Phase, SessionScript, SimConfig, Simulation, Tick};
use crate::SimError;

pub mod noise_sweep;

/// The 12 landmarks of the paper's Table 1.
pub const TABLE1_LANDMARKS: [Landmark; 12] = [
    Landmark::LeftShoulder,
    Landmark::RightShoulder,
    Landmark::LeftElbow,
    Landmark::RightElbow,
    Landmark::LeftWrist,
    Landmark::RightWrist,
    Landmark::LeftHip,
    Landmark::RightHip,
    Landmark::LeftKnee,
    Landmark::RightKnee,
    Landmark::LeftAnkle,
    Landmark::RightAnkle,
];

/// What every experiment runs on.
#[derive(Debug, Clone)]
pub struct Setup {
    pub rig: CameraRig,
    pub noise: DetectorNoise,
    pub seed: u64,
}

/// The handover points, world frame: one before adaptation, one per class after.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Handovers {
    /// The single handover point of the unadapted robot (set for a 1.75 m operator).
    pub before_m: Point3<f64>,
    pub c1_m: Point3<f64>,
    pub c2_m: Point3<f64>,
    pub c3_m: Point3<f64>,
    /// The statures `[min, max]` each class's handover point was derived for (its trajectory
    /// file's `[stature]`, the class itself); service is judged on the served range below.
    pub c1_stature_m: [f64; 2],
    pub c2_stature_m: [f64; 2],
    pub c3_stature_m: [f64; 2],
    /// The statures each class's trajectory is validated and served for (its file's served range,
    /// wider than the class): what the height decision may choose the class for, and what the
    /// session checks the operator's interval against before the robot moves ([`Handovers::serves`]).
    pub c1_served_m: [f64; 2],
    pub c2_served_m: [f64; 2],
    pub c3_served_m: [f64; 2],
}

impl Handovers {
    /// The class's handover point.
    pub fn for_class(&self, class: HeightClass) -> Point3<f64> {
        match class {
            HeightClass::C1 => self.c1_m,
            HeightClass::C2 => self.c2_m,
            HeightClass::C3 => self.c3_m,
        }
    }

    /// The served statures of every class, for the height decision.
    pub fn served(&self) -> Result<ServedStatures, SimError> {
        Ok(ServedStatures::new([
            self.c1_served_m,
            self.c2_served_m,
            self.c3_served_m,
        ])?)
    }

    /// The statures `class`'s trajectory is served for.
    pub fn served_m(&self, class: HeightClass) -> [f64; 2] {
        match class {
            HeightClass::C1 => self.c1_served_m,
            HeightClass::C2 => self.c2_served_m,
            HeightClass::C3 => self.c3_served_m,
        }
    }

    /// Whether the cell would hand over in `class` to an operator whose stature interval is
    /// `interval_m`: the session's own rule ([`serves_interval`]: the whole interval inside the
    /// statures the class's trajectory is served for).
    pub fn serves(&self, class: HeightClass, interval_m: [f64; 2]) -> bool {
        serves_interval(self.served_m(class), interval_m)
    }

    /// A cell's handover points: each class's trajectory file's point (`specs` in class order c1,
    /// c2, c3; station frame) and `before_station_m`, the unadapted point (station frame), placed in
    /// the world by `cell`'s station; each class's statures and served statures from its file.
    pub fn from_cell(
        cell: &ergocell_robot::CellConfig,
        specs: &[ergocell_robot::TrajectorySpec; 3],
        before_station_m: [f64; 3],
    ) -> Self {
        let point = |s: &ergocell_robot::TrajectorySpec| {
            let h = &s.handover;
            cell.handover_world([h.forward_m, h.lateral_m, h.height_m])
        };
        let stature = |s: &ergocell_robot::TrajectorySpec| [s.stature.min_m, s.stature.max_m];
        let served = |s: &ergocell_robot::TrajectorySpec| {
            let (lo, hi) = s.stature.served_m();
            [lo, hi]
        };
        let [c1, c2, c3] = specs;
        Self {
            before_m: cell.handover_world(before_station_m),
            c1_m: point(c1),
            c2_m: point(c2),
            c3_m: point(c3),
            c1_stature_m: stature(c1),
            c2_stature_m: stature(c2),
            c3_stature_m: stature(c3),
            c1_served_m: served(c1),
            c2_served_m: served(c2),
            c3_served_m: served(c3),
        }
    }
}

/// Progress callback: `(sessions done, sessions in total)`.
pub type Progress<'a> = &'a mut dyn FnMut(usize, usize);

pub(crate) fn up() -> Result<UpVector, SimError> {
    Ok(UpVector::new(Vector3::z())?)
}

pub(crate) fn session_seed(seed: u64, session: usize) -> u64 {
    seed.wrapping_mul(1000).wrapping_add(session as u64)
}

fn simulate(
    setup: &Setup,
    session: usize,
    stature_m: f64,
    script: &SessionScript,
) -> Result<Vec<Tick>, SimError> {
    simulate_operator(setup, session, Operator::new(stature_m)?, script)
}

fn simulate_operator(
    setup: &Setup,
    session: usize,
    operator: Operator,
    script: &SessionScript,
) -> Result<Vec<Tick>, SimError> {
    let config = SimConfig {
        noise: setup.noise,
        ..SimConfig::new(session_seed(setup.seed, session))
    };
    Simulation::new(setup.rig.clone(), operator, *script, config)?.collect()
}

/// The assessor for the ground truth: the true angles of each instant, unsmoothed (the pipeline's
/// assessor keeps the cell controller's defaults, smoothing included, and its lag counts against it).
pub(crate) fn truth_config(cfg: &AssessmentConfig) -> AssessmentConfig {
    AssessmentConfig {
        smoothing_window_nanos: 0,
        ..*cfg
    }
}

pub(crate) fn at_station(phase: Phase) -> bool {
    !matches!(phase, Phase::WalkIn | Phase::WalkOut | Phase::Gone)
}

pub(crate) fn round6(x: f64) -> f64 {
    (x * 1e6).round() / 1e6
}

// ---------------------------------------------------------------------------------------------
// Table 1

/// Result of [`table1`].
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Table1 {
    /// The 12 landmark names.
    pub landmarks: Vec<String>,
    /// RMSE per landmark, metres, per method: each stereo pair by name, `paper_fusion`,
    /// `default_fusion`. `None` where a method never estimated the landmark.
    pub rmse_m: BTreeMap<String, Vec<Option<f64>>>,
    /// Median error per landmark, metres, per method (RMSE is dominated by the rare catastrophic
    /// estimates of a narrow-baseline pair; the median shows the typical error).
    pub median_m: BTreeMap<String, Vec<Option<f64>>>,
    /// Share of the frames in which each method estimated each landmark.
    pub coverage: BTreeMap<String, Vec<f64>>,
    /// Frames evaluated.
    pub frames: usize,
    /// Operators' statures.
    pub statures_m: Vec<f64>,
}

impl Table1 {
    /// For each landmark, the smallest RMSE of any single stereo pair.
    pub fn best_pair(&self) -> Vec<Option<f64>> {
        (0..TABLE1_LANDMARKS.len())
            .map(|i| {
                self.rmse_m
                    .iter()
                    .filter(|(k, _)| *k != "paper_fusion" && *k != "default_fusion")
                    .filter_map(|(_, v)| v[i])
                    .min_by(f64::total_cmp)
            })
            .collect()
    }

    /// Landmarks on which `method` beats (strictly lower RMSE) `other`'s per-landmark values.
    pub fn wins(&self, method: &str, other: &[Option<f64>]) -> usize {
        let Some(m) = self.rmse_m.get(method) else {
            return 0;
        };
        m.iter()
            .zip(other)
            .filter(|(a, b)| match (a, b) {
                (Some(a), Some(b)) => a < b,
                (Some(_), None) => true,
                _ => false,
            })
            .count()
    }
}

#[derive(Default, Clone)]
struct Acc {
    sum_sq: Vec<f64>,
    n: Vec<usize>,
    errors: Vec<Vec<f64>>,
}

impl Acc {
    fn new() -> Self {
        Self {
            sum_sq: vec![0.0; TABLE1_LANDMARKS.len()],
            n: vec![0; TABLE1_LANDMARKS.len()],
            errors: vec![Vec::new(); TABLE1_LANDMARKS.len()],
        }
    }
    fn add(&mut self, i: usize, est: Option<Point3<f64>>, truth: &Point3<f64>) {
        if let Some(e) = est {
            let d = (e - truth).norm();
            self.sum_sq[i] += d * d;
            self.n[i] += 1;
            self.errors[i].push(d);
        }
    }
    fn medians(&mut self) -> Vec<Option<f64>> {
        self.errors
            .iter_mut()
            .map(|v| {
                if v.is_empty() {
                    return None;
                }
                v.sort_by(f64::total_cmp);
                let n = v.len();
                Some(round6(if n % 2 == 1 {
                    v[n / 2]
                } else {
                    0.5 * (v[n / 2 - 1] + v[n / 2])
                }))
            })
            .collect()
    }
}

/// The paper's Table 1 on the simulator: operators of `statures_m`, `cycles` handovers each at their
/// class's handover point.
pub fn table1(
    setup: &Setup,
    handovers: &Handovers,
    statures_m: &[f64],
    cycles: usize,
    progress: Progress<'_>,
) -> Result<Table1, SimError> {
    let pair_names: Vec<String> = setup.rig.pairs().iter().map(|p| p.name.clone()).collect();
    let mut pairs = vec![Acc::new(); pair_names.len()];
    let mut paper = Acc::new();
    let mut default = Acc::new();
    let mut frames = 0usize;
    let thresholds = HeightConfig::new(up()?).thresholds;
    for (s, &h) in statures_m.iter().enumerate() {
        let mut script = SessionScript::new(handovers.for_class(HeightClass::of(h, &thresholds)));
        script.cycles = cycles;
        let ticks = simulate(setup, s, h, &script)?;
        let mut e_paper = FusionEngine::new(setup.rig.clone(), FusionMethod::Paper)?;
        let mut e_default = FusionEngine::new(setup.rig.clone(), FusionMethod::Default)?;
        for tick in ticks.iter().filter(|t| at_station(t.truth.phase)) {
            frames += 1;
            let per_pair = e_default.pair_estimates_of(&tick.frame)?;
            let fp = e_paper.fuse(&tick.frame)?.skeleton;
            let fd = e_default.fuse(&tick.frame)?.skeleton;
            for (i, lm) in TABLE1_LANDMARKS.iter().enumerate() {
                let Some(truth) = tick.truth.skeleton.position(*lm) else {
                    continue;
                };
                for (acc, est) in pairs.iter_mut().zip(&per_pair) {
                    acc.add(i, est[lm.index()], &truth);
                }
                paper.add(i, fp.position(*lm), &truth);
                default.add(i, fd.position(*lm), &truth);
            }
        }
        progress(s + 1, statures_m.len());
    }
    let mut rmse_m = BTreeMap::new();
    let mut median_m = BTreeMap::new();
    let mut coverage = BTreeMap::new();
    let all = pair_names.into_iter().zip(pairs).chain([
        ("paper_fusion".to_owned(), paper),
        ("default_fusion".to_owned(), default),
    ]);
    for (name, mut acc) in all {
        median_m.insert(name.clone(), acc.medians());
        rmse_m.insert(
            name.clone(),
            acc.sum_sq
                .iter()
                .zip(&acc.n)
                .map(|(s, n)| (*n > 0).then(|| round6((s / *n as f64).sqrt())))
                .collect(),
        );
        coverage.insert(
            name,
            acc.n
                .iter()
                .map(|n| round6(*n as f64 / frames.max(1) as f64))
                .collect(),
        );
    }
    Ok(Table1 {
        landmarks: TABLE1_LANDMARKS
            .iter()
            .map(|l| l.name().to_owned())
            .collect(),
        rmse_m,
        median_m,
        coverage,
        frames,
        statures_m: statures_m.to_vec(),
    })
}

// ---------------------------------------------------------------------------------------------
// The noisy pipeline and RULA on it

/// The cell controller's pipeline with its defaults on the experiment's rig.
fn pipeline(setup: &Setup) -> Result<Pipeline, SimError> {
    Ok(Pipeline::new(
        setup.rig.clone(),
        PipelineConfig::new(up()?),
    )?)
}

/// [`run_pipeline`] with a pipeline configured by `config`.
pub fn run_pipeline_with(
    setup: &Setup,
    config: PipelineConfig,
    ticks: &[Tick],
    mut f: impl FnMut(usize, &TrackedFrame) -> Result<(), SimError>,
) -> Result<Pipeline, SimError> {
    let mut p = Pipeline::new(setup.rig.clone(), config)?;
    for tick in ticks {
        for output in p.push_views(tick.frame.stamp_nanos, tick.frame.views.clone()) {
            let output = output?;
            for tracked in &output.tracked {
                f(nearest_tick(ticks, tracked.skeleton.stamp_nanos), tracked)?;
            }
        }
    }
    Ok(p)
}

/// Runs the controller's pipeline over a session's ticks as the session does (each tick's views
/// pushed at the tick's time) and hands every tracked frame it releases to `f` with the index of the
/// tick nearest the frame's stamp (views carry jittered capture stamps; frames wait for late cameras).
/// Returns the pipeline, for its final state (the height).
pub fn run_pipeline(
    setup: &Setup,
    ticks: &[Tick],
    mut f: impl FnMut(usize, &TrackedFrame) -> Result<(), SimError>,
) -> Result<Pipeline, SimError> {
    let mut p = pipeline(setup)?;
    for tick in ticks {
        for output in p.push_views(tick.frame.stamp_nanos, tick.frame.views.clone()) {
            let output = output?;
            for tracked in &output.tracked {
                f(nearest_tick(ticks, tracked.skeleton.stamp_nanos), tracked)?;
            }
        }
    }
    Ok(p)
}

/// Index of the tick whose time is nearest `stamp_nanos` (ticks in time order).
pub(crate) fn nearest_tick(ticks: &[Tick], stamp_nanos: i64) -> usize {
    let i = ticks.partition_point(|t| t.frame.stamp_nanos < stamp_nanos);
    match (i.checked_sub(1), ticks.get(i)) {
        (Some(j), Some(next))
            if (stamp_nanos - ticks[j].frame.stamp_nanos).abs()
                <= (next.frame.stamp_nanos - stamp_nanos).abs() =>
        {
            j
        }
        (Some(j), None) => j,
        _ => i.min(ticks.len().saturating_sub(1)),
    }
}

/// Per-region scores and angles of one scored frame (worse side).
#[derive(Debug, Clone, Copy, Default)]
pub(crate) struct Scored {
    pub(crate) grand: u8,
    pub(crate) regions: [u8; 6],
    /// The assessor marked the score uncertain (a landmark it used is below its confidence floor, or
    /// an input was held or never observed).
    uncertain: bool,
    /// The continuous posture cost of the same side's worksheet ([`posture_cost`]).
    pub(crate) cost: f64,
}

pub(crate) fn scored(a: &FrameAssessment) -> Result<Option<Scored>, SimError> {
    let Some(h) = a.headline() else {
        return Ok(None);
    };
    Ok(Some(Scored {
        grand: h.scores.final_score,
        regions: BodyRegion::ALL.map(|r| r.score(&h.scores)),
        uncertain: h.uncertain,
        cost: posture_cost(&h.input)?.cost(),
    }))
}

/// The pipeline's headline of a tracked frame.
pub(crate) fn pipeline_headline(tracked: &TrackedFrame) -> Result<Option<Scored>, SimError> {
    match &tracked.assessment {
        Ok(a) => scored(a),
        Err(e) => Err(e.clone().into()),
    }
}

/// The ground truth's headline of every tick (assessed in tick order, unsmoothed).
fn truth_headlines(ticks: &[Tick]) -> Result<Vec<Option<Scored>>, SimError> {
    let mut truth = RulaAssessor::new(truth_config(&AssessmentConfig::new(up()?)))?;
    ticks
        .iter()
        .map(|t| scored(&truth.assess(&t.truth.skeleton)?))
        .collect()
}

/// Warnings the controller's warning tracker raises on the truth's assessments (unsmoothed, every
/// tick).
fn true_warnings_raised(ticks: &[Tick]) -> Result<Vec<RaisedWarning>, SimError> {
    let mut truth = RulaAssessor::new(truth_config(&AssessmentConfig::new(up()?)))?;
    let mut warnings = WarningTracker::new(WarningConfig::default());
    let mut raised = Vec::new();
    for t in ticks {
        let a = truth.assess(&t.truth.skeleton)?;
        raised.extend(warnings.update(&a).iter().filter_map(RaisedWarning::of));
    }
    Ok(raised)
}

/// A posture warning raised (not changed or cleared): where and when, for matching the pipeline's
/// warnings against the truth's.
#[derive(Debug, Clone, Copy, PartialEq)]
struct RaisedWarning {
    stamp_nanos: i64,
    region: BodyRegion,
    side: Option<Side>,
}

impl RaisedWarning {
    fn of(w: &WarningEvent) -> Option<Self> {
        (w.kind == WarningKind::Raised).then_some(Self {
            stamp_nanos: w.stamp_nanos,
            region: w.region,
            side: w.side,
        })
    }
}

/// How many of `a`'s warnings have a warning of `b` for the same region and side within
/// `window_nanos` of their stamp (each of `b`'s used at most once, nearest first).
fn warnings_matched(a: &[RaisedWarning], b: &[RaisedWarning], window_nanos: i64) -> usize {
    let mut used = vec![false; b.len()];
    let mut matched = 0;
    for w in a {
        let nearest = b
            .iter()
            .enumerate()
            .filter(|(j, v)| {
                !used[*j]
                    && v.region == w.region
                    && v.side == w.side
                    && (v.stamp_nanos - w.stamp_nanos).abs() <= window_nanos
            })
            .min_by_key(|(_, v)| (v.stamp_nanos - w.stamp_nanos).abs());
        if let Some((j, _)) = nearest {
            used[j] = true;
            matched += 1;
        }
    }
    matched
}

/// `n` per minute, NaN over no time.
fn per_minute(n: usize, minutes: f64) -> f64 {
    if minutes > 0.0 {
        round6(n as f64 / minutes)
    } else {
        f64::NAN
    }
}

/// Result of [`adaptation`].
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Adaptation {
    /// The heights the experiment stands for.
    pub heights_m: Vec<f64>,
    /// Each height's operator's true stature: the height itself for Drillis & Contini's
    /// proportions, a measured person's own within 1 cm of it (unless none was near).
    pub statures_m: Vec<f64>,
    /// The measured person at each height (ANSUR II `subjectid`), `None` for the proportions.
    pub subject_ids: Vec<Option<u32>>,
    /// Mean RULA grand score (worse side) over the handover frames, noisy pipeline. After
    /// adaptation, an operator outside the statures of their class's trajectory is not served (the
    /// session ends without moving the robot): every "after" value of that height is NaN (`null` in
    /// JSON) and `not_served_after` says why.
    pub mean_grand_score_before: Vec<f64>,
    pub mean_grand_score_after: Vec<f64>,
    /// The same on the ground-truth skeleton.
    pub true_mean_grand_score_before: Vec<f64>,
    pub true_mean_grand_score_after: Vec<f64>,
    /// Mean continuous posture cost (worse side, [`posture_cost`]: the grand score plus how far
    /// each region's angle lies into its band) over the same frames, pipeline and truth.
    pub mean_posture_cost_before: Vec<f64>,
    pub mean_posture_cost_after: Vec<f64>,
    pub true_mean_posture_cost_before: Vec<f64>,
    pub true_mean_posture_cost_after: Vec<f64>,
    /// Mean score per body region (upper_arm, lower_arm, wrist, neck, trunk, legs), per height.
    pub region_names: Vec<String>,
    pub mean_region_scores_before: Vec<Vec<f64>>,
    pub mean_region_scores_after: Vec<Vec<f64>>,
    /// True joint angles of the working side while holding, degrees, per height (mean over frames):
    /// trunk flexion, shoulder flexion, elbow flexion, neck flexion.
    pub angle_names: Vec<String>,
    pub mean_angles_deg_before: Vec<Vec<f64>>,
    pub mean_angles_deg_after: Vec<Vec<f64>>,
    /// Every frame's true angles (same order), before and after, for distributions.
    pub angle_samples_deg_before: Vec<Vec<f64>>,
    pub angle_samples_deg_after: Vec<Vec<f64>>,
    /// The handover point used after adaptation, per height.
    pub handover_after_m: Vec<[f64; 3]>,
    /// Per height: `None` when the cell hands over after adaptation, else why it does not.
    pub not_served_after: Vec<Option<String>>,
}

fn mean(v: &[f64]) -> f64 {
    if v.is_empty() {
        f64::NAN
    } else {
        v.iter().sum::<f64>() / v.len() as f64
    }
}

struct TaskRun {
    grand: Vec<f64>,
    true_grand: Vec<f64>,
    cost: Vec<f64>,
    true_cost: Vec<f64>,
    regions: Vec<[f64; 6]>,
    angles: Vec<[f64; 4]>,
}

impl TaskRun {
    /// No handover took place: every mean is NaN.
    fn empty() -> Self {
        Self {
            grand: Vec::new(),
            true_grand: Vec::new(),
            cost: Vec::new(),
            true_cost: Vec::new(),
            regions: Vec::new(),
            angles: Vec::new(),
        }
    }
}

fn run_task(
    setup: &Setup,
    session: usize,
    op: &Operator,
    handover: Point3<f64>,
    cycles: usize,
) -> Result<TaskRun, SimError> {
    let mut script = SessionScript::new(handover);
    script.cycles = cycles;
    let ticks = simulate_operator(setup, session, *op, &script)?;
    let truth = truth_headlines(&ticks)?;
    let mut out = TaskRun::empty();
    let holding = |t: &Tick| matches!(t.truth.phase, Phase::Hold { .. });
    // The truth and its angles over every holding tick; the pipeline over the frames it released
    // whose nearest tick is a holding one.
    for (tick, t) in ticks.iter().zip(&truth) {
        if !holding(tick) {
            continue;
        }
        if let Some(t) = t {
            out.true_grand.push(f64::from(t.grand));
            out.true_cost.push(t.cost);
        }
        let q = &tick.truth.posture;
        let arm = q.working_arm(op.right_handed);
        out.angles.push(
            [
                q.trunk_flexion_rad,
                arm.flexion_rad,
                arm.elbow_flexion_rad,
                q.neck_flexion_rad,
            ]
            .map(f64::to_degrees),
        );
    }
    run_pipeline(setup, &ticks, |k, tracked| {
        if holding(&ticks[k]) {
            if let Some(e) = pipeline_headline(tracked)? {
                out.grand.push(f64::from(e.grand));
                out.cost.push(e.cost);
                out.regions.push(e.regions.map(f64::from));
            }
        }
        Ok(())
    })?;
    Ok(out)
}

/// Heights 1.50–2.00 m in 5 cm steps.
pub fn adaptation_heights() -> Vec<f64> {
    (0..=10)
        .map(|i| round6(1.50 + 0.05 * f64::from(i)))
        .collect()
}

/// `n` operators' statures, evenly from 1.55 to 1.95 m, to the micrometre (one operator: 1.55 m):
/// the operators of `table1`, `rula_agreement` and the warnings.
pub fn operator_statures(n: usize) -> Vec<f64> {
    (0..n)
        .map(|i| round6(1.55 + 0.40 * i as f64 / (n.max(2) - 1) as f64))
        .collect()
}

/// Whose bodies the adaptation experiment's operators have.
#[derive(Debug, Clone, Copy)]
pub enum AdaptationBodies<'a> {
    /// Drillis & Contini's proportions at exactly each height (the robot's planning model).
    Proportions,
    /// Measured people: at each height, one of these people within 1 cm of it (the nearest when
    /// none is), drawn by the seed. The caller passes ANSUR II's reporting half, never fitted.
    Measured(&'a [Person]),
}

/// The person of `people` standing in for `height_m` in session `session` of `seed`: one of those
/// within 1 cm, drawn by the session's seed; the nearest when none is. `None` for no people.
pub fn person_near(people: &[Person], height_m: f64, seed: u64, session: usize) -> Option<&Person> {
    let near: Vec<&Person> = people
        .iter()
        .filter(|p| (p.stature_m - height_m).abs() <= 0.01 + 1e-9)
        .collect();
    if near.is_empty() {
        return people.iter().min_by(|a, b| {
            (a.stature_m - height_m)
                .abs()
                .total_cmp(&(b.stature_m - height_m).abs())
        });
    }
    let mut rng = ChaCha8Rng::seed_from_u64(session_seed(seed, session));
    Some(near[rng.random_range(0..near.len())])
}

/// The paper's Figs. 7–9: RULA before vs after the class-specific handover. Each height's operator
/// is served by the class of their own true stature (the paper's protocol), and holds the part in
/// the same session (seed, habits, cameras) before and after: only the handover point differs.
pub fn adaptation(
    setup: &Setup,
    handovers: &Handovers,
    heights_m: &[f64],
    bodies: AdaptationBodies<'_>,
    cycles: usize,
    progress: Progress<'_>,
) -> Result<Adaptation, SimError> {
    let thresholds = HeightConfig::new(up()?).thresholds;
    let mut r = Adaptation {
        heights_m: heights_m.to_vec(),
        statures_m: Vec::new(),
        subject_ids: Vec::new(),
        mean_grand_score_before: Vec::new(),
        mean_grand_score_after: Vec::new(),
        true_mean_grand_score_before: Vec::new(),
        true_mean_grand_score_after: Vec::new(),
        mean_posture_cost_before: Vec::new(),
        mean_posture_cost_after: Vec::new(),
        true_mean_posture_cost_before: Vec::new(),
        true_mean_posture_cost_after: Vec::new(),
        region_names: BodyRegion::ALL
            .iter()
            .map(|b| b.name().to_owned())
            .collect(),
        mean_region_scores_before: Vec::new(),
        mean_region_scores_after: Vec::new(),
        angle_names: [
            "trunk_flexion",
            "shoulder_flexion",
            "elbow_flexion",
            "neck_flexion",
        ]
        .map(str::to_owned)
        .to_vec(),
        mean_angles_deg_before: Vec::new(),
        mean_angles_deg_after: Vec::new(),
        angle_samples_deg_before: vec![Vec::new(); 4],
        angle_samples_deg_after: vec![Vec::new(); 4],
        handover_after_m: Vec::new(),
        not_served_after: Vec::new(),
    };
    let total = 2 * heights_m.len();
    for (i, &nominal) in heights_m.iter().enumerate() {
        let (op, subject_id) = match bodies {
            AdaptationBodies::Proportions => (Operator::new(nominal)?, None),
            AdaptationBodies::Measured(people) => {
                let p =
                    person_near(people, nominal, setup.seed, i).ok_or(SimError::BadParameter {
                        name: "people",
                        value: 0.0,
                        why: "measured bodies need at least one person",
                    })?;
                (Operator::measured(p)?, Some(p.subject_id))
            }
        };
        let h = op.stature_m();
        r.statures_m.push(round6(h));
        r.subject_ids.push(subject_id);
        let class = HeightClass::of(h, &thresholds);
        let after_point = handovers.for_class(class);
        r.handover_after_m
            .push([after_point.x, after_point.y, after_point.z]);
        // The paper's protocol: the class of the true stature, so the interval is the point.
        let served = handovers.serves(class, [h, h]);
        r.not_served_after.push((!served).then(|| {
            let [lo, hi] = handovers.served_m(class);
            format!(
                "{h:.2} m is outside the statures class {}'s trajectory is served for \
                 ({lo:.2}–{hi:.2} m): the session ends without moving the robot",
                class.name()
            )
        }));
        for (k, point) in [handovers.before_m, after_point].into_iter().enumerate() {
            // The same session seed before and after: only the handover point differs.
            let run = if k == 1 && !served {
                TaskRun::empty()
            } else {
                run_task(setup, i, &op, point, cycles)?
            };
            let regions: Vec<f64> = (0..6)
                .map(|j| round6(mean(&run.regions.iter().map(|x| x[j]).collect::<Vec<_>>())))
                .collect();
            let angles: Vec<f64> = (0..4)
                .map(|j| round6(mean(&run.angles.iter().map(|x| x[j]).collect::<Vec<_>>())))
                .collect();
            let (grand, true_grand) = (round6(mean(&run.grand)), round6(mean(&run.true_grand)));
            let (cost, true_cost) = (round6(mean(&run.cost)), round6(mean(&run.true_cost)));
            let samples = if k == 0 {
                r.mean_grand_score_before.push(grand);
                r.true_mean_grand_score_before.push(true_grand);
                r.mean_posture_cost_before.push(cost);
                r.true_mean_posture_cost_before.push(true_cost);
                r.mean_region_scores_before.push(regions);
                r.mean_angles_deg_before.push(angles);
                &mut r.angle_samples_deg_before
            } else {
                r.mean_grand_score_after.push(grand);
                r.true_mean_grand_score_after.push(true_grand);
                r.mean_posture_cost_after.push(cost);
                r.true_mean_posture_cost_after.push(true_cost);
                r.mean_region_scores_after.push(regions);
                r.mean_angles_deg_after.push(angles);
                &mut r.angle_samples_deg_after
            };
            for a in &run.angles {
                for j in 0..4 {
                    samples[j].push(round6(a[j]));
                }
            }
            progress(2 * i + k + 1, total);
        }
    }
    Ok(r)
}

// ---------------------------------------------------------------------------------------------
// Height

/// One operator of the height experiment.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct HeightRow {
    /// The ANSUR II person simulated.
    pub subject_id: u32,
    pub true_m: f64,
    pub estimated_m: Option<f64>,
    /// The estimate's stated uncertainty (1σ), metres: at the decision, or at the end when undecided.
    pub uncertainty_m: Option<f64>,
    pub true_class: HeightClass,
    /// `None` = undecided.
    pub decided_class: Option<HeightClass>,
    /// How the class was decided: `interval` (the ±kσ interval inside one class: a wrong class
    /// here is confidently wrong) or across a boundary (a stated probability below certainty).
    pub basis: Option<DecisionBasis>,
    /// The decision's stated probability that its class is the true one.
    pub probability: Option<f64>,
    /// Seconds from the operator's arrival at the station (standing upright) to the decision; 0
    /// when decided on the way in.
    pub decided_after_s: Option<f64>,
    /// The decision's RULA cost: the class's curve minus the true class's curve at the true
    /// stature (grand score; `None` without curves or undecided).
    pub rula_cost: Option<f64>,
    /// Whether any trajectory serves this stature at all (inside some class's served range).
    pub servable: bool,
}

/// Result of [`height`].
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct HeightResult {
    /// The cell's ear offset, as its calibration sessions measured it (or the default).
    pub calibration: EarOffset,
    /// The detector's true ear offset in this run, metres.
    pub detector_ear_offset_m: f64,
    /// Mean absolute stature error over operators with an estimate, metres.
    pub mae_m: f64,
    /// Share of all operators whose decided class is correct.
    pub class_accuracy: f64,
    /// The same over operators more than 2 cm from a class boundary.
    pub class_accuracy_beyond_2cm: f64,
    /// Operators given a wrong class although their whole interval lay inside it.
    pub confidently_wrong: usize,
    /// Operators given the neighbouring class across a boundary (stated probability below
    /// certainty).
    pub wrong_across_boundary: usize,
    /// Servable operators left undecided.
    pub undecided: usize,
    /// Operators whose stature no trajectory serves (never given a class, by design).
    pub not_servable: usize,
    /// Operators within 2 cm of a class boundary.
    pub near_boundary: usize,
    /// Decided operators per class.
    pub decided_per_class: [usize; 3],
    /// Seconds from arrival at the station to the decision: median and 95th percentile.
    pub decision_time_median_s: f64,
    pub decision_time_p95_s: f64,
    /// The decisions' RULA cost (chosen class minus true class at the true stature): mean and worst
    /// over the decided operators (`None` without curves).
    pub rula_cost_mean: Option<f64>,
    pub rula_cost_worst: Option<f64>,
    /// The half-width of the stated interval in σ (the estimator's `decision_sigmas`).
    pub interval_sigmas: f64,
    /// Empirical coverage: the share of operators with an estimate whose true stature lies inside the
    /// stated interval `estimate ± interval_sigmas · σ` (nominal ≈ 0.954 for 2σ of a normal error),
    /// and inside `estimate ± σ` (nominal ≈ 0.683).
    pub coverage: f64,
    pub coverage_1sigma: f64,
    pub operators: Vec<HeightRow>,
}

/// What the height experiment simulates besides the rig and the detector.
#[derive(Debug, Clone, PartialEq)]
pub struct HeightOptions {
    /// Operators drawn, without replacement, from the reporting half of the people (odd subject ids).
    pub count: usize,
    /// Seconds each operator stands idle at the station.
    pub idle_secs: f64,
    /// Calibration sessions drawn from the fitting half (even subject ids) before the operators, as
    /// `ergocell height calibrate` would run them; 0 = an uncalibrated cell.
    pub calibration_sessions: usize,
    /// The classes' RULA-versus-stature curves the decision and its cost use.
    pub rula: Option<HandoverRula>,
    /// The decision interval's half-width in σ; `None`: the cell's (`HeightConfig::decision_sigmas`).
    pub decision_sigmas: Option<f64>,
}

use ergocell_perception::metrics::rank_quantile as quantile;

/// Draws `k` distinct indices of `0..n` (a partial Fisher–Yates shuffle).
fn draw(rng: &mut ChaCha8Rng, n: usize, k: usize) -> Vec<usize> {
    let mut idx: Vec<usize> = (0..n).collect();
    let k = k.min(n);
    for i in 0..k {
        let j = i + (rng.random::<f64>() * (n - i) as f64) as usize;
        idx.swap(i, j.min(n - 1));
    }
    idx.truncate(k);
    idx
}

/// The cell controller's pipeline as `config/cell.toml`'s defaults set it up (the operator zone
/// around the station at the world origin, so the height is measured only there).
fn cell_pipeline() -> Result<PipelineConfig, SimError> {
    Ok(ergocell_cell::CellSettings::default().pipeline(up()?)?)
}

/// One person standing idle at the station: the ticks, with the detector of `setup`.
fn simulate_person(
    setup: &Setup,
    session: usize,
    person: &Person,
    handovers: &Handovers,
    idle_secs: f64,
) -> Result<Vec<Tick>, SimError> {
    let mut script = SessionScript::new(handovers.before_m);
    script.cycles = 0;
    script.idle_secs = idle_secs;
    script.walk_out_secs = 0.0;
    let config = SimConfig {
        noise: setup.noise,
        ..SimConfig::new(session_seed(setup.seed, session))
    };
    Simulation::new(
        setup.rig.clone(),
        Operator::measured(person)?,
        script,
        config,
    )?
    .collect()
}

/// The operator's stature as a cell calibrates it: measured over the whole session with no ear
/// offset subtracted, as `ergocell height calibrate` does.
fn calibration_sample(
    setup: &Setup,
    ticks: &[Tick],
    person: &Person,
) -> Result<Option<CalibrationSample>, SimError> {
    let mut config = cell_pipeline()?;
    config.height.min_frames = usize::MAX;
    config.height.ear_offset = EarOffset {
        offset_m: 0.0,
        ..EarOffset::default()
    };
    let p = run_pipeline_with(setup, config, ticks, |_, _| Ok(()))?;
    Ok(match p.height_status() {
        HeightStatus::Measuring {
            estimate: Some(e), ..
        } => Some(CalibrationSample::from_estimate(&e, person.stature_m)),
        _ => None,
    })
}

/// The stature experiment on measured people: ANSUR II adults (the reporting half, odd subject ids,
/// never used to fit the stature model or calibrate) each standing idle at the station for
/// `idle_secs`, after the cell was calibrated on `calibration_sessions` people of the fitting half.
pub fn height(
    setup: &Setup,
    handovers: &Handovers,
    people: &[Person],
    options: &HeightOptions,
    progress: Progress<'_>,
) -> Result<HeightResult, SimError> {
    let fit: Vec<&Person> = people.iter().filter(|p| p.split() == Split::Fit).collect();
    let report: Vec<&Person> = people
        .iter()
        .filter(|p| p.split() == Split::Report)
        .collect();
    let mut rng = ChaCha8Rng::seed_from_u64(setup.seed);
    rng.set_stream(8);
    let total = options.calibration_sessions + options.count;
    // 1. Calibration: sessions 1_000_000.. keep their seeds apart from the operators'.
    let calibration = if options.calibration_sessions == 0 {
        EarOffset::default()
    } else {
        let mut samples = Vec::new();
        for (k, i) in draw(&mut rng, fit.len(), options.calibration_sessions)
            .into_iter()
            .enumerate()
        {
            let ticks =
                simulate_person(setup, 1_000_000 + k, fit[i], handovers, options.idle_secs)?;
            if let Some(s) = calibration_sample(setup, &ticks, fit[i])? {
                samples.push(s);
            }
            progress(k + 1, total);
        }
        calibrate_ear_offset(&samples)?
    };

    // 2. The operators.
    let served = handovers.served()?;
    let mut config = cell_pipeline()?;
    config.height.ear_offset = calibration;
    config.height.served_m = Some(served);
    config.height.handover_rula.clone_from(&options.rula);
    if let Some(k) = options.decision_sigmas {
        config.height.decision_sigmas = k;
    }
    let t = config.height.thresholds;
    let k = config.height.decision_sigmas;
    let mut population = ChaCha8Rng::seed_from_u64(setup.seed);
    population.set_stream(7);
    let mut rows = Vec::with_capacity(options.count);
    for (i, j) in draw(&mut population, report.len(), options.count)
        .into_iter()
        .enumerate()
    {
        let person = report[j];
        let h = person.stature_m;
        let ticks = simulate_person(setup, i, person, handovers, options.idle_secs)?;
        let arrived = ticks
            .iter()
            .find(|t| t.truth.phase != Phase::WalkIn)
            .map_or(0, |t| t.truth.stamp_nanos);
        // The height as the session decides it: the pipeline's first decision, which is final.
        let pipeline = run_pipeline_with(setup, config.clone(), &ticks, |_, _| Ok(()))?;
        let (estimate, decision) = match pipeline.height_status() {
            HeightStatus::Decided(d) => (Some(d.estimate.clone()), Some(d)),
            HeightStatus::Measuring { estimate, .. } => (estimate, None),
        };
        let true_class = HeightClass::of(h, &t);
        let rula_cost = decision.as_ref().and_then(|d| {
            options
                .rula
                .as_ref()
                .map(|c| round6(c.at(d.class, h) - c.at(true_class, h)))
        });
        rows.push(HeightRow {
            subject_id: person.subject_id,
            true_m: round6(h),
            estimated_m: estimate.as_ref().map(|e| round6(e.height_m)),
            uncertainty_m: estimate.as_ref().map(|e| round6(e.uncertainty_m)),
            true_class,
            decided_class: decision.as_ref().map(|d| d.class),
            basis: decision.as_ref().map(|d| d.basis),
            probability: decision.as_ref().map(|d| round6(d.probability)),
            decided_after_s: decision
                .as_ref()
                .map(|d| round6(((d.stamp_nanos - arrived) as f64 * 1e-9).max(0.0))),
            rula_cost,
            servable: HeightClass::ALL.iter().any(|c| {
                let [lo, hi] = served.of(*c);
                (lo..=hi).contains(&h)
            }),
        });
        progress(options.calibration_sessions + i + 1, total);
    }
    let count = rows.len();
    let errors: Vec<f64> = rows
        .iter()
        .filter_map(|r| r.estimated_m.map(|e| (e - r.true_m).abs()))
        .collect();
    let near = |r: &HeightRow| {
        (r.true_m - t.c1_below_m()).abs() <= 0.02 || (r.true_m - t.c2_up_to_m()).abs() <= 0.02
    };
    let beyond: Vec<&HeightRow> = rows.iter().filter(|r| !near(r)).collect();
    let covered = |sigmas: f64| {
        let with: Vec<bool> = rows
            .iter()
            .filter_map(|r| {
                let (e, u) = (r.estimated_m?, r.uncertainty_m?);
                Some((e - r.true_m).abs() <= sigmas * u)
            })
            .collect();
        round6(with.iter().filter(|c| **c).count() as f64 / with.len().max(1) as f64)
    };
    let mut times: Vec<f64> = rows.iter().filter_map(|r| r.decided_after_s).collect();
    times.sort_by(f64::total_cmp);
    let costs: Vec<f64> = rows.iter().filter_map(|r| r.rula_cost).collect();
    let wrong = |r: &&HeightRow| r.decided_class.is_some_and(|c| c != r.true_class);
    Ok(HeightResult {
        calibration,
        detector_ear_offset_m: setup.noise.ear_offset_m,
        interval_sigmas: k,
        coverage: covered(k),
        coverage_1sigma: covered(1.0),
        mae_m: round6(mean(&errors)),
        class_accuracy: round6(
            rows.iter()
                .filter(|r| r.decided_class == Some(r.true_class))
                .count() as f64
                / count.max(1) as f64,
        ),
        class_accuracy_beyond_2cm: round6(
            beyond
                .iter()
                .filter(|r| r.decided_class == Some(r.true_class))
                .count() as f64
                / beyond.len().max(1) as f64,
        ),
        confidently_wrong: rows
            .iter()
            .filter(wrong)
            .filter(|r| r.basis == Some(DecisionBasis::Interval))
            .count(),
        wrong_across_boundary: rows
            .iter()
            .filter(wrong)
            .filter(|r| r.basis != Some(DecisionBasis::Interval))
            .count(),
        undecided: rows
            .iter()
            .filter(|r| r.servable && r.decided_class.is_none())
            .count(),
        not_servable: rows.iter().filter(|r| !r.servable).count(),
        near_boundary: rows.iter().filter(|r| near(r)).count(),
        decided_per_class: HeightClass::ALL
            .map(|c| rows.iter().filter(|r| r.decided_class == Some(c)).count()),
        decision_time_median_s: round6(quantile(&times, 0.5)),
        decision_time_p95_s: round6(quantile(&times, 0.95)),
        rula_cost_mean: (!costs.is_empty()).then(|| round6(mean(&costs))),
        rula_cost_worst: costs.iter().copied().max_by(f64::total_cmp).map(round6),
        operators: rows,
    })
}

// ---------------------------------------------------------------------------------------------
// Each class's RULA at its handover point, per stature

/// Statures of the handover-RULA curves: 1.40–2.10 m in 2 cm steps (beyond every served range).
pub fn handover_rula_statures() -> Vec<f64> {
    (0..=35)
        .map(|i| round6(1.40 + 0.02 * f64::from(i)))
        .collect()
}

/// Each class's RULA-versus-stature curve: the mean true RULA grand score (worse side) over the
/// holding frames of an operator of each stature (Drillis & Contini's proportions, the robot's
/// planning model) handed the part at the class's handover point, averaged over `seeds` (each a
/// session of `cycles` handovers). The ground truth, not the pipeline: the curve is what the class
/// does to the operator, not what the cameras measure of it.
pub fn handover_rula(
    rig: &CameraRig,
    handovers: &Handovers,
    statures_m: &[f64],
    cycles: usize,
    seeds: &[u64],
    progress: Progress<'_>,
) -> Result<HandoverRula, SimError> {
    let total = statures_m.len() * 3 * seeds.len();
    let mut done = 0;
    let mut curves = [Vec::new(), Vec::new(), Vec::new()];
    for (i, &h) in statures_m.iter().enumerate() {
        for (k, class) in HeightClass::ALL.into_iter().enumerate() {
            let mut per_seed = Vec::new();
            for &seed in seeds {
                let setup = Setup {
                    rig: rig.clone(),
                    noise: DetectorNoise::none(),
                    seed,
                };
                let mut script = SessionScript::new(handovers.for_class(class));
                script.cycles = cycles;
                let ticks = simulate(&setup, i, h, &script)?;
                let truth = truth_headlines(&ticks)?;
                let grand: Vec<f64> = ticks
                    .iter()
                    .zip(&truth)
                    .filter(|(t, _)| matches!(t.truth.phase, Phase::Hold { .. }))
                    .filter_map(|(_, s)| s.map(|s| f64::from(s.grand)))
                    .collect();
                per_seed.push(mean(&grand));
                done += 1;
                progress(done, total);
            }
            let m = mean(&per_seed);
            if !m.is_finite() {
                return Err(SimError::BadParameter {
                    name: "stature_m",
                    value: h,
                    why: "no holding frame was scored at this stature: no curve point",
                });
            }
            curves[k].push((m * 1e4).round() / 1e4);
        }
    }
    let [c1, c2, c3] = curves;
    let rula = HandoverRula {
        statures_m: statures_m.to_vec(),
        c1,
        c2,
        c3,
    };
    rula.check()?;
    Ok(rula)
}

// ---------------------------------------------------------------------------------------------
// RULA agreement

/// Exact agreement and Cohen's κ of one score.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Agreement {
    pub exact: f64,
    pub kappa: f64,
    /// `confusion[truth][estimate]`, scores 1..=n mapped to 0..n.
    pub confusion: Vec<Vec<usize>>,
}

/// Result of [`rula_agreement`].
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct RulaAgreement {
    /// The pipeline scored on a fixed-lag smoother of this many seconds either side
    /// ([`PipelineConfig::fixed_lag_s`], the controller's default); absent: on the causal filter.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub fixed_lag_s: Option<f64>,
    pub grand_score: Agreement,
    pub action_level: Agreement,
    /// Exact agreement of each region's score (upper_arm, lower_arm, wrist, neck, trunk, legs): where
    /// the disagreement comes from.
    pub region_names: Vec<String>,
    pub region_exact: Vec<f64>,
    /// Mean region score, noisy pipeline minus ground truth (positive = the pipeline scores higher).
    pub region_mean_difference: Vec<f64>,
    /// Per region, `confusion[truth][estimate]` of the region score (1..=6 mapped to 0..6).
    pub region_confusion: Vec<Vec<Vec<usize>>>,
    /// Frames whose grand score differs although every region score agrees: the muscle-use
    /// adjustment (from the time series) differs.
    pub grand_differs_with_regions_equal: usize,
    /// Frames scored by both.
    pub frames: usize,
    /// Of those, the frames whose pipeline score the assessor marked uncertain, and the grand score's
    /// exact agreement among them and among the rest (NaN, `null` in JSON, for an empty group):
    /// whether the flag tells the reviewer anything.
    pub uncertain_frames: usize,
    pub grand_exact_uncertain: f64,
    pub grand_exact_certain: f64,
    /// Posture warnings raised per minute of session (every frame, not only at the station): by the
    /// pipeline, and by the same warning tracker on the truth's assessments. An operator told of a
    /// posture more often than the truth would tell them learns to ignore the display.
    pub warnings_per_min: f64,
    pub true_warnings_per_min: f64,
    /// The same as counts: warnings raised by the pipeline and on the truth, over `minutes`.
    pub warnings_raised: usize,
    pub true_warnings_raised: usize,
    pub minutes: f64,
    /// Of the truth's warnings, those the pipeline also raised (same region and side, within the
    /// warnings' dwell time of the truth's stamp): an operator must get the warnings that matter,
    /// not only few of them.
    pub true_warnings_caught: usize,
    /// Of the pipeline's warnings, those the truth also raised (the same match).
    pub warnings_confirmed: usize,
    pub statures_m: Vec<f64>,
}

/// Exact agreement and Cohen's κ from a confusion matrix.
pub fn agreement(confusion: Vec<Vec<usize>>) -> Agreement {
    let n: usize = confusion.iter().flatten().sum();
    let k = confusion.len();
    if n == 0 {
        return Agreement {
            exact: f64::NAN,
            kappa: f64::NAN,
            confusion,
        };
    }
    let nf = n as f64;
    let po = (0..k).map(|i| confusion[i][i]).sum::<usize>() as f64 / nf;
    let pe: f64 = (0..k)
        .map(|i| {
            let row: usize = confusion[i].iter().sum();
            let col: usize = confusion.iter().map(|r| r[i]).sum();
            row as f64 * col as f64 / (nf * nf)
        })
        .sum();
    let kappa = if (1.0 - pe).abs() < 1e-12 {
        1.0
    } else {
        (po - pe) / (1.0 - pe)
    };
    Agreement {
        exact: round6(po),
        kappa: round6(kappa),
        confusion,
    }
}

/// Per-frame RULA from the noisy pipeline vs from ground truth, for operators of `statures_m` doing
/// `cycles` handovers at the unadapted handover point (a spread of postures and scores).
pub fn rula_agreement(
    setup: &Setup,
    handovers: &Handovers,
    statures_m: &[f64],
    cycles: usize,
    progress: Progress<'_>,
) -> Result<RulaAgreement, SimError> {
    rula_agreement_with(setup, handovers, statures_m, cycles, None, progress)
}

/// [`rula_agreement`] on the controller's pipeline with its fixed lag set to `fixed_lag_s` seconds
/// ([`PipelineConfig::fixed_lag_s`]: no causal filter; each tracked frame scored and warned about on
/// its mean over the half window either side, that much later); `Some(0.0)`: the causal filter
/// instead; `None`: the controller's default.
pub fn rula_agreement_with(
    setup: &Setup,
    handovers: &Handovers,
    statures_m: &[f64],
    cycles: usize,
    fixed_lag_s: Option<f64>,
    progress: Progress<'_>,
) -> Result<RulaAgreement, SimError> {
    let mut config = PipelineConfig::new(up()?);
    match fixed_lag_s {
        Some(0.0) => config.fixed_lag_s = None,
        Some(w) => config.fixed_lag_s = Some(w),
        None => {}
    }
    let mut grand = vec![vec![0usize; 7]; 7];
    let mut level = vec![vec![0usize; 4]; 4];
    let mut frames = 0;
    let mut region_same = [0usize; 6];
    let mut region_diff = [0i64; 6];
    let mut region_confusion = vec![vec![vec![0usize; 6]; 6]; 6];
    let mut grand_differs_with_regions_equal = 0;
    // [certain, uncertain]: (frames, grand score equal)
    let mut by_flag = [(0usize, 0usize); 2];
    let (mut raised, mut true_raised, mut minutes) = (0usize, 0usize, 0.0);
    let (mut caught, mut confirmed) = (0usize, 0usize);
    let match_window = WarningConfig::default().dwell_nanos;
    for (i, &h) in statures_m.iter().enumerate() {
        let mut script = SessionScript::new(handovers.before_m);
        script.cycles = cycles;
        let ticks = simulate(setup, i, h, &script)?;
        let truth = truth_headlines(&ticks)?;
        let true_warnings = true_warnings_raised(&ticks)?;
        true_raised += true_warnings.len();
        let mut warnings: Vec<RaisedWarning> = Vec::new();
        if let (Some(first), Some(last)) = (ticks.first(), ticks.last()) {
            minutes += (last.frame.stamp_nanos - first.frame.stamp_nanos) as f64 / 60e9;
        }
        // (tick index, the pipeline's headline) of every tracked frame
        let mut scores: Vec<(usize, Option<Scored>)> = Vec::new();
        run_pipeline_with(setup, config.clone(), &ticks, |k, tracked| {
            warnings.extend(tracked.warnings.iter().filter_map(RaisedWarning::of));
            scores.push((k, pipeline_headline(tracked)?));
            Ok(())
        })?;
        raised += warnings.len();
        caught += warnings_matched(&true_warnings, &warnings, match_window);
        confirmed += warnings_matched(&warnings, &true_warnings, match_window);
        for (k, e) in scores {
            if !at_station(ticks[k].truth.phase) {
                continue;
            }
            if let (Some(e), Some(t)) = (e, truth[k]) {
                let (ge, gt) = (
                    usize::from(e.grand.clamp(1, 7)),
                    usize::from(t.grand.clamp(1, 7)),
                );
                grand[gt - 1][ge - 1] += 1;
                let (le, lt) = (
                    usize::from(action_level(e.grand).clamp(1, 4)),
                    usize::from(action_level(t.grand).clamp(1, 4)),
                );
                level[lt - 1][le - 1] += 1;
                for j in 0..6 {
                    region_same[j] += usize::from(e.regions[j] == t.regions[j]);
                    region_diff[j] += i64::from(e.regions[j]) - i64::from(t.regions[j]);
                    let (re, rt) = (
                        usize::from(e.regions[j].clamp(1, 6)),
                        usize::from(t.regions[j].clamp(1, 6)),
                    );
                    region_confusion[j][rt - 1][re - 1] += 1;
                }
                grand_differs_with_regions_equal +=
                    usize::from(e.grand != t.grand && e.regions == t.regions);
                let flag = &mut by_flag[usize::from(e.uncertain)];
                flag.0 += 1;
                flag.1 += usize::from(e.grand == t.grand);
                frames += 1;
            }
        }
        progress(i + 1, statures_m.len());
    }
    // NaN (null in JSON) when no frame is in the group: no agreement to report.
    let share = |(n, same): (usize, usize)| {
        if n == 0 {
            f64::NAN
        } else {
            round6(same as f64 / n as f64)
        }
    };
    Ok(RulaAgreement {
        fixed_lag_s: config.fixed_lag_s,
        grand_score: agreement(grand),
        action_level: agreement(level),
        region_names: BodyRegion::ALL
            .iter()
            .map(|b| b.name().to_owned())
            .collect(),
        region_exact: region_same
            .iter()
            .map(|n| round6(*n as f64 / frames.max(1) as f64))
            .collect(),
        region_mean_difference: region_diff
            .iter()
            .map(|n| round6(*n as f64 / frames.max(1) as f64))
            .collect(),
        region_confusion,
        grand_differs_with_regions_equal,
        frames,
        uncertain_frames: by_flag[1].0,
        grand_exact_uncertain: share(by_flag[1]),
        grand_exact_certain: share(by_flag[0]),
        warnings_per_min: per_minute(raised, minutes),
        true_warnings_per_min: per_minute(true_raised, minutes),
        warnings_raised: raised,
        true_warnings_raised: true_raised,
        minutes: round6(minutes),
        true_warnings_caught: caught,
        warnings_confirmed: confirmed,
        statures_m: statures_m.to_vec(),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn warnings_match_by_region_side_and_time_each_once() {
        let w = |secs: f64, region: BodyRegion, side: Option<Side>| RaisedWarning {
            stamp_nanos: (secs * 1e9) as i64,
            region,
            side,
        };
        let truth = [
            w(10.0, BodyRegion::Neck, None),
            w(10.5, BodyRegion::Neck, None),
            w(20.0, BodyRegion::Wrist, Some(Side::Left)),
            w(30.0, BodyRegion::Trunk, None),
        ];
        let pipeline = [
            // one neck warning can stand for one of the truth's two, not both
            w(11.0, BodyRegion::Neck, None),
            // the other wrist
            w(20.0, BodyRegion::Wrist, Some(Side::Right)),
            // too late
            w(32.5, BodyRegion::Trunk, None),
        ];
        let window = 2_000_000_000;
        assert_eq!(warnings_matched(&truth, &pipeline, window), 1);
        assert_eq!(warnings_matched(&pipeline, &truth, window), 1);
        assert_eq!(warnings_matched(&truth, &truth, window), truth.len());
        assert_eq!(warnings_matched(&truth, &[], window), 0);
        // within the window, on either side
        let early = [w(28.0, BodyRegion::Trunk, None)];
        assert_eq!(warnings_matched(&truth, &early, window), 1);
    }

    #[test]
    fn kappa_of_perfect_and_chance_agreement() {
        let perfect = agreement(vec![vec![5, 0], vec![0, 5]]);
        assert_eq!((perfect.exact, perfect.kappa), (1.0, 1.0));
        // Independent raters at 50/50: Po = 0.5, Pe = 0.5, κ = 0.
        let chance = agreement(vec![vec![25, 25], vec![25, 25]]);
        assert_eq!((chance.exact, chance.kappa), (0.5, 0.0));
        // A textbook example: 20/5/10/15 → Po = 0.7, Pe = 0.5, κ = 0.4.
        let k = agreement(vec![vec![20, 5], vec![10, 15]]);
        assert!((k.exact - 0.7).abs() < 1e-9 && (k.kappa - 0.4).abs() < 1e-9);
        assert!(agreement(vec![vec![0]]).exact.is_nan());
    }

    #[test]
    fn adaptation_heights_are_eleven_five_centimetre_steps() {
        let h = adaptation_heights();
        assert_eq!(h.len(), 11);
        assert_eq!(h[0], 1.5);
        assert_eq!(h[10], 2.0);
        assert_eq!(h[5], 1.75);
    }

    #[test]
    fn the_person_near_a_height_is_within_a_centimetre_drawn_by_the_seed_or_the_nearest() {
        let people: Vec<Person> = ergocell_anthropometry::ansur::people()
            .unwrap()
            .into_iter()
            .filter(|p| p.split() == Split::Report)
            .collect();
        let near = |h: f64, seed: u64, session: usize| {
            person_near(&people, h, seed, session).unwrap().subject_id
        };
        let within = people
            .iter()
            .filter(|p| (p.stature_m - 1.75).abs() <= 0.01)
            .count();
        assert!(within > 10, "{within}");
        let mut drawn = std::collections::BTreeSet::new();
        for seed in 301..=340 {
            let id = near(1.75, seed, 5);
            // the same seed and session draw the same person
            assert_eq!(id, near(1.75, seed, 5));
            let p = people.iter().find(|p| p.subject_id == id).unwrap();
            assert!((p.stature_m - 1.75).abs() <= 0.01 + 1e-9, "{}", p.stature_m);
            assert_eq!(p.split(), Split::Report);
            drawn.insert(id);
        }
        // different seeds stand different people in
        assert!(drawn.len() > 10, "{}", drawn.len());
        // nobody within a centimetre of 2.30 m: the tallest person
        let tallest = people
            .iter()
            .max_by(|a, b| a.stature_m.total_cmp(&b.stature_m))
            .unwrap();
        assert_eq!(near(2.30, 1, 0), tallest.subject_id);
        assert!(person_near(&[], 1.75, 1, 0).is_none());
    }

    #[test]
    fn operator_statures_run_evenly_from_1_55_to_1_95_m() {
        assert_eq!(operator_statures(5), vec![1.55, 1.65, 1.75, 1.85, 1.95]);
        assert_eq!(operator_statures(2), vec![1.55, 1.95]);
        assert_eq!(operator_statures(1), vec![1.55]);
        assert!(operator_statures(0).is_empty());
        let many = operator_statures(7);
        assert_eq!((many[0], many[6]), (1.55, 1.95));
        assert!(many.windows(2).all(|w| w[0] < w[1]));
        // to the micrometre: a third of 0.40 m is not carried further
        assert_eq!(operator_statures(4)[1], 1.683_333);
    }

    #[test]
    fn a_cells_handovers_are_its_class_files_placed_by_its_station() {
        let cell_text = include_str!("../../config/cell.toml");
        let moved = cell_text.replacen("xyz_m = [0.0, 0.0, 0.0]", "xyz_m = [1.0, 2.0, 0.0]", 1);
        assert_ne!(moved, cell_text, "the shipped station is at the origin");
        let cell = ergocell_robot::CellConfig::from_toml_str(&moved).unwrap();
        let specs = [
            include_str!("../../trajectories/c1.toml"),
            include_str!("../../trajectories/c2.toml"),
            include_str!("../../trajectories/c3.toml"),
        ]
        .map(|t| ergocell_robot::TrajectorySpec::from_toml_str(t).unwrap());
        let h = Handovers::from_cell(&cell, &specs, [0.41, -0.10, 1.055]);
        assert!((h.before_m - Point3::new(1.41, 1.90, 1.055)).norm() < 1e-12);
        for (class, spec) in HeightClass::ALL.into_iter().zip(&specs) {
            let p = &spec.handover;
            let want = Point3::new(p.forward_m + 1.0, p.lateral_m + 2.0, p.height_m);
            assert!((h.for_class(class) - want).norm() < 1e-12, "{class:?}");
            let (lo, hi) = spec.stature.served_m();
            assert_eq!(h.served_m(class), [lo, hi]);
        }
        assert_eq!(
            h.c3_stature_m,
            [specs[2].stature.min_m, specs[2].stature.max_m]
        );
        // the served statures are the files' wider ones, not the classes'
        assert!(h.c1_served_m[0] < h.c1_stature_m[0] && h.c3_served_m[1] > h.c3_stature_m[1]);
    }
}
