//! `ergocell trajectories` end to end on a copy of the shipped cell in a temp dir: validate, lock,
//! verify (fails until approved, naming what is missing), approve, verify, then a one-byte edit of the
//! trajectory file makes verify fail.

// Test helpers outside `#[test]` functions unwrap too (clippy.toml allows it only inside them).
#![allow(clippy::unwrap_used, clippy::expect_used)]

use std::path::{Path, PathBuf};
use std::process::Command;

fn copy_dir(from: &Path, to: &Path) {
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

/// A fresh cell: `config/` and the trajectory files (no locks, no approvals).
fn fresh_cell(name: &str) -> PathBuf {
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

const ALICE: &str = "alice@plant.example";
const BOB: &str = "bob@plant.example";

/// Writes an Ed25519 key made from `seed` as `<dir>/<name>` (OpenSSH private key, mode 0600, as
/// ssh-keygen writes it) and returns its allowed-signers line for `principal`.
fn key_file(dir: &Path, name: &str, seed: u8, principal: &str) -> String {
    use ergocell_robot::signing;
    let key = signing::key_from_seed(&[seed; 32], name);
    let path = dir.join(name);
    std::fs::write(&path, signing::private_key_openssh(&key).unwrap()).unwrap();
    #[cfg(unix)]
    {
        use std::os::unix::fs::PermissionsExt;
        std::fs::set_permissions(&path, std::fs::Permissions::from_mode(0o600)).unwrap();
    }
    format!(
        "{principal} namespaces=\"{}\" {}\n",
        signing::APPROVAL_NAMESPACE,
        signing::public_key_openssh(&key).unwrap()
    )
}

/// A fresh cell whose config/approvers/allowed_signers trusts alice and bob; their keys (and
/// mallory's, trusted by no one) in `<dir>/keys/`.
fn fresh_cell_with_approvers(name: &str) -> PathBuf {
    let dir = fresh_cell(name);
    let keys = dir.join("keys");
    std::fs::create_dir_all(&keys).unwrap();
    let alice = key_file(&keys, "alice", 1, ALICE);
    let bob = key_file(&keys, "bob", 2, BOB);
    key_file(&keys, "mallory", 3, "mallory@elsewhere.example");
    std::fs::write(
        dir.join("config/approvers/allowed_signers"),
        format!("# test approvers\n{alice}{bob}"),
    )
    .unwrap();
    dir
}

/// `ssh-keygen`, when this machine has it; CI sets ERGOCELL_REQUIRE_SSH_KEYGEN=1 so it cannot be skipped.
fn ssh_keygen() -> Option<&'static str> {
    let found = Command::new("ssh-keygen").arg("-?").output().is_ok();
    if !found {
        assert!(
            std::env::var_os("ERGOCELL_REQUIRE_SSH_KEYGEN").is_none(),
            "ERGOCELL_REQUIRE_SSH_KEYGEN is set but ssh-keygen is not installed"
        );
        eprintln!("ssh-keygen not found: skipping the OpenSSH interop checks");
        return None;
    }
    Some("ssh-keygen")
}

fn ergocell(dir: &Path, args: &[&str]) -> (i32, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_ergocell"))
        .current_dir(dir)
        .args(args)
        .output()
        .unwrap();
    (
        out.status.code().unwrap(),
        String::from_utf8(out.stdout).unwrap(),
        String::from_utf8(out.stderr).unwrap(),
    )
}

#[test]
fn validate_lock_approve_verify_and_a_one_byte_edit_fails_verify() {
    let dir = fresh_cell_with_approvers("trajectories_workflow");

    let (code, out, _) = ergocell(&dir, &["trajectories", "validate", "--class", "c2"]);
    assert_eq!(code, 0, "{out}");
    assert!(
        out.contains("class c2 — ACCEPTED") && out.contains("status Solved"),
        "{out}"
    );

    let (code, out, _) = ergocell(&dir, &["trajectories", "validate", "--json"]);
    assert_eq!(code, 0);
    let json: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert_eq!(json.as_array().unwrap().len(), 3);
    assert_eq!(json[1]["report"]["qp"]["status"], "Solved");

    // Verify before lock: fails, naming the missing lock.
    let (code, out, _) = ergocell(&dir, &["trajectories", "verify", "--class", "c2"]);
    assert_eq!(code, 1);
    assert!(out.contains("no lock file"), "{out}");

    let (code, out, err) = ergocell(&dir, &["trajectories", "lock"]);
    assert_eq!(code, 0, "{out}{err}");
    assert!(dir.join("trajectories/locks/c2.lock.toml").exists());

    // Locked but not approved: verify fails and says what is missing; --allow-unapproved passes.
    let (code, out, _) = ergocell(&dir, &["trajectories", "verify"]);
    assert_eq!(code, 1);
    assert!(
        out.contains("no approval for lock sha256") && out.contains("approve --class c1"),
        "{out}"
    );
    let (code, out, _) = ergocell(&dir, &["trajectories", "verify", "--allow-unapproved"]);
    assert_eq!(code, 0, "{out}");
    assert!(out.contains("NOT APPROVED"));

    let (code, out, err) = approve(&dir, "c2", ALICE, "keys/alice");
    assert_eq!(code, 0, "{out}{err}");
    let approvals = std::fs::read_to_string(dir.join("trajectories/approvals/c2.toml")).unwrap();
    assert!(approvals.contains(&format!("approved_by = \"{ALICE}\"")));
    assert!(approvals.contains("-----BEGIN SSH SIGNATURE-----"));
    let (code, out, _) = ergocell(&dir, &["trajectories", "verify", "--class", "c2"]);
    assert_eq!(code, 0, "{out}");
    assert!(
        out.contains("c2: OK") && out.contains(ALICE) && out.contains("signature verified"),
        "{out}"
    );

    // One byte of the trajectory file: verify fails and names the file.
    let path = dir.join("trajectories/c2.toml");
    let mut bytes = std::fs::read(&path).unwrap();
    let at = bytes.iter().position(u8::is_ascii_digit).unwrap();
    bytes[at] = if bytes[at] == b'9' {
        b'8'
    } else {
        bytes[at] + 1
    };
    std::fs::write(&path, &bytes).unwrap();
    let (code, out, _) = ergocell(&dir, &["trajectories", "verify", "--class", "c2"]);
    assert_eq!(code, 1, "{out}");
    assert!(
        out.contains("trajectory file trajectories/c2.toml changed"),
        "{out}"
    );

    // An edited trajectory cannot be approved either.
    let (code, _, err) = approve(&dir, "c2", ALICE, "keys/alice");
    assert_eq!(code, 1);
    assert!(err.contains("refusing to approve"), "{err}");
}

/// A lock whose samples were edited and whose `lock_sha256` was recomputed agrees with every hash, but
/// it does not hold what validation produces: it can be neither approved nor verified.
#[test]
fn a_hand_edited_and_rehashed_lock_is_neither_approved_nor_verified() {
    use ergocell_robot::lock::LockFile;
    use ergocell_robot::TrajectoryClass;

    let dir = fresh_cell_with_approvers("trajectories_forged_lock");
    let (code, out, err) = ergocell(&dir, &["trajectories", "lock", "--class", "c1"]);
    assert_eq!(code, 0, "{out}{err}");
    let (code, out, _) = ergocell(
        &dir,
        &[
            "trajectories",
            "verify",
            "--class",
            "c1",
            "--allow-unapproved",
        ],
    );
    assert_eq!(code, 0, "{out}");

    let path = dir.join("trajectories/locks/c1.lock.toml");
    let mut lock = LockFile::from_toml_str(
        TrajectoryClass::C1,
        &std::fs::read_to_string(&path).unwrap(),
    )
    .unwrap();
    lock.trajectory.point[40].velocities_rad_s[1] *= 1.5;
    lock.lock_sha256 = lock.content_sha256();
    std::fs::write(&path, lock.to_toml().unwrap()).unwrap();

    let (code, _, err) = approve(&dir, "c1", ALICE, "keys/alice");
    assert_eq!(code, 1);
    assert!(
        err.contains("does not hold the validated trajectory")
            && err.contains("refusing to approve"),
        "{err}"
    );
    assert!(!dir.join("trajectories/approvals/c1.toml").exists());
    let (code, out, _) = ergocell(
        &dir,
        &[
            "trajectories",
            "verify",
            "--class",
            "c1",
            "--allow-unapproved",
        ],
    );
    assert_eq!(code, 1, "{out}");
    assert!(
        out.contains("c1: FAIL") && out.contains("point 40: velocities_rad_s[1]"),
        "{out}"
    );
}

#[test]
fn an_unknown_class_is_a_usage_error() {
    let dir = fresh_cell("trajectories_usage");
    let (code, _, err) = ergocell(&dir, &["trajectories", "validate", "--class", "c9"]);
    assert_eq!(code, 2);
    assert!(err.contains("unknown trajectory class"), "{err}");
}

fn approve(dir: &Path, class: &str, by: &str, key: &str) -> (i32, String, String) {
    ergocell(
        dir,
        &[
            "trajectories",
            "approve",
            "--class",
            class,
            "--by",
            by,
            "--key",
            key,
        ],
    )
}

/// The forgeries of issue 16 through the command line: an outsider's key, someone else's key, a
/// name that draws a fake line, a hand-written entry, an edited last entry, a removed entry, a revoked
/// key and a trust file edited without re-locking — each refused, naming why. And OpenSSH agrees:
/// `ssh-keygen -Y verify` accepts what `approve` wrote, and `approve --signed` takes what
/// `ssh-keygen -Y sign` made.
#[test]
fn approvals_are_signed_and_forgeries_are_refused_naming_why() {
    let dir = fresh_cell_with_approvers("trajectories_signed");
    let (code, out, err) = ergocell(&dir, &["trajectories", "lock", "--class", "c2"]);
    assert_eq!(code, 0, "{out}{err}");
    let approvals = dir.join("trajectories/approvals/c2.toml");

    // An outsider's key, and a trusted key used under another engineer's name.
    let (code, _, err) = approve(&dir, "c2", "mallory@elsewhere.example", "keys/mallory");
    assert_eq!(code, 1);
    assert!(err.contains("is not a trusted approver's key"), "{err}");
    let (code, _, err) = approve(&dir, "c2", ALICE, "keys/bob");
    assert!(
        code == 1 && err.contains("not for `alice@plant.example`"),
        "{err}"
    );
    // A name that would print a fake verdict line.
    let (code, _, err) = approve(
        &dir,
        "c2",
        "Alice\nc3: OK — approved\u{1b}[31m",
        "keys/alice",
    );
    assert!(
        code == 1 && err.contains("control character") && !err.contains("\nc3: OK"),
        "{err}"
    );
    assert!(!approvals.exists());

    // A hand-written entry (the 64-zero chain start, no valid signature) is refused.
    std::fs::create_dir_all(approvals.parent().unwrap()).unwrap();
    let lock_sha = {
        let text = std::fs::read_to_string(dir.join("trajectories/locks/c2.lock.toml")).unwrap();
        ergocell_robot::LockFile::from_toml_str(ergocell_robot::TrajectoryClass::C2, &text)
            .unwrap()
            .lock_sha256
    };
    std::fs::write(
        &approvals,
        format!(
            "[[approval]]\nclass = \"c2\"\nlock_sha256 = \"{lock_sha}\"\napproved_by = \"Dr.\\nc3: OK\"\n\
             approved_at_utc = \"1999-01-01T00:00:00Z\"\nprevious_sha256 = \"{}\"\n\
             signature = \"-----BEGIN SSH SIGNATURE-----\\nAAAA\\n-----END SSH SIGNATURE-----\"\n",
            "0".repeat(64)
        ),
    )
    .unwrap();
    let (code, out, _) = ergocell(&dir, &["trajectories", "verify", "--class", "c2"]);
    assert_eq!(code, 1, "{out}");
    assert!(
        out.contains("refused: approver `Dr.\\nc3: OK` contains whitespace")
            && !out.contains("\nc3: OK"),
        "{out}"
    );
    // The same with a well-formed name: the signature is what fails.
    let text = std::fs::read_to_string(&approvals).unwrap();
    std::fs::write(
        &approvals,
        text.replace("Dr.\\nc3: OK", "dr.chief@plant.example"),
    )
    .unwrap();
    let (code, out, _) = ergocell(&dir, &["trajectories", "verify", "--class", "c2"]);
    assert!(
        code == 1 && out.contains("refused: the signature is not an SSH signature"),
        "{out}"
    );
    std::fs::remove_file(&approvals).unwrap();

    // Alice approves; the approval verifies.
    let (code, out, err) = approve(&dir, "c2", ALICE, "keys/alice");
    assert_eq!(code, 0, "{out}{err}");
    let good = std::fs::read_to_string(&approvals).unwrap();
    let (code, out, _) = ergocell(&dir, &["trajectories", "verify", "--class", "c2"]);
    assert_eq!(code, 0, "{out}");

    // OpenSSH checks the approval with the cell's own trust file.
    if let Some(keygen) = ssh_keygen() {
        let (code, message, err) = ergocell(
            &dir,
            &[
                "trajectories",
                "approval-message",
                "--class",
                "c2",
                "--entry",
                "0",
                "--signature-out",
                "entry0.sig",
            ],
        );
        assert_eq!(code, 0, "{err}");
        let verify = |message: &str| {
            use std::io::Write as _;
            let mut child = Command::new(keygen)
                .current_dir(&dir)
                .args([
                    "-Y",
                    "verify",
                    "-f",
                    "config/approvers/allowed_signers",
                    "-I",
                    ALICE,
                    "-n",
                    ergocell_robot::signing::APPROVAL_NAMESPACE,
                    "-s",
                    "entry0.sig",
                    "-r",
                    "config/approvers/revoked_keys",
                ])
                .stdin(std::process::Stdio::piped())
                .stdout(std::process::Stdio::piped())
                .stderr(std::process::Stdio::piped())
                .spawn()
                .unwrap();
            child
                .stdin
                .take()
                .unwrap()
                .write_all(message.as_bytes())
                .unwrap();
            let out = child.wait_with_output().unwrap();
            (
                out.status.success(),
                String::from_utf8_lossy(&out.stdout).into_owned(),
            )
        };
        let (ok, said) = verify(&message);
        assert!(
            ok && said.contains("Good \"ergocell-trajectory-approval\" signature"),
            "{said}"
        );
        let (ok, _) = verify(&message.replace("c2", "c3"));
        assert!(!ok, "ssh-keygen must refuse an edited message");

        // Two steps: ergocell writes the message, ssh-keygen signs it, ergocell appends it.
        let (code, out, err) = ergocell(
            &dir,
            &[
                "trajectories",
                "approve",
                "--class",
                "c2",
                "--by",
                BOB,
                "--message-out",
                "bob.txt",
            ],
        );
        assert_eq!(code, 0, "{out}{err}");
        let signed = Command::new(keygen)
            .current_dir(&dir)
            .args([
                "-Y",
                "sign",
                "-f",
                "keys/bob",
                "-n",
                ergocell_robot::signing::APPROVAL_NAMESPACE,
                "bob.txt",
            ])
            .output()
            .unwrap();
        assert!(
            signed.status.success(),
            "{}",
            String::from_utf8_lossy(&signed.stderr)
        );
        let (code, out, err) = ergocell(
            &dir,
            &[
                "trajectories",
                "approve",
                "--class",
                "c2",
                "--signed",
                "bob.txt",
            ],
        );
        assert_eq!(code, 0, "{out}{err}");
        let (code, out, _) = ergocell(&dir, &["trajectories", "verify", "--class", "c2"]);
        assert!(
            code == 0 && out.contains(ALICE) && out.contains(BOB),
            "{out}"
        );
        // The same signed message cannot be appended twice (the chain moved on).
        let (code, _, err) = ergocell(
            &dir,
            &[
                "trajectories",
                "approve",
                "--class",
                "c2",
                "--signed",
                "bob.txt",
            ],
        );
        assert!(code == 1 && err.contains("write a new message"), "{err}");
        std::fs::write(&approvals, &good).unwrap();
    }

    // The last entry edited (its time): the chain cannot see it, the signature does.
    std::fs::write(
        &approvals,
        good.replacen("approved_at_utc = \"20", "approved_at_utc = \"19", 1),
    )
    .unwrap();
    let (code, out, _) = ergocell(&dir, &["trajectories", "verify", "--class", "c2"]);
    assert!(
        code == 1 && out.contains("the signature does not match the entry"),
        "{out}"
    );
    // Its time replaced by words.
    let words = regex_free_replace_time(&good, "not a time at all");
    std::fs::write(&approvals, words).unwrap();
    let (code, out, _) = ergocell(&dir, &["trajectories", "verify", "--class", "c2"]);
    assert!(
        code == 1 && out.contains("is not an RFC 3339 time"),
        "{out}"
    );
    // The entry removed: nothing approves the lock.
    std::fs::write(&approvals, "").unwrap();
    let (code, out, _) = ergocell(&dir, &["trajectories", "verify", "--class", "c2"]);
    assert!(
        code == 1 && out.contains("no approval for lock sha256"),
        "{out}"
    );
    std::fs::write(&approvals, &good).unwrap();

    // Alice's key revoked, without re-locking: the lock sees the edited trust file.
    let alice_pub = ergocell_robot::signing::public_key_openssh(
        &ergocell_robot::signing::key_from_seed(&[1; 32], "alice"),
    )
    .unwrap();
    let revoked = dir.join("config/approvers/revoked_keys");
    let mut text = std::fs::read_to_string(&revoked).unwrap();
    text.push_str(&alice_pub);
    text.push('\n');
    std::fs::write(&revoked, text).unwrap();
    let (code, out, _) = ergocell(&dir, &["trajectories", "verify", "--class", "c2"]);
    assert!(
        code == 1
            && out.contains("revoked approvers' keys approvers/revoked_keys")
            && out.contains("changed since the lock was written"),
        "{out}"
    );
    // Re-locked: alice can no longer approve, and her old approval does not carry over.
    let (code, out, err) = ergocell(&dir, &["trajectories", "lock", "--class", "c2"]);
    assert_eq!(code, 0, "{out}{err}");
    let (code, _, err) = approve(&dir, "c2", ALICE, "keys/alice");
    assert!(code == 1 && err.contains("is revoked"), "{err}");
    let (code, out, _) = ergocell(&dir, &["trajectories", "verify", "--class", "c2"]);
    assert!(code == 1 && out.contains("none for this hash"), "{out}");
}

/// `good` with its (only) approved_at_utc value replaced by `value`.
fn regex_free_replace_time(good: &str, value: &str) -> String {
    good.lines()
        .map(|l| {
            if l.starts_with("approved_at_utc = ") {
                format!("approved_at_utc = \"{value}\"")
            } else {
                l.to_owned()
            }
        })
        .collect::<Vec<_>>()
        .join("\n")
        + "\n"
}

/// A stdout closed early (`ergocell trajectories lock | head -1`) is no reason to stop halfway:
/// every class is locked, the exit is 0 and nothing panics.
#[test]
fn a_closed_stdout_does_not_stop_the_work_halfway() {
    let dir = fresh_cell("trajectories_closed_stdout");
    let mut child = Command::new(env!("CARGO_BIN_EXE_ergocell"))
        .current_dir(&dir)
        .args(["trajectories", "lock"])
        .stdout(std::process::Stdio::piped())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .unwrap();
    // The reader is gone before the first line is written.
    drop(child.stdout.take());
    let out = child.wait_with_output().unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success(), "{:?}: {err}", out.status);
    assert!(!err.contains("panicked"), "{err}");
    for class in ["c1", "c2", "c3"] {
        assert!(
            dir.join(format!("trajectories/locks/{class}.lock.toml"))
                .exists(),
            "{class} locked"
        );
    }
}

/// A write cut short — the file-size limit reached mid-write (SIGXFSZ kills the process, as a full
/// disk or a kill would cut the write) — leaves the previous lock whole: locks are written beside and
/// moved into place, never truncated in place.
#[cfg(unix)]
#[test]
fn a_lock_write_cut_short_leaves_the_previous_lock_whole() {
    let dir = fresh_cell("trajectories_cut_write");
    let (code, out, err) = ergocell(&dir, &["trajectories", "lock", "--class", "c2"]);
    assert_eq!(code, 0, "{out}{err}");
    let lock = dir.join("trajectories/locks/c2.lock.toml");
    let before = std::fs::read(&lock).unwrap();
    assert!(before.len() > 16 * 1024, "{} bytes", before.len());
    // Files of at most 8 blocks (4–8 KiB, by the shell's unit) for the re-lock.
    let status = Command::new("sh")
        .current_dir(&dir)
        .args([
            "-c",
            "ulimit -f 8; exec \"$0\" trajectories lock --class c2",
            env!("CARGO_BIN_EXE_ergocell"),
        ])
        .stdout(std::process::Stdio::null())
        .stderr(std::process::Stdio::null())
        .status()
        .unwrap();
    assert!(!status.success(), "the write was cut: {status:?}");
    assert_eq!(
        std::fs::read(&lock).unwrap(),
        before,
        "the previous lock is whole"
    );
}
