//! The camera topics as the cell's landmark source: each `ergocell_msgs/CameraLandmarks` message
//! checked and turned into a [`View2`] of the rig's camera (its video geometry mapped), or rejected
//! and counted — never passed on half-read.

use std::collections::BTreeMap;

use ergocell_bridge::msg::CameraLandmarks;
use ergocell_perception::video_geometry::VideoGeometry;
use ergocell_perception::{CameraRig, View2};

use crate::messages;

/// The cameras' messages in, views out.
#[derive(Debug, Clone)]
pub struct CameraInbox {
    rig: CameraRig,
    /// Per camera of the rig: the declared geometry of its video (`None`: the calibrated image).
    geometries: Vec<Option<VideoGeometry>>,
    rejected: u64,
    /// Per camera id: the last rejection's reason. A camera that keeps sending what the cell cannot
    /// use (a wrong image size at 30 Hz) is said once per reason, not once per message.
    last_reason: BTreeMap<String, String>,
}

impl CameraInbox {
    pub fn new(rig: CameraRig, geometries: Vec<Option<VideoGeometry>>) -> Self {
        Self {
            rig,
            geometries,
            rejected: 0,
            last_reason: BTreeMap::new(),
        }
    }

    /// The message's view, or `None` when it is rejected (logged with why, and counted).
    pub fn accept(&mut self, m: &CameraLandmarks) -> Option<View2> {
        match messages::view_from_message_with(&self.rig, &self.geometries, m) {
            Ok(v) => Some(v),
            Err(e) => {
                self.rejected += 1;
                let reason = e.to_string();
                if self.first_of_its_kind(&m.camera_id, &reason) {
                    tracing::warn!(
                        error = %reason,
                        camera = %m.camera_id,
                        "camera message rejected (the same again from this camera: counted in the \
                         summary, logged at debug)"
                    );
                } else {
                    tracing::debug!(error = %reason, camera = %m.camera_id, "camera message rejected");
                }
                None
            }
        }
    }

    /// Whether this rejection's reason is new for its camera (then it is said at warn level). Ids the
    /// rig does not know share one entry, so the memory is bounded by the rig.
    fn first_of_its_kind(&mut self, camera_id: &str, reason: &str) -> bool {
        let key = if self.rig.index_of_name(camera_id).is_some() {
            camera_id
        } else {
            ""
        };
        if self.last_reason.get(key).is_some_and(|r| r == reason) {
            return false;
        }
        self.last_reason.insert(key.to_owned(), reason.to_owned());
        true
    }

    /// Messages rejected so far.
    pub fn rejected(&self) -> u64 {
        self.rejected
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn message(camera: &str, width: u32) -> CameraLandmarks {
        CameraLandmarks {
            camera_id: camera.to_owned(),
            image_width: width,
            image_height: 720,
            x_px: vec![100.0; 33],
            y_px: vec![100.0; 33],
            visibility: vec![0.9; 33],
            presence: vec![0.9; 33],
            ..CameraLandmarks::default()
        }
    }

    #[test]
    fn a_camera_that_keeps_sending_the_same_bad_message_is_said_once_and_counted_every_time() {
        let text = include_str!("../../config/rig.toml");
        let (rig, _) =
            ergocell_formats::rig_file::parse_rig(text, "config/rig.toml").expect("shipped rig");
        let camera = rig.cameras()[0].id.as_str().to_owned();
        let mut inbox = CameraInbox::new(rig, Vec::new());
        for _ in 0..50 {
            assert!(inbox.accept(&message(&camera, 7)).is_none());
        }
        assert_eq!(inbox.rejected(), 50);
        // said once for the reason, not once per message
        assert!(!inbox.first_of_its_kind(&camera, &inbox.last_reason[&camera].clone()));
        // another reason from the same camera is said again
        assert!(inbox.first_of_its_kind(&camera, "another reason"));
        // unknown ids share one entry: a flood of invented names cannot grow the memory
        for i in 0..100 {
            inbox.accept(&message(&format!("nobody{i}"), 7));
        }
        assert_eq!(inbox.last_reason.len(), 2);
        assert_eq!(inbox.rejected(), 150);
    }
}
