//! Named pipes and devices, as inputs and as outputs, end to end: every command that reads a file
//! answers at once when it is given a pipe nobody writes into (it used to block in `open`, deaf to
//! SIGTERM), and no output is ever written onto a device or a pipe, `--force` or not.
#![allow(clippy::unwrap_used, clippy::expect_used)]

use std::os::unix::fs::FileTypeExt as _;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::Duration;

fn dir(name: &str) -> PathBuf {
    let d = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join(name);
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

fn mkfifo(path: &Path) -> bool {
    Command::new("mkfifo")
        .arg(path)
        .status()
        .is_ok_and(|s| s.success())
}

/// Runs ergocell in `cwd`; kills it after 60 s. Returns its exit code, or `None` if it had to be
/// killed (a hang).
fn run_bounded(cwd: &Path, args: &[&str]) -> Option<i32> {
    let mut child = Command::new(env!("CARGO_BIN_EXE_ergocell"))
        .current_dir(cwd)
        .args(args)
        .stdin(Stdio::null())
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .spawn()
        .unwrap();
    // 1200 polls 50 ms apart: about a minute.
    for _ in 0..1200 {
        if let Some(status) = child.try_wait().unwrap() {
            return status.code();
        }
        std::thread::sleep(Duration::from_millis(50));
    }
    let _ = child.kill();
    let _ = child.wait();
    None
}

#[test]
fn a_pipe_nobody_writes_into_is_answered_at_once_by_every_reader() {
    let d = dir("fifo-inputs");
    let ff = d.join("ff");
    if !mkfifo(&ff) {
        // Straight to the stream: cargo test shows it without --nocapture.
        let _ = std::io::Write::write_all(
            &mut std::io::stderr(),
            b"SKIPPED: mkfifo is not available\n",
        );
        return;
    }
    let fifo_mcap = d.join("ff.mcap");
    let fifo_toml = d.join("ff.toml");
    assert!(mkfifo(&fifo_mcap) && mkfifo(&fifo_toml));
    let root = env!("CARGO_MANIFEST_DIR");
    let cases: Vec<Vec<String>> = vec![
        vec![
            "report".into(),
            "ff.mcap".into(),
            "--out".into(),
            "r.html".into(),
        ],
        vec![
            "exposure".into(),
            "ff.mcap".into(),
            "--out".into(),
            "exp".into(),
        ],
        vec![
            "trajectories".into(),
            "verify".into(),
            "--cell".into(),
            fifo_toml.display().to_string(),
            "--trajectories-dir".into(),
            format!("{root}/trajectories"),
        ],
        vec![
            "demo".into(),
            "--rig".into(),
            "ff.toml".into(),
            "--out".into(),
            "d.mcap".into(),
        ],
        vec!["rula".into(), "score".into(), "--input".into(), "ff".into()],
    ];
    for args in &cases {
        let args: Vec<&str> = args.iter().map(String::as_str).collect();
        let code = run_bounded(&d, &args);
        assert!(code.is_some(), "{args:?} hung on a pipe nobody writes into");
        assert_ne!(code, Some(0), "{args:?} took an empty pipe for its input");
    }
}

#[test]
fn no_output_goes_onto_a_device_or_a_pipe_even_forced() {
    let d = dir("device-outputs");
    let rec = d.join("rec.mcap");
    let code = run_bounded(
        &d,
        &[
            "demo",
            "--cycles",
            "1",
            "--no-faults",
            "--out",
            rec.to_str().unwrap(),
        ],
    );
    assert_eq!(code, Some(0));
    let fifo = d.join("out.html");
    assert!(mkfifo(&fifo) || !cfg!(unix));
    for out in ["/dev/null", fifo.to_str().unwrap()] {
        let code = run_bounded(
            &d,
            &["report", rec.to_str().unwrap(), "--out", out, "--force"],
        );
        assert_eq!(code, Some(2), "report --out {out} --force");
    }
    assert!(std::fs::metadata(&fifo).unwrap().file_type().is_fifo());
    assert!(std::fs::metadata("/dev/null")
        .unwrap()
        .file_type()
        .is_char_device());
    // a recording is never made onto a device either
    let code = run_bounded(
        &d,
        &["demo", "--cycles", "1", "--out", "/dev/null", "--force"],
    );
    assert_eq!(code, Some(2));
}
