//! Host: the cell's files on this machine's file system, behind the ports the library crates
//! define. The binary's commands and the integration tests use it; it decides what a file may be,
//! never what the cell does with it.
//!
//! - [`input`]: every input file read one way: bounded by kind, folders, devices and pipes refused
//!   or read without hanging, named in every error; lists of images by folder or pattern.
//! - [`output`]: every output file written one way: never over an existing file unless asked
//!   (`--force`), never onto one of the command's inputs or a device, pipe or socket, written
//!   atomically (a temporary file beside it, synced, then moved), a refusal told apart from a
//!   failure ([`output::OutputError`]).
//! - [`detections`]: `triangulate`'s 2D detections (OpenPose folders read frame by frame,
//!   caliscope CSV streamed) and the `video.json` beside each camera's frames, the parsing
//!   `ergocell_formats`'.
//! - [`recordings`]: the session recordings `review` and `report` read: whole, or a long one
//!   streamed twice into an overview, the analysis `ergocell_review`'s.
//! - [`review_files`]: the files `trajectories` reads and writes: the cell, its URDF and
//!   approvers' files as one `ReviewCell`, a class file, a private key, the approvals folder's lock
//!   (`ApprovalsLock`, which also finds what a killed writer left), new files written once.
//! - [`scratch`]: a command's private scratch folder in the temporary folder (the demo's own
//!   approvals), removed on every way out, and those of runs killed outright removed by the next.
//! - [`shipped`]: the reference cell embedded in the binary (rig, cell file, URDF, approvers'
//!   files, trajectories, locks, RULA curves), the defaults that make the binary work from any
//!   directory; a file that exists is always the one read.
//! - [`provider`]: the approvals crate's file port ([`ergocell_approvals::files::CellFiles`]) on
//!   the file system ([`provider::OsFiles`]), and the trajectory provider over it with the wall
//!   clock, the trust anchor and the witness where the site installed them.
//! - [`trust_anchor`]: where the site's approvers authority lives and its one-descriptor read (the
//!   rule about who may own it is `ergocell_approvals::anchor`'s).
//! - [`witness`]: where the witness of the approvals files lives and its synced append (the check
//!   is `ergocell_robot::witness`'s).
//!
//! What it must not do: decide anything about sessions, classes or the robot; speak ROS; run the
//! twin. Like the ROS backend and the web servers it does I/O: this machine's files and clock.

pub mod detections;
pub mod input;
pub mod output;
pub mod provider;
pub mod recordings;
pub mod review_files;
pub mod scratch;
pub mod shipped;
pub mod trust_anchor;
pub mod witness;
