//! Shared by the integration tests: a running `ergocell review`, killed on drop, and the demo session
//! the review tests review; a scratch folder outside the repository; the reference rig and a
//! trajectory provider with demo approvals (the session tests').

#![allow(clippy::unwrap_used, clippy::expect_used, dead_code)]

use std::io::Write as _;
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
        // Straight to the stream: cargo test shows it without --nocapture.
        let _ = writeln!(std::io::stderr(), "SKIPPED: the browser test needs {why}");
        return true;
    }
    false
}

/// The reference cell's rig (`config/rig.toml`).
pub fn reference_rig() -> ergocell_perception::CameraRig {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let text = std::fs::read_to_string(root.join("config/rig.toml")).unwrap();
    ergocell_formats::rig_file::parse_rig(&text, "config/rig.toml")
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
    let p = ergocell::session::provider::on_disk(
        &root.join("config/cell.toml"),
        &root.join("trajectories"),
        &dir,
    )
    .with_demo_key(&[7; 32])
    .unwrap();
    if let Some(class) = approve {
        ergocell::session::provider::approve_for_demo(&p, class, "2026-01-01T00:00:00Z").unwrap();
    }
    p
}

/// Copies the folder `from` into `to`, recursively.
pub fn copy_dir(from: &Path, to: &Path) {
    std::fs::create_dir_all(to).unwrap();
    for entry in std::fs::read_dir(from).unwrap() {
        let path = entry.unwrap().path();
        let dest = to.join(path.file_name().unwrap());
        if path.is_dir() {
            copy_dir(&path, &dest);
        } else {
            std::fs::copy(&path, &dest).unwrap();
        }
    }
}

/// A fresh cell in the tests' scratch folder: `config/` and the trajectory files (no locks, no
/// approvals).
pub fn fresh_cell(name: &str) -> PathBuf {
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR"));
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join(name);
    let _ = std::fs::remove_dir_all(&dir);
    copy_dir(&root.join("config"), &dir.join("config"));
    std::fs::create_dir_all(dir.join("trajectories")).unwrap();
    for class in ["c1", "c2", "c3"] {
        std::fs::copy(
            root.join(format!("trajectories/{class}.toml")),
            dir.join(format!("trajectories/{class}.toml")),
        )
        .unwrap();
    }
    dir
}

pub const ALICE: &str = "alice@plant.example";
pub const BOB: &str = "bob@plant.example";
pub const MALLORY: &str = "mallory@evil.example";

/// Writes an Ed25519 key made from `seed` as `<dir>/<name>` (OpenSSH private key, mode 0600, as
/// ssh-keygen writes it) and returns its allowed-signers line for `principal`.
pub fn key_file(dir: &Path, name: &str, seed: u8, principal: &str) -> String {
    use ergocell_robot::signing;
    use std::os::unix::fs::PermissionsExt as _;
    let key = signing::key_from_seed(&[seed; 32], name);
    let path = dir.join(name);
    std::fs::write(&path, signing::private_key_openssh(&key).unwrap()).unwrap();
    std::fs::set_permissions(&path, std::fs::Permissions::from_mode(0o600)).unwrap();
    format!(
        "{principal} namespaces=\"{}\" {}\n",
        signing::APPROVAL_NAMESPACE,
        signing::public_key_openssh(&key).unwrap()
    )
}

/// Runs `command` to its end: (exit code, stdout, stderr).
pub fn outcome(command: &mut Command) -> (i32, String, String) {
    let out = command.output().unwrap();
    (
        out.status.code().unwrap(),
        String::from_utf8(out.stdout).unwrap(),
        String::from_utf8(out.stderr).unwrap(),
    )
}

/// Whether this process runs as root (/proc/self is owned by the effective uid).
pub fn is_root() -> bool {
    use std::os::unix::fs::MetadataExt as _;
    std::fs::metadata("/proc/self").is_ok_and(|m| m.uid() == 0)
}

/// A fresh cell whose approvers (alice and bob; mallory's key trusted by no one, all in
/// `<dir>/keys/`) are signed by a site approvers authority installed in a root-owned anchor folder
/// outside the cell (`anchor`, under /tmp), as an integrator installs /etc/ergocell.
pub struct AnchoredCell {
    pub dir: PathBuf,
    pub anchor: PathBuf,
}

impl AnchoredCell {
    /// `None` (test skipped, said on stderr) when this process is not root: only root can make a
    /// root-owned anchor. CI runs as root and sets ERGOCELL_REQUIRE_ANCHOR=1, so there it cannot skip.
    pub fn new(name: &str) -> Option<Self> {
        use std::os::unix::fs::PermissionsExt as _;
        if !is_root() {
            assert!(
                std::env::var_os("ERGOCELL_REQUIRE_ANCHOR").is_none(),
                "ERGOCELL_REQUIRE_ANCHOR is set but the tests do not run as root"
            );
            let _ = writeln!(
                std::io::stderr(),
                "SKIPPED: a root-owned trust anchor needs root (CI runs as root)"
            );
            return None;
        }
        let dir = fresh_cell(name);
        let keys = dir.join("keys");
        std::fs::create_dir_all(&keys).unwrap();
        let alice = key_file(&keys, "alice", 1, ALICE);
        let bob = key_file(&keys, "bob", 2, BOB);
        key_file(&keys, "mallory", 3, MALLORY);
        key_file(&keys, "site", 90, "site");
        std::fs::write(
            dir.join("config/approvers/allowed_signers"),
            format!("# test approvers\n{alice}{bob}"),
        )
        .unwrap();
        let anchor = std::env::temp_dir().join(format!(
            "ergocell-test-anchor-{name}-{}",
            std::process::id()
        ));
        let _ = std::fs::remove_dir_all(&anchor);
        std::fs::create_dir_all(&anchor).unwrap();
        std::fs::set_permissions(&anchor, std::fs::Permissions::from_mode(0o755)).unwrap();
        let site = ergocell_robot::signing::key_from_seed(&[90; 32], "site");
        let key = anchor.join("approvers-authority.pub");
        std::fs::write(
            &key,
            ergocell_robot::signing::public_key_openssh(&site).unwrap() + "\n",
        )
        .unwrap();
        std::fs::set_permissions(&key, std::fs::Permissions::from_mode(0o644)).unwrap();
        let cell = Self { dir, anchor };
        let (code, out, err) =
            cell.ergocell(&["trajectories", "sign-approvers", "--key", "keys/site"]);
        assert_eq!(code, 0, "{out}{err}");
        Some(cell)
    }

    /// Runs the binary in the cell's folder with the anchor: (exit code, stdout, stderr).
    pub fn ergocell(&self, args: &[&str]) -> (i32, String, String) {
        outcome(
            Command::new(env!("CARGO_BIN_EXE_ergocell"))
                .current_dir(&self.dir)
                .env("ERGOCELL_TRUST_ANCHOR_DIR", &self.anchor)
                .args(args),
        )
    }

    /// `trajectories approve --class <class> --by <by> --key <key>`.
    pub fn approve(&self, class: &str, by: &str, key: &str) -> (i32, String, String) {
        self.sign("approve", class, by, key)
    }

    /// `trajectories withdraw --class <class> --by <by> --key <key>`.
    pub fn withdraw(&self, class: &str, by: &str, key: &str) -> (i32, String, String) {
        self.sign("withdraw", class, by, key)
    }

    fn sign(&self, command: &str, class: &str, by: &str, key: &str) -> (i32, String, String) {
        self.ergocell(&[
            "trajectories",
            command,
            "--class",
            class,
            "--by",
            by,
            "--key",
            key,
        ])
    }

    /// The provider `ergocell run` uses, on this cell with its anchor.
    pub fn provider(&self) -> ergocell::session::provider::FileTrajectories {
        ergocell::session::provider::on_disk(
            &self.dir.join("config/cell.toml"),
            &self.dir.join("trajectories"),
            &self.dir.join("trajectories/approvals"),
        )
        .with_anchor_dir(&self.anchor)
    }

    /// What a hostile user with write access to the project folder does: appends her own key to the
    /// allowed signers, loosens the cell (the arm's capsules to 1 cm), re-locks `class` under the
    /// edited files and approves it with her key, writing the approval with the library (the
    /// command refuses to). Returns the approvals file's path.
    pub fn mallory_attack(&self, class: ergocell_robot::TrajectoryClass) -> PathBuf {
        use ergocell_robot::lock::{ApprovalsFile, LockFile};
        let allowed_path = self.dir.join("config/approvers/allowed_signers");
        let mut allowed = std::fs::read_to_string(&allowed_path).unwrap();
        allowed.push_str(&key_file(&self.dir.join("keys"), "mallory", 3, MALLORY));
        std::fs::write(&allowed_path, &allowed).unwrap();
        let cell_path = self.dir.join("config/cell.toml");
        let cell = std::fs::read_to_string(&cell_path).unwrap();
        assert!(cell.contains("link_radius_m = 0.08"));
        std::fs::write(
            &cell_path,
            cell.replace("link_radius_m = 0.08", "link_radius_m = 0.01"),
        )
        .unwrap();
        let (code, out, err) = self.ergocell(&["trajectories", "lock", "--class", class.as_str()]);
        assert_eq!(code, 0, "{out}{err}");
        assert!(err.contains("not trusted"), "lock says so: {err}");
        // The command refuses to approve under files the authority did not sign.
        let (code, _, err) = self.approve(class.as_str(), MALLORY, "keys/mallory");
        assert!(code == 1 && err.contains("edited after signing"), "{err}");
        // So she writes the approval herself, trusting her own edited list.
        let revoked =
            std::fs::read_to_string(self.dir.join("config/approvers/revoked_keys")).unwrap();
        let trusted = ergocell_robot::TrustedSigners::parse(&allowed, &revoked).unwrap();
        let lock_path = self
            .dir
            .join(format!("trajectories/locks/{class}.lock.toml"));
        let lock =
            LockFile::from_toml_str(class, &std::fs::read_to_string(lock_path).unwrap()).unwrap();
        let approvals = self
            .dir
            .join(format!("trajectories/approvals/{class}.toml"));
        let mut file = std::fs::read_to_string(&approvals)
            .map(|t| ApprovalsFile::from_toml_str(&t).unwrap())
            .unwrap_or_default();
        let key = ergocell_robot::signing::private_key_from_openssh(
            &std::fs::read_to_string(self.dir.join("keys/mallory")).unwrap(),
        )
        .unwrap();
        file.approve(&lock, MALLORY, "2026-12-04T12:00:00Z", &trusted, &key)
            .unwrap();
        std::fs::create_dir_all(approvals.parent().unwrap()).unwrap();
        std::fs::write(&approvals, file.to_toml().unwrap()).unwrap();
        approvals
    }
}

impl Drop for AnchoredCell {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.anchor);
    }
}

/// A small but complete recording (one operator session) for `report`.
pub fn small_recording(path: &Path) {
    let mut rec = ergocell::recording::McapRecorder::create(path).unwrap();
    write_sessions(&mut rec, 0, &[("c2", 1.75)], 20, 2);
    rec.finish().unwrap();
}

/// Writes one operator session per `(class, height)` into `rec`, 20 s apart from `start_nanos`
/// (nanoseconds, the recording's clock): a `working` state, `frames` poses at 10 Hz (every landmark
/// at (0, 0, 1)), then `session_ended` `end_secs` after its start.
pub fn write_sessions(
    rec: &mut ergocell::recording::McapRecorder,
    start_nanos: i64,
    sessions: &[(&str, f64)],
    frames: i64,
    end_secs: i64,
) {
    use ergocell::recording::topics;
    use ergocell_bridge::msg::{Header, OperatorPose, SessionState};
    let s = 1_000_000_000i64;
    for (k, (class, height)) in sessions.iter().enumerate() {
        let t0 = start_nanos + k as i64 * 20 * s;
        let state = |t: i64, name: &str| SessionState {
            header: Header::new(t, "world"),
            state: name.to_owned(),
            height_m: *height,
            height_class: (*class).to_owned(),
            ..SessionState::default()
        };
        rec.write(topics::SESSION_STATE, t0, &state(t0, "working"))
            .unwrap();
        for f in 0..frames {
            let t = t0 + f * s / 10;
            let pose = OperatorPose {
                header: Header::new(t, "world"),
                x: vec![0.0; 33],
                y: vec![0.0; 33],
                z: vec![1.0; 33],
                ..OperatorPose::default()
            };
            rec.write(topics::OPERATOR_POSE, t, &pose).unwrap();
        }
        let end = t0 + end_secs * s;
        rec.write(topics::SESSION_STATE, end, &state(end, "session_ended"))
            .unwrap();
    }
}
