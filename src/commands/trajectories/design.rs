//! `ergocell trajectories design --out-dir <dir>`: each class's handover point chosen for the people
//! it serves, written as class files for the safety engineer's review.
//!
//! Composition only: the people are ANSUR II's ([`ergocell_anthropometry::ansur`]); the design,
//! its report and its figure are [`ergocell_sim::design_report`]'s (the twin's body model, a
//! candidate accepted only by the same [`ergocell_robot::plan_and_validate`] as `trajectories
//! validate`). Here: the class files read, their `[handover]` edited in place (comments kept), and
//! the outputs written. Nothing is locked or approved here: `lock` and `approve` follow as for any
//! edited class file.

use std::path::{Path, PathBuf};

use anyhow::Context as _;
use ergocell_anthropometry::ansur;
use ergocell_ergonomics::height::ClassThresholds;
use ergocell_robot::{InputHashes, TrajectoryClass, TrajectorySpec};
use ergocell_sim::design_report::{self, ClassFile, Design, DesignReport, Fitted};

use super::{write_new, Context, UsageError};

/// The files `design` writes into `--out-dir`, besides the class files.
const REPORT_FILES: [&str; 2] = ["design.json", "design_cost.svg"];

/// Runs the design and writes `<out_dir>/c1.toml`…, `design.json` and `design_cost.svg`, none of
/// them over an existing file.
pub(super) fn design(
    ctx: &Context,
    out_dir: &Path,
    step_m: f64,
    sample: usize,
    before_handover: [f64; 3],
) -> anyhow::Result<()> {
    if !design_report::step_ok(step_m) {
        anyhow::bail!(UsageError(format!(
            "--step {step_m}: expected 0.001 to 0.05 m"
        )));
    }
    // Before three minutes of work, not after: nothing here is ever written over.
    if let Some(taken) = outputs(out_dir).iter().find(|p| p.exists()) {
        anyhow::bail!(UsageError(format!(
            "{} exists: design writes into a new folder and never over a file",
            taken.display()
        )));
    }
    let people = ansur::people()?;
    let design = Design {
        people: &people,
        thresholds: ClassThresholds::default(),
        model: design_report::body_model(),
        robot: &ctx.model,
        cell: &ctx.cell,
        step_m,
        sample,
        before_handover,
    };
    let mut specs = Vec::new();
    for class in TrajectoryClass::ALL {
        specs.push(ctx.spec_with_text(class)?);
    }
    let report = designed(&design, &specs)?;
    write_outputs(out_dir, &specs, &report)
}

/// Every file `design` would write into `out_dir`.
fn outputs(out_dir: &Path) -> Vec<PathBuf> {
    TrajectoryClass::ALL
        .iter()
        .map(|c| out_dir.join(format!("{c}.toml")))
        .chain(REPORT_FILES.map(|f| out_dir.join(f)))
        .collect()
}

/// Each class fitted, then designed (saying so as each is done), then the report.
fn designed(
    design: &Design<'_>,
    specs: &[(TrajectorySpec, InputHashes, String)],
) -> anyhow::Result<DesignReport> {
    let fitted = specs
        .iter()
        .map(|(spec, _, _)| design.fit(spec))
        .collect::<Result<Vec<Fitted>, _>>()?;
    let hardest_misread = Fitted::hardest_misread(&fitted);
    let mut classes = Vec::new();
    for ((spec, hashes, _), fitted) in specs.iter().zip(&fitted) {
        let class = design.class(ClassFile { spec, hashes }, fitted, hardest_misread)?;
        eprintln!("{}", class.progress_text());
        classes.push(class);
    }
    Ok(design.report(classes)?)
}

/// Writes the designed class files (each class's file as it was, its point replaced), prints the
/// report, and writes `design.json` and `design_cost.svg`.
fn write_outputs(
    out_dir: &Path,
    specs: &[(TrajectorySpec, InputHashes, String)],
    report: &DesignReport,
) -> anyhow::Result<()> {
    std::fs::create_dir_all(out_dir)
        .with_context(|| format!("cannot create {}", out_dir.display()))?;
    for ((spec, _, text), c) in specs.iter().zip(&report.classes) {
        let class = spec.class;
        let Some(chosen) = &c.choice.chosen else {
            eprintln!("{class}: no candidate validated; its file is not written");
            continue;
        };
        let edited = with_handover(text, &c.handover_comment(chosen), chosen.station_m)?;
        let path = out_dir.join(format!("{class}.toml"));
        write_new(&path, &edited)?;
        println!("wrote {}", path.display());
    }
    print!("{}", report.text());
    let [json, svg] = REPORT_FILES.map(|f| out_dir.join(f));
    write_new(&json, &serde_json::to_string_pretty(report)?)?;
    println!("wrote {}", json.display());
    write_new(&svg, &report.figure()?.svg)?;
    println!("wrote {}", svg.display());
    Ok(())
}

/// The class file with its `[handover]` point replaced by `[forward, lateral, height]` and
/// `comment` above it; everything else (comments included) as it was.
fn with_handover(text: &str, comment: &str, point: [f64; 3]) -> anyhow::Result<String> {
    let mut doc: toml_edit::DocumentMut = text.parse().context("class file")?;
    let handover = doc
        .get_mut("handover")
        .and_then(toml_edit::Item::as_table_mut)
        .context("class file has no [handover] table")?;
    let [f, l, z] = point;
    // The validated point itself (the grid's points are round to the micrometre).
    handover["forward_m"] = toml_edit::value(f);
    handover["lateral_m"] = toml_edit::value(l);
    handover["height_m"] = toml_edit::value(z);
    if let Some(mut key) = handover.key_mut("forward_m") {
        key.leaf_decor_mut().set_prefix(comment.to_owned());
    }
    let out = doc.to_string();
    TrajectorySpec::from_toml_str(&out).context("the designed class file does not read back")?;
    Ok(out)
}
