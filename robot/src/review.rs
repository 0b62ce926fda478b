//! What the safety engineer's review commands (`ergocell trajectories validate`, `lock`, `approve`,
//! `withdraw`) decide and say of a class: the re-validation that ties a lock to what validation
//! produces from the current inputs, the sign-off an approve or a withdraw appends to the approvals
//! file, why one is refused, and the lines each command prints.
//!
//! It lives beside [`crate::lock`] and [`crate::validate`] because it is their vocabulary: the binary
//! reads the files, the keys and the clock, and prints these strings; nothing here does I/O.

use std::path::{Path, PathBuf};

use crate::config::TrajectoryClass;
use crate::lock::{self, Approval, ApprovalsFile, LockFile, VerifyFailure};
use crate::signing::{self, Action, ApprovalError, PrivateKey, TrustedSigners};
use crate::validate::{plan_and_validate, PlanInputs, Validation};
use crate::RobotError;

/// Why a lock is not what validation produces from the current inputs.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum RevalidationError {
    /// Validation of the current inputs fails, or rejects the trajectory.
    #[error("validation of the current inputs fails: {cause}")]
    Validation { cause: RobotError },
    /// The lock's samples, limits or input hashes differ from validation's
    /// ([`lock::check_matches_validation`]).
    #[error("{cause}")]
    Differs { cause: RobotError },
}

/// Re-plans the class from `inputs` and checks that `lock` holds exactly that trajectory: a lock
/// edited by hand (and re-hashed) is refused even though its hashes agree.
pub fn revalidate(inputs: &PlanInputs<'_>, lock: &LockFile) -> Result<(), RevalidationError> {
    let validated = plan_and_validate(inputs)
        .and_then(Validation::into_locked)
        .map_err(|cause| RevalidationError::Validation { cause })?;
    lock::check_matches_validation(lock, &validated)
        .map_err(|cause| RevalidationError::Differs { cause })
}

/// The classes as `validate`, `lock` and `verify` name them in their summaries: `c1, c3`.
pub fn class_list(classes: &[TrajectoryClass]) -> String {
    classes
        .iter()
        .map(ToString::to_string)
        .collect::<Vec<_>>()
        .join(", ")
}

/// The classes a command works on: the one asked for, or all of them.
pub fn selected(class: Option<TrajectoryClass>) -> Vec<TrajectoryClass> {
    class.map_or_else(|| TrajectoryClass::ALL.to_vec(), |c| vec![c])
}

/// One class through `trajectories validate`: the validation, or why there is none.
#[derive(Debug, Clone)]
pub struct ClassValidation {
    pub class: TrajectoryClass,
    pub outcome: Result<Validation, RobotError>,
}

impl ClassValidation {
    /// Plans and validates the class ([`plan_and_validate`]).
    pub fn plan(class: TrajectoryClass, inputs: &PlanInputs<'_>) -> Self {
        Self {
            class,
            outcome: plan_and_validate(inputs),
        }
    }

    /// Whether the class is accepted (planned, and every check passed).
    pub fn accepted(&self) -> bool {
        matches!(&self.outcome, Ok(v) if v.report.accepted)
    }

    /// The text `validate` prints (a line of its own, then a blank line after a refusal).
    pub fn text(&self) -> String {
        match &self.outcome {
            Ok(v) => v.report.to_string(),
            Err(e) => format!(
                "Trajectory validation — class {} — REJECTED\n  {e}\n",
                self.class
            ),
        }
    }

    /// The entry of `validate --json`: `{"class": …, "report": …}` (SI units), or
    /// `{"class": …, "error": "…"}`.
    pub fn json(&self) -> Result<serde_json::Value, serde_json::Error> {
        let mut entry = serde_json::Map::new();
        entry.insert("class".to_owned(), serde_json::to_value(self.class)?);
        match &self.outcome {
            Ok(v) => entry.insert("report".to_owned(), serde_json::to_value(&v.report)?),
            Err(e) => entry.insert("error".to_owned(), serde_json::Value::String(e.to_string())),
        };
        Ok(serde_json::Value::Object(entry))
    }
}

/// What `lock` prints for a lock it wrote at `path`, and what to do next.
pub fn locked_text(lock: &LockFile, path: &Path) -> String {
    let class = lock.class;
    format!(
        "{class}: locked {} (lock_sha256 {})\n    review it, then: ergocell trajectories approve \
         --class {class} --by <principal> --key <ssh key>",
        path.display(),
        lock.lock_sha256
    )
}

/// Why `lock` wrote nothing: the classes that did not lock.
pub fn not_locked_text(failed: &[TrajectoryClass]) -> String {
    format!(
        "not locked: {} — no lock file was written (every lock is as it was)",
        class_list(failed)
    )
}

/// `lock`'s note when the approvers' files are not trusted (`why`).
pub fn untrusted_lock_note(why: &str) -> String {
    format!(
        "note: the approvers' files are not trusted, so no approval of these locks will count \
         until they are: {why}"
    )
}

/// What an `approve` or a `withdraw` signs: the approval of a lock (which passed
/// [`lock::verify_integrity`] and [`revalidate`]), or the withdrawal of a class's standing approval.
#[derive(Debug, Clone, Copy)]
pub enum SignOff<'a> {
    Approve(&'a LockFile),
    Withdraw(TrajectoryClass),
}

impl SignOff<'_> {
    /// The entry's action.
    pub fn action(&self) -> Action {
        match self {
            Self::Approve(_) => Action::Approve,
            Self::Withdraw(_) => Action::Withdraw,
        }
    }

    /// The class whose approvals file takes the entry.
    pub fn class(&self) -> TrajectoryClass {
        match self {
            Self::Approve(lock) => lock.class,
            Self::Withdraw(class) => *class,
        }
    }

    /// The command: `approve` or `withdraw`.
    pub fn verb(&self) -> &'static str {
        verb(self.action())
    }

    /// Appends the entry by `principal` at `at_utc`, signed here with `key`
    /// ([`ApprovalsFile::approve`], [`ApprovalsFile::withdraw`]).
    pub fn sign<'f>(
        &self,
        file: &'f mut ApprovalsFile,
        principal: &str,
        at_utc: &str,
        trusted: &TrustedSigners,
        key: &PrivateKey,
    ) -> Result<&'f Approval, Refused> {
        match self {
            Self::Approve(lock) => file.approve(lock, principal, at_utc, trusted, key),
            Self::Withdraw(class) => file.withdraw(*class, principal, at_utc, trusted, key),
        }
        .map_err(|cause| self.refused(cause))
    }

    /// The exact message the entry by `principal` at `at_utc` would sign, for `ssh-keygen -Y sign`.
    pub fn message(
        &self,
        file: &ApprovalsFile,
        principal: &str,
        at_utc: &str,
    ) -> Result<String, RobotError> {
        match self {
            Self::Approve(lock) => file.next_message(lock, principal, at_utc),
            Self::Withdraw(class) => file.next_withdrawal_message(*class, principal, at_utc),
        }
    }

    /// Appends the entry of `message`, signed outside ergocell with `signature`
    /// ([`ApprovalsFile::append_signed`], [`ApprovalsFile::append_signed_withdrawal`]).
    pub fn append_signed<'f>(
        &self,
        file: &'f mut ApprovalsFile,
        message: &str,
        signature: &str,
        trusted: &TrustedSigners,
    ) -> Result<&'f Approval, Refused> {
        match self {
            Self::Approve(lock) => file.append_signed(lock, message, signature, trusted),
            Self::Withdraw(class) => {
                file.append_signed_withdrawal(*class, message, signature, trusted)
            }
        }
        .map_err(|cause| self.refused(cause))
    }

    /// What the two-step flow's first step says after writing the message to `out`.
    pub fn message_written_text(&self, out: &Path) -> String {
        let class = self.class();
        format!(
            "{class}: wrote the {} message to {} — sign it with\n  ssh-keygen -Y sign -f <your key> \
             -n {} {}\nthen: ergocell trajectories {} --class {class} --signed {}",
            self.action(),
            out.display(),
            signing::APPROVAL_NAMESPACE,
            out.display(),
            self.verb(),
            out.display()
        )
    }

    fn refused(&self, cause: RobotError) -> Refused {
        Refused::Entry {
            cause: Box::new(cause),
            verb: self.verb(),
        }
    }
}

/// The command that writes entries of `action`: `approve` or `withdraw`.
pub fn verb(action: Action) -> &'static str {
    match action {
        Action::Approve => "approve",
        Action::Withdraw => "withdraw",
    }
}

/// Why an `approve` or a `withdraw` wrote nothing.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum Refused {
    /// The approvers' files are not trusted (`why`), so no entry could count.
    #[error("the approvers' files are not trusted: {why}\nrefusing to {verb}")]
    ApproversNotTrusted { why: String, verb: &'static str },
    /// The lock to approve fails its integrity check.
    #[error("{failure}\nrefusing to approve")]
    Integrity { failure: VerifyFailure },
    /// The lock to approve is not what validation produces now.
    #[error("{cause}\nrefusing to approve")]
    NotValidated { cause: RevalidationError },
    /// The entry could not be signed or appended (an untrusted key, a message that does not fit).
    #[error("{cause}\nrefusing to {verb}")]
    Entry {
        cause: Box<RobotError>,
        verb: &'static str,
    },
    /// The entry bears a time `verify` would refuse.
    #[error("{cause}\nrefusing to {verb}: nothing was written")]
    EntryTime {
        cause: ApprovalError,
        verb: &'static str,
    },
}

impl Refused {
    /// Refuses to `verb` (approve, withdraw) while the approvers' files are not trusted
    /// (`trust_problem` says why): no entry could count.
    pub fn unless_trusted(trust_problem: Option<&str>, verb: &'static str) -> Result<(), Refused> {
        match trust_problem {
            Some(why) => Err(Refused::ApproversNotTrusted {
                why: why.to_owned(),
                verb,
            }),
            None => Ok(()),
        }
    }
}

/// Refuses an entry whose time `verify` would refuse at `now_unix`, before it is written (it would
/// otherwise be announced as recorded and then block the class until withdrawn).
pub fn check_entry_time(entry: &Approval, now_unix: i64) -> Result<(), Refused> {
    signing::check_approval_time(&entry.approved_at_utc, now_unix).map_err(|cause| {
        Refused::EntryTime {
            cause,
            verb: verb(entry.action),
        }
    })
}

/// What `approve` or `withdraw` prints once `entry` of `class` is recorded in the approvals file at
/// `path` (names from a file are shown [`signing::printable`]).
pub fn recorded_text(class: TrajectoryClass, entry: &Approval, path: &Path) -> String {
    match entry.action {
        Action::Approve => format!(
            "{class}: approved by {} at {} (signature verified) — lock_sha256 {} — recorded in {}",
            signing::printable(&entry.approved_by),
            entry.approved_at_utc,
            entry.lock_sha256,
            path.display()
        ),
        Action::Withdraw => format!(
            "{class}: approval of lock_sha256 {} WITHDRAWN by {} at {} (signature verified) — \
             recorded in {}; the lock does not run until it is approved again",
            entry.lock_sha256,
            signing::printable(&entry.approved_by),
            entry.approved_at_utc,
            path.display()
        ),
    }
}

/// Why `approval-message` shows no entry of an approvals file.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum NoEntry {
    /// The file has no entry `entry`.
    #[error("{} has {count} entries; there is no entry {entry}", path.display())]
    Missing {
        path: PathBuf,
        count: usize,
        entry: usize,
    },
    /// The entry's fields are not well-formed.
    #[error("{} entry {entry}: {cause}", path.display())]
    Malformed {
        path: PathBuf,
        entry: usize,
        cause: ApprovalError,
    },
}

/// Entry `entry` (0-based) of the approvals file `file`, read from `path`, to show: only with
/// well-formed fields ([`signing::check_claim`]), as they come from a file anyone may have edited.
pub fn entry_to_show<'f>(
    file: &'f ApprovalsFile,
    entry: usize,
    path: &Path,
) -> Result<&'f Approval, NoEntry> {
    let Some(approval) = file.approval.get(entry) else {
        return Err(NoEntry::Missing {
            path: path.to_owned(),
            count: file.approval.len(),
            entry,
        });
    };
    signing::check_claim(&approval.claim()).map_err(|cause| NoEntry::Malformed {
        path: path.to_owned(),
        entry,
        cause,
    })?;
    Ok(approval)
}

#[cfg(test)]
mod tests {
    //! The texts from known values, line for line; the sign-offs and the re-validation on the
    //! shipped cell's c2 (one plan).

    // Test helpers panic on purpose: a panic is the failure report.
    #![allow(clippy::unwrap_used, clippy::expect_used)]

    use super::*;
    use crate::{CellConfig, InputHashes, RobotModel, TrajectorySpec, TrustFiles};

    const ALICE: &str = "alice@plant.example";
    const AT: &str = "2026-02-03T04:05:06Z";

    fn read(rel: &str) -> String {
        let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
        std::fs::read_to_string(root.join(rel)).unwrap_or_else(|e| panic!("{rel}: {e}"))
    }

    fn alice() -> (PrivateKey, TrustedSigners) {
        let key = signing::key_from_seed(&[1; 32], "alice");
        let line = format!(
            "{ALICE} namespaces=\"{}\" {}\n",
            signing::APPROVAL_NAMESPACE,
            signing::public_key_openssh(&key).unwrap()
        );
        (key, TrustedSigners::parse(&line, "").unwrap())
    }

    fn entry(action: Action, by: &str) -> Approval {
        Approval {
            class: TrajectoryClass::C2,
            action,
            lock_sha256: "ab".repeat(32),
            approved_by: by.to_owned(),
            approved_at_utc: AT.to_owned(),
            previous_sha256: "0".repeat(64),
            signature: String::new(),
        }
    }

    #[test]
    fn class_lists_and_selections_name_every_class_in_order() {
        use TrajectoryClass::{C1, C2, C3};
        assert_eq!(class_list(&[C1, C3]), "c1, c3");
        assert_eq!(class_list(&[]), "");
        assert_eq!(selected(None), vec![C1, C2, C3]);
        assert_eq!(selected(Some(C2)), vec![C2]);
        assert_eq!(
            not_locked_text(&[C1, C3]),
            "not locked: c1, c3 — no lock file was written (every lock is as it was)"
        );
    }

    #[test]
    fn recorded_lines_name_the_entry_and_escape_what_came_from_a_file() {
        let path = Path::new("trajectories/approvals/c2.toml");
        let sha = "ab".repeat(32);
        assert_eq!(
            recorded_text(TrajectoryClass::C2, &entry(Action::Approve, ALICE), path),
            format!(
                "c2: approved by {ALICE} at {AT} (signature verified) — lock_sha256 {sha} — \
                 recorded in trajectories/approvals/c2.toml"
            )
        );
        assert_eq!(
            recorded_text(
                TrajectoryClass::C2,
                &entry(Action::Withdraw, "bob\nc3: OK"),
                path
            ),
            format!(
                "c2: approval of lock_sha256 {sha} WITHDRAWN by bob\\nc3: OK at {AT} (signature \
                 verified) — recorded in trajectories/approvals/c2.toml; the lock does not run \
                 until it is approved again"
            )
        );
    }

    #[test]
    fn only_an_existing_well_formed_entry_is_shown() {
        let path = Path::new("approvals/c2.toml");
        let mut file = ApprovalsFile::default();
        let e = entry_to_show(&file, 0, path).unwrap_err();
        assert_eq!(
            e.to_string(),
            "approvals/c2.toml has 0 entries; there is no entry 0"
        );
        file.approval.push(entry(Action::Approve, ALICE));
        file.approval.push(entry(Action::Withdraw, "bob\nc3: OK"));
        assert_eq!(entry_to_show(&file, 0, path).unwrap().approved_by, ALICE);
        let e = entry_to_show(&file, 1, path).unwrap_err();
        assert!(matches!(e, NoEntry::Malformed { entry: 1, .. }), "{e}");
        assert!(
            e.to_string().starts_with("approvals/c2.toml entry 1: "),
            "{e}"
        );
        assert!(matches!(
            entry_to_show(&file, 2, path),
            Err(NoEntry::Missing { count: 2, .. })
        ));
    }

    #[test]
    fn refusals_say_what_was_refused_and_by_which_command() {
        Refused::unless_trusted(None, "withdraw").unwrap();
        let untrusted =
            Refused::unless_trusted(Some("approvers.sig is missing"), "withdraw").unwrap_err();
        assert_eq!(
            untrusted.to_string(),
            "the approvers' files are not trusted: approvers.sig is missing\nrefusing to withdraw"
        );
        // A time before signed approvals began is refused before anything is written.
        let mut old = entry(Action::Withdraw, ALICE);
        old.approved_at_utc = "2020-01-01T00:00:00Z".to_owned();
        let e = check_entry_time(&old, 1_800_000_000).unwrap_err();
        assert!(
            matches!(
                e,
                Refused::EntryTime {
                    verb: "withdraw",
                    ..
                }
            ),
            "{e}"
        );
        assert!(e
            .to_string()
            .ends_with("\nrefusing to withdraw: nothing was written"));
        check_entry_time(&entry(Action::Approve, ALICE), 1_800_000_000).unwrap();
    }

    #[test]
    fn a_json_entry_holds_the_class_and_the_error() {
        let v = ClassValidation {
            class: TrajectoryClass::C3,
            outcome: Err(RobotError::Config {
                reason: "no".to_owned(),
            }),
        };
        assert!(!v.accepted());
        assert_eq!(
            v.json().unwrap(),
            serde_json::json!({ "class": "c3", "error": "invalid configuration: no" })
        );
        assert_eq!(
            v.text(),
            "Trajectory validation — class c3 — REJECTED\n  invalid configuration: no\n"
        );
    }

    /// c2 of the shipped cell, planned once: locked, re-validated, a sample edited and refused,
    /// approved and withdrawn with a key here and through a signed message.
    #[test]
    fn a_lock_revalidates_and_its_sign_offs_append_in_both_flows() {
        let cell = CellConfig::from_toml_str(&read("config/cell.toml")).unwrap();
        let urdf = read(&format!("config/{}", cell.robot.urdf));
        let model =
            RobotModel::from_urdf_str(&urdf, &cell.robot.base_link, &cell.robot.flange_link)
                .unwrap();
        let spec_text = read("trajectories/c2.toml");
        let spec = TrajectorySpec::from_toml_str(&spec_text).unwrap();
        let hashes = InputHashes::new(
            spec_text.as_bytes(),
            urdf.as_bytes(),
            &cell,
            TrustFiles {
                allowed_signers: b"",
                revoked_keys: b"",
            },
            "test",
        );
        let inputs = PlanInputs {
            model: &model,
            cell: &cell,
            spec: &spec,
            hashes: &hashes,
        };
        let validation = ClassValidation::plan(TrajectoryClass::C2, &inputs);
        assert!(validation.accepted());
        assert_eq!(
            validation.json().unwrap()["report"]["accepted"],
            serde_json::Value::Bool(true)
        );
        let lock = LockFile::from_locked(&validation.outcome.unwrap().into_locked().unwrap());
        revalidate(&inputs, &lock).unwrap();
        assert_eq!(
            locked_text(&lock, Path::new("locks/c2.lock.toml")),
            format!(
                "c2: locked locks/c2.lock.toml (lock_sha256 {})\n    review it, then: ergocell \
                 trajectories approve --class c2 --by <principal> --key <ssh key>",
                lock.lock_sha256
            )
        );
        let mut edited = lock.clone();
        edited.trajectory.point[3].velocities_rad_s[1] += 0.01;
        let e = revalidate(&inputs, &edited).unwrap_err();
        assert!(matches!(e, RevalidationError::Differs { .. }), "{e}");
        assert!(
            e.to_string().contains("point 3: velocities_rad_s[1]"),
            "{e}"
        );

        let (key, trusted) = alice();
        let mut file = ApprovalsFile::default();
        let approve = SignOff::Approve(&lock);
        let approved = approve.sign(&mut file, ALICE, AT, &trusted, &key).unwrap();
        assert_eq!(
            (approved.action, approved.lock_sha256.as_str()),
            (Action::Approve, lock.lock_sha256.as_str())
        );
        // The withdrawal signed outside ergocell: the message, then its signature.
        let withdraw = SignOff::Withdraw(TrajectoryClass::C2);
        let message = withdraw.message(&file, ALICE, AT).unwrap();
        let signature = key
            .sign(
                signing::APPROVAL_NAMESPACE,
                ssh_key::HashAlg::Sha512,
                message.as_bytes(),
            )
            .unwrap()
            .to_pem(ssh_key::LineEnding::LF)
            .unwrap();
        let withdrawn = withdraw
            .append_signed(&mut file, &message, &signature, &trusted)
            .unwrap();
        assert_eq!(withdrawn.action, Action::Withdraw);
        assert_eq!(file.approval.len(), 2);
        // Nothing left to withdraw: refused, naming the command.
        let again = withdraw
            .sign(&mut file, ALICE, AT, &trusted, &key)
            .unwrap_err();
        assert!(
            again.to_string().ends_with("\nrefusing to withdraw"),
            "{again}"
        );
        assert_eq!(
            withdraw.message_written_text(Path::new("w.txt")),
            "c2: wrote the withdrawal message to w.txt — sign it with\n  ssh-keygen -Y sign -f \
             <your key> -n ergocell-trajectory-approval w.txt\nthen: ergocell trajectories \
             withdraw --class c2 --signed w.txt"
        );
    }
}
