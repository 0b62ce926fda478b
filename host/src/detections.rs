//! The 2D detections `ergocell triangulate` reads on this machine: a folder of per-camera folders of
//! OpenPose-style JSON files, each file read when its frame is, or caliscope's `xy_*.csv`, streamed
//! when its rows are in `sync_index` order and read whole otherwise; and the `video.json` that
//! `ergocell-edge detect` writes beside a camera's frames, whose video size decides how that
//! camera's pixels map into its calibrated image ([`VideoMap`]).
//!
//! Every file is read through [`crate::input`] (bounded, named in every error); the parsing and
//! the pairing of frames are `ergocell_formats::import`'s, the maps
//! `ergocell_perception::video_geometry`'s. What is found on the way (the camera folders, an
//! unsorted file, the declared maps) is handed to the caller to tell ([`Found`]); what makes the
//! detections unusable is an [`InputError::Detections`], bad input.

use std::fs::File;
use std::io::BufReader;
use std::path::{Path, PathBuf};

use ergocell_formats::import::{
    match_camera_folders, parse_caliscope_xy_bytes, scan_caliscope_xy, CaliscopeStream,
    OpenPosePlan,
};
use ergocell_perception::detections::{Frame2, ImportStats};
use ergocell_perception::video_geometry::{parse_declarations, VideoGeometry, VideoMap};
use ergocell_perception::{CameraRig, KeypointFormat, PerceptionError};

use crate::input::{self, InputError, Kind};

/// The file `ergocell-edge detect` writes beside a camera's frames: the video's source, size, rate
/// and the detector's figures. Only the size is read here.
pub const VIDEO_SIDECAR: &str = "video.json";

/// How the detections are stored.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Format {
    /// A folder of per-camera folders of OpenPose-style JSON files, a file per frame.
    OpenPose,
    /// caliscope's `xy_*.csv`.
    Caliscope,
}

/// The detections to open.
#[derive(Debug, Clone)]
pub struct Request<'a> {
    /// The folder (OpenPose) or the file (caliscope).
    pub path: &'a Path,
    /// `None`: OpenPose for a folder, caliscope for anything else.
    pub format: Option<Format>,
    /// The keypoint layout of OpenPose-style files.
    pub keypoints: KeypointFormat,
    /// The frame rate of OpenPose-style files (they carry no time stamps), Hz.
    pub rate_hz: f64,
    /// `--video-geometry` declarations, `CAMERA=fit` or `CAMERA=affine:SX,SY,OX,OY`.
    pub video_geometry: &'a [String],
}

/// What [`open`] found on the way, in the order it found it, for the caller to tell.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Found<'a> {
    /// A camera folder matched to the rig camera `camera`, with its detection files counted.
    CameraFolder {
        camera: &'a str,
        folder: &'a str,
        files: usize,
    },
    /// A caliscope file whose rows are not in `sync_index` order: read whole before the first frame.
    Unsorted { name: &'a str },
    /// A camera's declared video geometry and the map it resolved to.
    VideoMap {
        camera: &'a str,
        geometry: VideoGeometry,
        map: VideoMap,
    },
}

/// A video frame's size in pixels, from [`VIDEO_SIDECAR`].
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Deserialize)]
pub struct VideoSize {
    pub width: u32,
    pub height: u32,
}

/// Why detections cannot be used (inside [`InputError::Detections`]: bad input).
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum DetectionsError {
    /// The detections file cannot be opened (`source` says why).
    #[error("reading {name}")]
    Open {
        name: String,
        #[source]
        source: Box<InputError>,
    },
    /// A folder cannot be listed.
    #[error("reading {}", path.display())]
    Listing {
        path: PathBuf,
        #[source]
        source: std::io::Error,
    },
    /// The detections, or a `--video-geometry` declaration, do not parse (the message names what).
    #[error("{0}")]
    Format(PerceptionError),
    /// An OpenPose folder without camera folders.
    #[error("{}: no camera folders inside", path.display())]
    NoCameraFolders { path: PathBuf },
    /// Detections without a single frame.
    #[error("{}: no frames found", path.display())]
    NoFrames { path: PathBuf },
    /// A [`VIDEO_SIDECAR`] that does not give a size.
    #[error("{}: not a video description (width and height in pixels): {error}", path.display())]
    NotAVideoDescription {
        path: PathBuf,
        error: serde_json::Error,
    },
    /// A camera whose video is not its calibrated size, with no `--video-geometry` for it.
    #[error(
        "camera {camera}: its video is {}x{} (its folder's {VIDEO_SIDECAR}) but it was calibrated at {}x{}: \
         declare how they relate, e.g. --video-geometry {camera}=fit (the calibrated image scaled to fit \
         the video, centred) or {camera}=affine:SX,SY,OX,OY",
        video.0, video.1, calibrated.0, calibrated.1
    )]
    UndeclaredVideoSize {
        camera: String,
        video: (u32, u32),
        calibrated: (u32, u32),
    },
    /// `CAMERA=fit` for a camera with no [`VIDEO_SIDECAR`].
    #[error(
        "--video-geometry {camera}=fit needs the video's size, and no {VIDEO_SIDECAR} gives it: \
         use {camera}=affine:SX,SY,OX,OY"
    )]
    FitWithoutVideoSize { camera: String },
    /// A declared geometry that cannot map this camera's video.
    #[error("camera {camera}: {error}")]
    Geometry {
        camera: String,
        error: Box<PerceptionError>,
    },
}

impl From<DetectionsError> for InputError {
    fn from(e: DetectionsError) -> Self {
        Self::Detections(Box::new(e))
    }
}

/// Detections opened: the frames in order, read one at a time, each view already mapped into its
/// camera's calibrated image; what was left out, as it is read.
pub struct Detections<'r> {
    source: FrameSource<'r>,
    maps: Vec<VideoMap>,
}

impl Detections<'_> {
    /// How many frames there are (at least one).
    pub fn frame_count(&self) -> usize {
        self.source.frame_count()
    }

    /// What was left out so far.
    pub fn stats(&self) -> ImportStats {
        self.source.stats()
    }

    /// A line per file left out so far, naming it (OpenPose folders).
    pub fn warnings(&self) -> &[String] {
        self.source.warnings()
    }
}

impl Iterator for Detections<'_> {
    type Item = Frame2;

    fn next(&mut self) -> Option<Frame2> {
        let mut frame = self.source.next()?;
        for view in &mut frame.views {
            if let Some(m) = self.maps.get(view.camera) {
                m.apply_view(view);
            }
        }
        Some(frame)
    }
}

/// Opens the detections of `request` for `rig` (see the module docs), telling `found` what it
/// finds on the way. Detections without a frame are refused.
pub fn open<'r>(
    request: &Request<'_>,
    rig: &'r CameraRig,
    found: &mut dyn FnMut(Found<'_>),
) -> Result<Detections<'r>, InputError> {
    let path = request.path;
    let format = request.format.unwrap_or_else(|| {
        if path.is_dir() {
            Format::OpenPose
        } else {
            Format::Caliscope
        }
    });
    let source = match format {
        Format::Caliscope => FrameSource::caliscope(path, rig, found)?,
        Format::OpenPose => FrameSource::openpose(request, rig, found)?,
    };
    let maps = video_maps(rig, request.video_geometry, source.video_sizes(), found)?;
    if source.frame_count() == 0 {
        return Err(DetectionsError::NoFrames {
            path: path.to_owned(),
        }
        .into());
    }
    Ok(Detections { source, maps })
}

/// Where the frames come from: read one at a time (caliscope CSV in `sync_index` order, OpenPose
/// folders), or, for a CSV whose rows are not in order, the whole file parsed first.
enum FrameSource<'r> {
    Stream {
        frames: CaliscopeStream<'r, BufReader<File>>,
        count: usize,
    },
    Memory {
        frames: std::vec::IntoIter<Frame2>,
        count: usize,
        stats: ImportStats,
    },
    OpenPose {
        plan: OpenPosePlan,
        next: usize,
        stats: ImportStats,
        /// Per rig camera, the video size of its folder's [`VIDEO_SIDECAR`], when there is one.
        video_sizes: Vec<Option<VideoSize>>,
    },
}

impl<'r> FrameSource<'r> {
    /// A caliscope file: scanned once for its frames and order, then streamed, or read whole when
    /// its rows are out of order.
    fn caliscope(
        path: &Path,
        rig: &'r CameraRig,
        found: &mut dyn FnMut(Found<'_>),
    ) -> Result<Self, InputError> {
        let name = path.display().to_string();
        let open = || {
            input::open(path)
                .map(|(f, _)| BufReader::new(f))
                .map_err(|e| DetectionsError::Open {
                    name: name.clone(),
                    source: Box::new(e),
                })
        };
        let scan = scan_caliscope_xy(open()?, &name).map_err(DetectionsError::Format)?;
        if scan.sorted {
            let frames =
                CaliscopeStream::new(open()?, &name, rig).map_err(DetectionsError::Format)?;
            return Ok(Self::Stream {
                frames,
                count: scan.frames,
            });
        }
        found(Found::Unsorted { name: &name });
        let bytes = input::read(path, Kind::Data)?;
        let mut stats = ImportStats::default();
        let frames = parse_caliscope_xy_bytes(&bytes, &name, rig, &mut stats)
            .map_err(DetectionsError::Format)?;
        Ok(Self::Memory {
            count: frames.len(),
            frames: frames.into_iter(),
            stats,
        })
    }

    /// Lists the camera folders and their files (names only; each file is read when its frame
    /// is), and reads each folder's [`VIDEO_SIDECAR`].
    fn openpose(
        request: &Request<'_>,
        rig: &CameraRig,
        found: &mut dyn FnMut(Found<'_>),
    ) -> Result<Self, InputError> {
        let dir = request.path;
        let folders = camera_folders(dir)?;
        if folders.is_empty() {
            return Err(DetectionsError::NoCameraFolders {
                path: dir.to_owned(),
            }
            .into());
        }
        let matched = match_camera_folders(&folders, rig).map_err(DetectionsError::Format)?;
        // Frames are paired by the frame number in each file name (OpenPosePlan): a missing file
        // is a missing view of that frame only, never a shift of every later frame.
        let mut cameras = Vec::new();
        let mut video_sizes = vec![None; rig.len()];
        for (folder, camera) in matched {
            let (files, sidecar) = camera_files(&dir.join(&folder))?;
            if let (Some(path), Some(slot)) = (sidecar, video_sizes.get_mut(camera)) {
                *slot = Some(read_video_sidecar(&path)?);
            }
            found(Found::CameraFolder {
                camera: rig.cameras().get(camera).map_or("", |c| c.id.as_str()),
                folder: &folder,
                files: files.len(),
            });
            cameras.push((camera, files));
        }
        let mut stats = ImportStats::default();
        let plan = OpenPosePlan::new(&cameras, request.keypoints, request.rate_hz, &mut stats)
            .map_err(DetectionsError::Format)?;
        Ok(Self::OpenPose {
            plan,
            next: 0,
            stats,
            video_sizes,
        })
    }

    /// Per rig camera, the video size the detections were made in, where known.
    fn video_sizes(&self) -> Option<&[Option<VideoSize>]> {
        match self {
            Self::OpenPose { video_sizes, .. } => Some(video_sizes),
            _ => None,
        }
    }

    fn frame_count(&self) -> usize {
        match self {
            Self::Stream { count, .. } | Self::Memory { count, .. } => *count,
            Self::OpenPose { plan, .. } => plan.frame_count(),
        }
    }

    fn stats(&self) -> ImportStats {
        match self {
            Self::Stream { frames, .. } => frames.stats(),
            Self::Memory { stats, .. } | Self::OpenPose { stats, .. } => *stats,
        }
    }

    fn warnings(&self) -> &[String] {
        match self {
            Self::OpenPose { plan, .. } => &plan.warnings,
            _ => &[],
        }
    }
}

impl Iterator for FrameSource<'_> {
    type Item = Frame2;

    fn next(&mut self) -> Option<Frame2> {
        match self {
            Self::Stream { frames, .. } => frames.next(),
            Self::Memory { frames, .. } => frames.next(),
            Self::OpenPose {
                plan, next, stats, ..
            } => {
                let k = *next;
                *next += 1;
                // the file names are full paths (as listed)
                plan.frame(k, |_, name| input::read(Path::new(name), Kind::Data), stats)
            }
        }
    }
}

/// The names of the folders inside `dir`.
fn camera_folders(dir: &Path) -> Result<Vec<String>, DetectionsError> {
    let listing = |source| DetectionsError::Listing {
        path: dir.to_owned(),
        source,
    };
    let mut folders = Vec::new();
    for entry in std::fs::read_dir(dir).map_err(listing)? {
        let entry = entry.map_err(listing)?;
        if entry.file_type().map_err(listing)?.is_dir() {
            folders.push(entry.file_name().to_string_lossy().into_owned());
        }
    }
    Ok(folders)
}

/// A camera folder's detection files (every `*.json` but the sidecar, as paths) and its
/// [`VIDEO_SIDECAR`], if it has one.
fn camera_files(folder: &Path) -> Result<(Vec<String>, Option<PathBuf>), DetectionsError> {
    let entries = std::fs::read_dir(folder).map_err(|source| DetectionsError::Listing {
        path: folder.to_owned(),
        source,
    })?;
    let (mut files, mut sidecar) = (Vec::new(), None);
    for path in entries.filter_map(Result::ok).map(|e| e.path()) {
        if path.file_name().is_some_and(|n| n == VIDEO_SIDECAR) {
            sidecar = Some(path);
        } else if path
            .extension()
            .is_some_and(|e| e.eq_ignore_ascii_case("json"))
        {
            files.push(path.display().to_string());
        }
    }
    Ok((files, sidecar))
}

/// The video size a [`VIDEO_SIDECAR`] gives.
pub fn read_video_sidecar(path: &Path) -> Result<VideoSize, InputError> {
    let text = input::read_text(path, Kind::Config)?;
    serde_json::from_str(&text).map_err(|error| {
        DetectionsError::NotAVideoDescription {
            path: path.to_owned(),
            error,
        }
        .into()
    })
}

/// Each camera's map from its video's pixels into its calibrated image: the declared
/// `--video-geometry` (each told to `found`), checked against the video sizes the detector
/// recorded. A camera whose recorded video size is not its calibrated size and that has no
/// declaration is refused, as is a declaration for an unknown camera or a `fit` with no known
/// video size.
fn video_maps(
    rig: &CameraRig,
    entries: &[String],
    sizes: Option<&[Option<VideoSize>]>,
    found: &mut dyn FnMut(Found<'_>),
) -> Result<Vec<VideoMap>, DetectionsError> {
    let declared = parse_declarations(rig, entries).map_err(DetectionsError::Format)?;
    let mut maps = Vec::with_capacity(rig.len());
    for (index, camera) in rig.cameras().iter().enumerate() {
        let calibrated = (camera.intrinsics.width_px, camera.intrinsics.height_px);
        let video = sizes
            .and_then(|s| s.get(index).copied().flatten())
            .map(|s| (s.width, s.height));
        let id = camera.id.as_str();
        let map = match (declared.get(index).copied().flatten(), video) {
            (None, Some(video)) if video != calibrated => {
                return Err(DetectionsError::UndeclaredVideoSize {
                    camera: id.to_owned(),
                    video,
                    calibrated,
                })
            }
            (None, _) => VideoMap::IDENTITY,
            (Some(VideoGeometry::Fit), None) => {
                return Err(DetectionsError::FitWithoutVideoSize {
                    camera: id.to_owned(),
                })
            }
            (Some(geometry), video) => {
                let map = geometry
                    .map(video.unwrap_or(calibrated), calibrated)
                    .map_err(|error| DetectionsError::Geometry {
                        camera: id.to_owned(),
                        error: Box::new(error),
                    })?;
                found(Found::VideoMap {
                    camera: id,
                    geometry,
                    map,
                });
                map
            }
        };
        maps.push(map);
    }
    Ok(maps)
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::fs;

    /// The shipped rig (1280x720 cameras `s1_left`, `s1_right`, …), its first two cameras renamed
    /// `cam_0` and `cam_1` when `caliscope` (caliscope's port N is camera `cam_N`).
    fn rig(caliscope: bool) -> CameraRig {
        let mut text = include_str!("../../config/rig.toml").to_owned();
        if caliscope {
            text = text
                .replace("s1_left", "cam_0")
                .replace("s1_right", "cam_1");
        }
        ergocell_formats::rig_file::parse_rig(&text, "rig.toml")
            .unwrap()
            .0
    }

    fn folder(name: &str) -> PathBuf {
        let dir =
            std::env::temp_dir().join(format!("ergocell-detections-{name}-{}", std::process::id()));
        let _ = fs::remove_dir_all(&dir);
        fs::create_dir_all(&dir).unwrap();
        dir
    }

    fn request<'a>(path: &'a Path, video_geometry: &'a [String]) -> Request<'a> {
        Request {
            path,
            format: None,
            keypoints: KeypointFormat::Coco17,
            rate_hz: 30.0,
            video_geometry,
        }
    }

    /// Opens `request`, collecting what was found as text.
    fn opened<'r>(
        request: &Request<'_>,
        rig: &'r CameraRig,
    ) -> (Result<Detections<'r>, InputError>, Vec<String>) {
        let mut said = Vec::new();
        let result = open(request, rig, &mut |f: Found<'_>| {
            said.push(format!("{f:?}"));
        });
        (result, said)
    }

    /// Why detections were refused.
    fn why(e: &InputError) -> &DetectionsError {
        match e {
            InputError::Detections(why) => why,
            _ => panic!("not a refusal of detections: {e}"),
        }
    }

    const CSV_HEADER: &str = "sync_index,port,frame_time,point_id,img_loc_x,img_loc_y";

    /// A file whose rows are out of `sync_index` order is said and read whole, and gives the very
    /// frames the same rows in order give, streamed.
    #[test]
    fn a_caliscope_file_out_of_order_is_said_and_read_whole_with_the_same_frames() {
        let dir = folder("caliscope");
        let rows = [
            "0,0,0.0,0,100,200",
            "0,1,0.0,0,110,200",
            "1,0,0.1,0,101,201",
            "1,1,0.1,0,111,201",
            "2,0,0.2,0,102,202",
        ];
        let sorted = dir.join("sorted.csv");
        fs::write(&sorted, format!("{CSV_HEADER}\n{}\n", rows.join("\n"))).unwrap();
        let unsorted = dir.join("unsorted.csv");
        let moved = [&rows[1..], &rows[..1]].concat();
        fs::write(&unsorted, format!("{CSV_HEADER}\n{}\n", moved.join("\n"))).unwrap();
        let rig = rig(true);
        let (a, said_a) = opened(&request(&sorted, &[]), &rig);
        let (b, said_b) = opened(&request(&unsorted, &[]), &rig);
        let (a, b) = (a.unwrap(), b.unwrap());
        assert_eq!((a.frame_count(), b.frame_count()), (3, 3));
        assert!(said_a.is_empty(), "{said_a:?}");
        assert_eq!(said_b.len(), 1);
        assert!(said_b[0].starts_with("Unsorted"), "{said_b:?}");
        let (a, b): (Vec<Frame2>, Vec<Frame2>) = (a.collect(), b.collect());
        assert_eq!(a.len(), 3);
        assert_eq!(a, b);
        assert_eq!(a[0].views.len(), 2);
        assert_eq!(a[2].views.len(), 1);
        let _ = fs::remove_dir_all(&dir);
    }

    /// One OpenPose file with one COCO person whose nose is at `nose`.
    fn openpose_file(nose: (f64, f64)) -> String {
        let mut values = vec![0.0; 17 * 3];
        values[..3].copy_from_slice(&[nose.0, nose.1, 0.9]);
        serde_json::json!({ "people": [{ "pose_keypoints_2d": values }] }).to_string()
    }

    /// Two camera folders of two frames each, the first with a sidecar giving a 1920x1080 video.
    fn openpose_folders(name: &str) -> PathBuf {
        let dir = folder(name);
        for camera in ["s1_left", "s1_right"] {
            fs::create_dir_all(dir.join(camera)).unwrap();
            for k in 0..2 {
                let file = dir.join(format!("{camera}/{camera}_{k:012}_keypoints.json"));
                fs::write(file, openpose_file((960.25, 540.25))).unwrap();
            }
        }
        let sidecar = dir.join("s1_left").join(VIDEO_SIDECAR);
        fs::write(
            sidecar,
            r#"{"source": "a.mp4", "width": 1920, "height": 1080}"#,
        )
        .unwrap();
        dir
    }

    /// The sidecar is no detection file; a video size other than the calibrated one must be
    /// declared, and then each view is mapped into its calibrated image (`fit`: 1920x1080 into
    /// 1280x720 is a scale of 1.5, the pixel centres 0.25 px in), an undeclared camera untouched.
    #[test]
    fn openpose_folders_map_a_declared_video_and_refuse_an_undeclared_one() {
        let dir = openpose_folders("openpose");
        let rig = rig(false);
        let (refused, said) = opened(&request(&dir, &[]), &rig);
        let e = refused.err().unwrap();
        let DetectionsError::UndeclaredVideoSize {
            camera,
            video,
            calibrated,
        } = why(&e)
        else {
            panic!("{e}");
        };
        assert_eq!(
            (camera.as_str(), *video, *calibrated),
            ("s1_left", (1920, 1080), (1280, 720))
        );
        assert!(
            e.to_string().contains("--video-geometry s1_left=fit"),
            "{e}"
        );
        assert_eq!(said.len(), 2, "{said:?}");
        assert!(said.iter().all(|s| s.contains("files: 2")), "{said:?}");
        let fit = ["s1_left=fit".to_owned()];
        let (detections, said) = opened(&request(&dir, &fit), &rig);
        let detections = detections.unwrap();
        assert_eq!(detections.frame_count(), 2);
        assert!(said[2].starts_with("VideoMap"), "{said:?}");
        let frames: Vec<Frame2> = detections.collect();
        assert_eq!(frames.len(), 2);
        // The one keypoint of a camera's view: the nose.
        let nose = |f: &Frame2, camera: usize| {
            let view = f.views.iter().find(|v| v.camera == camera).unwrap();
            assert_eq!(view.observed_count(), 1);
            let p = view.keypoints().iter().flatten().next().unwrap().pixel();
            (p.x, p.y)
        };
        for f in &frames {
            let (x, y) = nose(f, 0);
            assert!(
                (x - 640.0).abs() < 1e-9 && (y - 360.0).abs() < 1e-9,
                "{x} {y}"
            );
            assert_eq!(nose(f, 1), (960.25, 540.25));
        }
        let _ = fs::remove_dir_all(&dir);
    }

    /// Each way detections can be unusable is bad input naming the file.
    #[test]
    fn unusable_detections_are_refused_by_name() {
        let dir = folder("refused");
        let rig = rig(true);
        let refusal = |path: &Path, geometry: &[String]| {
            let (result, _) = opened(&request(path, geometry), &rig);
            result.err().unwrap()
        };
        let e = refusal(&dir.join("missing.csv"), &[]);
        assert!(
            e.to_string().starts_with("reading ") && e.to_string().ends_with("missing.csv"),
            "{e}"
        );
        assert!(matches!(why(&e), DetectionsError::Open { .. }), "{e}");
        let empty = dir.join("empty.csv");
        fs::write(&empty, format!("{CSV_HEADER}\n")).unwrap();
        let e = refusal(&empty, &[]);
        assert!(e.to_string().ends_with("empty.csv: no frames found"), "{e}");
        let e = refusal(&dir, &[]);
        assert!(e.to_string().ends_with("no camera folders inside"), "{e}");
        fs::create_dir_all(dir.join("cam_0")).unwrap();
        let e = refusal(&dir, &["cam_0=fit".to_owned()]);
        assert!(
            matches!(why(&e), DetectionsError::FitWithoutVideoSize { .. }),
            "{e}"
        );
        fs::write(dir.join("cam_0").join(VIDEO_SIDECAR), "{\"width\": 1920}").unwrap();
        let e = refusal(&dir, &[]);
        assert!(e.to_string().contains("not a video description"), "{e}");
        let _ = fs::remove_dir_all(&dir);
    }
}
