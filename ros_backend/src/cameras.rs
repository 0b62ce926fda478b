//! The camera topics as the cell's landmark source: each `ergocell_msgs/CameraLandmarks` message
//! checked and turned into a [`View2`] of the rig's camera (its video geometry mapped), or rejected
//! and counted — never passed on half-read.

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
}

impl CameraInbox {
    pub fn new(rig: CameraRig, geometries: Vec<Option<VideoGeometry>>) -> Self {
        Self {
            rig,
            geometries,
            rejected: 0,
        }
    }

    /// The message's view, or `None` when it is rejected (logged with why, and counted).
    pub fn accept(&mut self, m: &CameraLandmarks) -> Option<View2> {
        match messages::view_from_message_with(&self.rig, &self.geometries, m) {
            Ok(v) => Some(v),
            Err(e) => {
                self.rejected += 1;
                tracing::warn!(error = %e, camera = %m.camera_id, "camera message rejected");
                None
            }
        }
    }

    /// Messages rejected so far.
    pub fn rejected(&self) -> u64 {
        self.rejected
    }
}
