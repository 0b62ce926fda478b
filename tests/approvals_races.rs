//! Two engineers at once, with real parallel processes: `approve ∥ approve` and `approve ∥
//! withdraw` on one class, round after round. Every command that announced an entry as recorded
//! has it in the approvals file, the chain and the witness stay valid, and a killed write's
//! temporary file is cleaned up. (Before the approvals were locked, 15 rounds of two parallel
//! approves announced 30 entries and the file held 17.)
#![allow(clippy::unwrap_used, clippy::expect_used)]

use std::process::{Command, Stdio};

mod common;
use common::{AnchoredCell, ALICE, BOB};

/// The number of entries in the class's approvals file.
fn entries(cell: &AnchoredCell) -> usize {
    let path = cell.dir.join("trajectories/approvals/c2.toml");
    let text = std::fs::read_to_string(path).unwrap_or_default();
    ergocell_robot::lock::ApprovalsFile::from_toml_str(&text)
        .unwrap()
        .approval
        .len()
}

/// Starts `trajectories <command> --class c2 --by <by> --key <key>` without waiting.
fn start(cell: &AnchoredCell, command: &str, by: &str, key: &str) -> std::process::Child {
    Command::new(env!("CARGO_BIN_EXE_ergocell"))
        .current_dir(&cell.dir)
        .env("ERGOCELL_TRUST_ANCHOR_DIR", &cell.anchor)
        .args([
            "trajectories",
            command,
            "--class",
            "c2",
            "--by",
            by,
            "--key",
            key,
        ])
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap()
}

#[test]
fn parallel_approvals_and_withdrawals_never_lose_an_announced_entry() {
    let Some(cell) = AnchoredCell::new("approvals_races") else {
        return;
    };
    let (code, out, err) = cell.ergocell(&["trajectories", "lock", "--class", "c2"]);
    assert_eq!(code, 0, "{out}{err}");
    let mut announced = 0;
    for round in 0..50_u32 {
        // Even rounds: both approve. Odd rounds: alice approves while bob withdraws his approval.
        let second = if round.is_multiple_of(2) {
            "approve"
        } else {
            "withdraw"
        };
        let a = start(&cell, "approve", ALICE, "keys/alice");
        let b = start(&cell, second, BOB, "keys/bob");
        for (who, child) in [("approve", a), (second, b)] {
            let out = child.wait_with_output().unwrap();
            let stdout = String::from_utf8_lossy(&out.stdout);
            if out.status.success() {
                assert!(stdout.contains("recorded in"), "{who}: {stdout}");
                announced += 1;
            }
        }
        assert_eq!(
            entries(&cell),
            announced,
            "round {round}: an announced entry is lost"
        );
    }
    assert!(announced >= 50, "{announced}");
    // The chain and the witness agree with the file: verify reads it without a rollback.
    let (_, out, err) = cell.ergocell(&["trajectories", "verify", "--class", "c2"]);
    assert!(
        !out.contains("rolled back") && !err.contains("restored from an older copy"),
        "{out}{err}"
    );
    assert!(out.contains("c2: OK"), "{out}{err}");

    // A write killed mid-way leaves `.c2.toml.partial-<pid>`: the next approve removes it, saying so.
    let stale = cell
        .dir
        .join("trajectories/approvals/.c2.toml.partial-99999");
    std::fs::write(&stale, "half an approvals file").unwrap();
    let (code, out, err) = cell.approve("c2", ALICE, "keys/alice");
    assert_eq!(code, 0, "{out}{err}");
    assert!(!stale.exists());
    assert!(err.contains("stopped mid-write"), "{err}");
}

/// `approve --signed` with a time `verify` refuses (two days ahead, 9999, before 2026) used to be
/// announced as recorded and then blocked the class; now nothing is written.
#[test]
fn a_signed_approval_with_a_time_verify_refuses_is_not_written() {
    let Some(cell) = AnchoredCell::new("approvals_signed_time") else {
        return;
    };
    let (code, out, err) = cell.ergocell(&["trajectories", "lock", "--class", "c2"]);
    assert_eq!(code, 0, "{out}{err}");
    let lock_text =
        std::fs::read_to_string(cell.dir.join("trajectories/locks/c2.lock.toml")).unwrap();
    let lock =
        ergocell_robot::LockFile::from_toml_str(ergocell_robot::TrajectoryClass::C2, &lock_text)
            .unwrap();
    let key_text = std::fs::read_to_string(cell.dir.join("keys/alice")).unwrap();
    let key = ergocell_robot::signing::private_key_from_openssh(&key_text).unwrap();
    // The clock verify reads (the binary's wall clock).
    let now = ergocell::trust_anchor::now_unix();
    let two_days_ahead = ergocell_robot::signing::rfc3339_utc(now + 2 * 86_400).unwrap();
    for at in [
        two_days_ahead.as_str(),
        "9999-12-31T00:00:00Z",
        "2020-01-01T00:00:00Z",
    ] {
        let file = ergocell_robot::lock::ApprovalsFile::default();
        let message = file.next_message(&lock, ALICE, at).unwrap();
        let signature = key
            .sign(
                ergocell_robot::signing::APPROVAL_NAMESPACE,
                ssh_key::HashAlg::Sha512,
                message.as_bytes(),
            )
            .unwrap()
            .to_pem(ssh_key::LineEnding::LF)
            .unwrap();
        let msg_path = cell.dir.join("approval.txt");
        std::fs::write(&msg_path, &message).unwrap();
        std::fs::write(cell.dir.join("approval.txt.sig"), signature).unwrap();
        let (code, out, err) = cell.ergocell(&[
            "trajectories",
            "approve",
            "--class",
            "c2",
            "--signed",
            "approval.txt",
        ]);
        assert_ne!(code, 0, "{at}: {out}{err}");
        assert!(!out.contains("recorded in"), "{at}: {out}");
        assert!(err.contains("nothing was written"), "{at}: {err}");
        assert_eq!(entries(&cell), 0, "{at}");
    }
}

/// The cell's own account in [`with_state`]: `nobody`, unprivileged. It owns the cell folder and
/// the state folder and runs every command, as on a real cell; the trust anchor stays root's.
const CELL_ACCOUNT: u32 = 65534;

/// Hands `paths` (recursively) to [`CELL_ACCOUNT`]. False when `setpriv` (util-linux) is missing,
/// so the commands cannot run as that account; CI (ERGOCELL_REQUIRE_ANCHOR) must have it.
fn hand_to_cell_account(paths: &[&std::path::Path]) -> bool {
    fn chown_all(p: &std::path::Path) {
        std::os::unix::fs::lchown(p, Some(CELL_ACCOUNT), Some(CELL_ACCOUNT)).unwrap();
        if p.is_dir() && !p.is_symlink() {
            for entry in std::fs::read_dir(p).unwrap() {
                chown_all(&entry.unwrap().path());
            }
        }
    }
    if Command::new("setpriv").arg("--version").output().is_err() {
        assert!(
            std::env::var_os("ERGOCELL_REQUIRE_ANCHOR").is_none(),
            "ERGOCELL_REQUIRE_ANCHOR is set but setpriv is missing: the cell's account cannot be tried"
        );
        return false;
    }
    for p in paths {
        chown_all(p);
    }
    true
}

/// Runs ergocell in the cell with the anchor folder `anchor` and the state folder `state` as the
/// cell's own, unprivileged account ([`CELL_ACCOUNT`]) when `unprivileged`: (exit code, stdout,
/// stderr).
fn with_state(
    cell: &AnchoredCell,
    anchor: &std::path::Path,
    state: &std::path::Path,
    unprivileged: bool,
    args: &[&str],
) -> (i32, String, String) {
    let bin = env!("CARGO_BIN_EXE_ergocell");
    let mut command = if unprivileged {
        let mut c = Command::new("setpriv");
        c.arg(format!("--reuid={CELL_ACCOUNT}"))
            .arg(format!("--regid={CELL_ACCOUNT}"))
            .args(["--clear-groups", "--"])
            .arg(bin)
            .env("HOME", state);
        c
    } else {
        Command::new(bin)
    };
    common::outcome(
        command
            .current_dir(&cell.dir)
            .env("ERGOCELL_TRUST_ANCHOR_DIR", anchor)
            .env("ERGOCELL_STATE_DIR", state)
            .args(args),
    )
}

/// The approvals folder swapped for a symlink to a folder holding the older copy (before the
/// withdrawal): the witness keyed its records by the resolved path, so it had never seen that
/// file and `verify` said "c2: OK". One appended byte in the witness switched it off the same way.
/// Every command runs as the cell's own unprivileged account, which owns the cell and the witness's
/// folder (the account the attack was made from); the anchor is root's.
#[test]
fn a_symlinked_approvals_folder_or_a_poisoned_witness_does_not_revive_a_withdrawal() {
    let Some(cell) = AnchoredCell::new("approvals_symlink") else {
        return;
    };
    let state = cell.dir.join("state");
    std::fs::create_dir_all(&state).unwrap();
    let unprivileged = hand_to_cell_account(&[&cell.dir]);
    if !unprivileged {
        let _ = std::io::Write::write_all(
            &mut std::io::stderr(),
            b"note: setpriv missing: the commands run as root, not as the cell's account\n",
        );
    }
    let run = |args: &[&str]| with_state(&cell, &cell.anchor, &state, unprivileged, args);
    let (code, out, err) = run(&["trajectories", "lock", "--class", "c2"]);
    assert_eq!(code, 0, "{out}{err}");
    let sign = |command: &str| {
        run(&[
            "trajectories",
            command,
            "--class",
            "c2",
            "--by",
            ALICE,
            "--key",
            "keys/alice",
        ])
    };
    assert_eq!(sign("approve").0, 0);
    if unprivileged {
        // The witness was written by the cell's account, not by root.
        let owner = std::os::unix::fs::MetadataExt::uid(
            &std::fs::metadata(state.join("witness.jsonl")).unwrap(),
        );
        assert_eq!(owner, CELL_ACCOUNT);
    }
    let approvals = cell.dir.join("trajectories/approvals");
    let older = std::fs::read(approvals.join("c2.toml")).unwrap();
    assert_eq!(sign("withdraw").0, 0);
    let (code, out, _) = run(&["trajectories", "verify", "--class", "c2"]);
    assert_ne!(code, 0, "withdrawn: {out}");

    // The symlinked folder.
    std::fs::rename(&approvals, cell.dir.join("trajectories/approvals-real")).unwrap();
    let old_dir = cell.dir.join("trajectories/approvals-old");
    std::fs::create_dir_all(&old_dir).unwrap();
    std::fs::write(old_dir.join("c2.toml"), &older).unwrap();
    std::os::unix::fs::symlink("approvals-old", &approvals).unwrap();
    let (code, out, err) = run(&["trajectories", "verify", "--class", "c2"]);
    assert_ne!(code, 0, "{out}{err}");
    assert!(!out.contains("c2: OK"), "{out}");
    assert!(
        format!("{out}{err}").contains("restored from an older copy"),
        "{out}{err}"
    );

    // The witness poisoned with one appended byte: refused, never noted and passed.
    std::fs::remove_file(&approvals).unwrap();
    std::fs::rename(cell.dir.join("trajectories/approvals-real"), &approvals).unwrap();
    std::fs::write(approvals.join("c2.toml"), &older).unwrap();
    let witness = state.join("witness.jsonl");
    let mut bytes = std::fs::read(&witness).unwrap();
    bytes.extend(b"\xff\n");
    std::fs::write(&witness, bytes).unwrap();
    let (code, out, err) = run(&["trajectories", "verify", "--class", "c2"]);
    assert_ne!(code, 0, "{out}{err}");
    assert!(!out.contains("c2: OK"), "{out}");
    assert!(
        format!("{out}{err}").contains("the witness of the approvals cannot be read"),
        "{out}{err}"
    );
}

/// The trust-anchor race, as the hostile account made it: the cell's own unprivileged account
/// points `ERGOCELL_TRUST_ANCHOR_DIR` at a folder of its own whose `approvers-authority.pub` is a
/// symlink that **a separate process of that account** (a perl loop: a new symlink renamed over
/// the old, as fast as the two system calls go) flips between root's key and a key of its own. The
/// account has added its approver (mallory) to the allowed signers and signed them with its own
/// authority, and mallory's approval of c2 is on file (recorded while root had, for the control,
/// installed that authority: `approve` passes then, so the anchor check alone refuses below).
/// 50 rounds of `approve` (mallory again) and `verify` run as that account while the flipper runs:
/// each passes only if the account's key is admitted, and none may. Checking the anchor through one
/// open of the path and reading it through another let `approve` through on the 2nd try.
#[test]
fn an_anchor_symlink_flipped_by_another_process_never_admits_a_self_made_authority() {
    use std::os::unix::fs::PermissionsExt as _;
    /// Kills the flipper and removes the account's folders however the test ends.
    struct Cleanup(Option<std::process::Child>, Vec<std::path::PathBuf>);
    impl Drop for Cleanup {
        fn drop(&mut self) {
            if let Some(child) = self.0.as_mut() {
                let _ = child.kill();
                let _ = child.wait();
            }
            for dir in &self.1 {
                let _ = std::fs::remove_dir_all(dir);
            }
        }
    }
    let Some(cell) = AnchoredCell::new("anchor_flip") else {
        return;
    };
    let state = cell.dir.join("state");
    std::fs::create_dir_all(&state).unwrap();
    // The account's own authority, and its approver among the allowed signers, signed by that
    // authority (with no anchor installed the signature is written unchecked); then the lock.
    let keys = cell.dir.join("keys");
    common::key_file(&keys, "evil", 66, "evil");
    let allowed_path = cell.dir.join("config/approvers/allowed_signers");
    let mut allowed = std::fs::read_to_string(&allowed_path).unwrap();
    allowed.push_str(&common::key_file(&keys, "mallory", 3, common::MALLORY));
    std::fs::write(&allowed_path, &allowed).unwrap();
    let nowhere = cell.dir.join("no-anchor-here");
    let (code, out, err) = with_state(
        &cell,
        &nowhere,
        &state,
        false,
        &["trajectories", "sign-approvers", "--key", "keys/evil"],
    );
    assert_eq!(code, 0, "{out}{err}");
    let (code, out, err) = cell.ergocell(&["trajectories", "lock", "--class", "c2"]);
    assert_eq!(code, 0, "{out}{err}");

    let pid = std::process::id();
    let theirs = std::env::temp_dir().join(format!("ergocell-test-anchor-theirs-{pid}"));
    let installed = std::env::temp_dir().join(format!("ergocell-test-anchor-installed-{pid}"));
    let mut cleanup = Cleanup(None, vec![theirs.clone(), installed.clone()]);
    let evil = ergocell_robot::signing::key_from_seed(&[66; 32], "evil");
    let evil_pub = ergocell_robot::signing::public_key_openssh(&evil).unwrap() + "\n";
    for dir in [&theirs, &installed] {
        let _ = std::fs::remove_dir_all(dir);
        std::fs::create_dir_all(dir).unwrap();
        std::fs::set_permissions(dir, std::fs::Permissions::from_mode(0o755)).unwrap();
    }
    std::fs::write(theirs.join("evil.pub"), &evil_pub).unwrap();
    let roots = cell.anchor.join("approvers-authority.pub");
    let link = theirs.join("approvers-authority.pub");
    std::os::unix::fs::symlink(&roots, &link).unwrap();
    // root installs the account's key (the control's anchor)
    let key = installed.join("approvers-authority.pub");
    std::fs::write(&key, &evil_pub).unwrap();
    std::fs::set_permissions(&key, std::fs::Permissions::from_mode(0o644)).unwrap();
    if !hand_to_cell_account(&[&cell.dir, &theirs]) {
        let _ = std::io::Write::write_all(
            &mut std::io::stderr(),
            b"SKIPPED: setpriv missing: the race needs a second account\n",
        );
        return;
    }
    let run =
        |anchor: &std::path::Path, args: &[&str]| with_state(&cell, anchor, &state, true, args);
    let approve: &[&str] = &[
        "trajectories",
        "approve",
        "--class",
        "c2",
        "--by",
        common::MALLORY,
        "--key",
        "keys/mallory",
    ];
    let verify: &[&str] = &["trajectories", "verify", "--class", "c2"];
    // The control: under the installed key both pass.
    let (code, out, err) = run(&installed, approve);
    assert_eq!(code, 0, "{out}{err}");
    let (code, out, err) = run(&installed, verify);
    assert_eq!(code, 0, "{out}{err}");
    assert_eq!(entries(&cell), 1);

    cleanup.0 = Some(
        Command::new("setpriv")
            .arg(format!("--reuid={CELL_ACCOUNT}"))
            .arg(format!("--regid={CELL_ACCOUNT}"))
            .args(["--clear-groups", "--", "perl", "-e"])
            .arg(
                "my ($link, @to) = @ARGV; my $tmp = \"$link.flip\"; \
                 for (my $k = 0; ; $k++) { unlink $tmp; \
                 rename($tmp, $link) if symlink($to[$k % 2], $tmp); }",
            )
            .arg(&link)
            .arg("evil.pub")
            .arg(&roots)
            .stdout(Stdio::null())
            .stderr(Stdio::null())
            .spawn()
            .unwrap(),
    );
    // The rounds start once the link has been seen on both keys (the flipper is running).
    let (mut saw_evil, mut saw_root) = (false, false);
    for _ in 0..2000 {
        match std::fs::read_link(&link) {
            Ok(target) if target == std::path::Path::new("evil.pub") => saw_evil = true,
            Ok(target) if target == roots => saw_root = true,
            _ => {}
        }
        if saw_evil && saw_root {
            break;
        }
        std::thread::sleep(std::time::Duration::from_millis(10));
    }
    assert!(
        saw_evil && saw_root,
        "the link was not seen on both keys within 20 s"
    );
    for round in 0..50 {
        let (code, out, err) = run(&theirs, approve);
        assert_ne!(code, 0, "round {round}: approve passed: {out}{err}");
        let (code, out, err) = run(&theirs, verify);
        assert_ne!(code, 0, "round {round}: verify passed: {out}{err}");
    }
    let flipping = cleanup
        .0
        .as_mut()
        .is_some_and(|c| c.try_wait().ok().flatten().is_none());
    assert!(flipping, "the flipping process stopped early");
    assert_eq!(entries(&cell), 1, "an approval was written in the race");
}
