//! The `ergocell` binary's library half: the cell controller's session state machine and its
//! recording, shared by the `demo`, `run` and `replay` commands and by the integration tests.
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
