//! Importers for 2D detections written by other tools. No I/O: callers pass file contents.
//!
//! - **OpenPose JSON** (also written by RTMPose/Pose2Sim): one folder per camera, one file per frame,
//!   `{"people": [{"pose_keypoints_2d": [x0, y0, c0, x1, …]}]}`. Undetected keypoints are `0, 0, 0`.
//!   Camera folders are matched to the calibration's cameras by name where they match, else in sorted
//!   order, as Pose2Sim does ([`match_camera_folders`]). With several people in a frame the operator is
//!   chosen by [`OperatorSelector`].
//! - **caliscope** long CSV (`xy_*.csv`): `sync_index, port, frame_index, frame_time, point_id,
//!   img_loc_x, img_loc_y`, BlazePose point ids, no confidence column (taken as 1).

use std::collections::BTreeMap;

use ergocell_skeleton::LANDMARK_COUNT;
use nalgebra::Point2;
use serde::Deserialize;

use crate::detections::{Frame2, ImportStats, Keypoint2, KeypointFormat, View2};
use crate::error::{parse_err, Result};
use crate::rig::{CameraIndex, CameraRig};

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

#[derive(Debug, Deserialize)]
struct CaliscopeRow {
    sync_index: i64,
    port: i64,
    frame_time: f64,
    point_id: i64,
    img_loc_x: Option<f64>,
    img_loc_y: Option<f64>,
}

/// Parses caliscope's long `xy_*.csv` into one [`Frame2`] per `sync_index` (in order). `port` N maps
/// to camera `cam_N` of the rig; rows for unknown ports or invalid points are skipped and counted.
/// The frame's stamp is the earliest camera time of that sync index.
pub fn parse_caliscope_xy(
    text: &str,
    source_name: &str,
    rig: &CameraRig,
    stats: &mut ImportStats,
) -> Result<Vec<Frame2>> {
    let mut reader = csv::ReaderBuilder::new()
        .has_headers(true)
        .trim(csv::Trim::All)
        .from_reader(text.as_bytes());
    let mut frames: BTreeMap<i64, BTreeMap<CameraIndex, View2>> = BTreeMap::new();
    for (line, record) in reader.deserialize::<CaliscopeRow>().enumerate() {
        let row = record.map_err(|e| parse_err(source_name, format!("row {}", line + 2), e))?;
        let Some(camera) = rig.index_of_name(&format!("cam_{}", row.port)) else {
            stats.skipped_records += 1;
            continue;
        };
        let Some(landmark) = usize::try_from(row.point_id)
            .ok()
            .and_then(ergocell_skeleton::Landmark::from_index)
        else {
            stats.skipped_records += 1;
            continue;
        };
        if !row.frame_time.is_finite() {
            stats.skipped_records += 1;
            continue;
        }
        let stamp_nanos = (row.frame_time * 1e9).round() as i64;
        let view = frames
            .entry(row.sync_index)
            .or_default()
            .entry(camera)
            .or_insert_with(|| View2::empty(camera, stamp_nanos));
        match (row.img_loc_x, row.img_loc_y) {
            (Some(u), Some(v)) => match Keypoint2::new(u, v, 1.0) {
                Ok(k) => view.set(landmark, Some(k)),
                Err(_) => stats.invalid_keypoints += 1,
            },
            _ => stats.invalid_keypoints += 1,
        }
    }
    Ok(frames
        .into_values()
        .map(|views| {
            let views: Vec<View2> = views.into_values().collect();
            let stamp_nanos = views.iter().map(|v| v.stamp_nanos).min().unwrap_or(0);
            Frame2 { stamp_nanos, views }
        })
        .collect())
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
