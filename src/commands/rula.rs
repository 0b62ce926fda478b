//! `ergocell rula`: RULA worksheets and RULA over a 3D landmark recording.
//!
//! ```text
//! ergocell rula score --input cases.json       JSON array of single-side worksheets → JSON array of breakdowns
//! ergocell rula track --landmarks frames.json  per-frame scores for both sides, warnings and a summary
//!                     [--up x,y,z | --rig config/rig.toml] [--floor-height-m 0] [--task task.json] [--json]
//!                     [--fixed-lag-s 0.55]
//! ```
//!
//! The landmark file is what `ergocell triangulate` writes (`.json` array of skeletons; `.csv` and
//! `.trc` are read too). `--up` is the world's up in the file's frame; by default it is taken from
//! the rig file the landmarks were triangulated with (`--rig`, default `config/rig.toml`, the
//! reference cell: z-up, floor at z = 0). It is never assumed: a calibration without a stated up
//! (caliscope, Anipose) needs `--up`.
//!
//! `track` always says why: a side that is not scored, or scored but uncertain (an input held, never
//! observed, scored conservatively — a wrist the keypoint layout has no hand points for, e.g.
//! OpenPose BODY_25B or COCO-17 — or of low confidence), comes with its reasons: in the text output on
//! a `why` line whenever they change, in `--json` as each frame's `unscored_reasons` and each side's
//! `uncertain_reasons`.

use std::path::{Path, PathBuf};

use ergocell::input::{self, Kind};
use ergocell_cell::{Assessment, PipelineConfig};
use ergocell_ergonomics::activity::{Activity, ActivityConfig, ActivityTracker};
use ergocell_ergonomics::export::{self, FrameCsv};
use ergocell_ergonomics::rula::{parse_worksheets, score_worksheet};
use ergocell_ergonomics::summary::{SessionSummary, SummaryBuilder, DEFAULT_MAX_FRAME_NANOS};
use ergocell_ergonomics::track_text::{self, FrameText};
use ergocell_ergonomics::{
    summary_text, AssessmentConfig, RulaScores, TaskConfig, UpVector, WarningEvent,
};
use ergocell_formats::landmarks_file::{read_landmarks, LandmarksFormat};
use ergocell_perception::fixed_lag::centered_mean;
use ergocell_skeleton::Skeleton3;
use nalgebra::Vector3;

use super::UsageError;

/// Arguments of `ergocell rula`.
#[derive(Debug, clap::Args)]
pub struct Args {
    #[command(subcommand)]
    pub command: Sub,
}

#[derive(Debug, clap::Subcommand)]
pub enum Sub {
    /// Score single-side worksheets: reads a JSON array, prints a JSON array of breakdowns in order.
    Score {
        /// JSON array of worksheets (fields as in the RULA worksheet, angles in degrees).
        #[arg(long)]
        input: PathBuf,
    },
    /// Score every frame of a 3D landmark recording, both sides, with warnings and a summary.
    Track(TrackArgs),
}

/// Arguments of `ergocell rula track`.
#[derive(Debug, clap::Args)]
pub struct TrackArgs {
    /// 3D landmark file from `ergocell triangulate` (.json, .csv or .trc).
    #[arg(long)]
    pub landmarks: PathBuf,
    /// The world's up vector in the file's frame, `x,y,z` (default: the `up` of the rig file).
    #[arg(long, value_parser = parse_up, allow_hyphen_values = true)]
    pub up: Option<UpVector>,
    /// The calibration the landmarks were triangulated with; its `up` is the default for `--up`.
    #[arg(long, default_value = "config/rig.toml")]
    pub rig: PathBuf,
    /// Floor height along up, metres (default: the lowest foot landmark of each frame).
    #[arg(long, allow_hyphen_values = true)]
    pub floor_height_m: Option<f64>,
    /// Task config as JSON (what cameras cannot see): RULA's force/load scores, wrist twist, arm
    /// support, seated; REBA's `reba_load_kg`, `reba_load_shock_or_rapid_build_up`, `reba_coupling`
    /// ("good" | "fair" | "poor" | "unacceptable") and `reba_rapid_changes_or_unstable_base`.
    #[arg(long)]
    pub task: Option<PathBuf>,
    /// Landmark confidence below which a score is marked uncertain.
    #[arg(long, default_value_t = 0.5)]
    pub min_confidence: f64,
    /// Print frames, warnings and summary as one JSON document instead of text.
    #[arg(long)]
    pub json: bool,
    /// Also write one CSV row per frame (both sides' scores, angles and flags, the frame's warnings;
    /// units in the column names), for a spreadsheet.
    #[arg(long, value_name = "FILE")]
    pub csv: Option<PathBuf>,
    /// Also write the session summary as CSV (`quantity,side,region,score,value,unit,phase`: time
    /// shares per RULA and REBA action level, region score and grand score, exposure over time,
    /// static holds, warnings raised per region, per task phase where `phase` is set;
    /// docs/ergonomist.md names every quantity).
    #[arg(long, value_name = "FILE")]
    pub summary_csv: Option<PathBuf>,
    /// Score each frame on the landmarks' mean over this many seconds either side of it (a
    /// fixed-lag smoother, `perception::fixed_lag`; the legs below the hips are left as they are),
    /// for a file of unfiltered landmarks (`ergocell triangulate` without `--filter`). Offline it
    /// costs nothing; on the digital twin under the detector fitted to real MediaPipe data, 0.55 s
    /// raised per-frame RULA agreement from κ 0.77 (the controller's causal filter) to 0.88
    /// (docs/sim). The window is in time (the same at any frame rate) and stops at a gap in the
    /// file.
    #[arg(long, value_name = "SECONDS")]
    pub fixed_lag_s: Option<f64>,
    /// Overwrite an existing --csv / --summary-csv file.
    #[arg(long)]
    pub force: bool,
}

/// The world's up: `--up` when given, else the rig file's `up`; never assumed. A calibration whose
/// world frame has no known up (caliscope, Anipose: the frame of a camera or a board) needs `--up`.
pub fn resolve_up(up: Option<UpVector>, rig: &Path) -> anyhow::Result<UpVector> {
    if let Some(up) = up {
        return Ok(up);
    }
    let (text, name) = ergocell::shipped::read_or_shipped(rig).map_err(|e| {
        UsageError(format!(
            "the world's up direction is unknown: pass --up x,y,z or --rig <rig.toml> ({e:#})"
        ))
    })?;
    let (rig, _) = ergocell_formats::rig_file::parse_rig(&text, &name)
        .map_err(|e| UsageError(e.to_string()))?;
    let up = rig.up().ok_or_else(|| {
        UsageError(format!(
            "{name} does not state the world's up direction: pass --up x,y,z"
        ))
    })?;
    UpVector::new(up).map_err(|e| UsageError(format!("{name}: up: {e}")).into())
}

/// Parses `x,y,z` into a normalised up vector.
pub fn parse_up(s: &str) -> Result<UpVector, String> {
    let parts: Vec<&str> = s.split(',').map(str::trim).collect();
    let [x, y, z] = parts.as_slice() else {
        return Err(format!("expected x,y,z, got {s:?}"));
    };
    let num = |t: &str| {
        t.parse::<f64>()
            .map_err(|e| format!("{t:?} is not a number: {e}"))
    };
    UpVector::new(Vector3::new(num(x)?, num(y)?, num(z)?)).map_err(|e| e.to_string())
}

/// Reads a 3D landmark recording; a malformed file is a usage error.
pub fn read_skeletons(path: &Path) -> anyhow::Result<Vec<Skeleton3>> {
    let format = LandmarksFormat::from_path(path).map_err(|e| UsageError(e.to_string()))?;
    let text = input::read_text(path, Kind::Data)?;
    let frames = read_landmarks(&text, format, &path.display().to_string())
        .map_err(|e| UsageError(e.to_string()))?;
    if frames.is_empty() {
        return Err(UsageError(format!("{}: no frames", path.display())).into());
    }
    Ok(frames)
}

pub fn run(args: &Args) -> anyhow::Result<()> {
    match &args.command {
        Sub::Score { input } => score(input),
        Sub::Track(track_args) => track(track_args),
    }
}

fn score(input: &Path) -> anyhow::Result<()> {
    let text = input::read_text(input, Kind::Data)?;
    let worksheets =
        parse_worksheets(&text).map_err(|e| UsageError(format!("{}: {e}", input.display())))?;
    let mut out: Vec<RulaScores> = Vec::with_capacity(worksheets.len());
    for (index, w) in worksheets.iter().enumerate() {
        let result = score_worksheet(w)
            .map_err(|e| UsageError(format!("{}: entry {index}: {e}", input.display())))?;
        for note in &result.notes {
            eprintln!("entry {index}: {}", serde_json::to_string(note)?);
        }
        out.push(result.scores);
    }
    println!("{}", serde_json::to_string_pretty(&out)?);
    Ok(())
}

/// The outputs, checked before any work: never an input, never each other, no overwrite without
/// --force.
fn check_outputs(args: &TrackArgs) -> anyhow::Result<()> {
    let mut inputs: Vec<(&str, &Path)> =
        vec![("--landmarks", &args.landmarks), ("--rig", &args.rig)];
    if let Some(task) = &args.task {
        inputs.push(("--task", task));
    }
    if let Some(csv) = &args.csv {
        super::output::check("--csv", csv, args.force, &inputs)?;
        inputs.push(("--csv", csv));
    }
    if let Some(summary_csv) = &args.summary_csv {
        super::output::check("--summary-csv", summary_csv, args.force, &inputs)?;
        if args.csv.as_deref() == Some(summary_csv.as_path()) {
            return Err(UsageError(format!(
                "--summary-csv {} is also --csv: choose two files",
                summary_csv.display()
            ))
            .into());
        }
    }
    Ok(())
}

/// The assessment's configuration: the task file's (or the defaults), the world's up, the floor and
/// the confidence threshold.
fn assessment_config(args: &TrackArgs) -> anyhow::Result<AssessmentConfig> {
    let task: TaskConfig = match &args.task {
        Some(path) => {
            let text = input::read_text(path, Kind::Config)?;
            serde_json::from_str(&text)
                .map_err(|e| UsageError(format!("{}: {e}", path.display())))?
        }
        None => TaskConfig::default(),
    };
    let mut config = AssessmentConfig::new(resolve_up(args.up, &args.rig)?);
    config.floor_height_m = args.floor_height_m;
    config.min_confidence = args.min_confidence;
    config.task = task;
    Ok(config)
}

/// What scoring every frame gave: the summary, the warning events, the frames as JSON (`--json`)
/// and the frame CSV's bytes (`--csv`).
struct Scored {
    summary: SessionSummary,
    events: Vec<WarningEvent>,
    frame_docs: Vec<serde_json::Value>,
    frame_csv: Option<Vec<u8>>,
}

/// Scores every frame with the cell controller's assessment stage (RULA → warnings) and its
/// defaults, on the file's skeletons as they are (a file from `triangulate --filter causal` was
/// filtered there); prints each frame's text unless `--json`.
fn score_frames(
    args: &TrackArgs,
    frames: &[Skeleton3],
    config: &AssessmentConfig,
) -> anyhow::Result<Scored> {
    let mut pipeline_config = PipelineConfig::new(config.up);
    pipeline_config.assessment = *config;
    let mut stage = Assessment::new(&pipeline_config).map_err(|e| UsageError(e.to_string()))?;
    // The one summary (time-weighted, gaps not counted), as `ergocell review` shows it.
    let mut summary = SummaryBuilder::new(DEFAULT_MAX_FRAME_NANOS)
        .trunk_supported(config.task.seated_well_supported);
    // Task segments from the skeleton alone (walking, floor pick, in place).
    let mut activity = ActivityTracker::new(ActivityConfig::default(), &config.up)
        .map_err(|e| UsageError(e.to_string()))?;
    let mut text = FrameText::new(frames[0].stamp_nanos);
    if !args.json {
        print!("{}", track_text::header_text(args.fixed_lag_s));
    }
    let mut frame_docs = Vec::new();
    let mut events = Vec::new();
    let mut frame_csv = match &args.csv {
        Some(_) => Some(FrameCsv::new(Vec::new())?),
        None => None,
    };
    for (i, skeleton) in frames.iter().enumerate() {
        let tracked = stage.score(skeleton.clone());
        let frame = tracked
            .assessment
            .map_err(|e| UsageError(format!("{}: frame {i}: {e}", args.landmarks.display())))?;
        summary.add(&frame, activity.update(skeleton).map(Activity::name));
        let new_events = tracked.warnings;
        if let Some(csv) = frame_csv.as_mut() {
            csv.write(&frame, &new_events)?;
        }
        if args.json {
            frame_docs.push(track_text::frame_json(&frame));
        } else {
            print!("{}", text.frame(&frame, &new_events));
        }
        events.extend(new_events);
    }
    Ok(Scored {
        summary: summary.finish(),
        events,
        frame_docs,
        frame_csv: frame_csv.map(FrameCsv::finish).transpose()?,
    })
}

fn track(args: &TrackArgs) -> anyhow::Result<()> {
    check_outputs(args)?;
    let frames = read_skeletons(&args.landmarks)?;
    let frames = match args.fixed_lag_s {
        Some(seconds) => centered_mean(&frames, seconds)
            .map_err(|e| UsageError(format!("--fixed-lag-s: {e}")))?,
        None => frames,
    };
    let config = assessment_config(args)?;
    let t0 = frames[0].stamp_nanos;
    let scored = score_frames(args, &frames, &config)?;
    let (s, events) = (&scored.summary, &scored.events);
    if let (Some(path), Some(bytes)) = (&args.csv, &scored.frame_csv) {
        super::output::write("--csv", path, args.force, bytes)?;
    }
    if let Some(path) = &args.summary_csv {
        let bytes = export::write_summary(Vec::new(), s, &export::raised_per_region(events))?;
        super::output::write("--summary-csv", path, args.force, &bytes)?;
    }
    if args.json {
        let doc = track_text::document_json(&scored.frame_docs, events, s, args.fixed_lag_s);
        println!("{}", serde_json::to_string_pretty(&doc)?);
        return Ok(());
    }
    print!("{}", summary_text::session_text(s, events, t0));
    Ok(())
}
