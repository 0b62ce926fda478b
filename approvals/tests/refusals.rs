//! Every refusal of docs/safety.md ("What `verify` and `run` refuse", the trust anchor, the
//! witness), staged on the in-memory cell: no disk, no root, no `ssh-keygen`. Each asserts the
//! typed reason the provider gives. (How the binary reads the anchor from the disk, with root's
//! ownership and a racing symlink, is tested beside it in `host/src/trust_anchor.rs`.)
#![allow(clippy::unwrap_used, clippy::expect_used)]

use ergocell_approvals::anchor::{NotRootAlone, TrustListError, AUTHORITY_FILE};
use ergocell_approvals::files::{AnchorFile, Ownership};
use ergocell_approvals::fixture::{self, Fixture, ALICE, APPROVED_AT, BOB};
use ergocell_approvals::ProviderError;
use ergocell_robot::authority::{AuthorityError, APPROVERS_SIGNATURE};
use ergocell_robot::signing::{self, ApprovalError, TrustedSigners};
use ergocell_robot::{RobotError, TrajectoryClass};
use std::path::Path;

const C2: TrajectoryClass = TrajectoryClass::C2;

fn now() -> i64 {
    fixture::a_day_later()
}

/// The problems of a `NotVerified` refusal.
fn problems(result: Result<ergocell_robot::ApprovedTrajectory, ProviderError>) -> Vec<RobotError> {
    match result {
        Err(ProviderError::NotVerified { failure, .. }) => {
            assert_eq!(failure.class, C2);
            failure.problems
        }
        other => panic!("not refused by verification: {other:?}"),
    }
}

fn approval_refused(problems: &[RobotError]) -> Vec<ApprovalError> {
    problems
        .iter()
        .filter_map(|p| match p {
            RobotError::ApprovalRefused { reason, .. } => Some((**reason).clone()),
            _ => None,
        })
        .collect()
}

#[test]
fn a_lock_approved_by_a_trusted_engineer_verifies_and_the_witness_records_it() {
    let f = Fixture::approved(C2).unwrap();
    let approved = f.provider(now).verify(C2).unwrap();
    assert_eq!(approved.class(), C2);
    assert_eq!(approved.approvals().len(), 1);
    assert_eq!(approved.approvals()[0].approved_by, ALICE);
    let witness = f.files.get(Path::new(fixture::WITNESS_PATH)).unwrap();
    assert_eq!(String::from_utf8(witness).unwrap().lines().count(), 1);
}

#[test]
fn a_lock_no_one_approved_is_refused() {
    let f = Fixture::new().unwrap();
    f.lock(C2).unwrap();
    let refused = f.provider(now).verify(C2);
    assert_eq!(
        refused.as_ref().err().map(ProviderError::refusal),
        Some(ergocell_approvals::Refusal::NotApproved)
    );
    let p = problems(refused);
    assert!(
        matches!(p.as_slice(), [RobotError::NotApproved { .. }]),
        "{p:?}"
    );
}

/// c2 locked and approved as alice, signed with `key` under a trust list that names `key` as alice's:
/// the signer's own list, not the cell's. The reasons the cell's list refuses it.
fn approved_as_alice_with(
    key: impl Fn(&Fixture) -> ergocell_robot::signing::PrivateKey,
) -> Vec<ApprovalError> {
    let f = Fixture::new().unwrap();
    let lock = f.lock(C2).unwrap();
    let key = key(&f);
    let their_list =
        TrustedSigners::parse(&fixture::allowed_line(ALICE, &key).unwrap(), "").unwrap();
    let mut file = f.approvals(C2).unwrap();
    file.approve(&lock, ALICE, APPROVED_AT, &their_list, &key)
        .unwrap();
    f.put_approvals(C2, &file).unwrap();
    approval_refused(&problems(f.provider(now).verify(C2)))
}

#[test]
fn a_key_the_cell_does_not_trust_is_refused() {
    // Mallory, whom the cell does not list, signs as alice.
    let refused = approved_as_alice_with(|f| f.mallory.clone());
    assert!(
        matches!(refused.as_slice(), [ApprovalError::Untrusted { .. }]),
        "{refused:?}"
    );
}

#[test]
fn a_trusted_key_under_another_engineers_name_is_refused() {
    // Bob's key, which the cell trusts as bob's, signing as alice.
    let refused = approved_as_alice_with(|f| f.bob.clone());
    assert!(
        matches!(refused.as_slice(), [ApprovalError::WrongPrincipal { .. }]),
        "{refused:?}"
    );
}

#[test]
fn an_edited_entry_is_refused() {
    let f = Fixture::approved(C2).unwrap();
    let mut file = f.approvals(C2).unwrap();
    file.approval[0].approved_at_utc = "2026-01-01T00:30:00Z".to_owned();
    f.put_approvals(C2, &file).unwrap();
    let p = problems(f.provider(now).verify(C2));
    assert!(
        approval_refused(&p).contains(&ApprovalError::Mismatch),
        "{p:?}"
    );
}

#[test]
fn a_signature_moved_onto_this_lock_from_another_is_refused() {
    let f = Fixture::new().unwrap();
    let lock = f.lock(C2).unwrap();
    // Alice signed another lock of c2; her entry is then pointed at this one.
    let mut other = lock.clone();
    other.lock_sha256 = "1".repeat(64);
    let mut file = f.approvals(C2).unwrap();
    file.approve(&other, ALICE, APPROVED_AT, &f.trusted, &f.alice)
        .unwrap();
    file.approval[0].lock_sha256.clone_from(&lock.lock_sha256);
    f.put_approvals(C2, &file).unwrap();
    let p = problems(f.provider(now).verify(C2));
    assert!(
        approval_refused(&p).contains(&ApprovalError::Mismatch),
        "{p:?}"
    );
}

#[test]
fn a_removed_entry_breaks_the_chain_and_is_refused() {
    let f = Fixture::approved(C2).unwrap();
    f.approve(C2, BOB, &f.bob.clone(), "2026-01-01T01:00:00Z")
        .unwrap();
    let mut file = f.approvals(C2).unwrap();
    file.approval.remove(0);
    assert!(file.check_chain().is_err(), "the chain is broken");
    f.put_approvals(C2, &file).unwrap();
    let p = problems(f.provider(now).verify(C2));
    // The chain's own refusal (what `check_chain` says), and nothing approved by it.
    let chain = file.check_chain().unwrap_err();
    assert!(p.contains(&chain), "the broken chain: {p:?}");
}

#[test]
fn a_withdrawn_approval_is_refused() {
    let f = Fixture::approved(C2).unwrap();
    f.withdraw(C2, BOB, &f.bob.clone(), "2026-01-01T02:00:00Z")
        .unwrap();
    let lock = f.current_lock(C2).unwrap();
    // The chain's standing: this lock's approval, withdrawn by entry 1.
    let standing = f.approvals(C2).unwrap().standing(C2);
    assert_eq!(
        standing.lock_sha256.as_deref(),
        Some(lock.lock_sha256.as_str())
    );
    assert_eq!(standing.withdrawn, Some(1));
    let p = problems(f.provider(now).verify(C2));
    assert!(
        matches!(p.as_slice(), [RobotError::NotApproved { lock_sha256, .. }] if *lock_sha256 == lock.lock_sha256),
        "{p:?}"
    );
}

#[test]
fn an_approval_by_a_key_revoked_at_the_anchor_is_refused() {
    let f = Fixture::approved(C2).unwrap();
    f.revoke_at_anchor(&signing::public_key_openssh(&f.alice).unwrap());
    let p = problems(f.provider(now).verify(C2));
    assert!(
        matches!(
            approval_refused(&p).as_slice(),
            [ApprovalError::Revoked { .. }]
        ),
        "{p:?}"
    );
}

#[test]
fn a_trust_file_edited_without_relocking_is_refused() {
    let f = Fixture::approved(C2).unwrap();
    // A new engineer added and signed by the authority, but the lock covers the old list.
    let allowed = format!(
        "{}{}",
        f.allowed_signers,
        fixture::allowed_line("carol@plant.example", &f.mallory).unwrap()
    );
    let dir = Path::new(fixture::CELL_PATH).parent().unwrap();
    f.files
        .put(dir.join(signing::ALLOWED_SIGNERS), allowed.as_str());
    f.files.put(
        dir.join(APPROVERS_SIGNATURE),
        ergocell_robot::authority::sign_approvers(&allowed, "", &f.authority).unwrap(),
    );
    let p = problems(f.provider(now).verify(C2));
    assert!(
        p.iter()
            .any(|e| matches!(e, RobotError::LockMismatch { .. })),
        "{p:?}"
    );
}

#[test]
fn approvers_edited_after_the_authority_signed_them_trust_no_one() {
    let f = Fixture::approved(C2).unwrap();
    let dir = Path::new(fixture::CELL_PATH).parent().unwrap();
    let allowed = format!(
        "{}{}",
        f.allowed_signers,
        fixture::allowed_line("mallory@plant.example", &f.mallory).unwrap()
    );
    f.files
        .put(dir.join(signing::ALLOWED_SIGNERS), allowed.as_str());
    assert_eq!(
        f.provider(now).verify(C2).err().map(|e| e.refusal()),
        Some(ergocell_approvals::Refusal::ApproversNotTrusted)
    );
    match f.provider(now).verify(C2) {
        Err(ProviderError::TrustList { cause }) => assert!(
            matches!(*cause, TrustListError::Authority(AuthorityError::Edited)),
            "{cause:?}"
        ),
        other => panic!("{other:?}"),
    }
    // No signature at all: unsigned.
    f.files.remove(&dir.join(APPROVERS_SIGNATURE));
    match f.provider(now).verify(C2) {
        Err(ProviderError::TrustList { cause }) => assert!(
            matches!(
                *cause,
                TrustListError::Authority(AuthorityError::Unsigned { keys: 3 })
            ),
            "{cause:?}"
        ),
        other => panic!("{other:?}"),
    }
}

#[test]
fn an_anchor_another_account_could_change_trusts_no_one() {
    let f = Fixture::approved(C2).unwrap();
    let path = Path::new(fixture::ANCHOR_DIR).join(AUTHORITY_FILE);
    let key = signing::public_key_openssh(&f.authority).unwrap();
    let mut chain: Vec<Ownership> = path
        .ancestors()
        .map(|p| Ownership {
            path: p.to_owned(),
            uid: 0,
            mode: 0o755,
            regular_file: p == path,
        })
        .collect();
    chain[0].uid = 1000;
    f.files.put_anchor(
        &path,
        AnchorFile {
            bytes: key.into_bytes(),
            chain,
        },
    );
    match f.provider(now).verify(C2) {
        Err(ProviderError::TrustList { cause }) => assert!(
            matches!(
                *cause,
                TrustListError::Authority(AuthorityError::NoAuthority { keys: 2, .. })
            ),
            "{cause:?}"
        ),
        other => panic!("{other:?}"),
    }
    // The rule itself names the owner.
    assert!(matches!(
        ergocell_approvals::anchor::read_root_owned(&f.files, &path),
        Err(ergocell_approvals::anchor::AnchorError::Unsafe {
            problem: NotRootAlone::Owner { uid: 1000 },
            ..
        })
    ));
}

#[test]
fn an_approval_dated_more_than_a_day_ahead_of_the_clock_is_refused() {
    fn two_days_later() -> i64 {
        fixture::a_day_later() + 2 * 86_400
    }
    let f = Fixture::new().unwrap();
    f.lock(C2).unwrap();
    f.approve(C2, ALICE, &f.alice.clone(), "2026-01-03T00:00:01Z")
        .unwrap();
    match f.provider(now).verify(C2) {
        Err(ProviderError::ApprovalTime { approver, cause }) => {
            assert_eq!(approver, ALICE);
            assert!(matches!(cause, ApprovalError::BadTime { .. }), "{cause:?}");
        }
        other => panic!("{other:?}"),
    }
    // The same file, two days later: the approval counts.
    assert!(f.provider(two_days_later).verify(C2).is_ok());
}

#[test]
fn a_withdrawal_deleted_from_the_approvals_file_is_caught_by_the_witness() {
    let f = Fixture::approved(C2).unwrap();
    let provider = f.provider(now);
    provider.verify(C2).unwrap();
    let approved_only = f.approvals(C2).unwrap();
    f.withdraw(C2, BOB, &f.bob.clone(), "2026-01-01T02:00:00Z")
        .unwrap();
    // Refused for the withdrawal; the witness saw both entries.
    assert!(matches!(
        provider.verify(C2),
        Err(ProviderError::NotVerified { .. })
    ));
    // The withdrawal deleted: the chain alone is intact again, the witness is not fooled.
    f.put_approvals(C2, &approved_only).unwrap();
    assert_eq!(
        provider.verify(C2).err().map(|e| e.refusal()),
        Some(ergocell_approvals::Refusal::RolledBack)
    );
    match provider.verify(C2) {
        Err(ProviderError::Witness { cause, .. }) => assert!(
            matches!(
                *cause,
                RobotError::RolledBack {
                    witness_line: 2,
                    ..
                }
            ),
            "{cause:?}"
        ),
        other => panic!("{other:?}"),
    }
    // So is the file deleted.
    f.files.remove(&f.layout.approvals(C2));
    match provider.verify(C2) {
        Err(ProviderError::NotVerified {
            witness: Some(w), ..
        }) => assert!(matches!(*w, ProviderError::Witness { .. }), "{w:?}"),
        other => panic!("{other:?}"),
    }
}

#[test]
fn a_witness_with_a_line_ergocell_did_not_write_refuses_every_approval() {
    let f = Fixture::approved(C2).unwrap();
    f.files.put(fixture::WITNESS_PATH, "not a sighting\n{}\n");
    assert_eq!(
        f.provider(now).verify(C2).err().map(|e| e.refusal()),
        Some(ergocell_approvals::Refusal::WitnessUnreadable)
    );
    match f.provider(now).verify(C2) {
        Err(ProviderError::Witness { cause, .. }) => assert!(
            matches!(*cause, RobotError::WitnessUnreadable { .. }),
            "{cause:?}"
        ),
        other => panic!("{other:?}"),
    }
}

#[test]
fn a_lock_older_than_the_chains_last_approval_is_refused() {
    let f = Fixture::approved(C2).unwrap();
    let old_lock = f.files.get(&f.layout.lock(C2)).unwrap();
    let old_spec = f.files.get(&f.layout.spec(C2)).unwrap();
    // The class re-locked (its file changed by a comment) and the new lock approved.
    let mut spec = old_spec.clone();
    spec.extend_from_slice(b"\n# reviewed again\n");
    f.files.put(f.layout.spec(C2), spec);
    f.lock(C2).unwrap();
    f.approve(C2, BOB, &f.bob.clone(), "2026-01-01T03:00:00Z")
        .unwrap();
    assert!(f.provider(now).verify(C2).is_ok());
    let new_hash = f.current_lock(C2).unwrap().lock_sha256;
    // The old lock and its inputs restored: approved once, superseded since.
    f.files.put(f.layout.spec(C2), old_spec);
    f.files.put(f.layout.lock(C2), old_lock);
    let old_hash = f.current_lock(C2).unwrap().lock_sha256;
    assert_ne!(old_hash, new_hash);
    // The chain's standing approval is of the newer lock; the older one is refused by its hash.
    let standing = f.approvals(C2).unwrap().standing(C2);
    assert_eq!(standing.lock_sha256.as_deref(), Some(new_hash.as_str()));
    let p = problems(f.provider(now).verify(C2));
    assert!(
        matches!(p.as_slice(), [RobotError::NotApproved { lock_sha256, .. }] if *lock_sha256 == old_hash),
        "{p:?}"
    );
}

/// Alice's approval of the current lock of c2 with `approved_by` and `at_utc` as given, signed over
/// exactly its message in `namespace`, written as the file's one entry: what ergocell's own writer
/// would refuse to make.
fn signed_as_given(f: &Fixture, approved_by: &str, at_utc: &str, namespace: &str) {
    use ergocell_robot::lock::{Approval, ApprovalsFile};
    use ergocell_robot::signing::{Action, ApprovalClaim};
    let lock = f.lock(C2).unwrap();
    let previous = "0".repeat(64);
    let claim = ApprovalClaim {
        action: Action::Approve,
        class: C2.as_str(),
        lock_sha256: &lock.lock_sha256,
        approved_by,
        approved_at_utc: at_utc,
        previous_sha256: &previous,
    };
    let message = signing::approval_message(&claim);
    let signature = f
        .alice
        .sign(namespace, ssh_key::HashAlg::Sha512, message.as_bytes())
        .unwrap()
        .to_pem(ssh_key::LineEnding::LF)
        .unwrap();
    let mut file = ApprovalsFile::default();
    file.approval.push(Approval {
        class: C2,
        action: Action::Approve,
        lock_sha256: lock.lock_sha256.clone(),
        approved_by: approved_by.to_owned(),
        approved_at_utc: at_utc.to_owned(),
        previous_sha256: previous,
        signature,
    });
    f.put_approvals(C2, &file).unwrap();
}

#[test]
fn a_signature_made_in_another_namespace_is_refused() {
    let f = Fixture::new().unwrap();
    // A git commit's signature over the same bytes.
    signed_as_given(&f, ALICE, APPROVED_AT, "git");
    let p = problems(f.provider(now).verify(C2));
    assert!(
        matches!(
            approval_refused(&p).as_slice(),
            [ApprovalError::WrongNamespace { namespace }] if namespace == "git"
        ),
        "{p:?}"
    );
}

#[test]
fn a_time_that_is_not_rfc3339_utc_or_a_name_with_control_characters_is_refused() {
    let f = Fixture::new().unwrap();
    signed_as_given(
        &f,
        ALICE,
        "2026-01-01 00:00:00",
        signing::APPROVAL_NAMESPACE,
    );
    let p = problems(f.provider(now).verify(C2));
    assert!(
        matches!(
            approval_refused(&p).as_slice(),
            [ApprovalError::BadTime { text, .. }] if text == "2026-01-01 00:00:00"
        ),
        "{p:?}"
    );
    let f = Fixture::new().unwrap();
    signed_as_given(
        &f,
        "alice@plant.example\u{1b}[2K",
        APPROVED_AT,
        signing::APPROVAL_NAMESPACE,
    );
    let p = problems(f.provider(now).verify(C2));
    assert!(
        matches!(
            approval_refused(&p).as_slice(),
            [ApprovalError::BadApprover { .. }]
        ),
        "{p:?}"
    );
}

#[test]
fn an_anchor_in_a_folder_others_can_write_or_not_a_file_trusts_no_one() {
    for (folder_mode, regular_file) in [(0o777, true), (0o755, false)] {
        let f = Fixture::approved(C2).unwrap();
        let path = Path::new(fixture::ANCHOR_DIR).join(AUTHORITY_FILE);
        let chain: Vec<Ownership> = path
            .ancestors()
            .enumerate()
            .map(|(i, p)| Ownership {
                path: p.to_owned(),
                uid: 0,
                mode: match i {
                    0 => 0o644,
                    1 => folder_mode,
                    _ => 0o755,
                },
                regular_file: i == 0 && regular_file,
            })
            .collect();
        f.files.put_anchor(
            &path,
            AnchorFile {
                bytes: signing::public_key_openssh(&f.authority)
                    .unwrap()
                    .into_bytes(),
                chain,
            },
        );
        let expected = if regular_file {
            NotRootAlone::Writable { mode: 0o777 }
        } else {
            NotRootAlone::NotRegularFile
        };
        assert!(matches!(
            ergocell_approvals::anchor::read_root_owned(&f.files, &path),
            Err(ergocell_approvals::anchor::AnchorError::Unsafe { problem, .. }) if problem == expected
        ));
        assert!(
            matches!(
                f.provider(now).verify(C2),
                Err(ProviderError::TrustList { cause })
                    if matches!(*cause, TrustListError::Authority(AuthorityError::NoAuthority { .. }))
            ),
            "{expected:?}"
        );
    }
}

#[test]
fn a_witness_that_cannot_be_read_refuses_and_one_that_cannot_be_written_is_said() {
    let f = Fixture::approved(C2).unwrap();
    f.files.fail_witness(true);
    match f.provider(now).verify(C2) {
        Err(ProviderError::Witness { cause, .. }) => assert!(
            matches!(*cause, RobotError::WitnessUnreadable { line: 0, .. }),
            "{cause:?}"
        ),
        other => panic!("{other:?}"),
    }
    // Readable but not writable: the check holds on what was read; the note says it.
    f.files.fail_witness(false);
    let notes = ergocell_approvals::witness_store::observe(
        &FailingAppend(f.files.clone()),
        Path::new(fixture::WITNESS_PATH),
        &f.layout.approvals(C2),
        C2,
        &f.approvals(C2).unwrap(),
        &f.trusted,
        now(),
    )
    .unwrap();
    assert!(
        matches!(
            notes.as_slice(),
            [ergocell_approvals::witness_store::WitnessNote::NotRecorded { .. }]
        ),
        "{notes:?}"
    );
}

/// Memory files whose witness can be read but never appended to.
#[derive(Debug)]
struct FailingAppend(ergocell_approvals::MemoryFiles);

impl ergocell_approvals::CellFiles for FailingAppend {
    fn read(
        &self,
        kind: ergocell_approvals::FileKind,
        path: &Path,
    ) -> Result<String, ergocell_approvals::FileError> {
        self.0.read(kind, path)
    }
    fn read_anchor(
        &self,
        path: &Path,
        max_bytes: u64,
        allowed: &dyn Fn(&[Ownership]) -> bool,
    ) -> Result<AnchorFile, ergocell_approvals::FileError> {
        self.0.read_anchor(path, max_bytes, allowed)
    }
    fn read_witness(&self, path: &Path) -> Result<Vec<u8>, ergocell_approvals::FileError> {
        self.0.read_witness(path)
    }
    fn append_witness(&self, path: &Path, _: &str) -> Result<(), ergocell_approvals::FileError> {
        Err(ergocell_approvals::FileError::TooLarge {
            path: path.to_owned(),
            limit: 0,
        })
    }
    fn absolute(&self, path: &Path) -> std::path::PathBuf {
        self.0.absolute(path)
    }
    fn resolved(&self, path: &Path) -> Option<std::path::PathBuf> {
        self.0.resolved(path)
    }
}
