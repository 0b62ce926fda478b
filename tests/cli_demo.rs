//! `ergocell demo` end to end, as the README runs it: a whole session, the locked trajectory's hash in
//! the output, the floor pick's posture warning raised and cleared, a readable MCAP with every topic,
//! and no approval written into `trajectories/approvals/`.
#![allow(clippy::unwrap_used, clippy::expect_used)]

use std::collections::BTreeSet;
use std::path::Path;
use std::process::Command;

#[test]
fn demo_runs_a_whole_session_and_records_it() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let out = Path::new(env!("CARGO_TARGET_TMPDIR")).join("cli-demo.mcap");
    let approvals = root.join("trajectories/approvals");
    let approvals_before = approvals.exists();
    let run = Command::new(env!("CARGO_BIN_EXE_ergocell"))
        .current_dir(root)
        .args(["--log", "error", "demo", "--cycles", "1", "--out"])
        .arg(&out)
        .output()
        .unwrap();
    let stdout = String::from_utf8_lossy(&run.stdout);
    assert!(
        run.status.success(),
        "{stdout}\n{}",
        String::from_utf8_lossy(&run.stderr)
    );
    let lock = std::fs::read_to_string(root.join("trajectories/locks/c2.lock.toml")).unwrap();
    let sha = lock
        .lines()
        .find_map(|l| l.strip_prefix("lock_sha256 = \""))
        .unwrap()
        .trim_end_matches('"');
    for expected in [
        "DEMO APPROVAL",
        "→ class c2",
        &format!("locked: sha256 {sha}"),
        "robot ← HOLD",
        "state held → working",
        "change to c3 refused",
        "session:        session_ended",
        "floor pick after handover cycle 1",
        "RULA warning: Trunk bent forward",
        "RULA warning: Trunk back within limits",
    ] {
        assert!(
            stdout.contains(expected),
            "missing `{expected}` in:\n{stdout}"
        );
    }
    // The floor pick raises at least one posture warning.
    let raised: u32 = stdout
        .lines()
        .find_map(|l| l.trim().strip_prefix("RULA:"))
        .and_then(|l| l.split_whitespace().next())
        .and_then(|n| n.parse().ok())
        .unwrap_or_else(|| panic!("no `RULA: N warnings raised` in:\n{stdout}"));
    assert!(raised >= 1, "no warning raised:\n{stdout}");
    assert_eq!(
        approvals.exists(),
        approvals_before,
        "the demo never writes trajectories/approvals/"
    );

    let bytes = std::fs::read(&out).unwrap();
    let topics: BTreeSet<String> = mcap::MessageStream::new(&bytes)
        .unwrap()
        .map(|m| m.unwrap().channel.topic.clone())
        .collect();
    for t in [
        "/ergocell/session_state",
        "/ergocell/ergonomics",
        "/ergocell/skeleton",
        "/ergocell/camera/s1_left/landmarks",
        "/joint_states",
        "/joint_trajectory_controller/joint_trajectory",
    ] {
        assert!(topics.contains(t), "{t} not in {topics:?}");
    }
}
