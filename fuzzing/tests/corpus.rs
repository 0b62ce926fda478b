//! Replays the committed fuzz corpus (`fuzz/corpus/<target>/`) and every committed crash
//! (`fuzz/artifacts/<target>/`) through the same entry points the fuzz targets call
//! (`ergocell_fuzzing`), as ordinary tests: a parser change that brings back a crash, or breaks a
//! property an entry checks, fails CI without a fuzzer.
#![allow(clippy::unwrap_used, clippy::expect_used)]

use std::path::{Path, PathBuf};

type Entry = fn(&[u8]);

/// Every target: one replay test each, and the table the completeness test checks.
macro_rules! targets {
    ($($name:ident),* $(,)?) => {
        const TARGETS: &[&str] = &[$(stringify!($name)),*];
        $(
            #[test]
            fn $name() {
                assert!(replay(stringify!($name), ergocell_fuzzing::$name) > 0);
            }
        )*
    };
}

targets!(
    rig,
    openpose_json,
    caliscope_csv,
    landmarks_file,
    urdf,
    trajectory_toml,
    cell_toml,
    lock_toml,
    approvals_toml,
    mcap_recording,
    cdr_messages,
    rula_json,
    review_request,
    detector_model,
    place_points,
    nesting_xml,
    nesting_toml,
    nesting_json,
);

fn fuzz_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../fuzz")
}

fn files(dir: &Path) -> Vec<PathBuf> {
    let Ok(entries) = std::fs::read_dir(dir) else {
        return Vec::new();
    };
    let mut files: Vec<PathBuf> = entries
        .filter_map(Result::ok)
        .map(|e| e.path())
        .filter(|p| p.is_file())
        .collect();
    files.sort();
    files
}

fn replay(name: &str, entry: Entry) -> usize {
    let mut count = 0;
    for sub in ["corpus", "artifacts"] {
        for path in files(&fuzz_dir().join(sub).join(name)) {
            let data = match std::fs::read(&path) {
                Ok(data) => data,
                // a fuzzer running beside the test replaces corpus files as it shrinks them
                Err(e) if e.kind() == std::io::ErrorKind::NotFound => continue,
                Err(e) => panic!("{}: {e}", path.display()),
            };
            let outcome = std::panic::catch_unwind(|| entry(&data));
            assert!(outcome.is_ok(), "{name}: {} fails", path.display());
            count += 1;
        }
    }
    count
}

/// Every target the fuzz crate builds is replayed here, and has a corpus.
#[test]
fn every_fuzz_target_is_replayed_and_has_a_corpus() {
    let mut built: Vec<String> = files(&fuzz_dir().join("fuzz_targets"))
        .iter()
        .filter_map(|p| Some(p.file_stem()?.to_str()?.to_owned()))
        .collect();
    built.sort();
    let mut replayed: Vec<String> = TARGETS.iter().map(|n| (*n).to_owned()).collect();
    replayed.sort();
    assert_eq!(built, replayed);
    for name in TARGETS {
        assert!(
            !files(&fuzz_dir().join("corpus").join(name)).is_empty(),
            "{name} has no corpus"
        );
    }
}

/// The seeds are real inputs of their parsers (so the fuzzer starts from inside the accepted
/// language, not from garbage), and the entries refuse broken inputs without a panic.
#[test]
fn seeds_parse_and_broken_inputs_are_refused_without_panicking() {
    for name in [
        "seed_ergocell_rig.toml",
        "seed_anipose.toml",
        "seed_caliscope_config.toml",
    ] {
        let text = std::fs::read_to_string(fuzz_dir().join("corpus/rig").join(name)).unwrap();
        ergocell_formats::rig_file::parse_rig(&text, name).unwrap();
        ergocell_fuzzing::rig(&text.as_bytes()[..text.len() / 2]);
    }
    for class in ["c1", "c2", "c3"] {
        let path = fuzz_dir().join(format!("corpus/lock_toml/seed_{class}.lock.toml"));
        let text = std::fs::read_to_string(path).unwrap();
        let class: ergocell_robot::TrajectoryClass =
            serde_json::from_value(serde_json::json!(class)).unwrap();
        ergocell_robot::lock::LockFile::from_toml_str(class, &text).unwrap();
    }
    ergocell_fuzzing::review_request(b"GET / HTTP/1.1\r\nHost: 127.0.0.1:8765\r\n\r\n");
    ergocell_fuzzing::review_request(b"\x00\xff garbage");
    ergocell_fuzzing::cdr_messages(&[0, 0, 1, 0, 0, 255, 255, 255, 255]);
    ergocell_fuzzing::lock_toml(b"format = 3\n[[[");
}

/// Deep nesting in every syntax ergocell reads — XML (a URDF, a Qualisys calibration), TOML arrays
/// and inline tables, JSON — through every fuzz entry point, on a thread with the main thread's
/// stack (8 MiB): each is refused or read, never a stack overflow (which aborts the process and so
/// fails this test). A 50,000-deep URDF of unknown elements used to abort with exit 134.
#[test]
fn deep_nesting_is_refused_by_every_reader_without_overflowing_the_stack() {
    const ENTRIES: &[(&str, Entry)] = &[
        ("rig", ergocell_fuzzing::rig),
        ("openpose_json", ergocell_fuzzing::openpose_json),
        ("caliscope_csv", ergocell_fuzzing::caliscope_csv),
        ("landmarks_file", ergocell_fuzzing::landmarks_file),
        ("urdf", ergocell_fuzzing::urdf),
        ("trajectory_toml", ergocell_fuzzing::trajectory_toml),
        ("cell_toml", ergocell_fuzzing::cell_toml),
        ("lock_toml", ergocell_fuzzing::lock_toml),
        ("approvals_toml", ergocell_fuzzing::approvals_toml),
        ("rula_json", ergocell_fuzzing::rula_json),
        ("detector_model", ergocell_fuzzing::detector_model),
        ("place_points", ergocell_fuzzing::place_points),
    ];
    let n = 50_000;
    let open_close = |open: &str, close: &str| format!("{}{}", open.repeat(n), close.repeat(n));
    let payloads = [
        format!(
            "<robot name=\"deep\"><link name=\"link_0\"/>{}</robot>",
            open_close("<x>", "</x>")
        ),
        format!(
            "<calibration><cameras>{}</cameras></calibration>",
            open_close("<camera>", "</camera>")
        ),
        format!("a = {}", open_close("[", "]")),
        format!("a = {}1{}", "{ b = ".repeat(n), "}".repeat(n)),
        open_close("[", "]"),
        format!("{}1{}", "{\"a\":".repeat(n), "}".repeat(n)),
    ];
    assert_eq!(
        ENTRIES.len() + 6,
        TARGETS.len(),
        "every text reader is here (the three nesting entries build their own deep inputs)"
    );
    for (name, entry) in ENTRIES {
        for (k, payload) in payloads.iter().enumerate() {
            let bytes = payload.clone().into_bytes();
            let entry = *entry;
            let done = std::thread::Builder::new()
                .stack_size(8 << 20)
                .spawn(move || entry(&bytes))
                .unwrap()
                .join();
            assert!(done.is_ok(), "{name}: payload {k} panicked");
        }
    }
}
