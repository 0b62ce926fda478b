//! The binary's safety rows: no output written over an existing file unless asked (`--force`), never
//! over an input; SIGTERM handled like Ctrl-C (robot held, recording closed, documented exit code);
//! durations from the command line validated instead of panicking or running forever; the demo's
//! time limit taken from its script; no ANSI colour in a redirected log.
#![allow(clippy::unwrap_used, clippy::expect_used)]

use std::io::{BufRead as _, BufReader};
use std::path::{Path, PathBuf};
use std::process::{Child, Command, Output, Stdio};
use std::time::Duration;

use ergocell::recording::topics;
use ergocell_bridge::msg::SessionState;

mod common;

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// A fresh folder for one test, removed at the end.
struct Scratch(PathBuf);

impl Scratch {
    fn new(name: &str) -> Self {
        let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR"))
            .join(format!("cli-safety-{name}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).unwrap();
        Self(dir)
    }

    fn path(&self, name: &str) -> PathBuf {
        self.0.join(name)
    }

    /// A file with `text`, to see whether a command left it alone.
    fn file(&self, name: &str, text: &str) -> PathBuf {
        let p = self.path(name);
        std::fs::write(&p, text).unwrap();
        p
    }
}

impl Drop for Scratch {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.0);
    }
}

fn ergocell(dir: &Path, args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_ergocell"))
        .current_dir(dir)
        .args(args)
        .output()
        .unwrap()
}

fn text(bytes: &[u8]) -> String {
    String::from_utf8_lossy(bytes).into_owned()
}

/// A usage error (exit 2, no panic) whose message contains every one of `needles`.
fn assert_usage_error(o: &Output, needles: &[&str]) {
    let err = text(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{err}\n{}", text(&o.stdout));
    for n in needles {
        assert!(err.contains(n), "missing `{n}` in: {err}");
    }
}

use common::small_recording as recording;

/// Row "an existing recording is truncated": every file the user names is refused when it exists,
/// before any work (here even before the inputs are read), and written with `--force`.
#[test]
fn existing_output_is_not_overwritten_without_force() {
    let dir = Scratch::new("existing");
    let keep = "an earlier session: keep me\n";

    // run --record: refused before the config is read or DDS is started.
    let rec = dir.file("sessions.mcap", keep);
    let o = ergocell(&dir.0, &["run", "--record", "sessions.mcap"]);
    assert_usage_error(&o, &["--record sessions.mcap", "already exists", "--force"]);
    assert_eq!(std::fs::read_to_string(&rec).unwrap(), keep);

    // an output in a folder that does not exist: bad input, said before any work
    let o = ergocell(&dir.0, &["demo", "--out", "shifts/mon.mcap"]);
    assert_usage_error(&o, &["--out shifts/mon.mcap", "shifts does not exist"]);
    assert!(!dir.0.join("shifts").exists());

    // demo --out: refused before the session starts (no demo approval written).
    let o = ergocell(&dir.0, &["demo", "--out", "sessions.mcap"]);
    assert_usage_error(&o, &["--out sessions.mcap", "already exists", "--force"]);
    assert!(!text(&o.stdout).contains("DEMO APPROVAL"), "nothing ran");
    assert_eq!(std::fs::read_to_string(&rec).unwrap(), keep);

    // report --out, also its default report.html; --force overwrites.
    let input = dir.path("input.mcap");
    recording(&input);
    let html = dir.file("report.html", keep);
    let o = ergocell(&dir.0, &["report", "input.mcap"]);
    assert_usage_error(&o, &["--out report.html", "already exists"]);
    let o = ergocell(&dir.0, &["report", "input.mcap", "--out", "report.html"]);
    assert_usage_error(&o, &["--out report.html", "already exists"]);
    assert_eq!(std::fs::read_to_string(&html).unwrap(), keep);
    let o = ergocell(
        &dir.0,
        &["report", "input.mcap", "--out", "report.html", "--force"],
    );
    assert!(o.status.success(), "{}", text(&o.stderr));
    assert!(std::fs::read_to_string(&html)
        .unwrap()
        .contains("ERGOCELL_REVIEW_DATA"));

    // triangulate --out: refused before the (missing) calibration is read.
    let trc = dir.file("out.trc", keep);
    let o = ergocell(
        &dir.0,
        &[
            "triangulate",
            "--calibration",
            "missing.toml",
            "--detections",
            "missing.csv",
            "--out",
            "out.trc",
        ],
    );
    assert_usage_error(&o, &["--out out.trc", "already exists"]);
    assert_eq!(std::fs::read_to_string(&trc).unwrap(), keep);

    // calibrate --out: refused before any image is decoded (these are not images at all).
    let images = dir.path("images");
    std::fs::create_dir_all(&images).unwrap();
    std::fs::write(images.join("a.png"), "not a png").unwrap();
    let rig = dir.file("rig.toml", keep);
    for sub in [
        &["intrinsics", "--images", "images"][..],
        &["stereo", "--left", "images", "--right", "images"][..],
    ] {
        let mut args = vec!["calibrate"];
        args.extend_from_slice(sub);
        args.extend_from_slice(&["--out", "rig.toml"]);
        let o = ergocell(&dir.0, &args);
        assert_usage_error(&o, &["--out rig.toml", "already exists"]);
        assert_eq!(std::fs::read_to_string(&rig).unwrap(), keep);
    }
}

/// Row "an existing recording is truncated", the README's first command run twice: the demo's
/// default recording moves on to the next free numbered name, says so, and keeps the first one.
#[test]
fn demo_default_output_moves_to_the_next_free_name() {
    let dir = Scratch::new("demo-default");
    let first = dir.file("ergocell-demo.mcap", "the first demo session\n");
    let o = ergocell(
        &dir.0,
        &[
            "--log",
            "error",
            "demo",
            "--cycles",
            "1",
            "--no-faults",
            "--no-floor-pick",
        ],
    );
    let stdout = text(&o.stdout);
    assert!(o.status.success(), "{stdout}\n{}", text(&o.stderr));
    assert_eq!(
        std::fs::read_to_string(&first).unwrap(),
        "the first demo session\n"
    );
    assert!(
        stdout.contains("ergocell-demo.mcap exists (kept): recording into ergocell-demo-2.mcap"),
        "{stdout}"
    );
    assert!(
        stdout.contains("recording:      ergocell-demo-2.mcap"),
        "{stdout}"
    );
    let bytes = std::fs::read(dir.path("ergocell-demo-2.mcap")).unwrap();
    assert!(mcap::MessageStream::new(&bytes).unwrap().count() > 100);
}

/// Row "an input replaced by the output": an output that is one of the inputs is refused, by
/// canonical path (another spelling, a symlink) or by inode (a hard link), even with `--force`.
#[test]
fn an_output_that_is_an_input_is_refused_even_with_force() {
    let dir = Scratch::new("input-output");
    let rec = dir.path("rec.mcap");
    recording(&rec);
    let original = std::fs::read(&rec).unwrap();
    let other = dir.path("other.mcap");
    recording(&other);
    std::fs::create_dir_all(dir.path("sub")).unwrap();
    std::os::unix::fs::symlink(&rec, dir.path("link.mcap")).unwrap();
    std::fs::hard_link(&rec, dir.path("hard.mcap")).unwrap();

    for (args, named) in [
        (
            &["report", "rec.mcap", "--out", "rec.mcap", "--force"][..],
            "--out rec.mcap is also an input (<recording> rec.mcap)",
        ),
        (
            &["report", "rec.mcap", "--out", "sub/../rec.mcap", "--force"][..],
            "is also an input",
        ),
        (
            &["report", "rec.mcap", "--out", "link.mcap", "--force"][..],
            "is also an input",
        ),
        (
            &["report", "rec.mcap", "--out", "hard.mcap", "--force"][..],
            "is also an input",
        ),
        (
            &[
                "report",
                "rec.mcap",
                "--compare",
                "other.mcap",
                "--out",
                "./other.mcap",
                "--force",
            ][..],
            "(--compare other.mcap)",
        ),
    ] {
        let o = ergocell(&dir.0, args);
        assert_usage_error(&o, &[named, "--force or not"]);
    }
    assert_eq!(std::fs::read(&rec).unwrap(), original);
    assert_eq!(std::fs::read(&other).unwrap(), original);

    // triangulate: the detections and the calibration are inputs.
    let xy = dir.file("xy.csv", "sync_index,cam_id,point_id,img_loc_x,img_loc_y\n");
    let calibration = std::fs::read_to_string(root().join("config/rig.toml")).unwrap();
    let rig = dir.file("rig.csv", &calibration);
    for (args, named) in [
        (
            &[
                "triangulate",
                "--calibration",
                "rig.csv",
                "--detections",
                "xy.csv",
                "--out",
                "xy.csv",
                "--force",
            ][..],
            "--out xy.csv is also an input (--detections xy.csv)",
        ),
        (
            &[
                "triangulate",
                "--calibration",
                "rig.csv",
                "--detections",
                "xy.csv",
                "--out",
                "rig.csv",
                "--force",
            ][..],
            "--out rig.csv is also an input (--calibration rig.csv)",
        ),
    ] {
        let o = ergocell(&dir.0, args);
        assert_usage_error(&o, &[named]);
    }
    assert_eq!(
        std::fs::read_to_string(&xy).unwrap(),
        "sync_index,cam_id,point_id,img_loc_x,img_loc_y\n"
    );
    assert_eq!(std::fs::read_to_string(&rig).unwrap(), calibration);

    // calibrate: an image is an input.
    std::fs::create_dir_all(dir.path("images")).unwrap();
    let image = dir.file("images/a.png", "not a png");
    let o = ergocell(
        &dir.0,
        &[
            "calibrate",
            "intrinsics",
            "--images",
            "images",
            "--out",
            "images/a.png",
            "--force",
        ],
    );
    assert_usage_error(&o, &["is also an input (image"]);
    assert_eq!(std::fs::read_to_string(&image).unwrap(), "not a png");
}

/// Kills the child on drop (a test that fails midway leaves no process behind).
struct Running(Child);

impl Drop for Running {
    fn drop(&mut self) {
        let _ = self.0.kill();
        let _ = self.0.wait();
    }
}

fn send(child: &Child, signal: &str) {
    let status = Command::new("kill")
        .args([signal, &child.id().to_string()])
        .status()
        .unwrap();
    assert!(status.success(), "kill {signal} failed");
}

/// Waits for the child's exit, at most `secs` (then it is killed and the test fails).
fn wait_at_most(child: &mut Child, secs: u64) -> std::process::ExitStatus {
    for _ in 0..secs * 10 {
        if let Some(status) = child.try_wait().unwrap() {
            return status;
        }
        std::thread::sleep(Duration::from_millis(100));
    }
    let _ = child.kill();
    panic!("the process did not exit within {secs} s of the signal");
}

/// Starts a long demo (twenty cycles: about two minutes of simulated session, some seconds of wall
/// time in a debug build), waits until its trajectory is locked (mid-session), sends `signal`, and
/// returns (exit code, stdout, stderr, the recording's bytes).
fn demo_stopped_by(signal: &str, name: &str) -> (Option<i32>, String, String, Vec<u8>) {
    let dir = Scratch::new(name);
    let out = dir.path("stopped.mcap");
    let child = Command::new(env!("CARGO_BIN_EXE_ergocell"))
        .current_dir(&dir.0)
        .args(["--log", "error", "demo", "--cycles", "20", "--no-faults"])
        .arg("--out")
        .arg(&out)
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let mut child = Running(child);
    let stdout = child.0.stdout.take().unwrap();
    let mut stderr = child.0.stderr.take().unwrap();
    let mut lines = BufReader::new(stdout).lines();
    let mut seen = String::new();
    loop {
        let line = lines
            .next()
            .unwrap_or_else(|| panic!("the demo ended before locking a trajectory:\n{seen}"))
            .unwrap();
        seen.push_str(&line);
        seen.push('\n');
        if line.contains("locked: sha256") {
            break;
        }
    }
    send(&child.0, signal);
    for line in lines {
        seen.push_str(&line.unwrap());
        seen.push('\n');
    }
    let status = wait_at_most(&mut child.0, 60);
    let mut err = String::new();
    std::io::Read::read_to_string(&mut stderr, &mut err).unwrap();
    (status.code(), seen, err, std::fs::read(&out).unwrap())
}

/// The recording reads to its end: every message, the summary and the footer.
fn assert_recording_closed(bytes: &[u8]) {
    let mut states = Vec::new();
    for m in mcap::MessageStream::new(bytes).unwrap() {
        let m = m.unwrap();
        if m.channel.topic == topics::SESSION_STATE {
            let s: SessionState = ergocell_bridge::cdr::decode(&m.data).unwrap();
            states.push(s.state);
        }
    }
    assert!(
        mcap::Summary::read(bytes).unwrap().is_some(),
        "no summary: the recording was not closed"
    );
    assert_eq!(
        states.last().map(String::as_str),
        Some("session_ended"),
        "{states:?}"
    );
}

/// Row "`run` ignores SIGTERM" (the demo runs the same session loop without ROS): SIGTERM mid-session
/// holds the robot, closes the recording with its footer and exits 143.
#[test]
fn sigterm_holds_the_robot_closes_the_recording_and_exits_143() {
    let (code, stdout, stderr, bytes) = demo_stopped_by("-TERM", "sigterm");
    assert_eq!(code, Some(143), "{stdout}\n{stderr}");
    for expected in [
        "robot ← HOLD (stopped where it is; not an e-stop): session interrupted: SIGTERM",
        "ended:          interrupted: SIGTERM (robot held)",
    ] {
        assert!(
            stdout.contains(expected),
            "missing `{expected}` in:\n{stdout}"
        );
    }
    assert!(
        stderr.contains("stopped by SIGTERM: robot held, recording") && stderr.contains("closed"),
        "{stderr}"
    );
    assert_recording_closed(&bytes);
}

/// Ctrl-C (SIGINT) the same way, with its own exit code: 130.
#[test]
fn sigint_holds_the_robot_closes_the_recording_and_exits_130() {
    let (code, stdout, stderr, bytes) = demo_stopped_by("-INT", "sigint");
    assert_eq!(code, Some(130), "{stdout}\n{stderr}");
    assert!(
        stdout.contains("session interrupted: Ctrl-C (SIGINT)"),
        "{stdout}"
    );
    assert!(stderr.contains("stopped by Ctrl-C (SIGINT)"), "{stderr}");
    assert_recording_closed(&bytes);
}

/// Row "`run` ignores SIGTERM", the review server: SIGTERM stops it like Ctrl-C, exit 0.
#[test]
fn sigterm_stops_the_review_server_like_ctrl_c() {
    let dir = Scratch::new("review-sigterm");
    let rec = dir.path("rec.mcap");
    recording(&rec);
    let child = Command::new(env!("CARGO_BIN_EXE_ergocell"))
        .current_dir(&dir.0)
        .args(["review", "rec.mcap", "--port", "0"])
        .stdout(Stdio::piped())
        .stderr(Stdio::null())
        .spawn()
        .unwrap();
    let mut child = Running(child);
    let mut lines = BufReader::new(child.0.stdout.take().unwrap()).lines();
    loop {
        let line = lines.next().expect("no URL printed").unwrap();
        if line.starts_with("review: http://") {
            break;
        }
    }
    send(&child.0, "-TERM");
    let rest: Vec<String> = lines.map(Result::unwrap).collect();
    let status = wait_at_most(&mut child.0, 30);
    assert_eq!(status.code(), Some(0), "{rest:?}");
    assert!(
        rest.iter().any(|l| l == "review: stopped by SIGTERM"),
        "{rest:?}"
    );
}

/// Row "`replay --speed 1e-300` panics, `run --max-secs nan` runs forever": each is a usage error
/// naming the value, before anything is read or started.
#[test]
fn speed_and_max_secs_out_of_range_are_usage_errors() {
    let dir = Scratch::new("durations");
    for speed in ["1e-300", "0", "-1", "NaN", "inf", "1e300"] {
        let o = ergocell(
            &dir.0,
            &[
                "replay",
                "missing.mcap",
                "--ros",
                &format!("--speed={speed}"),
            ],
        );
        assert_usage_error(&o, &["--speed", "must be a factor from 0.01 to 100"]);
    }
    for (secs, shown) in [
        ("nan", "NaN"),
        ("inf", "inf"),
        ("-1", "-1"),
        ("0", "0"),
        ("1e300", "1e300"),
    ] {
        let o = ergocell(&dir.0, &["run", &format!("--max-secs={secs}")]);
        assert_usage_error(&o, &[&format!("--max-secs {shown}"), "must be"]);
    }
    let o = ergocell(&dir.0, &["demo", "--cycles", "100000"]);
    assert_usage_error(&o, &["--cycles 100000"]);
    assert!(
        std::fs::read_dir(&dir.0).unwrap().next().is_none(),
        "nothing written"
    );
}

/// Row "`demo --cycles 20` stops at a hidden 120 s limit": the limit follows the script, so twenty
/// cycles (about 122 s of simulated session) end normally.
#[test]
fn demo_time_limit_follows_the_script() {
    let dir = Scratch::new("cycles20");
    let o = ergocell(
        &dir.0,
        &[
            "--log",
            "error",
            "demo",
            "--cycles",
            "20",
            "--no-faults",
            "--out",
            "c20.mcap",
        ],
    );
    let stdout = text(&o.stdout);
    assert!(o.status.success(), "{stdout}\n{}", text(&o.stderr));
    assert!(stdout.contains("session:        session_ended"), "{stdout}");
    assert!(
        stdout.contains("ended:          operator left, robot at home"),
        "{stdout}"
    );
}

/// Row "ANSI colour in redirected stderr": the log on a pipe is plain text.
#[test]
fn log_has_no_ansi_colour_when_stderr_is_not_a_terminal() {
    let dir = Scratch::new("ansi");
    let o = ergocell(
        &dir.0,
        &[
            "--log",
            "info",
            "demo",
            "--cycles",
            "0",
            "--no-faults",
            "--no-floor-pick",
        ],
    );
    let stderr = text(&o.stderr);
    assert!(o.status.success(), "{stderr}");
    assert!(stderr.contains("INFO"), "no log lines: {stderr}");
    assert!(!stderr.contains('\u{1b}'), "ANSI escape in: {stderr:?}");
}

/// Row "~13 rustdds ERROR lines on every clean exit": `run` ends (here at `--max-secs`, the robot
/// held) without one ERROR line: the DDS participant outlives every reader and writer
/// (`RosNode::participant`).
#[test]
fn run_exits_without_rustdds_error_lines() {
    let o = ergocell(
        &root(),
        &["run", "--config", "config/cell.toml", "--max-secs", "2"],
    );
    let stderr = text(&o.stderr);
    assert!(
        stderr.contains("--max-secs reached (robot held)"),
        "the session ran and ended: {stderr}"
    );
    let errors: Vec<&str> = stderr.lines().filter(|l| l.contains(" ERROR ")).collect();
    assert!(errors.is_empty(), "ERROR lines on exit: {errors:#?}");
}

/// Every file the cell reads is an input, named by a flag or not: `run --record` and `demo --out`
/// onto a lock, an approvals file, the approvers' files, the URDF or a trajectory file are refused,
/// `--force` or not, and the file is left as it was.
#[test]
fn an_output_onto_any_file_the_cell_reads_is_refused_even_with_force() {
    let dir = Scratch::new("cell-inputs");
    let root = root();
    for sub in ["config", "trajectories"] {
        let status = Command::new("cp")
            .args(["-r"])
            .arg(root.join(sub))
            .arg(dir.path(sub))
            .status()
            .unwrap();
        assert!(status.success());
    }
    std::fs::create_dir_all(dir.path("trajectories/approvals")).unwrap();
    let approvals = dir.file("trajectories/approvals/c2.toml", "# approvals\n");
    let targets = [
        "trajectories/locks/c2.lock.toml",
        "trajectories/c2.toml",
        "trajectories/approvals/c2.toml",
        "config/approvers/allowed_signers",
        "config/approvers/revoked_keys",
        "config/robots/iiwa14_r820.urdf",
    ];
    let before: Vec<Vec<u8>> = targets
        .iter()
        .map(|t| std::fs::read(dir.path(t)).unwrap())
        .collect();
    for target in targets {
        let o = ergocell(
            &dir.0,
            &["run", "--record", target, "--force", "--max-secs", "1"],
        );
        assert_usage_error(
            &o,
            &["is also an input (a file the cell reads:", "--force or not"],
        );
        let o = ergocell(
            &dir.0,
            &[
                "demo",
                "--cell",
                "config/cell.toml",
                "--trajectories",
                "trajectories",
                "--out",
                target,
                "--force",
            ],
        );
        assert_usage_error(
            &o,
            &["is also an input (a file the cell reads:", "--force or not"],
        );
    }
    // The shipped cell (no --cell): its files in this folder are still the user's.
    let o = ergocell(
        &dir.0,
        &["demo", "--out", "trajectories/c2.toml", "--force"],
    );
    assert_usage_error(&o, &["is also an input"]);
    for (t, b) in targets.iter().zip(&before) {
        assert_eq!(
            &std::fs::read(dir.path(t)).unwrap(),
            b,
            "{t} left as it was"
        );
    }
    assert_eq!(std::fs::read_to_string(approvals).unwrap(), "# approvals\n");
}

/// One rule for exit codes on bad input: a missing, unreadable or malformed input file is exit 2
/// (as clap's usage errors), whichever command reads it; the message names the file once.
#[test]
fn a_missing_or_malformed_input_is_exit_2_for_every_command() {
    let dir = Scratch::new("exit-codes");
    dir.file("bad.toml", "this is [ not toml\n");
    dir.file("bad.json", "not json\n");
    for args in [
        &["run", "--config", "nosuch.toml", "--max-secs", "1"][..],
        &["run", "--config", "bad.toml", "--max-secs", "1"][..],
        &["demo", "--cell", "nosuch.toml", "--out", "a.mcap"][..],
        &["demo", "--cell", "bad.toml", "--out", "a.mcap"][..],
        &["demo", "--trajectories", "nosuch", "--out", "a.mcap"][..],
        &[
            "security",
            "create-keystore",
            "--keystore",
            "ks",
            "--config",
            "nosuch.toml",
        ][..],
        &["trajectories", "--cell", "bad.toml", "validate"][..],
        &["report", "nosuch.mcap", "--out", "r.html"][..],
        &["report", "bad.json", "--out", "r.html"][..],
        &["rula", "score", "--input", "bad.json"][..],
        &["rula", "track", "--landmarks", "nosuch.json"][..],
    ] {
        let o = ergocell(&dir.0, args);
        let err = text(&o.stderr);
        assert_eq!(o.status.code(), Some(2), "{args:?}: {err}");
        assert!(!err.contains("panicked"), "{args:?}: {err}");
        let once = err.matches("No such file or directory").count() <= 1;
        assert!(once, "{args:?} says it twice: {err}");
    }
}
