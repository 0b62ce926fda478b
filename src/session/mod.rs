//! The session's backends that do I/O, around the core in `ergocell_cell::session` (re-exported here,
//! so `ergocell::session::SessionMachine` is the one machine): trajectories read and verified from
//! the files ([`provider`]) and the simulator as a landmark source ([`sim`]).

pub mod provider;
pub mod sim;

pub use ergocell_cell::session::*;
