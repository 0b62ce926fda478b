//! The operator display in a real browser (issue 20): `ergocell demo --display` serves the page and
//! runs the session in real time; Debian's headless Chromium driven by Playwright (`web/e2e/
//! display.e2e.mjs`) watches it: the state as it changes, a posture warning with its advice and
//! colour, a reload that brings the picture back at once, and — the demo ended, a second one started
//! on the same address with the shipped task mix — the page reconnecting by itself and showing a
//! warning raised and then cleared. Everything the page showed is checked against
//! docs/operator.md, which the script reads: each top-bar text among the guide's (the hold reasons
//! too), each posture band in the guide's words and colour for its action level, RULA's action level
//! for its score, and no coloured band while the operator is asked to stand straight. It prints the
//! event-to-screen latency of
//! every update it rendered (measured, not asserted) and writes a screenshot (with
//! `ERGOCELL_DISPLAY_SCREENSHOT=PATH`, there too: `docs/display.png` in the README).
//!
//! Needs `chromium` and `npm ci --prefix web`; skipped without them unless `ERGOCELL_REQUIRE_BROWSER`
//! is set (`.ci/run` sets it).

// Test helpers outside `#[test]` functions unwrap too (clippy.toml allows it only inside them).
#![allow(clippy::unwrap_used, clippy::expect_used)]

use std::io::{BufRead, BufReader};
use std::path::{Path, PathBuf};
use std::process::{Child, Command, Stdio};
use std::sync::mpsc;
use std::time::Duration;

mod common;

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

fn tmp(name: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join(name)
}

/// A demo serving the display on `addr` (with the shipped task mix when `tasks`); returns it and the
/// URL it printed.
fn demo(addr: &str, seed: u64, out: &Path, tasks: bool) -> (Child, String) {
    let mut child = Command::new(env!("CARGO_BIN_EXE_ergocell"))
        .current_dir(root())
        .args([
            "demo",
            "--cycles",
            "1",
            "--force",
            "--display",
            addr,
            "--seed",
        ])
        .arg(seed.to_string())
        .arg("--out")
        .arg(out)
        .args(if tasks {
            &["--tasks", "default"][..]
        } else {
            &[][..]
        })
        .stdout(Stdio::piped())
        .stderr(Stdio::null())
        .spawn()
        .unwrap();
    let stdout = child.stdout.take().unwrap();
    let (tx, rx) = mpsc::channel();
    std::thread::spawn(move || {
        for line in BufReader::new(stdout).lines().map_while(Result::ok) {
            if let Some(i) = line.find("operator display: http://") {
                let url = line[i + "operator display: ".len()..]
                    .split_whitespace()
                    .next()
                    .unwrap()
                    .to_owned();
                let _ = tx.send(url);
            }
        }
    });
    let url = rx.recv_timeout(Duration::from_mins(1)).unwrap();
    (child, url)
}

#[test]
fn the_operator_display_shows_the_session_live_and_survives_reload_and_restart() {
    if common::skip_browser_test() {
        return;
    }
    let (mut first, url) = demo("127.0.0.1:0", 11, &tmp("display-1.mcap"), false);
    let shot = tmp("display.png");
    let node = Command::new("node")
        .current_dir(root())
        .arg("web/e2e/display.e2e.mjs")
        .arg(&url)
        .arg(&shot)
        .arg("restart")
        .arg("tasks")
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    // the first session ends (the page loses its server), then a second one on the same address
    let status = first.wait().unwrap();
    assert!(status.success(), "the first demo failed: {status}");
    let addr = url
        .trim_start_matches("http://")
        .trim_end_matches('/')
        .to_owned();
    // the second session runs the station's task mix: a warning raised and cleared on screen
    let (mut second, _) = demo(&addr, 12, &tmp("display-2.mcap"), true);
    let out = node.wait_with_output().unwrap();
    let _ = second.kill();
    let _ = second.wait();
    let stdout = String::from_utf8_lossy(&out.stdout);
    let stderr = String::from_utf8_lossy(&out.stderr);
    eprintln!("{stdout}{stderr}");
    assert!(out.status.success(), "the display's browser checks failed");
    assert!(stdout.contains("latency: "), "no latency figure");
    if let Some(dest) = std::env::var_os("ERGOCELL_DISPLAY_SCREENSHOT") {
        std::fs::copy(&shot, dest).unwrap();
    }
}
