//! SROS2 keystores from `ergocell_bridge::security`: RustDDS's DDS Security accepts what is generated
//! (identity chain, private key, signed governance and permissions), each enclave may create exactly the
//! writers and readers its permissions grant, and a tampered permissions file is refused. Participants
//! are created (local checks); no traffic is needed.

#![allow(clippy::unwrap_used, clippy::expect_used)]

use std::path::{Path, PathBuf};

use ergocell_bridge::msg::{CameraLandmarks, JointTrajectory};
use ergocell_bridge::qos;
use ergocell_bridge::scope::{NetworkScope, ScopeEnv};
use ergocell_bridge::security::{cell_enclaves, create_keystore};
use ergocell_bridge::transport::{RosConfig, RosNode};

fn cell() -> RosConfig {
    let text =
        std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("../config/cell.toml"))
            .unwrap();
    RosConfig::from_cell_toml(&text).unwrap()
}

/// Seconds since the Unix epoch, for the certificates' and permissions' validity.
#[allow(clippy::disallowed_methods)]
fn now() -> i64 {
    std::time::SystemTime::now()
        .duration_since(std::time::UNIX_EPOCH)
        .unwrap()
        .as_secs() as i64
}

fn keystore(name: &str) -> PathBuf {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join(name);
    let _ = std::fs::remove_dir_all(&dir);
    // Valid from an hour ago: the permissions' validity is checked against the clock.
    for f in create_keystore(0, &cell_enclaves(&cell()), now() - 3600, 30).unwrap() {
        let path = dir.join(&f.path);
        std::fs::create_dir_all(path.parent().unwrap()).unwrap();
        std::fs::write(path, f.contents).unwrap();
    }
    dir
}

fn localhost() -> NetworkScope {
    NetworkScope::resolve(
        None,
        None,
        &ScopeEnv {
            automatic_discovery_range: Some("LOCALHOST".to_owned()),
            ..ScopeEnv::default()
        },
    )
    .unwrap()
}

#[test]
fn generated_enclaves_are_accepted_and_grant_exactly_their_topics() {
    let ks = keystore("sros2-keystore");
    let ros = cell();
    let scope = localhost();
    // The camera s1_left may publish its own landmarks, not another camera's, and not to the robot.
    let mut camera = RosNode::new(
        0,
        "/ergocell",
        "camera_s1_left",
        &scope,
        Some(&ks.join("enclaves/ergocell/camera/s1_left")),
    )
    .unwrap();
    camera
        .publisher::<CameraLandmarks>(&ros.camera_topic_of("s1_left"), qos::CAMERA_LANDMARKS)
        .unwrap();
    assert!(camera
        .publisher::<CameraLandmarks>(&ros.camera_topic_of("s2_left"), qos::CAMERA_LANDMARKS)
        .is_err());
    assert!(camera
        .publisher::<JointTrajectory>(&ros.joint_trajectory_topic, qos::TRAJECTORY_COMMAND)
        .is_err());
    // The cell may command the robot and read the cameras; the recorder may only listen.
    let mut cell_node = RosNode::new(
        0,
        "/ergocell",
        "cell",
        &scope,
        Some(&ks.join("enclaves/ergocell/cell")),
    )
    .unwrap();
    cell_node
        .publisher::<JointTrajectory>(&ros.joint_trajectory_topic, qos::TRAJECTORY_COMMAND)
        .unwrap();
    cell_node
        .subscription::<CameraLandmarks>(&ros.camera_topic_of("s3_right"), qos::CAMERA_LANDMARKS)
        .unwrap();
    let mut recorder = RosNode::new(
        0,
        "/ergocell",
        "recorder",
        &scope,
        Some(&ks.join("enclaves/ergocell/recorder")),
    )
    .unwrap();
    recorder
        .subscription::<JointTrajectory>(&ros.joint_trajectory_topic, qos::TRAJECTORY_COMMAND)
        .unwrap();
    assert!(recorder
        .publisher::<JointTrajectory>(&ros.joint_trajectory_topic, qos::TRAJECTORY_COMMAND)
        .is_err());
}

#[test]
fn a_tampered_permissions_file_or_a_missing_enclave_is_refused() {
    let ks = keystore("sros2-tampered");
    let enclave = ks.join("enclaves/ergocell/camera/s1_left");
    let p7s = enclave.join("permissions.p7s");
    let text = std::fs::read_to_string(&p7s).unwrap();
    let widened = text.replacen(
        "<topic>rt/ergocell/camera/s1_left/landmarks</topic>",
        "<topic>rt/*</topic>",
        1,
    );
    assert_ne!(widened, text);
    std::fs::write(&p7s, widened).unwrap();
    assert!(
        RosNode::new(
            0,
            "/ergocell",
            "camera_s1_left",
            &localhost(),
            Some(&enclave)
        )
        .is_err(),
        "a permissions file edited after signing must be refused"
    );
    let err = RosNode::new(
        0,
        "/ergocell",
        "x",
        &localhost(),
        Some(&ks.join("enclaves/nowhere")),
    )
    .err()
    .unwrap();
    assert!(err.to_string().contains("no identity_ca.cert.pem"), "{err}");
}
