//! Real data: caliscope's 4-camera MediaPipe recording (`../shared/data/caliscope-4cam`, see its
//! SOURCE.md). The recording tool's own 3D output is the known answer for plain N-view DLT, and the
//! bone lengths measure how consistent each fusion is.

#![allow(clippy::unwrap_used, clippy::expect_used)] // test helpers outside #[test] fns

use std::path::PathBuf;

use ergocell_formats::import::parse_caliscope_xy;
use ergocell_formats::rig_file::{parse_rig, RigFormat};
use ergocell_perception::detections::ImportStats;
use ergocell_perception::fusion::{FusionEngine, FusionMethod};
use ergocell_perception::metrics::{bone_length_variation_percent, common_bone_variation_percent};
use ergocell_perception::{CameraRig, Frame2};
use ergocell_skeleton::Skeleton3;

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

fn load() -> (CameraRig, Vec<Frame2>) {
    let (rig, format) = parse_rig(&read("config.toml"), "config.toml").unwrap();
    assert_eq!(format, RigFormat::Caliscope);
    assert_eq!(rig.len(), 4);
    let mut stats = ImportStats::default();
    let frames =
        parse_caliscope_xy(&read("xy_pose33.csv"), "xy_pose33.csv", &rig, &mut stats).unwrap();
    (rig, frames)
}

#[test]
fn unweighted_nview_dlt_reproduces_caliscopes_own_3d_output() {
    if ergocell_testdata::skip_without("data/caliscope-4cam") {
        return;
    }
    let (rig, frames) = load();
    let engine = FusionEngine::new(rig, FusionMethod::Default).unwrap();
    // xyz_pose33.csv: index, sync_index, point_id, x, y, z
    let text = read("xyz_pose33.csv");
    let mut reader = csv::Reader::from_reader(text.as_bytes());
    let mut expected = std::collections::HashMap::new();
    for row in reader.records() {
        let row = row.unwrap();
        let sync: usize = row[1].parse().unwrap();
        let point: usize = row[2].parse().unwrap();
        let p: Vec<f64> = (3..6).map(|i| row[i].parse().unwrap()).collect();
        expected.insert((sync, point), p);
    }
    assert!(expected.len() > 7000);
    let mut worst: f64 = 0.0;
    let mut compared = 0;
    // sync indices are consecutive from 0 in this recording, so frame k is sync index k
    for (sync, frame) in frames.iter().enumerate() {
        let ours = engine.raw_pixel_dlt(frame).unwrap();
        for (point, p) in ours.iter().enumerate() {
            if let Some(e) = expected.get(&(sync, point)) {
                let p = p.unwrap_or_else(|| panic!("sync {sync} point {point}: we found no point"));
                let d = ((p.x - e[0]).powi(2) + (p.y - e[1]).powi(2) + (p.z - e[2]).powi(2)).sqrt();

                worst = worst.max(d);
                compared += 1;
            }
        }
    }
    assert_eq!(
        compared,
        expected.len(),
        "every point caliscope triangulated, we triangulated"
    );
    assert!(worst < 1e-6, "worst difference {worst} m");
}

fn skeletons(points: &[[Option<nalgebra::Point3<f64>>; 33]]) -> Vec<Skeleton3> {
    points
        .iter()
        .enumerate()
        .map(|(k, pts)| Skeleton3::from_optional_points(k as i64, pts).unwrap())
        .collect()
}

#[test]
fn default_fusion_has_less_bone_length_variation_than_the_papers_and_plain_dlt() {
    if ergocell_testdata::skip_without("data/caliscope-4cam") {
        return;
    }
    let (rig, frames) = load();
    let mut paper = FusionEngine::new(rig.clone(), FusionMethod::Paper).unwrap();
    let mut default = FusionEngine::new(rig, FusionMethod::Default).unwrap();
    let paper_frames: Vec<Skeleton3> = frames
        .iter()
        .map(|f| paper.fuse(f).unwrap().skeleton)
        .collect();
    let default_frames: Vec<Skeleton3> = frames
        .iter()
        .map(|f| default.fuse(f).unwrap().skeleton)
        .collect();
    let dlt = skeletons(
        &frames
            .iter()
            .map(|f| default.raw_pixel_dlt(f).unwrap())
            .collect::<Vec<_>>(),
    );
    let weighted = skeletons(
        &frames
            .iter()
            .map(|f| default.weighted_dlt(f).unwrap())
            .collect::<Vec<_>>(),
    );
    // each method over the bones it observed
    for (name, rec) in [
        ("paper", &paper_frames),
        ("raw DLT", &dlt),
        ("undistorted DLT", &weighted),
        ("default", &default_frames),
    ] {
        eprintln!(
            "{name}: {:.2}% over the bones it observed",
            bone_length_variation_percent(rec).unwrap()
        );
    }
    // fair comparison: over the bones every method observed
    let (bones, cv) =
        common_bone_variation_percent(&[&paper_frames, &dlt, &weighted, &default_frames]).unwrap();
    let [cv_paper, cv_dlt, cv_weighted, cv_default] = cv[..] else {
        panic!("four means")
    };
    eprintln!(
        "over the {} bones all observed: paper {cv_paper:.2}%  raw DLT {cv_dlt:.2}%  undistorted DLT {cv_weighted:.2}%  default {cv_default:.2}%",
        bones.len()
    );
    assert!(
        cv_default < cv_paper,
        "default {cv_default} vs paper {cv_paper}"
    );
    assert!(cv_default < cv_dlt, "default {cv_default} vs DLT {cv_dlt}");
    assert!(
        cv_default < cv_weighted,
        "default {cv_default} vs undistorted DLT {cv_weighted}"
    );
    // and over all 12 bones (the paper fusion sees only some of them)
    let all_default = bone_length_variation_percent(&default_frames).unwrap();
    let all_weighted = bone_length_variation_percent(&weighted).unwrap();
    assert!(
        all_default < all_weighted,
        "default {all_default} vs undistorted DLT {all_weighted} over all bones"
    );
}

#[test]
fn the_streaming_reader_gives_the_frames_of_the_whole_file_parse() {
    if ergocell_testdata::skip_without("data/caliscope-4cam") {
        return;
    }
    let (rig, frames) = load();
    let text = read("xy_pose33.csv");
    let scan =
        ergocell_formats::import::scan_caliscope_xy(text.as_bytes(), "xy_pose33.csv").unwrap();
    assert_eq!(
        scan,
        ergocell_formats::import::CaliscopeScan {
            frames: 267,
            sorted: true
        }
    );
    let mut stream =
        ergocell_formats::import::CaliscopeStream::new(text.as_bytes(), "xy_pose33.csv", &rig)
            .unwrap();
    let streamed: Vec<Frame2> = stream.by_ref().collect();
    assert_eq!(streamed, frames);
    assert_eq!(stream.stats(), {
        let mut stats = ImportStats::default();
        parse_caliscope_xy(&text, "xy_pose33.csv", &rig, &mut stats).unwrap();
        stats
    });
    // Rows out of sync_index order: the scan says so (and counts the frames), the stream skips
    // what arrives late and counts it, the whole-file parse keeps it.
    let mut lines: Vec<&str> = text.lines().collect();
    let moved = lines.remove(1); // a row of sync 0, moved to the end
    lines.push(moved);
    let unsorted = lines.join("\n");
    let scan = ergocell_formats::import::scan_caliscope_xy(unsorted.as_bytes(), "u.csv").unwrap();
    assert_eq!((scan.frames, scan.sorted), (267, false));
    let mut stream =
        ergocell_formats::import::CaliscopeStream::new(unsorted.as_bytes(), "u.csv", &rig).unwrap();
    assert_eq!(stream.by_ref().count(), 267);
    assert_eq!(stream.stats().skipped_records, 1);
}
