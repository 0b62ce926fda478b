//! Signed approvals (issue 16): each way of forging or moving an approval is refused with a message
//! that names it; a valid one verifies. Keys come from fixed seeds.

// Test helpers panic on purpose: a panic is the failure report.
#![allow(clippy::unwrap_used, clippy::expect_used)]

mod common;

use ergocell_robot::lock::{self, Approval, ApprovalsFile, LockFile, VerifyInputs};
use ergocell_robot::signing::{self, ApprovalClaim, TrustedSigners};
use ergocell_robot::{plan_and_validate, InputHashes, PlanInputs, TrajectoryClass};

const CLASS: TrajectoryClass = TrajectoryClass::C2;

struct Fixture {
    s: common::Shipped,
    t: common::Approvers,
    lock: LockFile,
    lock_toml: String,
    current: InputHashes,
}

fn fixture() -> Fixture {
    let s = common::shipped();
    let t = common::signers();
    let text = common::spec_text(CLASS);
    let current = common::hashes_with_trust(&s, &text, &t);
    let spec = common::spec(CLASS);
    let locked = plan_and_validate(&PlanInputs {
        model: &s.model,
        cell: &s.cell,
        spec: &spec,
        hashes: &current,
    })
    .unwrap()
    .into_locked()
    .unwrap();
    let lock = LockFile::from_locked(&locked);
    let lock_toml = lock.to_toml().unwrap();
    Fixture {
        s,
        t,
        lock,
        lock_toml,
        current,
    }
}

fn verify(f: &Fixture, approvals: &str, trusted: &TrustedSigners) -> Result<(), String> {
    lock::verify(&VerifyInputs {
        class: CLASS,
        lock_toml: &f.lock_toml,
        current_inputs: &f.current,
        model: &f.s.model,
        approvals_toml: Some(approvals),
        trusted,
    })
    .map(|_| ())
    .map_err(|e| e.to_string())
}

fn approved(f: &Fixture) -> ApprovalsFile {
    let mut file = ApprovalsFile::default();
    file.approve(
        &f.lock,
        common::ALICE,
        "2026-12-01T10:00:00Z",
        &f.t.trusted,
        &f.t.alice,
    )
    .unwrap();
    file
}

/// [`approved`], then withdrawn by bob at 12:00.
fn withdrawn(f: &Fixture) -> ApprovalsFile {
    let mut file = approved(f);
    file.withdraw(
        CLASS,
        common::BOB,
        "2026-12-01T12:00:00Z",
        &f.t.trusted,
        &f.t.bob,
    )
    .unwrap();
    file
}

/// `key`'s armored SSH signature over `message` in `namespace`, as `ssh-keygen -Y sign` makes one.
fn ssh_sign(key: &ssh_key::PrivateKey, namespace: &str, message: &str) -> String {
    key.sign(namespace, ssh_key::HashAlg::Sha512, message.as_bytes())
        .unwrap()
        .to_pem(ssh_key::LineEnding::LF)
        .unwrap()
}

/// Re-chains `entries` (each `previous_sha256` the hash of the one before), as a forger with no key
/// but a text editor and `sha256sum` could.
fn rechain(mut entries: Vec<Approval>) -> String {
    let mut previous = "0".repeat(64);
    for e in &mut entries {
        e.previous_sha256.clone_from(&previous);
        previous = e.entry_sha256();
    }
    ApprovalsFile { approval: entries }.to_toml().unwrap()
}

#[test]
fn a_valid_signed_approval_verifies_and_its_message_names_every_signed_field() {
    let f = fixture();
    let file = approved(&f);
    verify(&f, &file.to_toml().unwrap(), &f.t.trusted).unwrap();
    let m = file.approval[0].message();
    for field in [
        "class: c2",
        &format!("lock_sha256: {}", f.lock.lock_sha256),
        "approved_by: alice@plant.example",
        "approved_at_utc: 2026-12-01T10:00:00Z",
        &format!("previous_sha256: {}", "0".repeat(64)),
    ] {
        assert!(m.contains(field), "{m}");
    }
    assert_eq!(
        signing::parse_approval_message(&m).unwrap().1[2],
        common::ALICE
    );
}

#[test]
fn an_untrusted_key_cannot_approve_nor_sign_as_a_trusted_name() {
    let f = fixture();
    let err = ApprovalsFile::default()
        .approve(
            &f.lock,
            common::ALICE,
            "2026-12-01T10:00:00Z",
            &f.t.trusted,
            &f.t.mallory,
        )
        .unwrap_err();
    assert!(
        err.to_string().contains("is not a trusted approver's key"),
        "{err}"
    );
    // Mallory signs with her own key under a trust list that includes her, then the entry is
    // checked against the cell's: refused, naming her key's fingerprint.
    let with_mallory = TrustedSigners::parse(
        &format!(
            "{}{}",
            f.t.allowed_signers,
            common::allowed_line(common::ALICE, &f.t.mallory)
        ),
        "",
    )
    .unwrap();
    let mut file = ApprovalsFile::default();
    file.approve(
        &f.lock,
        common::ALICE,
        "2026-12-01T10:00:00Z",
        &with_mallory,
        &f.t.mallory,
    )
    .unwrap();
    let err = verify(&f, &file.to_toml().unwrap(), &f.t.trusted).unwrap_err();
    let fp = signing::fingerprint(f.t.mallory.public_key());
    assert!(
        err.contains("is not a trusted approver's key") && err.contains(&fp),
        "{err}"
    );
}

#[test]
fn a_signature_over_another_locks_hash_is_refused() {
    let f = fixture();
    // Alice's genuine approval of another lock (another hash), moved onto this lock.
    let mut other = f.lock.clone();
    other.lock_sha256 = "ab".repeat(32);
    let mut file = ApprovalsFile::default();
    file.approve(
        &other,
        common::ALICE,
        "2026-12-01T10:00:00Z",
        &f.t.trusted,
        &f.t.alice,
    )
    .unwrap();
    let mut moved = file.approval.clone();
    moved[0].lock_sha256.clone_from(&f.lock.lock_sha256);
    let err = verify(&f, &rechain(moved), &f.t.trusted).unwrap_err();
    assert!(
        err.contains("the signature does not match the entry"),
        "{err}"
    );
    // Left as it was, it approves the other hash only.
    let err = verify(&f, &file.to_toml().unwrap(), &f.t.trusted).unwrap_err();
    assert!(err.contains("none for this hash"), "{err}");
}

#[test]
fn edited_and_removed_entries_are_refused() {
    let f = fixture();
    let mut file = approved(&f);
    file.approve(
        &f.lock,
        common::BOB,
        "2026-12-01T11:00:00Z",
        &f.t.trusted,
        &f.t.bob,
    )
    .unwrap();
    verify(&f, &file.to_toml().unwrap(), &f.t.trusted).unwrap();
    // The last entry edited and the chain recomputed: its signature no longer matches.
    let mut edited = file.approval.clone();
    edited[1].approved_at_utc = "2026-12-01T12:00:00Z".to_owned();
    let err = verify(&f, &rechain(edited), &f.t.trusted).unwrap_err();
    assert!(
        err.contains("entry 1") && err.contains("does not match"),
        "{err}"
    );
    // The first entry removed: the chain breaks at the next.
    let removed = ApprovalsFile {
        approval: file.approval[1..].to_vec(),
    };
    let err = verify(&f, &removed.to_toml().unwrap(), &f.t.trusted).unwrap_err();
    assert!(err.contains("hash chain broken at entry 0"), "{err}");
    // Both removed: not approved.
    let err = verify(&f, "", &f.t.trusted).unwrap_err();
    assert!(err.contains("no approval for lock sha256"), "{err}");
}

#[test]
fn a_revoked_key_and_a_foreign_namespace_are_refused() {
    let f = fixture();
    let file = approved(&f).to_toml().unwrap();
    let alice_pub = signing::public_key_openssh(&f.t.alice).unwrap();
    let revoked = TrustedSigners::parse(&f.t.allowed_signers, &alice_pub).unwrap();
    let err = verify(&f, &file, &revoked).unwrap_err();
    assert!(err.contains("is revoked"), "{err}");

    // A genuine SSH signature by alice over the same bytes, but made for git (`-n git`).
    let mut entries = approved(&f).approval;
    let sig = ssh_sign(&f.t.alice, "git", &entries[0].message());
    entries[0].signature = sig;
    let err = verify(&f, &rechain(entries), &f.t.trusted).unwrap_err();
    assert!(err.contains("namespace `git`"), "{err}");
}

#[test]
fn a_time_that_is_not_rfc3339_utc_is_refused_at_approve_and_at_verify() {
    let f = fixture();
    let err = ApprovalsFile::default()
        .approve(
            &f.lock,
            common::ALICE,
            "not a time at all",
            &f.t.trusted,
            &f.t.alice,
        )
        .unwrap_err();
    assert!(err.to_string().contains("not an RFC 3339 time"), "{err}");
    let claim = ApprovalClaim {
        action: signing::Action::Approve,
        class: "c2",
        lock_sha256: &f.lock.lock_sha256,
        approved_by: common::ALICE,
        approved_at_utc: "2026-12-01T10:00:00+01:00",
        previous_sha256: &"0".repeat(64),
    };
    let sig = f.t.trusted.sign(&claim, &f.t.alice).unwrap();
    assert!(matches!(
        f.t.trusted.verify(&claim, &sig).unwrap_err(),
        signing::ApprovalError::BadTime { why, .. } if why == "is not in UTC"
    ));
    // One instant, one spelling: RFC 3339's other forms (a newline or `t` for the `T`, fractions,
    // `+00:00`) are refused, so no time carries a line break into a message or a terminal.
    for other in [
        "2026-12-01\n10:00:00Z",
        "2026-12-01t10:00:00z",
        "2026-12-01T10:00:00.5Z",
        "2026-12-01T10:00:00+00:00",
    ] {
        let e = signing::check_utc_time(other).unwrap_err();
        assert!(matches!(e, signing::ApprovalError::BadTime { .. }), "{e}");
        assert!(!e.to_string().contains('\n'), "{e}");
    }
    signing::check_utc_time("2026-12-01T10:00:00Z").unwrap();
}

#[test]
fn the_trust_file_refuses_what_it_cannot_honour_exactly() {
    let t = common::signers();
    let line = common::allowed_line(common::ALICE, &t.alice);
    for (edit, expect) in [
        (
            line.replace(common::ALICE, "*@plant.example"),
            "contains one of",
        ),
        (
            line.replace("namespaces=", "cert-authority,namespaces="),
            "option `cert-authority`",
        ),
        (
            line.replace(signing::APPROVAL_NAMESPACE, "git"),
            "does not list",
        ),
        (line.replace("ssh-ed25519", "ssh-rsa"), "only ssh-ed25519"),
        (line.replace("AAAA", "!!!!"), "not an OpenSSH public key"),
        (
            line.replace(
                &format!("\"{}\"", signing::APPROVAL_NAMESPACE),
                &format!("\"!{0},{0}\"", signing::APPROVAL_NAMESPACE),
            ),
            "patterns are not supported",
        ),
        (
            line.replace(common::ALICE, "j\u{fc}rgen@plant.example"),
            "non-ASCII",
        ),
    ] {
        let err = TrustedSigners::parse(&edit, "").unwrap_err();
        assert!(err.to_string().contains(expect), "{edit}: {err}");
    }
    // Two principals on one key, and a quoted namespace list with several entries, are honoured.
    let two = line
        .replace(common::ALICE, "alice@plant.example,a.smith@plant.example")
        .replace(
            &format!("\"{}\"", signing::APPROVAL_NAMESPACE),
            &format!("\"git,{}\"", signing::APPROVAL_NAMESPACE),
        );
    let parsed = TrustedSigners::parse(&two, "").unwrap();
    assert_eq!(parsed.keys()[0].principals.len(), 2);
    // Tabs separate fields as spaces do; the comment may hold anything, a quote included.
    let tabbed = format!(
        "{}\tcomment with a \" quote",
        line.trim_end().replacen(' ', "\t", 1)
    );
    assert_eq!(TrustedSigners::parse(&tabbed, "").unwrap().keys().len(), 1);
    assert_eq!(
        signing::printable("Alice\nc3: OK\u{1b}[31m\u{202e}"),
        "Alice\\nc3: OK\\u{1b}[31m\\u{202e}"
    );
}

#[test]
fn the_shipped_trust_file_trusts_no_one_and_parses() {
    let (allowed, revoked) = common::shipped_trust();
    let t = TrustedSigners::parse(&allowed, &revoked).unwrap();
    assert!(t.keys().is_empty());
}

/// Approvals dated 1970 or 2099 are refused: before signed approvals existed, or in the future of
/// the verifying clock beyond a few minutes' skew; the edges are exact.
#[test]
fn an_approval_dated_1970_or_2099_is_refused() {
    use ergocell_robot::signing::{check_approval_time, APPROVAL_CLOCK_SKEW_S};
    let now = 1_796_000_000; // 2026-12-1x
    for (text, ok) in [
        ("1970-01-01T00:00:00Z", false),
        ("2025-12-31T23:59:59Z", false),
        ("2026-01-01T00:00:00Z", true),
        ("2099-01-01T00:00:00Z", false),
    ] {
        assert_eq!(check_approval_time(text, now).is_ok(), ok, "{text}");
    }
    let at = |t: i64| ergocell_robot::signing::rfc3339_utc(t).unwrap();
    assert!(check_approval_time(&at(now + APPROVAL_CLOCK_SKEW_S), now).is_ok());
    let e = check_approval_time(&at(now + APPROVAL_CLOCK_SKEW_S + 1), now).unwrap_err();
    assert!(e.to_string().contains("in the future"), "{e}");
    let e = check_approval_time("1970-01-01T00:00:00Z", now).unwrap_err();
    assert!(e.to_string().contains("before 2026-01-01"), "{e}");
}

/// `file` with an approval of another lock (another hash) appended, by bob.
fn with_later_lock_approved(f: &Fixture, mut file: ApprovalsFile) -> ApprovalsFile {
    let mut later = f.lock.clone();
    later.lock_sha256 = "cd".repeat(32);
    file.approve(
        &later,
        common::BOB,
        "2026-12-02T09:00:00Z",
        &f.t.trusted,
        &f.t.bob,
    )
    .unwrap();
    file
}

#[test]
fn a_lock_older_than_the_chains_last_approval_is_refused_as_superseded() {
    let f = fixture();
    // The lock was approved, then re-locked and the new lock approved: the old lock file, restored
    // from git or a backup beside the current approvals, must not run on its old approval.
    let file = with_later_lock_approved(&f, approved(&f));
    let err = verify(&f, &file.to_toml().unwrap(), &f.t.trusted).unwrap_err();
    assert!(
        err.contains("this lock was approved (entry 0, by alice@plant.example")
            && err.contains("a later approval (entry 1, by bob@plant.example")
            && err.contains(&"cd".repeat(32))
            && err.contains("restored from a backup or from git"),
        "{err}"
    );
    // Reviewed and approved again, the restored lock runs: the chain's last approval decides.
    let mut file = file;
    file.approve(
        &f.lock,
        common::ALICE,
        "2026-12-02T10:00:00Z",
        &f.t.trusted,
        &f.t.alice,
    )
    .unwrap();
    let approved = lock::verify(&VerifyInputs {
        class: CLASS,
        lock_toml: &f.lock_toml,
        current_inputs: &f.current,
        model: &f.s.model,
        approvals_toml: Some(&file.to_toml().unwrap()),
        trusted: &f.t.trusted,
    })
    .unwrap();
    // Only the approval since the lock was approved anew is listed, not the superseded one.
    assert_eq!(approved.approvals().len(), 1);
    assert_eq!(
        approved.approvals()[0].approved_at_utc,
        "2026-12-02T10:00:00Z"
    );
}

#[test]
fn a_withdrawn_approval_stops_the_lock_until_it_is_approved_anew() {
    let f = fixture();
    let mut file = approved(&f);
    // Any trusted approver may withdraw; the withdrawal names the standing lock by itself.
    let w = file
        .withdraw(
            CLASS,
            common::BOB,
            "2026-12-01T12:00:00Z",
            &f.t.trusted,
            &f.t.bob,
        )
        .unwrap()
        .clone();
    assert_eq!(w.lock_sha256, f.lock.lock_sha256);
    assert!(w
        .message()
        .starts_with("ergocell trajectory withdrawal v1\n"));
    assert!(w.message().contains("withdrawn_by: bob@plant.example\n"));
    let text = file.to_toml().unwrap();
    assert!(text.contains("action = \"withdraw\""), "{text}");
    let err = verify(&f, &text, &f.t.trusted).unwrap_err();
    assert!(
        err.contains(
            "its approval was withdrawn (entry 1, by bob@plant.example at 2026-12-01T12:00:00Z)"
        ),
        "{err}"
    );
    // Withdrawing twice is refused, and so is withdrawing where nothing was approved.
    let err = file
        .clone()
        .withdraw(
            CLASS,
            common::BOB,
            "2026-12-01T12:05:00Z",
            &f.t.trusted,
            &f.t.bob,
        )
        .unwrap_err();
    assert!(err.to_string().contains("already withdrawn"), "{err}");
    let err = ApprovalsFile::default()
        .withdraw(
            CLASS,
            common::BOB,
            "2026-12-01T12:05:00Z",
            &f.t.trusted,
            &f.t.bob,
        )
        .unwrap_err();
    assert!(err.to_string().contains("nothing to withdraw"), "{err}");
    // An untrusted key cannot withdraw either (a forged stop is refused, not obeyed silently).
    assert!(approved(&f)
        .withdraw(
            CLASS,
            common::BOB,
            "2026-12-01T12:00:00Z",
            &f.t.trusted,
            &f.t.mallory
        )
        .is_err());
    // Approved anew, it runs.
    file.approve(
        &f.lock,
        common::ALICE,
        "2026-12-01T13:00:00Z",
        &f.t.trusted,
        &f.t.alice,
    )
    .unwrap();
    verify(&f, &file.to_toml().unwrap(), &f.t.trusted).unwrap();
}

#[test]
fn a_withdrawal_cannot_be_turned_into_an_approval_nor_forged() {
    let f = fixture();
    let file = withdrawn(&f);
    // The withdrawal's `action` edited back to an approval (chain recomputed): its signature is
    // over a withdrawal message, so the entry is refused and the lock with it.
    let mut entries = file.approval.clone();
    entries[1].action = signing::Action::Approve;
    let err = verify(&f, &rechain(entries), &f.t.trusted).unwrap_err();
    assert!(
        err.contains("entry 1") && err.contains("does not match"),
        "{err}"
    );
    // A withdrawal entry with mallory's signature: refused, naming it.
    let mut entries = approved(&f).approval;
    let mut forged = entries[0].clone();
    forged.action = signing::Action::Withdraw;
    forged.signature = ssh_sign(&f.t.mallory, signing::APPROVAL_NAMESPACE, &forged.message());
    entries.push(forged);
    let err = verify(&f, &rechain(entries), &f.t.trusted).unwrap_err();
    assert!(
        err.contains("entry 1") && err.contains("not a trusted approver"),
        "{err}"
    );
}

#[test]
fn a_withdrawal_signed_outside_ergocell_is_appended_and_an_approval_message_is_not() {
    let f = fixture();
    let mut file = approved(&f);
    let message = file
        .next_withdrawal_message(CLASS, common::ALICE, "2026-12-01T12:00:00Z")
        .unwrap();
    let (action, fields) = signing::parse_approval_message(&message).unwrap();
    assert_eq!(action, signing::Action::Withdraw);
    let sig = ssh_sign(&f.t.alice, signing::APPROVAL_NAMESPACE, &message);
    // The withdrawal message offered as an approval is refused, saying what it is.
    let err = file
        .clone()
        .append_signed(&f.lock, &message, &sig, &f.t.trusted)
        .unwrap_err();
    assert!(
        err.to_string()
            .contains("it is a withdrawal message, not an approval message"),
        "{err}"
    );
    file.append_signed_withdrawal(CLASS, &message, &sig, &f.t.trusted)
        .unwrap();
    assert_eq!(file.approval[1].approved_by, fields[2]);
    let err = verify(&f, &file.to_toml().unwrap(), &f.t.trusted).unwrap_err();
    assert!(err.contains("withdrawn"), "{err}");
}

mod witness {
    use super::*;
    use ergocell_robot::witness::Witness;

    const PATH: &str = "/cell/trajectories/approvals/c2.toml";

    /// The witness after seeing `file` (empty witness, one line recorded).
    fn seen(f: &Fixture, file: &ApprovalsFile) -> String {
        Witness::default()
            .sighting_line(PATH, CLASS, file, &f.t.trusted, "2026-12-01T12:00:00Z")
            .unwrap()
    }

    #[test]
    fn a_deleted_last_entry_or_an_older_copy_is_refused() {
        let f = fixture();
        let file = withdrawn(&f);
        let witness = Witness::parse(seen(&f, &file).as_bytes()).unwrap();
        assert!(witness.unreadable.is_empty(), "{:?}", witness.unreadable);
        witness.check(PATH, CLASS, &file).unwrap();
        // The withdrawal deleted: the chain alone is intact and the lock would verify again...
        let cut = ApprovalsFile {
            approval: file.approval[..1].to_vec(),
        };
        cut.check_chain().unwrap();
        verify(&f, &cut.to_toml().unwrap(), &f.t.trusted).unwrap();
        // ...but the witness saw two entries.
        let err = witness.check(PATH, CLASS, &cut).unwrap_err().to_string();
        assert!(
            err.contains("has 1 entries, but on 2026-12-01T12:00:00Z it had 2")
                && err.contains("witness line 1"),
            "{err}"
        );
        // A same-length chain that ends otherwise (an older copy with other entries) is refused
        // too; a longer one that keeps what was seen passes, and only then is a new line due.
        let other = with_later_lock_approved(&f, approved(&f));
        assert_eq!(other.approval.len(), 2);
        assert!(witness.check(PATH, CLASS, &other).is_err());
        let mut longer = file.clone();
        longer
            .approve(
                &f.lock,
                common::ALICE,
                "2026-12-01T13:00:00Z",
                &f.t.trusted,
                &f.t.alice,
            )
            .unwrap();
        witness.check(PATH, CLASS, &longer).unwrap();
        assert!(witness
            .sighting_line(PATH, CLASS, &file, &f.t.trusted, "2026-12-01T13:00:00Z")
            .is_none());
        let next = witness
            .sighting_line(PATH, CLASS, &longer, &f.t.trusted, "2026-12-01T13:00:00Z")
            .unwrap();
        assert!(next.contains("\"entries\":3"), "{next}");
        // A forged entry appended (no trusted key signed it) is not witnessed: removing it later
        // is no rollback.
        let mut forged = longer.clone();
        let mut entry = forged.approval[2].clone();
        entry.previous_sha256 = forged.head_sha256();
        entry.approved_at_utc = "2026-12-01T14:00:00Z".to_owned();
        forged.approval.push(entry);
        forged.check_chain().unwrap();
        assert!(witness
            .sighting_line(PATH, CLASS, &forged, &f.t.trusted, "2026-12-01T14:00:00Z")
            .unwrap()
            .contains("\"entries\":3"));
        // Sightings of another file or class do not bind this one.
        assert!(witness.check("/elsewhere/c2.toml", CLASS, &cut).is_ok());
        assert!(witness.check(PATH, TrajectoryClass::C3, &cut).is_ok());
    }

    #[test]
    fn a_torn_append_is_passed_over_and_said_and_the_good_lines_still_bind() {
        let f = fixture();
        let file = approved(&f);
        let line = seen(&f, &file);
        let torn = &line[..line.len() / 2];
        // A crash cut the last append short (no newline): passed over, said.
        let witness = Witness::parse(format!("{line}{torn}").as_bytes()).unwrap();
        assert_eq!(witness.unreadable.len(), 1, "{:?}", witness.unreadable);
        assert!(witness.unreadable[0].starts_with("line 2: an append cut short"));
        assert!(witness
            .check(PATH, CLASS, &ApprovalsFile::default())
            .is_err());
        // The next append went on after the fragment: that line's sighting still binds.
        let witness = Witness::parse(format!("{torn}{line}").as_bytes()).unwrap();
        assert!(witness.unreadable[0].starts_with("line 1: begins with an append cut short"));
        assert!(witness
            .check(PATH, CLASS, &ApprovalsFile::default())
            .is_err());
    }

    /// One appended byte (`printf '\\377\\n' >> witness.jsonl`) made the whole witness unreadable,
    /// which switched it off: every such line now refuses the witness, naming the line.
    #[test]
    fn a_line_ergocell_did_not_write_refuses_the_witness() {
        let f = fixture();
        let file = approved(&f);
        let line = seen(&f, &file);
        for bad in [
            b"\xff\n".to_vec(),
            b"not json\n".to_vec(),
            b"{\"format\":\"other/1\"}\n".to_vec(),
        ] {
            let mut bytes = line.clone().into_bytes();
            bytes.extend(&bad);
            let err = Witness::parse(&bytes).unwrap_err();
            assert!(
                matches!(
                    err,
                    ergocell_robot::RobotError::WitnessUnreadable { line: 2, .. }
                ),
                "{err}"
            );
        }
    }
}
