//! Lock files, approvals and verification: any edited byte is caught, approvals bind to one hash, and the
//! session lock refuses changes until the session ends.

// Test and bench helpers panic on purpose: a panic is the failure report.
#![allow(clippy::unwrap_used, clippy::expect_used)]

mod common;

use std::path::PathBuf;

use ergocell_robot::lock::{self, ApprovalsFile, LockFile, SessionLock, VerifyInputs};
use ergocell_robot::{
    plan_and_validate, InputHashes, PlanInputs, RobotError, RobotModel, TrajectoryClass,
    TrajectorySpec,
};

const CLASS: TrajectoryClass = TrajectoryClass::C2;

fn lock_for(s: &common::Shipped, text: &str) -> LockFile {
    let spec = TrajectorySpec::from_toml_str(text).unwrap();
    let hashes = common::hashes(s, text);
    let locked = plan_and_validate(&PlanInputs {
        model: &s.model,
        cell: &s.cell,
        spec: &spec,
        hashes: &hashes,
    })
    .unwrap()
    .into_locked()
    .unwrap();
    LockFile::from_locked(&locked)
}

fn inputs<'a>(
    lock_toml: &'a str,
    current: &'a InputHashes,
    model: &'a RobotModel,
    approvals: Option<&'a str>,
) -> VerifyInputs<'a> {
    VerifyInputs {
        class: CLASS,
        lock_toml,
        current_inputs: current,
        model,
        approvals_toml: approvals,
        trusted: trusted(),
    }
}

/// The test approvers (alice and bob), parsed once.
fn trusted() -> &'static ergocell_robot::TrustedSigners {
    static T: std::sync::OnceLock<ergocell_robot::TrustedSigners> = std::sync::OnceLock::new();
    T.get_or_init(|| common::signers().trusted)
}

/// A fresh directory under the system temp dir (no wall clock: pid + test name).
fn temp_dir(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("ergocell_robot_{}_{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

#[test]
fn a_lock_round_trips_through_toml_with_the_same_hash() {
    let s = common::shipped();
    let text = common::spec_text(CLASS);
    let lock = lock_for(&s, &text);
    let toml = lock.to_toml().unwrap();
    let parsed = LockFile::from_toml_str(CLASS, &toml).unwrap();
    assert_eq!(parsed, lock);
    assert_eq!(parsed.content_sha256(), lock.lock_sha256);
    assert!(toml.contains("lock_sha256 = \""));
}

#[test]
fn verify_without_an_approval_fails_naming_what_is_missing() {
    let s = common::shipped();
    let text = common::spec_text(CLASS);
    let lock = lock_for(&s, &text);
    let toml = lock.to_toml().unwrap();
    let current = common::hashes(&s, &text);
    lock::verify_integrity(&inputs(&toml, &current, &s.model, None)).unwrap();
    let failure = lock::verify(&inputs(&toml, &current, &s.model, None)).unwrap_err();
    assert_eq!(failure.problems.len(), 1);
    let msg = failure.to_string();
    assert!(
        msg.contains(&lock.lock_sha256)
            && msg.contains("approvals/c2.toml")
            && msg.contains("approve"),
        "{msg}"
    );
}

#[test]
fn an_approval_in_a_temp_dir_verifies_and_binds_to_exactly_that_hash() {
    let s = common::shipped();
    let text = common::spec_text(CLASS);
    let lock = lock_for(&s, &text);
    let toml = lock.to_toml().unwrap();
    let current = common::hashes(&s, &text);

    let dir = temp_dir("approval");
    let path = dir.join("c2.toml");
    let t = common::signers();
    let mut approvals = ApprovalsFile::default();
    approvals
        .approve(
            &lock,
            common::ALICE,
            "2026-01-01T00:00:00Z",
            &t.trusted,
            &t.alice,
        )
        .unwrap();
    std::fs::write(&path, approvals.to_toml().unwrap()).unwrap();
    let approvals_text = std::fs::read_to_string(&path).unwrap();

    let approved = lock::verify(&inputs(&toml, &current, &s.model, Some(&approvals_text))).unwrap();
    assert_eq!(approved.class(), CLASS);
    assert_eq!(approved.approvals()[0].approved_by, common::ALICE);
    assert_eq!(approved.points().len(), 100);

    // An approval of another hash does not carry over.
    let other = approvals_text.replace(&lock.lock_sha256, &"0".repeat(64));
    let failure = lock::verify(&inputs(&toml, &current, &s.model, Some(&other))).unwrap_err();
    assert!(
        matches!(failure.problems[0], RobotError::NotApproved { .. }),
        "{failure}"
    );

    // A second approval chains to the first; editing the first breaks the chain.
    approvals
        .approve(
            &lock,
            common::BOB,
            "2026-01-02T00:00:00Z",
            &t.trusted,
            &t.bob,
        )
        .unwrap();
    let chained = approvals.to_toml().unwrap();
    lock::verify(&inputs(&toml, &current, &s.model, Some(&chained))).unwrap();
    let forged = chained.replacen("2026-01-01T00:00:00Z", "2025-01-01T00:00:00Z", 1);
    let failure = lock::verify(&inputs(&toml, &current, &s.model, Some(&forged))).unwrap_err();
    assert!(
        failure.to_string().contains("hash chain broken at entry 1"),
        "{failure}"
    );

    // An empty name is refused.
    assert!(ApprovalsFile::default()
        .approve(&lock, "  ", "2026-01-01T00:00:00Z", &t.trusted, &t.alice)
        .is_err());
    let _ = std::fs::remove_dir_all(dir);
}

#[test]
fn editing_one_byte_of_the_trajectory_file_makes_verify_fail() {
    let s = common::shipped();
    let text = common::spec_text(CLASS);
    let lock = lock_for(&s, &text);
    let toml = lock.to_toml().unwrap();
    let t = common::signers();
    let mut approvals = ApprovalsFile::default();
    approvals
        .approve(
            &lock,
            common::ALICE,
            "2026-01-01T00:00:00Z",
            &t.trusted,
            &t.alice,
        )
        .unwrap();
    let approvals_text = approvals.to_toml().unwrap();

    // Change one byte: the handover height's last digit (still inside the class band, so only the
    // hash can tell). Even a comment byte would do.
    let mut bytes = text.clone().into_bytes();
    let line = text.find("\nheight_m = ").unwrap() + 1;
    let at = line + text[line..].find('\n').unwrap() - 1;
    bytes[at] = if bytes[at] == b'1' { b'2' } else { b'1' };
    let edited = String::from_utf8(bytes).unwrap();
    assert_eq!(edited.len(), text.len());
    let current = common::hashes(&s, &edited);
    let failure =
        lock::verify(&inputs(&toml, &current, &s.model, Some(&approvals_text))).unwrap_err();
    match &failure.problems[0] {
        RobotError::LockMismatch { what, .. } => {
            assert!(what.contains("trajectory file"), "{failure}");
        }
        other => panic!("expected LockMismatch, got {other:?}"),
    }

    // A one-byte edit inside the header comment also fails.
    let mut c = text.clone().into_bytes();
    assert!(c[0] == b'#' && c[2].is_ascii_alphabetic());
    c[2] ^= 0x20; // `H` → `h`
    let current = common::hashes(&s, &String::from_utf8(c).unwrap());
    assert!(lock::verify(&inputs(&toml, &current, &s.model, Some(&approvals_text))).is_err());
}

#[test]
fn editing_one_byte_of_the_lock_file_makes_verify_fail() {
    let s = common::shipped();
    let text = common::spec_text(CLASS);
    let lock = lock_for(&s, &text);
    let toml = lock.to_toml().unwrap();
    let current = common::hashes(&s, &text);
    // Change a digit inside the trajectory samples.
    let at = toml.find("positions_rad = [0.0, 0.3").unwrap() + "positions_rad = [0.0, 0.".len();
    let mut bytes = toml.into_bytes();
    bytes[at] = b'4';
    let edited = String::from_utf8(bytes).unwrap();
    let failure = lock::verify_integrity(&inputs(&edited, &current, &s.model, None)).unwrap_err();
    assert!(
        matches!(failure.problems[0], RobotError::LockCorrupt { .. }),
        "{failure}"
    );
    assert!(failure.to_string().contains("content was edited"));
}

#[test]
fn a_changed_urdf_or_cell_config_makes_verify_fail() {
    let s = common::shipped();
    let text = common::spec_text(CLASS);
    let lock = lock_for(&s, &text);
    let toml = lock.to_toml().unwrap();
    let urdf = s.urdf.replacen("effort=\"320\"", "effort=\"321\"", 1);
    let mut current = common::hashes(&s, &text);
    current.urdf_sha256 = ergocell_robot::validate::sha256_hex(urdf.as_bytes());
    let failure = lock::verify_integrity(&inputs(&toml, &current, &s.model, None)).unwrap_err();
    assert!(failure.to_string().contains("URDF changed"), "{failure}");

    let mut cell = s.cell.clone();
    cell.robot.base_xyz_m[0] += 0.001;
    let mut current = common::hashes(&s, &text);
    current.cell_sha256 = ergocell_robot::validate::sha256_hex(&cell.canonical_bytes());
    let failure = lock::verify_integrity(&inputs(&toml, &current, &s.model, None)).unwrap_err();
    assert!(failure.to_string().contains("cell config"), "{failure}");
}

#[test]
fn a_lock_for_another_class_is_refused() {
    let s = common::shipped();
    let text = common::spec_text(CLASS);
    let toml = lock_for(&s, &text).to_toml().unwrap();
    let err = LockFile::from_toml_str(TrajectoryClass::C1, &toml).unwrap_err();
    assert!(err.to_string().contains("file is for class c2"), "{err}");
}

#[test]
fn the_session_lock_refuses_changes_until_the_session_ends() {
    let s = common::shipped();
    let text = common::spec_text(CLASS);
    let lock = lock_for(&s, &text);
    let toml = lock.to_toml().unwrap();
    let current = common::hashes(&s, &text);
    let t = common::signers();
    let mut approvals = ApprovalsFile::default();
    approvals
        .approve(
            &lock,
            common::ALICE,
            "2026-01-01T00:00:00Z",
            &t.trusted,
            &t.alice,
        )
        .unwrap();
    let approvals_text = approvals.to_toml().unwrap();
    let approved = lock::verify(&inputs(&toml, &current, &s.model, Some(&approvals_text))).unwrap();

    let start = approved.points()[0].positions_rad.clone();
    approved.check_start(&start, 1e-3).unwrap();
    let mut elsewhere = start.clone();
    elsewhere[1] += 0.01;
    let err = approved.check_start(&elsewhere, 1e-3).unwrap_err();
    assert!(
        matches!(err, RobotError::StartMismatch { ref joint, .. } if joint == "joint_2"),
        "{err}"
    );

    let mut session = SessionLock::start(approved);
    assert!(session.request(TrajectoryClass::C2).is_ok());
    let err = session.request(TrajectoryClass::C3).unwrap_err();
    assert!(matches!(err, RobotError::SessionLocked { .. }), "{err}");
    assert_eq!(session.refused().len(), 1);
    let (session, err) = session.end(true, false).unwrap_err();
    assert!(err.to_string().contains("robot at home: false"));
    let refused = session.end(true, true).unwrap();
    assert_eq!(refused.len(), 1);
}

#[test]
fn the_committed_locks_match_the_committed_inputs() {
    // The shipped locks (trajectories/locks/) must stay in step with the trajectory files, URDF and
    // cell config: edit an input, and this test tells you to re-run `ergocell trajectories lock`.
    let s = common::shipped();
    let (allowed, revoked) = common::shipped_trust();
    let shipped_trust = ergocell_robot::TrustedSigners::parse(&allowed, &revoked).unwrap();
    for class in TrajectoryClass::ALL {
        let text = common::spec_text(class);
        let current = InputHashes::new(
            text.as_bytes(),
            s.urdf.as_bytes(),
            &s.cell,
            ergocell_robot::TrustFiles {
                allowed_signers: allowed.as_bytes(),
                revoked_keys: revoked.as_bytes(),
            },
            env!("CARGO_PKG_VERSION"),
        );
        let lock_text = common::read(common::layout().lock(class));
        let inputs = VerifyInputs {
            class,
            lock_toml: &lock_text,
            current_inputs: &current,
            model: &s.model,
            approvals_toml: None,
            trusted: &shipped_trust,
        };
        if let Err(f) = lock::verify_integrity(&inputs) {
            panic!("{f}\nre-run `ergocell trajectories lock` and have the locks re-approved");
        }
    }
}

#[test]
fn a_hand_edited_and_rehashed_lock_passes_integrity_but_not_the_validation_match() {
    let s = common::shipped();
    let text = common::spec_text(CLASS);
    let spec = TrajectorySpec::from_toml_str(&text).unwrap();
    let hashes = common::hashes(&s, &text);
    let validated = plan_and_validate(&PlanInputs {
        model: &s.model,
        cell: &s.cell,
        spec: &spec,
        hashes: &hashes,
    })
    .unwrap()
    .into_locked()
    .unwrap();
    let honest = LockFile::from_locked(&validated);
    lock::check_matches_validation(&honest, &validated).unwrap();
    let parsed = LockFile::from_toml_str(CLASS, &honest.to_toml().unwrap()).unwrap();
    lock::check_matches_validation(&parsed, &validated).unwrap();

    // 0.01 rad on joint 4 mid-way, lock_sha256 recomputed: every hash agrees, limits still hold.
    let mut forged = honest.clone();
    forged.trajectory.point[50].positions_rad[3] += 0.01;
    forged.lock_sha256 = forged.content_sha256();
    let toml = forged.to_toml().unwrap();
    assert!(lock::verify_integrity(&inputs(&toml, &hashes, &s.model, None)).is_ok());
    let err = lock::check_matches_validation(&forged, &validated).unwrap_err();
    assert!(matches!(err, RobotError::LockCorrupt { .. }), "{err}");
    assert!(
        err.to_string().contains("point 50: positions_rad[3]"),
        "{err}"
    );
}

/// The execution monitor's limits are the cell's `[monitor]` when the trajectory is locked: in the
/// lock, through its TOML, covered by the cell hash (another `[monitor]` is another cell). A lock
/// whose limits were loosened and re-hashed passes integrity but not the validation match; one
/// whose limit is out of range is refused on reading.
#[test]
fn the_monitor_limits_are_the_cells_when_locked_and_a_loosened_lock_is_refused() {
    let s = common::shipped();
    let text = common::spec_text(CLASS);
    let mut cell = s.cell.clone();
    cell.monitor.goal_tolerance_rad = 0.005;
    cell.monitor.stop_time_s = 0.3;
    let spec = TrajectorySpec::from_toml_str(&text).unwrap();
    let mut hashes = common::hashes(&s, &text);
    assert_eq!(
        hashes.cell_sha256,
        ergocell_robot::validate::sha256_hex(&s.cell.canonical_bytes())
    );
    hashes.cell_sha256 = ergocell_robot::validate::sha256_hex(&cell.canonical_bytes());
    assert_ne!(hashes.cell_sha256, common::hashes(&s, &text).cell_sha256);
    let validated = plan_and_validate(&PlanInputs {
        model: &s.model,
        cell: &cell,
        spec: &spec,
        hashes: &hashes,
    })
    .unwrap()
    .into_locked()
    .unwrap();
    let lock = LockFile::from_locked(&validated);
    assert_eq!(lock.summary.monitor, cell.monitor);
    let parsed = LockFile::from_toml_str(CLASS, &lock.to_toml().unwrap()).unwrap();
    assert_eq!(parsed.summary.monitor, cell.monitor);
    lock::check_matches_validation(&parsed, &validated).unwrap();

    let mut loosened = lock.clone();
    loosened.summary.monitor.goal_tolerance_rad = 0.5;
    loosened.lock_sha256 = loosened.content_sha256();
    let toml = loosened.to_toml().unwrap();
    assert!(lock::verify_integrity(&inputs(&toml, &hashes, &s.model, None)).is_ok());
    let err = lock::check_matches_validation(&loosened, &validated).unwrap_err();
    assert!(matches!(err, RobotError::LockCorrupt { .. }), "{err}");

    let mut bad = lock.clone();
    bad.summary.monitor.stall_window_s = 0.0;
    bad.lock_sha256 = bad.content_sha256();
    let err = LockFile::from_toml_str(CLASS, &bad.to_toml().unwrap()).unwrap_err();
    assert!(matches!(err, RobotError::LockCorrupt { .. }), "{err}");
}

/// `[monitor]` in the cell file: left out, the defaults; a value out of range or an unknown key is
/// refused.
#[test]
fn the_cells_monitor_table_is_optional_and_strict() {
    use ergocell_robot::monitor::MonitorLimits;
    let shipped = common::read("config/cell.toml");
    let cell = ergocell_robot::CellConfig::from_toml_str(&shipped).unwrap();
    let start = shipped.find("[monitor]").unwrap();
    let end = start + shipped[start..].find("\n[").unwrap();
    let without = format!("{}{}", &shipped[..start], &shipped[end..]);
    let default = ergocell_robot::CellConfig::from_toml_str(&without).unwrap();
    assert_eq!(default.monitor, MonitorLimits::default());
    assert_eq!(cell.monitor, MonitorLimits::default(), "the shipped values");
    for bad in [
        "stall_window_s = 0.0",
        "stop_time_s = 11.0",
        "stall_window = 0.1",
    ] {
        let text = shipped.replacen("stall_window_s = 0.1", bad, 1);
        assert_ne!(text, shipped);
        assert!(
            matches!(
                ergocell_robot::CellConfig::from_toml_str(&text),
                Err(RobotError::Config { .. })
            ),
            "{bad}"
        );
    }
}
