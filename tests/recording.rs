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
