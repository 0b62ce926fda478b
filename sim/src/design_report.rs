//! The handover design of `ergocell trajectories design`, composed and reported: each class's point
//! chosen for the people it serves, today's (hand-set) point and the unadapted cell's single point
//! costed on the people never fitted, the cost curves against stature, and what the command prints,
//! writes into the class files' comments and draws.
//!
//! The people are the caller's (ANSUR II, [`ergocell_anthropometry::ansur`]: the fitting half
//! chooses, the reporting half judges); the cost of a point is the twin's body model
//! ([`crate::design`]); a candidate is accepted only by the robot's own [`plan_and_validate`], as
//! `trajectories validate` accepts a class file. It lives here because the body model, the costs and
//! the figure are the twin's; the binary reads the class files, edits their TOML and writes the
//! outputs. No I/O, no clock, no randomness: the same people and files give the same bytes.

use std::fmt::Write as _;

use ergocell_anthropometry::ansur::{Person, Sex, Split};
use ergocell_cell::session::trajectory_class;
use ergocell_ergonomics::height::ClassThresholds;
use ergocell_ergonomics::HeightClass;
use ergocell_robot::validate::class_band;
use ergocell_robot::{
    plan_and_validate, CellConfig, InputHashes, PlanInputs, RobotModel, TrajectoryClass,
    TrajectorySpec,
};
use serde::Serialize;

use crate::design::{self, BodyModel, CandidateCost, Choice, PopulationCost, Requirements};
use crate::report::{line_chart, Figure, FigureError, COLORS};
use crate::session::Habits;
use crate::{Operator, ReachConfig, SessionScript, SimError};

/// How many of the cheapest candidates may be refused before a class gives up.
pub const MAX_REFUSALS: usize = 400;

/// How many of the cheapest points of the coarse grid are refined ([`design::search`]).
pub const KEEP: usize = 6;

/// How much lower than at the "before" point c1's and c3's designed point must put the posture cost
/// of every stature they serve, at every corner of the habits (RULA points): a margin for what the
/// twin's sessions add to the body model (each person's build, the robot's placement scatter).
pub const MARGIN: f64 = 0.02;

/// The highest RULA grand score any stature of a class may hold its point at, at every node of the
/// body model's averages (not only on average): action level 2 at most.
pub const GRAND_CEILING: f64 = 3.0;

/// The cell's reading error per angled region (upper arm, lower arm, wrist, neck, trunk), RMS
/// degrees: the twin's pipeline under the detector fitted to real MediaPipe error on the reference
/// rig, against its truth, over the tuning seeds' station frames (`ergocell sim warnings --detector
/// sim/detectors/mediapipe-pose2sim.toml --seeds 1..20 --fit-confidence` prints it).
pub const READ_ERROR_RMS_DEG: [f64; 5] = [2.14, 2.02, 3.31, 1.52, 1.18];

/// The spacings of the candidate grid the design accepts, metres (1 to 50 mm).
pub const STEP_RANGE_M: std::ops::RangeInclusive<f64> = 0.001..=0.05;

/// Whether `step_m` is a candidate spacing the design accepts ([`STEP_RANGE_M`], finite).
pub fn step_ok(step_m: f64) -> bool {
    step_m.is_finite() && STEP_RANGE_M.contains(&step_m)
}

/// The body model the design costs points on: where the part really arrives around the point (the
/// twin's placement scatter, `target_sigma_m` of [`SessionScript::new`]), the twin's habits and
/// reach, and the cell's reading error ([`READ_ERROR_RMS_DEG`]).
pub fn body_model() -> BodyModel {
    BodyModel {
        placement_sigma_m: SessionScript::new(nalgebra::Point3::origin()).target_sigma_m,
        habits: Habits::default(),
        reach: ReachConfig::default(),
        read_sd_deg: READ_ERROR_RMS_DEG,
    }
}

/// The statures the cost curves are drawn over: 1.50 to 2.00 m, every centimetre.
pub fn chart_statures_m() -> Vec<f64> {
    (0..=50).map(|i| 1.50 + 0.01 * f64::from(i)).collect()
}

/// One class's design.
#[derive(Debug, Clone, Serialize)]
pub struct ClassDesign {
    pub class: TrajectoryClass,
    pub stature_m: [f64; 2],
    /// ANSUR II fitting people of the class the point was chosen for.
    pub fit_people: usize,
    pub candidates: usize,
    pub step_m: f64,
    /// Today's point, on the same people.
    pub hand_set: CandidateCost,
    /// Candidates set aside because the cell would misread their grand score more often than the
    /// hardest class's hand-set point ([`CandidateCost::mean_misread`]): those cheaper than the
    /// chosen one, or all of them when none was chosen.
    pub harder_to_read: usize,
    pub choice: Choice,
}

/// The figures on the people never fitted: the whole reporting half, each at their class's point.
#[derive(Debug, Clone, Serialize)]
pub struct Population {
    /// Every person at the unadapted cell's one point (`--before-handover`).
    pub before: [Option<PopulationCost>; 2],
    /// Each person at their class's hand-set point.
    pub hand_set: [Option<PopulationCost>; 2],
    /// Each person at their class's designed point.
    pub designed: [Option<PopulationCost>; 2],
}

/// Everything the design found: `design.json` as it is written.
#[derive(Debug, Clone, Serialize)]
pub struct DesignReport {
    pub step_m: f64,
    pub classes: Vec<ClassDesign>,
    /// Women first, then men.
    pub population: Population,
    /// Cost against stature (Drillis & Contini's proportions), per class point.
    pub statures_m: Vec<f64>,
    pub curves: Vec<(String, Vec<f64>)>,
}

/// A class as the design needs it: its trajectory file and the hashes of the inputs validation
/// checks a candidate against.
#[derive(Debug, Clone, Copy)]
pub struct ClassFile<'a> {
    pub spec: &'a TrajectorySpec,
    pub hashes: &'a InputHashes,
}

/// A class's fitting people and what today's (hand-set) point costs them.
#[derive(Debug, Clone)]
pub struct Fitted {
    pub people: Vec<Operator>,
    pub hand_set: CandidateCost,
}

impl Fitted {
    /// The most often any class's people misread the grand score at its hand-set point: no
    /// designed point may be misread more often (the cell's warnings and its agreement with the
    /// truth are judged on these readings, and a point on the band edges that move the grand score
    /// makes them disagree however good the posture).
    pub fn hardest_misread(fitted: &[Fitted]) -> f64 {
        fitted
            .iter()
            .fold(0.0, |worst, f| worst.max(f.hand_set.mean_misread))
    }
}

/// What the design is computed from besides the classes.
#[derive(Debug, Clone, Copy)]
pub struct Design<'a> {
    /// ANSUR II, both halves ([`Split`]).
    pub people: &'a [Person],
    pub thresholds: ClassThresholds,
    pub model: BodyModel,
    /// The robot and the cell every candidate is validated on.
    pub robot: &'a RobotModel,
    pub cell: &'a CellConfig,
    /// Spacing of the candidate points in the class's grasp band, metres.
    pub step_m: f64,
    /// At most this many fitting people per class, evenly spread over the subject ids (0 takes
    /// one).
    pub sample: usize,
    /// The unadapted cell's one handover point (station frame), which c1's and c3's points must
    /// improve on.
    pub before_handover: [f64; 3],
}

impl Design<'_> {
    /// The class's fitting people and the cost of its hand-set point to them.
    pub fn fit(&self, spec: &TrajectorySpec) -> Result<Fitted, SimError> {
        let people = self.fitting_people(spec)?;
        let h = &spec.handover;
        let hand_set = design::rank(
            &people,
            &[[h.forward_m, h.lateral_m, h.height_m]],
            &self.model,
        )?[0];
        Ok(Fitted { people, hand_set })
    }

    /// Designs one class: the candidates of its grasp band ranked for its fitting people, those
    /// harder to read than `hardest_misread` set aside, and the cheapest that meets the design's
    /// requirements at every stature the class serves and that validation accepts.
    ///
    /// c1's and c3's points must improve on the unadapted cell's one point (the paper's "before",
    /// set for a 1.75 m operator) for every stature they serve, at every corner of the habits. c2
    /// is the class that point was set for, and its point is chosen freely: held to that
    /// requirement (Drillis & Contini's proportions at 1.68-1.75 m refuse every cheaper candidate)
    /// it keeps the single point itself, which costs the class's measured people more than today's
    /// hand-set point and is misread twice as often.
    pub fn class(
        &self,
        file: ClassFile<'_>,
        fitted: &Fitted,
        hardest_misread: f64,
    ) -> Result<ClassDesign, SimError> {
        let spec = file.spec;
        let band = class_band(spec.stature.min_m, spec.stature.max_m);
        let readable = |c: &CandidateCost| c.mean_misread <= hardest_misread + 1e-12;
        let ranked = design::search(
            &fitted.people,
            band.forward_m,
            band.height_m,
            spec.handover.lateral_m,
            self.step_m,
            KEEP,
            readable,
            &self.model,
        )?;
        let (ranked, unreadable): (Vec<CandidateCost>, Vec<CandidateCost>) =
            ranked.into_iter().partition(readable);
        let req = Requirements {
            before: (spec.class != TrajectoryClass::C2).then_some(self.before_handover),
            margin: MARGIN,
            grand_ceiling: GRAND_CEILING,
        };
        let statures = self.class_statures(spec);
        let choice = design::choose::<SimError>(&ranked, MAX_REFUSALS, |point| {
            let short = design::shortfalls(point, &req, &statures, &self.model)?;
            Ok(short.or_else(|| self.refusal(file, point)))
        })?;
        let harder_to_read = choice.chosen.map_or(unreadable.len(), |chosen| {
            unreadable
                .iter()
                .filter(|c| c.mean_cost < chosen.mean_cost)
                .count()
        });
        Ok(ClassDesign {
            class: spec.class,
            stature_m: [spec.stature.min_m, spec.stature.max_m],
            fit_people: fitted.people.len(),
            candidates: ranked.len() + unreadable.len(),
            step_m: self.step_m,
            hand_set: fitted.hand_set,
            harder_to_read,
            choice,
        })
    }

    /// The report on the designed `classes`: the people never fitted at each point, and the cost
    /// curves against stature.
    pub fn report(&self, classes: Vec<ClassDesign>) -> Result<DesignReport, SimError> {
        let population = self.population(&classes)?;
        let statures_m = chart_statures_m();
        let curves = self.curves(&classes, &statures_m)?;
        Ok(DesignReport {
            step_m: self.step_m,
            classes,
            population,
            statures_m,
            curves,
        })
    }

    /// Whether a person of stature `h` is one the class serves: its side of the thresholds, inside
    /// the class file's `[stature]`.
    fn serves(&self, spec: &TrajectorySpec, h: f64) -> bool {
        trajectory_class(HeightClass::of(h, &self.thresholds)) == spec.class
            && (spec.stature.min_m..=spec.stature.max_m).contains(&h)
    }

    /// The class's people of ANSUR II's fitting half, at most [`Design::sample`] of them, evenly
    /// spread over the subject ids (the cost of a point is a mean; a few hundred people fix it to a
    /// few thousandths).
    fn fitting_people(&self, spec: &TrajectorySpec) -> Result<Vec<Operator>, SimError> {
        let all: Vec<&Person> = self
            .people
            .iter()
            .filter(|p| p.split() == Split::Fit && self.serves(spec, p.stature_m))
            .collect();
        all.iter()
            .step_by(spread(all.len(), self.sample))
            .map(|p| Operator::measured(p))
            .collect()
    }

    /// Where the points must improve on the single point: every centimetre of the class's
    /// statures, Drillis & Contini's proportions.
    fn class_statures(&self, spec: &TrajectorySpec) -> Vec<f64> {
        design::statures(spec.stature.min_m, spec.stature.max_m + 0.005, 0.01)
            .into_iter()
            .filter(|h| self.serves(spec, *h))
            .collect()
    }

    /// Why validation refuses the class file with its handover at `point`, or `None` when it
    /// accepts it.
    fn refusal(&self, file: ClassFile<'_>, point: [f64; 3]) -> Option<String> {
        let [f, l, z] = point;
        let mut candidate = file.spec.clone();
        candidate.handover.forward_m = f;
        candidate.handover.lateral_m = l;
        candidate.handover.height_m = z;
        let inputs = PlanInputs {
            model: self.robot,
            cell: self.cell,
            spec: &candidate,
            hashes: file.hashes,
        };
        match plan_and_validate(&inputs) {
            Ok(v) if v.report.accepted => None,
            Ok(v) => Some(v.report.reasons.join("; ")),
            Err(e) => Some(e.to_string()),
        }
    }

    /// The people never fitted, each at the single before point, their class's hand-set point and
    /// their class's designed point.
    fn population(&self, classes: &[ClassDesign]) -> Result<Population, SimError> {
        let mut costs: [Vec<(Sex, f64)>; 3] = Default::default();
        for p in self.people.iter().filter(|p| p.split() == Split::Report) {
            let op = Operator::measured(p)?;
            let class = trajectory_class(HeightClass::of(p.stature_m, &self.thresholds));
            let Some(c) = classes.iter().find(|c| c.class == class) else {
                return Err(SimError::BadParameter {
                    name: "classes",
                    value: classes.len() as f64,
                    why: "the population needs the design of every class",
                });
            };
            for (j, at) in [self.before_handover, c.hand_set.station_m, c.designed_m()]
                .into_iter()
                .enumerate()
            {
                let cost = design::hold_cost(&op, &at.into(), &self.model)?;
                costs[j].push((p.sex, cost.cost));
            }
        }
        let [before, hand_set, designed] = costs.map(|c| design::population(&c));
        Ok(Population {
            before,
            hand_set,
            designed,
        })
    }

    /// The cost against stature of the before point, then each class's hand-set and designed
    /// points.
    fn curves(
        &self,
        classes: &[ClassDesign],
        statures_m: &[f64],
    ) -> Result<Vec<(String, Vec<f64>)>, SimError> {
        let mut named = vec![(
            "before: the one point for everyone".to_owned(),
            self.before_handover,
        )];
        for c in classes {
            named.push((format!("{} hand-set", c.class), c.hand_set.station_m));
            named.push((format!("{} designed", c.class), c.designed_m()));
        }
        named
            .into_iter()
            .map(|(name, at)| -> Result<(String, Vec<f64>), SimError> {
                let curve = statures_m
                    .iter()
                    .map(|&h| {
                        Ok(design::hold_cost(&Operator::new(h)?, &at.into(), &self.model)?.cost)
                    })
                    .collect::<Result<Vec<f64>, SimError>>()?;
                Ok((name, curve))
            })
            .collect()
    }
}

/// The stride that takes at most `sample` of `n` items evenly (every item when `sample` is at
/// least `n`; one item when it is 0).
fn spread(n: usize, sample: usize) -> usize {
    n.div_ceil(sample.max(1)).max(1)
}

impl ClassDesign {
    /// The designed point, or the hand-set one when no candidate was chosen.
    pub fn designed_m(&self) -> [f64; 3] {
        self.choice
            .chosen
            .map_or(self.hand_set.station_m, |chosen| chosen.station_m)
    }

    /// The line `design` prints when the class is done.
    pub fn progress_text(&self) -> String {
        format!(
            "{}: {} fitting people, {} candidates, {} cheaper ones harder to read, {} refused",
            self.class,
            self.fit_people,
            self.candidates,
            self.harder_to_read,
            self.choice.refused.len()
        )
    }

    /// The comment written above the designed class file's `[handover]` point (`chosen`, the
    /// class's chosen candidate): where it came from, as TOML comment lines of at most 104
    /// characters, between line breaks.
    pub fn handover_comment(&self, chosen: &CandidateCost) -> String {
        let hs = self.hand_set.station_m;
        let requirement = if self.class == TrajectoryClass::C2 {
            "the class the unadapted cell's one point was set for, compared with it only in the \
             report, so the twin's per-stature comparison may find it costlier than that point at \
             some statures"
        } else {
            "a lower cost, by the margin, and no higher RULA than at the unadapted cell's one point"
        };
        let text = format!(
            "Designed (`ergocell trajectories design`): of {n} candidate points (down to {step:.1} mm \
             apart) in the class band, the one with the lowest expected posture cost for {p} ANSUR II \
             people of the class from the fitting half (even subject ids, {lo:.2}–{hi:.2} m), on the \
             twin's body model, with the hold repeated all shift (RULA's muscle use where it leaves the \
             relaxed posture), that meets the design's requirements at every stature of the class and \
             every corner of the habits a session draws (RULA at most 3 before repetitions; \
             {requirement}), that the cell misreads no more often than the hardest hand-set point, and \
             that `trajectories validate` accepts: mean posture cost {cost:.3} (RULA grand score \
             {grand:.2}, grand score misread {misread:.1} % of the time); the hand-set point ({hf:.3}, \
             {hz:.3}) m cost them {hcost:.3} ({hgrand:.2}, {hmisread:.1} %). {harder} \
             cheaper candidates were harder to read, {refused} were refused. See design.json.",
            n = self.candidates,
            step = self.step_m * 1e3,
            p = self.fit_people,
            lo = self.stature_m[0],
            hi = self.stature_m[1],
            cost = chosen.mean_cost,
            grand = chosen.mean_grand_score,
            hf = hs[0],
            hz = hs[2],
            hcost = self.hand_set.mean_cost,
            hgrand = self.hand_set.mean_grand_score,
            misread = 100.0 * chosen.mean_misread,
            hmisread = 100.0 * self.hand_set.mean_misread,
            harder = self.harder_to_read,
            refused = self.choice.refused.len(),
        );
        format!("\n{}\n", comment_lines(&text, 104))
    }
}

/// `text` as TOML comment lines of at most `width` characters (a longer word gets a line of its
/// own).
fn comment_lines(text: &str, width: usize) -> String {
    let mut lines: Vec<String> = Vec::new();
    let mut line = String::from("#");
    for word in text.split_whitespace() {
        if line.len() > 1 && line.chars().count() + 1 + word.chars().count() > width {
            lines.push(std::mem::replace(&mut line, String::from("#")));
        }
        line.push(' ');
        line.push_str(word);
    }
    lines.push(line);
    lines.join("\n")
}

/// One group's costs: `women …; men …`, each mean, 95th percentile and head count, or a dash.
fn population_text(p: &[Option<PopulationCost>; 2]) -> String {
    let one = |x: &Option<PopulationCost>| {
        x.map_or("—".to_owned(), |c| {
            format!("mean {:.3}, p95 {:.3} ({} people)", c.mean, c.p95, c.people)
        })
    };
    format!("women {}; men {}", one(&p[0]), one(&p[1]))
}

impl DesignReport {
    /// What `design` prints: each class's hand-set and designed points with their costs, then the
    /// people never fitted at the three kinds of point. Every line ends in a line break.
    pub fn text(&self) -> String {
        let mut out = String::from(
            "posture cost of holding the part (RULA points), ANSUR II fitting half:\n",
        );
        for c in &self.classes {
            let hs = &c.hand_set;
            let Some(d) = &c.choice.chosen else {
                let _ = writeln!(out, "  {}: no candidate validated", c.class);
                continue;
            };
            let _ = writeln!(
                out,
                "  {}: hand-set ({:.3}, {:.3}, {:.3}) m {:.3} (misread {:.1} %) → designed ({:.3}, {:.3}, {:.3}) m {:.3} (misread {:.1} %) ({} people, {} cheaper harder to read, {} refused)",
                c.class,
                hs.station_m[0], hs.station_m[1], hs.station_m[2], hs.mean_cost, 100.0 * hs.mean_misread,
                d.station_m[0], d.station_m[1], d.station_m[2], d.mean_cost, 100.0 * d.mean_misread,
                c.fit_people, c.harder_to_read, c.choice.refused.len()
            );
        }
        let p = &self.population;
        out.push_str("people never fitted (reporting half), posture cost:\n");
        let _ = writeln!(out, "  before (one point): {}", population_text(&p.before));
        let _ = writeln!(
            out,
            "  hand-set classes:   {}",
            population_text(&p.hand_set)
        );
        let _ = writeln!(
            out,
            "  designed classes:   {}",
            population_text(&p.designed)
        );
        out
    }

    /// The chart's cost axis: every curve's values with a tenth of a point to spare, on tenths
    /// (1 to 7, RULA's range, when there is no finite value).
    pub fn y_range(&self) -> (f64, f64) {
        let values = self.curves.iter().flat_map(|(_, v)| v.iter().copied());
        let (lo, hi) = values
            .filter(|v| v.is_finite())
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), v| {
                (lo.min(v), hi.max(v))
            });
        if lo > hi {
            return (1.0, 7.0);
        }
        (
            (lo * 10.0).floor() / 10.0 - 0.1,
            (hi * 10.0).ceil() / 10.0 + 0.1,
        )
    }

    /// `design_cost.svg`: the cost against stature of every point, the before point solid in the
    /// first colour, then each class in a colour of its own, hand-set dashed and designed solid.
    pub fn figure(&self) -> Result<Figure, FigureError> {
        let series: Vec<(&str, &[f64], _, bool)> = self
            .curves
            .iter()
            .enumerate()
            .map(|(i, (name, v))| {
                let colour = [COLORS[0], COLORS[4], COLORS[5], COLORS[3]][i.div_ceil(2).min(3)];
                (name.as_str(), v.as_slice(), colour, i % 2 == 1)
            })
            .collect();
        line_chart(
            "design_cost.svg",
            "Posture cost of holding the part against stature, per class's point",
            "operator stature, m",
            "posture cost (RULA points)",
            &self.statures_m,
            &series,
            self.y_range(),
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn cost(station_m: [f64; 3], mean_cost: f64, mean_misread: f64) -> CandidateCost {
        CandidateCost {
            station_m,
            mean_cost,
            mean_grand_score: 3.0,
            mean_first_cost: mean_cost,
            mean_first_grand_score: 3.0,
            mean_misread,
            worst_miss_m: 0.0,
        }
    }

    fn class_design(chosen: Option<CandidateCost>) -> ClassDesign {
        ClassDesign {
            class: TrajectoryClass::C1,
            stature_m: [1.5, 1.62],
            fit_people: 150,
            candidates: 40,
            step_m: 0.005,
            hand_set: cost([0.3, -0.1, 0.95], 2.5, 0.1),
            harder_to_read: 3,
            choice: Choice {
                chosen,
                refused: vec![(cost([0.31, -0.1, 0.9], 2.0, 0.0), "no".to_owned())],
            },
        }
    }

    fn report(curves: Vec<(String, Vec<f64>)>) -> DesignReport {
        let pc = |people, mean, p95| Some(PopulationCost { people, mean, p95 });
        DesignReport {
            step_m: 0.005,
            classes: vec![
                class_design(Some(cost([0.305, -0.1, 1.0], 2.25, 0.05))),
                class_design(None),
            ],
            population: Population {
                before: [pc(10, 3.0, 4.0), None],
                hand_set: [pc(10, 2.5, 3.5), pc(12, 2.75, 3.25)],
                designed: [None, None],
            },
            statures_m: vec![1.5, 1.6],
            curves,
        }
    }

    #[test]
    fn comment_lines_wrap_at_the_width_and_keep_every_word() {
        let text = "one two three four five six seven eight nine ten eleven twelve";
        let out = comment_lines(text, 20);
        assert!(out
            .lines()
            .all(|l| l.starts_with("# ") && l.chars().count() <= 20));
        let words: Vec<&str> = out.lines().flat_map(|l| l[2..].split(' ')).collect();
        assert_eq!(words.join(" "), text);
        assert_eq!(
            comment_lines("averyveryverylongword", 5),
            "# averyveryverylongword"
        );
    }

    #[test]
    fn the_y_range_holds_every_finite_value_on_tenths_with_a_tenth_to_spare() {
        let r = report(vec![
            ("a".to_owned(), vec![2.34, f64::NAN]),
            ("b".to_owned(), vec![3.01, f64::INFINITY]),
        ]);
        let (lo, hi) = r.y_range();
        assert!(
            (lo - 2.2).abs() < 1e-12 && (hi - 3.2).abs() < 1e-12,
            "{lo} {hi}"
        );
        assert_eq!(
            report(vec![("a".to_owned(), vec![f64::NAN])]).y_range(),
            (1.0, 7.0)
        );
        assert_eq!(report(Vec::new()).y_range(), (1.0, 7.0));
    }

    #[test]
    fn the_report_text_lists_each_class_and_each_group() {
        let text = report(Vec::new()).text();
        let lines: Vec<&str> = text.lines().collect();
        assert_eq!(
            lines,
            [
                "posture cost of holding the part (RULA points), ANSUR II fitting half:",
                "  c1: hand-set (0.300, -0.100, 0.950) m 2.500 (misread 10.0 %) → designed \
                 (0.305, -0.100, 1.000) m 2.250 (misread 5.0 %) (150 people, 3 cheaper harder to \
                 read, 1 refused)",
                "  c1: no candidate validated",
                "people never fitted (reporting half), posture cost:",
                "  before (one point): women mean 3.000, p95 4.000 (10 people); men —",
                "  hand-set classes:   women mean 2.500, p95 3.500 (10 people); men mean 2.750, p95 \
                 3.250 (12 people)",
                "  designed classes:   women —; men —",
            ]
        );
        assert!(text.ends_with('\n'));
    }

    #[test]
    fn a_class_says_its_progress_and_falls_back_to_its_hand_set_point() {
        let chosen = cost([0.305, -0.1, 1.0], 2.25, 0.05);
        let designed = class_design(Some(chosen));
        assert_eq!(designed.designed_m(), [0.305, -0.1, 1.0]);
        assert_eq!(class_design(None).designed_m(), [0.3, -0.1, 0.95]);
        assert_eq!(
            designed.progress_text(),
            "c1: 150 fitting people, 40 candidates, 3 cheaper ones harder to read, 1 refused"
        );
        let comment = designed.handover_comment(&chosen);
        assert!(comment.starts_with("\n# Designed") && comment.ends_with(" See design.json.\n"));
        assert!(comment
            .lines()
            .skip(1)
            .all(|l| l.starts_with("# ") && l.chars().count() <= 104));
        let words = comment.split_whitespace().filter(|w| *w != "#");
        let said: Vec<&str> = words.collect();
        for phrase in [
            "of 40 candidate points (down to 5.0 mm apart)",
            "for 150 ANSUR II people",
            "(even subject ids, 1.50–1.62 m)",
            "mean posture cost 2.250 (RULA grand score 3.00, grand score misread 5.0 % of the time)",
            "the hand-set point (0.300, 0.950) m cost them 2.500 (3.00, 10.0 %). 3 cheaper \
             candidates were harder to read, 1 were refused.",
            "no higher RULA than at the unadapted cell's one point",
        ] {
            assert!(said.join(" ").contains(phrase), "{phrase}: {comment}");
        }
    }

    #[test]
    fn spread_takes_at_most_the_sample_evenly() {
        assert_eq!(spread(1000, 150), 7);
        assert_eq!((0..1000).step_by(spread(1000, 150)).count(), 143);
        assert_eq!(spread(100, 150), 1);
        assert_eq!(spread(0, 150), 1);
        assert_eq!(spread(10, 0), 10);
        assert!(step_ok(0.01) && step_ok(0.001) && step_ok(0.05));
        assert!(!step_ok(0.0009) && !step_ok(0.051) && !step_ok(f64::NAN));
        assert_eq!(chart_statures_m().len(), 51);
        assert!((chart_statures_m()[50] - 2.0).abs() < 1e-12);
    }
}
