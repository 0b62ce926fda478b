//! `ergocell height`: the operator's stature and height class from a 3D landmark recording.
//!
//! ```text
//! ergocell height --landmarks frames.json [--up x,y,z | --rig config/rig.toml] [--floor-height-m 0] [--c1-below-m 1.68]
//!                 [--c2-up-to-m 1.82] [--json]
//! ```
//!
//! Prints the estimate with its uncertainty (1σ), each estimator, and the class with the frame it was
//! decided at, or "undecided" and why.
//!
//! ```text
//! ergocell height calibrate --session a.json=1.712 --session b.json=1.655 … [--config config/cell.toml]
//!                           [--rig config/rig.toml | --up x,y,z] [--dry-run] [--json]
//! ```
//!
//! Measures the pose estimator's ear-landmark offset on sessions of people whose stature was
//! measured with a stadiometer (at least 5) and writes it into the cell configuration's `[height]`
//! (`ear_offset_m`, `ear_offset_sigma_m`, `ear_offset_sessions`; the file's comments and layout kept,
//! written to a temporary file and moved into place).

use std::path::PathBuf;

use ergocell_ergonomics::height::{ClassThresholds, DecisionBasis, HeightEstimate};
use ergocell_ergonomics::{HeightConfig, HeightEstimator, HeightStatus, UpVector};

use super::rula::{parse_up, read_skeletons, resolve_up};
use super::UsageError;

/// Arguments of `ergocell height`.
#[derive(Debug, clap::Args)]
#[command(args_conflicts_with_subcommands = true, subcommand_negates_reqs = true)]
pub struct Args {
    #[command(subcommand)]
    pub command: Option<Sub>,
    /// 3D landmark file from `ergocell triangulate` (.json, .csv or .trc).
    #[arg(long, required = true)]
    pub landmarks: Option<PathBuf>,
    /// The world's up vector in the file's frame, `x,y,z` (default: the `up` of the rig file).
    #[arg(long, value_parser = parse_up, allow_hyphen_values = true)]
    pub up: Option<UpVector>,
    /// The calibration the landmarks were triangulated with; its `up` is the default for `--up`.
    #[arg(long, default_value = "config/rig.toml")]
    pub rig: PathBuf,
    /// Floor height along up, metres (default: the lowest foot landmark of each frame).
    #[arg(long, allow_hyphen_values = true)]
    pub floor_height_m: Option<f64>,
    /// Class c1 is below this stature, metres.
    #[arg(long, default_value_t = 1.68)]
    pub c1_below_m: f64,
    /// Class c2 reaches up to and including this stature, metres; c3 is above.
    #[arg(long, default_value_t = 1.82)]
    pub c2_up_to_m: f64,
    /// Print the status as JSON.
    #[arg(long)]
    pub json: bool,
}

/// `ergocell height`'s subcommands.
#[derive(Debug, clap::Subcommand)]
pub enum Sub {
    /// Measure the pose estimator's ear-landmark offset on sessions of people of known stature and
    /// write it into the cell configuration.
    Calibrate(CalibrateArgs),
}

/// Arguments of `ergocell height calibrate`.
#[derive(Debug, clap::Args)]
pub struct CalibrateArgs {
    /// One session: a 3D landmark file of a person standing upright at the station (from
    /// `ergocell triangulate`, or a recording's landmarks) and their stature measured with a
    /// stadiometer, metres: `<file>=<stature_m>`. At least 5.
    #[arg(long = "session", value_parser = parse_session, required = true)]
    pub sessions: Vec<(PathBuf, f64)>,
    /// The cell configuration whose `[height]` settings measure, and which the offset is written into.
    #[arg(long, default_value = "config/cell.toml")]
    pub config: PathBuf,
    /// The world's up vector in the files' frame, `x,y,z` (default: the `up` of the rig file).
    #[arg(long, value_parser = parse_up, allow_hyphen_values = true)]
    pub up: Option<UpVector>,
    /// The calibration the landmarks were triangulated with; its `up` is the default for `--up`.
    #[arg(long, default_value = "config/rig.toml")]
    pub rig: PathBuf,
    /// Print the result; do not write the cell configuration.
    #[arg(long)]
    pub dry_run: bool,
    /// Print the result as JSON.
    #[arg(long)]
    pub json: bool,
}

fn parse_session(s: &str) -> Result<(PathBuf, f64), String> {
    let (file, stature) = s
        .rsplit_once('=')
        .ok_or_else(|| format!("expected <file>=<stature_m>, got {s:?}"))?;
    let stature_m: f64 = stature
        .trim()
        .parse()
        .map_err(|e| format!("{s:?}: the stature {stature:?} is not a number of metres: {e}"))?;
    if !(stature_m.is_finite() && (0.5..=2.5).contains(&stature_m)) {
        return Err(format!(
            "{s:?}: stature {stature_m} m is not a person's (0.5–2.5 m; centimetres given as metres?)"
        ));
    }
    if file.is_empty() {
        return Err(format!("{s:?}: no landmark file before '='"));
    }
    Ok((PathBuf::from(file), stature_m))
}

fn calibrate(args: &CalibrateArgs) -> anyhow::Result<()> {
    use anyhow::Context as _;
    use ergocell_ergonomics::height::{calibrate_ear_offset, CalibrationSample, EarOffset};
    let text = ergocell::input::read_text(&args.config, ergocell::input::Kind::Config)
        .with_context(|| {
            format!(
            "cannot read {} (the calibration is written into the cell's own configuration: pass \
             --config with an existing file)",
            args.config.display()
        )
        })?;
    let label = args.config.display().to_string();
    let settings = ergocell_cell::CellSettings::from_toml_str(&text, &label)
        .map_err(|e| UsageError(e.to_string()))?;
    let up = resolve_up(args.up, &args.rig)?;
    let mut config = settings.pipeline(up)?.height;
    // Measured with no offset subtracted, over every upright frame, never deciding.
    config.ear_offset = EarOffset::default();
    config.min_frames = usize::MAX;
    let mut samples = Vec::new();
    let mut rows = Vec::new();
    for (path, measured_m) in &args.sessions {
        for (other, _) in &args.sessions {
            if std::ptr::eq(path, other) {
                break;
            }
            if super::output::same_path(path, other) {
                return Err(UsageError(format!(
                    "--session {}: the same session given twice",
                    path.display()
                ))
                .into());
            }
        }
        let frames = read_skeletons(path)?;
        let mut estimator = HeightEstimator::new(config.clone());
        for f in &frames {
            estimator.push(f);
        }
        let estimate = estimator.estimate().ok_or_else(|| {
            UsageError(format!(
                "--session {}: no upright frame in {} frames (the person must stand straight at the \
                 station, facing the cameras)",
                path.display(),
                frames.len()
            ))
        })?;
        let sample = CalibrationSample::from_estimate(&estimate, *measured_m);
        rows.push(serde_json::json!({
            "session": path.display().to_string(),
            "measured_m": measured_m,
            "estimated_m": sample.estimated_m,
            "upright_frames": estimate.frames_used,
        }));
        samples.push(sample);
    }
    let offset = calibrate_ear_offset(&samples).map_err(|e| UsageError(e.to_string()))?;
    let Some(sessions) = offset.calibrated_sessions else {
        anyhow::bail!("the calibration returned no session count");
    };
    if args.json {
        let doc =
            serde_json::json!({ "ear_offset": offset, "sessions": rows, "written": !args.dry_run });
        println!("{}", serde_json::to_string_pretty(&doc)?);
    } else {
        for (r, s) in rows.iter().zip(&samples) {
            println!(
                "  {}: measured {:.3} m, estimated {:.3} m uncalibrated ({:+.1} mm)",
                r["session"].as_str().unwrap_or("?"),
                s.measured_m,
                s.estimated_m,
                (s.estimated_m - s.measured_m) * 1e3
            );
        }
        println!(
            "ear landmark offset: {:+.1} ± {:.1} mm (1σ) from {sessions} sessions",
            offset.offset_m * 1e3,
            offset.sigma_m * 1e3
        );
    }
    if args.dry_run {
        return Ok(());
    }
    let mut doc: toml_edit::DocumentMut = text
        .parse()
        .map_err(|e| UsageError(format!("{label}: {e}")))?;
    if !doc.contains_table("height") {
        doc["height"] = toml_edit::table();
    }
    let round = |x: f64| (x * 1e6).round() / 1e6;
    doc["height"]["ear_offset_m"] = toml_edit::value(round(offset.offset_m));
    doc["height"]["ear_offset_sigma_m"] = toml_edit::value(round(offset.sigma_m));
    doc["height"]["ear_offset_sessions"] = toml_edit::value(i64::try_from(sessions)?);
    let new_text = doc.to_string();
    // What is written must read back as a valid configuration with this offset.
    ergocell_cell::CellSettings::from_toml_str(&new_text, &label)
        .map_err(|e| anyhow::anyhow!("the calibrated configuration does not read back: {e}"))?;
    let mut out = super::output::Partial::create("--config", &args.config, true)?;
    out.write(new_text.as_bytes())?;
    out.finish()?;
    if !args.json {
        println!(
            "wrote [height] ear_offset_m, ear_offset_sigma_m, ear_offset_sessions into {label}"
        );
    }
    Ok(())
}

fn print_estimate(e: &HeightEstimate) {
    println!(
        "stature: {:.3} m ± {:.3} m (1σ), from {} upright frames",
        e.height_m, e.uncertainty_m, e.frames_used
    );
    let o = &e.ear_offset;
    if let Some(n) = o.calibrated_sessions {
        println!(
            "  ear landmark offset {:+.4} ± {:.4} m, calibrated on {n} sessions",
            o.offset_m, o.sigma_m
        );
    } else {
        println!(
            "  ear landmark offset uncalibrated: {:+.4} ± {:.4} m assumed (`ergocell height calibrate` measures it)",
            o.offset_m, o.sigma_m
        );
    }
    for x in &e.estimators {
        println!(
            "  {:<14} {:.3} m ± {:.3} m ({} frames)",
            x.name, x.height_m, x.sigma_m, x.frames
        );
    }
}

pub fn run(args: &Args) -> anyhow::Result<()> {
    if let Some(Sub::Calibrate(c)) = &args.command {
        return calibrate(c);
    }
    let Some(landmarks) = &args.landmarks else {
        return Err(UsageError("--landmarks is required".to_owned()).into());
    };
    let frames = read_skeletons(landmarks)?;
    let mut config = HeightConfig::new(resolve_up(args.up, &args.rig)?);
    config.floor_height_m = args.floor_height_m;
    config.thresholds = ClassThresholds::new(args.c1_below_m, args.c2_up_to_m)
        .map_err(|e| UsageError(e.to_string()))?;
    let mut estimator = HeightEstimator::new(config);
    let mut decided_at = None;
    for (i, f) in frames.iter().enumerate() {
        if estimator.push(f).is_some() {
            decided_at = Some(i);
        }
    }
    let status = estimator.status();
    let segments = estimator.segment_estimate();
    if args.json {
        let doc = serde_json::json!({
            "status": status,
            "segment_lengths_any_posture": segments,
            "decided_at_frame": decided_at,
            "final_estimate": estimator.estimate(),
            "frames": frames.len(),
        });
        println!("{}", serde_json::to_string_pretty(&doc)?);
        return Ok(());
    }
    println!("{} frames read from {}", frames.len(), landmarks.display());
    match &status {
        HeightStatus::Decided(d) => {
            print_estimate(&d.estimate);
            let [lo, hi] = d.interval_m;
            let basis = match d.basis {
                DecisionBasis::Interval => format!(
                    "the ±{}σ interval {lo:.3}–{hi:.3} m lies inside the class",
                    d.sigmas
                ),
                DecisionBasis::ExpectedRula => format!(
                    "the ±{}σ interval {lo:.3}–{hi:.3} m straddles a boundary: the lowest expected RULA",
                    d.sigmas
                ),
                DecisionBasis::MostProbable => format!(
                    "the ±{}σ interval {lo:.3}–{hi:.3} m straddles a boundary: the most probable class",
                    d.sigmas
                ),
            };
            println!(
                "class: {} (decided at frame {}: {basis})",
                d.class.name(),
                decided_at.map_or_else(|| "?".to_owned(), |i| i.to_string())
            );
            for o in &d.options {
                println!(
                    "  {}: probability {:.3}{}{}",
                    o.class.name(),
                    o.probability,
                    o.expected_rula
                        .map_or(String::new(), |r| format!(", expected RULA {r:.2}")),
                    if o.served {
                        ""
                    } else {
                        ", its trajectory does not serve this interval"
                    }
                );
            }
            if let Some(cost) = d.expected_rula_cost {
                println!("expected cost against the true class: {cost:+.3} RULA grand score");
            }
            if let Some(now) = estimator.estimate() {
                if now.frames_used > d.estimate.frames_used {
                    println!(
                        "over the whole recording: {:.3} m ± {:.3} m from {} upright frames",
                        now.height_m, now.uncertainty_m, now.frames_used
                    );
                }
            }
        }
        HeightStatus::Measuring {
            estimate,
            why,
            frames_seen,
            upright_frames,
        } => {
            if let Some(e) = estimate {
                print_estimate(e);
            }
            println!(
                "class: undecided — still measuring ({upright_frames} upright of {frames_seen} frames): {why}"
            );
        }
    }
    if let Some(seg) = segments {
        println!(
            "segment lengths (any posture, never decides the class): {:.3} m ± {:.3} m (1σ) over {} frames",
            seg.height_m, seg.sigma_m, seg.frames
        );
    }
    Ok(())
}
