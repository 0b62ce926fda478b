//! The `ergocell` binary's library half, shared by the commands and by the integration tests: the
//! session state machine and the cell loop (`ergocell_cell`, re-exported as [`session`], with the
//! trajectory provider on this machine's files as [`session::provider`]), the host's files
//! (`ergocell_host`: [`input`], [`output`], [`detections`], [`recordings`], [`shipped`], [`trust_anchor`], [`witness`]), three modules of the
//! ROS 2 backend ([`messages`], [`recording`], [`robot_markers`]), and [`sim_record`], the twin's
//! height recordings. Typed errors only; `anyhow` is the commands'.

pub mod session;
pub mod sim_record;

pub use ergocell_host::{detections, input, output, recordings, shipped, trust_anchor, witness};

pub use ergocell_ros_backend::{messages, recording, robot_markers};
