//! Session recordings: MCAP with the `ros2` profile, `ros2msg` schemas and CDR payloads — the layout
//! rosbag2 writes since Iron — so Foxglove, `ros2 bag play` and `rosbags` open them.
//!
//! Crash safety: messages go into chunks that are closed and flushed to the file at least once per
//! second of log time, so a killed process leaves every chunk up to the last second readable (an MCAP
//! reader recovers a file without its summary; `mcap recover` rewrites one). A normal end writes the
//! summary and the footer.
//!
//! What is recorded is what the cell publishes: [`record`] writes a step's
//! [`Outgoing`](crate::messages::Outgoing) messages under the topic names of
//! [`ergocell_bridge::topics`].

use std::collections::BTreeMap;
use std::fs::File;
use std::io::BufWriter;
use std::path::Path;

use ergocell_bridge::cdr;
use ergocell_bridge::msg::RosMessage;
use ergocell_bridge::session_info::{self, OperatorId};

pub use ergocell_bridge::topics;

/// A recording could not be written or read.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum RecordingError {
    #[error("{path}: {source}")]
    Io {
        path: String,
        source: std::io::Error,
    },
    #[error("MCAP: {0}")]
    Mcap(#[from] mcap::McapError),
    #[error(transparent)]
    Bridge(#[from] ergocell_bridge::BridgeError),
}

/// The compression of a recording's chunks, as MCAP names it.
pub const COMPRESSION: &str = "zstd";
const COMPRESSION_KIND: mcap::Compression = mcap::Compression::Zstd;

/// Writes one session's MCAP file.
pub struct McapRecorder {
    writer: mcap::Writer<BufWriter<File>>,
    schemas: BTreeMap<String, u16>,
    channels: BTreeMap<String, u16>,
    sequence: u32,
    last_flush_nanos: Option<i64>,
    /// The newest log time written: a message stamped earlier (a joint state the monitor task
    /// noted before the loop recorded a later step) is logged at this time, so the file's log times
    /// never go back; its publish time keeps its own stamp.
    last_log_nanos: i64,
    messages: u64,
    /// Messages were written since the last flush.
    unflushed: bool,
}

impl McapRecorder {
    /// Creates the file, truncating an existing one. The commands create their recordings with
    /// [`McapRecorder::from_file`] on a file that overwrites only when asked (`--force`).
    pub fn create(path: &Path) -> Result<Self, RecordingError> {
        let file = File::create(path).map_err(|source| RecordingError::Io {
            path: path.display().to_string(),
            source,
        })?;
        Self::from_file(file)
    }

    /// Records into an open, empty file.
    pub fn from_file(file: File) -> Result<Self, RecordingError> {
        let options = mcap::WriteOptions::new()
            .profile("ros2")
            // zstd, as rosbag2 and Foxglove write: a chunk is closed (compressed and written) at
            // least every second by `tick`, so a crash loses at most that second.
            .compression(Some(COMPRESSION_KIND))
            // in the writing thread: no compression workers beside the session loop (a second's
            // chunk takes about a millisecond)
            .compression_threads(0)
            .library(concat!("ergocell ", env!("CARGO_PKG_VERSION")));
        let writer = options.create(BufWriter::new(file))?;
        let mut rec = Self {
            writer,
            schemas: BTreeMap::new(),
            channels: BTreeMap::new(),
            sequence: 0,
            last_flush_nanos: None,
            last_log_nanos: 0,
            messages: 0,
            unflushed: false,
        };
        // The header on disk at once: a file killed before its first message is still an MCAP file.
        rec.writer.flush()?;
        Ok(rec)
    }

    /// Called on the session's clock whether or not messages arrive: whatever was written more than
    /// a second ago is flushed, so a kill -9 loses at most the last second, however quiet the cell.
    pub fn tick(&mut self, now_nanos: i64) -> Result<(), RecordingError> {
        let last = *self.last_flush_nanos.get_or_insert(now_nanos);
        if self.unflushed && now_nanos - last >= 1_000_000_000 {
            self.flush(now_nanos)?;
        }
        Ok(())
    }

    /// Records who the recording serves: the operator's pseudonymous id, as the MCAP metadata record
    /// [`session_info::METADATA_NAME`] (read back by the review and `ergocell exposure`).
    pub fn write_operator(&mut self, operator: &OperatorId) -> Result<(), RecordingError> {
        self.writer.write_metadata(&mcap::records::Metadata {
            name: session_info::METADATA_NAME.to_owned(),
            metadata: session_info::metadata(operator),
        })?;
        self.writer.flush()?;
        Ok(())
    }

    /// Messages written so far.
    pub fn messages(&self) -> u64 {
        self.messages
    }

    /// Records `message` on `topic` at `log_time_nanos` (the session clock). The file's log times
    /// never go back: a message stamped before the newest one written is logged at the newest
    /// time, with its own stamp as its publish time.
    pub fn write<M: RosMessage>(
        &mut self,
        topic: &str,
        log_time_nanos: i64,
        message: &M,
    ) -> Result<(), RecordingError> {
        let channel = self.channel::<M>(topic)?;
        let data = cdr::encode(message)?;
        self.sequence = self.sequence.wrapping_add(1);
        let publish_time = u64::try_from(log_time_nanos).unwrap_or(0);
        self.last_log_nanos = self.last_log_nanos.max(log_time_nanos);
        let log_time = u64::try_from(self.last_log_nanos).unwrap_or(0);
        self.writer.write_to_known_channel(
            &mcap::records::MessageHeader {
                channel_id: channel,
                sequence: self.sequence,
                log_time,
                publish_time,
            },
            &data,
        )?;
        self.messages += 1;
        self.unflushed = true;
        let last = *self.last_flush_nanos.get_or_insert(log_time_nanos);
        if log_time_nanos - last >= 1_000_000_000 {
            self.flush(log_time_nanos)?;
        }
        Ok(())
    }

    /// Closes the current chunk and flushes it to the file.
    pub fn flush(&mut self, log_time_nanos: i64) -> Result<(), RecordingError> {
        self.writer.flush()?;
        self.last_flush_nanos = Some(log_time_nanos);
        self.unflushed = false;
        Ok(())
    }

    /// Writes the summary and footer.
    pub fn finish(mut self) -> Result<u64, RecordingError> {
        self.writer.finish()?;
        Ok(self.messages)
    }

    fn channel<M: RosMessage>(&mut self, topic: &str) -> Result<u16, RecordingError> {
        if let Some(id) = self.channels.get(topic) {
            return Ok(*id);
        }
        let type_name = M::type_name();
        let schema = if let Some(id) = self.schemas.get(&type_name) {
            *id
        } else {
            let id = self
                .writer
                .add_schema(&type_name, "ros2msg", M::schema_text().as_bytes())?;
            self.schemas.insert(type_name, id);
            id
        };
        let id = self
            .writer
            .add_channel(schema, topic, "cdr", &BTreeMap::new())?;
        self.channels.insert(topic.to_owned(), id);
        Ok(id)
    }
}

/// Records a step's outgoing messages (from [`crate::messages::step_messages`]).
pub fn record(
    rec: &mut McapRecorder,
    now_nanos: i64,
    messages: &[crate::messages::Outgoing],
) -> Result<(), RecordingError> {
    use crate::messages::Outgoing as O;
    for m in messages {
        match m {
            O::SessionState(m) => rec.write(topics::SESSION_STATE, now_nanos, m)?,
            O::Ergonomics(m) => rec.write(topics::ERGONOMICS, now_nanos, m)?,
            O::Reba(m) => rec.write(topics::REBA, now_nanos, m)?,
            O::Warning(m) => rec.write(topics::WARNINGS, now_nanos, m)?,
            O::Skeleton(m) => rec.write(topics::SKELETON, now_nanos, m)?,
            O::OperatorPose(m) => rec.write(topics::OPERATOR_POSE, now_nanos, m)?,
            O::Trajectory(m) => rec.write(topics::JOINT_TRAJECTORY, now_nanos, m)?,
        }
    }
    Ok(())
}

/// Records a step's events (the same messages the cell publishes).
pub fn record_events(
    rec: &mut McapRecorder,
    machine: &ergocell_cell::session::SessionMachine,
    now_nanos: i64,
    events: &[ergocell_cell::session::SessionEvent],
) -> Result<(), RecordingError> {
    record(
        rec,
        now_nanos,
        &crate::messages::step_messages(machine, now_nanos, events),
    )
}

/// The camera landmarks of a recording, as far as it can be read.
#[derive(Debug, Clone, PartialEq)]
pub struct CameraReadout {
    /// `(log time, message)` in file order.
    pub frames: Vec<(u64, ergocell_bridge::msg::CameraLandmarks)>,
    /// Why reading stopped early (a damaged chunk, a file cut mid-chunk), if it did.
    pub damaged: Option<String>,
    /// Camera messages that did not decode (skipped).
    pub undecodable: usize,
}

/// Reads every camera-landmarks message of a recording (`ergocell replay`): a file cut by a crash is
/// read up to its last complete chunk; a damaged record stops the reading and is reported, never
/// silently; an undecodable message is skipped and counted.
///
/// Read front to back, each chunk decompressed whole and checked against its CRC before any of its
/// messages is taken, each record and each decompressed chunk bounded by [`MAX_RECORD_BYTES`]: a
/// compressed chunk (zstd, lz4) cannot unpack into more memory than that.
pub fn read_camera_landmarks(bytes: &[u8]) -> Result<CameraReadout, RecordingError> {
    use mcap::sans_io::{LinearReadEvent, LinearReader, LinearReaderOptions};
    if !bytes.starts_with(mcap::MAGIC) {
        return Err(RecordingError::Mcap(mcap::McapError::BadMagic));
    }
    // each chunk checked whole before its records are taken: a damaged one gives no frame
    let options = LinearReaderOptions::default()
        .with_skip_end_magic(true)
        .with_validate_chunk_crcs(true)
        .with_prevalidate_chunk_crcs(true)
        .with_record_length_limit(MAX_RECORD_BYTES);
    let mut linear = LinearReader::new_with_options(options);
    let mut out = CameraReadout {
        frames: Vec::new(),
        damaged: None,
        undecodable: 0,
    };
    // channel id → whether it carries a camera's landmarks
    let mut cameras: BTreeMap<u16, bool> = BTreeMap::new();
    let mut rest = bytes;
    while let Some(event) = linear.next_event() {
        let record = match event {
            Err(e) => {
                out.damaged = Some(e.to_string());
                break;
            }
            Ok(LinearReadEvent::ReadRequest(need)) => {
                let n = need.min(rest.len());
                linear.insert(n).copy_from_slice(&rest[..n]);
                linear.notify_read(n);
                rest = &rest[n..];
                continue;
            }
            Ok(LinearReadEvent::Record { opcode, data }) => mcap::parse_record(opcode, data),
        };
        match record {
            Err(e) => {
                out.damaged = Some(e.to_string());
                break;
            }
            Ok(mcap::records::Record::Channel(c)) => {
                cameras.insert(c.id, topics::camera_id(&c.topic).is_some());
            }
            Ok(mcap::records::Record::Message { header, data }) => {
                match cameras.get(&header.channel_id) {
                    Some(true) => {
                        match cdr::decode::<ergocell_bridge::msg::CameraLandmarks>(&data) {
                            Ok(lm) => out.frames.push((header.log_time, lm)),
                            Err(_) => out.undecodable += 1,
                        }
                    }
                    Some(false) => {}
                    None => {
                        out.damaged = Some(format!(
                            "a message on channel {} that no channel record declared",
                            header.channel_id
                        ));
                        break;
                    }
                }
            }
            // the summary repeats the channels; nothing after the data section is needed
            Ok(mcap::records::Record::DataEnd(_)) => break,
            Ok(_) => {}
        }
    }
    Ok(out)
}

/// The largest record, or decompressed chunk, [`read_camera_landmarks`] takes: a damaged length
/// field, or a compressed chunk that would unpack into more, stops the reading instead.
pub const MAX_RECORD_BYTES: usize = 256 << 20;

/// A session's recording that cannot stop silently: the recorder while it works and its first write
/// error, after which nothing more is written. The cell loop asks for the failure
/// ([`Recording::new_failure`]) and ends the session, held: a cell that records must not run on
/// unrecorded.
pub struct Recording {
    recorder: Option<McapRecorder>,
    failure: Option<ergocell_cell::session::Cause>,
    reported: bool,
}

impl Recording {
    /// Recording into `recorder`, or not recording at all (`None`).
    pub fn new(recorder: Option<McapRecorder>) -> Self {
        Self {
            recorder,
            failure: None,
            reported: false,
        }
    }

    /// Recording, and nothing has failed.
    pub fn is_on(&self) -> bool {
        self.recorder.is_some() && self.failure.is_none()
    }

    /// Runs one write; its error is kept (logged once) instead of ending the caller's loop unheld.
    pub fn with(&mut self, write: impl FnOnce(&mut McapRecorder) -> Result<(), RecordingError>) {
        if !self.is_on() {
            return;
        }
        if let Some(rec) = self.recorder.as_mut() {
            if let Err(e) = write(rec) {
                // the whole chain: "MCAP: I/O error …: No space left on device (os error 28)"
                tracing::error!(error = %ergocell_cell::error::chain(&e), "the recording cannot be written");
                self.failure = Some(std::sync::Arc::new(e));
            }
        }
    }

    /// The failure, the first time it is asked for after it happened.
    pub fn new_failure(&mut self) -> Option<ergocell_cell::session::OutputError> {
        if self.reported {
            return None;
        }
        let cause = self.failure.clone()?;
        self.reported = true;
        Some(ergocell_cell::session::OutputError {
            output: "recording",
            cause,
        })
    }

    /// Closes the recording with its summary and footer: the messages written, or `None` when there
    /// was no recording or it failed (what reached the disk stays readable, without its footer).
    pub fn close(self) -> Result<Option<u64>, RecordingError> {
        if self.failure.is_some() {
            return Ok(None);
        }
        self.recorder.map(McapRecorder::finish).transpose()
    }

    /// Whether a write failed.
    pub fn failed(&self) -> bool {
        self.failure.is_some()
    }
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)]
    use super::*;
    use ergocell_bridge::msg::{Header, JointState};

    /// A message noted before the newest one written (the monitor task's joint state, recorded by
    /// the loop after a later step) keeps its stamp as publish time; the log times never go back.
    #[test]
    fn log_times_never_go_back_and_publish_times_keep_the_stamp() {
        let dir = std::env::temp_dir().join(format!("ergocell-rec-order-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let path = dir.join("order.mcap");
        let mut rec = McapRecorder::create(&path).unwrap();
        for t in [5_000, 3_000, 7_000, 6_000] {
            let js = JointState {
                header: Header::new(t, ""),
                ..JointState::default()
            };
            rec.write("/joint_states", t, &js).unwrap();
        }
        rec.finish().unwrap();
        let bytes = std::fs::read(&path).unwrap();
        let times: Vec<(u64, u64)> = mcap::MessageStream::new(&bytes)
            .unwrap()
            .map(|m| {
                let m = m.unwrap();
                (m.log_time, m.publish_time)
            })
            .collect();
        assert_eq!(
            times,
            [
                (5_000, 5_000),
                (5_000, 3_000),
                (7_000, 7_000),
                (7_000, 6_000)
            ]
        );
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
