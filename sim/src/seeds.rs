//! The experiments over many seeds: each quantity's mean, standard deviation and worst seed, and
//! each goal judged seed by seed ("holds on N of M seeds", with the seeds where it fails).
//!
//! A result tuned on one seed is a result about that seed: the binary's `--seeds A..B` runs an
//! experiment once per seed (each seed's sessions are independent, so the same range gives
//! byte-identical JSON) and summarises the runs here. Pure functions of the per-seed results; no I/O.

use serde::Serialize;

use crate::experiments::{Adaptation, HeightResult, RulaAgreement, Table1};

/// Which direction is worse for a quantity.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Worse {
    Higher,
    Lower,
}

/// One quantity over the seeds.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Spread {
    pub mean: f64,
    /// Sample standard deviation (n − 1); 0 for one seed.
    pub sd: f64,
    pub min: f64,
    pub max: f64,
    /// The worst value and the seed that gave it (the first such seed on a tie).
    pub worst: f64,
    pub worst_seed: u64,
    /// The value of each seed, in the order of `seeds`.
    pub per_seed: Vec<f64>,
}

fn round6(x: f64) -> f64 {
    (x * 1e6).round() / 1e6
}

/// The spread of `values` (one per seed, in the order of `seeds`); non-finite values (a quantity a
/// seed did not produce) are left out of the statistics but kept in `per_seed`. `None` when no seed
/// produced a finite value.
pub fn spread(seeds: &[u64], values: &[f64], worse: Worse) -> Option<Spread> {
    let finite: Vec<(u64, f64)> = seeds
        .iter()
        .zip(values)
        .filter(|(_, v)| v.is_finite())
        .map(|(s, v)| (*s, *v))
        .collect();
    let (first_seed, first) = *finite.first()?;
    let n = finite.len() as f64;
    let mean = finite.iter().map(|(_, v)| v).sum::<f64>() / n;
    let sd = if finite.len() > 1 {
        (finite.iter().map(|(_, v)| (v - mean).powi(2)).sum::<f64>() / (n - 1.0)).sqrt()
    } else {
        0.0
    };
    let (mut worst_seed, mut worst) = (first_seed, first);
    for &(s, v) in &finite {
        let is_worse = match worse {
            Worse::Higher => v > worst,
            Worse::Lower => v < worst,
        };
        if is_worse {
            (worst_seed, worst) = (s, v);
        }
    }
    Some(Spread {
        mean: round6(mean),
        sd: round6(sd),
        min: round6(finite.iter().map(|(_, v)| *v).fold(f64::INFINITY, f64::min)),
        max: round6(
            finite
                .iter()
                .map(|(_, v)| *v)
                .fold(f64::NEG_INFINITY, f64::max),
        ),
        worst: round6(worst),
        worst_seed,
        per_seed: values.iter().map(|v| round6(*v)).collect(),
    })
}

/// A goal judged on every seed.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Goal {
    pub goal: String,
    pub holds_on: usize,
    pub seeds: usize,
    /// The seeds where it does not hold, each with why.
    pub fails: Vec<(u64, String)>,
}

impl Goal {
    /// `check(seed index)` returns `None` when the goal holds on that seed, else why not.
    pub(crate) fn judge(
        goal: &str,
        seeds: &[u64],
        mut check: impl FnMut(usize) -> Option<String>,
    ) -> Self {
        let fails: Vec<(u64, String)> = seeds
            .iter()
            .enumerate()
            .filter_map(|(i, s)| check(i).map(|why| (*s, why)))
            .collect();
        Self {
            goal: goal.to_owned(),
            holds_on: seeds.len() - fails.len(),
            seeds: seeds.len(),
            fails,
        }
    }

    pub fn holds_everywhere(&self) -> bool {
        self.fails.is_empty()
    }
}

/// Table 1 over seeds.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Table1Seeds {
    pub seeds: Vec<u64>,
    pub landmarks: Vec<String>,
    /// Per landmark: the default fusion's RMSE (m) over seeds.
    pub default_rmse_m: Vec<Option<Spread>>,
    /// Per landmark: the paper fusion's RMSE (m) over seeds.
    pub paper_rmse_m: Vec<Option<Spread>>,
    /// Per landmark: the best single stereo pair's RMSE (m) over seeds.
    pub best_pair_rmse_m: Vec<Option<Spread>>,
    pub goals: Vec<Goal>,
}

/// Summarises Table 1 runs, one per seed.
pub fn table1(seeds: &[u64], runs: &[Table1]) -> Table1Seeds {
    let landmarks = runs
        .first()
        .map(|r| r.landmarks.clone())
        .unwrap_or_default();
    let per_landmark = |pick: &dyn Fn(&Table1) -> Vec<Option<f64>>| -> Vec<Option<Spread>> {
        (0..landmarks.len())
            .map(|i| {
                let v: Vec<f64> = runs
                    .iter()
                    .map(|r| pick(r).get(i).copied().flatten().unwrap_or(f64::NAN))
                    .collect();
                spread(seeds, &v, Worse::Higher)
            })
            .collect()
    };
    let of = |name: &'static str| move |r: &Table1| r.rmse_m.get(name).cloned().unwrap_or_default();
    let n = landmarks.len();
    let goals = vec![
        Goal::judge(
            "default fusion beats the best single stereo pair on every landmark",
            seeds,
            |i| {
                let w = runs[i].wins("default_fusion", &runs[i].best_pair());
                (w < n).then(|| format!("{w}/{n} landmarks"))
            },
        ),
        Goal::judge(
            "default fusion beats the paper fusion on every landmark",
            seeds,
            |i| {
                let paper = runs[i]
                    .rmse_m
                    .get("paper_fusion")
                    .cloned()
                    .unwrap_or_default();
                let w = runs[i].wins("default_fusion", &paper);
                (w < n).then(|| format!("{w}/{n} landmarks"))
            },
        ),
    ];
    Table1Seeds {
        seeds: seeds.to_vec(),
        default_rmse_m: per_landmark(&of("default_fusion")),
        paper_rmse_m: per_landmark(&of("paper_fusion")),
        best_pair_rmse_m: per_landmark(&Table1::best_pair),
        landmarks,
        goals,
    }
}

/// The adaptation experiment over seeds.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct AdaptationSeeds {
    pub seeds: Vec<u64>,
    pub heights_m: Vec<f64>,
    /// Per height, the mean grand score over seeds: pipeline before/after, truth before/after.
    pub before: Vec<Option<Spread>>,
    pub after: Vec<Option<Spread>>,
    pub true_before: Vec<Option<Spread>>,
    pub true_after: Vec<Option<Spread>>,
    /// Per height, the mean posture cost over seeds, the same four ways.
    pub cost_before: Vec<Option<Spread>>,
    pub cost_after: Vec<Option<Spread>>,
    pub true_cost_before: Vec<Option<Spread>>,
    pub true_cost_after: Vec<Option<Spread>>,
    pub goals: Vec<Goal>,
}

/// The grand-score goal after adaptation (RULA action level ≤ 2).
pub const ADAPTATION_MAX_AFTER: f64 = 3.0;

/// The statures around the 1.75 m operator the unadapted handover was set for: there adaptation
/// may leave the posture cost as it was; everywhere else it must lower it.
pub const ADAPTATION_SET_FOR_M: [f64; 2] = [1.70, 1.80];

/// Names height `i` of a run in a failure: the height, and the measured person standing in for it.
fn who(r: &Adaptation, i: usize) -> String {
    let h = r.heights_m.get(i).copied().unwrap_or(f64::NAN);
    match (r.subject_ids.get(i).copied().flatten(), r.statures_m.get(i)) {
        (Some(id), Some(s)) => format!("{h:.2} m (subject {id}, {s:.3} m)"),
        _ => format!("{h:.2} m"),
    }
}

/// Why a run's true posture cost fails the goal: worse than before at any served height, or not
/// lower outside [`ADAPTATION_SET_FOR_M`].
fn cost_check(r: &Adaptation) -> Vec<String> {
    let mut why = Vec::new();
    let [lo, hi] = ADAPTATION_SET_FOR_M;
    for (i, h) in r.heights_m.iter().enumerate() {
        let a = r
            .true_mean_posture_cost_after
            .get(i)
            .copied()
            .unwrap_or(f64::NAN);
        let b = r
            .true_mean_posture_cost_before
            .get(i)
            .copied()
            .unwrap_or(f64::NAN);
        if !a.is_finite() {
            continue;
        }
        // The operator's own stature (a measured person's may lie up to 1 cm from the height).
        let s = r.statures_m.get(i).copied().unwrap_or(*h);
        let outside = s < lo - 1e-9 || s > hi + 1e-9;
        let at = who(r, i);
        if !b.is_finite() {
            why.push(format!("{at} has no cost before"));
        } else if a > b {
            why.push(format!("{at} cost worse after ({b:.3} → {a:.3})"));
        } else if outside && a >= b {
            why.push(format!("{at} cost not lower after ({b:.3} → {a:.3})"));
        }
    }
    why
}

/// Summarises adaptation runs, one per seed.
pub fn adaptation(seeds: &[u64], runs: &[Adaptation]) -> AdaptationSeeds {
    let heights_m = runs
        .first()
        .map(|r| r.heights_m.clone())
        .unwrap_or_default();
    let per_height = |pick: &dyn Fn(&Adaptation) -> &Vec<f64>| -> Vec<Option<Spread>> {
        (0..heights_m.len())
            .map(|i| {
                let v: Vec<f64> = runs
                    .iter()
                    .map(|r| pick(r).get(i).copied().unwrap_or(f64::NAN))
                    .collect();
                spread(seeds, &v, Worse::Higher)
            })
            .collect()
    };
    // Served heights only (a height outside every class's validated statures is not handed over).
    let check = |r: &Adaptation, after: &[f64], before: &[f64], what: &str| -> Vec<String> {
        let mut why = Vec::new();
        for i in 0..r.heights_m.len() {
            let (a, b) = (after[i], before[i]);
            if !a.is_finite() {
                continue;
            }
            let at = who(r, i);
            if a > ADAPTATION_MAX_AFTER {
                why.push(format!(
                    "{at} {what} after {a:.2} > {ADAPTATION_MAX_AFTER:.2}"
                ));
            }
            if a > b {
                why.push(format!("{at} {what} worse after ({b:.2} → {a:.2})"));
            }
        }
        why
    };
    let goal = |name: &str, pick: &dyn Fn(&Adaptation) -> Vec<String>| {
        Goal::judge(name, seeds, |i| {
            let why = pick(&runs[i]);
            (!why.is_empty()).then(|| why.join("; "))
        })
    };
    let goals = vec![
        goal(
            "pipeline: every served height ≤ 3.00 after adaptation and never worse than before",
            &|r| {
                check(
                    r,
                    &r.mean_grand_score_after,
                    &r.mean_grand_score_before,
                    "pipeline",
                )
            },
        ),
        goal(
            "truth: every served height ≤ 3.00 after adaptation and never worse than before",
            &|r| {
                check(
                    r,
                    &r.true_mean_grand_score_after,
                    &r.true_mean_grand_score_before,
                    "truth",
                )
            },
        ),
        goal(
            "truth: posture cost never worse after adaptation, and lower outside 1.70–1.80 m",
            &cost_check,
        ),
    ];
    AdaptationSeeds {
        seeds: seeds.to_vec(),
        cost_before: per_height(&|r| &r.mean_posture_cost_before),
        cost_after: per_height(&|r| &r.mean_posture_cost_after),
        true_cost_before: per_height(&|r| &r.true_mean_posture_cost_before),
        true_cost_after: per_height(&|r| &r.true_mean_posture_cost_after),
        before: per_height(&|r| &r.mean_grand_score_before),
        after: per_height(&|r| &r.mean_grand_score_after),
        true_before: per_height(&|r| &r.true_mean_grand_score_before),
        true_after: per_height(&|r| &r.true_mean_grand_score_after),
        heights_m,
        goals,
    }
}

/// The height experiment over seeds.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct HeightSeeds {
    pub seeds: Vec<u64>,
    pub mae_m: Option<Spread>,
    pub class_accuracy_beyond_2cm: Option<Spread>,
    pub undecided: Option<Spread>,
    pub not_servable: Option<Spread>,
    pub coverage: Option<Spread>,
    pub coverage_1sigma: Option<Spread>,
    pub decision_time_median_s: Option<Spread>,
    pub decision_time_p95_s: Option<Spread>,
    pub rula_cost_mean: Option<Spread>,
    pub rula_cost_worst: Option<Spread>,
    /// The calibrated ear offset per seed, metres.
    pub calibrated_offset_m: Option<Spread>,
    /// The ±kσ coverage over every seed's operators together (60 operators a seed move a
    /// seed's own coverage by about ±3 points by chance alone; their calibration is shared).
    pub coverage_pooled: f64,
    pub coverage_1sigma_pooled: f64,
    /// Operators given a wrong class although their whole interval lay inside it, over every
    /// seed's whole population.
    pub confidently_wrong_total: usize,
    /// Operators given the neighbouring class across a boundary, over every seed.
    pub wrong_across_boundary_total: usize,
    /// Operators within 2 cm of a boundary, over every seed.
    pub near_boundary_total: usize,
    /// Decided operators per class (c1, c2, c3), over every seed.
    pub decided_per_class_total: [usize; 3],
    pub operators_total: usize,
    pub goals: Vec<Goal>,
}

/// The MAE goal of the height experiment, metres.
pub const HEIGHT_MAE_GOAL_M: f64 = 0.010;
/// The nominal coverage of a ±2σ interval of a normal error.
pub const NOMINAL_2SIGMA: f64 = 0.9545;
/// The nominal coverage of a ±kσ interval of a normal error.
pub fn nominal_coverage(k: f64) -> f64 {
    2.0 * ergocell_ergonomics::height::normal_cdf(k) - 1.0
}
/// How far from nominal the coverage may be.
pub const COVERAGE_TOLERANCE: f64 = 0.03;

/// Summarises height runs, one per seed.
pub fn height(seeds: &[u64], runs: &[HeightResult]) -> HeightSeeds {
    let pick = |f: &dyn Fn(&HeightResult) -> f64| runs.iter().map(f).collect::<Vec<f64>>();
    let mut goals = vec![
        Goal::judge("every servable operator standing upright is served (0 undecided)", seeds, |i| {
            let n = runs[i].undecided;
            (n > 0).then(|| format!("{n} undecided"))
        }),
        Goal::judge("MAE ≤ 1.0 cm", seeds, |i| {
            let m = runs[i].mae_m;
            (m.is_nan() || m > HEIGHT_MAE_GOAL_M).then(|| format!("MAE {:.2} cm", m * 100.0))
        }),
        Goal::judge(
            "every operator beyond 2 cm of a boundary in the right class",
            seeds,
            |i| {
                let a = runs[i].class_accuracy_beyond_2cm;
                (a < 1.0).then(|| format!("{:.1} % right", a * 100.0))
            },
        ),
        Goal::judge("no operator confidently in the wrong class", seeds, |i| {
            let r = &runs[i];
            let wrong: Vec<String> = r
                .operators
                .iter()
                .filter(|o| {
                    o.decided_class.is_some_and(|c| c != o.true_class)
                        && o.basis == Some(ergocell_ergonomics::height::DecisionBasis::Interval)
                })
                .map(|o| {
                    format!(
                        "{:.3} m {} → {} (estimated {})",
                        o.true_m,
                        o.true_class.name(),
                        o.decided_class.map_or("-", |c| c.name()),
                        o.estimated_m.map_or("-".to_owned(), |e| format!("{e:.3}"))
                    )
                })
                .collect();
            (!wrong.is_empty()).then(|| wrong.join("; "))
        }),
        Goal::judge(
            &format!(
                "the stated ±{k}σ interval covers the truth within 3 points of its nominal {nominal:.3} (each seed's {n} operators)",
                k = runs.first().map_or(2.0, |r| r.interval_sigmas),
                nominal = runs.first().map_or(NOMINAL_2SIGMA, |r| nominal_coverage(r.interval_sigmas)),
                n = runs.first().map_or(0, |r| r.operators.len()),
            ),
            seeds,
            |i| {
                let c = runs[i].coverage;
                ((c - nominal_coverage(runs[i].interval_sigmas)).abs() > COVERAGE_TOLERANCE)
                    .then(|| format!("coverage {c:.3}"))
            },
        ),
        Goal::judge(
            "time from standing at the station to the decision: median ≤ 3 s, p95 ≤ 6 s",
            seeds,
            |i| {
                let r = &runs[i];
                (r.decision_time_median_s.is_nan()
                    || r.decision_time_median_s > 3.0
                    || r.decision_time_p95_s > 6.0)
                    .then(|| {
                        format!(
                            "median {:.1} s, p95 {:.1} s",
                            r.decision_time_median_s, r.decision_time_p95_s
                        )
                    })
            },
        ),
    ];
    if runs.iter().all(|r| r.rula_cost_mean.is_some()) {
        goals.push(Goal::judge(
            "the decision's RULA cost (chosen minus true class): mean ≤ 0.05, worst ≤ 0.2",
            seeds,
            |i| {
                let r = &runs[i];
                let (m, w) = (
                    r.rula_cost_mean.unwrap_or(f64::NAN),
                    r.rula_cost_worst.unwrap_or(f64::NAN),
                );
                (m.is_nan() || m > 0.05 || w > 0.2).then(|| format!("mean {m:.3}, worst {w:.3}"))
            },
        ));
    }
    let pooled = |sigmas_of: &dyn Fn(&HeightResult) -> f64| {
        let (mut inside, mut n) = (0usize, 0usize);
        for r in runs {
            let k = sigmas_of(r);
            for o in &r.operators {
                if let (Some(e), Some(u)) = (o.estimated_m, o.uncertainty_m) {
                    n += 1;
                    inside += usize::from((e - o.true_m).abs() <= k * u);
                }
            }
        }
        (inside as f64 / n.max(1) as f64 * 1e6).round() / 1e6
    };
    let optional = |f: &dyn Fn(&HeightResult) -> Option<f64>, worse| {
        let v: Vec<f64> = runs.iter().map(|r| f(r).unwrap_or(f64::NAN)).collect();
        spread(seeds, &v, worse)
    };
    HeightSeeds {
        seeds: seeds.to_vec(),
        mae_m: spread(seeds, &pick(&|r| r.mae_m), Worse::Higher),
        class_accuracy_beyond_2cm: spread(
            seeds,
            &pick(&|r| r.class_accuracy_beyond_2cm),
            Worse::Lower,
        ),
        undecided: spread(seeds, &pick(&|r| r.undecided as f64), Worse::Higher),
        not_servable: spread(seeds, &pick(&|r| r.not_servable as f64), Worse::Higher),
        coverage: spread(seeds, &pick(&|r| r.coverage), Worse::Lower),
        coverage_1sigma: spread(seeds, &pick(&|r| r.coverage_1sigma), Worse::Lower),
        decision_time_median_s: spread(seeds, &pick(&|r| r.decision_time_median_s), Worse::Higher),
        decision_time_p95_s: spread(seeds, &pick(&|r| r.decision_time_p95_s), Worse::Higher),
        rula_cost_mean: optional(&|r| r.rula_cost_mean, Worse::Higher),
        rula_cost_worst: optional(&|r| r.rula_cost_worst, Worse::Higher),
        calibrated_offset_m: spread(seeds, &pick(&|r| r.calibration.offset_m), Worse::Higher),
        coverage_pooled: pooled(&|r| r.interval_sigmas),
        coverage_1sigma_pooled: pooled(&|_| 1.0),
        confidently_wrong_total: runs.iter().map(|r| r.confidently_wrong).sum(),
        wrong_across_boundary_total: runs.iter().map(|r| r.wrong_across_boundary).sum(),
        near_boundary_total: runs.iter().map(|r| r.near_boundary).sum(),
        decided_per_class_total: [0, 1, 2]
            .map(|k| runs.iter().map(|r| r.decided_per_class[k]).sum()),
        operators_total: runs.iter().map(|r| r.operators.len()).sum(),
        goals,
    }
}

/// The RULA-agreement experiment over seeds.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct RulaSeeds {
    pub seeds: Vec<u64>,
    pub grand_exact: Option<Spread>,
    pub grand_kappa: Option<Spread>,
    pub action_level_exact: Option<Spread>,
    pub action_level_kappa: Option<Spread>,
    /// Per region (upper_arm, lower_arm, wrist, neck, trunk, legs): exact agreement over seeds.
    pub region_names: Vec<String>,
    pub region_exact: Vec<Option<Spread>>,
    pub warnings_per_min: Option<Spread>,
    pub true_warnings_per_min: Option<Spread>,
    /// The warnings of every seed together.
    pub warnings_pooled: PooledWarnings,
    pub goals: Vec<Goal>,
}

/// Posture warnings of many seeds' sessions together: a seed on which the truth raises none and the
/// pipeline one fails the per-seed goal, so the rate over all of them is what an operator meets.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct PooledWarnings {
    pub minutes: f64,
    pub raised: usize,
    pub true_raised: usize,
    /// Per minute over all the seeds' sessions (NaN, `null` in JSON, over no time).
    pub per_min: f64,
    pub true_per_min: f64,
    /// Of the truth's warnings, the share the pipeline also raised (same region and side, within
    /// the dwell time); NaN when the truth raised none.
    pub caught_share: f64,
    /// Of the pipeline's warnings, the share the truth also raised; NaN when it raised none.
    pub confirmed_share: f64,
}

impl PooledWarnings {
    fn of(runs: &[RulaAgreement]) -> Self {
        let sum = |f: &dyn Fn(&RulaAgreement) -> usize| runs.iter().map(f).sum::<usize>();
        let minutes: f64 = runs.iter().map(|r| r.minutes).sum();
        let (raised, true_raised) = (
            sum(&|r| r.warnings_raised),
            sum(&|r| r.true_warnings_raised),
        );
        let ratio = |n: usize, d: f64| if d > 0.0 { n as f64 / d } else { f64::NAN };
        Self {
            minutes,
            raised,
            true_raised,
            per_min: ratio(raised, minutes),
            true_per_min: ratio(true_raised, minutes),
            caught_share: ratio(sum(&|r| r.true_warnings_caught), true_raised as f64),
            confirmed_share: ratio(sum(&|r| r.warnings_confirmed), raised as f64),
        }
    }

    /// Whether the pooled rate is at most the truth's + 20 % ([`WARNING_RATE_GOAL`]).
    pub fn rate_goal_holds(&self) -> bool {
        self.per_min <= WARNING_RATE_GOAL * self.true_per_min
    }
}

/// The operator's warnings may come at most this much more often than the truth's (1.2: 20 %).
pub const WARNING_RATE_GOAL: f64 = 1.2;

/// The grand score's κ goal (above the Kinect anchor, κ 0.84) and exact agreement goal.
pub const RULA_KAPPA_GOAL: f64 = 0.84;
pub const RULA_EXACT_GOAL: f64 = 0.90;

/// Summarises RULA-agreement runs, one per seed.
pub fn rula_agreement(seeds: &[u64], runs: &[RulaAgreement]) -> RulaSeeds {
    let pick = |f: &dyn Fn(&RulaAgreement) -> f64| runs.iter().map(f).collect::<Vec<f64>>();
    let region_names = runs
        .first()
        .map(|r| r.region_names.clone())
        .unwrap_or_default();
    let region_exact = (0..region_names.len())
        .map(|j| {
            spread(
                seeds,
                &pick(&|r| r.region_exact.get(j).copied().unwrap_or(f64::NAN)),
                Worse::Lower,
            )
        })
        .collect();
    let goals = vec![
        Goal::judge("grand score κ > 0.84", seeds, |i| {
            let k = runs[i].grand_score.kappa;
            (k.is_nan() || k <= RULA_KAPPA_GOAL).then(|| format!("κ {k:.3}"))
        }),
        Goal::judge("grand score exact agreement ≥ 0.90", seeds, |i| {
            let e = runs[i].grand_score.exact;
            (e.is_nan() || e < RULA_EXACT_GOAL).then(|| format!("exact {e:.3}"))
        }),
        Goal::judge(
            "warnings raised per minute at most the truth's + 20 %",
            seeds,
            |i| {
                let (w, t) = (runs[i].warnings_per_min, runs[i].true_warnings_per_min);
                (w.is_nan() || t.is_nan() || w > WARNING_RATE_GOAL * t)
                    .then(|| format!("{w:.2} per minute, the truth {t:.2}"))
            },
        ),
    ];
    RulaSeeds {
        seeds: seeds.to_vec(),
        grand_exact: spread(seeds, &pick(&|r| r.grand_score.exact), Worse::Lower),
        grand_kappa: spread(seeds, &pick(&|r| r.grand_score.kappa), Worse::Lower),
        action_level_exact: spread(seeds, &pick(&|r| r.action_level.exact), Worse::Lower),
        action_level_kappa: spread(seeds, &pick(&|r| r.action_level.kappa), Worse::Lower),
        region_names,
        region_exact,
        warnings_per_min: spread(seeds, &pick(&|r| r.warnings_per_min), Worse::Higher),
        true_warnings_per_min: spread(seeds, &pick(&|r| r.true_warnings_per_min), Worse::Higher),
        warnings_pooled: PooledWarnings::of(runs),
        goals,
    }
}

/// A seed range that does not parse.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("{text:?}: {why}")]
pub struct BadSeeds {
    /// The part of the range that was refused.
    pub text: String,
    pub why: String,
}

/// Parses a seed range: `A..B` (inclusive of both ends, as the docs write 101..120) or a count `N`
/// (seeds 1..=N).
pub fn parse_seeds(text: &str) -> Result<Vec<u64>, BadSeeds> {
    let t = text.trim();
    let bad = |text: &str, why: String| BadSeeds {
        text: text.to_owned(),
        why,
    };
    let (a, b) = match t.split_once("..") {
        Some((a, b)) => {
            let b = b.strip_prefix('=').unwrap_or(b);
            (
                a.trim().parse::<u64>().map_err(|e| bad(a, e.to_string()))?,
                b.trim().parse::<u64>().map_err(|e| bad(b, e.to_string()))?,
            )
        }
        None => (
            1,
            t.parse::<u64>()
                .map_err(|e| bad(t, format!("expected A..B or a count: {e}")))?,
        ),
    };
    if a > b || b - a >= 10_000 {
        return Err(bad(
            t,
            "expected A..B with A ≤ B and at most 10000 seeds".to_owned(),
        ));
    }
    Ok((a..=b).collect())
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)]
    use super::*;

    #[test]
    fn spread_of_known_values() {
        let s = spread(&[1, 2, 3, 4], &[2.0, 4.0, 4.0, 6.0], Worse::Higher).unwrap();
        assert_eq!((s.mean, s.min, s.max), (4.0, 2.0, 6.0));
        // Sample s.d. of 2, 4, 4, 6: sqrt(8/3).
        assert!((s.sd - (8.0f64 / 3.0).sqrt()).abs() < 1e-6);
        assert_eq!((s.worst, s.worst_seed), (6.0, 4));
        let low = spread(&[1, 2, 3, 4], &[2.0, 4.0, 4.0, 6.0], Worse::Lower).unwrap();
        assert_eq!((low.worst, low.worst_seed), (2.0, 1));
        // NaN is left out of the statistics, kept in per_seed; nothing finite → None.
        let n = spread(&[1, 2], &[f64::NAN, 1.0], Worse::Higher).unwrap();
        assert_eq!((n.mean, n.sd, n.worst_seed), (1.0, 0.0, 2));
        assert!(n.per_seed[0].is_nan());
        assert!(spread(&[1], &[f64::NAN], Worse::Higher).is_none());
    }

    #[test]
    fn seed_ranges_parse_inclusively_and_bad_ones_are_refused() {
        assert_eq!(parse_seeds("101..104").unwrap(), vec![101, 102, 103, 104]);
        assert_eq!(parse_seeds("3..=3").unwrap(), vec![3]);
        assert_eq!(parse_seeds("3").unwrap(), vec![1, 2, 3]);
        for bad in ["5..2", "a..b", "", "1..20000", "-1..3"] {
            assert!(parse_seeds(bad).is_err(), "{bad}");
        }
    }

    #[test]
    fn a_goal_counts_the_seeds_it_holds_on_and_names_the_others() {
        let g = Goal::judge("even", &[10, 11, 12], |i| {
            (i % 2 == 1).then(|| "odd".into())
        });
        assert_eq!((g.holds_on, g.seeds), (2, 3));
        assert_eq!(g.fails, vec![(11, "odd".to_owned())]);
        assert!(!g.holds_everywhere());
    }
}
