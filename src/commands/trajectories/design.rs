//! `ergocell trajectories design --out-dir <dir>`: each class's handover point chosen for the people
//! it serves, written as class files for the safety engineer's review.
//!
//! Composition only: the people are ANSUR II's ([`ergocell_anthropometry::ansur`]), split by
//! subject id; the cost of a point is the twin's body model ([`ergocell_sim::design`]); a candidate
//! is accepted only by the same [`plan_and_validate`] as `trajectories validate`. Nothing is locked
//! or approved here: `lock` and `approve` follow as for any edited class file.

use std::path::Path;

use anyhow::Context as _;
use ergocell_anthropometry::ansur::{self, Person, Sex, Split};
use ergocell_ergonomics::height::ClassThresholds;
use ergocell_ergonomics::HeightClass;
use ergocell_robot::validate::class_band;
use ergocell_robot::{plan_and_validate, PlanInputs, TrajectoryClass, TrajectorySpec};
use ergocell_sim::design::{self, BodyModel, CandidateCost, Choice, PopulationCost, Requirements};
use ergocell_sim::session::Habits;
use ergocell_sim::{Operator, ReachConfig};
use serde::Serialize;

use super::{write_new, Context};
use ergocell::session::trajectory_class;
use ergocell_sim::report::{line_chart, COLORS};

/// How many of the cheapest candidates may be refused before a class gives up.
const MAX_REFUSALS: usize = 400;

/// How many of the cheapest points of the coarse grid are refined ([`design::search`]).
const KEEP: usize = 6;

/// How much lower than at the "before" point c1's and c3's designed point must put the posture cost
/// of every stature they serve, at every corner of the habits (RULA points): a margin for what the
/// twin's sessions add to the body model (each person's build, the robot's placement scatter).
const MARGIN: f64 = 0.02;

/// The highest RULA grand score any stature of a class may hold its point at, at every node of the
/// body model's averages (not only on average): action level 2 at most.
const GRAND_CEILING: f64 = 3.0;

/// The cell's reading error per angled region (upper arm, lower arm, wrist, neck, trunk), RMS
/// degrees: the twin's pipeline under the detector fitted to real MediaPipe error on the reference
/// rig, against its truth, over the tuning seeds' station frames (`ergocell sim warnings --detector
/// sim/detectors/mediapipe-pose2sim.toml --seeds 1..20 --fit-confidence` prints it).
const READ_ERROR_RMS_DEG: [f64; 5] = [2.14, 2.02, 3.31, 1.52, 1.18];

/// Where the part really arrives around the point, σ per axis (metres): the twin's
/// placement scatter (`target_sigma_m` of [`ergocell_sim::SessionScript::new`]).
fn scatter_m() -> f64 {
    ergocell_sim::SessionScript::new(nalgebra::Point3::origin()).target_sigma_m
}

/// One class's design.
#[derive(Debug, Serialize)]
struct ClassDesign {
    class: TrajectoryClass,
    stature_m: [f64; 2],
    /// ANSUR II fitting people of the class the point was chosen for.
    fit_people: usize,
    candidates: usize,
    step_m: f64,
    /// Today's point, on the same people.
    hand_set: CandidateCost,
    /// Candidates set aside because the cell would misread their grand score more often than the
    /// hardest class's hand-set point ([`CandidateCost::mean_misread`]): those cheaper than the
    /// chosen one, or all of them when none was chosen.
    harder_to_read: usize,
    choice: Choice,
}

/// The figures on the people never fitted: the whole reporting half, each at their class's point.
#[derive(Debug, Serialize)]
struct Population {
    /// Every person at the unadapted cell's one point (`--before-handover`).
    before: [Option<PopulationCost>; 2],
    /// Each person at their class's hand-set point.
    hand_set: [Option<PopulationCost>; 2],
    /// Each person at their class's designed point.
    designed: [Option<PopulationCost>; 2],
}

#[derive(Debug, Serialize)]
struct Report {
    step_m: f64,
    classes: Vec<ClassDesign>,
    /// Women first, then men.
    population: Population,
    /// Cost against stature (Drillis & Contini's proportions), per class point.
    statures_m: Vec<f64>,
    curves: Vec<(String, Vec<f64>)>,
}

/// Runs the design and writes `<out_dir>/c1.toml`…, `design.json` and `design_cost.svg`, none of
/// them over an existing file.
pub(super) fn design(
    ctx: &Context,
    out_dir: &Path,
    step_m: f64,
    sample: usize,
    before_handover: [f64; 3],
) -> anyhow::Result<()> {
    if !(step_m.is_finite() && (0.001..=0.05).contains(&step_m)) {
        anyhow::bail!(super::UsageError(format!(
            "--step {step_m}: expected 0.001 to 0.05 m"
        )));
    }
    let outputs: Vec<std::path::PathBuf> = TrajectoryClass::ALL
        .iter()
        .map(|c| out_dir.join(format!("{c}.toml")))
        .chain(["design.json", "design_cost.svg"].map(|f| out_dir.join(f)))
        .collect();
    // Before three minutes of work, not after: nothing here is ever written over.
    if let Some(taken) = outputs.iter().find(|p| p.exists()) {
        anyhow::bail!(super::UsageError(format!(
            "{} exists: design writes into a new folder and never over a file",
            taken.display()
        )));
    }
    let people = ansur::people()?;
    let thresholds = ClassThresholds::default();
    let model = BodyModel {
        placement_sigma_m: scatter_m(),
        habits: Habits::default(),
        reach: ReachConfig::default(),
        read_sd_deg: READ_ERROR_RMS_DEG,
    };
    let mut specs = Vec::new();
    for class in TrajectoryClass::ALL {
        let (spec, hashes, text) = ctx.spec_with_text(class)?;
        specs.push((class, text, spec, hashes));
    }
    // How often the cell misreads the grand score at today's points, on each class's people: no
    // designed point may be misread more often than the hardest of them (the cell's warnings and
    // its agreement with the truth are judged on these readings, and a point on the band edges
    // that move the grand score makes them disagree however good the posture).
    let mut hand_set_misread: f64 = 0.0;
    let mut fitted = Vec::new();
    for (class, _, spec, _) in &specs {
        let fit = fitting_people(&people, *class, spec, &thresholds, sample)?;
        let h = &spec.handover;
        let hand_set = design::rank(&fit, &[[h.forward_m, h.lateral_m, h.height_m]], &model)?[0];
        hand_set_misread = hand_set_misread.max(hand_set.mean_misread);
        fitted.push((fit, hand_set));
    }
    let mut designs = Vec::new();
    for ((class, _, spec, hashes), (fit, hand_set)) in specs.iter().zip(fitted) {
        // c1's and c3's points must improve on the unadapted cell's one point (the paper's
        // "before", set for a 1.75 m operator: the twin's `--before-handover`) for every stature
        // they serve, at every corner of the habits. c2 is the class that point was set for, and
        // its point is chosen freely: held to that requirement (Drillis & Contini's proportions
        // at 1.68-1.75 m refuse every cheaper candidate) it keeps the single point itself, which
        // costs the class's measured people more than today's hand-set point and is misread
        // twice as often.
        let before = (*class != TrajectoryClass::C2).then_some(before_handover);
        let in_class = |h: f64| serves(*class, spec, &thresholds, h);
        let band = class_band(spec.stature.min_m, spec.stature.max_m);
        let h = &spec.handover;
        let readable = |c: &CandidateCost| c.mean_misread <= hand_set_misread + 1e-12;
        let ranked = design::search(
            &fit,
            band.forward_m,
            band.height_m,
            h.lateral_m,
            step_m,
            KEEP,
            readable,
            &model,
        )?;
        let (ranked, unreadable): (Vec<CandidateCost>, Vec<CandidateCost>) =
            ranked.into_iter().partition(readable);
        // Where the points must improve on the single point: every centimetre of the class's
        // statures, Drillis & Contini's proportions.
        let statures: Vec<f64> =
            design::statures(spec.stature.min_m, spec.stature.max_m + 0.005, 0.01)
                .into_iter()
                .filter(|h| in_class(*h))
                .collect();
        let choice = design::choose::<anyhow::Error>(&ranked, MAX_REFUSALS, |point| {
            let req = Requirements {
                before,
                margin: MARGIN,
                grand_ceiling: GRAND_CEILING,
            };
            let short = design::shortfalls(point, &req, &statures, &model)?;
            if short.is_some() {
                return Ok(short);
            }
            let [f, l, z] = point;
            let mut candidate: TrajectorySpec = spec.clone();
            candidate.handover.forward_m = f;
            candidate.handover.lateral_m = l;
            candidate.handover.height_m = z;
            let inputs = PlanInputs {
                model: &ctx.model,
                cell: &ctx.cell,
                spec: &candidate,
                hashes,
            };
            Ok(match plan_and_validate(&inputs) {
                Ok(v) if v.report.accepted => None,
                Ok(v) => Some(v.report.reasons.join("; ")),
                Err(e) => Some(e.to_string()),
            })
        })?;
        let harder_to_read = choice.chosen.map_or(unreadable.len(), |chosen| {
            unreadable
                .iter()
                .filter(|c| c.mean_cost < chosen.mean_cost)
                .count()
        });
        eprintln!(
            "{class}: {} fitting people, {} candidates, {} cheaper ones harder to read, {} refused",
            fit.len(),
            ranked.len() + unreadable.len(),
            harder_to_read,
            choice.refused.len()
        );
        designs.push(ClassDesign {
            class: *class,
            stature_m: [spec.stature.min_m, spec.stature.max_m],
            fit_people: fit.len(),
            candidates: ranked.len() + unreadable.len(),
            step_m,
            hand_set,
            harder_to_read,
            choice,
        });
    }
    let classes = designs;
    let point = |i: usize, designed: bool| -> [f64; 3] {
        let c = &classes[i];
        match (designed, &c.choice.chosen) {
            (true, Some(chosen)) => chosen.station_m,
            _ => c.hand_set.station_m,
        }
    };
    // The people never fitted, each at the single before point, their class's hand-set point and
    // their class's designed point.
    let before = before_handover;
    let mut costs: [Vec<(Sex, f64)>; 3] = Default::default();
    for p in people.iter().filter(|p| p.split() == Split::Report) {
        let op = Operator::measured(p)?;
        let class = trajectory_class(HeightClass::of(p.stature_m, &thresholds));
        let k = TrajectoryClass::ALL
            .iter()
            .position(|c| *c == class)
            .unwrap_or(1);
        for (j, at) in [before, point(k, false), point(k, true)]
            .into_iter()
            .enumerate()
        {
            let c = design::hold_cost(&op, &at.into(), &model)?;
            costs[j].push((p.sex, c.cost));
        }
    }
    let [b, hs, d] = costs.map(|c| design::population(&c));
    let statures_m: Vec<f64> = (0..=50).map(|i| 1.50 + 0.01 * f64::from(i)).collect();
    let mut curves = Vec::new();
    let mut named = vec![("before: the one point for everyone".to_owned(), before)];
    for (i, c) in classes.iter().enumerate() {
        named.push((format!("{} hand-set", c.class), point(i, false)));
        named.push((format!("{} designed", c.class), point(i, true)));
    }
    for (name, at) in named {
        let curve = statures_m
            .iter()
            .map(|&h| {
                let op = Operator::new(h)?;
                Ok(design::hold_cost(&op, &at.into(), &model)?.cost)
            })
            .collect::<Result<Vec<f64>, ergocell_sim::SimError>>()?;
        curves.push((name, curve));
    }
    let report = Report {
        step_m,
        classes,
        population: Population {
            before: b,
            hand_set: hs,
            designed: d,
        },
        statures_m,
        curves,
    };
    std::fs::create_dir_all(out_dir)
        .with_context(|| format!("cannot create {}", out_dir.display()))?;
    for (i, (class, text, _, _)) in specs.iter().enumerate() {
        let c = &report.classes[i];
        let Some(chosen) = &c.choice.chosen else {
            eprintln!("{class}: no candidate validated; its file is not written");
            continue;
        };
        let edited = with_handover(text, c, chosen)?;
        let path = out_dir.join(format!("{class}.toml"));
        write_new(&path, &edited)?;
        println!("wrote {}", path.display());
    }
    print_report(&report);
    let json = out_dir.join("design.json");
    write_new(&json, &serde_json::to_string_pretty(&report)?)?;
    println!("wrote {}", json.display());
    let svg = out_dir.join("design_cost.svg");
    write_new(&svg, &plot(&report)?.svg)?;
    println!("wrote {}", svg.display());
    Ok(())
}

/// Whether a person of stature `h` is one the class serves: its side of the thresholds, inside the
/// class file's `[stature]`.
fn serves(class: TrajectoryClass, spec: &TrajectorySpec, t: &ClassThresholds, h: f64) -> bool {
    trajectory_class(HeightClass::of(h, t)) == class
        && (spec.stature.min_m..=spec.stature.max_m).contains(&h)
}

/// The class's people of ANSUR II's fitting half, at most `sample` of them, evenly spread over the
/// subject ids (the cost of a point is a mean; a few hundred people fix it to a few thousandths).
fn fitting_people(
    people: &[Person],
    class: TrajectoryClass,
    spec: &TrajectorySpec,
    t: &ClassThresholds,
    sample: usize,
) -> anyhow::Result<Vec<Operator>> {
    let all: Vec<&Person> = people
        .iter()
        .filter(|p| p.split() == Split::Fit && serves(class, spec, t, p.stature_m))
        .collect();
    let every = all.len().div_ceil(sample.max(1)).max(1);
    Ok(all
        .iter()
        .step_by(every)
        .map(|p| Operator::measured(p))
        .collect::<Result<_, _>>()?)
}

/// The class file with its `[handover]` point replaced, and the comment above it saying where it
/// came from; everything else (comments included) as it was.
fn with_handover(text: &str, c: &ClassDesign, chosen: &CandidateCost) -> anyhow::Result<String> {
    let mut doc: toml_edit::DocumentMut = text.parse().context("class file")?;
    let handover = doc
        .get_mut("handover")
        .and_then(toml_edit::Item::as_table_mut)
        .context("class file has no [handover] table")?;
    let [f, l, z] = chosen.station_m;
    let hs = c.hand_set.station_m;
    let requirement = if c.class == TrajectoryClass::C2 {
        "the class the unadapted cell's one point was set for, compared with it only in the report, \
         so the twin's per-stature comparison may find it costlier than that point at some \
         statures"
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
        n = c.candidates,
        step = c.step_m * 1e3,
        p = c.fit_people,
        lo = c.stature_m[0],
        hi = c.stature_m[1],
        cost = chosen.mean_cost,
        grand = chosen.mean_grand_score,
        hf = hs[0],
        hz = hs[2],
        hcost = c.hand_set.mean_cost,
        hgrand = c.hand_set.mean_grand_score,
        misread = 100.0 * chosen.mean_misread,
        hmisread = 100.0 * c.hand_set.mean_misread,
        harder = c.harder_to_read,
        refused = c.choice.refused.len(),
    );
    let comment = format!("\n{}\n", comment_lines(&text, 104));
    // The validated point itself (the grid's points are round to the micrometre).
    handover["forward_m"] = toml_edit::value(f);
    handover["lateral_m"] = toml_edit::value(l);
    handover["height_m"] = toml_edit::value(z);
    if let Some(mut key) = handover.key_mut("forward_m") {
        key.leaf_decor_mut().set_prefix(comment);
    }
    let out = doc.to_string();
    TrajectorySpec::from_toml_str(&out).context("the designed class file does not read back")?;
    Ok(out)
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

fn population_text(p: &[Option<PopulationCost>; 2]) -> String {
    let one = |x: &Option<PopulationCost>| {
        x.map_or("—".to_owned(), |c| {
            format!("mean {:.3}, p95 {:.3} ({} people)", c.mean, c.p95, c.people)
        })
    };
    format!("women {}; men {}", one(&p[0]), one(&p[1]))
}

fn print_report(r: &Report) {
    println!("posture cost of holding the part (RULA points), ANSUR II fitting half:");
    for c in &r.classes {
        let hs = &c.hand_set;
        let Some(d) = &c.choice.chosen else {
            println!("  {}: no candidate validated", c.class);
            continue;
        };
        println!(
            "  {}: hand-set ({:.3}, {:.3}, {:.3}) m {:.3} (misread {:.1} %) → designed ({:.3}, {:.3}, {:.3}) m {:.3} (misread {:.1} %) ({} people, {} cheaper harder to read, {} refused)",
            c.class,
            hs.station_m[0], hs.station_m[1], hs.station_m[2], hs.mean_cost, 100.0 * hs.mean_misread,
            d.station_m[0], d.station_m[1], d.station_m[2], d.mean_cost, 100.0 * d.mean_misread,
            c.fit_people, c.harder_to_read, c.choice.refused.len()
        );
    }
    println!("people never fitted (reporting half), posture cost:");
    println!(
        "  before (one point): {}",
        population_text(&r.population.before)
    );
    println!(
        "  hand-set classes:   {}",
        population_text(&r.population.hand_set)
    );
    println!(
        "  designed classes:   {}",
        population_text(&r.population.designed)
    );
}

/// The chart's cost axis: every curve's values with a tenth of a point to spare, on tenths.
fn y_range(r: &Report) -> (f64, f64) {
    let values = r.curves.iter().flat_map(|(_, v)| v.iter().copied());
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

fn plot(r: &Report) -> Result<ergocell_sim::report::Figure, ergocell_sim::report::FigureError> {
    let series: Vec<(&str, &[f64], _, bool)> = r
        .curves
        .iter()
        .enumerate()
        .map(|(i, (name, v))| {
            // The before point, then c1, c2 and c3 in colours apart.
            let colour = [COLORS[0], COLORS[4], COLORS[5], COLORS[3]][i.div_ceil(2).min(3)];
            // Hand-set dashed, designed solid; the before line solid in the first colour.
            (name.as_str(), v.as_slice(), colour, i % 2 == 1)
        })
        .collect();
    line_chart(
        "design_cost.svg",
        "Posture cost of holding the part against stature, per class's point",
        "operator stature, m",
        "posture cost (RULA points)",
        &r.statures_m,
        &series,
        y_range(r),
    )
}

#[cfg(test)]
mod tests {
    #[test]
    fn comment_lines_wrap_at_the_width_and_keep_every_word() {
        let text = "one two three four five six seven eight nine ten eleven twelve";
        let out = super::comment_lines(text, 20);
        assert!(out
            .lines()
            .all(|l| l.starts_with("# ") && l.chars().count() <= 20));
        let words: Vec<&str> = out.lines().flat_map(|l| l[2..].split(' ')).collect();
        assert_eq!(words.join(" "), text);
        assert_eq!(
            super::comment_lines("averyveryverylongword", 5),
            "# averyveryverylongword"
        );
    }
}
