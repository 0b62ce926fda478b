//! `ergocell triangulate`: 2D detections + calibration → one 3D position per landmark per frame, and a
//! summary (frames, landmarks triangulated, median reprojection error, bone-length variation,
//! throughput). Streamed: a recording of any length is read, fused and written one frame at a time.

use std::path::{Path, PathBuf};

use anyhow::bail;
use ergocell::detections::{self, Detections, Found};
use ergocell::input::{self, Kind};
use ergocell_cell::{Reconstruction, ReconstructionConfig};
use ergocell_formats::landmarks_file::{LandmarksFormat, StreamingEncoder};
use ergocell_formats::rig_file::parse_rig;
use ergocell_perception::detections::Frame2;
use ergocell_perception::detector_error;
use ergocell_perception::metrics::RunTally;
use ergocell_perception::report_text;
use ergocell_perception::temporal::OneEuroParams;
use ergocell_perception::{CameraRig, FusionMethod, KeypointFormat};

use super::signals::{StopFlag, Stopped};
use super::{output, UsageError};

/// Frames read ahead of the fusion by the reading thread (a few hundred kB: memory stays flat).
const READ_AHEAD: usize = 64;

/// The output is written out whenever this much of it is encoded.
const FLUSH_BYTES: usize = 1 << 20;

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
    /// A camera whose video is not its calibrated image: `CAMERA=fit` (the calibrated image scaled
    /// to fit the video frame, centred: letterbox or pillarbox) or `CAMERA=affine:SX,SY,OX,OY`
    /// (`x_cal = SX·(x − OX)`, `y_cal = SY·(y − OY)`). Repeat per camera. The video's size comes
    /// from the `video.json` that `ergocell-edge detect` writes beside the frames; a folder whose
    /// video size differs from the calibration and has no declaration is refused.
    #[arg(long = "video-geometry", value_name = "CAMERA=SPEC")]
    pub video_geometry: Vec<String>,
    /// Also measure the detector's error, each view against the other views
    /// (`ergocell_perception::detector_error`), print its tables and write them to this JSON file
    /// (refused if it exists, unless --force). Holds the detections in memory.
    #[arg(long, value_name = "FILE.json")]
    pub detector_error: Option<PathBuf>,
    /// The window whose mean residual is a view's persistent error, seconds (with --detector-error).
    #[arg(long, default_value_t = 1.0, requires = "detector_error")]
    pub persistent_window_s: f64,
}

pub fn run(args: &Args) -> anyhow::Result<()> {
    let out_format = check_args(args)?;
    let rig = read_rig(&args.calibration)?;
    let source = open_detections(args, &rig)?;
    let frame_count = source.frame_count();
    let reconstruction = Reconstruction::new(rig.clone(), reconstruction_config(args))?;
    let name = args
        .out
        .file_name()
        .map(|n| n.to_string_lossy().into_owned())
        .unwrap_or_default();
    // Streamed: frames are read, fused and written one at a time into a temporary file beside
    // --out, renamed onto it at the end (a failed or stopped run leaves no half-written --out). The
    // TRC header states the rate: estimated from the first fused frames, which are held back until
    // then (`StreamingEncoder`).
    let out = output::Partial::create("--out", &args.out, args.force)?;
    let stop = StopFlag::install()?;
    // the binary's wall clock, for the throughput figure only
    #[allow(clippy::disallowed_methods)]
    let started = std::time::Instant::now();
    let mut fusing = Fusing {
        args,
        rig: &rig,
        reconstruction,
        tally: RunTally::default(),
        encoder: StreamingEncoder::new(out_format, &name, args.rate_hz, frame_count),
        out,
        kept_frames: Vec::new(),
        progress: progress_bar(frame_count),
        frame_count,
    };
    let source = fusing.fuse_all(source, &stop)?;
    let done = fusing.finish(&source, started)?;
    print_source_warnings(&source);
    let learnt_offsets: Vec<_> = (0..rig.len())
        .map(|k| done.reconstruction.view_offset(k))
        .collect();
    print!(
        "{}",
        report_text::triangulation_summary(
            &rig,
            &done.tally,
            &learnt_offsets,
            &args.fusion,
            &args.filter,
            done.elapsed_s
        )
    );
    println!("wrote {}", args.out.display());
    if let Some(path) = &args.detector_error {
        write_detector_error(args, path, &rig, &done.kept_frames)?;
    }
    Ok(())
}

/// The cell controller's reconstruction stage with its defaults, but every frame written (no
/// tracked gate: a file keeps what was seen) and the filter only when asked for.
fn reconstruction_config(args: &Args) -> ReconstructionConfig {
    ReconstructionConfig {
        fusion: FusionMethod::from_name(&args.fusion).unwrap_or_default(),
        filter: (args.filter == "causal").then(OneEuroParams::default),
        min_tracked_landmarks: 0,
        ..ReconstructionConfig::default()
    }
}

/// The flags checked before anything is read: --out's format, the outputs (not an existing file
/// unless --force, never an input), --persistent-window-s and --rate-hz.
fn check_args(args: &Args) -> anyhow::Result<LandmarksFormat> {
    let out_format =
        LandmarksFormat::from_path(&args.out).map_err(|e| UsageError(e.to_string()))?;
    let inputs = [
        ("--calibration", args.calibration.as_path()),
        ("--detections", args.detections.as_path()),
    ];
    output::check("--out", &args.out, args.force, &inputs)?;
    if let Some(path) = &args.detector_error {
        let others = [inputs[0], inputs[1], ("--out", args.out.as_path())];
        output::check("--detector-error", path, args.force, &others)?;
        if !(args.persistent_window_s.is_finite() && args.persistent_window_s > 0.0) {
            bail!(UsageError(format!(
                "--persistent-window-s must be positive, got {}",
                args.persistent_window_s
            )));
        }
    }
    if !(args.rate_hz.is_finite() && args.rate_hz > 0.0) {
        bail!(UsageError(format!(
            "--rate-hz must be positive, got {}",
            args.rate_hz
        )));
    }
    Ok(out_format)
}

/// The calibration (ergocell, Anipose/Pose2Sim or caliscope; a file that does not parse is a usage
/// error), announced on stderr.
fn read_rig(path: &Path) -> anyhow::Result<CameraRig> {
    let name = path.display().to_string();
    let text = input::read_text(path, Kind::Config)?;
    let (rig, rig_format) = parse_rig(&text, &name).map_err(|e| UsageError(e.to_string()))?;
    eprintln!(
        "calibration: {} cameras ({rig_format:?} format), {} stereo pairs",
        rig.len(),
        rig.pairs().len()
    );
    Ok(rig)
}

/// What the fusion loop updates frame by frame: the reconstruction, the run's tallies, the output
/// being encoded and written, and the frames kept for --detector-error.
struct Fusing<'a> {
    args: &'a Args,
    rig: &'a CameraRig,
    reconstruction: Reconstruction,
    tally: RunTally,
    encoder: StreamingEncoder,
    out: output::Partial,
    kept_frames: Vec<Frame2>,
    progress: indicatif::ProgressBar,
    frame_count: usize,
}

/// A finished run: the reconstruction (with the image offsets it learnt), the tallies, the frames
/// kept for --detector-error, and the wall time reading, fusion and writing took.
struct Fused {
    reconstruction: Reconstruction,
    tally: RunTally,
    kept_frames: Vec<Frame2>,
    elapsed_s: f64,
}

impl Fusing<'_> {
    /// The detections are read and parsed on a second thread, up to READ_AHEAD frames ahead of the
    /// fusion (one producer, one FIFO channel: the order is kept): reading was a third of the time.
    /// Each view is mapped into its calibrated image there ([`Detections`]). The reader hands
    /// `source` back for its statistics; it stops when the fusion does (a closed channel).
    fn fuse_all<'s>(
        &mut self,
        mut source: Detections<'s>,
        stop: &StopFlag,
    ) -> anyhow::Result<Detections<'s>> {
        std::thread::scope(|scope| -> anyhow::Result<Detections<'s>> {
            let (frames, received) = std::sync::mpsc::sync_channel::<Frame2>(READ_AHEAD);
            let reader = scope.spawn(move || {
                for frame in source.by_ref() {
                    if frames.send(frame).is_err() {
                        break;
                    }
                }
                source
            });
            for frame in received {
                self.stop_if_asked(stop)?;
                self.fuse(frame)?;
            }
            reader
                .join()
                .map_err(|_| anyhow::anyhow!("the thread reading the detections failed"))
        })
    }

    /// A stop signal (SIGINT, SIGTERM) ends the run: the output discarded, what was done said.
    fn stop_if_asked(&mut self, stop: &StopFlag) -> anyhow::Result<()> {
        let Some(signal) = stop.get() else {
            return Ok(());
        };
        self.out.discard();
        Err(Stopped {
            signal,
            what: format!(
                "{} of {} frames triangulated, {} not written",
                self.tally.stats.frames(),
                self.frame_count,
                self.args.out.display()
            ),
        }
        .into())
    }

    /// One frame: fused, tallied, kept for --detector-error if asked, encoded (written out by the
    /// [`FLUSH_BYTES`]).
    fn fuse(&mut self, frame: Frame2) -> anyhow::Result<()> {
        let r = self.reconstruction.process_frame(&frame)?;
        let (fused, tracked) = (r.fused, r.tracked);
        let delivered = tracked.as_ref().unwrap_or(&fused.skeleton);
        self.tally.push(self.rig, &frame, &fused, delivered);
        if self.args.detector_error.is_some() {
            self.kept_frames.push(frame);
        }
        self.progress.inc(1);
        self.encoder.push(tracked.unwrap_or(fused.skeleton));
        if let Some(text) = self.encoder.take_text_over(FLUSH_BYTES) {
            self.out.write(text.as_bytes())?;
        }
        Ok(())
    }

    /// Ends the output (the frames still held, the footer) and moves it onto --out when every frame
    /// announced came out; otherwise discards it and says why. The wall time is taken before the
    /// move.
    fn finish(self, source: &Detections<'_>, started: std::time::Instant) -> anyhow::Result<Fused> {
        let Self {
            args,
            reconstruction,
            tally,
            encoder,
            mut out,
            kept_frames,
            progress,
            frame_count,
            ..
        } = self;
        let (text, written) = encoder.finish();
        out.write(text.as_bytes())?;
        progress.finish_and_clear();
        let elapsed_s = started.elapsed().as_secs_f64();
        if written != frame_count {
            out.discard();
            let detections = args.detections.display();
            if let Some(w) = source.stats().warning() {
                bail!("{detections}: {frame_count} frames found, {written} usable: {w}");
            }
            bail!(
                "{detections}: {frame_count} frames announced, {written} read (the detections changed while being read?)"
            );
        }
        out.finish()?;
        Ok(Fused {
            reconstruction,
            tally,
            kept_frames,
            elapsed_s,
        })
    }
}

/// --detector-error: each view measured against the other views over the kept frames
/// (`ergocell_perception::detector_error`), the tables printed and written as JSON.
fn write_detector_error(
    args: &Args,
    path: &Path,
    rig: &CameraRig,
    frames: &[Frame2],
) -> anyhow::Result<()> {
    let config = detector_error::MeasureConfig {
        window_s: args.persistent_window_s,
        ..detector_error::MeasureConfig::default()
    };
    let report = detector_error::measure(rig, frames, &config).report(rig, config.window_s);
    print!("{}", report_text::detector_error_tables(&report));
    let json = serde_json::to_string_pretty(&report)?;
    output::write("--detector-error", path, args.force, json.as_bytes())?;
    println!("wrote {}", path.display());
    Ok(())
}

/// The detections (`--format`, or by what `--detections` is: a folder of OpenPose JSON, else a
/// caliscope file), each view mapped into its camera's calibrated image
/// ([`ergocell::detections`]), saying what was found on the way.
fn open_detections<'a>(args: &'a Args, rig: &'a CameraRig) -> anyhow::Result<Detections<'a>> {
    let keypoints = KeypointFormat::from_name(&args.keypoints)
        .ok_or_else(|| UsageError(format!("unknown keypoint layout {}", args.keypoints)))?;
    let format = args.format.as_deref().map(|f| match f {
        "caliscope" => detections::Format::Caliscope,
        _ => detections::Format::OpenPose,
    });
    let request = detections::Request {
        path: &args.detections,
        format,
        keypoints,
        rate_hz: args.rate_hz,
        video_geometry: &args.video_geometry,
    };
    Ok(detections::open(&request, rig, &mut say_found)?)
}

/// What opening the detections found, on stderr.
fn say_found(found: Found<'_>) {
    match found {
        Found::CameraFolder {
            camera,
            folder,
            files,
        } => eprintln!("camera {camera} ← {folder}/ ({files} files)"),
        Found::Unsorted { name } => eprintln!(
            "note: {name}: rows not in sync_index order, so the whole file is read first"
        ),
        Found::VideoMap {
            camera,
            geometry,
            map,
        } => eprintln!(
            "camera {camera}: video geometry {geometry}: x_cal = {:.6}·(x − {:.3}), y_cal = {:.6}·(y − {:.3})",
            map.scale[0], map.offset_px[0], map.scale[1], map.offset_px[1]
        ),
    }
}

/// The reader's warnings (the first [`MAX_WARNINGS`]) and its statistics' warning.
fn print_source_warnings(source: &Detections<'_>) {
    for w in source.warnings().iter().take(MAX_WARNINGS) {
        eprintln!("warning: {w}");
    }
    if source.warnings().len() > MAX_WARNINGS {
        eprintln!(
            "warning: … and {} more files left out",
            source.warnings().len() - MAX_WARNINGS
        );
    }
    if let Some(w) = source.stats().warning() {
        eprintln!("warning: {w}");
    }
}

/// A progress bar on stderr when it is a terminal (hidden otherwise: no escape codes in logs).
fn progress_bar(frames: usize) -> indicatif::ProgressBar {
    use std::io::IsTerminal as _;
    if !std::io::stderr().is_terminal() {
        return indicatif::ProgressBar::hidden();
    }
    let bar = indicatif::ProgressBar::new(frames as u64);
    if let Ok(style) =
        indicatif::ProgressStyle::with_template("{bar:40} {pos}/{len} frames  {per_sec}  eta {eta}")
    {
        bar.set_style(style);
    }
    bar
}

/// At most this many per-file warnings are printed (the rest are counted).
const MAX_WARNINGS: usize = 20;
