//! `ergocell replay --ros`: a recording's camera landmarks published as the edge cameras would,
//! each re-stamped with its capture time now and paced as recorded, faster or slower by a factor.

use std::collections::BTreeMap;
use std::time::Duration;

use ergocell_bridge::msg::{CameraLandmarks, Time};
use ergocell_bridge::qos;
use ergocell_bridge::transport::{publish, RosConfig, RosNode};
use ergocell_bridge::BridgeError;

use crate::clock::{instant, now_nanos};

/// How long discovery is given before the first frame.
pub const DISCOVERY_WAIT: Duration = Duration::from_millis(1500);

/// When a message logged at `log_nanos` is due, from the first one's `first_log_nanos`, played
/// `speed` times as fast as recorded: seconds after the start (a log time before the first counts
/// as the start).
pub fn offset_secs(log_nanos: u64, first_log_nanos: u64, speed: f64) -> f64 {
    log_nanos.saturating_sub(first_log_nanos) as f64 * 1e-9 / speed
}

/// The offset as a wait; never a panic on a huge one (a recording spanning centuries played slow).
pub fn due(offset_secs: f64) -> Duration {
    Duration::try_from_secs_f64(offset_secs).unwrap_or(Duration::MAX)
}

/// Why a replay stopped.
#[derive(Debug, thiserror::Error)]
pub enum ReplayError {
    /// The speed factor is not a positive finite number.
    #[error("speed {0:?}: must be a positive factor")]
    BadSpeed(f64),
    /// Publishing failed.
    #[error(transparent)]
    Bridge(#[from] BridgeError),
}

/// Publishes `frames` (log time, message; in log-time order) on the camera topics of `ros`, paced
/// at `speed` and re-stamped with the capture time now, after [`DISCOVERY_WAIT`]. A message of a
/// camera `[ros]` does not list is skipped. Returns how many were sent.
pub async fn publish_paced(
    node: &mut RosNode,
    ros: &RosConfig,
    frames: Vec<(u64, CameraLandmarks)>,
    speed: f64,
) -> Result<usize, ReplayError> {
    if !(speed.is_finite() && speed > 0.0) {
        return Err(ReplayError::BadSpeed(speed));
    }
    let mut publishers = BTreeMap::new();
    for id in &ros.cameras {
        let p =
            node.publisher::<CameraLandmarks>(&ros.camera_topic_of(id), qos::CAMERA_LANDMARKS)?;
        publishers.insert(id.clone(), p);
    }
    tokio::time::sleep(DISCOVERY_WAIT).await;
    let Some(&(first_log, _)) = frames.first() else {
        return Ok(0);
    };
    let t0 = instant();
    let start = now_nanos();
    let mut sent = 0usize;
    for (log_time, mut m) in frames {
        let offset = offset_secs(log_time, first_log, speed);
        if let Some(wait) = due(offset).checked_sub(t0.elapsed()) {
            tokio::time::sleep(wait).await;
        }
        // Re-stamp as a live camera would: capture time now.
        m.header.stamp = Time::from_nanos(start + (offset * 1e9) as i64);
        if let Some(p) = publishers.get(&m.camera_id) {
            publish(p, m).await?;
            sent += 1;
        }
    }
    Ok(sent)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn offsets_are_scaled_by_the_speed_and_never_negative_or_a_panic() {
        assert_eq!(offset_secs(3_000_000_000, 1_000_000_000, 1.0), 2.0);
        assert_eq!(offset_secs(3_000_000_000, 1_000_000_000, 2.0), 1.0);
        assert_eq!(offset_secs(3_000_000_000, 1_000_000_000, 0.5), 4.0);
        assert_eq!(offset_secs(0, 1_000_000_000, 1.0), 0.0);
        assert_eq!(due(2.5), Duration::from_millis(2500));
        assert_eq!(due(f64::MAX), Duration::MAX);
        assert!(offset_secs(u64::MAX, 0, 0.01) > 0.0);
    }
}
