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
    ControllerEvent, ErgonomicState, JointTrajectory, MarkerArray, OperatorPose, PostureWarning,
    RebaState, RosMessage, SessionState,
};
use ergocell_bridge::session_info;
use serde::de::DeserializeOwned;

use crate::legacy::{
    take_controller_event, take_ergonomic_state, take_posture_warning, take_session_state,
};
use crate::ReviewError;

/// Topics the review reads: the recorder's names, from the one table in the bridge.
pub use ergocell_bridge::topics;

/// A message and its log time (nanoseconds, the session clock).
#[derive(Debug, Clone, PartialEq)]
pub struct Stamped<M> {
    /// The time the message is read at: its log time, or its capture stamp where the recording's
    /// clock disagreed with it ([`MAX_LOG_CLOCK_DISAGREEMENT_NANOS`]).
    pub log_time_nanos: u64,
    /// The log time as the file has it (what [`Visit::wants_at`] was asked with).
    pub logged_nanos: u64,
    pub message: M,
}

/// One channel of the file: its schema name and how many messages were read from it.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ChannelInfo {
    pub schema: String,
    pub messages: u64,
}

/// One decoded message of the session's topics.
#[derive(Debug, Clone, PartialEq)]
pub enum Decoded {
    Pose(Stamped<OperatorPose>),
    Ergonomics(Stamped<ErgonomicState>),
    Reba(Stamped<RebaState>),
    Warning(Stamped<PostureWarning>),
    State(Stamped<SessionState>),
    RobotMarkers(Stamped<MarkerArray>),
    Trajectory(Stamped<JointTrajectory>),
    ControllerEvent(Stamped<ControllerEvent>),
}

/// A message is logged when the cell handles it, milliseconds to a second after its capture; a log
/// time further than this from the message's own capture stamp is the recording's clock
/// disagreeing with the cameras' (a clock stepped, a file rewritten with one time for every
/// message), and the message is read by its capture stamp.
pub const MAX_LOG_CLOCK_DISAGREEMENT_NANOS: u64 = 10_000_000_000;

impl Decoded {
    /// The capture stamp in the message's header (a marker array's first marker's), nanoseconds;
    /// `None` when it has none or it is zero or negative.
    pub fn capture_stamp_nanos(&self) -> Option<u64> {
        let header = match self {
            Self::Pose(m) => Some(&m.message.header),
            Self::Ergonomics(m) => Some(&m.message.header),
            Self::Reba(m) => Some(&m.message.header),
            Self::Warning(m) => Some(&m.message.header),
            Self::State(m) => Some(&m.message.header),
            Self::RobotMarkers(m) => m.message.markers.first().map(|k| &k.header),
            Self::Trajectory(m) => Some(&m.message.header),
            Self::ControllerEvent(m) => Some(&m.message.header),
        }?;
        u64::try_from(header.stamp.to_nanos())
            .ok()
            .filter(|&t| t > 0)
    }

    /// Reads the message at `nanos` instead of its log time.
    fn set_log_time(&mut self, nanos: u64) {
        match self {
            Self::Pose(m) => m.log_time_nanos = nanos,
            Self::Ergonomics(m) => m.log_time_nanos = nanos,
            Self::Reba(m) => m.log_time_nanos = nanos,
            Self::Warning(m) => m.log_time_nanos = nanos,
            Self::State(m) => m.log_time_nanos = nanos,
            Self::RobotMarkers(m) => m.log_time_nanos = nanos,
            Self::Trajectory(m) => m.log_time_nanos = nanos,
            Self::ControllerEvent(m) => m.log_time_nanos = nanos,
        }
    }

    /// The log time as the file has it, nanoseconds ([`Stamped::logged_nanos`]).
    pub fn logged_nanos(&self) -> u64 {
        match self {
            Self::Pose(m) => m.logged_nanos,
            Self::Ergonomics(m) => m.logged_nanos,
            Self::Reba(m) => m.logged_nanos,
            Self::Warning(m) => m.logged_nanos,
            Self::State(m) => m.logged_nanos,
            Self::RobotMarkers(m) => m.logged_nanos,
            Self::Trajectory(m) => m.logged_nanos,
            Self::ControllerEvent(m) => m.logged_nanos,
        }
    }

    /// The message's log time, nanoseconds (the session clock).
    pub fn log_time_nanos(&self) -> u64 {
        match self {
            Self::Pose(m) => m.log_time_nanos,
            Self::Ergonomics(m) => m.log_time_nanos,
            Self::Reba(m) => m.log_time_nanos,
            Self::Warning(m) => m.log_time_nanos,
            Self::State(m) => m.log_time_nanos,
            Self::RobotMarkers(m) => m.log_time_nanos,
            Self::Trajectory(m) => m.log_time_nanos,
            Self::ControllerEvent(m) => m.log_time_nanos,
        }
    }
}

/// What a reader hands the recording to, message by message ([`read_recording`] collects it all
/// into a [`Recording`]; [`stream_recording`] hands it on without keeping it).
pub trait Visit {
    /// Whether to decode the messages of `topic` (those not wanted are counted, never decoded).
    fn wants(&self, _topic: &str) -> bool {
        true
    }
    /// Whether to decode this one message of `topic`, logged at `log_time_nanos` (by default, as
    /// [`Visit::wants`] says for its topic). A message not wanted is counted, never decoded, so what
    /// is wrong with it is not found either.
    fn wants_at(&mut self, topic: &str, _log_time_nanos: u64) -> bool {
        self.wants(topic)
    }
    /// An MCAP metadata record (e.g. [`ergocell_bridge::session_info::METADATA_NAME`]).
    fn metadata(&mut self, _name: &str, _entries: &BTreeMap<String, String>) {}
    /// A message on one of the session's topics, decoded.
    fn message(&mut self, message: Decoded);
}

/// What a reader found, apart from the messages: the file's size, how far it read, its channels.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct ReadStats {
    /// Bytes read.
    pub bytes: u64,
    /// Messages read (all topics).
    pub messages: u64,
    /// The file ends with its footer and every record before it was read.
    pub complete: bool,
    /// What is wrong with the file, for a person (empty for a clean recording).
    pub problems: Vec<String>,
    pub first_log_time_nanos: Option<u64>,
    pub last_log_time_nanos: Option<u64>,
    /// Every channel by topic.
    pub channels: BTreeMap<String, ChannelInfo>,
    /// Messages on the session's topics (operator, RULA, warnings, states, robot markers) that were
    /// decoded or not asked for.
    pub session_messages: u64,
    /// Messages read by their capture stamp because their log time disagreed with it
    /// ([`MAX_LOG_CLOCK_DISAGREEMENT_NANOS`]); one of [`ReadStats::problems`] names them.
    pub clock_disagreements: u64,
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
    /// REBA beside RULA (`/ergocell/reba`); empty in a recording made before REBA.
    pub reba: Vec<Stamped<RebaState>>,
    pub warnings: Vec<Stamped<PostureWarning>>,
    pub states: Vec<Stamped<SessionState>>,
    pub robot_markers: Vec<Stamped<MarkerArray>>,
    /// The robot commands (`/joint_trajectory_controller/joint_trajectory`): each leg, and each hold
    /// (an empty trajectory).
    pub trajectories: Vec<Stamped<JointTrajectory>>,
    /// What the robot side did (`/ergocell/controller_events`): the controller's answers, the
    /// execution monitor's verdicts, the driver's state.
    pub controller_events: Vec<Stamped<ControllerEvent>>,
    /// Every channel by topic.
    pub channels: BTreeMap<String, ChannelInfo>,
    /// The operator's pseudonymous id, when the recording names one
    /// ([`ergocell_bridge::session_info`]).
    pub operator: Option<String>,
}

impl Visit for Recording {
    fn metadata(&mut self, name: &str, entries: &BTreeMap<String, String>) {
        operator_metadata(&mut self.operator, &mut self.problems, name, entries);
    }

    fn message(&mut self, message: Decoded) {
        match message {
            Decoded::Pose(m) => self.poses.push(m),
            Decoded::Ergonomics(m) => self.ergonomics.push(m),
            Decoded::Reba(m) => self.reba.push(m),
            Decoded::Warning(m) => self.warnings.push(m),
            Decoded::State(m) => self.states.push(m),
            Decoded::RobotMarkers(m) => self.robot_markers.push(m),
            Decoded::Trajectory(m) => self.trajectories.push(m),
            Decoded::ControllerEvent(m) => self.controller_events.push(m),
        }
    }
}

/// Reads the operator's id from a metadata record named [`session_info::METADATA_NAME`]; a
/// malformed id is a problem, never an id.
fn operator_metadata(
    operator: &mut Option<String>,
    problems: &mut Vec<String>,
    name: &str,
    entries: &BTreeMap<String, String>,
) {
    if name != session_info::METADATA_NAME {
        return;
    }
    match session_info::operator_of(entries) {
        Ok(Some(id)) => *operator = Some(id.to_string()),
        Ok(None) => {}
        Err(e) => problems.push(format!("the recording's operator is left out: {e}")),
    }
}

impl Recording {
    /// Messages on the session's topics (the operator, RULA, warnings, states, robot markers): the
    /// robot's commands and controller events alone make no reviewable session.
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
/// A file with its summary is read chunk by chunk through the summary's chunk index, each chunk's
/// CRC checked: a damaged chunk is skipped and named, the rest is read. A file without a summary (cut
/// short) is read linearly up to the first unreadable record.
///
/// # Errors
/// [`ReviewError::NotMcap`] when nothing of it reads as MCAP, [`ReviewError::Foreign`] when it is MCAP
/// but holds none of ergocell's topics (the error lists the channels it does hold).
pub fn read_recording(bytes: &[u8]) -> Result<Recording, ReviewError> {
    let mut rec = Recording::default();
    let stats = read_into(bytes, &mut rec)?;
    let own_problems = std::mem::take(&mut rec.problems);
    Ok(Recording {
        bytes: stats.bytes,
        messages: stats.messages,
        complete: stats.complete,
        problems: stats.problems.into_iter().chain(own_problems).collect(),
        first_log_time_nanos: stats.first_log_time_nanos,
        last_log_time_nanos: stats.last_log_time_nanos,
        channels: stats.channels,
        ..rec
    })
}

/// Reads `bytes` (a whole `.mcap` file) as [`read_recording`] does, handing each message to
/// `visitor`.
///
/// # Errors
/// As [`read_recording`].
pub fn read_into<V: Visit>(bytes: &[u8], visitor: &mut V) -> Result<ReadStats, ReviewError> {
    if !bytes.starts_with(mcap::MAGIC) {
        return Err(ReviewError::NotMcap {
            reason: format!(
                "the file does not start with the MCAP magic bytes ({} bytes long)",
                bytes.len()
            ),
        });
    }
    if bytes.len() <= mcap::MAGIC.len() * 2 {
        return Err(ReviewError::NotMcap {
            reason: format!(
                "{} bytes: the MCAP magic and no header or records",
                bytes.len()
            ),
        });
    }
    let summary = mcap::Summary::read(bytes).ok().flatten();
    match summary {
        Some(summary) if !summary.chunk_indexes.is_empty() => {
            let mut reader = Reader::new(visitor);
            reader.rec.bytes = bytes.len() as u64;
            for (name, entries) in metadata_records(bytes, &summary) {
                reader.visitor.metadata(&name, &entries);
            }
            reader.read_chunks(bytes, &summary);
            reader.finish()
        }
        // Front to back, as a stream is read: each record's size bounded, so a compressed chunk
        // cannot unpack into more memory than that.
        _ => stream_recording(bytes, visitor),
    }
}

/// The metadata records a summary indexes (unreadable ones left out).
fn metadata_records(
    bytes: &[u8],
    summary: &mcap::Summary,
) -> Vec<(String, BTreeMap<String, String>)> {
    summary
        .metadata_indexes
        .iter()
        .filter_map(|index| {
            let start = usize::try_from(index.offset).ok()?.checked_add(9)?;
            let end = usize::try_from(index.offset.checked_add(index.length)?).ok()?;
            match mcap::parse_record(mcap::records::op::METADATA, bytes.get(start..end)?) {
                Ok(mcap::records::Record::Metadata(m)) => Some((m.name, m.metadata)),
                _ => None,
            }
        })
        .collect()
}

/// Reads a recording from `source` front to back, never holding more of it than a few batches of
/// records, and hands each message to `visitor`: memory does not grow with the file. Each chunk's CRC is
/// checked; a file cut short (a crash, a partial copy) is read up to its last complete record and
/// says so in [`ReadStats::problems`].
///
/// Two threads: one reads `source`, decompresses its chunks and splits them into records
/// (`read_batches`), the calling one decodes the messages and visits them; between them are at most
/// four or five batches of 4 MiB or 4,096 records (a single record may reach the 256 MiB bound).
///
/// # Errors
/// As [`read_recording`]; an error reading `source` is [`ReviewError::NotMcap`] with its reason.
pub fn stream_recording<R: std::io::Read + Send, V: Visit>(
    source: R,
    visitor: &mut V,
) -> Result<ReadStats, ReviewError> {
    let mut reader = Reader::new(visitor);
    let mut schemas: BTreeMap<u16, String> = BTreeMap::new();
    let mut channels: BTreeMap<u16, (String, String)> = BTreeMap::new();
    let mut past_data_end = false;
    let mut failure: Option<String> = None;
    // A chunk compressed with what this build does not decompress: said so, with the way out.
    let mut unsupported = false;
    std::thread::scope(|scope| -> Result<(), ReviewError> {
        let (tx, rx) = std::sync::mpsc::sync_channel(2);
        // Batches go back to the reading thread to be filled again: their buffers are allocated
        // once, and freed by the thread that allocated them.
        let (free_tx, free_rx) = std::sync::mpsc::channel();
        scope.spawn(move || read_batches(source, &tx, &free_rx));
        // Leaving this loop early drops `rx`: the reading thread stops at its next batch.
        'batches: for mut batch in rx {
            reader.rec.bytes += batch.bytes;
            for (opcode, range) in &batch.records {
                if past_data_end {
                    break;
                }
                let record = match mcap::parse_record(*opcode, &batch.data[range.clone()]) {
                    Ok(r) => r,
                    Err(e) => {
                        failure = Some(e.to_string());
                        break 'batches;
                    }
                };
                match record {
                    mcap::records::Record::Schema { header, .. } => {
                        schemas.insert(header.id, header.name);
                    }
                    mcap::records::Record::Channel(c) => {
                        let schema = schemas.get(&c.schema_id).cloned().unwrap_or_default();
                        channels.insert(c.id, (c.topic, schema));
                    }
                    mcap::records::Record::Message { header, data } => {
                        let Some((topic, schema)) = channels.get(&header.channel_id) else {
                            failure = Some(format!(
                                "a message on channel {} that no channel record declared",
                                header.channel_id
                            ));
                            break 'batches;
                        };
                        reader.take_message(topic, schema, header.log_time, &data);
                    }
                    mcap::records::Record::Metadata(m) => {
                        reader.visitor.metadata(&m.name, &m.metadata);
                    }
                    mcap::records::Record::DataEnd(_) => past_data_end = true,
                    _ => {}
                }
            }
            match batch.end.take() {
                None => {}
                Some(End::Failed(mcap::McapError::UnsupportedCompression(c))) => {
                    unsupported = true;
                    failure = Some(format!("its chunks are {c}-compressed"));
                    break;
                }
                Some(End::Failed(e)) => {
                    failure = Some(e.to_string());
                    break;
                }
                Some(End::Io(e)) => {
                    return Err(ReviewError::NotMcap {
                        reason: format!("reading it failed after {} bytes: {e}", reader.rec.bytes),
                    })
                }
            }
            // The reading thread may be done: then the batch is freed here.
            let _ = free_tx.send(batch);
        }
        Ok(())
    })?;
    if reader.rec.bytes < (mcap::MAGIC.len() * 2) as u64 && reader.rec.messages == 0 {
        return Err(ReviewError::NotMcap {
            reason: failure.unwrap_or_else(|| format!("{} bytes", reader.rec.bytes)),
        });
    }
    if let Some(why) = failure {
        reader.rec.complete = false;
        let at = reader.rec.last_log_time_nanos.map_or_else(
            || "before the first message".to_owned(),
            |t| format!("after {:.1} s of recording", reader.secs_into(t)),
        );
        let why = if past_data_end {
            format!("its summary is unreadable ({why}); every message before it was read")
        } else if unsupported {
            format!("{why}; {READ_COMPRESSIONS}")
        } else {
            format!("the rest is unreadable ({why}): the recording was cut short or damaged")
        };
        reader.rec.problems.push(format!(
            "the recording could be read only up to {at} ({} messages): {why}",
            reader.rec.messages
        ));
    }
    reader.finish()
}

/// What the reading thread of [`stream_recording`] hands the decoding one: records in file order,
/// each an opcode and its bytes' range in one buffer.
#[derive(Default)]
struct Batch {
    data: Vec<u8>,
    records: Vec<(u8, std::ops::Range<usize>)>,
    /// How many bytes of the source were read meanwhile.
    bytes: u64,
    /// Why reading ended after these records, if it did.
    end: Option<End>,
}

/// Why the reading thread stopped before the end of the source.
enum End {
    /// The MCAP reader's error.
    Failed(mcap::McapError),
    /// Reading the source failed.
    Io(std::io::Error),
}

/// How many records, or how many of their bytes, [`read_batches`] sends at once.
const BATCH_RECORDS: usize = 4096;
const BATCH_BYTES: usize = 4 << 20;

/// Reads `source` with mcap's streaming reader (each chunk's CRC checked, each record's size
/// bounded) and sends its records to `tx` in batches (refilling those `free` gives back), until
/// the end, an error, or the receiver is gone.
fn read_batches<R: std::io::Read>(
    mut source: R,
    tx: &std::sync::mpsc::SyncSender<Batch>,
    free: &std::sync::mpsc::Receiver<Batch>,
) {
    use mcap::sans_io::{LinearReadEvent, LinearReader, LinearReaderOptions};
    // Each chunk decompressed whole and its CRC checked before any of its records is handed on:
    // a damaged chunk gives no message (its size bounded by the record limit).
    let options = LinearReaderOptions::default()
        .with_validate_chunk_crcs(true)
        .with_prevalidate_chunk_crcs(true)
        .with_record_length_limit(MAX_RECORD_BYTES);
    let mut linear = LinearReader::new_with_options(options);
    let mut batch = Batch::default();
    while let Some(event) = linear.next_event() {
        match event {
            Err(e) => {
                batch.end = Some(End::Failed(e));
                break;
            }
            Ok(LinearReadEvent::ReadRequest(need)) => {
                let buf = linear.insert(need);
                match source.read(buf) {
                    Ok(n) => {
                        linear.notify_read(n);
                        batch.bytes += n as u64;
                    }
                    Err(e) if e.kind() == std::io::ErrorKind::Interrupted => linear.notify_read(0),
                    Err(e) => {
                        batch.end = Some(End::Io(e));
                        break;
                    }
                }
            }
            Ok(LinearReadEvent::Record { opcode, data }) => {
                let at = batch.data.len();
                batch.data.extend_from_slice(data);
                batch.records.push((opcode, at..batch.data.len()));
                if batch.records.len() >= BATCH_RECORDS || batch.data.len() >= BATCH_BYTES {
                    let mut next = free.try_recv().unwrap_or_default();
                    next.data.clear();
                    next.records.clear();
                    // a batch that carried a large record does not keep its memory
                    next.data.shrink_to(BATCH_BYTES);
                    next.records.shrink_to(BATCH_RECORDS);
                    next.bytes = 0;
                    if tx.send(std::mem::replace(&mut batch, next)).is_err() {
                        return;
                    }
                }
            }
        }
    }
    // The receiver may be gone already: nothing to tell it then.
    let _ = tx.send(batch);
}

/// The largest record, or decompressed chunk, the streaming reader accepts: a damaged length field,
/// or a compressed chunk that would unpack into more, is refused, never allocated.
const MAX_RECORD_BYTES: usize = 256 << 20;

/// Reading state: what was read and what was skipped.
struct Reader<'v, V: Visit> {
    rec: ReadStats,
    skipped: BTreeMap<String, Skipped>,
    /// Messages read by their capture stamp (their log time too far from it), and the first one's
    /// log time and stamp.
    clock_disagreements: u64,
    first_disagreement: Option<(u64, u64)>,
    /// The log clock disagreed at the latest stamped message.
    clock_lies: bool,
    /// The latest capture stamp read: while the clock disagrees, where a message without a stamp
    /// of its own is placed (a session's state changes are stamped the instant they are logged).
    latest_stamp: Option<u64>,
    /// The span of the decoded messages' times (their capture stamps where the clock disagreed):
    /// the recording's span when it did, as the other topics' log times cannot be checked.
    decoded_span: Option<(u64, u64)>,
    visitor: &'v mut V,
}

impl<'v, V: Visit> Reader<'v, V> {
    fn new(visitor: &'v mut V) -> Self {
        Self {
            rec: ReadStats {
                complete: true,
                ..ReadStats::default()
            },
            skipped: BTreeMap::new(),
            clock_disagreements: 0,
            first_disagreement: None,
            clock_lies: false,
            latest_stamp: None,
            decoded_span: None,
            visitor,
        }
    }

    /// The time of a message without a capture stamp to check its log time against: the log time,
    /// or while the clock disagrees, the latest capture stamp read.
    fn unstamped(&self, t: u64) -> u64 {
        match (self.clock_lies, self.latest_stamp) {
            (true, Some(latest)) => latest,
            _ => t,
        }
    }

    /// Counts `t` into the span of log times read.
    fn span(&mut self, t: u64) {
        let rec = &mut self.rec;
        rec.first_log_time_nanos = Some(rec.first_log_time_nanos.map_or(t, |f| f.min(t)));
        rec.last_log_time_nanos = Some(rec.last_log_time_nanos.map_or(t, |l| l.max(t)));
    }

    fn secs_into(&self, t: u64) -> f64 {
        t.saturating_sub(self.rec.first_log_time_nanos.unwrap_or(t)) as f64 * 1e-9
    }

    /// Every chunk through the summary's index, in time order; damaged chunks skipped and named.
    fn read_chunks(&mut self, bytes: &[u8], summary: &mcap::Summary) {
        let mut indexes: Vec<&mcap::records::ChunkIndex> = summary.chunk_indexes.iter().collect();
        indexes.sort_by_key(|i| (i.message_start_time, i.chunk_start_offset));
        let first_time = indexes.first().map_or(0, |i| i.message_start_time);
        let span = |i: &mcap::records::ChunkIndex| {
            format!(
                "{:.1}–{:.1} s",
                i.message_start_time.saturating_sub(first_time) as f64 * 1e-9,
                i.message_end_time.saturating_sub(first_time) as f64 * 1e-9
            )
        };
        // Chunks in a compression this build does not decompress: one problem per compression
        // (a file has thousands of chunks), with how many and the span they cover.
        let mut unsupported: BTreeMap<String, (usize, String)> = BTreeMap::new();
        for index in indexes {
            match check_chunk(bytes, index) {
                Ok(()) => {}
                Err(ChunkProblem::Unsupported(compression)) => {
                    self.rec.complete = false;
                    unsupported
                        .entry(compression)
                        .or_insert_with(|| (0, span(index)))
                        .0 += 1;
                    continue;
                }
                Err(ChunkProblem::Damaged(why)) => {
                    self.rec.complete = false;
                    self.rec.problems.push(format!(
                        "the chunk of {} is unreadable and was skipped: {why}",
                        span(index)
                    ));
                    continue;
                }
            }
            let messages = match summary.stream_chunk(bytes, index) {
                Ok(m) => m,
                Err(e) => {
                    self.rec.complete = false;
                    self.rec.problems.push(format!(
                        "the chunk of {} is unreadable and was skipped: {e}",
                        span(index)
                    ));
                    continue;
                }
            };
            for m in messages {
                match m {
                    Ok(m) => self.take_mcap_message(&m),
                    Err(e) => {
                        self.rec.complete = false;
                        self.rec.problems.push(format!(
                            "the chunk of {} is damaged: read up to a bad record ({e})",
                            span(index)
                        ));
                        break;
                    }
                }
            }
        }
        for (compression, (chunks, first)) in unsupported {
            self.rec.problems.push(format!(
                "{chunks} chunk(s), the first of {first}, are {compression}-compressed and were \
                 skipped; {READ_COMPRESSIONS}"
            ));
        }
        if let Some(stats) = &summary.stats {
            if stats.message_count > self.rec.messages {
                self.rec.complete = false;
                self.rec.problems.push(format!(
                    "{} of the {} messages the file's summary counts could not be read",
                    stats.message_count - self.rec.messages,
                    stats.message_count
                ));
            }
        }
    }

    fn take_mcap_message(&mut self, m: &mcap::Message<'_>) {
        let schema = m.channel.schema.as_ref().map_or("", |s| s.name.as_str());
        self.take_message(&m.channel.topic, schema, m.log_time, &m.data);
    }

    fn take_message(&mut self, topic: &str, schema: &str, t: u64, data: &[u8]) {
        let rec = &mut self.rec;
        rec.messages += 1;
        if let Some(c) = rec.channels.get_mut(topic) {
            c.messages += 1;
        } else {
            rec.channels.insert(
                topic.to_owned(),
                ChannelInfo {
                    schema: schema.to_owned(),
                    messages: 1,
                },
            );
        }
        let session_topic = matches!(
            topic,
            topics::OPERATOR_POSE
                | topics::ERGONOMICS
                | topics::WARNINGS
                | topics::SESSION_STATE
                | topics::ROBOT_MARKERS
        );
        let known = session_topic
            || matches!(
                topic,
                topics::REBA | topics::JOINT_TRAJECTORY | topics::CONTROLLER_EVENTS
            );
        if !known {
            self.span(self.unstamped(t));
            return;
        }
        if !self.visitor.wants_at(topic, t) {
            rec.session_messages += u64::from(session_topic);
            self.span(self.unstamped(t));
            return;
        }
        let outcome = match topic {
            topics::OPERATOR_POSE => take(schema, data, t).map(Decoded::Pose),
            topics::ERGONOMICS => take_ergonomic_state(schema, data, t).map(Decoded::Ergonomics),
            topics::REBA => take(schema, data, t).map(Decoded::Reba),
            topics::WARNINGS => take_posture_warning(schema, data, t).map(Decoded::Warning),
            topics::SESSION_STATE => take_session_state(schema, data, t).map(Decoded::State),
            topics::ROBOT_MARKERS => take(schema, data, t).map(Decoded::RobotMarkers),
            topics::JOINT_TRAJECTORY => take(schema, data, t).map(Decoded::Trajectory),
            _ => take_controller_event(schema, data, t).map(Decoded::ControllerEvent),
        };
        match outcome {
            Ok(mut message) => {
                self.rec.session_messages += u64::from(session_topic);
                let stamp = message.capture_stamp_nanos();
                if let Some(s) = stamp {
                    self.latest_stamp = Some(self.latest_stamp.map_or(s, |l| l.max(s)));
                }
                let at = match stamp {
                    Some(stamp) if t.abs_diff(stamp) > MAX_LOG_CLOCK_DISAGREEMENT_NANOS => {
                        self.clock_disagreements += 1;
                        self.first_disagreement.get_or_insert((t, stamp));
                        self.clock_lies = true;
                        stamp
                    }
                    Some(_) => {
                        self.clock_lies = false;
                        t
                    }
                    None => self.unstamped(t),
                };
                if at != t {
                    message.set_log_time(at);
                }
                self.span(at);
                self.decoded_span = Some(
                    self.decoded_span
                        .map_or((at, at), |(a, b)| (a.min(at), b.max(at))),
                );
                self.visitor.message(message);
            }
            Err(why) => {
                self.span(self.unstamped(t));
                let s = self.skipped.entry(topic.to_owned()).or_default();
                s.count += 1;
                if s.first.is_empty() {
                    s.first = why;
                }
            }
        }
    }

    fn finish(mut self) -> Result<ReadStats, ReviewError> {
        self.rec.clock_disagreements = self.clock_disagreements;
        if let Some((log, stamp)) = self.first_disagreement {
            if let Some((first, last)) = self.decoded_span {
                self.rec.first_log_time_nanos = Some(first);
                self.rec.last_log_time_nanos = Some(last);
            }
            let secs = |n: u64| n as f64 * 1e-9;
            self.rec.problems.push(format!(
                "the recording's clock disagrees with its capture stamps: {} message(s) were logged more than {} s from the instant they were captured (the first logged at {:.3} s, captured at {:.3} s, Unix time) and are read by their capture stamps",
                self.clock_disagreements,
                MAX_LOG_CLOCK_DISAGREEMENT_NANOS / 1_000_000_000,
                secs(log),
                secs(stamp)
            ));
        }
        let rec = &mut self.rec;
        for (topic, s) in std::mem::take(&mut self.skipped) {
            rec.problems.push(format!(
                "{} message(s) on {topic} skipped: {}",
                s.count, s.first
            ));
        }
        if rec.session_messages == 0 {
            let ours = rec
                .channels
                .keys()
                .any(|t| t.starts_with(topics::NAMESPACE));
            if !rec.complete || ours {
                let mut reason = if rec.messages == 0 {
                    "no message could be read".to_owned()
                } else {
                    format!(
                        "{} messages read ({}), none of the session's (operator pose, RULA, session state)",
                        rec.messages,
                        channel_list(&rec.channels)
                    )
                };
                if !rec.problems.is_empty() {
                    reason.push_str("; ");
                    reason.push_str(&rec.problems.join("; "));
                }
                return Err(ReviewError::NotMcap { reason });
            }
            return Err(ReviewError::Foreign {
                message_count: rec.messages,
                channels: channel_list(&rec.channels),
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
        Ok(self.rec)
    }
}

fn channel_list(channels: &BTreeMap<String, ChannelInfo>) -> String {
    if channels.is_empty() {
        return "no channels".to_owned();
    }
    channels
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
}

/// What a recording's chunks may be compressed with, for the message that refuses another.
const READ_COMPRESSIONS: &str =
    "ergocell reads chunks compressed with zstd or lz4, or uncompressed \
     (`mcap convert --compression zstd` re-compresses one)";

/// Why a chunk the summary indexes is not read.
#[derive(Debug, Clone, PartialEq)]
enum ChunkProblem {
    /// Compressed with this (chunk `compression` field), which this build does not decompress.
    Unsupported(String),
    /// Not where the index says, not a chunk, or its bytes damaged: why.
    Damaged(String),
}

/// A chunk's record is whole and its uncompressed bytes match its CRC (a compressed chunk is
/// decompressed to check it).
fn check_chunk(bytes: &[u8], index: &mcap::records::ChunkIndex) -> Result<(), ChunkProblem> {
    let damaged = |e: &dyn std::fmt::Display| ChunkProblem::Damaged(e.to_string());
    let start = usize::try_from(index.chunk_start_offset).map_err(|e| damaged(&e))?;
    let end = usize::try_from(index.chunk_start_offset.saturating_add(index.chunk_length))
        .map_err(|e| damaged(&e))?;
    let record = bytes
        .get(start..end)
        .filter(|r| r.len() >= 9)
        .ok_or_else(|| damaged(&"beyond the end of the file"))?;
    match mcap::parse_record(mcap::records::op::CHUNK, &record[9..]) {
        Ok(mcap::records::Record::Chunk { header, data }) => {
            if !header.compression.is_empty() {
                return check_compressed_chunk(record);
            }
            if header.uncompressed_crc != 0 && crc32fast::hash(&data) != header.uncompressed_crc {
                return Err(damaged(&"its CRC does not match (the bytes were damaged)"));
            }
            Ok(())
        }
        Ok(_) => Err(damaged(&"the index does not point at a chunk")),
        Err(e) => Err(damaged(&e)),
    }
}

/// A compressed chunk's `record` (opcode, length and body) read through mcap's streaming reader,
/// which decompresses it and checks the CRC of what comes out.
fn check_compressed_chunk(record: &[u8]) -> Result<(), ChunkProblem> {
    use mcap::sans_io::{LinearReadEvent, LinearReader, LinearReaderOptions};
    let options = LinearReaderOptions::default()
        .with_skip_start_magic(true)
        .with_skip_end_magic(true)
        .with_validate_chunk_crcs(true)
        .with_record_length_limit(MAX_RECORD_BYTES);
    let mut linear = LinearReader::new_with_options(options);
    let mut rest = record;
    while let Some(event) = linear.next_event() {
        match event {
            Err(mcap::McapError::UnsupportedCompression(c)) => {
                return Err(ChunkProblem::Unsupported(c));
            }
            Err(mcap::McapError::BadChunkCrc { .. }) => {
                return Err(ChunkProblem::Damaged(
                    "its CRC does not match (the bytes were damaged)".to_owned(),
                ));
            }
            Err(e) => {
                return Err(ChunkProblem::Damaged(format!(
                    "it does not decompress ({e})"
                )))
            }
            Ok(LinearReadEvent::ReadRequest(need)) => {
                let n = need.min(rest.len());
                linear.insert(n).copy_from_slice(&rest[..n]);
                linear.notify_read(n);
                rest = &rest[n..];
            }
            Ok(LinearReadEvent::Record { .. }) => {}
        }
    }
    Ok(())
}

/// Decodes one message of type `M` if the channel's schema names `M`.
pub(crate) fn take<M: RosMessage + DeserializeOwned>(
    schema: &str,
    data: &[u8],
    log_time_nanos: u64,
) -> Result<Stamped<M>, String> {
    let expected = M::type_name();
    if schema != expected {
        return Err(format!("schema is {schema:?}, expected {expected}"));
    }
    let message = cdr::decode::<M>(data).map_err(|e| e.to_string())?;
    Ok(Stamped {
        log_time_nanos,
        logged_nanos: log_time_nanos,
        message,
    })
}

/// The messages of `v` whose log time `f` accepts.
fn part<M: Clone>(v: &[Stamped<M>], f: &dyn Fn(u64) -> bool) -> Vec<Stamped<M>> {
    v.iter().filter(|m| f(m.log_time_nanos)).cloned().collect()
}

/// Whether a recording of `count` operator sessions holds session `session` (1-based): a
/// recording in which nobody was seen is one session.
pub fn holds_session(count: usize, session: usize) -> bool {
    session != 0 && session <= count.max(1)
}

/// Session `session` (1-based) of a recording read whole ([`split_sessions`]), ready for its page:
/// its label (`name`, or for one of several sessions [`crate::text::session_label`]) and its
/// messages, with a note on the other sessions among its problems. `Err(count)` when the recording
/// holds no such session, only `count`.
pub fn pick_session(
    recording: Recording,
    session: usize,
    name: &str,
) -> Result<(String, Recording), usize> {
    let mut parts = split_sessions(&recording);
    let count = parts.len();
    if !holds_session(count, session) {
        return Err(count);
    }
    let (label, note) =
        crate::text::session_page(name, session, count, || crate::text::parts_listing(&parts));
    let mut chosen = if note.is_some() {
        parts.swap_remove(session - 1).recording
    } else {
        parts.pop().map_or(recording, |p| p.recording)
    };
    chosen.problems.extend(note);
    chosen.problems.dedup();
    Ok((label, chosen))
}

/// One operator session of a recording: its number (1-based) and its messages.
#[derive(Debug, Clone, PartialEq)]
pub struct SessionPart {
    pub number: usize,
    pub recording: Recording,
}

/// How long after a session's `session_ended` a controller event about a leg still belongs to that
/// session: the controller answers a goal's end (`finished`) up to ~2 s after the robot is home and
/// the session has ended.
pub const LATE_EVENT_NANOS: u64 = 3_000_000_000;

/// Splits a recording into its operator sessions: `ergocell run --record` writes one session after
/// another into one file, each ending with a `session_ended` state. A session is the messages up to
/// and including its `session_ended`; what follows the last one counts only if an operator was seen
/// in it (poses or RULA), e.g. a session cut short by the end of the file.
///
/// A controller event about a leg recorded within [`LATE_EVENT_NANOS`] after a session's end, before
/// the next session sent any leg, is that session's (a late `finished`).
pub fn split_sessions(rec: &Recording) -> Vec<SessionPart> {
    let ends: Vec<u64> = rec
        .states
        .iter()
        .filter(|s| s.message.state == ergocell_bridge::msg::SessionState::SESSION_ENDED)
        .map(|s| s.log_time_nanos)
        .collect();
    if ends.len() <= 1 {
        let only_one = ends.first().is_none_or(|&end| {
            rec.poses.iter().all(|p| p.log_time_nanos <= end)
                && rec.ergonomics.iter().all(|e| e.log_time_nanos <= end)
        });
        if only_one {
            return vec![SessionPart {
                number: 1,
                recording: rec.clone(),
            }];
        }
    }
    let mut bounds: Vec<(Option<u64>, Option<u64>)> = Vec::new();
    let mut from = None;
    for &end in &ends {
        bounds.push((from, Some(end)));
        from = Some(end);
    }
    bounds.push((from, None));
    let inside = |t: u64, (a, b): (Option<u64>, Option<u64>)| {
        a.is_none_or(|a| t > a) && b.is_none_or(|b| t <= b)
    };
    // Each controller event's range: by its time, or the previous one's for a late answer.
    let leg_sent_in = |a: u64, b: u64| {
        rec.trajectories
            .iter()
            .any(|m| !m.message.points.is_empty() && m.log_time_nanos > a && m.log_time_nanos <= b)
            || rec.controller_events.iter().any(|m| {
                m.message.event_kind() == Some(ergocell_bridge::msg::ControllerEventKind::GoalSent)
                    && m.log_time_nanos > a
                    && m.log_time_nanos <= b
            })
    };
    let event_range: Vec<usize> = rec
        .controller_events
        .iter()
        .map(|e| {
            let t = e.log_time_nanos;
            let k = bounds
                .iter()
                .position(|&r| inside(t, r))
                .unwrap_or(bounds.len() - 1);
            let late = k > 0
                && e.message.event_kind()
                    != Some(ergocell_bridge::msg::ControllerEventKind::GoalSent)
                && !e.message.leg.is_empty()
                && bounds[k].0.is_some_and(|end| {
                    t <= end.saturating_add(LATE_EVENT_NANOS) && !leg_sent_in(end, t)
                });
            if late {
                k - 1
            } else {
                k
            }
        })
        .collect();
    let mut parts = Vec::new();
    for (k, range) in bounds.into_iter().enumerate() {
        let f = |t: u64| inside(t, range);
        let poses = part(&rec.poses, &f);
        let ergonomics = part(&rec.ergonomics, &f);
        if poses.is_empty() && ergonomics.is_empty() {
            continue; // nobody seen: between operators, or waiting after the last one
        }
        parts.push(Recording {
            bytes: rec.bytes,
            messages: rec.messages,
            complete: rec.complete,
            problems: rec.problems.clone(),
            first_log_time_nanos: range.0.map_or(rec.first_log_time_nanos, |a| Some(a + 1)),
            last_log_time_nanos: range.1.or(rec.last_log_time_nanos),
            poses,
            ergonomics,
            reba: part(&rec.reba, &f),
            warnings: part(&rec.warnings, &f),
            states: part(&rec.states, &f),
            robot_markers: part(&rec.robot_markers, &f),
            trajectories: part(&rec.trajectories, &f),
            controller_events: rec
                .controller_events
                .iter()
                .zip(&event_range)
                .filter(|&(_, &r)| r == k)
                .map(|(e, _)| e.clone())
                .collect(),
            channels: rec.channels.clone(),
            operator: rec.operator.clone(),
        });
    }
    parts
        .into_iter()
        .enumerate()
        .map(|(i, recording)| SessionPart {
            number: i + 1,
            recording,
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::legacy::{
        ControllerEventWithoutLegId, ErgonomicStateWithoutConfidence,
        PostureWarningWithoutConfidence, SessionStateWithoutDecision,
    };

    fn stamped<M>(t: u64, message: M) -> Stamped<M> {
        Stamped {
            log_time_nanos: t,
            logged_nanos: t,
            message,
        }
    }

    fn state(name: &str) -> SessionState {
        SessionState {
            state: name.to_owned(),
            ..SessionState::default()
        }
    }

    /// Recordings made before the ergonomic state and the warnings carried their confidence still
    /// read (confidence unknown); the current layout reads its own; a cut payload is refused.
    #[test]
    fn ergonomics_and_warnings_without_confidence_still_read() {
        let side = ergocell_bridge::msg::RulaSide {
            scored: true,
            final_score: 5,
            action_level: 3,
            ..Default::default()
        };
        let old = cdr::encode(&ErgonomicStateWithoutConfidence {
            header: ergocell_bridge::msg::Header::default(),
            left: side,
            right: ergocell_bridge::msg::RulaSide::default(),
            action_level: 3,
        })
        .unwrap();
        let schema = ErgonomicState::type_name();
        let read = take_ergonomic_state(&schema, &old, 1).unwrap().message;
        assert_eq!((read.left, read.action_level), (side, 3));
        assert!(read.left_band_probability.is_empty() && read.left_angle_sd_deg.is_empty());
        let now = ErgonomicState {
            left: side,
            left_band_probability: vec![0.25, 0.5, f64::NAN, 0.75, 1.0],
            left_angle_sd_deg: vec![4.0; 5],
            ..ErgonomicState::default()
        };
        let read = take_ergonomic_state(&schema, &cdr::encode(&now).unwrap(), 2)
            .unwrap()
            .message;
        assert_eq!(read.left_band_probability[3], 0.75);
        assert!(read.left_band_probability[2].is_nan());
        assert!(take_ergonomic_state(&schema, &old[..old.len() - 3], 3).is_err());

        let old = cdr::encode(&PostureWarningWithoutConfidence {
            header: ergocell_bridge::msg::Header::default(),
            kind: "raised".into(),
            region: "neck".into(),
            side: String::new(),
            region_score: 3,
            angle_deg: 24.0,
            action_level: 3,
            uncertain: false,
            message: "m".into(),
        })
        .unwrap();
        let schema = PostureWarning::type_name();
        let read = take_posture_warning(&schema, &old, 4).unwrap().message;
        assert_eq!((read.region.as_str(), read.region_score), ("neck", 3));
        assert!(read.band_probability.is_nan() && !read.near_limit);
        let now = PostureWarning {
            region: "trunk".into(),
            band_probability: 0.62,
            near_limit: true,
            ..PostureWarning::default()
        };
        let read = take_posture_warning(&schema, &cdr::encode(&now).unwrap(), 5)
            .unwrap()
            .message;
        assert_eq!((read.band_probability, read.near_limit), (0.62, true));
        assert!(take_posture_warning(&schema, &old[..old.len() - 3], 6).is_err());
    }

    /// A recording made before `ControllerEvent` carried `leg_id` still reads: the leg's constant
    /// from its words; the current layout reads its constant, not the words.
    #[test]
    fn a_controller_event_without_the_leg_constant_still_reads() {
        let old = |leg: &str| {
            cdr::encode(&ControllerEventWithoutLegId {
                header: ergocell_bridge::msg::Header::default(),
                kind: "finished".into(),
                leg: leg.into(),
                status: "succeeded".into(),
                error_code: 0,
                text: String::new(),
                feedback_count: 3,
                max_error: f64::NAN,
                sample_stamp: ergocell_bridge::msg::Time::default(),
            })
            .unwrap()
        };
        let schema = ControllerEvent::type_name();
        let mut into = Vec::new();
        for (k, leg) in ["home → handover", "handover → home", ""]
            .iter()
            .enumerate()
        {
            into.push(take_controller_event(&schema, &old(leg), k as u64).unwrap());
        }
        let ids: Vec<u8> = into.iter().map(|e| e.message.leg_id).collect();
        assert_eq!(
            ids,
            [
                ControllerEvent::LEG_TO_HANDOVER,
                ControllerEvent::LEG_TO_HOME,
                ControllerEvent::LEG_NONE
            ]
        );
        assert_eq!(into[0].message.feedback_count, 3);
        let now = cdr::encode(&ControllerEvent {
            leg: "whatever words".into(),
            leg_id: ControllerEvent::LEG_TO_HOME,
            ..event("finished", "")
        })
        .unwrap();
        into.push(take_controller_event(&schema, &now, 9).unwrap());
        assert_eq!(into[3].message.leg_id, ControllerEvent::LEG_TO_HOME);
        let cut = old("home → handover");
        assert!(take_controller_event(&schema, &cut[..cut.len() - 9], 10).is_err());
    }

    /// A recording made before `SessionState` carried the decision's fields still reads: the
    /// decision's fields are unknown, the rest as recorded; a damaged payload is still refused.
    #[test]
    fn a_session_state_without_the_decision_fields_still_reads() {
        let old = cdr::encode(&SessionStateWithoutDecision {
            header: ergocell_bridge::msg::Header::default(),
            state: "class_decided".into(),
            reason: "r".into(),
            height_m: 1.7,
            height_uncertainty_m: 0.01,
            height_class: "c2".into(),
            trajectory_sha256: String::new(),
            robot_held: false,
            cameras_fresh: 6,
            stereo_pairs_tracking: 3,
            trajectory_approved_by: vec!["a".into()],
        })
        .unwrap();
        let schema = SessionState::type_name();
        let mut into = Vec::new();
        into.push(take_session_state(&schema, &old, 5).unwrap());
        let m = &into[0].message;
        assert_eq!((m.height_class.as_str(), m.cameras_fresh), ("c2", 6));
        assert_eq!(m.trajectory_approved_by, ["a"]);
        assert!(m.height_class_probability.is_nan() && m.height_decision_basis.is_empty());
        // The current layout reads with its fields.
        let now = cdr::encode(&SessionState {
            height_decision_basis: "expected_rula".into(),
            height_class_probability: 0.79,
            height_expected_rula_cost: -0.02,
            ..state("class_decided")
        })
        .unwrap();
        into.push(take_session_state(&schema, &now, 6).unwrap());
        assert_eq!(into[1].message.height_class_probability, 0.79);
        // Cut short, neither layout reads.
        assert!(take_session_state(&schema, &old[..old.len() - 9], 7).is_err());
        assert_eq!(into.len(), 2);
    }

    #[test]
    fn a_recording_of_two_operators_splits_at_session_ended() {
        let s = 1_000_000_000;
        let rec = Recording {
            states: vec![
                stamped(0, state("measuring_height")),
                stamped(10 * s, state("session_ended")),
                stamped(11 * s, state("waiting_for_operator")),
                stamped(12 * s, state("measuring_height")),
                stamped(20 * s, state("session_ended")),
                stamped(21 * s, state("waiting_for_operator")),
            ],
            poses: [1, 5, 9, 13, 19]
                .iter()
                .map(|&k| stamped(k * s, OperatorPose::default()))
                .collect(),
            first_log_time_nanos: Some(0),
            last_log_time_nanos: Some(22 * s),
            ..Recording::default()
        };
        let parts = split_sessions(&rec);
        assert_eq!(
            parts.len(),
            2,
            "the idle tail after the second operator is no session"
        );
        assert_eq!(parts[0].recording.poses.len(), 3);
        assert_eq!(parts[1].recording.poses.len(), 2);
        assert_eq!(parts[1].number, 2);
        // Each part starts its own clock after the previous session's end.
        assert_eq!(parts[1].recording.first_log_time_nanos, Some(10 * s + 1));
        assert_eq!(
            parts[1]
                .recording
                .states
                .first()
                .map(|m| m.message.state.as_str()),
            Some("waiting_for_operator")
        );
        // One session (or none ended yet): the recording itself.
        let one = Recording {
            states: rec.states[..2].to_vec(),
            poses: rec.poses[..3].to_vec(),
            ..Recording::default()
        };
        assert_eq!(split_sessions(&one).len(), 1);
    }

    /// The session asked for is picked, labelled and told about the others; one that is not
    /// there is refused with how many there are.
    #[test]
    fn a_session_is_picked_labelled_and_noted_or_refused() {
        let s = 1_000_000_000;
        let rec = Recording {
            states: vec![
                stamped(0, state("measuring_height")),
                stamped(10 * s, state("session_ended")),
                stamped(12 * s, state("measuring_height")),
                stamped(20 * s, state("session_ended")),
            ],
            poses: [1, 5, 13]
                .iter()
                .map(|&k| stamped(k * s, OperatorPose::default()))
                .collect(),
            ..Recording::default()
        };
        let (label, second) = pick_session(rec.clone(), 2, "a.mcap").unwrap();
        assert_eq!(label, "a.mcap · session 2/2");
        assert_eq!(second.poses.len(), 1);
        assert_eq!(second.problems.len(), 1);
        assert!(
            second.problems[0].contains("2 operator sessions"),
            "{:?}",
            second.problems
        );
        assert_eq!(pick_session(rec.clone(), 3, "a.mcap"), Err(2));
        assert_eq!(pick_session(rec.clone(), 0, "a.mcap"), Err(2));
        let one = Recording {
            poses: rec.poses.clone(),
            ..Recording::default()
        };
        let (label, whole) = pick_session(one.clone(), 1, "a.mcap").unwrap();
        assert_eq!((label.as_str(), &whole), ("a.mcap", &one));
        // Nobody seen: the recording itself is its one session.
        let (_, empty) = pick_session(Recording::default(), 1, "a.mcap").unwrap();
        assert_eq!(empty, Recording::default());
        assert_eq!(pick_session(Recording::default(), 2, "a.mcap"), Err(1));
    }

    /// An event about the leg named `leg` (its constant as `ergocell run` sets it).
    fn event(kind: &str, leg: &str) -> ControllerEvent {
        let leg_id = match leg {
            "home → handover" => ControllerEvent::LEG_TO_HANDOVER,
            "handover → home" => ControllerEvent::LEG_TO_HOME,
            _ => ControllerEvent::LEG_NONE,
        };
        ControllerEvent {
            kind: kind.to_owned(),
            leg: leg.to_owned(),
            leg_id,
            max_error: f64::NAN,
            ..ControllerEvent::default()
        }
    }

    fn leg_command() -> JointTrajectory {
        JointTrajectory {
            points: vec![ergocell_bridge::msg::JointTrajectoryPoint::default()],
            ..JointTrajectory::default()
        }
    }

    #[test]
    fn a_late_finished_stays_with_the_session_of_its_leg() {
        let s = 1_000_000_000;
        let ms = 1_000_000;
        let rec = Recording {
            states: vec![
                stamped(0, state("working")),
                stamped(10 * s, state("session_ended")),
                stamped(11 * s, state("measuring_height")),
                stamped(20 * s, state("session_ended")),
            ],
            poses: [1, 5, 9, 13, 19]
                .iter()
                .map(|&k| stamped(k * s, OperatorPose::default()))
                .collect(),
            trajectories: vec![
                stamped(7 * s, leg_command()),
                stamped(12 * s + 500 * ms, leg_command()),
                // A hold in the second session, right after its start: no leg.
                stamped(10 * s + 100 * ms, JointTrajectory::default()),
            ],
            controller_events: vec![
                stamped(7 * s, event("goal_sent", "handover → home")),
                stamped(8 * s, event("feedback", "handover → home")),
                // 1.5 s after the first session's end: its last leg's answer.
                stamped(11 * s + 500 * ms, event("finished", "handover → home")),
                // The driver's state at the same moment is about no leg: the second session's.
                stamped(11 * s + 500 * ms, event("driver", "")),
                stamped(12 * s + 500 * ms, event("goal_sent", "home → handover")),
                // Within 3 s of the first end, but after the second session sent its leg.
                stamped(12 * s + 800 * ms, event("accepted", "home → handover")),
                // Later than 3 s after the first end.
                stamped(14 * s, event("finished", "home → handover")),
            ],
            first_log_time_nanos: Some(0),
            last_log_time_nanos: Some(20 * s),
            ..Recording::default()
        };
        let parts = split_sessions(&rec);
        assert_eq!(parts.len(), 2);
        let kinds = |k: usize| -> Vec<(String, u64)> {
            parts[k]
                .recording
                .controller_events
                .iter()
                .map(|e| (e.message.kind.clone(), e.log_time_nanos / ms))
                .collect()
        };
        assert_eq!(
            kinds(0),
            [
                ("goal_sent".to_owned(), 7000),
                ("feedback".to_owned(), 8000),
                ("finished".to_owned(), 11500)
            ]
        );
        assert_eq!(
            kinds(1),
            [
                ("driver".to_owned(), 11500),
                ("goal_sent".to_owned(), 12500),
                ("accepted".to_owned(), 12800),
                ("finished".to_owned(), 14000)
            ]
        );
        // The commands go by their time.
        assert_eq!(parts[0].recording.trajectories.len(), 1);
        assert_eq!(parts[1].recording.trajectories.len(), 2);
    }

    /// MCAP bytes of `n` session states, one chunk each, naming operator `op-7`.
    fn states_recording(n: u64) -> Vec<u8> {
        states_recording_compressed(n, None)
    }

    /// As [`states_recording`], each chunk compressed with `compression`.
    fn states_recording_compressed(n: u64, compression: Option<mcap::Compression>) -> Vec<u8> {
        let (mut w, channel) = states_writer(compression, Some(64));
        w.write_metadata(&mcap::records::Metadata {
            name: session_info::METADATA_NAME.to_owned(),
            metadata: session_info::metadata(&session_info::OperatorId::new("op-7").unwrap()),
        })
        .unwrap();
        for k in 0..n {
            let data = cdr::encode(&state(if k + 1 == n {
                "session_ended"
            } else {
                "working"
            }))
            .unwrap();
            w.write_to_known_channel(&state_header(channel, k), &data)
                .unwrap();
        }
        w.finish().unwrap();
        w.into_inner().into_inner()
    }

    /// An MCAP writer in memory with the session-state channel (its id).
    fn states_writer(
        compression: Option<mcap::Compression>,
        chunk_size: Option<u64>,
    ) -> (mcap::Writer<std::io::Cursor<Vec<u8>>>, u16) {
        let mut w = mcap::WriteOptions::new()
            .profile("ros2")
            .compression(compression)
            .chunk_size(chunk_size)
            .create(std::io::Cursor::new(Vec::new()))
            .unwrap();
        let schema = w
            .add_schema(&SessionState::type_name(), "ros2msg", b"")
            .unwrap();
        let channel = w
            .add_channel(schema, topics::SESSION_STATE, "cdr", &BTreeMap::new())
            .unwrap();
        (w, channel)
    }

    /// Message `k` on `channel`, logged at `k` seconds.
    fn state_header(channel: u16, k: u64) -> mcap::records::MessageHeader {
        mcap::records::MessageHeader {
            channel_id: channel,
            sequence: u32::try_from(k).unwrap(),
            log_time: k * 1_000_000_000,
            publish_time: k * 1_000_000_000,
        }
    }

    /// A reader handing out one byte at a time: the stream never needs more than it asks for.
    struct Trickle<'a>(&'a [u8]);
    impl std::io::Read for Trickle<'_> {
        fn read(&mut self, buf: &mut [u8]) -> std::io::Result<usize> {
            let Some((&b, rest)) = self.0.split_first() else {
                return Ok(0);
            };
            match buf.first_mut() {
                Some(slot) => {
                    *slot = b;
                    self.0 = rest;
                    Ok(1)
                }
                None => Ok(0),
            }
        }
    }

    #[test]
    fn the_stream_reads_what_the_whole_file_reader_reads_and_where_a_cut_file_ends() {
        let bytes = states_recording(40);
        let whole = read_recording(&bytes).unwrap();
        assert_eq!(
            (whole.states.len(), whole.operator.as_deref()),
            (40, Some("op-7"))
        );
        let mut streamed = Recording::default();
        let stats = stream_recording(Trickle(&bytes), &mut streamed).unwrap();
        assert_eq!(streamed.states, whole.states);
        assert_eq!(streamed.operator.as_deref(), Some("op-7"));
        assert!(stats.complete, "{:?}", stats.problems);
        assert_eq!(
            stats.problems, whole.problems,
            "the same file, the same words"
        );
        assert_eq!((stats.messages, stats.bytes), (40, bytes.len() as u64));

        // Cut in the middle: what came before is read, and the problem says where it ends.
        let mut cut = Recording::default();
        let stats = stream_recording(&bytes[..bytes.len() / 2], &mut cut).unwrap();
        assert!(!stats.complete);
        assert!(
            cut.states.len() > 5 && cut.states.len() < 40,
            "{}",
            cut.states.len()
        );
        assert_eq!(cut.states[..], whole.states[..cut.states.len()]);
        assert!(
            stats
                .problems
                .iter()
                .any(|p| p.contains("could be read only up to")),
            "{:?}",
            stats.problems
        );
        // Not MCAP at all.
        assert!(matches!(
            stream_recording(&b"not a recording"[..], &mut Recording::default()),
            Err(ReviewError::NotMcap { .. })
        ));
    }

    /// Streamed over several batches between the reading and the decoding thread: every message in
    /// order, as the whole-file reader reads them; a damaged chunk far in stops the stream there,
    /// with the messages before it read.
    #[test]
    fn a_long_recording_streams_across_batches_in_order_and_stops_at_damage() {
        let n = 3 * BATCH_RECORDS as u64;
        let bytes = states_recording_compressed(n, Some(mcap::Compression::Zstd));
        let whole = read_recording(&bytes).unwrap();
        let mut streamed = Recording::default();
        let stats = stream_recording(&bytes[..], &mut streamed).unwrap();
        assert!(stats.complete, "{:?}", stats.problems);
        assert_eq!(streamed.states.len() as u64, n);
        assert!(
            streamed.states == whole.states,
            "the same messages in the same order"
        );
        let summary = mcap::Summary::read(&bytes).unwrap().unwrap();
        let index = &summary.chunk_indexes[2 * BATCH_RECORDS];
        let mut damaged = bytes.clone();
        damaged[(index.chunk_start_offset + index.chunk_length) as usize - 6] ^= 0x55;
        let mut cut = Recording::default();
        let stats = stream_recording(&damaged[..], &mut cut).unwrap();
        assert!(!stats.complete);
        assert!(
            cut.states.len() >= 2 * BATCH_RECORDS - 1 && cut.states.len() <= 2 * BATCH_RECORDS,
            "{}",
            cut.states.len()
        );
        assert!(cut.states[..] == whole.states[..cut.states.len()]);
    }

    /// A compressed chunk that unpacks into a record larger than the readers take (a zstd "bomb":
    /// 257 MiB of zeros is a few kB compressed) is refused unread by every path, never allocated.
    #[test]
    fn a_compressed_record_past_the_size_bound_is_refused_unread() {
        let (mut w, channel) = states_writer(
            Some(mcap::Compression::Zstd),
            Some(mcap::WriteOptions::DEFAULT_CHUNK_SIZE),
        );
        let header = |k: u64| state_header(channel, k);
        w.write_to_known_channel(&header(0), &cdr::encode(&state("working")).unwrap())
            .unwrap();
        w.flush().unwrap();
        w.write_to_known_channel(&header(1), &vec![0u8; MAX_RECORD_BYTES + 1])
            .unwrap();
        w.finish().unwrap();
        let bytes = w.into_inner().into_inner();
        assert!(bytes.len() < 1 << 20, "{} bytes: compressed", bytes.len());
        // through the summary: that chunk skipped, the first read
        let read = read_recording(&bytes).unwrap();
        assert_eq!((read.states.len(), read.complete), (1, false));
        // streamed, and linearly (no summary): read up to it
        let mut streamed = Recording::default();
        let stats = stream_recording(&bytes[..], &mut streamed).unwrap();
        assert_eq!((streamed.states.len(), stats.complete), (1, false));
        let summary = mcap::Summary::read(&bytes).unwrap().unwrap();
        let last = summary.chunk_indexes.last().unwrap();
        let cut = &bytes[..(last.chunk_start_offset + last.chunk_length) as usize];
        let linear = read_recording(cut).unwrap();
        assert_eq!((linear.states.len(), linear.complete), (1, false));
    }

    /// Recordings as rosbag2, Foxglove and Python's mcap write them (zstd or lz4 chunks) read as the
    /// uncompressed one does, by every reader; a damaged compressed chunk is skipped and named; a
    /// compression this build does not decompress is refused with the ones it does.
    #[test]
    fn zstd_and_lz4_recordings_read_as_uncompressed_ones_and_damage_is_found() {
        let plain_bytes = states_recording(40);
        let plain = read_recording(&plain_bytes).unwrap();
        assert_eq!(plain.states.len(), 40);
        // cut before chunk 30's start: what the linear reader makes of a file without its summary
        let plain_summary = mcap::Summary::read(&plain_bytes).unwrap().unwrap();
        let plain_cut = read_recording(
            &plain_bytes[..plain_summary.chunk_indexes[30].chunk_start_offset as usize],
        )
        .unwrap();
        assert!(plain_cut.states.len() >= 29 && !plain_cut.complete);
        let same = |a: &Recording, b: &Recording| a.states == b.states;
        for compression in [mcap::Compression::Zstd, mcap::Compression::Lz4] {
            let bytes = states_recording_compressed(40, Some(compression));
            let summary = mcap::Summary::read(&bytes).unwrap().unwrap();
            assert!(
                summary.chunk_indexes.len() >= 40,
                "{compression:?}: one chunk a state"
            );
            let first = summary.chunk_indexes[0].chunk_start_offset as usize + 9;
            let Ok(mcap::records::Record::Chunk { header, .. }) =
                mcap::parse_record(mcap::records::op::CHUNK, &bytes[first..])
            else {
                panic!("{compression:?}: no chunk at the index");
            };
            assert_ne!(
                header.compression, "",
                "{compression:?}: written compressed"
            );

            // through the summary's index, linearly (no summary: cut before it) and streamed
            let whole = read_recording(&bytes).unwrap();
            assert!(same(&whole, &plain), "{compression:?}");
            assert!(whole.complete, "{compression:?}: {:?}", whole.problems);
            let mut streamed = Recording::default();
            let stats = stream_recording(Trickle(&bytes), &mut streamed).unwrap();
            assert!(same(&streamed, &plain), "{compression:?}");
            assert!(stats.complete, "{compression:?}: {:?}", stats.problems);
            let cut = &bytes[..summary.chunk_indexes[30].chunk_start_offset as usize];
            let linear = read_recording(cut).unwrap();
            assert!(same(&linear, &plain_cut), "{compression:?}");

            // one chunk's compressed bytes damaged: that chunk skipped, the others read
            let mut damaged = bytes.clone();
            let index = &summary.chunk_indexes[10];
            let at = (index.chunk_start_offset + index.chunk_length) as usize - 6;
            damaged[at] ^= 0x55;
            let read = read_recording(&damaged).unwrap();
            assert!(!read.complete, "{compression:?}");
            assert_eq!(read.states.len(), 39, "{compression:?}");
            // said: the chunk skipped, and the summary's count not reached
            assert_eq!(
                read.problems.len(),
                whole.problems.len() + 2,
                "{compression:?}: {:?}",
                read.problems
            );
        }
        // a compression no reader here decompresses ("zstd" renamed in place, same length)
        let mut bytes = states_recording_compressed(40, Some(mcap::Compression::Zstd));
        let mut renamed = 0;
        for at in 0..bytes.len() - 8 {
            if &bytes[at..at + 8] == b"\x04\0\0\0zstd" {
                bytes[at + 7] = b'x';
                renamed += 1;
            }
        }
        assert!(renamed >= 40, "{renamed}");
        // through the summary: every chunk skipped, said once; linearly: the first chunk stops it
        for read in [
            read_recording(&bytes),
            read_recording(&bytes[..bytes.len() / 2]),
        ] {
            let Err(ReviewError::NotMcap { reason }) = read else {
                panic!("read: {read:?}");
            };
            assert_eq!(reason.matches("zstx-compressed").count(), 1, "{reason}");
        }
    }
}
