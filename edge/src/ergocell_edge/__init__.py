"""ergocell's edge camera node: video to MediaPipe BlazePose-33 body landmarks.

``ergocell-edge detect`` writes OpenPose-layout JSON files per frame (offline); ``ergocell-edge publish``
publishes ``ergocell_msgs/msg/CameraLandmarks`` over ROS 2 (live). See README.md.
"""

__version__ = "0.1.0"

#: BlazePose's 33 landmarks, in MediaPipe's order (the order of every array this package writes).
LANDMARK_NAMES = (
    "nose", "left_eye_inner", "left_eye", "left_eye_outer", "right_eye_inner", "right_eye",
    "right_eye_outer", "left_ear", "right_ear", "mouth_left", "mouth_right", "left_shoulder",
    "right_shoulder", "left_elbow", "right_elbow", "left_wrist", "right_wrist", "left_pinky",
    "right_pinky", "left_index", "right_index", "left_thumb", "right_thumb", "left_hip", "right_hip",
    "left_knee", "right_knee", "left_ankle", "right_ankle", "left_heel", "right_heel",
    "left_foot_index", "right_foot_index",
)
LANDMARK_COUNT = 33
assert len(LANDMARK_NAMES) == LANDMARK_COUNT


class EdgeError(Exception):
    """A user error (bad argument, missing file, undecodable video...): reported without a traceback."""
