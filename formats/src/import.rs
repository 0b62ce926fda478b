//! Importers for 2D detections written by other tools. No I/O: callers pass file contents.
//!
//! - **OpenPose JSON** (also written by RTMPose/Pose2Sim): one folder per camera, one file per frame,
//!   `{"people": [{"pose_keypoints_2d": [x0, y0, c0, x1, …]}]}`. Undetected keypoints are `0, 0, 0`.
//!   Camera folders are matched to the calibration's cameras by name where they match, else in sorted
//!   order, as Pose2Sim does ([`match_camera_folders`]). With several people in a frame the operator is
//!   chosen by [`OperatorSelector`]. Frames are paired across cameras by the frame number in each
//!   file name, not by file order ([`assemble_openpose`]), so a missing file is a missing view of
//!   that frame only.
//! - **caliscope** long CSV (`xy_*.csv`): `sync_index, port, frame_index, frame_time, point_id,
//!   img_loc_x, img_loc_y`, BlazePose point ids, no confidence column (taken as 1).
//!
//! One bad record (a non-UTF-8 or malformed file, an unparsable row) is skipped and counted in
//! [`ImportStats`], never fatal and never shifting the others; a file that cannot be read as its
//! format at all (a required CSV column missing) is an error naming what is missing.

use std::collections::BTreeMap;

use ergocell_skeleton::LANDMARK_COUNT;
use nalgebra::Point2;
use serde::Deserialize;

use crate::error::{parse_err, Result};
use ergocell_perception::detections::{Frame2, ImportStats, Keypoint2, KeypointFormat, View2};
use ergocell_perception::rig::{CameraIndex, CameraRig};

/// One person of an OpenPose frame, already mapped to BlazePose order.
#[derive(Debug, Clone, PartialEq)]
pub struct Person2 {
    pub keypoints: [Option<Keypoint2>; LANDMARK_COUNT],
}

impl Person2 {
    /// Mean confidence over all keypoints of the layout (undetected ones count as 0).
    pub fn mean_confidence(&self) -> f64 {
        let (sum, n) = self
            .keypoints
            .iter()
            .flatten()
            .fold((0.0, 0usize), |(s, n), k| (s + k.confidence(), n + 1));
        if n == 0 {
            0.0
        } else {
            sum / n as f64
        }
    }

    /// Confidence-weighted centroid of the detected keypoints.
    pub fn centroid(&self) -> Option<Point2<f64>> {
        let mut w = 0.0;
        let mut c = nalgebra::Vector2::zeros();
        for k in self.keypoints.iter().flatten() {
            w += k.confidence();
            c += k.pixel().coords * k.confidence();
        }
        (w > 0.0).then(|| Point2::from(c / w))
    }
}

#[derive(Deserialize)]
struct OpenPoseFile {
    #[serde(default)]
    people: Vec<OpenPosePerson>,
}

#[derive(Deserialize)]
struct OpenPosePerson {
    #[serde(default)]
    pose_keypoints_2d: Vec<f64>,
}

/// Parses one OpenPose JSON frame into the people it lists (BlazePose order). Keypoints with zero
/// confidence are "not observed"; invalid ones are dropped and counted in `stats`.
pub fn parse_openpose_frame(
    text: &str,
    source_name: &str,
    format: KeypointFormat,
    stats: &mut ImportStats,
) -> Result<Vec<Person2>> {
    // serde_json rejects NaN literals; OpenPose writes none, but other tools do: map them to null first
    // would be guesswork, so a file with them is reported as malformed.
    let file: OpenPoseFile =
        serde_json::from_str(text).map_err(|e| parse_err(source_name, "people", e))?;
    let mapping = format.mapping();
    let mut people = Vec::with_capacity(file.people.len());
    for (p, person) in file.people.iter().enumerate() {
        let flat = &person.pose_keypoints_2d;
        if flat.len() != 3 * mapping.len() {
            return Err(parse_err(
                source_name,
                format!("people[{p}].pose_keypoints_2d"),
                format!(
                    "expected {} values for {format:?} ({} keypoints × 3), got {}",
                    3 * mapping.len(),
                    mapping.len(),
                    flat.len()
                ),
            ));
        }
        let mut keypoints = [None; LANDMARK_COUNT];
        for (i, landmark) in mapping.iter().enumerate() {
            let Some(landmark) = landmark else { continue };
            let (u, v, c) = (flat[3 * i], flat[3 * i + 1], flat[3 * i + 2]);
            if c == 0.0 {
                continue;
            }
            match Keypoint2::new(u, v, c) {
                Ok(k) => keypoints[landmark.index()] = Some(k),
                Err(_) => stats.invalid_keypoints += 1,
            }
        }
        people.push(Person2 { keypoints });
    }
    Ok(people)
}

/// Chooses the operator among the people one camera sees, consistently over time: the person nearest
/// to the operator's last position in this camera (among those at least half as confident as the best),
/// or, with no history, the one with the highest mean confidence.
#[derive(Debug, Clone, Default)]
pub struct OperatorSelector {
    last_centroid: BTreeMap<CameraIndex, Point2<f64>>,
}

impl OperatorSelector {
    /// Picks the operator for `camera` and remembers where they were.
    pub fn select(&mut self, camera: CameraIndex, people: &[Person2]) -> Option<usize> {
        let best_conf = people
            .iter()
            .map(Person2::mean_confidence)
            .fold(0.0, f64::max);
        if best_conf <= 0.0 {
            return None;
        }
        let candidates = people
            .iter()
            .enumerate()
            .filter(|(_, p)| p.mean_confidence() >= 0.5 * best_conf);
        let chosen = match self.last_centroid.get(&camera) {
            Some(last) => candidates
                .filter_map(|(i, p)| p.centroid().map(|c| (i, (c - last).norm())))
                .min_by(|a, b| a.1.total_cmp(&b.1))
                .map(|(i, _)| i),
            None => candidates
                .max_by(|a, b| a.1.mean_confidence().total_cmp(&b.1.mean_confidence()))
                .map(|(i, _)| i),
        }?;
        if let Some(c) = people[chosen].centroid() {
            self.last_centroid.insert(camera, c);
        }
        Some(chosen)
    }
}

/// Matches camera folder names to the rig's cameras: by exact name (or a folder name that contains the
/// camera id, e.g. `cam_0_json` for `cam_0`) where every folder matches, else in sorted order (as
/// Pose2Sim does). Returns `(folder, camera index)` pairs; folders beyond the rig's size are an error.
pub fn match_camera_folders(
    folders: &[String],
    rig: &CameraRig,
) -> Result<Vec<(String, CameraIndex)>> {
    let mut sorted = folders.to_vec();
    sorted.sort();
    let by_name: Option<Vec<_>> = sorted
        .iter()
        .map(|f| {
            rig.index_of_name(f).or_else(|| {
                // longest camera id contained in the folder name, to tell cam_1 from cam_10
                rig.cameras()
                    .iter()
                    .enumerate()
                    .filter(|(_, c)| f.contains(c.id.as_str()))
                    .max_by_key(|(_, c)| c.id.as_str().len())
                    .map(|(i, _)| i)
            })
        })
        .collect();
    if let Some(indices) = by_name {
        let mut seen = indices.clone();
        seen.sort_unstable();
        seen.dedup();
        if seen.len() == indices.len() {
            return Ok(sorted.into_iter().zip(indices).collect());
        }
    }
    if sorted.len() > rig.len() {
        return Err(parse_err(
            "detections",
            "(camera folders)",
            format!(
                "{} camera folders but the calibration has {} cameras",
                sorted.len(),
                rig.len()
            ),
        ));
    }
    Ok(sorted
        .into_iter()
        .enumerate()
        .map(|(i, f)| (f, i))
        .collect())
}

/// One camera's OpenPose-style detection files as the caller read them from its folder.
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct CameraFiles {
    /// The rig camera this folder belongs to (see [`match_camera_folders`]).
    pub camera: CameraIndex,
    /// `(file name or path, raw bytes)` per file, in any order; the frame number is read from the
    /// name's last path component ([`frame_number_of`]).
    pub files: Vec<(String, Vec<u8>)>,
}

/// How [`assemble_openpose`] put the cameras' files together into frames.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum FramePairing {
    /// By the frame number in each file name: a missing file is a missing view of that frame only.
    ByFrameNumber,
    /// No file name carries a frame number: the `k`-th file (sorted by name) of every camera is
    /// frame `k`, so a missing file shifts that camera's later frames (reported as a warning).
    BySortedOrder,
}

/// The frames of an OpenPose-style folder set, and what was left out.
#[derive(Debug, Clone, PartialEq)]
pub struct OpenPoseImport {
    /// One frame per frame number seen in any camera, in order; its stamp is
    /// `(number − first number) / rate`.
    pub frames: Vec<Frame2>,
    pub pairing: FramePairing,
    /// One line per file left out (not UTF-8, malformed JSON, no or a repeated frame number) and
    /// per pairing caveat, naming the file: for the caller to show.
    pub warnings: Vec<String>,
}

/// The frame number in a detection file's name: the last run of ASCII digits before `_keypoints`
/// (OpenPose writes `<stem>_<12-digit frame>_keypoints.json`), or, without `_keypoints`, the last run
/// of digits in the name without its extension (Pose2Sim and others: `cam01_000042.json`). `None`
/// when there is no digit (or the number does not fit in a `u64`). Only the last path component
/// counts, so digits in folder names are ignored.
pub fn frame_number_of(file_name: &str) -> Option<u64> {
    let base = file_name.rsplit(['/', '\\']).next().unwrap_or(file_name);
    let stem = match base.rfind("_keypoints") {
        Some(i) => &base[..i],
        None => base.rsplit_once('.').map_or(base, |(stem, _)| stem),
    };
    let end = stem.rfind(|c: char| c.is_ascii_digit())? + 1;
    let start = stem[..end]
        .rfind(|c: char| !c.is_ascii_digit())
        .map_or(0, |i| i + 1);
    stem[start..end].parse().ok()
}

/// Assembles OpenPose-style per-camera files into time-aligned frames — the pure part of reading an
/// OpenPose folder set (the caller lists the folders and reads the files).
///
/// Frames are paired by the frame number in each file name ([`frame_number_of`]), so a deleted file
/// is a missing view in that frame only (counted in `stats.missing_views`), never a shift of the
/// camera's later frames. Nothing in one file is fatal: a file that is not UTF-8, is not valid
/// OpenPose JSON, has no frame number while others do, or repeats another file's frame number in the
/// same camera is left out, counted in `stats.skipped_records` and named in the warnings. Only when no
/// file carries a frame number are files paired by sorted name, with a warning. With several people
/// in a view the operator is chosen by [`OperatorSelector`] (frames in order).
///
/// Errors only on a rate that is not a positive finite number.
pub fn assemble_openpose(
    cameras: &[CameraFiles],
    format: KeypointFormat,
    rate_hz: f64,
    stats: &mut ImportStats,
) -> Result<OpenPoseImport> {
    let names: Vec<(CameraIndex, Vec<String>)> = cameras
        .iter()
        .map(|c| (c.camera, c.files.iter().map(|(n, _)| n.clone()).collect()))
        .collect();
    let contents: BTreeMap<(CameraIndex, &str), &[u8]> = cameras
        .iter()
        .flat_map(|c| {
            c.files
                .iter()
                .map(move |(n, b)| ((c.camera, n.as_str()), b.as_slice()))
        })
        .collect();
    let mut plan = OpenPosePlan::new(&names, format, rate_hz, stats)?;
    let mut frames = Vec::with_capacity(plan.frame_count());
    for k in 0..plan.frame_count() {
        let frame = plan.frame(
            k,
            |camera, name| {
                contents
                    .get(&(camera, name))
                    .map(|b| b.to_vec())
                    .ok_or(NotGiven)
            },
            stats,
        );
        frames.extend(frame);
    }
    Ok(OpenPoseImport {
        frames,
        pairing: plan.pairing,
        warnings: plan.warnings,
    })
}

/// The pairing of an OpenPose-style folder set, made from the file names alone, so the frames can
/// then be read one at a time ([`OpenPosePlan::frame`]): what `ergocell triangulate` streams a long
/// recording with (memory grows with the number of file names, not with their contents).
/// [`assemble_openpose`] is this plan run over files already in memory.
#[derive(Debug, Clone)]
pub struct OpenPosePlan {
    /// How the files were paired.
    pub pairing: FramePairing,
    /// One line per file left out and per pairing caveat, naming the file (grows as frames are
    /// read: a file that cannot be read or parsed is named when its frame is assembled).
    pub warnings: Vec<String>,
    format: KeypointFormat,
    rate_hz: f64,
    /// camera → frame number → the one file of that frame (`None`: that number was repeated)
    by_camera: BTreeMap<CameraIndex, BTreeMap<u64, Option<String>>>,
    numbers: Vec<u64>,
    selector: OperatorSelector,
}

impl OpenPosePlan {
    /// Pairs the cameras' file names (see [`assemble_openpose`] for the rules). Errors only on a
    /// rate that is not a positive finite number.
    pub fn new(
        cameras: &[(CameraIndex, Vec<String>)],
        format: KeypointFormat,
        rate_hz: f64,
        stats: &mut ImportStats,
    ) -> Result<Self> {
        if !(rate_hz.is_finite() && rate_hz > 0.0) {
            return Err(parse_err(
                "detections",
                "rate_hz",
                format!("{rate_hz} is not a positive frame rate"),
            ));
        }
        let mut warnings = Vec::new();
        let any_numbered = cameras
            .iter()
            .flat_map(|c| &c.1)
            .any(|name| frame_number_of(name).is_some());
        let pairing = if any_numbered || cameras.iter().all(|c| c.1.is_empty()) {
            FramePairing::ByFrameNumber
        } else {
            warnings.push(
                "no frame numbers in the detection file names: frames paired by sorted file order, \
                 so a missing file shifts that camera's later frames"
                    .to_owned(),
            );
            FramePairing::BySortedOrder
        };
        let mut by_camera: BTreeMap<CameraIndex, BTreeMap<u64, Option<String>>> = BTreeMap::new();
        for (camera, names) in cameras {
            let slots = by_camera.entry(*camera).or_default();
            let mut files: Vec<&String> = names.iter().collect();
            files.sort();
            for (k, file) in files.into_iter().enumerate() {
                let number = match pairing {
                    FramePairing::BySortedOrder => Some(k as u64),
                    FramePairing::ByFrameNumber => frame_number_of(file),
                };
                let Some(number) = number else {
                    stats.skipped_records += 1;
                    warnings.push(format!("skipping {file}: no frame number in the file name"));
                    continue;
                };
                match slots.get_mut(&number) {
                    None => {
                        slots.insert(number, Some(file.clone()));
                    }
                    Some(slot) => {
                        // Two files claim one frame of one camera: which one is right is a guess.
                        if let Some(first) = slot.take() {
                            stats.skipped_records += 1;
                            warnings.push(format!(
                                "skipping {first}: another file of this camera has frame number {number}"
                            ));
                        }
                        stats.skipped_records += 1;
                        warnings.push(format!(
                            "skipping {file}: another file of this camera has frame number {number}"
                        ));
                    }
                }
            }
        }
        let numbers: std::collections::BTreeSet<u64> = by_camera
            .values()
            .flat_map(|slots| slots.keys().copied())
            .collect();
        Ok(Self {
            pairing,
            warnings,
            format,
            rate_hz,
            by_camera,
            numbers: numbers.into_iter().collect(),
            selector: OperatorSelector::default(),
        })
    }

    /// Number of frames (one per frame number seen in any camera).
    pub fn frame_count(&self) -> usize {
        self.numbers.len()
    }

    /// Assembles frame `k` (frames in order: the operator selection follows them), reading each of
    /// its files with `read(camera, name)`; a file that cannot be read or parsed is left out,
    /// counted and named in [`Self::warnings`]. `None` for `k` beyond the last frame.
    pub fn frame<E: std::fmt::Display>(
        &mut self,
        k: usize,
        mut read: impl FnMut(CameraIndex, &str) -> std::result::Result<Vec<u8>, E>,
        stats: &mut ImportStats,
    ) -> Option<Frame2> {
        let number = *self.numbers.get(k)?;
        let first = self.numbers.first().copied().unwrap_or(0);
        let stamp_nanos = ((number - first) as f64 / self.rate_hz * 1e9).round() as i64;
        let mut views = Vec::new();
        let mut several = false;
        for (&camera, slots) in &self.by_camera {
            let Some(slot) = slots.get(&number) else {
                stats.missing_views += 1;
                continue;
            };
            // A repeated frame number: already counted and named.
            let Some(name) = slot else { continue };
            let bytes = match read(camera, name) {
                Ok(b) => b,
                Err(e) => {
                    stats.skipped_records += 1;
                    self.warnings.push(format!("skipping {name}: {e}"));
                    continue;
                }
            };
            let text = match std::str::from_utf8(&bytes) {
                Ok(t) => t,
                Err(e) => {
                    stats.skipped_records += 1;
                    self.warnings.push(format!(
                        "skipping {name}: not UTF-8 text (invalid byte at offset {})",
                        e.valid_up_to()
                    ));
                    continue;
                }
            };
            let people = match parse_openpose_frame(text, name, self.format, stats) {
                Ok(p) => p,
                Err(e) => {
                    stats.skipped_records += 1;
                    self.warnings.push(format!("skipping {e}"));
                    continue;
                }
            };
            several |= people.len() > 1;
            if let Some(i) = self.selector.select(camera, &people) {
                views.push(View2::new(camera, stamp_nanos, people[i].keypoints));
            }
        }
        if several {
            stats.multi_person_frames += 1;
        }
        Some(Frame2 { stamp_nanos, views })
    }
}

/// The columns of caliscope's `xy_*.csv` that ergocell reads (others, e.g. `frame_index` or
/// `obj_loc_x`, are ignored). A file without one of them is an error naming it.
pub const CALISCOPE_REQUIRED_COLUMNS: [&str; 6] = [
    "sync_index",
    "port",
    "frame_time",
    "point_id",
    "img_loc_x",
    "img_loc_y",
];

/// Parses caliscope's long `xy_*.csv` into one [`Frame2`] per `sync_index` (in order). `port` N maps
/// to camera `cam_N` of the rig. See [`parse_caliscope_xy_bytes`].
pub fn parse_caliscope_xy(
    text: &str,
    source_name: &str,
    rig: &CameraRig,
    stats: &mut ImportStats,
) -> Result<Vec<Frame2>> {
    parse_caliscope_xy_bytes(text.as_bytes(), source_name, rig, stats)
}

/// Parses caliscope's long `xy_*.csv` from its raw bytes (so one non-UTF-8 row does not lose the
/// file). A missing required column ([`CALISCOPE_REQUIRED_COLUMNS`]) is an error naming it; after
/// that nothing is fatal: a row that cannot be used — a non-numeric or non-UTF-8 cell, a wrong number
/// of fields, an unknown port or point id, a non-finite time — is skipped and counted in
/// `stats.skipped_records`; an empty or non-finite pixel is an invalid keypoint; a keypoint given
/// twice for one camera and sync index is left out (`stats.duplicate_keypoints`: which row is the
/// operator's cannot be told). Rows are independent, so a skipped row never shifts another. The frame's stamp is the earliest camera time of that sync
/// index.
pub fn parse_caliscope_xy_bytes(
    bytes: &[u8],
    source_name: &str,
    rig: &CameraRig,
    stats: &mut ImportStats,
) -> Result<Vec<Frame2>> {
    let mut rows = CaliscopeRows::new(bytes, source_name)?;
    let mut frames: BTreeMap<i64, BTreeMap<CameraIndex, Assembling>> = BTreeMap::new();
    while let Some(row) = rows.next_row(rig, stats) {
        add_row(frames.entry(row.sync_index).or_default(), &row, stats);
    }
    Ok(frames.into_values().map(frame_of).collect())
}

/// One usable row of caliscope's `xy_*.csv`.
struct CaliscopeRow {
    sync_index: i64,
    camera: CameraIndex,
    stamp_nanos: i64,
    landmark: ergocell_skeleton::Landmark,
    /// `None`: an empty pixel cell (not seen).
    pixel: Option<(f64, f64)>,
}

/// The rows of caliscope's `xy_*.csv`, checked and parsed one at a time (the shared part of the
/// in-memory and the streaming reader).
struct CaliscopeRows<R: std::io::Read> {
    reader: csv::Reader<R>,
    columns: [usize; CALISCOPE_REQUIRED_COLUMNS.len()],
    record: csv::ByteRecord,
    done: bool,
    /// The rig camera of each `port` looked up so far (a name lookup per row was a string
    /// allocation per keypoint).
    ports: Vec<(i64, Option<CameraIndex>)>,
}

impl<R: std::io::Read> CaliscopeRows<R> {
    /// Reads the header; a missing required column is an error naming it.
    fn new(reader: R, source_name: &str) -> Result<Self> {
        // no trimming by the reader: the header names and the cells read are trimmed where they
        // are used (`str::trim` removes all that the reader's ASCII trim would, and more), and
        // trimming every field of every record was ≈ 7 % of `ergocell triangulate`
        let mut reader = csv::ReaderBuilder::new()
            .has_headers(true)
            .from_reader(reader);
        let headers = reader
            .byte_headers()
            .map_err(|e| parse_err(source_name, "(header)", e))?
            .clone();
        let header_list = headers
            .iter()
            .map(|h| String::from_utf8_lossy(h.trim_ascii()).into_owned())
            .collect::<Vec<_>>()
            .join(", ");
        let mut columns = [0usize; CALISCOPE_REQUIRED_COLUMNS.len()];
        for (slot, name) in columns.iter_mut().zip(CALISCOPE_REQUIRED_COLUMNS) {
            *slot = headers
                .iter()
                .position(|h| h.trim_ascii() == name.as_bytes())
                .ok_or_else(|| {
                    parse_err(
                        source_name,
                        name,
                        format!(
                            "required column `{name}` is missing (the header has: {header_list})"
                        ),
                    )
                })?;
        }
        Ok(Self {
            reader,
            columns,
            record: csv::ByteRecord::new(),
            done: false,
            ports: Vec::new(),
        })
    }

    /// The rig's camera `cam_{port}`, if it has one.
    fn camera_of_port(&mut self, rig: &CameraRig, port: i64) -> Option<CameraIndex> {
        if let Some(&(_, camera)) = self.ports.iter().find(|(p, _)| *p == port) {
            return camera;
        }
        let camera = rig.index_of_name(&format!("cam_{port}"));
        // a file of garbage ports must not grow this without bound
        if self.ports.len() < 256 {
            self.ports.push((port, camera));
        }
        camera
    }

    /// The next usable row; rows that cannot be used are counted in `stats` and skipped.
    fn next_row(&mut self, rig: &CameraRig, stats: &mut ImportStats) -> Option<CaliscopeRow> {
        let [c_sync, c_port, c_time, c_point, c_x, c_y] = self.columns;
        while !self.done {
            match self.reader.read_byte_record(&mut self.record) {
                Ok(true) => {}
                Ok(false) => {
                    self.done = true;
                    break;
                }
                Err(e) => {
                    // A row with the wrong number of fields: that row only. Anything else (the
                    // reader cannot continue) ends the file here, keeping what was read.
                    stats.skipped_records += 1;
                    if matches!(e.kind(), csv::ErrorKind::UnequalLengths { .. }) {
                        continue;
                    }
                    self.done = true;
                    break;
                }
            }
            let record = &self.record;
            let cell = |c: usize| {
                record
                    .get(c)
                    .and_then(|b| std::str::from_utf8(b).ok())
                    .map(str::trim)
            };
            let int = |c: usize| cell(c).and_then(|t| t.parse::<i64>().ok());
            let float = |c: usize| cell(c).and_then(|t| t.parse::<f64>().ok());
            // An empty pixel cell is "not seen"; any other cell that does not parse spoils the row.
            let pixel = |c: usize| match cell(c) {
                Some("") => Some(None),
                Some(t) => t.parse::<f64>().ok().map(Some),
                None => None,
            };
            let (Some(sync_index), Some(port), Some(frame_time), Some(point_id), Some(u), Some(v)) = (
                int(c_sync),
                int(c_port),
                float(c_time),
                int(c_point),
                pixel(c_x),
                pixel(c_y),
            ) else {
                stats.skipped_records += 1;
                continue;
            };
            let Some(camera) = self.camera_of_port(rig, port) else {
                stats.unknown_camera_records += 1;
                stats.first_unknown_port.get_or_insert(port);
                continue;
            };
            let Some(landmark) = usize::try_from(point_id)
                .ok()
                .and_then(ergocell_skeleton::Landmark::from_index)
            else {
                stats.skipped_records += 1;
                continue;
            };
            if !frame_time.is_finite() {
                stats.skipped_records += 1;
                continue;
            }
            return Some(CaliscopeRow {
                sync_index,
                camera,
                stamp_nanos: (frame_time * 1e9).round() as i64,
                landmark,
                pixel: u.zip(v),
            });
        }
        None
    }
}

/// Adds one row to its frame's views.
/// One camera's view of a sync index being assembled, with which landmarks rows have given.
struct Assembling {
    view: View2,
    /// Bit `i`: a row gave landmark `i` (seen or not).
    given: u64,
}

fn add_row(
    views: &mut BTreeMap<CameraIndex, Assembling>,
    row: &CaliscopeRow,
    stats: &mut ImportStats,
) {
    let a = views.entry(row.camera).or_insert_with(|| Assembling {
        view: View2::empty(row.camera, row.stamp_nanos),
        given: 0,
    });
    let bit = 1_u64 << row.landmark.index();
    if a.given & bit != 0 {
        // The same keypoint twice for one camera and sync index (two detections, or rows merged
        // from two files): which is the operator's cannot be told, so neither is used.
        if a.view.get(row.landmark).is_some() {
            a.view.set(row.landmark, None);
        }
        stats.duplicate_keypoints += 1;
        return;
    }
    a.given |= bit;
    match row.pixel {
        Some((u, v)) => match Keypoint2::new(u, v, 1.0) {
            Ok(k) => a.view.set(row.landmark, Some(k)),
            Err(_) => stats.invalid_keypoints += 1,
        },
        None => stats.invalid_keypoints += 1,
    }
}

/// A frame from its views; its stamp is the earliest camera time.
fn frame_of(views: BTreeMap<CameraIndex, Assembling>) -> Frame2 {
    let views: Vec<View2> = views.into_values().map(|a| a.view).collect();
    let stamp_nanos = views.iter().map(|v| v.stamp_nanos).min().unwrap_or(0);
    Frame2 { stamp_nanos, views }
}

/// What [`scan_caliscope_xy`] found: enough to decide how to read the file and to announce how
/// many frames it holds (a TRC header states the count before the first frame).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct CaliscopeScan {
    /// Distinct `sync_index` values (the frames [`parse_caliscope_xy_bytes`] would return).
    pub frames: usize,
    /// The rows' `sync_index` never decreases, so [`CaliscopeStream`] reads the file in one pass
    /// with the same result as [`parse_caliscope_xy_bytes`]. (caliscope writes it so.)
    pub sorted: bool,
}

/// A first, cheap pass over caliscope's `xy_*.csv`: only the `sync_index` column is parsed.
/// Errors as [`parse_caliscope_xy_bytes`] does on a missing column.
pub fn scan_caliscope_xy<R: std::io::Read>(reader: R, source_name: &str) -> Result<CaliscopeScan> {
    let mut rows = CaliscopeRows::new(reader, source_name)?;
    let c_sync = rows.columns[0];
    let (mut frames, mut sorted, mut last) = (0usize, true, None::<i64>);
    let mut seen_unsorted = std::collections::BTreeSet::new();
    loop {
        match rows.reader.read_byte_record(&mut rows.record) {
            Ok(true) => {}
            Err(e) if matches!(e.kind(), csv::ErrorKind::UnequalLengths { .. }) => continue,
            Ok(false) | Err(_) => break,
        }
        let Some(sync) = rows
            .record
            .get(c_sync)
            .and_then(|b| std::str::from_utf8(b).ok())
            .and_then(|t| t.trim().parse::<i64>().ok())
        else {
            continue;
        };
        if sorted {
            match last {
                Some(l) if sync < l => {
                    // from here on count distinct values exactly (an unsorted file is read whole
                    // anyway)
                    sorted = false;
                    seen_unsorted.insert(sync);
                }
                Some(l) if sync == l => {}
                _ => {
                    frames += 1;
                    last = Some(sync);
                    seen_unsorted.insert(sync);
                }
            }
        } else {
            seen_unsorted.insert(sync);
        }
    }
    if !sorted {
        frames = seen_unsorted.len();
    }
    Ok(CaliscopeScan { frames, sorted })
}

/// caliscope's `xy_*.csv` read as a stream of frames, for a file whose `sync_index` never decreases
/// ([`scan_caliscope_xy`]): one frame is held at a time, so memory does not grow with the length.
/// For such a file the frames equal [`parse_caliscope_xy_bytes`]'s; a row whose `sync_index` is
/// below the frame being assembled (the file was not sorted after all) is skipped and counted in
/// [`CaliscopeStream::stats`] as a skipped record.
pub struct CaliscopeStream<'r, R: std::io::Read> {
    rows: CaliscopeRows<R>,
    rig: &'r CameraRig,
    stats: ImportStats,
    current: Option<(i64, BTreeMap<CameraIndex, Assembling>)>,
}

impl<'r, R: std::io::Read> CaliscopeStream<'r, R> {
    /// Reads the header; a missing required column is an error naming it.
    pub fn new(reader: R, source_name: &str, rig: &'r CameraRig) -> Result<Self> {
        Ok(Self {
            rows: CaliscopeRows::new(reader, source_name)?,
            rig,
            stats: ImportStats::default(),
            current: None,
        })
    }

    /// What was left out so far.
    pub fn stats(&self) -> ImportStats {
        self.stats
    }
}

impl<R: std::io::Read> Iterator for CaliscopeStream<'_, R> {
    type Item = Frame2;

    fn next(&mut self) -> Option<Frame2> {
        while let Some(row) = self.rows.next_row(self.rig, &mut self.stats) {
            match &mut self.current {
                Some((sync, views)) if *sync == row.sync_index => {
                    add_row(views, &row, &mut self.stats);
                }
                Some((sync, _)) if row.sync_index < *sync => self.stats.skipped_records += 1,
                _ => {
                    let mut views = BTreeMap::new();
                    add_row(&mut views, &row, &mut self.stats);
                    let done = self.current.replace((row.sync_index, views));
                    if let Some((_, views)) = done {
                        return Some(frame_of(views));
                    }
                }
            }
        }
        self.current.take().map(|(_, views)| frame_of(views))
    }
}

/// A file the frame names that the caller did not give (in-memory import).
#[derive(Debug)]
struct NotGiven;

impl std::fmt::Display for NotGiven {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str("not given")
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use ergocell_skeleton::Landmark;

    fn body25_person(offset: f64, conf: f64) -> String {
        let mut v = Vec::new();
        for i in 0..25 {
            v.push(format!("{}", 100.0 + offset + f64::from(i)));
            v.push(format!("{}", 200.0 + f64::from(i)));
            v.push(format!("{conf}"));
        }
        format!("{{\"pose_keypoints_2d\": [{}]}}", v.join(","))
    }

    #[test]
    fn openpose_body25_maps_to_blazepose_order() {
        let text = format!(
            "{{\"version\": 1.3, \"people\": [{}]}}",
            body25_person(0.0, 0.9)
        );
        let mut stats = ImportStats::default();
        let people =
            parse_openpose_frame(&text, "f.json", KeypointFormat::Body25, &mut stats).unwrap();
        assert_eq!(people.len(), 1);
        // BODY_25 index 4 is the right wrist: x = 104.
        let k = people[0].keypoints[Landmark::RightWrist.index()].unwrap();
        assert_eq!(k.pixel(), Point2::new(104.0, 204.0));
        assert!(people[0].keypoints[Landmark::LeftPinky.index()].is_none());
    }

    #[test]
    fn wrong_length_and_bad_confidence_are_reported() {
        let mut stats = ImportStats::default();
        let err = parse_openpose_frame(
            r#"{"people":[{"pose_keypoints_2d":[1,2,3]}]}"#,
            "f.json",
            KeypointFormat::Coco17,
            &mut stats,
        )
        .unwrap_err()
        .to_string();
        assert!(
            err.contains("f.json") && err.contains("people[0].pose_keypoints_2d"),
            "{err}"
        );
        let text = format!("{{\"people\": [{}]}}", body25_person(0.0, 1.5));
        let people =
            parse_openpose_frame(&text, "f.json", KeypointFormat::Body25, &mut stats).unwrap();
        assert_eq!(people[0].keypoints.iter().flatten().count(), 0);
        // BODY_25 has 21 points with a BlazePose equivalent (not: neck, mid-hip, small toes)
        assert_eq!(stats.invalid_keypoints, 21);
    }

    #[test]
    fn openpose_frames_paired_by_frame_number_read_from_the_file_name() {
        for (name, n) in [
            ("video_000000000042_keypoints.json", Some(42)),
            ("cam3/run2_000000000007_keypoints.json", Some(7)),
            (
                "C:\\data\\cam_10_json\\x_000000000011_keypoints.JSON",
                Some(11),
            ),
            ("cam01_000123.json", Some(123)),
            ("cam01.000124.json", Some(124)),
            ("frame17_keypoints.json", Some(17)),
            ("cam01_json/left.json", None),
            ("keypoints.json", None),
            ("f_99999999999999999999999_keypoints.json", None),
        ] {
            assert_eq!(frame_number_of(name), n, "{name}");
        }
    }

    fn coco_file(name: &str, x: f64) -> (String, Vec<u8>) {
        let values: Vec<String> = (0..17)
            .flat_map(|i| [format!("{}", x + f64::from(i)), "50".into(), "0.9".into()])
            .collect();
        let json = format!(
            "{{\"people\":[{{\"pose_keypoints_2d\":[{}]}}]}}",
            values.join(",")
        );
        (name.to_owned(), json.into_bytes())
    }

    fn nose_x(frame: &Frame2, camera: CameraIndex) -> Option<f64> {
        let view = frame.views.iter().find(|v| v.camera == camera)?;
        view.get(Landmark::Nose).map(|k| k.pixel().x)
    }

    #[test]
    fn openpose_frames_paired_by_frame_number_with_missing_repeated_and_unnumbered_files() {
        let cameras = [
            CameraFiles {
                camera: 0,
                files: vec![
                    coco_file("a_000000000003_keypoints.json", 3.0),
                    coco_file("a_000000000001_keypoints.json", 1.0),
                    coco_file("a_000000000002_keypoints.json", 2.0),
                ],
            },
            CameraFiles {
                camera: 1,
                // frame 2 deleted, frame 3 written twice, one file without a number
                files: vec![
                    coco_file("b_000000000001_keypoints.json", 101.0),
                    coco_file("b_000000000003_keypoints.json", 103.0),
                    coco_file("b2_000000000003_keypoints.json", 203.0),
                    coco_file("notes.json", 999.0),
                ],
            },
        ];
        let mut stats = ImportStats::default();
        let import = assemble_openpose(&cameras, KeypointFormat::Coco17, 10.0, &mut stats).unwrap();
        assert_eq!(import.pairing, FramePairing::ByFrameNumber);
        let f = &import.frames;
        assert_eq!(f.len(), 3);
        assert_eq!(
            f.iter().map(|f| f.stamp_nanos).collect::<Vec<_>>(),
            [0, 100_000_000, 200_000_000]
        );
        assert_eq!(
            (nose_x(&f[0], 0), nose_x(&f[0], 1)),
            (Some(1.0), Some(101.0))
        );
        assert_eq!((nose_x(&f[1], 0), nose_x(&f[1], 1)), (Some(2.0), None));
        assert_eq!((nose_x(&f[2], 0), nose_x(&f[2], 1)), (Some(3.0), None));
        assert_eq!(stats.missing_views, 1, "frame 2 of camera 1");
        assert_eq!(
            stats.skipped_records, 3,
            "both frame-3 files and notes.json"
        );
        assert_eq!(import.warnings.len(), 3, "{:?}", import.warnings);
        assert!(import.warnings.iter().any(|w| w.contains("notes.json")));
        assert!(import
            .warnings
            .iter()
            .any(|w| w.contains("b2_000000000003")));

        // No numbers anywhere: the old sorted-order pairing, said out loud.
        let plain = [CameraFiles {
            camera: 0,
            files: vec![coco_file("b.json", 2.0), coco_file("a.json", 1.0)],
        }];
        let import = assemble_openpose(&plain, KeypointFormat::Coco17, 10.0, &mut stats).unwrap();
        assert_eq!(import.pairing, FramePairing::BySortedOrder);
        assert_eq!(nose_x(&import.frames[0], 0), Some(1.0));
        assert!(import.warnings[0].contains("sorted file order"));
        assert!(assemble_openpose(&plain, KeypointFormat::Coco17, 0.0, &mut stats).is_err());
        assert!(
            assemble_openpose(&[], KeypointFormat::Coco17, 30.0, &mut stats)
                .unwrap()
                .frames
                .is_empty()
        );
    }

    #[test]
    fn operator_selection_is_consistent_over_time() {
        let mut stats = ImportStats::default();
        let text = format!(
            "{{\"people\": [{}, {}]}}",
            body25_person(0.0, 0.6),
            body25_person(500.0, 0.9)
        );
        let people =
            parse_openpose_frame(&text, "f.json", KeypointFormat::Body25, &mut stats).unwrap();
        let mut sel = OperatorSelector::default();
        assert_eq!(
            sel.select(0, &people),
            Some(1),
            "first frame: highest confidence"
        );
        // Next frame the bystander (near x=100) becomes slightly more confident; the operator stays.
        let text = format!(
            "{{\"people\": [{}, {}]}}",
            body25_person(5.0, 0.95),
            body25_person(505.0, 0.8)
        );
        let people =
            parse_openpose_frame(&text, "f.json", KeypointFormat::Body25, &mut stats).unwrap();
        assert_eq!(
            sel.select(0, &people),
            Some(1),
            "then: nearest to the last position"
        );
        assert_eq!(sel.select(0, &[]), None);
    }
}
