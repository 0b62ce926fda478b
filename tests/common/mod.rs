//! Shared by the integration tests: a running `ergocell review`, killed on drop, and the demo session
//! the review tests review; a scratch folder outside the repository.

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
