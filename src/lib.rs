//! The `ergocell` binary's library half: the I/O around the cell's core that is not ROS (the session
//! state machine and the cell loop live in `ergocell_cell` and are re-exported as [`session`], with
//! the approvals crate's file port on this machine beside it: [`session::provider`], the trust
//! anchor's place and read, [`trust_anchor`], the witness's place and append, [`witness`]), the
//! shipped reference cell; shared by the commands and by the integration tests. The operator
//! display and the review server are `ergocell_web`'s. The ROS 2 backend
//! (message conversions, the MCAP recorder, the robot sink and its monitor) is
//! `ergocell_ros_backend`; three of its modules are re-exported here as [`messages`], [`recording`]
//! and [`robot_markers`].
//!
//! This half returns typed errors, except [`shipped::read_or_shipped`] (a file or its shipped copy,
//! for the commands), which returns `anyhow`'s.

pub mod input;
pub mod session;
pub mod shipped;
pub mod sim_record;
pub mod trust_anchor;
pub mod witness;

pub use ergocell_ros_backend::{messages, recording, robot_markers};
