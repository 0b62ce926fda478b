//! Session recordings: the MCAP's profile, schemas and CDR payloads decode back to the messages, and a
//! file whose writer was killed (no summary, no footer) still yields every message up to the last
//! one-second flush.
#![allow(clippy::unwrap_used, clippy::expect_used)]

use std::path::PathBuf;

use ergocell::recording::{topics, McapRecorder};
use ergocell_bridge::cdr;
use ergocell_bridge::msg::{Header, JointState, MarkerArray, RosMessage, SessionState};

fn path(name: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join(name)
}

fn state(k: i64) -> SessionState {
    SessionState {
        header: Header::new(k * 100_000_000, "world"),
        state: "working".into(),
        height_m: 1.75,
        cameras_fresh: 6,
        ..SessionState::default()
    }
}

#[test]
fn finished_recording_has_ros2_profile_schemas_and_decodable_messages() {
    let p = path("finished.mcap");
    let mut rec = McapRecorder::create(&p).unwrap();
    for k in 0..30 {
        rec.write(topics::SESSION_STATE, k * 100_000_000, &state(k))
            .unwrap();
    }
    let js = JointState {
        header: Header::new(5, ""),
        name: vec!["joint_1".into()],
        position: vec![0.5],
        ..JointState::default()
    };
    rec.write(topics::JOINT_STATES, 3_000_000_000, &js).unwrap();
    assert_eq!(rec.finish().unwrap(), 31);

    let bytes = std::fs::read(&p).unwrap();
    let header = mcap::read::LinearReader::new(&bytes)
        .unwrap()
        .find_map(|r| match r.unwrap() {
            mcap::records::Record::Header(h) => Some(h),
            _ => None,
        })
        .unwrap();
    assert_eq!(header.profile, "ros2");
    // every chunk compressed as the recorder says (`run` and `demo` print it)
    let compressions: std::collections::BTreeSet<String> = mcap::read::LinearReader::new(&bytes)
        .unwrap()
        .filter_map(|r| match r.unwrap() {
            mcap::records::Record::Chunk { header, .. } => Some(header.compression),
            _ => None,
        })
        .collect();
    assert_eq!(
        compressions,
        [ergocell::recording::COMPRESSION.to_owned()].into()
    );
    let mut states = 0;
    for m in mcap::MessageStream::new(&bytes).unwrap() {
        let m = m.unwrap();
        let schema = m.channel.schema.as_ref().unwrap();
        assert_eq!(schema.encoding, "ros2msg");
        assert_eq!(m.channel.message_encoding, "cdr");
        if m.channel.topic == topics::SESSION_STATE {
            assert_eq!(schema.name, "ergocell_msgs/msg/SessionState");
            assert_eq!(
                std::str::from_utf8(&schema.data).unwrap(),
                SessionState::schema_text()
            );
            let s: SessionState = cdr::decode(&m.data).unwrap();
            assert_eq!(s, state(states));
            states += 1;
        } else {
            assert_eq!(schema.name, "sensor_msgs/msg/JointState");
            assert_eq!(cdr::decode::<JointState>(&m.data).unwrap(), js);
        }
    }
    assert_eq!(states, 30);
}

#[test]
fn killed_recording_is_readable_up_to_the_last_second() {
    let p = path("killed.mcap");
    let mut rec = McapRecorder::create(&p).unwrap();
    // 2.5 s at 10 Hz: chunks are flushed at 1 s and 2 s of log time.
    for k in 0..25 {
        rec.write(topics::SESSION_STATE, k * 100_000_000, &state(k))
            .unwrap();
    }
    // "Kill": read the file as it is on disk while the writer is still open.
    let bytes = std::fs::read(&p).unwrap();
    let options = enumset::EnumSet::only(mcap::read::Options::IgnoreEndMagic);
    let mut read = Vec::new();
    for m in mcap::read::MessageStream::new_with_options(&bytes, options).unwrap() {
        match m {
            Ok(m) => read.push(cdr::decode::<SessionState>(&m.data).unwrap()),
            Err(_) => break,
        }
    }
    assert!(read.len() >= 20, "{} messages recovered", read.len());
    for (k, s) in read.iter().enumerate() {
        assert_eq!(*s, state(k as i64));
    }
    drop(rec);
}

#[test]
fn skeleton_markers_hold_every_landmark_and_bone() {
    let truth = ergocell_sim::Operator::new(1.75).unwrap();
    let mut script = ergocell_sim::SessionScript::new(nalgebra::Point3::new(0.41, -0.10, 1.055));
    script.cycles = 1;
    let rig = ergocell_sim::ring_rig(6, &ergocell_sim::RingRigConfig::default()).unwrap();
    let mut sim =
        ergocell_sim::Simulation::new(rig, truth, script, ergocell_sim::SimConfig::new(1)).unwrap();
    let tick = sim.step().unwrap().unwrap();
    let m = ergocell::messages::skeleton_message(&tick.truth.skeleton, 3);
    assert_eq!(m.markers.len(), 2);
    assert_eq!(m.markers[0].points.len(), 33);
    assert_eq!(
        m.markers[1].points.len(),
        2 * ergocell_skeleton::BONES.len()
    );
    assert_eq!(m.markers[0].header.frame_id, "world");
    let p = tick
        .truth
        .skeleton
        .position(ergocell_skeleton::Landmark::Nose)
        .unwrap();
    assert_eq!(m.markers[0].points[0].z, p.z);
    assert_eq!(
        cdr::decode::<MarkerArray>(&cdr::encode(&m).unwrap()).unwrap(),
        m
    );
}

/// #18: a recording was not flushed while no messages arrived (92 bytes after 8 s, unreadable after
/// kill -9). The header is on disk at once, and `tick` on the session's clock flushes whatever was
/// written more than a second ago, messages or not.
#[test]
fn a_recording_is_flushed_on_a_timer_while_no_messages_arrive() {
    let read_on_disk = |p: &std::path::Path| -> Option<usize> {
        let bytes = std::fs::read(p).unwrap();
        let options = enumset::EnumSet::only(mcap::read::Options::IgnoreEndMagic);
        let stream = mcap::read::MessageStream::new_with_options(&bytes, options).ok()?;
        Some(stream.take_while(Result::is_ok).count())
    };
    let p = path("quiet.mcap");
    let mut rec = McapRecorder::create(&p).unwrap();
    assert_eq!(
        read_on_disk(&p),
        Some(0),
        "the header is on disk before any message"
    );
    // Two messages in the first 200 ms, then silence: no write ever reaches the 1 s flush.
    rec.write(topics::SESSION_STATE, 0, &state(0)).unwrap();
    rec.write(topics::SESSION_STATE, 200_000_000, &state(1))
        .unwrap();
    rec.tick(500_000_000).unwrap();
    assert_eq!(
        read_on_disk(&p),
        Some(0),
        "not yet a second: still buffered"
    );
    rec.tick(1_100_000_000).unwrap();
    assert_eq!(
        read_on_disk(&p),
        Some(2),
        "flushed by the timer, with no new message"
    );
    drop(rec);
}

/// #18: `replay` of a damaged file warned of nothing. Reading a recording's camera messages reports
/// where and why it stopped; a cut file gives what it holds.
#[test]
fn replay_of_a_damaged_file_says_where_it_stops() {
    let p = path("replay-damaged.mcap");
    let mut rec = McapRecorder::create(&p).unwrap();
    let view = ergocell_bridge::msg::CameraLandmarks {
        camera_id: "s1_left".into(),
        ..Default::default()
    };
    for k in 0..30 {
        rec.write(&topics::camera("s1_left"), k * 100_000_000, &view)
            .unwrap();
    }
    rec.finish().unwrap();
    let bytes = std::fs::read(&p).unwrap();
    let whole = ergocell::recording::read_camera_landmarks(&bytes).unwrap();
    assert_eq!(
        (whole.frames.len(), whole.damaged.clone(), whole.undecodable),
        (30, None, 0)
    );
    // Cut in the middle of the (compressed) chunk that holds them (a crash, a partial copy): fewer
    // messages, and why.
    let summary = mcap::Summary::read(&bytes).unwrap().unwrap();
    let chunk = &summary.chunk_indexes[0];
    let middle = (chunk.chunk_start_offset + chunk.chunk_length / 2) as usize;
    let cut = ergocell::recording::read_camera_landmarks(&bytes[..middle]).unwrap();
    assert!(cut.frames.len() < 30, "{}", cut.frames.len());
    assert!(cut.damaged.is_some(), "the cut is reported");
}

/// `replay` of a recording whose compressed chunk unpacks into a record past the bound (a zstd
/// "bomb": 257 MiB of zeros in a few kB): the camera messages before it are read and the reading
/// stops there, said, without allocating it.
#[test]
fn replay_refuses_a_compressed_record_past_the_size_bound() {
    let mut w = mcap::WriteOptions::new()
        .profile("ros2")
        .compression(Some(mcap::Compression::Zstd))
        .create(std::io::Cursor::new(Vec::new()))
        .unwrap();
    let schema = w
        .add_schema(
            &ergocell_bridge::msg::CameraLandmarks::type_name(),
            "ros2msg",
            b"",
        )
        .unwrap();
    let channel = w
        .add_channel(
            schema,
            &topics::camera("s1_left"),
            "cdr",
            &std::collections::BTreeMap::default(),
        )
        .unwrap();
    let header = |k: u32| mcap::records::MessageHeader {
        channel_id: channel,
        sequence: k,
        log_time: u64::from(k) * 100_000_000,
        publish_time: u64::from(k) * 100_000_000,
    };
    let view = ergocell_bridge::msg::CameraLandmarks {
        camera_id: "s1_left".into(),
        ..Default::default()
    };
    for k in 0..3 {
        w.write_to_known_channel(&header(k), &cdr::encode(&view).unwrap())
            .unwrap();
    }
    w.flush().unwrap();
    let bound = ergocell_ros_backend::recording::MAX_RECORD_BYTES;
    w.write_to_known_channel(&header(3), &vec![0u8; bound + 1])
        .unwrap();
    w.finish().unwrap();
    let bytes = w.into_inner().into_inner();
    assert!(bytes.len() < 1 << 20, "{} bytes: compressed", bytes.len());
    let read = ergocell::recording::read_camera_landmarks(&bytes).unwrap();
    assert_eq!(read.frames.len(), 3);
    assert!(read.damaged.is_some(), "the bound is said");
}
