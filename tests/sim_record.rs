//! `ergocell sim adaptation --record-height`: one operator's task recorded before and after the
//! adaptation. The two recordings differ only in the handover point the operator reaches for, are
//! byte-identical for the same seed, and open side by side in `ergocell report --compare`.

#![allow(clippy::unwrap_used, clippy::expect_used)]

use std::path::PathBuf;
use std::process::Command;

use ergocell::sim_record::record_both;
use ergocell_formats::rig_file::parse_rig;
use ergocell_sim::experiments::{Handovers, Setup};
use ergocell_sim::DetectorNoise;
use nalgebra::Point3;

fn setup(seed: u64) -> Setup {
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR"));
    let text = std::fs::read_to_string(root.join("config/rig.toml")).unwrap();
    let (rig, _) = parse_rig(&text, "config/rig.toml").unwrap();
    Setup {
        rig,
        noise: DetectorNoise::default(),
        seed,
    }
}

fn handovers() -> Handovers {
    Handovers {
        before_m: Point3::new(0.45, 0.0, 1.10),
        c1_m: Point3::new(0.42, 0.0, 0.98),
        c2_m: Point3::new(0.45, 0.0, 1.10),
        c3_m: Point3::new(0.48, 0.0, 1.22),
        c1_stature_m: [1.55, 1.68],
        c2_stature_m: [1.68, 1.82],
        c3_stature_m: [1.82, 1.95],
        c1_served_m: [1.55, 1.68],
        c2_served_m: [1.68, 1.82],
        c3_served_m: [1.82, 1.95],
    }
}

#[test]
fn before_and_after_recordings_differ_in_the_handover_only_and_are_deterministic() {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("sim-record");
    let again = dir.join("again");
    std::fs::create_dir_all(&again).unwrap();
    let [before, after] = record_both(&setup(5), &handovers(), 1.60, 1, &dir).unwrap();
    let [before2, _] = record_both(&setup(5), &handovers(), 1.60, 1, &again).unwrap();
    assert_eq!(
        std::fs::read(&before).unwrap(),
        std::fs::read(&before2).unwrap(),
        "same seed, same bytes"
    );
    // Each fused frame is recorded as a session records it (`messages::frame_messages`): its
    // skeleton markers, operator pose, RULA and REBA state, one of each.
    let bytes = std::fs::read(&before).unwrap();
    let mut per_topic = std::collections::BTreeMap::<String, usize>::new();
    for m in mcap::MessageStream::new(&bytes).unwrap() {
        *per_topic
            .entry(m.unwrap().channel.topic.clone())
            .or_default() += 1;
    }
    let frames = per_topic[ergocell_bridge::topics::OPERATOR_POSE];
    assert!(frames > 50, "{per_topic:?}");
    for topic in [
        ergocell_bridge::topics::SKELETON,
        ergocell_bridge::topics::ERGONOMICS,
        ergocell_bridge::topics::REBA,
    ] {
        assert_eq!(
            per_topic.get(topic),
            Some(&frames),
            "{topic}: {per_topic:?}"
        );
    }

    let html = dir.join("compare.html");
    let out = Command::new(env!("CARGO_BIN_EXE_ergocell"))
        .args(["report", before.to_str().unwrap(), "--compare"])
        .arg(&after)
        .arg("--out")
        .arg(&html)
        .arg("--force")
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let html = std::fs::read_to_string(&html).unwrap();
    let start = html.find("window.ERGOCELL_REVIEW_DATA = ").unwrap() + 30;
    let end = start + html[start..].find(";</script>").unwrap();
    let data: serde_json::Value = serde_json::from_str(&html[start..end]).unwrap();
    let sessions = data["sessions"].as_array().unwrap();
    assert_eq!(sessions.len(), 2);
    let hp = |k: usize| -> Vec<f64> {
        sessions[k]["robot"]["handover_point"]
            .as_array()
            .unwrap()
            .iter()
            .map(|v| v.as_f64().unwrap())
            .collect()
    };
    // A 1.60 m operator is c1: before reaches for the 1.75 m point, after for c1's lower one.
    assert_eq!(hp(0), vec![0.45, 0.0, 1.10]);
    assert_eq!(hp(1), vec![0.42, 0.0, 0.98]);
    for s in sessions {
        assert_eq!(s["facts"]["height_class"], "c1");
        assert!((s["facts"]["height_m"].as_f64().unwrap() - 1.60).abs() < 1e-12);
        assert!(s["frames"]["t"].as_array().unwrap().len() > 50);
        assert!(
            s["robot"]["tcp"].is_null(),
            "the simulator's task has no robot motion"
        );
    }
    assert_eq!(
        sessions[0]["frames"]["t"], sessions[1]["frames"]["t"],
        "the same script, the same frame times"
    );
}

#[test]
fn an_operator_the_cell_does_not_serve_after_adaptation_is_not_recorded() {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("sim-record-unserved");
    std::fs::create_dir_all(&dir).unwrap();
    let err = record_both(&setup(5), &handovers(), 2.00, 1, &dir).unwrap_err();
    assert!(err.to_string().contains("does not serve"), "{err}");
    assert!(
        !dir.join("adaptation_2.00m_before.mcap").exists(),
        "nothing written"
    );
}
