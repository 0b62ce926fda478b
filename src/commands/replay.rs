//! `ergocell replay --ros`: a recording's camera landmarks published over ROS 2 as the Jetsons
//! would, re-stamped with the capture time now and paced as recorded (`--speed`). The node is
//! `run`'s (the same `[ros]`, network scope and SROS2 enclave rules).

use std::path::PathBuf;

use ergocell_bridge::transport::RosConfig;
use ergocell_ros_backend::recording;
use ergocell_ros_backend::replay::publish_paced;

use super::ros_node::{runtime, say, StartedNode};
use super::UsageError;
use ergocell_bridge::scope::multicast_note;

/// `replay --speed` bounds.
const SPEED_RANGE: std::ops::RangeInclusive<f64> = 0.01..=100.0;

#[derive(Debug, clap::Args)]
pub struct ReplayArgs {
    /// An MCAP recording (e.g. from `ergocell demo`).
    pub recording: PathBuf,
    /// Publish the camera landmarks over ROS 2 (the only output so far; required).
    #[arg(long)]
    pub ros: bool,
    /// Cell configuration with the `[ros]` table.
    #[arg(long, default_value = "config/cell.toml")]
    pub config: PathBuf,
    /// Playback speed factor (1 = as recorded; 0.01..=100).
    #[arg(long, default_value_t = 1.0)]
    pub speed: f64,
    /// SROS2 keystore (DDS Security, enclave `/ergocell/replay`, or ROS_SECURITY_ENCLAVE_OVERRIDE);
    /// default ROS_SECURITY_KEYSTORE, then `[ros] keystore`.
    #[arg(long)]
    pub keystore: Option<PathBuf>,
}

pub fn replay(args: &ReplayArgs) -> anyhow::Result<()> {
    if !args.ros {
        return Err(UsageError("replay publishes over ROS 2: pass --ros".to_owned()).into());
    }
    if !SPEED_RANGE.contains(&args.speed) {
        return Err(UsageError(format!(
            "--speed {:?}: must be a factor from {} to {}",
            args.speed,
            SPEED_RANGE.start(),
            SPEED_RANGE.end()
        ))
        .into());
    }
    let (cell_text, cell_label) = ergocell::shipped::read_or_shipped(&args.config)?;
    let ros = RosConfig::from_cell_toml(&cell_text)
        .map_err(|e| UsageError(format!("{cell_label}: {e}")))?;
    let bytes = ergocell::input::read(&args.recording, ergocell::input::Kind::Recording)?;
    // Camera messages in log-time order; a recording cut by a crash is read up to its last chunk.
    let recording::CameraReadout {
        mut frames,
        damaged,
        undecodable,
    } = recording::read_camera_landmarks(&bytes)
        .map_err(|e| UsageError(format!("{}: {e}", args.recording.display())))?;
    // A damaged or cut recording is replayed up to where it can be read, and says so.
    if let Some(e) = damaged {
        eprintln!(
            "warning: {}: the recording cannot be read past {} camera messages ({e}); replaying \
             those",
            args.recording.display(),
            frames.len()
        );
    }
    if undecodable > 0 {
        eprintln!(
            "warning: {}: {undecodable} camera messages do not decode as CameraLandmarks and are \
             skipped",
            args.recording.display()
        );
    }
    frames.sort_by_key(|(t, _)| *t);
    if frames.is_empty() {
        return Err(UsageError(format!(
            "{}: no camera landmarks in the recording",
            args.recording.display()
        ))
        .into());
    }
    let mut node = StartedNode::start(
        runtime()?,
        &ros,
        "replay",
        &args.config,
        args.keystore.as_deref(),
        "/ergocell/replay",
    )?;
    say(multicast_note(&node.scope));
    let result = node
        .runtime
        .block_on(publish_paced(&mut node.node, &ros, frames, args.speed));
    if let Ok(sent) = &result {
        println!(
            "replayed {sent} camera messages from {}",
            args.recording.display()
        );
    }
    node.shut_down();
    result.map(drop).map_err(Into::into)
}
