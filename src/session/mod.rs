//! The session's backends that do I/O, around the core in `ergocell_cell::session` (re-exported here,
//! so `ergocell::session::SessionMachine` is the one machine): trajectories read and verified from
//! the files ([`provider`]). The simulator's landmark source is `ergocell_sim::source::SimSource`.

pub use ergocell_host::provider;

pub use ergocell_cell::session::*;
