//! Shared by the integration tests: a running `ergocell review`, killed on drop, and the demo session
//! the review tests review; a scratch folder outside the repository; the reference rig and a
//! trajectory provider with demo approvals (the session tests').

#![allow(clippy::unwrap_used, clippy::expect_used, dead_code)]

use std::io::{BufRead, BufReader, Lines};
use std::path::{Path, PathBuf};
use std::process::{Child, ChildStdout, Command, Stdio};
use std::sync::OnceLock;

/// A running `ergocell review` and the URL it printed.
pub struct ReviewServer {
    child: Child,
    pub url: String,
    /// `host:port` of the URL.
    pub authority: String,
    pub port: u16,
}

impl ReviewServer {
    /// Starts `ergocell review <rec> --port 0 <extra>` in `root` and waits for its URL.
    pub fn start(root: &Path, rec: &Path, extra: &[&str]) -> Self {
        // The reader is dropped after the URL line: the server must survive a closed stdout.
        let (child, url, _lines) = spawn_review(
            Command::new(env!("CARGO_BIN_EXE_ergocell")),
            root,
            rec,
            extra,
        );
        let authority = url
            .trim_start_matches("http://")
            .trim_end_matches('/')
            .to_owned();
        let port = authority.rsplit(':').next().unwrap().parse().unwrap();
        Self {
            child,
            url,
            authority,
            port,
        }
    }
}

/// Runs `command review <rec> --port 0 <extra>` in `root` (`command` is the binary, or a wrapper
/// that `exec`s it) and reads its stdout up to the URL it prints: the child, the URL and the rest
/// of its stdout.
pub fn spawn_review(
    mut command: Command,
    root: &Path,
    rec: &Path,
    extra: &[&str],
) -> (Child, String, Lines<BufReader<ChildStdout>>) {
    let mut child = command
        .current_dir(root)
        .arg("review")
        .arg(rec)
        .args(["--port", "0"])
        .args(extra)
        .stdout(Stdio::piped())
        .stderr(Stdio::null())
        .spawn()
        .unwrap();
    let mut lines = BufReader::new(child.stdout.take().unwrap()).lines();
    let url = loop {
        let line = lines
            .next()
            .expect("server exited before printing its URL")
            .unwrap();
        if let Some(u) = line.strip_prefix("review: ") {
            break u.to_owned();
        }
    };
    (child, url, lines)
}

impl Drop for ReviewServer {
    fn drop(&mut self) {
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}

/// One short demo session (one cycle, seed 7), recorded once per test binary as
/// `<CARGO_TARGET_TMPDIR>/<file>` (the first call's name is the one used).
pub fn demo_recording(file: &str) -> &'static Path {
    static REC: OnceLock<PathBuf> = OnceLock::new();
    REC.get_or_init(|| {
        let out = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join(file);
        let status = Command::new(env!("CARGO_BIN_EXE_ergocell"))
            .current_dir(env!("CARGO_MANIFEST_DIR"))
            .args(["demo", "--cycles", "1", "--seed", "7", "--force", "--out"])
            .arg(&out)
            .stdout(Stdio::null())
            .status()
            .unwrap();
        assert!(status.success(), "demo failed");
        out
    })
}

/// A fresh folder outside the repository, removed at the end.
pub struct Scratch(pub PathBuf);

impl Scratch {
    pub fn new(name: &str) -> Self {
        let dir = std::env::temp_dir().join(format!("ergocell-{name}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).unwrap();
        Self(dir)
    }
}

impl Drop for Scratch {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.0);
    }
}

/// `Some(why)` when the browser toolchain is missing: Debian's Chromium (or `$CHROMIUM`),
/// playwright-core from `npm ci --prefix web`, node.
pub fn missing_browser() -> Option<String> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let chromium = std::env::var("CHROMIUM").unwrap_or_else(|_| "/usr/bin/chromium".to_owned());
    if !Path::new(&chromium).exists() {
        return Some(format!(
            "no Chromium at {chromium} (apt-get install chromium)"
        ));
    }
    if !root.join("web/node_modules/playwright-core").exists() {
        return Some("web/node_modules/playwright-core missing (npm ci --prefix web)".to_owned());
    }
    if Command::new("node").arg("--version").output().is_err() {
        return Some("node is not installed".to_owned());
    }
    None
}

/// True when a browser test must be skipped (it says why); fails instead when
/// `ERGOCELL_REQUIRE_BROWSER` is set (CI: it must run).
pub fn skip_browser_test() -> bool {
    if let Some(why) = missing_browser() {
        assert!(
            std::env::var_os("ERGOCELL_REQUIRE_BROWSER").is_none(),
            "ERGOCELL_REQUIRE_BROWSER is set but the browser test cannot run: {why}"
        );
        eprintln!("SKIPPED: the browser test needs {why}");
        return true;
    }
    false
}

/// The reference cell's rig (`config/rig.toml`).
pub fn reference_rig() -> ergocell_perception::CameraRig {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let text = std::fs::read_to_string(root.join("config/rig.toml")).unwrap();
    ergocell_perception::rig_file::parse_rig(&text, "config/rig.toml")
        .unwrap()
        .0
}

/// A provider on the repository's files with a demo approval of `approve` in a fresh temp folder
/// of its own (numbered: tests running in parallel may ask for the same `name` and must not remove
/// each other's approvals).
pub fn demo_provider(
    name: &str,
    approve: Option<ergocell_robot::TrajectoryClass>,
) -> ergocell::session::provider::FileTrajectories {
    static NEXT: std::sync::atomic::AtomicUsize = std::sync::atomic::AtomicUsize::new(0);
    let n = NEXT.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join(format!("provider-{name}-{n}"));
    let _ = std::fs::remove_dir_all(&dir);
    let p = ergocell::session::provider::FileTrajectories::new(
        &root.join("config/cell.toml"),
        &root.join("trajectories"),
        &dir,
    )
    .with_demo_key(&[7; 32])
    .unwrap();
    if let Some(class) = approve {
        p.approve_for_demo(class, "2026-01-01T00:00:00Z").unwrap();
    }
    p
}
