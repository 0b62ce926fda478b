//! Warnings measured as an operator meets them: on sessions of the station's tasks
//! ([`crate::tasks`]), how many of the postures that clearly deserve a warning the controller warns
//! of, how long it takes, and how often it warns of nothing.
//!
//! The truth's warnings come from the controller's own warning tracker
//! ([`ergocell_ergonomics::WarningTracker`], default dwell and hysteresis) on the true skeleton's
//! RULA (unsmoothed, every tick); the controller's from the cell's pipeline
//! ([`ergocell_cell::Pipeline`], its defaults, fixed lag included) on the simulated cameras. Per
//! body region and side:
//!
//! - **clear**: the truth's posture is at least [`CLEAR_MARGIN_DEG`] past the band edge — the
//!   region's score, with the worksheet's adjustments as the truth measured them, still reaches the
//!   warning level with the angle moved that far either way — for at least the dwell + 1 s. The
//!   legs have no angle: their clear stretch is the truth's legs scoring the warning level.
//! - **recall**: of the clear stretches, those during which the controller warned (its warning for
//!   that region and side active at some instant from the posture crossing the band edge to the
//!   stretch's end + the dwell).
//! - **latency**: from the posture crossing the band edge (the first frame of the truth's run at the
//!   warning level that holds the clear stretch) to the controller's warning as the operator gets
//!   it — when the pipeline releases the frame that raised it, the fixed lag after that frame's
//!   stamp (0 when it was already up); it includes the fixed lag and the dwell. Every controller
//!   warning is timed by its release.
//! - **precision**: of the controller's raised warnings, those matched to a truth warning of the
//!   same region and side (raised within the dwell before the truth's warning was up, while it was,
//!   or within the dwell after it cleared); the rest are **false warnings**, counted per hour.
//!
//! Besides, the per-frame RULA agreement of the same sessions (grand score and action level, exact
//! and Cohen's κ over the frames at the station), as [`crate::experiments::rula_agreement`] counts it.
//! Pure: values in, values out.

use crate::band_reliability::{frame_samples, BandSample, Reliability, FIT_STRIDE};
use ergocell_ergonomics::confidence::SURE_PROBABILITY;
use std::collections::BTreeMap;

use ergocell_cell::{Pipeline, PipelineConfig};
use ergocell_ergonomics::assess::BodyRegion;
use ergocell_ergonomics::height::ClassThresholds;
use ergocell_ergonomics::rula::action_level;
use ergocell_ergonomics::warnings::{judged, region_angle, region_score_at};
use ergocell_ergonomics::HeightClass;
use ergocell_ergonomics::{
    AssessmentConfig, FrameAssessment, RulaAssessor, Side, WarningConfig, WarningKind,
    WarningTracker,
};
use serde::Serialize;

use crate::body::Operator;
use crate::experiments::{
    agreement, at_station, nearest_tick, pipeline_headline, round6, scored, session_seed,
    truth_config, up, Agreement, Handovers, Progress, Scored, Setup,
};
use crate::seeds::Goal;
use crate::session::{SessionScript, SimConfig, Simulation, Tick};
use crate::tasks::{TaskKind, TaskMix};
use crate::SimError;

/// How far past the band edge a posture must be for its warning to be clear, degrees.
pub const CLEAR_MARGIN_DEG: f64 = 5.0;
/// How long past the dwell a clear posture must last, nanoseconds.
pub const CLEAR_EXTRA_NANOS: i64 = 1_000_000_000;
/// The latency goal's allowance beyond the dwell and the fixed lag, seconds.
pub const LATENCY_ALLOWANCE_S: f64 = 0.5;

/// The goals of the operator's warnings, judged seed by seed.
pub const RECALL_GOAL: f64 = 0.95;
pub const PRECISION_GOAL: f64 = 0.90;
pub const FALSE_PER_HOUR_GOAL: f64 = 2.0;

type Key = (BodyRegion, Option<Side>);
/// Each key's warning intervals, and every raise as `(key, when)`.
type Warned = (BTreeMap<Key, Vec<Interval>>, Vec<(Key, i64)>);
/// Per tick: its stamp, and per key whether the truth is at the warning level and clearly.
type TickLevels = (i64, BTreeMap<Key, (bool, bool)>);

/// One region's warnings over a seed's sessions (both sides together for the sided regions).
#[derive(Debug, Clone, PartialEq, Serialize, Default)]
pub struct RegionWarnings {
    pub region: String,
    /// Warnings the truth raised.
    pub truth_raised: usize,
    /// Clear stretches of the truth's posture (each one a warning the truth raises).
    pub clear: usize,
    /// Of those, the ones the controller warned of.
    pub clear_caught: usize,
    /// `clear_caught / clear` (NaN, `null`, without a clear stretch).
    pub recall: f64,
    /// Warnings the controller raised.
    pub raised: usize,
    /// Of those, the ones matched to a truth warning.
    pub confirmed: usize,
    /// `confirmed / raised` (NaN without a raised warning).
    pub precision: f64,
    /// Seconds from the posture crossing the edge to the controller's warning, each caught clear
    /// stretch, in time order.
    pub latencies_s: Vec<f64>,
}

impl RegionWarnings {
    /// Adds `other`'s counts and latencies to these.
    fn add(&mut self, other: &RegionWarnings) {
        self.truth_raised += other.truth_raised;
        self.clear += other.clear;
        self.clear_caught += other.clear_caught;
        self.raised += other.raised;
        self.confirmed += other.confirmed;
        self.latencies_s.extend(&other.latencies_s);
    }

    /// Recall and precision from the counts.
    fn finish(&mut self) {
        self.recall = ratio(self.clear_caught, self.clear);
        self.precision = ratio(self.confirmed, self.raised);
    }
}

/// The warnings of one seed's sessions.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct WarningTrust {
    /// Per region, [`BodyRegion::ALL`] order.
    pub regions: Vec<RegionWarnings>,
    /// Every region together.
    pub all: RegionWarnings,
    /// Controller warnings matched to no truth warning (what precision counts against).
    pub unmatched_warnings: usize,
    /// Of those, the ones RULA did not deserve: the truth's posture did not score the warned level
    /// on most frames of the warning's dwell ([`FalseWarning::deserved`]).
    pub false_warnings: usize,
    /// Each unmatched warning: where and when, what the truth was doing, and whether RULA
    /// deserved it.
    pub false_list: Vec<FalseWarning>,
    pub false_per_hour: f64,
    /// Latency quantiles over every caught clear stretch, seconds (NaN without one).
    pub latency_p50_s: f64,
    pub latency_p95_s: f64,
    pub latency_max_s: f64,
    /// The latency goal: dwell + the fixed lag + [`LATENCY_ALLOWANCE_S`].
    pub latency_bound_s: f64,
    pub grand_score: Agreement,
    pub action_level: Agreement,
    pub frames: usize,
    pub hours: f64,
    /// How many times each task occurred, by name.
    pub tasks: BTreeMap<String, usize>,
    pub statures_m: Vec<f64>,
    /// The fixed lag the controller ran with (seconds either side; absent: the causal filter).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub fixed_lag_s: Option<f64>,
    /// Whether the controller's stated band probabilities were right, at the station.
    pub reliability: Reliability,
    /// Every [`crate::band_reliability::FIT_STRIDE`]-th sample of `reliability`, for the fit.
    #[serde(skip)]
    pub band_samples: Vec<BandSample>,
}

/// A controller warning the truth did not raise.
///
/// The truth's own warning can stay down for a posture RULA scores at the warned level: it rises
/// only once the posture is the rise margin past the band's edge, after the dwell. An upper arm
/// held at 47.9° scores 3 (past 45°) and is 0.1° short of the truth's rise; the controller measures
/// it at 48.5° and warns. That warning is unmatched (precision counts it) but not false: the
/// posture is what it says. It is false when the truth's posture did not score the warned level on
/// at least half the frames of the dwell before it.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct FalseWarning {
    /// The operator's index in `statures_m`.
    pub session: usize,
    /// When it was shown, seconds from the session's start.
    pub at_s: f64,
    pub region: String,
    pub side: Option<Side>,
    /// What the operator was doing then (the twin's phase).
    pub phase: crate::session::Phase,
    /// The truth's angle of the region then, degrees (none for the legs).
    pub truth_angle_deg: Option<f64>,
    /// The truth's posture scored the warned level on at least half the frames of the warning's
    /// dwell (the frames whose release showed it, the fixed lag earlier): RULA deserved it.
    pub deserved: bool,
}

/// A warning as an interval of time for one region and side: raised at `from`, cleared at `to`
/// (the session's last stamp when it never cleared).
#[derive(Debug, Clone, Copy, PartialEq)]
struct Interval {
    from: i64,
    to: i64,
}

/// Each key's warning intervals from a stream of events.
#[derive(Debug, Default)]
struct Intervals {
    open: BTreeMap<Key, i64>,
    done: BTreeMap<Key, Vec<Interval>>,
    raised: Vec<(Key, i64)>,
}

impl Intervals {
    /// Feeds events shown at `shown_at` (the controller's: when the pipeline released the frame,
    /// its fixed lag after the frame's stamp), or at their own stamps (`None`: the truth's).
    fn feed(&mut self, events: &[ergocell_ergonomics::WarningEvent], shown_at: Option<i64>) {
        for e in events {
            let key = (e.region, e.side);
            let at = shown_at.unwrap_or(e.stamp_nanos);
            match e.kind {
                WarningKind::Raised => {
                    self.open.insert(key, at);
                    self.raised.push((key, at));
                }
                WarningKind::Cleared => {
                    if let Some(from) = self.open.remove(&key) {
                        self.done
                            .entry(key)
                            .or_default()
                            .push(Interval { from, to: at });
                    }
                }
                WarningKind::Changed => {}
            }
        }
    }

    fn close(mut self, end: i64) -> Warned {
        for (key, from) in std::mem::take(&mut self.open) {
            self.done
                .entry(key)
                .or_default()
                .push(Interval { from, to: end });
        }
        (self.done, self.raised)
    }
}

/// Per key and tick: whether the truth's region scores the warning level, and whether clearly.
fn truth_levels(a: &FrameAssessment, config: &WarningConfig) -> Vec<(Key, bool, bool)> {
    BodyRegion::ALL
        .iter()
        .enumerate()
        .flat_map(move |(ri, region)| {
            let warn_at = config.warn_at[ri];
            judged(a, *region).into_iter().map(move |(side, s)| {
                let input = &s.input;
                let angle = region_angle(*region, input);
                let level = region_score_at(*region, input, angle) >= warn_at;
                let clear = match angle {
                    Some(x) => [x - CLEAR_MARGIN_DEG, x + CLEAR_MARGIN_DEG]
                        .iter()
                        .all(|v| region_score_at(*region, input, Some(*v)) >= warn_at),
                    None => level,
                };
                ((*region, side), level, clear && level)
            })
        })
        .collect()
}

/// A clear stretch of the truth's posture: when its posture crossed the band edge, and the clear
/// stretch's first and last stamps.
#[derive(Debug, Clone, Copy, PartialEq)]
struct ClearStretch {
    crossing: i64,
    last: i64,
}

/// The clear stretches per key, from the truth's per-tick levels (in tick order).
fn clear_stretches(
    per_tick: &[TickLevels],
    period_nanos: i64,
    dwell_nanos: i64,
) -> BTreeMap<Key, Vec<ClearStretch>> {
    let keys: std::collections::BTreeSet<Key> = per_tick
        .iter()
        .flat_map(|(_, m)| m.keys().copied())
        .collect();
    let mut out: BTreeMap<Key, Vec<ClearStretch>> = BTreeMap::new();
    for key in keys {
        // (start of the current run at the warning level, start of the current clear run)
        let mut level_from: Option<i64> = None;
        let mut clear_from: Option<(i64, i64)> = None; // (crossing, first clear stamp)
        let mut last_clear = 0;
        let finish = |crossing: i64, first: i64, last: i64, out: &mut BTreeMap<_, Vec<_>>| {
            if last - first + period_nanos >= dwell_nanos + CLEAR_EXTRA_NANOS {
                out.entry(key)
                    .or_default()
                    .push(ClearStretch { crossing, last });
            }
        };
        for (stamp, m) in per_tick {
            let (level, clear) = m.get(&key).copied().unwrap_or((false, false));
            if level {
                level_from.get_or_insert(*stamp);
            } else {
                level_from = None;
            }
            if clear {
                if clear_from.is_none() {
                    clear_from = Some((level_from.unwrap_or(*stamp), *stamp));
                }
                last_clear = *stamp;
            } else if let Some((crossing, first)) = clear_from.take() {
                finish(crossing, first, last_clear, &mut out);
            }
        }
        if let Some((crossing, first)) = clear_from.take() {
            finish(crossing, first, last_clear, &mut out);
        }
    }
    out
}

/// What one session adds to a seed's figures.
#[derive(Debug, Default)]
struct Counts {
    regions: [RegionWarnings; 6],
    false_list: Vec<FalseWarning>,
}

fn region_index(r: BodyRegion) -> usize {
    BodyRegion::ALL.iter().position(|x| *x == r).unwrap_or(0)
}

/// A session's timing, for [`compare`]: the controller's fixed lag and the frame period.
#[derive(Debug, Clone, Copy)]
struct Timing {
    lag_nanos: i64,
    period_nanos: i64,
}

/// The controller's and the truth's warnings of one session compared.
fn compare(
    ticks: &[Tick],
    truth: &[FrameAssessment],
    pipeline: Intervals,
    config: &WarningConfig,
    timing: Timing,
    session: usize,
    counts: &mut Counts,
) {
    let end = ticks.last().map_or(0, |t| t.frame.stamp_nanos);
    let dwell = config.dwell_nanos;
    let Timing {
        lag_nanos,
        period_nanos,
    } = timing;
    let mut truth_tracker = WarningTracker::new(*config);
    let mut truth_intervals = Intervals::default();
    let mut per_tick = Vec::with_capacity(ticks.len());
    for (t, a) in ticks.iter().zip(truth) {
        truth_intervals.feed(&truth_tracker.update(a), None);
        let levels: BTreeMap<Key, (bool, bool)> = truth_levels(a, config)
            .into_iter()
            .map(|(k, l, c)| (k, (l, c)))
            .collect();
        per_tick.push((t.frame.stamp_nanos, levels));
    }
    let (truth_done, truth_raised) = truth_intervals.close(end);
    let (pipe_done, pipe_raised) = pipeline.close(end);
    for (key, _) in &truth_raised {
        counts.regions[region_index(key.0)].truth_raised += 1;
    }
    for (key, stretches) in clear_stretches(&per_tick, period_nanos, dwell) {
        let r = &mut counts.regions[region_index(key.0)];
        let warned = pipe_done.get(&key).map_or(&[][..], Vec::as_slice);
        for s in stretches {
            r.clear += 1;
            let window_end = s.last + dwell;
            if let Some(w) = warned
                .iter()
                .find(|w| w.from <= window_end && w.to >= s.crossing)
            {
                r.clear_caught += 1;
                r.latencies_s
                    .push(round6((w.from - s.crossing).max(0) as f64 * 1e-9));
            }
        }
    }
    for (key, stamp) in pipe_raised {
        let r = &mut counts.regions[region_index(key.0)];
        r.raised += 1;
        let matched = truth_done.get(&key).is_some_and(|ws| {
            ws.iter()
                .any(|w| stamp >= w.from - dwell && stamp <= w.to + dwell)
        });
        if matched {
            r.confirmed += 1;
        } else {
            let start = ticks.first().map_or(0, |t| t.frame.stamp_nanos);
            let k = nearest_tick(ticks, stamp);
            let angle = truth.get(k).and_then(|a| {
                let s = match key.1 {
                    Some(side) => a.side(side),
                    None => a.headline(),
                }?;
                region_angle(key.0, &s.input)
            });
            // The frames the controller's dwell covered: shown at `stamp`, the lag after its frame.
            let (from, to) = (stamp - lag_nanos - dwell, stamp - lag_nanos);
            let (mut at_level, mut n) = (0usize, 0usize);
            for (t, levels) in &per_tick {
                if (from..=to).contains(t) {
                    n += 1;
                    at_level += usize::from(levels.get(&key).is_some_and(|l| l.0));
                }
            }
            counts.false_list.push(FalseWarning {
                session,
                at_s: round6((stamp - start) as f64 * 1e-9),
                region: key.0.name().to_owned(),
                side: key.1,
                phase: ticks[k].truth.phase,
                truth_angle_deg: angle.map(round6),
                deserved: n > 0 && 2 * at_level >= n,
            });
        }
    }
}

fn ratio(n: usize, d: usize) -> f64 {
    if d == 0 {
        f64::NAN
    } else {
        round6(n as f64 / d as f64)
    }
}

/// The `q` quantile of `sorted` (nearest rank; NaN when empty).
fn quantile(sorted: &[f64], q: f64) -> f64 {
    if sorted.is_empty() {
        return f64::NAN;
    }
    let rank = ((q * sorted.len() as f64).ceil() as usize).clamp(1, sorted.len());
    sorted[rank - 1]
}

/// The warnings of operators of `statures_m`, each doing a session of `mix` (its handovers at
/// their height class's handover point, class from the true stature with the default thresholds,
/// as the cell adapts to them) on `setup`'s rig and detector, through the controller's pipeline with
/// `config` (its fixed lag, assessor and warning tracker). Each frame's views reach the pipeline
/// `transport_delay_nanos` after their capture (0: at once), as the edge's inference and the network
/// delay them on a real cell.
pub fn warning_trust(
    setup: &Setup,
    handovers: &Handovers,
    statures_m: &[f64],
    mix: &TaskMix,
    config: &PipelineConfig,
    transport_delay_nanos: i64,
    progress: Progress<'_>,
) -> Result<WarningTrust, SimError> {
    let wconfig = config.warnings;
    let mut counts = Counts::default();
    let mut grand = vec![vec![0usize; 7]; 7];
    let mut level = vec![vec![0usize; 4]; 4];
    let (mut frames, mut nanos) = (0usize, 0i64);
    let mut tasks: BTreeMap<String, usize> = BTreeMap::new();
    let mut reliability = Reliability::default();
    let mut band_samples = Vec::new();
    for (i, &h) in statures_m.iter().enumerate() {
        let seed = session_seed(setup.seed, i);
        let class = HeightClass::of(h, &ClassThresholds::default());
        let mut script = SessionScript::new(handovers.for_class(class));
        script.cycles = mix.handovers;
        let sim_config = SimConfig {
            noise: setup.noise,
            ..SimConfig::new(seed)
        };
        let period = sim_config.frame_period_nanos;
        let drawn = mix.draw(seed);
        for t in &drawn {
            *tasks.entry(t.kind.name().to_owned()).or_default() += 1;
        }
        let ticks: Vec<Tick> = Simulation::with_tasks(
            setup.rig.clone(),
            Operator::new(h)?,
            script,
            sim_config,
            drawn,
        )?
        .collect::<Result<_, _>>()?;
        if let (Some(first), Some(last)) = (ticks.first(), ticks.last()) {
            nanos += last.frame.stamp_nanos - first.frame.stamp_nanos + period;
        }
        let mut assessor = RulaAssessor::new(truth_config(&AssessmentConfig::new(up()?)))?;
        let truth: Vec<FrameAssessment> = ticks
            .iter()
            .map(|t| assessor.assess(&t.truth.skeleton))
            .collect::<Result<_, _>>()?;
        let truth_scores: Vec<Option<Scored>> =
            truth.iter().map(scored).collect::<Result<_, _>>()?;
        let mut pipeline = Intervals::default();
        let mut scores: Vec<(usize, Option<Scored>)> = Vec::new();
        let mut sample_index = 0usize;
        // As run_pipeline_with, knowing when each frame is released (what the operator sees when):
        // each frame's views reach the cell `transport_delay_nanos` after their capture, and the
        // frames whose window has closed are released on the clock.
        let mut p = Pipeline::new(setup.rig.clone(), config.clone())?;
        for tick in &ticks {
            let now = tick.frame.stamp_nanos + transport_delay_nanos;
            let mut released = Vec::new();
            for output in p.push_views(now, tick.frame.views.clone()) {
                released.extend(output?.tracked);
            }
            released.extend(p.release_due(now));
            for tracked in &released {
                pipeline.feed(&tracked.warnings, Some(now));
                let k = nearest_tick(&ticks, tracked.skeleton.stamp_nanos);
                scores.push((k, pipeline_headline(tracked)?));
                if let (Ok(a), true) = (&tracked.assessment, at_station(ticks[k].truth.phase)) {
                    for (sample, stated) in frame_samples(a, &truth[k]) {
                        reliability.add(sample.region, stated, sample.right());
                        if sample_index.is_multiple_of(FIT_STRIDE) {
                            band_samples.push(sample);
                        }
                        sample_index += 1;
                    }
                }
            }
        }
        for (k, e) in scores {
            if !at_station(ticks[k].truth.phase) {
                continue;
            }
            if let (Some(e), Some(t)) = (e, truth_scores[k]) {
                let g = |s: u8| usize::from(s.clamp(1, 7)) - 1;
                grand[g(t.grand)][g(e.grand)] += 1;
                let l = |s: u8| usize::from(action_level(s).clamp(1, 4)) - 1;
                level[l(t.grand)][l(e.grand)] += 1;
                frames += 1;
            }
        }
        let lag_nanos = config.fixed_lag_s.map_or(0, |s| (s * 1e9).round() as i64);
        let timing = Timing {
            lag_nanos,
            period_nanos: period,
        };
        compare(&ticks, &truth, pipeline, &wconfig, timing, i, &mut counts);
        progress(i + 1, statures_m.len());
    }
    let hours = nanos as f64 / 3.6e12;
    let mut all = RegionWarnings {
        region: "all".to_owned(),
        ..RegionWarnings::default()
    };
    let mut regions = Vec::with_capacity(6);
    for (r, mut w) in BodyRegion::ALL.iter().zip(counts.regions) {
        r.name().clone_into(&mut w.region);
        w.finish();
        all.add(&w);
        regions.push(w);
    }
    all.finish();
    let mut sorted = all.latencies_s.clone();
    sorted.sort_by(f64::total_cmp);
    let lag_s = config.fixed_lag_s.unwrap_or(0.0);
    let unmatched_warnings = counts.false_list.len();
    let false_warnings = counts.false_list.iter().filter(|f| !f.deserved).count();
    Ok(WarningTrust {
        unmatched_warnings,
        regions,
        false_warnings,
        false_list: counts.false_list,
        false_per_hour: if hours > 0.0 {
            round6(false_warnings as f64 / hours)
        } else {
            f64::NAN
        },
        latency_p50_s: quantile(&sorted, 0.5),
        latency_p95_s: quantile(&sorted, 0.95),
        latency_max_s: sorted.last().copied().unwrap_or(f64::NAN),
        latency_bound_s: round6(wconfig.dwell_nanos as f64 * 1e-9 + lag_s + LATENCY_ALLOWANCE_S),
        all,
        grand_score: agreement(grand),
        action_level: agreement(level),
        frames,
        hours: round6(hours),
        tasks,
        statures_m: statures_m.to_vec(),
        fixed_lag_s: config.fixed_lag_s,
        reliability,
        band_samples,
    })
}

/// The warnings over many seeds: each goal judged seed by seed, and the latencies pooled.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct WarningTrustSeeds {
    pub seeds: Vec<u64>,
    /// Pooled over the seeds, per region then all (`latencies_s` pooled too).
    pub regions: Vec<RegionWarnings>,
    pub all: RegionWarnings,
    pub unmatched_warnings: usize,
    pub false_warnings: usize,
    pub false_per_hour: f64,
    pub hours: f64,
    pub latency_p50_s: f64,
    pub latency_p95_s: f64,
    pub latency_max_s: f64,
    pub latency_bound_s: f64,
    pub goals: Vec<Goal>,
    /// The stated band probabilities' reliability, pooled over the seeds.
    pub reliability: Reliability,
    /// Each seed's result.
    pub per_seed: Vec<WarningTrust>,
}

/// Pools the seeds' results and judges each goal on each seed.
pub fn over_seeds(seeds: &[u64], runs: Vec<WarningTrust>) -> WarningTrustSeeds {
    let mut regions: Vec<RegionWarnings> = BodyRegion::ALL
        .iter()
        .map(|r| RegionWarnings {
            region: r.name().to_owned(),
            ..RegionWarnings::default()
        })
        .collect();
    let mut all = RegionWarnings {
        region: "all".to_owned(),
        ..RegionWarnings::default()
    };
    let (mut unmatched_warnings, mut false_warnings, mut hours) = (0usize, 0usize, 0.0);
    let mut reliability = Reliability::default();
    for run in &runs {
        reliability.merge(&run.reliability);
        for (p, r) in regions
            .iter_mut()
            .chain([&mut all])
            .zip(run.regions.iter().chain([&run.all]))
        {
            p.add(r);
        }
        unmatched_warnings += run.unmatched_warnings;
        false_warnings += run.false_warnings;
        hours += run.hours;
    }
    for p in regions.iter_mut().chain([&mut all]) {
        p.finish();
    }
    let mut sorted = all.latencies_s.clone();
    sorted.sort_by(f64::total_cmp);
    let bound = runs.first().map_or(f64::NAN, |r| r.latency_bound_s);
    let goals = vec![
        Goal::judge(
            "recall of clear warnings ≥ 95 % in every region the tasks exercise",
            seeds,
            |i| {
                let low: Vec<String> = runs[i]
                    .regions
                    .iter()
                    .filter(|r| r.clear > 0 && r.recall < RECALL_GOAL)
                    .map(|r| format!("{} {}/{}", r.region, r.clear_caught, r.clear))
                    .collect();
                (!low.is_empty()).then(|| low.join(", "))
            },
        ),
        Goal::judge("precision ≥ 90 %", seeds, |i| {
            let a = &runs[i].all;
            (a.raised > 0 && a.precision < PRECISION_GOAL)
                .then(|| format!("{} of {} confirmed", a.confirmed, a.raised))
        }),
        Goal::judge("at most 2 false warnings per hour", seeds, |i| {
            let f = runs[i].false_per_hour;
            (f.is_nan() || f > FALSE_PER_HOUR_GOAL).then(|| {
                format!(
                    "{} false in {:.2} h: {f:.1} per hour",
                    runs[i].false_warnings, runs[i].hours
                )
            })
        }),
        Goal::judge("p95 latency ≤ dwell + fixed lag + 0.5 s", seeds, |i| {
            let (p, b) = (runs[i].latency_p95_s, runs[i].latency_bound_s);
            (p.is_nan() || p > b).then(|| format!("p95 {p:.2} s > {b:.2} s"))
        }),
        Goal::judge("grand score κ > 0.84", seeds, |i| {
            let k = runs[i].grand_score.kappa;
            (k.is_nan() || k <= crate::seeds::RULA_KAPPA_GOAL).then(|| format!("κ {k:.3}"))
        }),
        Goal::judge("action level exact agreement ≥ 0.90", seeds, |i| {
            let e = runs[i].action_level.exact;
            (e.is_nan() || e < crate::seeds::RULA_EXACT_GOAL).then(|| format!("exact {e:.3}"))
        }),
        Goal::judge(
            "band probabilities calibrated: every bin of ≥ 500 samples within 5 points",
            seeds,
            |i| {
                let off = runs[i].reliability.miscalibrated();
                (!off.is_empty()).then(|| off.join("; "))
            },
        ),
        Goal::judge(
            "of the samples stated ≥ 90 % sure, ≥ 90 % right",
            seeds,
            |i| {
                let r = &runs[i].reliability;
                let share = r.sure_share();
                (share.is_nan() || share < SURE_PROBABILITY)
                    .then(|| format!("{} of {} right ({:.3})", r.sure_right, r.sure, share))
            },
        ),
    ];
    WarningTrustSeeds {
        seeds: seeds.to_vec(),
        regions,
        all,
        unmatched_warnings,
        false_warnings,
        false_per_hour: if hours > 0.0 {
            round6(false_warnings as f64 / hours)
        } else {
            f64::NAN
        },
        hours: round6(hours),
        latency_p50_s: quantile(&sorted, 0.5),
        latency_p95_s: quantile(&sorted, 0.95),
        latency_max_s: sorted.last().copied().unwrap_or(f64::NAN),
        latency_bound_s: bound,
        goals,
        reliability,
        per_seed: runs,
    }
}

/// Which task kinds a mix exercises, by name (for the report's header).
pub fn task_names(mix: &TaskMix) -> Vec<&'static str> {
    mix.tasks.iter().map(|(k, _)| TaskKind::name(*k)).collect()
}

/// The controller's pipeline the warnings are measured on: its defaults (the twin's world, z up),
/// with a fixed lag of `fixed_lag_s` seconds either side when given; `Some(0.0)`: the causal filter
/// instead; `None`: the controller's default lag.
pub fn pipeline_config(fixed_lag_s: Option<f64>) -> Result<PipelineConfig, SimError> {
    let mut config = PipelineConfig::new(up()?);
    match fixed_lag_s {
        Some(0.0) => config.fixed_lag_s = None,
        Some(w) => config.fixed_lag_s = Some(w),
        None => {}
    }
    Ok(config)
}

/// The longest the views may take to reach the cell, milliseconds.
pub const MAX_TRANSPORT_DELAY_MS: f64 = 10_000.0;

/// A transport delay that is not a time of 0 to [`MAX_TRANSPORT_DELAY_MS`].
#[derive(Debug, Clone, Copy, PartialEq, thiserror::Error)]
#[error("{ms}: must be a time of 0 to 10000 ms")]
pub struct BadTransportDelay {
    /// The delay given, milliseconds.
    pub ms: f64,
}

/// How long after its capture each frame's views reach the cell: `ms` milliseconds (0 to
/// [`MAX_TRANSPORT_DELAY_MS`]) in nanoseconds, to the nearest nanosecond.
pub fn transport_delay_nanos(ms: f64) -> Result<i64, BadTransportDelay> {
    if ms.is_finite() && (0.0..=MAX_TRANSPORT_DELAY_MS).contains(&ms) {
        Ok((ms * 1e6).round() as i64)
    } else {
        Err(BadTransportDelay { ms })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn tick_levels(stamps: &[i64], clear: &[bool], level: &[bool]) -> Vec<TickLevels> {
        stamps
            .iter()
            .zip(clear.iter().zip(level))
            .map(|(s, (c, l))| {
                let mut m = BTreeMap::new();
                m.insert((BodyRegion::Neck, None), (*l, *c));
                (*s, m)
            })
            .collect()
    }

    #[test]
    fn a_clear_stretch_lasts_the_dwell_plus_a_second_and_starts_at_the_crossing() {
        let period = 100_000_000;
        let stamps: Vec<i64> = (0..60).map(|k| k * period).collect();
        // level from tick 5, clear from tick 10 to 39 (3.0 s), then level only to 45.
        let level: Vec<bool> = (0..60).map(|k| (5..46).contains(&k)).collect();
        let clear: Vec<bool> = (0..60).map(|k| (10..40).contains(&k)).collect();
        let s = clear_stretches(&tick_levels(&stamps, &clear, &level), period, 2_000_000_000);
        let got = &s[&(BodyRegion::Neck, None)];
        assert_eq!(
            got,
            &vec![ClearStretch {
                crossing: 5 * period,
                last: 39 * period
            }]
        );
        // 2.9 s of clear posture is not clear.
        let clear: Vec<bool> = (0..60).map(|k| (10..39).contains(&k)).collect();
        let s = clear_stretches(&tick_levels(&stamps, &clear, &level), period, 2_000_000_000);
        assert!(!s.contains_key(&(BodyRegion::Neck, None)));
    }

    #[test]
    fn quantiles_by_nearest_rank() {
        let v: Vec<f64> = (1..=20).map(f64::from).collect();
        assert_eq!(quantile(&v, 0.5), 10.0);
        assert_eq!(quantile(&v, 0.95), 19.0);
        assert!(quantile(&[], 0.5).is_nan());
    }

    #[test]
    fn the_fixed_lag_is_the_controllers_unless_given_and_zero_is_the_causal_filter() {
        let default = pipeline_config(None).unwrap().fixed_lag_s;
        assert_eq!(default, Some(ergocell_cell::pipeline::DEFAULT_FIXED_LAG_S));
        assert_eq!(pipeline_config(Some(0.0)).unwrap().fixed_lag_s, None);
        assert_eq!(pipeline_config(Some(0.3)).unwrap().fixed_lag_s, Some(0.3));
    }

    #[test]
    fn a_transport_delay_is_0_to_10_s_in_whole_nanoseconds() {
        assert_eq!(transport_delay_nanos(0.0), Ok(0));
        assert_eq!(transport_delay_nanos(100.0), Ok(100_000_000));
        assert_eq!(transport_delay_nanos(0.000_000_4), Ok(0));
        assert_eq!(transport_delay_nanos(0.000_000_6), Ok(1));
        assert_eq!(transport_delay_nanos(10_000.0), Ok(10_000_000_000));
        for bad in [-1.0, 10_000.5, f64::NAN, f64::INFINITY] {
            let e = transport_delay_nanos(bad).unwrap_err();
            assert!(
                e.to_string().ends_with(": must be a time of 0 to 10000 ms"),
                "{e}"
            );
        }
        assert_eq!(
            transport_delay_nanos(-1.0).unwrap_err().to_string(),
            "-1: must be a time of 0 to 10000 ms"
        );
    }
}
