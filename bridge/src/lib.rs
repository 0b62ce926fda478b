//! ROS 2 bridge: the messages and transport between ergocell, the camera nodes and the KUKA controller.
//!
//! - [`msg`]: hand-written ROS 2 message structs in exact IDL field order (std_msgs, sensor_msgs,
//!   trajectory_msgs and the repository's `ros2/ergocell_msgs` package), with their `ros2msg` schema
//!   text for recordings.
//! - [`cdr`]: the ROS 2 wire payload (XCDR1, little-endian, 4-byte encapsulation header).
//! - [`qos`]: the QoS of every topic and why.
//! - [`topics`]: the topic names (the `[ros]` defaults and every recording's);
//!   [`session_info`]: the operator's pseudonymous id a recording carries.
//! - [`transport`]: the `ros2-client` node, the cell's topics and the `[ros]` config table.
//! - [`action`]: control_msgs' FollowJointTrajectory (goal, result, both Feedback layouts);
//!   [`controller`]: the task that runs each goal on the controller and reports what it said.
//!
//! The only library crate that touches the network; it knows nothing of cameras, ergonomics or the
//! robot model — `ergocell_ros_backend::messages` converts between these messages and the library
//! types.

pub mod action;
pub mod cdr;
#[cfg(feature = "transport")]
pub mod controller;
pub mod msg;
pub mod qos;
pub mod scope;
#[cfg(feature = "transport")]
pub mod security;
pub mod session_info;
pub mod topics;
#[cfg(feature = "transport")]
pub mod transport;

/// Everything that can go wrong in the bridge.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[non_exhaustive]
pub enum BridgeError {
    /// A message could not be serialised.
    #[error("CDR encode: {0}")]
    Encode(String),
    /// A payload is not a valid CDR encoding of the expected message.
    #[error("CDR decode: {0}")]
    Decode(String),
    /// The `[ros]` table of the cell config is malformed.
    #[error("[ros] config: {0}")]
    Config(String),
    /// The ROS 2 middleware refused an operation.
    #[error("ROS 2: {0}")]
    Ros(String),
}
