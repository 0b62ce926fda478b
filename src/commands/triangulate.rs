//! `ergocell triangulate`: 2D detections + calibration → one 3D position per landmark per frame, and a
//! summary (frames, landmarks triangulated, median reprojection error, bone-length variation).

use std::path::{Path, PathBuf};

use anyhow::{bail, Context as _};
use ergocell_cell::{Reconstruction, ReconstructionConfig};
use ergocell_perception::detections::{Frame2, ImportStats};
use ergocell_perception::import::{
    assemble_openpose, match_camera_folders, parse_caliscope_xy_bytes, CameraFiles,
};
use ergocell_perception::landmarks_file::{write_landmarks, LandmarksFormat};
use ergocell_perception::metrics::{
    bone_length_variation_percent, bone_stats, median_reprojection_px,
};
use ergocell_perception::rig_file::parse_rig;
use ergocell_perception::temporal::OneEuroParams;
use ergocell_perception::{CameraRig, FusionMethod, KeypointFormat};
use ergocell_skeleton::{Skeleton3, LANDMARK_COUNT};

use super::{output, UsageError};

/// Arguments of `ergocell triangulate`.
#[derive(Debug, clap::Args)]
pub struct Args {
    /// Calibration file: ergocell rig TOML, Anipose/Pose2Sim TOML or caliscope config.toml.
    #[arg(long)]
    pub calibration: PathBuf,
    /// 2D detections: a folder of per-camera OpenPose JSON folders, or a caliscope `xy_*.csv`.
    #[arg(long)]
    pub detections: PathBuf,
    /// Detection format (default: `openpose` for a folder, `caliscope` for a .csv file).
    #[arg(long, value_parser = ["openpose", "caliscope"])]
    pub format: Option<String>,
    /// Keypoint layout of OpenPose-style detections.
    #[arg(long, default_value = "blazepose33", value_parser = ["blazepose33", "body_25", "body_25b", "coco17", "halpe26"])]
    pub keypoints: String,
    /// Fusion: the seed paper's graph-Laplacian baseline, or ergocell's default.
    #[arg(long, default_value = "default", value_parser = ["paper", "default"])]
    pub fusion: String,
    /// Temporal filter: none, or the causal One-Euro filter of the real-time path.
    #[arg(long, default_value = "none", value_parser = ["none", "causal"])]
    pub filter: String,
    /// Frame rate of OpenPose detections (they carry no time stamps), Hz.
    #[arg(long, default_value_t = 30.0)]
    pub rate_hz: f64,
    /// Output file: `.trc`, `.csv` or `.json`; an existing file is refused unless --force, and an
    /// input (the calibration or the detections) always.
    #[arg(long)]
    pub out: PathBuf,
    /// Overwrite an existing --out file.
    #[arg(long)]
    pub force: bool,
}

pub fn run(args: &Args) -> anyhow::Result<()> {
    let out_format =
        LandmarksFormat::from_path(&args.out).map_err(|e| UsageError(e.to_string()))?;
    output::check(
        "--out",
        &args.out,
        args.force,
        &[
            ("--calibration", args.calibration.as_path()),
            ("--detections", args.detections.as_path()),
        ],
    )?;
    if !(args.rate_hz.is_finite() && args.rate_hz > 0.0) {
        bail!(UsageError(format!(
            "--rate-hz must be positive, got {}",
            args.rate_hz
        )));
    }
    let calibration_name = args.calibration.display().to_string();
    let text = std::fs::read_to_string(&args.calibration)
        .with_context(|| format!("reading {calibration_name}"))?;
    let (rig, rig_format) =
        parse_rig(&text, &calibration_name).map_err(|e| UsageError(e.to_string()))?;
    eprintln!(
        "calibration: {} cameras ({rig_format:?} format), {} stereo pairs",
        rig.len(),
        rig.pairs().len()
    );

    let format = match args.format.as_deref() {
        Some(f) => f.to_owned(),
        None if args.detections.is_dir() => "openpose".to_owned(),
        None => "caliscope".to_owned(),
    };
    let mut stats = ImportStats::default();
    let frames = if format == "caliscope" {
        let name = args.detections.display().to_string();
        let bytes = std::fs::read(&args.detections).with_context(|| format!("reading {name}"))?;
        parse_caliscope_xy_bytes(&bytes, &name, &rig, &mut stats)
            .map_err(|e| UsageError(e.to_string()))?
    } else {
        let keypoints = KeypointFormat::from_name(&args.keypoints)
            .ok_or_else(|| UsageError(format!("unknown keypoint layout {}", args.keypoints)))?;
        read_openpose(&args.detections, &rig, keypoints, args.rate_hz, &mut stats)?
    };
    if frames.is_empty() {
        bail!(UsageError(format!(
            "{}: no frames found",
            args.detections.display()
        )));
    }
    if let Some(w) = stats.warning() {
        eprintln!("warning: {w}");
    }

    // The cell controller's reconstruction stage with its defaults, but every frame written (no
    // tracked gate: a file keeps what was seen) and the filter only when asked for.
    let config = ReconstructionConfig {
        fusion: FusionMethod::from_name(&args.fusion).unwrap_or_default(),
        filter: (args.filter == "causal").then(OneEuroParams::default),
        min_tracked_landmarks: 0,
        ..ReconstructionConfig::default()
    };
    let mut reconstruction = Reconstruction::new(rig, config)?;
    let mut skeletons: Vec<Skeleton3> = Vec::with_capacity(frames.len());
    let mut rejected = 0;
    let mut undistortion_failures = 0;
    for frame in &frames {
        let r = reconstruction.process_frame(frame)?;
        rejected += r.fused.rejected_views;
        undistortion_failures += r.fused.undistortion_failures;
        skeletons.push(r.tracked.unwrap_or(r.fused.skeleton));
    }

    let rate = estimate_rate_hz(&skeletons).unwrap_or(args.rate_hz);
    let name = args
        .out
        .file_name()
        .map(|n| n.to_string_lossy().into_owned())
        .unwrap_or_default();
    output::write(
        "--out",
        &args.out,
        args.force,
        write_landmarks(&skeletons, out_format, &name, rate).as_bytes(),
    )?;

    let triangulated: usize = skeletons.iter().map(Skeleton3::observed_count).sum();
    println!("frames:                   {}", skeletons.len());
    println!(
        "landmarks triangulated:   {triangulated} of {} ({:.1}%)",
        skeletons.len() * LANDMARK_COUNT,
        100.0 * triangulated as f64 / (skeletons.len() * LANDMARK_COUNT) as f64
    );
    println!(
        "fusion:                   {} (filter: {})",
        args.fusion, args.filter
    );
    if let Some(m) = median_reprojection_px(&skeletons) {
        println!("median reprojection err:  {m:.2} px");
    }
    println!("views rejected:           {rejected} (outliers or behind the camera), {undistortion_failures} keypoints outside the lens model");
    if let Some(cv) = bone_length_variation_percent(&skeletons) {
        println!("bone-length variation:    {cv:.2}% (mean coefficient of variation over bones)");
        for b in bone_stats(&skeletons) {
            println!(
                "  {:>15} – {:<15} {:>6.3} m  ±{:>5.2}%  ({} frames)",
                b.bone.0.name(),
                b.bone.1.name(),
                b.mean_m,
                b.cv_percent,
                b.frames
            );
        }
    }
    println!("wrote {}", args.out.display());
    Ok(())
}

/// The frame rate implied by the stamps (median frame interval).
fn estimate_rate_hz(skeletons: &[Skeleton3]) -> Option<f64> {
    let dts: Vec<f64> = skeletons
        .windows(2)
        .map(|w| (w[1].stamp_nanos - w[0].stamp_nanos) as f64 * 1e-9)
        .filter(|dt| *dt > 0.0)
        .collect();
    ergocell_perception::metrics::median(&dts).map(|dt| 1.0 / dt)
}

/// Reads an OpenPose-layout folder: one sub-folder per camera, one JSON per frame (frame `k` is the
/// `k`-th file in sorted order in every camera folder, as Pose2Sim synchronises them).
/// At most this many per-file warnings are printed (the rest are counted).
const MAX_WARNINGS: usize = 20;

fn read_openpose(
    dir: &Path,
    rig: &CameraRig,
    format: KeypointFormat,
    rate_hz: f64,
    stats: &mut ImportStats,
) -> anyhow::Result<Vec<Frame2>> {
    let mut folders = Vec::new();
    for entry in std::fs::read_dir(dir).with_context(|| format!("reading {}", dir.display()))? {
        let entry = entry?;
        if entry.file_type()?.is_dir() {
            folders.push(entry.file_name().to_string_lossy().into_owned());
        }
    }
    if folders.is_empty() {
        bail!(UsageError(format!(
            "{}: no camera folders inside",
            dir.display()
        )));
    }
    let matched = match_camera_folders(&folders, rig).map_err(|e| UsageError(e.to_string()))?;
    // Frames are paired by the frame number in each file name (perception::import::assemble_openpose):
    // a missing file is a missing view of that frame only, never a shift of every later frame.
    let mut cameras = Vec::new();
    for (folder, camera) in matched {
        let mut files = Vec::new();
        for path in std::fs::read_dir(dir.join(&folder))?
            .filter_map(Result::ok)
            .map(|e| e.path())
            .filter(|p| {
                p.extension()
                    .is_some_and(|e| e.eq_ignore_ascii_case("json"))
            })
        {
            let bytes =
                std::fs::read(&path).with_context(|| format!("reading {}", path.display()))?;
            files.push((path.display().to_string(), bytes));
        }
        eprintln!(
            "camera {} ← {folder}/ ({} files)",
            rig.cameras()[camera].id,
            files.len()
        );
        cameras.push(CameraFiles { camera, files });
    }
    let import = assemble_openpose(&cameras, format, rate_hz, stats)
        .map_err(|e| UsageError(e.to_string()))?;
    for w in import.warnings.iter().take(MAX_WARNINGS) {
        eprintln!("warning: {w}");
    }
    if import.warnings.len() > MAX_WARNINGS {
        eprintln!(
            "warning: … and {} more files left out",
            import.warnings.len() - MAX_WARNINGS
        );
    }
    Ok(import.frames)
}
