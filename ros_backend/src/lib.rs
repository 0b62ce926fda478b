//! The cell's ROS 2 backend: everything between the core (`ergocell_cell`, no ROS) and the network.
//!
//! - [`cameras`]: the camera topics' messages checked into views ([`cameras::CameraInbox`]).
//! - [`messages`]: every core ↔ ROS message conversion, and [`messages::step_messages`], the one
//!   mapping from a step's events to the messages the cell sends (published and recorded alike).
//! - [`recording`]: the MCAP recorder (rosbag2's layout) and [`recording::Recording`], a recording
//!   whose first failure is kept for the cell loop to end the session on.
//! - [`robot`]: the robot sink over ROS 2 ([`robot::RosRobot`]: the joint trajectory topic or a
//!   FollowJointTrajectory goal per leg, the hold as cancel + empty trajectory), and the robot
//!   side's messages turned into the cell's reports ([`robot::reports_of`]).
//! - [`monitor`]: the execution monitor's own task: every `/joint_states` sample judged against the
//!   locked leg as it arrives, the hold published at once on a deviation.
//! - [`outputs`]: the cell's publishers and recorder as one [`ergocell_cell::session::CellOutputs`].
//! - [`clock`]: the wall clock at this boundary, advanced monotonically ([`clock::SessionClock`]).
//! - [`robot_markers`]: the robot's TCP and handover point for the recording's markers.
//! - [`replay`]: a recording's camera landmarks published again, paced as recorded.
//! - [`station`]: `run`'s station, the cell's inputs on ROS 2 handed to the session driver one at a
//!   time; [`console`]: what `run` and `demo` say (`run`'s start, the sessions' summaries, the
//!   monitor's and the steps' timings; the demo's events and summary) as text.
//! - [`twin_recording`]: the twin's sessions recorded as a cell records its own.
//!
//! The binary's `run` composes these around [`ergocell_cell::session::CellLoop`]; the topics, QoS,
//! node and security are `ergocell_bridge`'s. What it must not do: decide (what a robot report
//! means, when the robot is held, which class serves an operator are the cell's rules), run the
//! twin, calibrate, or serve web pages. Its I/O is the network, the wall clock and the recording
//! file.

pub mod cameras;
pub mod clock;
pub mod console;
pub mod messages;
pub mod monitor;
pub mod outputs;
pub mod recording;
pub mod replay;
pub mod robot;
pub mod robot_markers;
pub mod station;
pub mod twin_recording;
