//! The importers against real data (caliscope's 4-camera MediaPipe recording,
//! `../shared/data/caliscope-4cam`, see its SOURCE.md), each test named after the issue row it
//! guards: one bad record is skipped and counted, never fatal and never shifting the rest; OpenPose
//! frames are paired by the frame number in the file name; a missing CSV column and insane
//! calibration values are errors naming what is wrong.

#![allow(clippy::unwrap_used, clippy::expect_used)] // test helpers outside #[test] fns

use std::collections::BTreeMap;
use std::fmt::Write as _;
use std::path::PathBuf;

use ergocell_formats::import::{
    assemble_openpose, parse_caliscope_xy, parse_caliscope_xy_bytes, CameraFiles, FramePairing,
};
use ergocell_formats::rig_file::parse_rig;
use ergocell_perception::detections::ImportStats;
use ergocell_perception::{
    CameraRig, Frame2, FusionEngine, FusionMethod, KeypointFormat, PerceptionError, View2,
};

fn data_dir() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../shared/data/caliscope-4cam")
}

fn read(name: &str) -> String {
    let path = data_dir().join(name);
    std::fs::read_to_string(&path).unwrap_or_else(|e| {
        panic!(
            "{}: {e} (the shared data must sit beside the repo)",
            path.display()
        )
    })
}

fn rig() -> CameraRig {
    parse_rig(&read("config.toml"), "config.toml").unwrap().0
}

fn caliscope(text: &str) -> (Vec<Frame2>, ImportStats) {
    let mut stats = ImportStats::default();
    let frames = parse_caliscope_xy(text, "xy_pose33.csv", &rig(), &mut stats).unwrap();
    (frames, stats)
}

/// The view of `camera` in a frame, if any.
fn view(frame: &Frame2, camera: usize) -> Option<&View2> {
    frame.views.iter().find(|v| v.camera == camera)
}

/// The recording's rows as OpenPose BlazePose-33 JSON files, one folder per camera and one file per
/// sync index, named as OpenPose names them (`<stem>_<12-digit frame>_keypoints.json`).
fn openpose_files() -> Vec<CameraFiles> {
    let text = read("xy_pose33.csv");
    let mut reader = csv::Reader::from_reader(text.as_bytes());
    // (port, sync) → 33 × (x, y, c)
    let mut people: BTreeMap<(usize, u64), [f64; 99]> = BTreeMap::new();
    for row in reader.records() {
        let row = row.unwrap();
        let sync: u64 = row[0].parse().unwrap();
        let port: usize = row[1].parse().unwrap();
        let point: usize = row[4].parse().unwrap();
        let flat = people.entry((port, sync)).or_insert([0.0; 99]);
        flat[3 * point] = row[5].parse().unwrap();
        flat[3 * point + 1] = row[6].parse().unwrap();
        flat[3 * point + 2] = 1.0;
    }
    let mut cameras: Vec<CameraFiles> = (0..4)
        .map(|camera| CameraFiles {
            camera,
            files: Vec::new(),
        })
        .collect();
    for ((port, sync), flat) in people {
        let mut values = String::new();
        for (i, v) in flat.iter().enumerate() {
            if i > 0 {
                values.push(',');
            }
            let _ = write!(values, "{v:?}");
        }
        let json = format!(
            "{{\"version\":1.3,\"people\":[{{\"person_id\":[-1],\"pose_keypoints_2d\":[{values}]}}]}}"
        );
        cameras[port].files.push((
            format!("cam_{port}_json/recording_1_{sync:012}_keypoints.json"),
            json.into_bytes(),
        ));
    }
    // The folder walk's order is not to be relied on.
    for c in &mut cameras {
        c.files.reverse();
    }
    cameras
}

fn assemble(cameras: &[CameraFiles]) -> (Vec<Frame2>, ImportStats, Vec<String>) {
    let mut stats = ImportStats::default();
    let import = assemble_openpose(cameras, KeypointFormat::BlazePose33, 24.0, &mut stats).unwrap();
    assert_eq!(import.pairing, FramePairing::ByFrameNumber);
    (import.frames, stats, import.warnings)
}

/// One frame's views' keypoint pixels, by camera.
type FramePixels = BTreeMap<usize, Vec<Option<(f64, f64)>>>;

/// Every frame's views' keypoint pixels, by camera.
fn keypoints(frames: &[Frame2]) -> Vec<FramePixels> {
    frames
        .iter()
        .map(|f| {
            f.views
                .iter()
                .map(|v| {
                    let k = v
                        .keypoints()
                        .iter()
                        .map(|k| k.map(|k| (k.pixel().x, k.pixel().y)))
                        .collect();
                    (v.camera, k)
                })
                .collect()
        })
        .collect()
}

#[test]
fn openpose_frames_paired_by_frame_number_a_deleted_file_is_one_missing_view() {
    if ergocell_testdata::skip_without("data/caliscope-4cam") {
        return;
    }
    let cameras = openpose_files();
    let (full, stats, warnings) = assemble(&cameras);
    assert!(warnings.is_empty(), "{warnings:?}");
    // The same detections as caliscope's CSV, frame for frame and view for view.
    let (reference, _) = caliscope(&read("xy_pose33.csv"));
    assert_eq!(full.len(), 267);
    assert_eq!(keypoints(&full), keypoints(&reference));
    // caliscope has 1062 of the 1068 (frame, camera) slots: the others are missing views.
    assert_eq!(stats.missing_views, 4 * 267 - 1062);
    assert_eq!(stats.skipped_records, 0);
    assert_eq!(
        full[100].stamp_nanos,
        (100.0 / 24.0 * 1e9_f64).round() as i64
    );

    // Delete camera 1's file of frame 10: only frame 10 loses camera 1.
    let mut deleted = cameras.clone();
    let before = deleted[1].files.len();
    deleted[1]
        .files
        .retain(|(name, _)| !name.ends_with("_000000000010_keypoints.json"));
    assert_eq!(deleted[1].files.len(), before - 1);
    let (frames, stats2, _) = assemble(&deleted);
    assert_eq!(frames.len(), full.len());
    assert_eq!(stats2.missing_views, stats.missing_views + 1);
    assert!(view(&full[10], 1).is_some());
    assert!(view(&frames[10], 1).is_none(), "frame 10 has no camera 1");
    let (mut a, mut b) = (keypoints(&full), keypoints(&frames));
    a[10].remove(&1);
    b[10].remove(&1);
    assert_eq!(
        a, b,
        "every other view, before and after frame 10, is unchanged"
    );
    for (x, y) in full.iter().zip(&frames) {
        assert_eq!(x.stamp_nanos, y.stamp_nanos);
    }

    // The first frame of every camera deleted: frame numbers still give the stamps.
    let mut no_first = cameras;
    for c in &mut no_first {
        c.files
            .retain(|(name, _)| !name.ends_with("_000000000000_keypoints.json"));
    }
    let (frames, _, _) = assemble(&no_first);
    assert_eq!(frames.len(), 266);
    assert_eq!(keypoints(&frames[..]), keypoints(&full[1..]));
    assert_eq!(frames[0].stamp_nanos, 0);
}

#[test]
fn one_non_utf8_file_is_skipped_and_counted_not_fatal() {
    if ergocell_testdata::skip_without("data/caliscope-4cam") {
        return;
    }
    let mut cameras = openpose_files();
    let (full, stats, _) = assemble(&cameras);
    let file = cameras[2]
        .files
        .iter_mut()
        .find(|(name, _)| name.ends_with("_000000000042_keypoints.json"))
        .unwrap();
    file.1.insert(20, 0xFF);
    assert!(std::str::from_utf8(&file.1).is_err());
    let (frames, stats2, warnings) = assemble(&cameras);
    assert_eq!(stats2.skipped_records, stats.skipped_records + 1);
    assert_eq!(
        stats2.missing_views, stats.missing_views,
        "a bad file is not a missing file"
    );
    assert_eq!(warnings.len(), 1);
    assert!(
        warnings[0].contains("cam_2_json/recording_1_000000000042_keypoints.json")
            && warnings[0].contains("UTF-8"),
        "{warnings:?}"
    );
    assert!(view(&frames[42], 2).is_none());
    let (mut a, mut b) = (keypoints(&full), keypoints(&frames));
    a[42].remove(&2);
    b[42].remove(&2);
    assert_eq!(a, b);
    // Malformed JSON, as before, is the same: skipped and counted.
    let file = cameras[3]
        .files
        .iter_mut()
        .find(|(name, _)| name.ends_with("_000000000043_keypoints.json"))
        .unwrap();
    file.1.truncate(30);
    let (frames, stats3, warnings) = assemble(&cameras);
    assert_eq!(stats3.skipped_records, stats.skipped_records + 2);
    assert_eq!(warnings.len(), 2);
    assert!(view(&frames[43], 3).is_none() && view(&frames[44], 3).is_some());
}

/// The recording's CSV with `cell` put into `column` of data row `row` (0-based, header excluded).
fn with_cell(text: &str, row: usize, column: &str, cell: &str) -> String {
    let mut lines: Vec<String> = text.lines().map(str::to_owned).collect();
    let c = lines[0].split(',').position(|h| h == column).unwrap();
    let mut fields: Vec<&str> = lines[row + 1].split(',').collect();
    fields[c] = cell;
    lines[row + 1] = fields.join(",");
    lines.join("\n") + "\n"
}

#[test]
fn one_non_numeric_csv_cell_is_skipped_and_counted_not_fatal() {
    if ergocell_testdata::skip_without("data/caliscope-4cam") {
        return;
    }
    let text = read("xy_pose33.csv");
    let (full, stats) = caliscope(&text);
    assert_eq!(stats, ImportStats::default(), "the recording is clean");
    // Data row 5000: which frame, camera and landmark it is.
    let row: Vec<String> = text
        .lines()
        .nth(5001)
        .unwrap()
        .split(',')
        .map(str::to_owned)
        .collect();
    let sync: usize = row[0].parse().unwrap();
    let port: usize = row[1].parse().unwrap();
    let point: usize = row[4].parse().unwrap();
    let landmark = ergocell_skeleton::Landmark::from_index(point).unwrap();
    assert!(view(&full[sync], port).unwrap().get(landmark).is_some());
    for column in [
        "img_loc_x",
        "img_loc_y",
        "sync_index",
        "port",
        "point_id",
        "frame_time",
    ] {
        let (frames, stats) = caliscope(&with_cell(&text, 5000, column, "abc"));
        assert_eq!(stats.skipped_records, 1, "{column}");
        assert_eq!(stats.invalid_keypoints, 0, "{column}");
        assert_eq!(frames.len(), full.len(), "{column}");
        assert!(
            view(&frames[sync], port).unwrap().get(landmark).is_none(),
            "{column}"
        );
        let (mut a, mut b) = (keypoints(&full), keypoints(&frames));
        a[sync].get_mut(&port).unwrap()[point] = None;
        b[sync].get_mut(&port).unwrap()[point] = None;
        assert_eq!(a, b, "{column}: nothing else changed");
    }
    // One row with a field too few, and one non-UTF-8 byte in a cell: each that row only.
    let mut lines: Vec<&str> = text.lines().collect();
    let short = lines[5001].rsplit_once(',').unwrap().0.to_owned();
    lines[5001] = &short;
    let mut bytes = (lines.join("\n") + "\n").into_bytes();
    let at = bytes.windows(2).position(|w| w == b"\n7").unwrap();
    bytes.insert(at + 1, 0xFF);
    let mut stats = ImportStats::default();
    let frames = parse_caliscope_xy_bytes(&bytes, "xy_pose33.csv", &rig(), &mut stats).unwrap();
    assert_eq!(stats.skipped_records, 2);
    assert_eq!(frames.len(), full.len());
    let observed = |f: &[Frame2]| -> usize {
        f.iter()
            .flat_map(|f| &f.views)
            .map(View2::observed_count)
            .sum()
    };
    assert_eq!(observed(&frames), observed(&full) - 2);
}

#[test]
fn caliscope_cells_padded_with_blanks_read_as_the_bare_ones_and_unknown_ports_are_skipped() {
    if ergocell_testdata::skip_without("data/caliscope-4cam") {
        return;
    }
    // the reader does not trim: every header name and cell is trimmed where it is read
    let text = read("xy_pose33.csv");
    let (bare, bare_stats) = caliscope(&text);
    let mut padded = String::new();
    for (i, line) in text.lines().enumerate() {
        let cells: Vec<String> = line
            .split(',')
            .enumerate()
            .map(|(j, c)| match (i + j) % 3 {
                0 => format!(" {c}"),
                1 => format!("{c}\t "),
                _ => c.to_string(),
            })
            .collect();
        padded.push_str(&cells.join(","));
        padded.push('\n');
    }
    // rows of a port the rig does not have, before and after the known ones
    let unknown = "0, 9,0,47389.9,0,520,193,,\n";
    let padded = format!(
        "{}{unknown}{}{unknown}",
        padded.lines().next().unwrap().to_string() + "\n",
        padded.split_once('\n').unwrap().1
    );
    let (frames, stats) = caliscope(&padded);
    assert!(!bare.is_empty());
    assert_eq!(frames, bare);
    assert_eq!(stats.invalid_keypoints, bare_stats.invalid_keypoints);
    assert_eq!(stats.skipped_records, bare_stats.skipped_records);
    assert_eq!(
        stats.unknown_camera_records,
        bare_stats.unknown_camera_records + 2
    );
    assert_eq!(stats.first_unknown_port, Some(9));
}

#[test]
fn caliscope_csv_without_img_loc_y_is_an_error_naming_the_column() {
    if ergocell_testdata::skip_without("data/caliscope-4cam") {
        return;
    }
    let text = read("xy_pose33.csv");
    let c = text
        .lines()
        .next()
        .unwrap()
        .split(',')
        .position(|h| h == "img_loc_y")
        .unwrap();
    let without: String = text
        .lines()
        .map(|line| {
            let mut fields: Vec<&str> = line.split(',').collect();
            fields.remove(c);
            fields.join(",") + "\n"
        })
        .collect();
    let mut stats = ImportStats::default();
    let err = parse_caliscope_xy(&without, "xy_pose33.csv", &rig(), &mut stats).unwrap_err();
    let text_err = err.to_string();
    assert!(
        text_err.contains("xy_pose33.csv")
            && text_err.contains("required column `img_loc_y` is missing"),
        "{text_err}"
    );
    assert!(
        matches!(err, PerceptionError::Parse { ref field, .. } if field == "img_loc_y"),
        "{err:?}"
    );
    // Each required column alike; the unused ones may go.
    for column in ["sync_index", "port", "frame_time", "point_id", "img_loc_x"] {
        let renamed = text.replacen(column, "renamed", 1);
        let err = parse_caliscope_xy(&renamed, "xy.csv", &rig(), &mut stats)
            .unwrap_err()
            .to_string();
        assert!(err.contains(&format!("`{column}`")), "{err}");
    }
    let no_frame_index = text.replacen("frame_index", "unused", 1);
    assert_eq!(caliscope(&no_frame_index).0.len(), 267);
    let err = parse_caliscope_xy("", "empty.csv", &rig(), &mut stats)
        .unwrap_err()
        .to_string();
    assert!(err.contains("`sync_index`"), "{err}");
}

/// The recording's calibration with one table's value replaced, as TOML text.
fn calibration_with(edit: impl FnOnce(&mut toml::Table)) -> String {
    let mut value: toml::Table = toml::from_str(&read("config.toml")).unwrap();
    edit(&mut value);
    toml::to_string(&value).unwrap()
}

fn set_matrix(t: &mut toml::Table, cam: &str, row: usize, col: usize, v: f64) {
    let m = t[cam]["matrix"].as_array_mut().unwrap()[row]
        .as_array_mut()
        .unwrap();
    m[col] = toml::Value::Float(v);
}

#[test]
fn calibration_values_only_checked_for_finiteness_now_range_checked() {
    if ergocell_testdata::skip_without("data/caliscope-4cam") {
        return;
    }
    for (row, col, value, field) in [
        (0, 0, 1e308, "fx = 1e308"),
        (1, 1, 1e308, "fy = 1e308"),
        (0, 0, 30.0, "fx = 30"),
        (0, 2, 1e5, "cx = 100000"),
        (1, 2, -400.0, "cy = -400"),
    ] {
        let text = calibration_with(|t| set_matrix(t, "cam_2", row, col, value));
        let err = parse_rig(&text, "config.toml").unwrap_err().to_string();
        assert!(
            err.contains("config.toml") && err.contains("cam_2") && err.contains(field),
            "{field}: {err}"
        );
    }
    // The committed reference rig passes the new checks unchanged.
    let reference = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../config/rig.toml");
    let (reference, _) = parse_rig(
        &std::fs::read_to_string(reference).unwrap(),
        "config/rig.toml",
    )
    .unwrap();
    assert_eq!(reference.len(), 6);
    // The edges of the documented ranges (1280 × 720: fx in [64, 128000], cx in [-640, 1920]) load.
    for (row, col, value) in [
        (0, 0, 64.0),
        (0, 0, 128_000.0),
        (0, 2, -640.0),
        (0, 2, 1920.0),
    ] {
        let text = calibration_with(|t| set_matrix(t, "cam_2", row, col, value));
        parse_rig(&text, "config.toml").unwrap();
    }
}

#[test]
fn a_one_camera_rig_or_coincident_cameras_are_errors_not_all_null_output() {
    if ergocell_testdata::skip_without("data/caliscope-4cam") {
        return;
    }
    // cam_1 moved onto cam_0's centre (its own orientation kept: still no baseline).
    let text = calibration_with(|t| {
        let r0 = t["cam_0"]["rotation"].clone();
        let t0 = t["cam_0"]["translation"].clone();
        let cam_1 = t["cam_1"].as_table_mut().unwrap();
        cam_1.insert("rotation".into(), r0);
        cam_1.insert("translation".into(), t0);
    });
    let err = parse_rig(&text, "config.toml").unwrap_err().to_string();
    assert!(
        err.contains("config.toml")
            && err.contains("`cam_0` and `cam_1`")
            && err.contains("0.000000 m apart"),
        "{err}"
    );
    // Half a millimetre apart is still one centre; 2 mm is a (tiny) baseline.
    for (dz, ok) in [(0.0005, false), (0.002, true)] {
        let text = calibration_with(|t| {
            let r0 = t["cam_0"]["rotation"].clone();
            let mut t0 = t["cam_0"]["translation"].as_array().unwrap().clone();
            t0[2] = toml::Value::Float(t0[2].as_float().unwrap() + dz);
            let cam_1 = t["cam_1"].as_table_mut().unwrap();
            cam_1.insert("rotation".into(), r0);
            cam_1.insert("translation".into(), toml::Value::Array(t0));
        });
        assert_eq!(parse_rig(&text, "config.toml").is_ok(), ok, "{dz} m");
    }
    // One camera loads (e.g. `calibrate intrinsics` writes one), but cannot be fused.
    let text = calibration_with(|t| {
        for cam in ["cam_1", "cam_2", "cam_3"] {
            t[cam]
                .as_table_mut()
                .unwrap()
                .insert("ignore".into(), toml::Value::Boolean(true));
        }
    });
    let (one, _) = parse_rig(&text, "config.toml").unwrap();
    assert_eq!(one.len(), 1);
    for method in [FusionMethod::Default, FusionMethod::Paper] {
        let err = FusionEngine::new(one.clone(), method).unwrap_err();
        assert_eq!(err, PerceptionError::TooFewCameras { cameras: 1 });
        assert!(err.to_string().contains("at least 2"), "{err}");
    }
    FusionEngine::new(rig(), FusionMethod::Default).unwrap();
}

/// A keypoint given twice for one camera and sync index (a row repeated 300 px away, as rows merged
/// from two detections would be) is left out and counted, never merged silently.
#[test]
fn a_keypoint_given_twice_for_one_frame_is_left_out_and_named() {
    if ergocell_testdata::skip_without("data/caliscope-4cam") {
        return;
    }
    let text = read("xy_pose33.csv");
    let mut lines = text.lines();
    let header = lines.next().unwrap();
    let rows: Vec<&str> = lines.take(40).collect();
    let mut fields: Vec<String> = rows[0].split(',').map(str::to_owned).collect();
    let x: f64 = fields[5].parse().unwrap();
    fields[5] = format!("{}", x + 300.0);
    let (port, point): (usize, usize) = (fields[1].parse().unwrap(), fields[4].parse().unwrap());
    let clean = format!("{header}\n{}\n", rows.join("\n"));
    let dirty = format!("{header}\n{}\n{}\n", rows.join("\n"), fields.join(","));
    let (a, sa) = caliscope(&clean);
    let (b, sb) = caliscope(&dirty);
    assert_eq!((sa.duplicate_keypoints, sb.duplicate_keypoints), (0, 1));
    assert!(view(&a[0], port).unwrap().keypoints()[point].is_some());
    assert!(
        view(&b[0], port).unwrap().keypoints()[point].is_none(),
        "neither of the two is used"
    );
    assert!(sb.warning().unwrap().contains("more than once"));
}

/// Rows for a camera the calibration does not have (caliscope `port` 9, no `cam_9`) are counted and
/// named, not read as "0 frames" with a guess about the file changing.
#[test]
fn rows_for_an_unknown_port_are_named() {
    if ergocell_testdata::skip_without("data/caliscope-4cam") {
        return;
    }
    let text = read("xy_pose33.csv");
    let mut lines = text.lines();
    let header = lines.next().unwrap();
    let rows: Vec<String> = lines
        .take(40)
        .map(|row| {
            let mut fields: Vec<&str> = row.split(',').collect();
            fields[1] = "9";
            fields.join(",")
        })
        .collect();
    let (_, stats) = caliscope(&format!("{header}\n{}\n", rows.join("\n")));
    assert_eq!(stats.unknown_camera_records, 40);
    assert_eq!(stats.first_unknown_port, Some(9));
    let w = stats.warning().unwrap();
    assert!(
        w.contains("40 rows for cameras the calibration does not have"),
        "{w}"
    );
    assert!(
        w.contains("caliscope port 9, which would be camera cam_9"),
        "{w}"
    );
}
