//! The cell's topic names: the defaults of `[ros]` (`transport::RosConfig`) and the names every
//! recording uses (the recorder, `ergocell review`, `ergocell replay`). One table; a cell may
//! rename its live topics in `[ros]`, a recording always uses these.

/// Every camera's landmarks topic starts with this.
pub const CAMERA_PREFIX: &str = "/ergocell/camera/";
/// The camera topic pattern, `{id}` replaced by the camera id.
pub const CAMERA_PATTERN: &str = "/ergocell/camera/{id}/landmarks";

/// `/ergocell/camera/<id>/landmarks`.
pub fn camera(id: &str) -> String {
    CAMERA_PATTERN.replace("{id}", id)
}

/// The camera id of a camera landmarks topic, if `topic` is one.
pub fn camera_id(topic: &str) -> Option<&str> {
    topic
        .strip_prefix(CAMERA_PREFIX)?
        .strip_suffix("/landmarks")
        .filter(|id| !id.is_empty() && !id.contains('/'))
}

pub const SESSION_STATE: &str = "/ergocell/session_state";
/// Every session event (state changes, class decided, trajectory locked, refusals, cameras), in order.
pub const SESSION_EVENTS: &str = "/ergocell/session_events";
/// The robot side's events (`ergocell_msgs/ControllerEvent`).
pub const CONTROLLER_EVENTS: &str = "/ergocell/controller_events";
/// kuka_drivers' robot manager: `std_msgs/Bool`, true once the driver is configured.
pub const IS_CONFIGURED: &str = "/robot_manager/is_configured";
/// kuka_drivers' event broadcaster: `kuka_driver_interfaces/HardwareEvent`.
pub const HARDWARE_EVENT: &str = "/event_broadcaster/hardware_event";
pub const ERGONOMICS: &str = "/ergocell/ergonomics";
/// REBA beside RULA (`ergocell_msgs/RebaState`), one per assessed frame.
pub const REBA: &str = "/ergocell/reba";
pub const WARNINGS: &str = "/ergocell/warnings";
/// The fused skeleton (`visualization_msgs/MarkerArray`).
pub const SKELETON: &str = "/ergocell/skeleton";
/// The fused skeleton by landmark and the joint angles (`ergocell_msgs/OperatorPose`).
pub const OPERATOR_POSE: &str = "/ergocell/operator_pose";
/// The robot's TCP (marker id 0) and the locked handover point (id 1), `world` frame.
pub const ROBOT_MARKERS: &str = "/ergocell/robot_markers";
pub const JOINT_STATES: &str = "/joint_states";
/// The joint trajectory controller's command topic (kuka_drivers' default controller name).
pub const JOINT_TRAJECTORY: &str = "/joint_trajectory_controller/joint_trajectory";
/// The joint trajectory controller's FollowJointTrajectory action.
pub const FOLLOW_JOINT_TRAJECTORY: &str = "/joint_trajectory_controller/follow_joint_trajectory";
/// The cell node's default namespace.
pub const NAMESPACE: &str = "/ergocell";

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn camera_topics_round_trip_their_id() {
        assert_eq!(camera("s1_left"), "/ergocell/camera/s1_left/landmarks");
        assert_eq!(camera_id(&camera("s1_left")), Some("s1_left"));
        assert_eq!(camera_id("/ergocell/camera//landmarks"), None);
        assert_eq!(camera_id("/ergocell/camera/a/b/landmarks"), None);
        assert_eq!(camera_id(SESSION_STATE), None);
    }
}
