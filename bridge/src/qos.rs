//! QoS of each ergocell topic, chosen per data kind (and stated on both ends: the peers' defaults
//! differ — ros2-client's subscriber default is best effort, rclcpp's is reliable).
//!
//! | topic | direction | reliability | durability | history | why |
//! |---|---|---|---|---|---|
//! | `/ergocell/camera/<id>/landmarks` | Jetson → cell | best effort | volatile | keep last 5 | sensor data: a late frame is worthless, a retransmission only adds latency; ROS 2's `SensorDataQoS` |
//! | `/joint_states` | driver → cell | best effort reader | volatile | keep last 5 | a best-effort reader matches both the driver's reliable and best-effort writers |
//! | `<controller>/joint_trajectory` | cell → driver | reliable | volatile | keep last 1 | a command must arrive; an old command must never be replayed to a late-joining driver |
//! | `/ergocell/session_state` | cell → all | reliable | transient local | keep last 1 | the state a late joiner (RViz, a Jetson restarting) must see at once |
//! | `/ergocell/session_events` | cell → all | reliable | transient local | keep last 100 | every event reaches every reader, also several in one step (keep-last-1 `session_state` keeps only the newest: `class_decided` and `trajectory_locked` were overwritten by `working`); a late joiner gets the recent ones |
//! | `/ergocell/controller_events` | cell → all | reliable | transient local | keep last 100 | every goal answer, cancel, monitor verdict and driver change, in order (recorded too) |
//! | `robot_manager/is_configured`, `event_broadcaster/hardware_event` | driver → cell | best effort reader | volatile | keep last 10 | kuka_drivers publishes them best effort on each change; a best-effort reader matches any writer |
//! | `/ergocell/warnings` | cell → all | reliable | transient local | keep last 20 | every warning must arrive; the recent ones for late joiners |
//! | `/ergocell/ergonomics`, `/ergocell/skeleton` | cell → all | reliable | volatile | keep last 10 | per-frame state for displays |
//!
//! Holding the robot (an empty `JointTrajectory`, or cancelling the FollowJointTrajectory goal) is a
//! software hold through the controller's normal interface. It is **not an emergency stop**: that stays
//! with the robot's safety controller (pendant E-stop, safety configuration).

/// Reliability of a topic.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Reliability {
    BestEffort,
    Reliable,
}

/// Durability of a topic.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Durability {
    Volatile,
    TransientLocal,
}

/// A topic's QoS: reliability, durability and history depth (keep last N).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct TopicQos {
    pub reliability: Reliability,
    pub durability: Durability,
    pub depth: u32,
}

/// Camera landmarks (sensor data).
pub const CAMERA_LANDMARKS: TopicQos = TopicQos {
    reliability: Reliability::BestEffort,
    durability: Durability::Volatile,
    depth: 5,
};
/// `/joint_states` as read by the cell.
pub const JOINT_STATES: TopicQos = TopicQos {
    reliability: Reliability::BestEffort,
    durability: Durability::Volatile,
    depth: 5,
};
/// Trajectory commands to the controller.
pub const TRAJECTORY_COMMAND: TopicQos = TopicQos {
    reliability: Reliability::Reliable,
    durability: Durability::Volatile,
    depth: 1,
};
/// Session state.
pub const SESSION_STATE: TopicQos = TopicQos {
    reliability: Reliability::Reliable,
    durability: Durability::TransientLocal,
    depth: 1,
};
/// Session events: every one, in order.
pub const SESSION_EVENTS: TopicQos = TopicQos {
    reliability: Reliability::Reliable,
    durability: Durability::TransientLocal,
    depth: 100,
};
/// The FollowJointTrajectory action's services and feedback (ROS 2's services default: reliable,
/// volatile, keep last 10).
pub const ACTION_SERVICES: TopicQos = TopicQos {
    reliability: Reliability::Reliable,
    durability: Durability::Volatile,
    depth: 10,
};
/// The action's status topic (transient local on the server, as rcl_action's default).
pub const ACTION_STATUS: TopicQos = TopicQos {
    reliability: Reliability::Reliable,
    durability: Durability::TransientLocal,
    depth: 1,
};
/// Controller events (goals, results, cancels, monitor verdicts, driver state): every one, in order.
pub const CONTROLLER_EVENTS: TopicQos = TopicQos {
    reliability: Reliability::Reliable,
    durability: Durability::TransientLocal,
    depth: 100,
};
/// The KUKA driver's state topics as read by the cell: kuka_drivers publishes `is_configured` best
/// effort, keep last 1, volatile (on each change only); a best-effort volatile reader matches every
/// writer.
pub const DRIVER_STATE: TopicQos = TopicQos {
    reliability: Reliability::BestEffort,
    durability: Durability::Volatile,
    depth: 10,
};
/// Posture warnings.
pub const WARNINGS: TopicQos = TopicQos {
    reliability: Reliability::Reliable,
    durability: Durability::TransientLocal,
    depth: 20,
};
/// Per-frame ergonomic state and skeleton.
pub const PER_FRAME_STATE: TopicQos = TopicQos {
    reliability: Reliability::Reliable,
    durability: Durability::Volatile,
    depth: 10,
};
