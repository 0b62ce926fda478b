//! ROS 2 messages, hand-written in exact IDL field order.
//!
//! CDR is positional: a struct's fields go on the wire in declaration order with no names, so each
//! struct below declares its fields in exactly the order of its `.msg` file. Sequences (`T[]`) are
//! `Vec<T>`; fixed arrays are avoided (serde stops at 32 elements, and the wire of `T[N]` differs from
//! `T[]`). The standard messages follow ROS 2 Jazzy (identical in Humble for the types here).
//!
//! Each message carries its `ros2msg` definition (the `.msg` text, dependencies appended the way
//! rosbag2 stores them) so an MCAP recording names its schemas and Foxglove / rosbag2 decode it. The
//! `ergocell_msgs` definitions are the files in `ros2/ergocell_msgs/msg/`, embedded at compile time.

use serde::{de::DeserializeOwned, Deserialize, Serialize};

/// A ROS 2 message type: its name, its definition and its dependencies' definitions.
pub trait RosMessage: Serialize + DeserializeOwned {
    /// Package, e.g. `sensor_msgs`.
    const PACKAGE: &'static str;
    /// Type name, e.g. `JointState`.
    const NAME: &'static str;
    /// The `.msg` text.
    const DEFINITION: &'static str;
    /// Every nested type (transitively, each once) as `("pkg/Name", definition)`.
    const DEPENDENCIES: &'static [(&'static str, &'static str)];
    /// `(type, field name)` in wire order, as in the `.msg` file (checked against it in the tests).
    const FIELDS: &'static [(&'static str, &'static str)];

    /// `pkg/msg/Name`, the name rosbag2 and Foxglove use.
    fn type_name() -> String {
        format!("{}/msg/{}", Self::PACKAGE, Self::NAME)
    }

    /// The `ros2msg` schema text: the definition, then each dependency after a separator line.
    fn schema_text() -> String {
        let mut text = Self::DEFINITION.trim_end().to_owned();
        text.push('\n');
        for (name, definition) in Self::DEPENDENCIES {
            text.push_str(&"=".repeat(80));
            text.push_str("\nMSG: ");
            text.push_str(name);
            text.push('\n');
            text.push_str(definition.trim_end());
            text.push('\n');
        }
        text
    }
}

/// `builtin_interfaces/Time`: seconds and nanoseconds since the Unix epoch (or the clock's origin).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
pub struct Time {
    pub sec: i32,
    pub nanosec: u32,
}

impl Time {
    /// From integer nanoseconds (negative stamps clamp to 0: ROS time is not negative).
    pub fn from_nanos(stamp_nanos: i64) -> Self {
        let t = stamp_nanos.max(0);
        Self {
            sec: i32::try_from(t / 1_000_000_000).unwrap_or(i32::MAX),
            nanosec: (t % 1_000_000_000) as u32,
        }
    }

    /// Integer nanoseconds.
    pub fn to_nanos(self) -> i64 {
        i64::from(self.sec) * 1_000_000_000 + i64::from(self.nanosec)
    }
}

const TIME_DEF: &str = "int32 sec\nuint32 nanosec\n";

/// `builtin_interfaces/Duration`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
pub struct Duration {
    pub sec: i32,
    pub nanosec: u32,
}

impl Duration {
    /// From seconds (non-negative; rounded to the nanosecond).
    pub fn from_secs_f64(secs: f64) -> Self {
        let nanos = (secs.max(0.0) * 1e9).round() as i64;
        Self {
            sec: i32::try_from(nanos / 1_000_000_000).unwrap_or(i32::MAX),
            nanosec: (nanos % 1_000_000_000) as u32,
        }
    }

    /// Seconds.
    pub fn as_secs_f64(self) -> f64 {
        f64::from(self.sec) + f64::from(self.nanosec) * 1e-9
    }
}

const DURATION_DEF: &str = "int32 sec\nuint32 nanosec\n";

/// `std_msgs/Header`.
#[derive(Debug, Clone, PartialEq, Eq, Default, Serialize, Deserialize)]
pub struct Header {
    pub stamp: Time,
    pub frame_id: String,
}

impl Header {
    pub fn new(stamp_nanos: i64, frame_id: &str) -> Self {
        Self {
            stamp: Time::from_nanos(stamp_nanos),
            frame_id: frame_id.to_owned(),
        }
    }
}

const HEADER_DEF: &str = "builtin_interfaces/Time stamp\nstring frame_id\n";
const HEADER_DEPS: [(&str, &str); 2] = [
    ("std_msgs/Header", HEADER_DEF),
    ("builtin_interfaces/Time", TIME_DEF),
];

/// `sensor_msgs/JointState`: map by name, the order is not guaranteed.
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
pub struct JointState {
    pub header: Header,
    pub name: Vec<String>,
    pub position: Vec<f64>,
    pub velocity: Vec<f64>,
    pub effort: Vec<f64>,
}

impl RosMessage for JointState {
    const PACKAGE: &'static str = "sensor_msgs";
    const NAME: &'static str = "JointState";
    const DEFINITION: &'static str = "std_msgs/Header header\nstring[] name\nfloat64[] position\nfloat64[] velocity\nfloat64[] effort\n";
    const DEPENDENCIES: &'static [(&'static str, &'static str)] = &HEADER_DEPS;
    const FIELDS: &'static [(&'static str, &'static str)] = &[
        ("std_msgs/Header", "header"),
        ("string[]", "name"),
        ("float64[]", "position"),
        ("float64[]", "velocity"),
        ("float64[]", "effort"),
    ];
}

impl JointState {
    /// Positions in the order of `names` (mapped by name); `None` if a joint is missing.
    pub fn positions_for(&self, names: &[String]) -> Option<Vec<f64>> {
        names
            .iter()
            .map(|n| {
                self.name
                    .iter()
                    .position(|m| m == n)
                    .and_then(|i| self.position.get(i).copied())
            })
            .collect()
    }
}

/// `trajectory_msgs/JointTrajectoryPoint`.
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
pub struct JointTrajectoryPoint {
    pub positions: Vec<f64>,
    pub velocities: Vec<f64>,
    pub accelerations: Vec<f64>,
    pub effort: Vec<f64>,
    pub time_from_start: Duration,
}

const POINT_DEF: &str = "float64[] positions\nfloat64[] velocities\nfloat64[] accelerations\nfloat64[] effort\nbuiltin_interfaces/Duration time_from_start\n";

/// `trajectory_msgs/JointTrajectory`. An empty one (no points) sent to the joint trajectory
/// controller's topic replaces the current goal: the robot stops (a hold, not an emergency stop).
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
pub struct JointTrajectory {
    pub header: Header,
    pub joint_names: Vec<String>,
    pub points: Vec<JointTrajectoryPoint>,
}

impl RosMessage for JointTrajectory {
    const PACKAGE: &'static str = "trajectory_msgs";
    const NAME: &'static str = "JointTrajectory";
    const DEFINITION: &'static str =
        "std_msgs/Header header\nstring[] joint_names\nJointTrajectoryPoint[] points\n";
    const DEPENDENCIES: &'static [(&'static str, &'static str)] = &[
        ("std_msgs/Header", HEADER_DEF),
        ("builtin_interfaces/Time", TIME_DEF),
        ("trajectory_msgs/JointTrajectoryPoint", POINT_DEF),
        ("builtin_interfaces/Duration", DURATION_DEF),
    ];
    const FIELDS: &'static [(&'static str, &'static str)] = &[
        ("std_msgs/Header", "header"),
        ("string[]", "joint_names"),
        ("JointTrajectoryPoint[]", "points"),
    ];
}

/// `ergocell_msgs/CameraLandmarks` (`ros2/ergocell_msgs/msg/CameraLandmarks.msg`).
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
pub struct CameraLandmarks {
    pub header: Header,
    pub camera_id: String,
    pub image_width: u32,
    pub image_height: u32,
    pub x_px: Vec<f32>,
    pub y_px: Vec<f32>,
    pub visibility: Vec<f32>,
    pub presence: Vec<f32>,
}

impl RosMessage for CameraLandmarks {
    const PACKAGE: &'static str = "ergocell_msgs";
    const NAME: &'static str = "CameraLandmarks";
    const DEFINITION: &'static str =
        include_str!("../../ros2/ergocell_msgs/msg/CameraLandmarks.msg");
    const DEPENDENCIES: &'static [(&'static str, &'static str)] = &HEADER_DEPS;
    const FIELDS: &'static [(&'static str, &'static str)] = &[
        ("std_msgs/Header", "header"),
        ("string", "camera_id"),
        ("uint32", "image_width"),
        ("uint32", "image_height"),
        ("float32[]", "x_px"),
        ("float32[]", "y_px"),
        ("float32[]", "visibility"),
        ("float32[]", "presence"),
    ];
}

/// `ergocell_msgs/SessionState`.
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
pub struct SessionState {
    pub header: Header,
    pub state: String,
    pub reason: String,
    pub height_m: f64,
    pub height_uncertainty_m: f64,
    pub height_class: String,
    pub trajectory_sha256: String,
    pub robot_held: bool,
    pub cameras_fresh: u32,
    pub stereo_pairs_tracking: u32,
    pub trajectory_approved_by: Vec<String>,
    pub height_decision_basis: String,
    pub height_class_probability: f64,
    pub height_expected_rula_cost: f64,
    pub parts_taken: u32,
    pub last_part_hand: String,
    pub last_part_closest_m: f64,
}

impl SessionState {
    /// `state` once the session has ended (the session machine's `SessionState::SessionEnded`).
    pub const SESSION_ENDED: &'static str = "session_ended";
}

impl RosMessage for SessionState {
    const PACKAGE: &'static str = "ergocell_msgs";
    const NAME: &'static str = "SessionState";
    const DEFINITION: &'static str = include_str!("../../ros2/ergocell_msgs/msg/SessionState.msg");
    const DEPENDENCIES: &'static [(&'static str, &'static str)] = &HEADER_DEPS;
    const FIELDS: &'static [(&'static str, &'static str)] = &[
        ("std_msgs/Header", "header"),
        ("string", "state"),
        ("string", "reason"),
        ("float64", "height_m"),
        ("float64", "height_uncertainty_m"),
        ("string", "height_class"),
        ("string", "trajectory_sha256"),
        ("bool", "robot_held"),
        ("uint32", "cameras_fresh"),
        ("uint32", "stereo_pairs_tracking"),
        ("string[]", "trajectory_approved_by"),
        ("string", "height_decision_basis"),
        ("float64", "height_class_probability"),
        ("float64", "height_expected_rula_cost"),
        ("uint32", "parts_taken"),
        ("string", "last_part_hand"),
        ("float64", "last_part_closest_m"),
    ];
}

/// `ergocell_msgs/OperatorPose`: the fused skeleton (33 landmarks, NaN where not fused) and the joint
/// angles RULA was scored from, radians.
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
pub struct OperatorPose {
    pub header: Header,
    pub x: Vec<f64>,
    pub y: Vec<f64>,
    pub z: Vec<f64>,
    pub angle_names: Vec<String>,
    pub angle_rad: Vec<f64>,
}

impl RosMessage for OperatorPose {
    const PACKAGE: &'static str = "ergocell_msgs";
    const NAME: &'static str = "OperatorPose";
    const DEFINITION: &'static str = include_str!("../../ros2/ergocell_msgs/msg/OperatorPose.msg");
    const DEPENDENCIES: &'static [(&'static str, &'static str)] = &HEADER_DEPS;
    const FIELDS: &'static [(&'static str, &'static str)] = &[
        ("std_msgs/Header", "header"),
        ("float64[]", "x"),
        ("float64[]", "y"),
        ("float64[]", "z"),
        ("string[]", "angle_names"),
        ("float64[]", "angle_rad"),
    ];
}

/// `ergocell_msgs/RulaSide`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
pub struct RulaSide {
    pub scored: bool,
    pub uncertain: bool,
    pub upper_arm_score: u8,
    pub lower_arm_score: u8,
    pub wrist_score: u8,
    pub wrist_twist_score: u8,
    pub posture_score_a: u8,
    pub score_c_wrist_arm: u8,
    pub neck_score: u8,
    pub trunk_score: u8,
    pub legs_score: u8,
    pub posture_score_b: u8,
    pub score_d_neck_trunk_legs: u8,
    pub final_score: u8,
    pub action_level: u8,
}

const RULA_SIDE_DEF: &str = include_str!("../../ros2/ergocell_msgs/msg/RulaSide.msg");

impl RosMessage for RulaSide {
    const PACKAGE: &'static str = "ergocell_msgs";
    const NAME: &'static str = "RulaSide";
    const DEFINITION: &'static str = RULA_SIDE_DEF;
    const DEPENDENCIES: &'static [(&'static str, &'static str)] = &[];
    const FIELDS: &'static [(&'static str, &'static str)] = &[
        ("bool", "scored"),
        ("bool", "uncertain"),
        ("uint8", "upper_arm_score"),
        ("uint8", "lower_arm_score"),
        ("uint8", "wrist_score"),
        ("uint8", "wrist_twist_score"),
        ("uint8", "posture_score_a"),
        ("uint8", "score_c_wrist_arm"),
        ("uint8", "neck_score"),
        ("uint8", "trunk_score"),
        ("uint8", "legs_score"),
        ("uint8", "posture_score_b"),
        ("uint8", "score_d_neck_trunk_legs"),
        ("uint8", "final_score"),
        ("uint8", "action_level"),
    ];
}

/// `ergocell_msgs/ErgonomicState`.
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
pub struct ErgonomicState {
    pub header: Header,
    pub left: RulaSide,
    pub right: RulaSide,
    pub action_level: u8,
    /// Per region (upper arm, lower arm, wrist, neck, trunk), the probability that its band is
    /// right; NaN where not known, empty when the side is not scored.
    pub left_band_probability: Vec<f64>,
    pub right_band_probability: Vec<f64>,
    /// The stated standard deviation of those angles, degrees (NaN: not known).
    pub left_angle_sd_deg: Vec<f64>,
    pub right_angle_sd_deg: Vec<f64>,
}

impl RosMessage for ErgonomicState {
    const PACKAGE: &'static str = "ergocell_msgs";
    const NAME: &'static str = "ErgonomicState";
    const DEFINITION: &'static str =
        include_str!("../../ros2/ergocell_msgs/msg/ErgonomicState.msg");
    const DEPENDENCIES: &'static [(&'static str, &'static str)] = &[
        ("std_msgs/Header", HEADER_DEF),
        ("builtin_interfaces/Time", TIME_DEF),
        ("ergocell_msgs/RulaSide", RULA_SIDE_DEF),
    ];
    const FIELDS: &'static [(&'static str, &'static str)] = &[
        ("std_msgs/Header", "header"),
        ("RulaSide", "left"),
        ("RulaSide", "right"),
        ("uint8", "action_level"),
        ("float64[]", "left_band_probability"),
        ("float64[]", "right_band_probability"),
        ("float64[]", "left_angle_sd_deg"),
        ("float64[]", "right_angle_sd_deg"),
    ];
}

/// `ergocell_msgs/RebaSide`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
pub struct RebaSide {
    pub scored: bool,
    pub uncertain: bool,
    pub trunk_score: u8,
    pub neck_score: u8,
    pub legs_score: u8,
    pub score_a: u8,
    pub upper_arm_score: u8,
    pub lower_arm_score: u8,
    pub wrist_score: u8,
    pub score_b: u8,
    pub table_c: u8,
    pub activity_score: u8,
    pub reba_score: u8,
    pub action_level: u8,
}

const REBA_SIDE_DEF: &str = include_str!("../../ros2/ergocell_msgs/msg/RebaSide.msg");

impl RosMessage for RebaSide {
    const PACKAGE: &'static str = "ergocell_msgs";
    const NAME: &'static str = "RebaSide";
    const DEFINITION: &'static str = REBA_SIDE_DEF;
    const DEPENDENCIES: &'static [(&'static str, &'static str)] = &[];
    const FIELDS: &'static [(&'static str, &'static str)] = &[
        ("bool", "scored"),
        ("bool", "uncertain"),
        ("uint8", "trunk_score"),
        ("uint8", "neck_score"),
        ("uint8", "legs_score"),
        ("uint8", "score_a"),
        ("uint8", "upper_arm_score"),
        ("uint8", "lower_arm_score"),
        ("uint8", "wrist_score"),
        ("uint8", "score_b"),
        ("uint8", "table_c"),
        ("uint8", "activity_score"),
        ("uint8", "reba_score"),
        ("uint8", "action_level"),
    ];
}

/// `ergocell_msgs/RebaState`: REBA beside RULA, one per assessed frame.
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
pub struct RebaState {
    pub header: Header,
    pub left: RebaSide,
    pub right: RebaSide,
    pub action_level: u8,
}

impl RosMessage for RebaState {
    const PACKAGE: &'static str = "ergocell_msgs";
    const NAME: &'static str = "RebaState";
    const DEFINITION: &'static str = include_str!("../../ros2/ergocell_msgs/msg/RebaState.msg");
    const DEPENDENCIES: &'static [(&'static str, &'static str)] = &[
        ("std_msgs/Header", HEADER_DEF),
        ("builtin_interfaces/Time", TIME_DEF),
        ("ergocell_msgs/RebaSide", REBA_SIDE_DEF),
    ];
    const FIELDS: &'static [(&'static str, &'static str)] = &[
        ("std_msgs/Header", "header"),
        ("RebaSide", "left"),
        ("RebaSide", "right"),
        ("uint8", "action_level"),
    ];
}

/// `ergocell_msgs/PostureWarning`.
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
pub struct PostureWarning {
    pub header: Header,
    pub kind: String,
    pub region: String,
    pub side: String,
    pub region_score: u8,
    pub angle_deg: f64,
    pub action_level: u8,
    pub uncertain: bool,
    pub message: String,
    pub band_probability: f64,
    pub near_limit: bool,
}

impl PostureWarning {
    /// `kind` of a warning raised (then `changed`, `cleared`: ergonomics' `WarningKind`).
    pub const RAISED: &'static str = "raised";
}

impl RosMessage for PostureWarning {
    const PACKAGE: &'static str = "ergocell_msgs";
    const NAME: &'static str = "PostureWarning";
    const DEFINITION: &'static str =
        include_str!("../../ros2/ergocell_msgs/msg/PostureWarning.msg");
    const DEPENDENCIES: &'static [(&'static str, &'static str)] = &HEADER_DEPS;
    const FIELDS: &'static [(&'static str, &'static str)] = &[
        ("std_msgs/Header", "header"),
        ("string", "kind"),
        ("string", "region"),
        ("string", "side"),
        ("uint8", "region_score"),
        ("float64", "angle_deg"),
        ("uint8", "action_level"),
        ("bool", "uncertain"),
        ("string", "message"),
        ("float64", "band_probability"),
        ("bool", "near_limit"),
    ];
}

/// `ergocell_msgs/ControllerEvent`: what the robot side did (the controller's answers, ergocell's
/// cancel requests, the execution monitor's verdicts, the driver's state).
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
pub struct ControllerEvent {
    pub header: Header,
    pub kind: String,
    pub leg: String,
    pub status: String,
    pub error_code: i32,
    pub text: String,
    pub feedback_count: u32,
    pub max_error: f64,
    pub sample_stamp: Time,
    /// The leg as a constant ([`ControllerEvent::LEG_TO_HANDOVER`], …): what programs read.
    pub leg_id: u8,
}

/// What a [`ControllerEvent`] reports: the `kind` field's values, named once. The wire carries the
/// name (so recordings stay readable by any tool); programs compare the kind, not the words.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum ControllerEventKind {
    /// ergocell sent a leg (a topic trajectory or a FollowJointTrajectory goal).
    GoalSent,
    /// The controller accepted the goal.
    Accepted,
    /// The controller rejected the goal.
    Rejected,
    /// The controller did not answer in time.
    NoResponse,
    /// The action exchange failed.
    Failed,
    /// ergocell asked the controller to cancel the goal.
    CancelRequested,
    /// Feedback received (counted).
    Feedback,
    /// The goal finished (its status and error code in the event).
    Finished,
    /// The execution monitor's verdict (a deviation, stale or returned joint states).
    Monitor,
    /// The KUKA driver's state.
    Driver,
}

impl ControllerEventKind {
    pub const ALL: [Self; 10] = [
        Self::GoalSent,
        Self::Accepted,
        Self::Rejected,
        Self::NoResponse,
        Self::Failed,
        Self::CancelRequested,
        Self::Feedback,
        Self::Finished,
        Self::Monitor,
        Self::Driver,
    ];

    /// The name on the wire.
    pub const fn name(self) -> &'static str {
        match self {
            Self::GoalSent => "goal_sent",
            Self::Accepted => "accepted",
            Self::Rejected => "rejected",
            Self::NoResponse => "no_response",
            Self::Failed => "failed",
            Self::CancelRequested => "cancel_requested",
            Self::Feedback => "feedback",
            Self::Finished => "finished",
            Self::Monitor => "monitor",
            Self::Driver => "driver",
        }
    }

    /// The kind a name on the wire stands for; `None` for one this version does not know.
    pub fn from_name(name: &str) -> Option<Self> {
        Self::ALL.into_iter().find(|k| k.name() == name)
    }
}

impl ControllerEvent {
    /// Not about a leg (the monitor's and the driver's events).
    pub const LEG_NONE: u8 = 0;
    /// Home → handover: the locked trajectory as stored.
    pub const LEG_TO_HANDOVER: u8 = 1;
    /// Handover → home: the locked trajectory time-reversed.
    pub const LEG_TO_HOME: u8 = 2;

    /// The event's kind; `None` for a name this version does not know.
    pub fn event_kind(&self) -> Option<ControllerEventKind> {
        ControllerEventKind::from_name(&self.kind)
    }
}

impl RosMessage for ControllerEvent {
    const PACKAGE: &'static str = "ergocell_msgs";
    const NAME: &'static str = "ControllerEvent";
    const DEFINITION: &'static str =
        include_str!("../../ros2/ergocell_msgs/msg/ControllerEvent.msg");
    const DEPENDENCIES: &'static [(&'static str, &'static str)] = &HEADER_DEPS;
    const FIELDS: &'static [(&'static str, &'static str)] = &[
        ("std_msgs/Header", "header"),
        ("string", "kind"),
        ("string", "leg"),
        ("string", "status"),
        ("int32", "error_code"),
        ("string", "text"),
        ("uint32", "feedback_count"),
        ("float64", "max_error"),
        ("builtin_interfaces/Time", "sample_stamp"),
        ("uint8", "leg_id"),
    ];
}

/// `kuka_driver_interfaces/HardwareEvent` (kroshu/kuka_drivers' `event_broadcaster/hardware_event`).
#[derive(Debug, Clone, PartialEq, Eq, Default, Serialize, Deserialize)]
pub struct HardwareEvent {
    pub robot_name: String,
    pub event: u8,
}

impl HardwareEvent {
    pub const COMMAND_ACCEPTED: u8 = 2;
    pub const CONTROL_STARTED: u8 = 3;
    pub const CONTROL_STOPPED: u8 = 4;
    pub const CONTROL_MODE_SWITCH: u8 = 5;
    pub const ERROR: u8 = 6;

    /// The event in words.
    pub fn describe(&self) -> String {
        let what = match self.event {
            Self::COMMAND_ACCEPTED => "command accepted",
            Self::CONTROL_STARTED => "control started",
            Self::CONTROL_STOPPED => "stopped by user",
            Self::CONTROL_MODE_SWITCH => "control mode switched",
            Self::ERROR => "stopped by error",
            _ => "unknown event",
        };
        format!("{what} ({})", self.event)
    }
}

impl RosMessage for HardwareEvent {
    const PACKAGE: &'static str = "kuka_driver_interfaces";
    const NAME: &'static str = "HardwareEvent";
    const DEFINITION: &'static str =
        include_str!("../../ros2/kuka_driver_interfaces/msg/HardwareEvent.msg");
    const DEPENDENCIES: &'static [(&'static str, &'static str)] = &[];
    const FIELDS: &'static [(&'static str, &'static str)] =
        &[("string", "robot_name"), ("uint8", "event")];
}

/// `std_msgs/Bool` (kuka_drivers' `robot_manager/is_configured`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
pub struct BoolMsg {
    pub data: bool,
}

impl RosMessage for BoolMsg {
    const PACKAGE: &'static str = "std_msgs";
    const NAME: &'static str = "Bool";
    const DEFINITION: &'static str = "bool data\n";
    const DEPENDENCIES: &'static [(&'static str, &'static str)] = &[];
    const FIELDS: &'static [(&'static str, &'static str)] = &[("bool", "data")];
}

/// `geometry_msgs/Point`, metres.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
pub struct Point {
    pub x: f64,
    pub y: f64,
    pub z: f64,
}

/// `geometry_msgs/Quaternion` (x, y, z, w).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Quaternion {
    pub x: f64,
    pub y: f64,
    pub z: f64,
    pub w: f64,
}

impl Default for Quaternion {
    fn default() -> Self {
        Self {
            x: 0.0,
            y: 0.0,
            z: 0.0,
            w: 1.0,
        }
    }
}

/// `geometry_msgs/Pose`.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
pub struct Pose {
    pub position: Point,
    pub orientation: Quaternion,
}

/// `geometry_msgs/Vector3`.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
pub struct Vector3 {
    pub x: f64,
    pub y: f64,
    pub z: f64,
}

/// `std_msgs/ColorRGBA`, each in `0..=1`.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
pub struct ColorRGBA {
    pub r: f32,
    pub g: f32,
    pub b: f32,
    pub a: f32,
}

/// `sensor_msgs/CompressedImage` (only as the Marker's `texture`; left empty).
#[derive(Debug, Clone, PartialEq, Eq, Default, Serialize, Deserialize)]
pub struct CompressedImage {
    pub header: Header,
    pub format: String,
    pub data: Vec<u8>,
}

/// `visualization_msgs/UVCoordinate`.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
pub struct UVCoordinate {
    pub u: f32,
    pub v: f32,
}

/// `visualization_msgs/MeshFile`.
#[derive(Debug, Clone, PartialEq, Eq, Default, Serialize, Deserialize)]
pub struct MeshFile {
    pub filename: String,
    pub data: Vec<u8>,
}

/// `visualization_msgs/Marker` in the **Jazzy** layout (Iron added `texture_resource`, `texture`,
/// `uv_coordinates` and `mesh_file`; a Humble peer's Marker has a different wire layout).
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
pub struct Marker {
    pub header: Header,
    pub ns: String,
    pub id: i32,
    pub r#type: i32,
    pub action: i32,
    pub pose: Pose,
    pub scale: Vector3,
    pub color: ColorRGBA,
    pub lifetime: Duration,
    pub frame_locked: bool,
    pub points: Vec<Point>,
    pub colors: Vec<ColorRGBA>,
    pub texture_resource: String,
    pub texture: CompressedImage,
    pub uv_coordinates: Vec<UVCoordinate>,
    pub text: String,
    pub mesh_resource: String,
    pub mesh_file: MeshFile,
    pub mesh_use_embedded_materials: bool,
}

impl Marker {
    pub const SPHERE: i32 = 2;
    pub const LINE_LIST: i32 = 5;
    pub const SPHERE_LIST: i32 = 7;
    pub const ADD: i32 = 0;
}

const MARKER_DEF: &str = "std_msgs/Header header\nstring ns\nint32 id\nint32 type\nint32 action\ngeometry_msgs/Pose pose\ngeometry_msgs/Vector3 scale\nstd_msgs/ColorRGBA color\nbuiltin_interfaces/Duration lifetime\nbool frame_locked\ngeometry_msgs/Point[] points\nstd_msgs/ColorRGBA[] colors\nstring texture_resource\nsensor_msgs/CompressedImage texture\nUVCoordinate[] uv_coordinates\nstring text\nstring mesh_resource\nMeshFile mesh_file\nbool mesh_use_embedded_materials\n";

/// `visualization_msgs/MarkerArray`: the fused skeleton for RViz and Foxglove.
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
pub struct MarkerArray {
    pub markers: Vec<Marker>,
}

impl RosMessage for MarkerArray {
    const PACKAGE: &'static str = "visualization_msgs";
    const NAME: &'static str = "MarkerArray";
    const DEFINITION: &'static str = "Marker[] markers\n";
    const DEPENDENCIES: &'static [(&'static str, &'static str)] = &[
        ("visualization_msgs/Marker", MARKER_DEF),
        ("std_msgs/Header", HEADER_DEF),
        ("builtin_interfaces/Time", TIME_DEF),
        (
            "geometry_msgs/Pose",
            "Point position\nQuaternion orientation\n",
        ),
        ("geometry_msgs/Point", "float64 x\nfloat64 y\nfloat64 z\n"),
        (
            "geometry_msgs/Quaternion",
            "float64 x 0\nfloat64 y 0\nfloat64 z 0\nfloat64 w 1\n",
        ),
        ("geometry_msgs/Vector3", "float64 x\nfloat64 y\nfloat64 z\n"),
        (
            "std_msgs/ColorRGBA",
            "float32 r\nfloat32 g\nfloat32 b\nfloat32 a\n",
        ),
        ("builtin_interfaces/Duration", DURATION_DEF),
        (
            "sensor_msgs/CompressedImage",
            "std_msgs/Header header\nstring format\nuint8[] data\n",
        ),
        ("visualization_msgs/UVCoordinate", "float32 u\nfloat32 v\n"),
        (
            "visualization_msgs/MeshFile",
            "string filename\nuint8[] data\n",
        ),
    ];
    const FIELDS: &'static [(&'static str, &'static str)] = &[("Marker[]", "markers")];
}

/// `(type, name)` of every field declared in a `.msg` text (comments, blank lines and constants
/// skipped).
pub fn msg_fields(definition: &str) -> Vec<(String, String)> {
    definition
        .lines()
        .map(|l| l.split('#').next().unwrap_or("").trim())
        .filter(|l| !l.is_empty() && !l.contains('='))
        .filter_map(|l| {
            let mut it = l.split_whitespace();
            Some((it.next()?.to_owned(), it.next()?.to_owned()))
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every kind's name reads back as that kind, the names are distinct, and a name this version
    /// does not know is no kind.
    #[test]
    fn controller_event_kinds_round_trip_through_their_names() {
        for kind in ControllerEventKind::ALL {
            assert_eq!(ControllerEventKind::from_name(kind.name()), Some(kind));
        }
        let names: std::collections::BTreeSet<&str> =
            ControllerEventKind::ALL.iter().map(|k| k.name()).collect();
        assert_eq!(names.len(), ControllerEventKind::ALL.len());
        let event = ControllerEvent {
            kind: "estop".to_owned(),
            ..ControllerEvent::default()
        };
        assert_eq!(event.event_kind(), None);
    }

    fn check<M: RosMessage>() {
        let declared = msg_fields(M::DEFINITION);
        let rust: Vec<(String, String)> = M::FIELDS
            .iter()
            .map(|(t, n)| ((*t).to_owned(), (*n).to_owned()))
            .collect();
        assert_eq!(declared, rust, "{}", M::type_name());
    }

    #[test]
    fn every_struct_lists_its_msg_fields_in_order() {
        check::<JointState>();
        check::<JointTrajectory>();
        check::<CameraLandmarks>();
        check::<SessionState>();
        check::<OperatorPose>();
        check::<RulaSide>();
        check::<ErgonomicState>();
        check::<RebaSide>();
        check::<RebaState>();
        check::<PostureWarning>();
        check::<MarkerArray>();
        check::<ControllerEvent>();
        check::<HardwareEvent>();
        check::<BoolMsg>();
        let marker: Vec<String> = msg_fields(MARKER_DEF).into_iter().map(|(_, n)| n).collect();
        assert_eq!(marker.len(), 19, "Jazzy Marker has 19 fields");
        assert_eq!(marker[3], "type");
        assert_eq!(marker[18], "mesh_use_embedded_materials");
        assert_eq!(
            msg_fields(POINT_DEF).len(),
            5,
            "JointTrajectoryPoint has five fields"
        );
    }

    #[test]
    fn the_controller_events_leg_constants_are_the_msg_files() {
        let constants: Vec<(String, u8)> = ControllerEvent::DEFINITION
            .lines()
            .map(|l| l.split('#').next().unwrap_or("").trim())
            .filter_map(|l| {
                let (decl, value) = l.split_once('=')?;
                let name = decl.split_whitespace().nth(1)?.to_owned();
                Some((name, value.trim().parse().ok()?))
            })
            .collect();
        assert_eq!(
            constants,
            [
                ("LEG_NONE".to_owned(), ControllerEvent::LEG_NONE),
                (
                    "LEG_TO_HANDOVER".to_owned(),
                    ControllerEvent::LEG_TO_HANDOVER
                ),
                ("LEG_TO_HOME".to_owned(), ControllerEvent::LEG_TO_HOME),
            ]
        );
    }

    #[test]
    fn schema_text_appends_dependencies_like_rosbag2() {
        let s = JointTrajectory::schema_text();
        assert!(s.starts_with("std_msgs/Header header\n"));
        assert!(s.contains("\nMSG: trajectory_msgs/JointTrajectoryPoint\nfloat64[] positions\n"));
        assert_eq!(s.matches("\nMSG: ").count(), 4);
        assert_eq!(
            JointTrajectory::type_name(),
            "trajectory_msgs/msg/JointTrajectory"
        );
    }

    #[test]
    fn time_round_trips_nanoseconds() {
        let t = Time::from_nanos(1_700_000_123_456_789_012);
        assert_eq!(t.sec, 1_700_000_123);
        assert_eq!(t.nanosec, 456_789_012);
        assert_eq!(t.to_nanos(), 1_700_000_123_456_789_012);
        assert_eq!(Time::from_nanos(-5), Time::default());
        let d = Duration::from_secs_f64(2.25);
        assert_eq!((d.sec, d.nanosec), (2, 250_000_000));
    }

    #[test]
    fn joint_state_maps_by_name() {
        let js = JointState {
            name: vec!["b".into(), "a".into()],
            position: vec![2.0, 1.0],
            ..JointState::default()
        };
        assert_eq!(
            js.positions_for(&["a".into(), "b".into()]),
            Some(vec![1.0, 2.0])
        );
        assert_eq!(js.positions_for(&["c".into()]), None);
    }
}
