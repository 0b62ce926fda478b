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

use ergocell_ergonomics::height::{
    calibrate_ear_offset, CalibrationSample, CalibrationSession, ClassThresholds, EarOffset,
    RecordingHeight, HUMAN_STATURE_M,
};
use ergocell_ergonomics::{height_text, HeightConfig, UpVector};

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
    if !(stature_m.is_finite() && HUMAN_STATURE_M.contains(&stature_m)) {
        return Err(format!(
            "{s:?}: stature {stature_m} m is not a person's (0.5–2.5 m; centimetres given as metres?)"
        ));
    }
    if file.is_empty() {
        return Err(format!("{s:?}: no landmark file before '='"));
    }
    Ok((PathBuf::from(file), stature_m))
}

/// Each session measured: its upright frames' estimate with no ear offset subtracted, beside the
/// stature measured. A session named twice or with no upright frame is a usage error.
fn measure_sessions(
    args: &CalibrateArgs,
    config: &HeightConfig,
) -> anyhow::Result<Vec<CalibrationSession>> {
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
        let session = path.display().to_string();
        let row = CalibrationSession::measure(session, config, &frames, *measured_m).ok_or_else(
            || {
                UsageError(format!(
                    "--session {}: no upright frame in {} frames (the person must stand straight at the \
                     station, facing the cameras)",
                    path.display(),
                    frames.len()
                ))
            },
        )?;
        rows.push(row);
    }
    Ok(rows)
}

/// Writes the offset into the configuration's `[height]` (comments and layout kept), after checking
/// that the result reads back; through a temporary file moved into place.
fn write_offset(
    args: &CalibrateArgs,
    text: &str,
    label: &str,
    offset: &EarOffset,
    sessions: usize,
) -> anyhow::Result<()> {
    let mut doc: toml_edit::DocumentMut = text
        .parse()
        .map_err(|e| UsageError(format!("{label}: {e}")))?;
    if !doc.contains_table("height") {
        doc["height"] = toml_edit::table();
    }
    let rounded = offset.rounded_to_micrometre();
    doc["height"]["ear_offset_m"] = toml_edit::value(rounded.offset_m);
    doc["height"]["ear_offset_sigma_m"] = toml_edit::value(rounded.sigma_m);
    doc["height"]["ear_offset_sessions"] = toml_edit::value(i64::try_from(sessions)?);
    let new_text = doc.to_string();
    // What is written must read back as a valid configuration with this offset.
    ergocell_cell::CellSettings::from_toml_str(&new_text, label)
        .map_err(|e| anyhow::anyhow!("the calibrated configuration does not read back: {e}"))?;
    let mut out = super::output::Partial::create("--config", &args.config, true)?;
    out.write(new_text.as_bytes())?;
    out.finish()?;
    Ok(())
}

fn calibrate(args: &CalibrateArgs) -> anyhow::Result<()> {
    use anyhow::Context as _;
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
    let config = settings.pipeline(up)?.height;
    let rows = measure_sessions(args, &config)?;
    let samples: Vec<CalibrationSample> = rows.iter().map(|r| r.sample).collect();
    let offset = calibrate_ear_offset(&samples).map_err(|e| UsageError(e.to_string()))?;
    let Some(sessions) = offset.calibrated_sessions else {
        anyhow::bail!("the calibration returned no session count");
    };
    if args.json {
        let doc = height_text::calibration_json(&rows, &offset, !args.dry_run);
        println!("{}", serde_json::to_string_pretty(&doc)?);
    } else {
        print!(
            "{}",
            height_text::calibration_text(&rows, &offset, sessions)
        );
    }
    if args.dry_run {
        return Ok(());
    }
    write_offset(args, &text, &label, &offset, sessions)?;
    if !args.json {
        println!(
            "wrote [height] ear_offset_m, ear_offset_sigma_m, ear_offset_sessions into {label}"
        );
    }
    Ok(())
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
    let recording = RecordingHeight::of(config, &frames);
    if args.json {
        println!("{}", serde_json::to_string_pretty(&recording.json())?);
        return Ok(());
    }
    println!("{} frames read from {}", frames.len(), landmarks.display());
    print!("{}", height_text::recording_text(&recording));
    Ok(())
}
