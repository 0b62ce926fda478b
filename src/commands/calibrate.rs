//! `ergocell calibrate`: camera and stereo calibration from checkerboard images (step A of the seed
//! paper's Algorithm 1), written as a rig file.
//!
//! ```text
//! ergocell calibrate intrinsics --images <dir|glob> --board 9x6 --square-m 0.025 --out cam.toml
//! ergocell calibrate stereo --left <dir|glob> --right <dir|glob> --board 9x6 --square-m 0.025 \
//!                           --out rig.toml [--format anipose] [--refine-intrinsics]
//! ergocell calibrate place --pair s1.toml --pair s2.toml --points measured.toml --out rig.toml
//! ```
//!
//! Prints one row per image (or pair): used with its reprojection error, or rejected and why. Too
//! few usable views is a usage error (exit 2). Stereo images pair up in sorted file-name order.

use std::io::IsTerminal as _;
use std::path::{Path, PathBuf};

use anyhow::Context as _;
use ergocell::input::{self, Kind};
use ergocell_calibration::detect::{camera_views, common_size, usable_views, ImageDetection};
use ergocell_calibration::report::{self, StereoPose};
use ergocell_calibration::{
    calibrate_camera, calibrate_stereo, place, BoardSpec, CalibrationError, RigOptions,
    SolveOptions,
};
use ergocell_formats::rig_file::{parse_rig, to_anipose_toml, to_ergocell_toml};
use ergocell_perception::{Camera, CameraId, CameraRig};
use indicatif::{ProgressBar, ProgressStyle};
use nalgebra::{Rotation3, Vector3};

use super::{output, UsageError};

/// Arguments of `ergocell calibrate`.
#[derive(Debug, clap::Args)]
pub struct Args {
    #[command(subcommand)]
    pub command: CalibrateCommand,
}

/// The calibrations.
#[derive(Debug, clap::Subcommand)]
pub enum CalibrateCommand {
    /// One camera's intrinsics and distortion from checkerboard images.
    Intrinsics(IntrinsicsArgs),
    /// A stereo pair: both cameras and the pose of the right one in the left one's frame.
    Stereo(StereoArgs),
    /// Every pair in the cell's frame: each pair's file (in its own frame, as `stereo` writes it)
    /// placed from points measured in the cell and seen by its cameras; writes the cell's rig file.
    Place(PlaceArgs),
}

/// Arguments of `ergocell calibrate place`.
#[derive(Debug, clap::Args)]
pub struct PlaceArgs {
    /// A rig file of cameras calibrated in one frame (a `calibrate stereo` output); once per pair.
    #[arg(long = "pair", required = true)]
    pub pairs: Vec<PathBuf>,
    /// Points measured in the cell's frame and the pixels each camera saw them at (TOML:
    /// `[[point]]` with `name`, `cell_m = [x, y, z]` and `[point.seen]` camera id = [u, v]).
    #[arg(long)]
    pub points: PathBuf,
    /// Output rig file (every camera in the cell's frame, `up` = +z); refused if it exists unless
    /// --force, and if it is an input.
    #[arg(long)]
    pub out: PathBuf,
    /// Overwrite an existing --out file.
    #[arg(long)]
    pub force: bool,
}

/// The board and the output, shared by both calibrations.
#[derive(Debug, clap::Args)]
pub struct BoardArgs {
    /// Inner corners per row x rows of inner corners (OpenCV's pattern size), e.g. 9x6.
    #[arg(long, default_value = "9x6")]
    pub board: String,
    /// Side of one square, metres.
    #[arg(long, default_value_t = 0.025)]
    pub square_m: f64,
    /// Output rig file; an existing file is refused unless --force, and an input image always.
    #[arg(long)]
    pub out: PathBuf,
    /// Overwrite an existing --out file.
    #[arg(long)]
    pub force: bool,
    /// Output format: ergocell's rig TOML (`config/` format) or the Anipose/Pose2Sim TOML.
    #[arg(long, default_value = "ergocell", value_parser = ["ergocell", "anipose"])]
    pub format: String,
}

/// Arguments of `ergocell calibrate intrinsics`.
#[derive(Debug, clap::Args)]
pub struct IntrinsicsArgs {
    /// A folder of .jpg/.png images, or a glob such as `data/left*.jpg`.
    #[arg(long)]
    pub images: String,
    /// Camera id written to the rig file.
    #[arg(long, default_value = "cam_0")]
    pub id: String,
    #[command(flatten)]
    pub common: BoardArgs,
}

/// Arguments of `ergocell calibrate stereo`.
#[derive(Debug, clap::Args)]
pub struct StereoArgs {
    /// Left camera images: a folder or a glob.
    #[arg(long)]
    pub left: String,
    /// Right camera images: a folder or a glob (same count, paired in sorted order).
    #[arg(long)]
    pub right: String,
    /// Camera ids written to the rig file.
    #[arg(long, default_value = "left")]
    pub left_id: String,
    #[arg(long, default_value = "right")]
    pub right_id: String,
    /// Refine both cameras' intrinsics in the stereo solve (default: held as calibrated alone).
    #[arg(long)]
    pub refine_intrinsics: bool,
    #[command(flatten)]
    pub common: BoardArgs,
}

pub fn run(args: &Args) -> anyhow::Result<()> {
    match &args.command {
        CalibrateCommand::Intrinsics(a) => run_intrinsics(a),
        CalibrateCommand::Stereo(a) => run_stereo(a),
        CalibrateCommand::Place(a) => run_place(a),
    }
}

/// `calibrate place`: reads the pairs and the points, places each pair, prints how well each fits,
/// writes the cell's rig.
fn run_place(args: &PlaceArgs) -> anyhow::Result<()> {
    let mut inputs: Vec<(&str, &Path)> =
        args.pairs.iter().map(|p| ("--pair", p.as_path())).collect();
    inputs.push(("--points", args.points.as_path()));
    output::check("--out", &args.out, args.force, &inputs)?;
    let mut groups = Vec::new();
    for path in &args.pairs {
        let text = input::read_text(path, Kind::Config)?;
        let (rig, _) =
            parse_rig(&text, &path.display().to_string()).map_err(|e| UsageError(e.to_string()))?;
        groups.push(rig);
    }
    let text = input::read_text(&args.points, Kind::Config)?;
    let points = place::parse_points(&text, &args.points.display().to_string())
        .map_err(|e| UsageError(e.to_string()))?;
    // Every failure here comes of the files given (a wrong id, a wrong measurement): bad input.
    let placed = place::place(&groups, &points).map_err(|e| UsageError(e.to_string()))?;
    let sources: Vec<String> = args.pairs.iter().map(|p| p.display().to_string()).collect();
    print!("{}", report::placement_text(&placed.groups, &sources));
    output::write(
        "--out",
        &args.out,
        args.force,
        to_ergocell_toml(&placed.rig).as_bytes(),
    )?;
    println!(
        "wrote {}: {} cameras in the cell's frame, up = +z",
        args.out.display(),
        placed.rig.len()
    );
    Ok(())
}

fn board_of(common: &BoardArgs) -> anyhow::Result<BoardSpec> {
    BoardSpec::parse(&common.board, common.square_m).map_err(|e| UsageError(e.to_string()).into())
}

fn camera_id(name: &str) -> anyhow::Result<CameraId> {
    CameraId::new(name).map_err(|e| UsageError(e.to_string()).into())
}

fn run_intrinsics(args: &IntrinsicsArgs) -> anyhow::Result<()> {
    let board = board_of(&args.common)?;
    let id = camera_id(&args.id)?;
    let paths = ergocell::input::list_images(&args.images)?;
    check_out(&args.common, &paths)?;
    let images = detect_all(&paths, &board, false)?;
    let size = common_size(&images, &id).map_err(|e| UsageError(e.to_string()))?;
    let (used, views) = usable_views(&images);
    let calib = match calibrate_camera(&views, &board, size, SolveOptions::default()) {
        Ok(c) => c,
        Err(e) => {
            print!("{}", report::intrinsics_table(&images, &[], &[]));
            return Err(usage_if_bad_views(e));
        }
    };
    print!(
        "{}",
        report::intrinsics_table(&images, &used, &calib.view_rms_px)
    );
    print!("{}", report::intrinsics_text(&id, &calib));
    let camera = Camera::new(
        id,
        calib.intrinsics,
        calib.distortion,
        Rotation3::identity(),
        Vector3::zeros(),
    )?;
    let rig = CameraRig::new(vec![camera], &[], None)?;
    write_rig(&rig, &args.common)
}

fn run_stereo(args: &StereoArgs) -> anyhow::Result<()> {
    let board = board_of(&args.common)?;
    let (left_id, right_id) = (camera_id(&args.left_id)?, camera_id(&args.right_id)?);
    if left_id == right_id {
        anyhow::bail!(UsageError(format!(
            "--left-id and --right-id are both `{left_id}`"
        )));
    }
    let (left_images, right_images) = detect_pairs(args, &board)?;
    let left = camera_views(left_id, &left_images).map_err(|e| UsageError(e.to_string()))?;
    let right = camera_views(right_id, &right_images).map_err(|e| UsageError(e.to_string()))?;
    let options = RigOptions {
        refine_intrinsics: args.refine_intrinsics,
        ..RigOptions::default()
    };
    let calib = match calibrate_stereo(left, right, &board, options) {
        Ok(c) => c,
        Err(e) => {
            print!(
                "{}",
                report::stereo_table(&left_images, &right_images, None)
            );
            return Err(usage_if_bad_views(e));
        }
    };
    let errors = Some(calib.view_rms_px.as_slice());
    print!(
        "{}",
        report::stereo_table(&left_images, &right_images, errors)
    );
    println!();
    print!("{}", report::rig_cameras_text(&calib));
    let pose = StereoPose::of(&calib, 0, 1).context("the stereo rig lost a camera")?;
    print!("{}", pose.text());
    write_rig(&calib.rig, &args.common)
}

/// The left and right images, listed (the output checked against them before any is decoded),
/// paired in sorted order (the counts must agree), and detected.
fn detect_pairs(
    args: &StereoArgs,
    board: &BoardSpec,
) -> anyhow::Result<(Vec<ImageDetection>, Vec<ImageDetection>)> {
    let left_paths = ergocell::input::list_images(&args.left)?;
    let right_paths = ergocell::input::list_images(&args.right)?;
    let mut all = left_paths.clone();
    all.extend(right_paths.iter().cloned());
    check_out(&args.common, &all)?;
    if left_paths.len() != right_paths.len() {
        anyhow::bail!(UsageError(format!(
            "{} left images but {} right images: stereo images must pair up",
            left_paths.len(),
            right_paths.len()
        )));
    }
    let mut left = detect_all(&all, board, true)?;
    let right = left.split_off(left_paths.len());
    Ok((left, right))
}

fn usage_if_bad_views(e: CalibrationError) -> anyhow::Error {
    match e {
        CalibrationError::TooFewViews { .. } => UsageError(format!(
            "{e} (see the table above for why images were rejected)"
        ))
        .into(),
        // the images cannot determine the camera: an input problem, not a failure of ours
        CalibrationError::Degenerate { .. } | CalibrationError::Initialisation(_) => {
            UsageError(e.to_string()).into()
        }
        other => anyhow::Error::new(other).context("calibration failed"),
    }
}

/// The output is checked before any image is decoded: not an existing file (unless `--force`), never
/// one of the images.
fn check_out(common: &BoardArgs, images: &[PathBuf]) -> anyhow::Result<()> {
    let inputs: Vec<(&str, &Path)> = images.iter().map(|p| ("image", p.as_path())).collect();
    Ok(output::check("--out", &common.out, common.force, &inputs)?)
}

fn write_rig(rig: &CameraRig, common: &BoardArgs) -> anyhow::Result<()> {
    let text = if common.format == "anipose" {
        to_anipose_toml(rig)
    } else {
        to_ergocell_toml(rig)
    };
    output::write("--out", &common.out, common.force, text.as_bytes())?;
    eprintln!("wrote {} ({} format)", common.out.display(), common.format);
    Ok(())
}

/// Reads, decodes and detects every image, on all cores, with a progress bar on a terminal. With
/// `for_rig`, views whose corner order cannot be matched across cameras are rejected.
fn detect_all(
    paths: &[PathBuf],
    board: &BoardSpec,
    for_rig: bool,
) -> anyhow::Result<Vec<ImageDetection>> {
    let bytes: Vec<Vec<u8>> = paths
        .iter()
        .map(|p| input::read(p, Kind::Image))
        .collect::<Result<_, _>>()?;
    let bar = progress_bar(paths.len());
    let workers = std::thread::available_parallelism()
        .map_or(1, std::num::NonZeroUsize::get)
        .min(paths.len().max(1));
    let mut results: Vec<Option<ImageDetection>> = (0..paths.len()).map(|_| None).collect();
    std::thread::scope(|scope| {
        let chunk = paths.len().div_ceil(workers).max(1);
        for (k, slot) in results.chunks_mut(chunk).enumerate() {
            let (bar, bytes) = (&bar, &bytes);
            scope.spawn(move || {
                for (j, out) in slot.iter_mut().enumerate() {
                    let i = k * chunk + j;
                    let name = paths[i].display().to_string();
                    *out = Some(ImageDetection::detect(&bytes[i], &name, board, for_rig));
                    bar.inc(1);
                }
            });
        }
    });
    bar.finish_and_clear();
    Ok(results.into_iter().flatten().collect())
}

/// A progress bar on stderr when it is a terminal (hidden otherwise: no escape codes in logs).
fn progress_bar(images: usize) -> ProgressBar {
    if !std::io::stderr().is_terminal() {
        return ProgressBar::hidden();
    }
    let bar = ProgressBar::new(images as u64);
    if let Ok(style) =
        ProgressStyle::with_template("detecting corners {bar:30} {pos}/{len} {wide_msg}")
    {
        bar.set_style(style);
    }
    bar
}
