//! The review page in a real browser (issue 8): Debian's headless Chromium driven by Playwright
//! (`web/e2e/`, playwright-core from `web/package-lock.json`; no browser download) against
//! `ergocell review` on a recording made here by `ergocell demo`, and against a `ergocell report`
//! opened from `file://`. The scripts fail on any console error, page error or failed request, and
//! check that play advances the frame counter, pause stops it, and a click on the timeline moves the
//! 3D view to that moment; each writes a screenshot.
//!
//! Needs `chromium` and `npm ci --prefix web` (`.ci/run` installs both). Without them the test says
//! so and passes on a developer machine, and fails when `ERGOCELL_REQUIRE_BROWSER` is set (`.ci/run`
//! sets it: in CI it must run).

// Test helpers outside `#[test]` functions unwrap too (clippy.toml allows it only inside them).
#![allow(clippy::unwrap_used, clippy::expect_used)]

use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};

mod common;
use common::ReviewServer;

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

fn tmp(name: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join(name)
}

fn demo(out: &Path) {
    let status = Command::new(env!("CARGO_BIN_EXE_ergocell"))
        .current_dir(root())
        .args(["demo", "--cycles", "1", "--seed", "11", "--force", "--out"])
        .arg(out)
        .stdout(Stdio::null())
        .status()
        .unwrap();
    assert!(status.success(), "demo failed");
}

/// `ergocell report <rec> <args…> --force --out <html>`, which must succeed.
fn report(rec: &Path, args: &[&std::ffi::OsStr], html: &Path) {
    let status = Command::new(env!("CARGO_BIN_EXE_ergocell"))
        .current_dir(root())
        .arg("report")
        .arg(rec)
        .args(args)
        .args(["--force", "--out"])
        .arg(html)
        .stdout(Stdio::null())
        .status()
        .unwrap();
    assert!(status.success(), "report failed");
}

/// Runs a node script, failing it after 3 minutes (a hung browser must not hang the test suite).
fn node(script: &str, args: &[&str]) {
    let mut child = Command::new("node")
        .current_dir(root())
        .arg(script)
        .args(args)
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let deadline = std::time::Duration::from_mins(3);
    let mut waited = std::time::Duration::ZERO;
    let status = loop {
        if let Some(status) = child.try_wait().unwrap() {
            break Some(status);
        }
        if waited >= deadline {
            let _ = child.kill();
            let _ = child.wait();
            break None;
        }
        std::thread::sleep(std::time::Duration::from_millis(100));
        waited += std::time::Duration::from_millis(100);
    };
    let mut out = String::new();
    let mut err = String::new();
    let _ = std::io::Read::read_to_string(&mut child.stdout.take().unwrap(), &mut out);
    let _ = std::io::Read::read_to_string(&mut child.stderr.take().unwrap(), &mut err);
    eprintln!("{out}{err}");
    let status =
        status.unwrap_or_else(|| panic!("{script} did not finish in 3 minutes:\n{out}\n{err}"));
    assert!(status.success(), "{script} failed:\n{out}\n{err}");
}

#[test]
fn review_page_plays_pauses_and_jumps_in_headless_chromium() {
    if common::skip_browser_test() {
        return;
    }
    let rec = tmp("browser-demo.mcap");
    demo(&rec);
    let server = ReviewServer::start(&root(), &rec, &[]);
    let url = server.url.clone();
    let shot = tmp("review.png");
    let _ = std::fs::remove_file(&shot);
    let result = std::panic::catch_unwind(|| {
        node("web/e2e/review.e2e.mjs", &[&url, shot.to_str().unwrap()]);
    });
    drop(server);
    if let Err(e) = result {
        std::panic::resume_unwind(e);
    }
    let png = std::fs::read(&shot).unwrap();
    assert!(
        png.starts_with(b"\x89PNG") && png.len() > 20_000,
        "screenshot"
    );
}

#[test]
fn report_opens_offline_from_file_in_headless_chromium() {
    if common::skip_browser_test() {
        return;
    }
    let rec = tmp("browser-report.mcap");
    demo(&rec);
    let html = tmp("browser-report.html");
    report(&rec, &["--compare".as_ref(), rec.as_os_str()], &html);
    let shot = tmp("report.png");
    let _ = std::fs::remove_file(&shot);
    node(
        "web/e2e/report.e2e.mjs",
        &[html.to_str().unwrap(), shot.to_str().unwrap()],
    );
    assert!(std::fs::read(&shot).unwrap().starts_with(b"\x89PNG"));
}

#[test]
fn report_prints_to_pdf_with_the_findings_on_page_one_in_headless_chromium() {
    // The print stylesheet at an A4 page's width: the findings first and on page 1 (time at each
    // action level, the worst moments with stills, a recommendation for each region that needs
    // one), no panel wider than the page or clipped, then the session's pages (web/e2e/print.e2e.mjs).
    if common::skip_browser_test() {
        return;
    }
    let rec = tmp("browser-print.mcap");
    demo(&rec);
    let html = tmp("browser-print.html");
    report(&rec, &[], &html);
    let pdf = tmp("report.pdf");
    let shot = tmp("report-page1.png");
    let _ = std::fs::remove_file(&pdf);
    node(
        "web/e2e/print.e2e.mjs",
        &[
            html.to_str().unwrap(),
            pdf.to_str().unwrap(),
            shot.to_str().unwrap(),
        ],
    );
    assert!(std::fs::read(&pdf).unwrap().starts_with(b"%PDF-"));
    assert!(std::fs::read(&shot).unwrap().starts_with(b"\x89PNG"));
}

#[test]
fn an_overview_report_plays_and_says_what_it_holds_in_headless_chromium() {
    if common::skip_browser_test() {
        return;
    }
    let rec = tmp("browser-overview.mcap");
    demo(&rec);
    let html = tmp("browser-overview.html");
    // A page of a few frames: a shift's overview at a small scale (sparse frames outside the worst
    // moment, every frame within it).
    let args = [
        "--page-frames",
        "overview",
        "--overview-frames",
        "20",
        "--window-frames",
        "150",
    ]
    .map(std::ffi::OsStr::new);
    report(&rec, &args, &html);
    let shot = tmp("overview.png");
    let _ = std::fs::remove_file(&shot);
    node(
        "web/e2e/report.e2e.mjs",
        &[html.to_str().unwrap(), shot.to_str().unwrap(), "--overview"],
    );
    assert!(std::fs::read(&shot).unwrap().starts_with(b"\x89PNG"));
}

#[test]
fn the_page_handles_edge_case_data_and_every_control() {
    // Zero frames, one frame, all-null strain, no robot, compare with problems, no sessions; step
    // buttons, keys, scrubber, speed, the warning tooltip, B's timeline (web/e2e/variants.e2e.mjs).
    if common::skip_browser_test() {
        return;
    }
    node("web/e2e/variants.e2e.mjs", &[]);
}
