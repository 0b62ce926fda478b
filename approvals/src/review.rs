//! What `ergocell trajectories verify` and `sign-approvers` decide and say: the verdict on one
//! class's lock and approvals (integrity, the lock against what validation produces now, the
//! approvals, their times and the witness's finding, listed together; a lock that no longer
//! validates is said alone, its approvals not looked at), and how the site authority's
//! signature over the approvers' files was checked before it is written.
//!
//! Here rather than in the binary because the same rules decide what the cell runs
//! ([`crate::provider`]); the binary reads the files, the witness and the clock, and prints these
//! strings.

use std::path::{Path, PathBuf};

use ergocell_robot::authority::{Authority, AuthorityError};
use ergocell_robot::lock::{self, ApprovedTrajectory, VerifyFailure, VerifyInputs};
use ergocell_robot::review::{revalidate, RevalidationError};
use ergocell_robot::signing::printable;
use ergocell_robot::{
    CellConfig, PlanInputs, RobotError, TrajectoryClass, TrajectorySpec, TrustedSigners,
};

use crate::anchor::AnchorError;
use crate::provider::check_approval_times;

/// What `verify` needs of one class besides the lock: the inputs it was planned from (to re-plan),
/// the witness's finding on the approvals file, and the clock.
#[derive(Debug, Clone)]
pub struct ClassCheck<'a> {
    pub inputs: VerifyInputs<'a>,
    pub cell: &'a CellConfig,
    pub spec: &'a TrajectorySpec,
    /// The witness's refusal of the approvals file, if it refused it (its notes are the caller's).
    pub witness: Result<(), RobotError>,
    pub now_unix: i64,
}

/// `verify`'s verdict on one class.
#[derive(Debug, Clone, PartialEq)]
pub enum Verdict {
    /// There is no lock file.
    NoLock {
        class: TrajectoryClass,
        lock_path: PathBuf,
    },
    /// The lock is whole but is not what validation produces from the current inputs.
    NotValidated {
        class: TrajectoryClass,
        cause: RevalidationError,
    },
    /// Locked, approved, every approval signed by a trusted key and bearing a possible time.
    Approved(Box<ApprovedTrajectory>),
    /// Whole, and nothing wrong but the missing approval (`--allow-unapproved`).
    NotApproved(VerifyFailure),
    /// Every problem found.
    Failed(VerifyFailure),
}

impl Verdict {
    /// The verdict on a class without a lock file at `lock_path`.
    pub fn no_lock(class: TrajectoryClass, lock_path: &Path) -> Self {
        Self::NoLock {
            class,
            lock_path: lock_path.to_owned(),
        }
    }

    /// Checks one class: a lock whose integrity holds must hold what validation produces now;
    /// then the full verification, the approvals' times and the witness's finding, every problem
    /// in one list. With `allow_unapproved`, a class whose only problems are missing approvals
    /// passes as [`Verdict::NotApproved`].
    pub fn of(check: ClassCheck<'_>, allow_unapproved: bool) -> Self {
        let class = check.inputs.class;
        if let Ok(lock) = lock::verify_integrity(&check.inputs) {
            let plan = PlanInputs {
                model: check.inputs.model,
                cell: check.cell,
                spec: check.spec,
                hashes: check.inputs.current_inputs,
            };
            if let Err(cause) = revalidate(&plan, &lock) {
                return Self::NotValidated { class, cause };
            }
        }
        let verified = lock::verify(&check.inputs).and_then(|approved| {
            check_approval_times(&approved, check.now_unix)
                .map(|()| approved)
                .map_err(|why| VerifyFailure {
                    class,
                    problems: vec![RobotError::Config {
                        reason: why.to_string(),
                    }],
                })
        });
        // The witness's refusal joins the others (a forged entry is also one it did not see).
        let verified = match (verified, check.witness) {
            (verified, Ok(())) => verified,
            (Ok(_), Err(e)) => Err(VerifyFailure {
                class,
                problems: vec![e],
            }),
            (Err(mut failure), Err(e)) => {
                failure.problems.push(e);
                Err(failure)
            }
        };
        match verified {
            Ok(approved) => Self::Approved(Box::new(approved)),
            Err(failure) if allow_unapproved && only_unapproved(&failure) => {
                Self::NotApproved(failure)
            }
            Err(failure) => Self::Failed(failure),
        }
    }

    /// Whether the class passes `verify` (approved, or only unapproved when that is allowed).
    pub fn passes(&self) -> bool {
        matches!(self, Self::Approved(_) | Self::NotApproved(_))
    }

    /// What `verify` prints of the class: a headline, then each problem on a `  - ` line.
    pub fn text(&self) -> String {
        let problems = |headline: String, failure: &VerifyFailure| -> String {
            failure
                .problems
                .iter()
                .fold(headline, |text, p| format!("{text}\n  - {p}"))
        };
        match self {
            Self::NoLock { class, lock_path } => format!(
                "{class}: FAIL\n  - no lock file {} (run `ergocell trajectories lock --class {class}`)",
                lock_path.display()
            ),
            Self::NotValidated { class, cause } => format!("{class}: FAIL\n  - {cause}"),
            Self::Approved(approved) => approved_text(approved),
            Self::NotApproved(failure) => problems(
                format!(
                    "{}: INTEGRITY OK, NOT APPROVED — the controller will refuse to run it",
                    failure.class
                ),
                failure,
            ),
            Self::Failed(failure) => problems(format!("{}: FAIL", failure.class), failure),
        }
    }
}

/// Whether every problem is a missing approval (vacuously so for none).
fn only_unapproved(failure: &VerifyFailure) -> bool {
    failure
        .problems
        .iter()
        .all(|p| matches!(p, RobotError::NotApproved { .. }))
}

/// `{class}: OK — lock_sha256 … — approved by <name> at <time> (signature verified), …`, the
/// names and times as a file holds them, escaped.
fn approved_text(approved: &ApprovedTrajectory) -> String {
    let names: Vec<String> = approved
        .approvals()
        .iter()
        .map(|a| {
            format!(
                "{} at {} (signature verified)",
                printable(&a.approved_by),
                printable(&a.approved_at_utc)
            )
        })
        .collect();
    format!(
        "{}: OK — lock_sha256 {} — approved by {}",
        approved.class(),
        approved.lock().lock_sha256,
        names.join(", ")
    )
}

/// `verify`'s first line when the approvers' files are not trusted (`why`).
pub fn untrusted_approvers_text(why: &str) -> String {
    format!(
        "approvers: NOT TRUSTED — {why}\n  (no approval counts until the site's approvers authority \
         signs these files)"
    )
}

/// How the authority's signature over the approvers' files was checked before it was written.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum SignatureCheck {
    /// Against the authority installed in `anchor_dir`, whose keys are `fingerprints`.
    Checked {
        anchor_dir: PathBuf,
        fingerprints: String,
    },
    /// Not checked: no authority is installed here (`missing` does not exist).
    NotInstalled { missing: PathBuf },
}

/// A signature over the approvers' files ready to be written: how it was checked, and how many of
/// the approvers' keys it makes count.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ApproversSigned {
    pub check: SignatureCheck,
    pub usable_keys: usize,
}

/// Why `sign-approvers` writes no signature.
#[derive(Debug, Clone, thiserror::Error)]
pub enum SignApproversError {
    /// The installed authority refuses the signature.
    #[error("{cause}\nrefusing to write the signature")]
    Refused { cause: AuthorityError },
    /// The installed authority cannot be used (not root's alone, unreadable, not keys).
    #[error("{cause}\nrefusing to write the signature")]
    Anchor { cause: AnchorError },
    /// The approvers' files do not parse.
    #[error(transparent)]
    Approvers(RobotError),
}

impl ApproversSigned {
    /// Checks `signature` over the approvers' files (`allowed`, `revoked`) against the authority
    /// loaded from `anchor_dir`: a signature it refuses is never written. With no authority
    /// installed there, the signature cannot be checked and is written as it is, saying so.
    pub fn check(
        authority: Result<Authority, AnchorError>,
        anchor_dir: &Path,
        allowed: &str,
        revoked: &str,
        signature: &str,
    ) -> Result<Self, SignApproversError> {
        match authority {
            Ok(authority) => {
                let trusted = authority
                    .verify(allowed, revoked, signature)
                    .map_err(|cause| SignApproversError::Refused { cause })?;
                Ok(Self {
                    check: SignatureCheck::Checked {
                        anchor_dir: anchor_dir.to_owned(),
                        fingerprints: authority.fingerprints(),
                    },
                    usable_keys: trusted.usable_keys(),
                })
            }
            Err(AnchorError::Missing(missing)) => Ok(Self {
                check: SignatureCheck::NotInstalled { missing },
                usable_keys: TrustedSigners::parse(allowed, revoked)
                    .map_err(SignApproversError::Approvers)?
                    .usable_keys(),
            }),
            Err(cause) => Err(SignApproversError::Anchor { cause }),
        }
    }

    /// What `sign-approvers` prints once the signature is written to `path`.
    pub fn text(&self, path: &Path) -> String {
        let checked = match &self.check {
            SignatureCheck::Checked {
                anchor_dir,
                fingerprints,
            } => format!(
                "checked against the site's approvers authority in {} ({fingerprints})",
                anchor_dir.display()
            ),
            SignatureCheck::NotInstalled { missing } => format!(
                "NOT checked: no approvers authority is installed here ({} does not exist); the \
                 cell trusts these approvers only if its authority holds the signing key",
                missing.display()
            ),
        };
        format!(
            "approvers signed: {} ({} key(s) trusted, revoked ones not counted; {checked})",
            path.display(),
            self.usable_keys
        )
    }
}

#[cfg(test)]
mod tests {
    // Test helpers panic on purpose: a panic is the failure report.
    #![allow(clippy::unwrap_used, clippy::expect_used)]

    use super::*;
    use crate::fixture::{self, Fixture, ALICE};
    use ergocell_robot::authority;
    use ergocell_robot::signing::key_from_seed;
    use ergocell_robot::{InputHashes, RobotModel, TrustFiles};

    const C2: TrajectoryClass = TrajectoryClass::C2;

    fn not_approved(class: TrajectoryClass) -> RobotError {
        RobotError::NotApproved {
            class: class.to_string(),
            lock_sha256: "ab".repeat(32),
            detail: "none for this hash".to_owned(),
        }
    }

    #[test]
    fn failures_list_every_problem_under_their_headline() {
        let failure = VerifyFailure {
            class: C2,
            problems: vec![
                not_approved(C2),
                RobotError::Config {
                    reason: "late".to_owned(),
                },
            ],
        };
        let sha = "ab".repeat(32);
        assert_eq!(
            Verdict::Failed(failure.clone()).text(),
            format!(
                "c2: FAIL\n  - c2: no approval for lock sha256 {sha} (none for this hash)\n  - \
                 invalid configuration: late"
            )
        );
        let unapproved = VerifyFailure {
            class: C2,
            problems: vec![not_approved(C2)],
        };
        assert_eq!(
            Verdict::NotApproved(unapproved.clone()).text(),
            format!(
                "c2: INTEGRITY OK, NOT APPROVED — the controller will refuse to run it\n  - c2: \
                 no approval for lock sha256 {sha} (none for this hash)"
            )
        );
        assert!(only_unapproved(&unapproved) && !only_unapproved(&failure));
        let no_lock = Verdict::no_lock(C2, Path::new("trajectories/locks/c2.lock.toml"));
        assert!(!no_lock.passes() && !Verdict::Failed(failure).passes());
        assert!(Verdict::NotApproved(unapproved).passes());
        assert_eq!(
            no_lock.text(),
            "c2: FAIL\n  - no lock file trajectories/locks/c2.lock.toml (run `ergocell \
             trajectories lock --class c2`)"
        );
        assert_eq!(
            untrusted_approvers_text("unsigned"),
            "approvers: NOT TRUSTED — unsigned\n  (no approval counts until the site's approvers \
             authority signs these files)"
        );
    }

    /// The fixture's c2, locked and approved by alice: OK; unapproved it passes only when allowed;
    /// the witness's refusal fails even an approved class. (Each verdict re-plans c2.)
    #[test]
    fn the_verdict_joins_the_lock_the_approvals_and_the_witness() {
        let f = Fixture::approved(C2).unwrap();
        let cell = CellConfig::from_toml_str(fixture::CELL).unwrap();
        let model = RobotModel::from_urdf_str(
            fixture::URDF,
            &cell.robot.base_link,
            &cell.robot.flange_link,
        )
        .unwrap();
        let spec_text = fixture::SPECS[1].1;
        let spec = TrajectorySpec::from_toml_str(spec_text).unwrap();
        let hashes = InputHashes::new(
            spec_text.as_bytes(),
            fixture::URDF.as_bytes(),
            &cell,
            TrustFiles {
                allowed_signers: f.allowed_signers.as_bytes(),
                revoked_keys: b"",
            },
            env!("CARGO_PKG_VERSION"),
        );
        let lock = f.current_lock(C2).unwrap();
        let lock_toml = lock.to_toml().unwrap();
        let approvals = f.approvals(C2).unwrap().to_toml().unwrap();
        let verdict = |approvals: Option<&str>, witness, allow_unapproved| {
            let check = ClassCheck {
                inputs: VerifyInputs {
                    class: C2,
                    lock_toml: &lock_toml,
                    current_inputs: &hashes,
                    model: &model,
                    approvals_toml: approvals,
                    trusted: &f.trusted,
                },
                cell: &cell,
                spec: &spec,
                witness,
                now_unix: fixture::a_day_later(),
            };
            Verdict::of(check, allow_unapproved)
        };
        let approved = verdict(Some(&approvals), Ok(()), false);
        assert_eq!(
            approved.text(),
            format!(
                "c2: OK — lock_sha256 {} — approved by {ALICE} at {} (signature verified)",
                lock.lock_sha256,
                fixture::APPROVED_AT
            )
        );
        let strict = verdict(None, Ok(()), false);
        assert!(matches!(strict, Verdict::Failed(_)) && !strict.passes());
        let lenient = verdict(None, Ok(()), true);
        assert!(matches!(lenient, Verdict::NotApproved(_)) && lenient.passes());
        let unreadable = RobotError::WitnessUnreadable {
            line: 0,
            why: "test".to_owned(),
        };
        assert_eq!(
            verdict(Some(&approvals), Err(unreadable.clone()), true),
            Verdict::Failed(VerifyFailure {
                class: C2,
                problems: vec![unreadable],
            })
        );
    }

    #[test]
    fn a_signature_is_checked_against_the_installed_authority_or_said_unchecked() {
        let site = key_from_seed(&[90; 32], "site");
        let other = key_from_seed(&[91; 32], "other");
        let public = ergocell_robot::signing::public_key_openssh(&site).unwrap();
        let authority = || Authority::parse(&public, "").unwrap();
        let alice = key_from_seed(&[1; 32], "alice");
        let allowed = fixture::allowed_line(ALICE, &alice).unwrap();
        let signed = authority::sign_approvers(&allowed, "", &site).unwrap();
        let anchor = Path::new("/etc/ergocell");
        let ok = ApproversSigned::check(Ok(authority()), anchor, &allowed, "", &signed).unwrap();
        assert_eq!(ok.usable_keys, 1);
        assert_eq!(
            ok.text(Path::new("config/approvers/approvers.sig")),
            format!(
                "approvers signed: config/approvers/approvers.sig (1 key(s) trusted, revoked ones \
                 not counted; checked against the site's approvers authority in /etc/ergocell ({}))",
                authority().fingerprints()
            )
        );
        // A signature by another key is refused and never written.
        let forged = authority::sign_approvers(&allowed, "", &other).unwrap();
        let e = ApproversSigned::check(Ok(authority()), anchor, &allowed, "", &forged).unwrap_err();
        assert!(matches!(
            e,
            SignApproversError::Refused {
                cause: AuthorityError::NotAuthority { .. }
            }
        ));
        assert!(
            e.to_string().ends_with("\nrefusing to write the signature"),
            "{e}"
        );
        // No authority installed: written unchecked, saying so.
        let missing = anchor.join("approvers-authority.pub");
        let unchecked = ApproversSigned::check(
            Err(AnchorError::Missing(missing.clone())),
            anchor,
            &allowed,
            "",
            &forged,
        )
        .unwrap();
        assert_eq!(
            unchecked.check,
            SignatureCheck::NotInstalled {
                missing: missing.clone()
            }
        );
        assert_eq!(
            unchecked.text(Path::new("a.sig")),
            "approvers signed: a.sig (1 key(s) trusted, revoked ones not counted; NOT checked: no \
             approvers authority is installed here (/etc/ergocell/approvers-authority.pub does not \
             exist); the cell trusts these approvers only if its authority holds the signing key)"
        );
        // Any other anchor problem refuses.
        let unsafe_anchor = AnchorError::NotText { path: missing };
        assert!(matches!(
            ApproversSigned::check(Err(unsafe_anchor), anchor, &allowed, "", &signed),
            Err(SignApproversError::Anchor { .. })
        ));
    }
}
