//! Every refusal of docs/safety.md ("What `verify` and `run` refuse", the trust anchor, the
//! witness), staged on the in-memory cell: no disk, no root, no `ssh-keygen`. Each asserts the
//! typed reason the provider gives.
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
    let p = problems(f.provider(now).verify(C2));
    assert!(
        matches!(p.as_slice(), [RobotError::NotApproved { .. }]),
        "{p:?}"
    );
}

#[test]
fn a_key_the_cell_does_not_trust_is_refused() {
    let f = Fixture::new().unwrap();
    let lock = f.lock(C2).unwrap();
    // Mallory signs as alice, under a trust list of her own making.
    let forged =
        TrustedSigners::parse(&fixture::allowed_line(ALICE, &f.mallory).unwrap(), "").unwrap();
    let mut file = f.approvals(C2).unwrap();
    file.approve(&lock, ALICE, APPROVED_AT, &forged, &f.mallory)
        .unwrap();
    f.put_approvals(C2, &file).unwrap();
    let p = problems(f.provider(now).verify(C2));
    assert!(
        matches!(
            approval_refused(&p).as_slice(),
            [ApprovalError::Untrusted { .. }]
        ),
        "{p:?}"
    );
}

#[test]
fn a_trusted_key_under_another_engineers_name_is_refused() {
    let f = Fixture::new().unwrap();
    let lock = f.lock(C2).unwrap();
    // Bob's key, signing as alice: a list that says so is bob's own, not the cell's.
    let as_alice =
        TrustedSigners::parse(&fixture::allowed_line(ALICE, &f.bob).unwrap(), "").unwrap();
    let mut file = f.approvals(C2).unwrap();
    file.approve(&lock, ALICE, APPROVED_AT, &as_alice, &f.bob)
        .unwrap();
    f.put_approvals(C2, &file).unwrap();
    let p = problems(f.provider(now).verify(C2));
    assert!(
        matches!(
            approval_refused(&p).as_slice(),
            [ApprovalError::WrongPrincipal { .. }]
        ),
        "{p:?}"
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
    f.put_approvals(C2, &file).unwrap();
    let p = problems(f.provider(now).verify(C2));
    assert!(
        p.iter().any(|e| matches!(e, RobotError::Config { .. })),
        "the broken chain: {p:?}"
    );
}

#[test]
fn a_withdrawn_approval_is_refused() {
    let f = Fixture::approved(C2).unwrap();
    f.withdraw(C2, BOB, &f.bob.clone(), "2026-01-01T02:00:00Z")
        .unwrap();
    let p = problems(f.provider(now).verify(C2));
    assert!(
        matches!(p.as_slice(), [RobotError::NotApproved { .. }]),
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
    // The old lock and its inputs restored: approved once, superseded since.
    f.files.put(f.layout.spec(C2), old_spec);
    f.files.put(f.layout.lock(C2), old_lock);
    let p = problems(f.provider(now).verify(C2));
    assert!(
        matches!(p.as_slice(), [RobotError::NotApproved { .. }]),
        "{p:?}"
    );
}
