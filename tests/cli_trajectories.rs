//! `ergocell trajectories` end to end on a copy of the shipped cell in a temp dir: validate, lock,
//! verify (fails until approved, naming what is missing), approve, verify, then a one-byte edit of the
//! trajectory file makes verify fail.

// Test helpers outside `#[test]` functions unwrap too (clippy.toml allows it only inside them).
#![allow(clippy::unwrap_used, clippy::expect_used)]

use std::path::{Path, PathBuf};
use std::process::Command;

mod common;

use common::{fresh_cell, AnchoredCell, ALICE, BOB};

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
    common::outcome(
        Command::new(env!("CARGO_BIN_EXE_ergocell"))
            .current_dir(dir)
            .args(args),
    )
}

#[test]
fn validate_lock_approve_verify_and_a_one_byte_edit_fails_verify() {
    let Some(cell) = AnchoredCell::new("trajectories_workflow") else {
        return;
    };
    let dir = cell.dir.clone();

    let (code, out, _) = cell.ergocell(&["trajectories", "validate", "--class", "c2"]);
    assert_eq!(code, 0, "{out}");
    assert!(
        out.contains("class c2 — ACCEPTED") && out.contains("status Solved"),
        "{out}"
    );

    let (code, out, _) = cell.ergocell(&["trajectories", "validate", "--json"]);
    assert_eq!(code, 0);
    let json: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert_eq!(json.as_array().unwrap().len(), 3);
    assert_eq!(json[1]["report"]["qp"]["status"], "Solved");

    // Verify before lock: fails, naming the missing lock.
    let (code, out, _) = cell.ergocell(&["trajectories", "verify", "--class", "c2"]);
    assert_eq!(code, 1);
    assert!(out.contains("no lock file"), "{out}");

    let (code, out, err) = cell.ergocell(&["trajectories", "lock"]);
    assert_eq!(code, 0, "{out}{err}");
    assert!(dir.join("trajectories/locks/c2.lock.toml").exists());

    // Locked but not approved: verify fails and says what is missing; --allow-unapproved passes.
    let (code, out, _) = cell.ergocell(&["trajectories", "verify"]);
    assert_eq!(code, 1);
    assert!(
        out.contains("no approval for lock sha256") && out.contains("approve --class c1"),
        "{out}"
    );
    let (code, out, _) = cell.ergocell(&["trajectories", "verify", "--allow-unapproved"]);
    assert_eq!(code, 0, "{out}");
    assert!(out.contains("NOT APPROVED"));

    let (code, out, err) = cell.approve("c2", ALICE, "keys/alice");
    assert_eq!(code, 0, "{out}{err}");
    let approvals = std::fs::read_to_string(dir.join("trajectories/approvals/c2.toml")).unwrap();
    assert!(approvals.contains(&format!("approved_by = \"{ALICE}\"")));
    assert!(approvals.contains("-----BEGIN SSH SIGNATURE-----"));
    let (code, out, _) = cell.ergocell(&["trajectories", "verify", "--class", "c2"]);
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
    let (code, out, _) = cell.ergocell(&["trajectories", "verify", "--class", "c2"]);
    assert_eq!(code, 1, "{out}");
    assert!(
        out.contains("trajectory file trajectories/c2.toml changed"),
        "{out}"
    );

    // An edited trajectory cannot be approved either.
    let (code, _, err) = cell.approve("c2", ALICE, "keys/alice");
    assert_eq!(code, 1);
    assert!(err.contains("refusing to approve"), "{err}");
}

/// A lock whose samples were edited and whose `lock_sha256` was recomputed agrees with every hash, but
/// it does not hold what validation produces: it can be neither approved nor verified.
#[test]
fn a_hand_edited_and_rehashed_lock_is_neither_approved_nor_verified() {
    use ergocell_robot::lock::LockFile;
    use ergocell_robot::TrajectoryClass;

    let Some(cell) = AnchoredCell::new("trajectories_forged_lock") else {
        return;
    };
    let dir = cell.dir.clone();
    let (code, out, err) = cell.ergocell(&["trajectories", "lock", "--class", "c1"]);
    assert_eq!(code, 0, "{out}{err}");
    let (code, out, _) = cell.ergocell(&[
        "trajectories",
        "verify",
        "--class",
        "c1",
        "--allow-unapproved",
    ]);
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

    let (code, _, err) = cell.approve("c1", ALICE, "keys/alice");
    assert_eq!(code, 1);
    assert!(
        err.contains("does not hold the validated trajectory")
            && err.contains("refusing to approve"),
        "{err}"
    );
    assert!(!dir.join("trajectories/approvals/c1.toml").exists());
    let (code, out, _) = cell.ergocell(&[
        "trajectories",
        "verify",
        "--class",
        "c1",
        "--allow-unapproved",
    ]);
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

/// The forgeries of issue 16 through the command line: an outsider's key, someone else's key, a
/// name that draws a fake line, a hand-written entry, an edited last entry, a removed entry, a revoked
/// key and a trust file edited without re-locking — each refused, naming why. And OpenSSH agrees:
/// `ssh-keygen -Y verify` accepts what `approve` wrote, and `approve --signed` takes what
/// `ssh-keygen -Y sign` made.
#[test]
fn approvals_are_signed_and_forgeries_are_refused_naming_why() {
    let Some(cell) = AnchoredCell::new("trajectories_signed") else {
        return;
    };
    let dir = cell.dir.clone();
    let (code, out, err) = cell.ergocell(&["trajectories", "lock", "--class", "c2"]);
    assert_eq!(code, 0, "{out}{err}");
    let approvals = dir.join("trajectories/approvals/c2.toml");

    // An outsider's key, and a trusted key used under another engineer's name.
    let (code, _, err) = cell.approve("c2", "mallory@elsewhere.example", "keys/mallory");
    assert_eq!(code, 1);
    assert!(err.contains("is not a trusted approver's key"), "{err}");
    let (code, _, err) = cell.approve("c2", ALICE, "keys/bob");
    assert!(
        code == 1 && err.contains("not for `alice@plant.example`"),
        "{err}"
    );
    // A name that would print a fake verdict line.
    let (code, _, err) = cell.approve("c2", "Alice\nc3: OK — approved\u{1b}[31m", "keys/alice");
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
    let (code, out, _) = cell.ergocell(&["trajectories", "verify", "--class", "c2"]);
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
    let (code, out, _) = cell.ergocell(&["trajectories", "verify", "--class", "c2"]);
    assert!(
        code == 1 && out.contains("refused: the signature is not an SSH signature"),
        "{out}"
    );
    std::fs::remove_file(&approvals).unwrap();

    // Alice approves; the approval verifies.
    let (code, out, err) = cell.approve("c2", ALICE, "keys/alice");
    assert_eq!(code, 0, "{out}{err}");
    let good = std::fs::read_to_string(&approvals).unwrap();
    let (code, out, _) = cell.ergocell(&["trajectories", "verify", "--class", "c2"]);
    assert_eq!(code, 0, "{out}");

    // OpenSSH checks the approval with the cell's own trust file.
    if let Some(keygen) = ssh_keygen() {
        let (code, message, err) = cell.ergocell(&[
            "trajectories",
            "approval-message",
            "--class",
            "c2",
            "--entry",
            "0",
            "--signature-out",
            "entry0.sig",
        ]);
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
        let (code, out, err) = cell.ergocell(&[
            "trajectories",
            "approve",
            "--class",
            "c2",
            "--by",
            BOB,
            "--message-out",
            "bob.txt",
        ]);
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
        let (code, out, err) = cell.ergocell(&[
            "trajectories",
            "approve",
            "--class",
            "c2",
            "--signed",
            "bob.txt",
        ]);
        assert_eq!(code, 0, "{out}{err}");
        let (code, out, _) = cell.ergocell(&["trajectories", "verify", "--class", "c2"]);
        assert!(
            code == 0 && out.contains(ALICE) && out.contains(BOB),
            "{out}"
        );
        // The same signed message cannot be appended twice (the chain moved on).
        let (code, _, err) = cell.ergocell(&[
            "trajectories",
            "approve",
            "--class",
            "c2",
            "--signed",
            "bob.txt",
        ]);
        assert!(code == 1 && err.contains("write a new message"), "{err}");
        // Rolled back to alice's approval on purpose: the witness that would refuse it is cleared.
        std::fs::write(&approvals, &good).unwrap();
        forget_witness(&cell.dir);
    }

    // The last entry edited (its time): the chain cannot see it, the signature does.
    std::fs::write(
        &approvals,
        good.replacen("approved_at_utc = \"20", "approved_at_utc = \"19", 1),
    )
    .unwrap();
    let (code, out, _) = cell.ergocell(&["trajectories", "verify", "--class", "c2"]);
    assert!(
        code == 1 && out.contains("the signature does not match the entry"),
        "{out}"
    );
    // Its time replaced by words.
    let words = regex_free_replace_time(&good, "not a time at all");
    std::fs::write(&approvals, words).unwrap();
    let (code, out, _) = cell.ergocell(&["trajectories", "verify", "--class", "c2"]);
    assert!(
        code == 1 && out.contains("is not an RFC 3339 time"),
        "{out}"
    );
    // The entry removed: nothing approves the lock.
    std::fs::write(&approvals, "").unwrap();
    let (code, out, _) = cell.ergocell(&["trajectories", "verify", "--class", "c2"]);
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
    let (code, out, _) = cell.ergocell(&["trajectories", "verify", "--class", "c2"]);
    assert!(
        code == 1
            && out.contains("approvers: NOT TRUSTED")
            && out.contains("edited after signing")
            && out.contains("revoked approvers' keys approvers/revoked_keys")
            && out.contains("changed since the lock was written"),
        "{out}"
    );
    // The site's authority signs the revocation; re-locked: alice can no longer approve, and her
    // old approval does not carry over.
    let (code, out, err) = cell.ergocell(&["trajectories", "sign-approvers", "--key", "keys/site"]);
    assert_eq!(code, 0, "{out}{err}");
    let (code, out, err) = cell.ergocell(&["trajectories", "lock", "--class", "c2"]);
    assert_eq!(code, 0, "{out}{err}");
    let (code, _, err) = cell.approve("c2", ALICE, "keys/alice");
    assert!(code == 1 && err.contains("is revoked"), "{err}");
    let (code, out, _) = cell.ergocell(&["trajectories", "verify", "--class", "c2"]);
    assert!(code == 1 && out.contains("none for this hash"), "{out}");
}

/// Deletes the cell's witness of its approvals, for tests that swap approvals files on purpose.
fn forget_witness(cell: &Path) {
    let _ = std::fs::remove_dir_all(cell.join("trajectories/approvals/.witness"));
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

/// The hostile user with write access to the project folder: her own key appended to the allowed
/// signers, the cell loosened, the class re-locked and approved by herself. `verify` refuses it and
/// says why (the approvers' files are not what the site's authority signed), as does the provider
/// `ergocell run` checks every trajectory with; so do her other ways round: signing the files with
/// her own key, or pointing the cell at an anchor she controls.
#[test]
fn the_mallory_attack_is_refused_by_verify_and_by_run_naming_why() {
    use ergocell_robot::TrajectoryClass;
    let Some(cell) = AnchoredCell::new("trajectories_mallory") else {
        return;
    };
    let (code, out, err) = cell.ergocell(&["trajectories", "lock", "--class", "c2"]);
    assert_eq!(code, 0, "{out}{err}");
    let (code, out, err) = cell.approve("c2", ALICE, "keys/alice");
    assert_eq!(code, 0, "{out}{err}");
    let (code, out, _) = cell.ergocell(&["trajectories", "verify", "--class", "c2"]);
    assert!(code == 0 && out.contains("c2: OK"), "{out}");
    cell.provider().verify(TrajectoryClass::C2).unwrap();

    cell.mallory_attack(TrajectoryClass::C2);
    let (code, out, _) = cell.ergocell(&["trajectories", "verify", "--class", "c2"]);
    assert_eq!(code, 1, "{out}");
    assert!(
        out.contains("approvers: NOT TRUSTED")
            && out.contains("edited after signing")
            && out.contains("c2: FAIL")
            && out.contains("is not a trusted approver's key")
            && !out.contains("c2: OK"),
        "{out}"
    );
    // The provider `run` uses refuses it for the same typed reason: the trust list, edited after
    // the authority signed it.
    let refused = cell.provider().verify(TrajectoryClass::C2).unwrap_err();
    let ergocell::session::ProviderError::TrustList { cause } = &refused else {
        panic!("not refused for the trust list: {refused}");
    };
    assert!(
        matches!(
            cause.as_ref(),
            ergocell::trust_anchor::TrustListError::Authority(
                ergocell_robot::authority::AuthorityError::Edited
            )
        ),
        "{refused}"
    );

    // She signs the edited files with her own key: refused, the signature is not written.
    let sig_path = cell.dir.join("config/approvers/approvers.sig");
    let sig_before = std::fs::read(&sig_path).unwrap();
    let (code, _, err) =
        cell.ergocell(&["trajectories", "sign-approvers", "--key", "keys/mallory"]);
    assert!(
        code == 1 && err.contains("not the site's approvers authority"),
        "{err}"
    );
    assert_eq!(std::fs::read(&sig_path).unwrap(), sig_before);
    // She writes that signature herself: verify names the key that is not the authority.
    let mallory = ergocell_robot::signing::private_key_from_openssh(
        &std::fs::read_to_string(cell.dir.join("keys/mallory")).unwrap(),
    )
    .unwrap();
    let allowed =
        std::fs::read_to_string(cell.dir.join("config/approvers/allowed_signers")).unwrap();
    let revoked = std::fs::read_to_string(cell.dir.join("config/approvers/revoked_keys")).unwrap();
    std::fs::write(
        &sig_path,
        ergocell_robot::authority::sign_approvers(&allowed, &revoked, &mallory).unwrap(),
    )
    .unwrap();
    let (code, out, _) = cell.ergocell(&["trajectories", "verify", "--class", "c2"]);
    assert!(
        code == 1 && out.contains("which is not the site's approvers authority"),
        "{out}"
    );
    // She installs her key as an "anchor" in a folder of her own (here: one owned by uid 1000, and
    // one in the project folder that the cell's account can write).
    for (anchor, owner) in [
        (cell.dir.join("my-anchor"), 1000),
        (cell.dir.join("config/anchor"), 0),
    ] {
        use std::os::unix::fs::PermissionsExt as _;
        std::fs::create_dir_all(&anchor).unwrap();
        let key = anchor.join("approvers-authority.pub");
        std::fs::write(
            &key,
            ergocell_robot::signing::public_key_openssh(&mallory).unwrap(),
        )
        .unwrap();
        std::os::unix::fs::chown(&key, Some(owner), None).unwrap();
        if owner == 0 {
            // The project folder as a service account's: writable by its group.
            std::fs::set_permissions(
                cell.dir.join("config"),
                std::fs::Permissions::from_mode(0o775),
            )
            .unwrap();
        }
        let out = Command::new(env!("CARGO_BIN_EXE_ergocell"))
            .current_dir(&cell.dir)
            .env("ERGOCELL_TRUST_ANCHOR_DIR", &anchor)
            .args(["trajectories", "verify", "--class", "c2"])
            .output()
            .unwrap();
        let said = String::from_utf8_lossy(&out.stdout);
        assert!(!out.status.success(), "{said}");
        assert!(
            said.contains("owned by uid 1000, not root")
                || said.contains("writable by group or others (mode 775)"),
            "{said}"
        );
    }
}

/// Approvers that trust keys but come without the authority's signature, or on a machine without
/// the authority installed, approve nothing; the shipped list (no keys) needs neither.
#[test]
fn unsigned_approvers_or_a_missing_authority_approve_nothing() {
    let Some(cell) = AnchoredCell::new("trajectories_unsigned") else {
        return;
    };
    let (code, out, err) = cell.ergocell(&["trajectories", "lock", "--class", "c2"]);
    assert_eq!(code, 0, "{out}{err}");
    let (code, out, err) = cell.approve("c2", ALICE, "keys/alice");
    assert_eq!(code, 0, "{out}{err}");
    std::fs::remove_file(cell.dir.join("config/approvers/approvers.sig")).unwrap();
    let (code, out, _) = cell.ergocell(&["trajectories", "verify", "--class", "c2"]);
    assert!(
        code == 1 && out.contains("approvers.sig is missing"),
        "{out}"
    );
    let (code, out, err) = cell.ergocell(&["trajectories", "sign-approvers", "--key", "keys/site"]);
    assert_eq!(code, 0, "{out}{err}");
    assert!(
        out.contains("checked against the site's approvers authority"),
        "{out}"
    );
    let (code, out, _) = cell.ergocell(&["trajectories", "verify", "--class", "c2"]);
    assert!(code == 0 && out.contains("c2: OK"), "{out}");
    // The same cell on a machine where no authority is installed.
    let out = Command::new(env!("CARGO_BIN_EXE_ergocell"))
        .current_dir(&cell.dir)
        .env("ERGOCELL_TRUST_ANCHOR_DIR", cell.dir.join("no-such-folder"))
        .args(["trajectories", "verify", "--class", "c2"])
        .output()
        .unwrap();
    let said = String::from_utf8_lossy(&out.stdout);
    assert!(
        !out.status.success() && said.contains("no approvers authority is installed"),
        "{said}"
    );
    // The shipped approvers (no key) need no authority: the integrity check still passes.
    let dir = fresh_cell("trajectories_unsigned_shipped");
    let (code, out, err) = ergocell(&dir, &["trajectories", "lock", "--class", "c2"]);
    assert_eq!(code, 0, "{out}{err}");
    let (code, out, _) = ergocell(
        &dir,
        &[
            "trajectories",
            "verify",
            "--class",
            "c2",
            "--allow-unapproved",
        ],
    );
    assert!(code == 0 && !out.contains("NOT TRUSTED"), "{out}");
}

/// `lock` of every class is all or nothing: with c3's trajectory file broken, c1 and c2 are not
/// re-locked either, and every lock keeps its bytes.
#[test]
fn lock_of_all_classes_writes_nothing_when_one_class_fails() {
    let dir = fresh_cell("trajectories_lock_all_or_nothing");
    let (code, out, err) = ergocell(&dir, &["trajectories", "lock"]);
    assert_eq!(code, 0, "{out}{err}");
    let locks: Vec<PathBuf> = ["c1", "c2", "c3"]
        .iter()
        .map(|c| dir.join(format!("trajectories/locks/{c}.lock.toml")))
        .collect();
    let before: Vec<Vec<u8>> = locks.iter().map(|p| std::fs::read(p).unwrap()).collect();
    // A change that would give c1 and c2 new locks (the arm's capsules), and c3's file broken.
    let cell = dir.join("config/cell.toml");
    let text = std::fs::read_to_string(&cell).unwrap();
    std::fs::write(
        &cell,
        text.replace("link_radius_m = 0.08", "link_radius_m = 0.07"),
    )
    .unwrap();
    std::fs::write(
        dir.join("trajectories/c3.toml"),
        "class = \"c3\"\nnot toml at all\n",
    )
    .unwrap();
    let (code, _, err) = ergocell(&dir, &["trajectories", "lock"]);
    assert_eq!(code, 2, "{err}");
    assert!(
        err.contains("c3: not locked") && err.contains("no lock file was written"),
        "{err}"
    );
    for (p, b) in locks.iter().zip(&before) {
        assert_eq!(&std::fs::read(p).unwrap(), b, "{} kept", p.display());
    }
}

/// Fault injection: `lock`, `approve` and `report --force` on a full filesystem (a small tmpfs,
/// filled to the last block, in a mount namespace of the test's own) fail with an error saying so,
/// and leave the previous lock, approvals and report byte for byte.
#[test]
fn lock_approve_and_report_on_a_full_filesystem_leave_the_previous_files_intact() {
    let Some(cell) = AnchoredCell::new("trajectories_full_disk") else {
        return;
    };
    let mountable = Command::new("unshare")
        .args(["-m", "sh", "-c", "mount -t tmpfs -o size=64k tmpfs /mnt"])
        .status()
        .is_ok_and(|s| s.success());
    if !mountable {
        assert!(
            std::env::var_os("ERGOCELL_REQUIRE_ANCHOR").is_none(),
            "CI must be able to mount a tmpfs in a mount namespace (root)"
        );
        // Straight to the stream: cargo test shows it without --nocapture.
        let _ = std::io::Write::write_all(
            &mut std::io::stderr(),
            b"SKIPPED: cannot mount a tmpfs here\n",
        );
        return;
    }
    let (code, out, err) = cell.ergocell(&["trajectories", "lock", "--class", "c2"]);
    assert_eq!(code, 0, "{out}{err}");
    let (code, out, err) = cell.approve("c2", ALICE, "keys/alice");
    assert_eq!(code, 0, "{out}{err}");
    common::small_recording(&cell.dir.join("rec.mcap"));
    let (code, out, err) = cell.ergocell(&["report", "rec.mcap", "--out", "report.html"]);
    assert_eq!(code, 0, "{out}{err}");

    // In a mount namespace: the cell copied onto a 4 MiB tmpfs, which is then filled.
    let script = r#"
        set -u
        mount -t tmpfs -o size=4m tmpfs "$FULL" || exit 90
        cp -r "$CELL"/. "$FULL"/ && cd "$FULL" || exit 91
        files="trajectories/locks/c2.lock.toml trajectories/approvals/c2.toml report.html"
        sha256sum $files > "$CELL/before.sha256"
        dd if=/dev/zero of=fill bs=4096 2>/dev/null
        df -k . | tail -1 | awk '{print "free kB: " $4}'
        "$BIN" trajectories lock --class c2 > lock.out 2> "$CELL/lock.err"; echo "lock exit $?"
        "$BIN" trajectories approve --class c2 --by bob@plant.example --key keys/bob > /dev/null 2> "$CELL/approve.err"; echo "approve exit $?"
        "$BIN" report rec.mcap --out report.html --force > /dev/null 2> "$CELL/report.err"; echo "report exit $?"
        sha256sum $files > "$CELL/after.sha256"
    "#;
    let full = std::env::temp_dir().join(format!("ergocell-full-{}", std::process::id()));
    std::fs::create_dir_all(&full).unwrap();
    let out = Command::new("unshare")
        .args(["-m", "sh", "-c", script])
        .env("FULL", &full)
        .env("CELL", &cell.dir)
        .env("BIN", env!("CARGO_BIN_EXE_ergocell"))
        .env("ERGOCELL_TRUST_ANCHOR_DIR", &cell.anchor)
        .output()
        .unwrap();
    let _ = std::fs::remove_dir(&full);
    let said = String::from_utf8_lossy(&out.stdout);
    assert!(
        said.contains("free kB: 0"),
        "the filesystem is full: {said}"
    );
    for (step, file) in [
        ("lock", "lock.err"),
        ("approve", "approve.err"),
        ("report", "report.err"),
    ] {
        let err = std::fs::read_to_string(cell.dir.join(file)).unwrap();
        assert!(
            !said.contains(&format!("{step} exit 0")),
            "{step} cannot succeed on a full disk: {said}{err}"
        );
        assert!(
            err.contains("No space left on device") && !err.contains("panicked"),
            "{step}: {err}"
        );
    }
    let before = std::fs::read_to_string(cell.dir.join("before.sha256")).unwrap();
    let after = std::fs::read_to_string(cell.dir.join("after.sha256")).unwrap();
    assert_eq!(
        before, after,
        "the previous lock, approvals and report are intact"
    );
    assert_eq!(before.lines().count(), 3);
}

/// An approval signed by a trusted key but dated 1970 or 2099 (a wrong clock, or a made-up entry)
/// is refused by `verify` and by the provider `run` uses, naming the date.
#[test]
fn approvals_dated_1970_or_2099_are_refused() {
    use ergocell_robot::lock::{ApprovalsFile, LockFile};
    use ergocell_robot::TrajectoryClass;
    let Some(cell) = AnchoredCell::new("trajectories_dates") else {
        return;
    };
    let (code, out, err) = cell.ergocell(&["trajectories", "lock", "--class", "c2"]);
    assert_eq!(code, 0, "{out}{err}");
    let read = |p: &str| std::fs::read_to_string(cell.dir.join(p)).unwrap();
    let trusted = ergocell_robot::TrustedSigners::parse(
        &read("config/approvers/allowed_signers"),
        &read("config/approvers/revoked_keys"),
    )
    .unwrap();
    let lock = LockFile::from_toml_str(
        TrajectoryClass::C2,
        &read("trajectories/locks/c2.lock.toml"),
    )
    .unwrap();
    let alice = ergocell_robot::signing::private_key_from_openssh(&read("keys/alice")).unwrap();
    let approvals = cell.dir.join("trajectories/approvals/c2.toml");
    std::fs::create_dir_all(approvals.parent().unwrap()).unwrap();
    for (date, why) in [
        ("1970-01-01T00:00:00Z", "before 2026-01-01"),
        ("2099-01-01T00:00:00Z", "in the future"),
    ] {
        let mut file = ApprovalsFile::default();
        file.approve(&lock, ALICE, date, &trusted, &alice).unwrap();
        std::fs::write(&approvals, file.to_toml().unwrap()).unwrap();
        // Each date on a fresh file: the witness of the one before would refuse the swap.
        forget_witness(&cell.dir);
        let (code, out, _) = cell.ergocell(&["trajectories", "verify", "--class", "c2"]);
        assert!(
            code == 1 && out.contains("c2: FAIL") && out.contains(date) && out.contains(why),
            "{out}"
        );
        let refused = cell
            .provider()
            .verify(TrajectoryClass::C2)
            .unwrap_err()
            .to_string();
        assert!(refused.contains(why), "{refused}");
    }
}

/// The lock's whole history binds its approval: a lock restored from an older copy, lock and
/// approvals restored together, and a deleted withdrawal are each refused by `verify` and by the
/// provider `run` uses, naming why; a withdrawal stops the class until it is approved anew.
#[test]
fn a_rollback_a_restored_lock_and_a_deleted_withdrawal_are_refused() {
    use ergocell_robot::TrajectoryClass;
    let Some(cell) = AnchoredCell::new("trajectories_rollback") else {
        return;
    };
    let lock_path = cell.dir.join("trajectories/locks/c2.lock.toml");
    let approvals_path = cell.dir.join("trajectories/approvals/c2.toml");
    let verify = || cell.ergocell(&["trajectories", "verify", "--class", "c2"]);
    let refused = || {
        cell.provider()
            .verify(TrajectoryClass::C2)
            .unwrap_err()
            .to_string()
    };
    let (code, out, err) = cell.ergocell(&["trajectories", "lock", "--class", "c2"]);
    assert_eq!(code, 0, "{out}{err}");
    let (code, out, err) = cell.approve("c2", ALICE, "keys/alice");
    assert_eq!(code, 0, "{out}{err}");
    let old_lock = std::fs::read(&lock_path).unwrap();
    let old_approvals = std::fs::read(&approvals_path).unwrap();
    // The class changed (a comment is enough: the trajectory file's hash is in the lock), re-locked
    // and the new lock approved.
    let spec = cell.dir.join("trajectories/c2.toml");
    let mut text = std::fs::read_to_string(&spec).unwrap();
    text.push_str("# reviewed again\n");
    std::fs::write(&spec, text).unwrap();
    let (code, out, err) = cell.ergocell(&["trajectories", "lock", "--class", "c2"]);
    assert_eq!(code, 0, "{out}{err}");
    let (code, out, err) = cell.approve("c2", BOB, "keys/bob");
    assert_eq!(code, 0, "{out}{err}");
    let (code, out, _) = verify();
    assert!(code == 0 && out.contains("c2: OK"), "{out}");
    let new_lock = std::fs::read(&lock_path).unwrap();
    let new_approvals = std::fs::read(&approvals_path).unwrap();
    // The witness lives beside the approvals, never tracked by git.
    let witness = cell.dir.join("trajectories/approvals/.witness");
    assert_eq!(
        std::fs::read_to_string(witness.join(".gitignore"))
            .unwrap()
            .lines()
            .last(),
        Some("*")
    );

    // 1. The old lock (and the old trajectory file) restored beside the current approvals.
    let new_spec = std::fs::read(&spec).unwrap();
    std::fs::write(
        &spec,
        &new_spec[..new_spec.len() - "# reviewed again\n".len()],
    )
    .unwrap();
    std::fs::write(&lock_path, &old_lock).unwrap();
    let (code, out, _) = verify();
    assert!(
        code == 1
            && out.contains("this lock was approved (entry 0, by alice@plant.example")
            && out.contains("restored from a backup or from git"),
        "{out}"
    );
    assert!(refused().contains("restored from a backup or from git"));
    // 2. Its approvals restored with it: the chain is the old one, valid in itself; the witness
    // saw two entries.
    std::fs::write(&approvals_path, &old_approvals).unwrap();
    let (code, out, _) = verify();
    assert!(
        code == 1
            && out.contains("has 1 entries, but on")
            && out.contains("it had 2")
            && out.contains("restored from an older copy"),
        "{out}"
    );
    assert!(refused().contains("restored from an older copy"));
    // Approving on top of the cut-back file is refused too (it would fork the chain).
    let (code, _, err) = cell.approve("c2", ALICE, "keys/alice");
    assert!(
        code == 1 && err.contains("restored from an older copy"),
        "{err}"
    );

    // 3. The current files back: OK. Bob withdraws: refused, saying so; run refuses the class.
    std::fs::write(&spec, &new_spec).unwrap();
    std::fs::write(&lock_path, &new_lock).unwrap();
    std::fs::write(&approvals_path, &new_approvals).unwrap();
    let (code, out, _) = verify();
    assert!(code == 0 && out.contains("c2: OK"), "{out}");
    let (code, out, err) = cell.withdraw("c2", BOB, "keys/bob");
    assert!(
        code == 0 && out.contains("WITHDRAWN by bob@plant.example"),
        "{out}{err}"
    );
    let (code, out, _) = verify();
    assert!(
        code == 1 && out.contains("its approval was withdrawn (entry 2, by bob@plant.example"),
        "{out}"
    );
    assert!(refused().contains("withdrawn"));
    let withdrawn = std::fs::read(&approvals_path).unwrap();
    // Mallory's key cannot withdraw (nor could it approve).
    let (code, _, err) = cell.withdraw("c2", BOB, "keys/mallory");
    assert!(code == 1 && err.contains("refusing to withdraw"), "{err}");
    // 4. The withdrawal deleted (the file as it was before it): the witness saw it.
    std::fs::write(&approvals_path, &new_approvals).unwrap();
    let (code, out, _) = verify();
    assert!(code == 1 && out.contains("it had 3"), "{out}");
    assert!(refused().contains("it had 3"));
    // Nothing is added on top of the cut-back file either.
    let (code, out, err) = cell.withdraw("c2", BOB, "keys/bob");
    assert!(
        code == 1 && err.contains("restored from an older copy"),
        "{out}{err}"
    );
    // 5. The withdrawal back, and the lock approved anew after review: it runs.
    std::fs::write(&approvals_path, &withdrawn).unwrap();
    let (code, out, err) = cell.approve("c2", ALICE, "keys/alice");
    assert_eq!(code, 0, "{out}{err}");
    let (code, out, _) = verify();
    assert!(code == 0 && out.contains("c2: OK"), "{out}");
    cell.provider().verify(TrajectoryClass::C2).unwrap();
    // The witness holds one line per new length seen: 1, 2, 3 and 4 entries.
    let sighted = std::fs::read_to_string(witness.join("witness.jsonl")).unwrap();
    assert_eq!(sighted.lines().count(), 4, "{sighted}");
    // 6. The whole approvals file deleted: an empty chain, where the witness saw four entries.
    std::fs::remove_file(&approvals_path).unwrap();
    let (code, out, _) = verify();
    assert!(code == 1 && out.contains("has 0 entries, but on"), "{out}");
}

/// An installed cell keeps its witness in its state folder (`ERGOCELL_STATE_DIR`), not beside the
/// approvals, and a rollback is caught from there too.
#[test]
fn the_witness_lives_in_the_state_folder_when_one_is_named() {
    let Some(cell) = AnchoredCell::new("trajectories_state_dir") else {
        return;
    };
    let state = cell.dir.join("var-lib-ergocell");
    let with_state = |args: &[&str]| {
        common::outcome(
            Command::new(env!("CARGO_BIN_EXE_ergocell"))
                .current_dir(&cell.dir)
                .env("ERGOCELL_TRUST_ANCHOR_DIR", &cell.anchor)
                .env("ERGOCELL_STATE_DIR", &state)
                .args(args),
        )
    };
    let (code, out, err) = with_state(&["trajectories", "lock", "--class", "c2"]);
    assert_eq!(code, 0, "{out}{err}");
    let approve = |by: &str, key: &str| {
        with_state(&[
            "trajectories",
            "approve",
            "--class",
            "c2",
            "--by",
            by,
            "--key",
            key,
        ])
    };
    let (code, out, err) = approve(ALICE, "keys/alice");
    assert_eq!(code, 0, "{out}{err}");
    let approvals = cell.dir.join("trajectories/approvals/c2.toml");
    let first = std::fs::read(&approvals).unwrap();
    let (code, out, err) = approve(BOB, "keys/bob");
    assert_eq!(code, 0, "{out}{err}");
    let witness = std::fs::read_to_string(state.join("witness.jsonl")).unwrap();
    assert_eq!(witness.lines().count(), 2, "{witness}");
    assert!(witness.contains("\"entries\":2"), "{witness}");
    assert!(!cell.dir.join("trajectories/approvals/.witness").exists());
    // Bob's approval deleted: caught from the state folder.
    std::fs::write(&approvals, first).unwrap();
    let (code, out, _) = with_state(&["trajectories", "verify", "--class", "c2"]);
    assert!(code == 1 && out.contains("it had 2"), "{out}");
}
