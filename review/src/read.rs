//! An MCAP session recording → the ergocell messages in it.
//!
//! The recorder (`src/recording.rs` in the binary) writes the `ros2` profile with `ros2msg` schemas
//! and CDR payloads, closing a chunk at least once per second of log time. So a file cut short still
//! holds every chunk before the cut: it is read up to there and [`Recording::problems`] says where it
//! ends. A message on an ergocell topic whose schema is not the expected type, or whose payload does
//! not decode, is skipped and counted, never guessed at.

use std::collections::BTreeMap;

use ergocell_bridge::cdr;
use ergocell_bridge::msg::{
    ErgonomicState, MarkerArray, OperatorPose, PostureWarning, RosMessage, SessionState,
};
use serde::de::DeserializeOwned;

use crate::ReviewError;

/// Topics the review reads (the recorder's names).
pub mod topics {
    pub const OPERATOR_POSE: &str = "/ergocell/operator_pose";
    pub const ERGONOMICS: &str = "/ergocell/ergonomics";
    pub const WARNINGS: &str = "/ergocell/warnings";
    pub const SESSION_STATE: &str = "/ergocell/session_state";
    pub const ROBOT_MARKERS: &str = "/ergocell/robot_markers";
}

/// A message and its log time (nanoseconds, the session clock).
#[derive(Debug, Clone, PartialEq)]
pub struct Stamped<M> {
    pub log_time_nanos: u64,
    pub message: M,
}

/// One channel of the file: its schema name and how many messages were read from it.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ChannelInfo {
    pub schema: String,
    pub messages: u64,
}

/// What could be read of one recording.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Recording {
    /// File size, bytes.
    pub bytes: u64,
    /// Messages read (all topics).
    pub messages: u64,
    /// The file ends with its footer and every record before it was read.
    pub complete: bool,
    /// What is wrong with the file, for a person (empty for a clean recording).
    pub problems: Vec<String>,
    /// Log time of the first message read, nanoseconds.
    pub first_log_time_nanos: Option<u64>,
    /// Log time of the last message read, nanoseconds.
    pub last_log_time_nanos: Option<u64>,
    pub poses: Vec<Stamped<OperatorPose>>,
    pub ergonomics: Vec<Stamped<ErgonomicState>>,
    pub warnings: Vec<Stamped<PostureWarning>>,
    pub states: Vec<Stamped<SessionState>>,
    pub robot_markers: Vec<Stamped<MarkerArray>>,
    /// Every channel by topic.
    pub channels: BTreeMap<String, ChannelInfo>,
}

impl Recording {
    /// Messages on the topics the review reads.
    pub fn ergocell_messages(&self) -> usize {
        self.poses.len()
            + self.ergonomics.len()
            + self.warnings.len()
            + self.states.len()
            + self.robot_markers.len()
    }
}

/// Skipped messages of one topic: how many and the first reason.
#[derive(Default)]
struct Skipped {
    count: u64,
    first: String,
}

/// Reads `bytes` (a whole `.mcap` file).
///
/// # Errors
/// [`ReviewError::NotMcap`] when nothing of it reads as MCAP, [`ReviewError::Foreign`] when it is MCAP
/// but holds none of ergocell's topics (the error lists the channels it does hold).
pub fn read_recording(bytes: &[u8]) -> Result<Recording, ReviewError> {
    if !bytes.starts_with(mcap::MAGIC) {
        return Err(ReviewError::NotMcap {
            reason: format!(
                "the file does not start with the MCAP magic bytes ({} bytes long)",
                bytes.len()
            ),
        });
    }
    let options = enumset::EnumSet::only(mcap::read::Options::IgnoreEndMagic);
    let stream = mcap::read::MessageStream::new_with_options(bytes, options).map_err(|e| {
        ReviewError::NotMcap {
            reason: e.to_string(),
        }
    })?;
    let mut rec = Recording {
        bytes: bytes.len() as u64,
        complete: true,
        ..Recording::default()
    };
    let mut skipped: BTreeMap<String, Skipped> = BTreeMap::new();
    for item in stream {
        let m = match item {
            Ok(m) => m,
            Err(e) => {
                rec.complete = false;
                let at = rec.last_log_time_nanos.map_or_else(
                    || "before the first message".to_owned(),
                    |t| {
                        format!(
                            "after {:.1} s of recording",
                            t.saturating_sub(rec.first_log_time_nanos.unwrap_or(t)) as f64 * 1e-9
                        )
                    },
                );
                rec.problems.push(format!(
                    "the recording is cut short: it could be read only up to {at} ({} messages); the rest is unreadable ({e})",
                    rec.messages
                ));
                break;
            }
        };
        rec.messages += 1;
        rec.first_log_time_nanos = Some(
            rec.first_log_time_nanos
                .map_or(m.log_time, |t| t.min(m.log_time)),
        );
        rec.last_log_time_nanos = Some(
            rec.last_log_time_nanos
                .map_or(m.log_time, |t| t.max(m.log_time)),
        );
        let topic = m.channel.topic.as_str();
        let schema = m
            .channel
            .schema
            .as_ref()
            .map_or_else(String::new, |s| s.name.clone());
        rec.channels
            .entry(topic.to_owned())
            .or_insert_with(|| ChannelInfo {
                schema: schema.clone(),
                messages: 0,
            })
            .messages += 1;
        let t = m.log_time;
        let outcome = match topic {
            topics::OPERATOR_POSE => take(&schema, &m.data, t, &mut rec.poses),
            topics::ERGONOMICS => take(&schema, &m.data, t, &mut rec.ergonomics),
            topics::WARNINGS => take(&schema, &m.data, t, &mut rec.warnings),
            topics::SESSION_STATE => take(&schema, &m.data, t, &mut rec.states),
            topics::ROBOT_MARKERS => take(&schema, &m.data, t, &mut rec.robot_markers),
            _ => Ok(()),
        };
        if let Err(why) = outcome {
            let s = skipped.entry(topic.to_owned()).or_default();
            s.count += 1;
            if s.first.is_empty() {
                s.first = why;
            }
        }
    }
    if rec.complete && !bytes.ends_with(mcap::MAGIC) {
        rec.complete = false;
        rec.problems.push(format!(
            "the file has no MCAP footer: the recording was cut short (a crash or a partial copy); {} messages were read up to its last complete chunk",
            rec.messages
        ));
    }
    for (topic, s) in skipped {
        rec.problems.push(format!(
            "{} message(s) on {topic} skipped: {}",
            s.count, s.first
        ));
    }
    if rec.ergocell_messages() == 0 {
        if rec.messages == 0 && !rec.complete {
            return Err(ReviewError::NotMcap {
                reason: rec.problems.join("; "),
            });
        }
        let channels = if rec.channels.is_empty() {
            "no channels".to_owned()
        } else {
            rec.channels
                .iter()
                .map(|(topic, c)| {
                    format!(
                        "{topic} [{}] × {}",
                        if c.schema.is_empty() {
                            "no schema"
                        } else {
                            &c.schema
                        },
                        c.messages
                    )
                })
                .collect::<Vec<_>>()
                .join(", ")
        };
        return Err(ReviewError::Foreign {
            message_count: rec.messages,
            channels,
        });
    }
    for topic in [
        topics::OPERATOR_POSE,
        topics::ERGONOMICS,
        topics::SESSION_STATE,
    ] {
        if !rec.channels.contains_key(topic) {
            rec.problems.push(format!(
                "no messages on {topic}: the review shows what the other topics hold"
            ));
        }
    }
    Ok(rec)
}

/// Decodes one message of type `M` if the channel's schema names `M`.
fn take<M: RosMessage + DeserializeOwned>(
    schema: &str,
    data: &[u8],
    log_time_nanos: u64,
    into: &mut Vec<Stamped<M>>,
) -> Result<(), String> {
    let expected = M::type_name();
    if schema != expected {
        return Err(format!("schema is {schema:?}, expected {expected}"));
    }
    let message = cdr::decode::<M>(data).map_err(|e| e.to_string())?;
    into.push(Stamped {
        log_time_nanos,
        message,
    });
    Ok(())
}
