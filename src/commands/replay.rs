//! `ergocell replay --ros`: a recording's camera landmarks published over ROS 2 as the Jetsons
//! would, re-stamped with the capture time now and paced as recorded (`--speed`). The node is
//! `run`'s (the same `[ros]`, network scope and SROS2 enclave rules).

use std::path::PathBuf;
use std::time::Duration;

use anyhow::Context as _;
use ergocell_bridge::msg::CameraLandmarks;
use ergocell_bridge::qos;
use ergocell_bridge::transport::{publish, RosConfig, RosNode};
use ergocell_ros_backend::clock::{instant, now_nanos};
use ergocell_ros_backend::recording;

use super::run::{network_scope, say, security_enclave};
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
    let runtime = tokio::runtime::Builder::new_multi_thread()
        .worker_threads(2)
        .enable_all()
        .build()
        .context("tokio runtime")?;
    let scope = network_scope(&ros)?;
    let enclave = security_enclave(
        &ros,
        &args.config,
        args.keystore.as_deref(),
        "/ergocell/replay",
    )?;
    let mut node = RosNode::new(
        ros.domain_id,
        &ros.namespace,
        "replay",
        &scope,
        enclave.as_deref(),
    )?;
    let participant = node.participant();
    runtime.spawn(node.spinner()?);
    say(multicast_note(&scope));
    let result = runtime.block_on(async {
        let mut publishers = std::collections::BTreeMap::new();
        for id in &ros.cameras {
            let p =
                node.publisher::<CameraLandmarks>(&ros.camera_topic_of(id), qos::CAMERA_LANDMARKS)?;
            publishers.insert(id.clone(), p);
        }
        // Give discovery a moment before the first frame.
        tokio::time::sleep(Duration::from_millis(1500)).await;
        let t0_log = frames[0].0;
        let t0 = instant();
        let start = now_nanos();
        let mut sent = 0usize;
        for (log_time, mut m) in frames {
            let offset_secs = log_time.saturating_sub(t0_log) as f64 * 1e-9 / args.speed;
            // Never a panic on a huge offset (a recording spanning centuries at a slow speed).
            let due = Duration::try_from_secs_f64(offset_secs).unwrap_or(Duration::MAX);
            if let Some(wait) = due.checked_sub(t0.elapsed()) {
                tokio::time::sleep(wait).await;
            }
            // Re-stamp as a live camera would: capture time now.
            m.header.stamp =
                ergocell_bridge::msg::Time::from_nanos(start + (offset_secs * 1e9) as i64);
            if let Some(p) = publishers.get(&m.camera_id) {
                publish(p, m).await?;
                sent += 1;
            }
        }
        println!(
            "replayed {sent} camera messages from {}",
            args.recording.display()
        );
        anyhow::Ok(())
    });
    // The node first (it tells the spinner to stop), then a moment for the spinner to finish while
    // the runtime still runs: every reader and writer says goodbye before the DDS participant goes.
    drop(node);
    runtime.block_on(async { tokio::time::sleep(Duration::from_millis(100)).await });
    drop(runtime);
    // the participant last: every entity has been removed from it (RosNode::participant)
    drop(participant);
    result
}
