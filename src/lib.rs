//! The `ergocell` binary's library half: the I/O around the cell's core (the session state machine
//! lives in `ergocell_cell` and is re-exported as [`session`], with the file-reading trajectory
//! provider and the simulated landmark source beside it), the core ↔ ROS message conversions
//! ([`messages`]), the MCAP recorder, the operator display and review servers, the shipped reference
//! cell; shared by the commands and by the integration tests.
//!
//! `anyhow` stays in the command modules of the binary; this half returns typed errors.

pub mod display;
pub mod fuzzing;
pub mod messages;
pub mod recording;
pub mod review_server;
pub mod robot_markers;
pub mod session;
pub mod shipped;
pub mod sim_record;
