//! `ergocell sim` end to end: every experiment prints the JSON shape issue 5 promises, writes its JSON
//! and figures, and the same seed gives byte-identical output (a short run: 2 operators, 1 cycle).

// Test helpers outside `#[test]` functions unwrap too (clippy.toml allows it only inside them).
#![allow(clippy::unwrap_used, clippy::expect_used)]

use std::path::{Path, PathBuf};
use std::process::Command;

fn run(experiment: &str, seed: u64, out: &Path, extra: &[&str]) -> String {
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR"));
    let output = Command::new(env!("CARGO_BIN_EXE_ergocell"))
        .current_dir(&root)
        .args([
            "sim",
            experiment,
            "--json",
            "--operators",
            "2",
            "--cycles",
            "1",
        ])
        .args(["--seed", &seed.to_string()])
        .arg("--out-dir")
        .arg(out)
        .args(extra)
        .output()
        .unwrap();
    assert!(
        output.status.success(),
        "{experiment}: {}",
        String::from_utf8_lossy(&output.stderr)
    );
    String::from_utf8(output.stdout).unwrap()
}

fn out_dir(name: &str) -> PathBuf {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join(name);
    let _ = std::fs::remove_dir_all(&dir);
    dir
}

fn num_array(v: &serde_json::Value, len: usize) {
    let a = v.as_array().unwrap();
    assert_eq!(a.len(), len);
}

#[test]
fn table1_has_the_promised_shape_and_is_reproducible() {
    let dir = out_dir("sim_table1");
    let a = run("table1", 3, &dir, &[]);
    assert_eq!(a, run("table1", 3, &dir, &[]));
    assert_ne!(a, run("table1", 4, &dir, &[]));
    let v: serde_json::Value = serde_json::from_str(&a).unwrap();
    num_array(&v["landmarks"], 12);
    for key in ["S1", "S2", "S3", "paper_fusion", "default_fusion"] {
        num_array(&v["rmse_m"][key], 12);
    }
    assert!(dir.join("table1.json").exists() && dir.join("table1_rmse.svg").exists());
}

#[test]
fn adaptation_height_and_agreement_have_the_promised_shapes() {
    let dir = out_dir("sim_others");
    let v: serde_json::Value =
        serde_json::from_str(&run("adaptation", 1, &dir, &["--cameras", "4"])).unwrap();
    num_array(&v["heights_m"], 11);
    num_array(&v["mean_grand_score_before"], 11);
    num_array(&v["mean_grand_score_after"], 11);
    assert_eq!(v["setup"]["camera_count"], 4);
    let v: serde_json::Value = serde_json::from_str(&run("height", 1, &dir, &[])).unwrap();
    for key in ["mae_m", "class_accuracy", "class_accuracy_beyond_2cm"] {
        assert!(v[key].is_f64(), "{key}");
    }
    assert!(v["confidently_wrong"].is_u64());
    let v: serde_json::Value =
        serde_json::from_str(&run("rula-agreement", 1, &dir, &["--noise-px", "1"])).unwrap();
    for group in ["grand_score", "action_level"] {
        assert!(
            v[group]["exact"].is_f64() && v[group]["kappa"].is_f64(),
            "{group}"
        );
    }
    for f in [
        "adaptation_grand_score.svg",
        "height_estimates.svg",
        "rula_agreement.svg",
        "rula_agreement_noise.svg",
    ] {
        assert!(dir.join(f).exists(), "{f}");
    }
}

#[test]
fn bad_camera_arguments_are_usage_errors() {
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR"));
    let out = out_dir("sim_bad");
    for cameras in ["0", "no/such/rig.toml"] {
        let status = Command::new(env!("CARGO_BIN_EXE_ergocell"))
            .current_dir(&root)
            .args(["sim", "table1", "--cameras", cameras, "--out-dir"])
            .arg(&out)
            .status()
            .unwrap();
        assert!(!status.success(), "{cameras}");
    }
    // the fixed-lag smoother is an option of rula-agreement and warnings only, and takes a half window in
    // (0, 60] seconds or 0 (off)
    for args in [
        &["height", "--fixed-lag-s", "0.5"][..],
        &["rula-agreement", "--fixed-lag-s", "-1"],
        &["rula-agreement", "--fixed-lag-s", "nan"],
        &["rula-agreement", "--fixed-lag-s", "61"],
        // the views' transport delay is an option of warnings only, a time of 0 to 10 s
        &["height", "--transport-delay-ms", "100"],
        &["warnings", "--transport-delay-ms", "nan"],
        &["warnings", "--transport-delay-ms", "10001"],
        // the recording of one operator: adaptation on one seed only, 1.3 to 2.2 m, refused before
        // the experiment runs
        &["table1", "--record-height", "1.70"],
        &["adaptation", "--seeds", "1..2", "--record-height", "1.70"],
        &["adaptation", "--record-height", "2.5"],
    ] {
        let status = Command::new(env!("CARGO_BIN_EXE_ergocell"))
            .current_dir(&root)
            .arg("sim")
            .args(args)
            .arg("--out-dir")
            .arg(&out)
            .status()
            .unwrap();
        assert_eq!(status.code(), Some(2), "{args:?}");
    }
}

/// `--seeds A..B`: every experiment runs once per seed and reports each quantity's spread and each
/// goal seed by seed; the same range gives byte-identical JSON, another range other numbers.
#[test]
fn a_seed_range_gives_byte_identical_json_and_judges_each_goal_per_seed() {
    let dir = out_dir("sim_seeds");
    for experiment in ["height", "rula-agreement", "table1", "adaptation"] {
        let a = run(experiment, 1, &dir, &["--seeds", "5..6"]);
        // Byte-identity on the two fast experiments (debug builds make adaptation slow).
        if matches!(experiment, "height" | "rula-agreement") {
            let b = run(experiment, 1, &dir, &["--seeds", "5..6"]);
            assert_eq!(a, b, "{experiment}");
        }
        let v: serde_json::Value = serde_json::from_str(&a).unwrap();
        assert_eq!(
            v["setup"]["seeds"],
            serde_json::json!([5, 6]),
            "{experiment}"
        );
        let goals = v["goals"].as_array().unwrap();
        assert!(!goals.is_empty(), "{experiment}");
        for g in goals {
            let (holds, of) = (
                g["holds_on"].as_u64().unwrap(),
                g["seeds"].as_u64().unwrap(),
            );
            assert_eq!(of, 2);
            assert_eq!(holds + g["fails"].as_array().unwrap().len() as u64, of);
        }
        let name = experiment.replace('-', "_");
        assert!(dir.join(format!("{name}_seeds.json")).exists());
    }
    // Another range, other numbers; the per-seed values are the single-seed runs' values.
    let h56: serde_json::Value =
        serde_json::from_str(&run("height", 1, &dir, &["--seeds", "5..6"])).unwrap();
    let h78: serde_json::Value =
        serde_json::from_str(&run("height", 1, &dir, &["--seeds", "7..8"])).unwrap();
    assert_ne!(h56["mae_m"], h78["mae_m"]);
    let single: serde_json::Value = serde_json::from_str(&run("height", 6, &dir, &[])).unwrap();
    assert_eq!(h56["mae_m"]["per_seed"][1], single["mae_m"]);
    assert_eq!(h56["coverage"]["per_seed"][1], single["coverage"]);
}
