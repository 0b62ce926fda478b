//! Lock files, approvals and their verification — the review workflow of the safety engineer.
//!
//! * A **lock file** (`trajectories/locks/<class>.lock.toml`) holds the validated joint trajectory, the
//!   SHA-256 of every input (trajectory file, URDF, cell config, versions), a summary of the checks, and
//!   `lock_sha256`: the SHA-256 of the canonical JSON of everything else in the file. Editing any byte of
//!   the content changes that hash; editing an input changes an input hash.
//! * An **approvals file** (`trajectories/approvals/<class>.toml`) is append-only: each `[[approval]]`
//!   records who signed off which `lock_sha256`, and when (UTC, RFC 3339, taken by the binary), the
//!   SHA-256 of the previous entry (so the file is a hash chain and an edited or removed earlier entry
//!   is caught), and the approver's **SSH signature** over exactly those fields
//!   ([`crate::signing::approval_message`]): without the private key of a trusted approver no one can
//!   write an approval, edit one (the last included) or move one to another lock. An entry with
//!   `action = "withdraw"` (signed over a message of its own kind) takes the standing approval back.
//! * **The chain decides** ([`ApprovalsFile::standing`]): only the lock named by the class's *last*
//!   approval may run, and not once a withdrawal follows it. A lock file restored from an older copy
//!   is refused as superseded, and a withdrawn lock runs again only when approved anew. What the
//!   chain cannot show by itself (its own last entries deleted) the [`crate::witness`] catches.
//! * [`verify`] checks the lock's own hash, every input hash against the current files (the trusted
//!   approvers' files among them), the locked samples against the current URDF's limits, and that the
//!   chain's standing approval is of exactly this lock hash, each of its entries signed by a
//!   trusted, unrevoked key for its principal. Only then does it hand out an [`ApprovedTrajectory`], the only thing the controller
//!   may send.
//! * [`check_matches_validation`] ties the samples to validation: the review commands re-plan from the
//!   current inputs and refuse a lock (hand-edited and re-hashed, say) that does not hold that result.
//! * A [`SessionLock`] holds one approved trajectory for a session; a request for another class is refused
//!   and recorded until the session ends (operator gone and robot at home).
//!
//! Where these files live is [`crate::layout::TrajectoryLayout`]'s business; this module only parses
//! and checks their text.
//!
//! The lock is a software guarantee on top of the robot's own safety controller, not a replacement.

use std::fmt;

use serde::{Deserialize, Serialize};

use crate::config::TrajectoryClass;
use crate::model::RobotModel;
use crate::monitor::MonitorLimits;
use crate::signing::{self, Action, ApprovalClaim, TrustedSigners};
use crate::validate::{sha256_hex, InputHashes, LockedTrajectory, SAFETY_NOTE};
use crate::RobotError;

/// Version tag of the lock format.
pub const LOCK_FORMAT: &str = "ergocell-trajectory-lock/4";

/// Headline numbers of the validation, kept in the lock for the reviewer.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct LockSummary {
    pub qp_status: String,
    pub qp_iterations: u32,
    pub min_position_margin_deg: f64,
    pub peak_tcp_speed_in_zone_m_s: f64,
    pub tcp_speed_limit_m_s: f64,
    pub min_separation_m: f64,
    pub required_separation_m: f64,
    pub min_singular_value: f64,
    pub handover_station_m: [f64; 3],
    /// The execution monitor's path tolerance per joint, radians (controller joint order), derived
    /// by the validation ([`crate::ValidationReport::path_tolerance_rad`]): signed off with the
    /// trajectory, carried with every leg; the cell may only tighten it.
    pub path_tolerance_rad: Vec<f64>,
    /// The execution monitor's other limits (goal, goal time, rest, stall window, stop time), the
    /// cell's `[monitor]` when it was locked: signed off with the trajectory, applied to every leg;
    /// the cell may only tighten them.
    pub monitor: MonitorLimits,
}

/// One knot of the locked trajectory.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct LockPoint {
    pub time_s: f64,
    pub positions_rad: Vec<f64>,
    pub velocities_rad_s: Vec<f64>,
    pub accelerations_rad_s2: Vec<f64>,
}

/// The locked joint trajectory (controller joint names; `time_from_start` per point).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct LockTrajectory {
    pub joint_names: Vec<String>,
    pub dt_s: f64,
    pub point: Vec<LockPoint>,
}

/// A lock file as stored.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct LockFile {
    pub format: String,
    pub class: TrajectoryClass,
    /// SHA-256 of the canonical JSON of all other fields (see [`LockFile::content_sha256`]).
    pub lock_sha256: String,
    pub note: String,
    pub inputs: InputHashes,
    pub summary: LockSummary,
    pub trajectory: LockTrajectory,
}

#[derive(Serialize)]
struct LockContent<'a> {
    format: &'a str,
    class: TrajectoryClass,
    note: &'a str,
    inputs: &'a InputHashes,
    summary: &'a LockSummary,
    trajectory: &'a LockTrajectory,
}

impl LockFile {
    /// Build the lock of a validated trajectory.
    pub fn from_locked(locked: &LockedTrajectory) -> Self {
        let r = locked.report();
        let point = locked
            .time_s()
            .iter()
            .enumerate()
            .map(|(k, &t)| LockPoint {
                time_s: t,
                positions_rad: locked.positions_rad()[k].clone(),
                velocities_rad_s: locked.velocities_rad_s()[k].clone(),
                accelerations_rad_s2: locked.accelerations_rad_s2()[k].clone(),
            })
            .collect();
        let mut lock = Self {
            format: LOCK_FORMAT.to_owned(),
            class: locked.class(),
            lock_sha256: String::new(),
            note: SAFETY_NOTE.to_owned(),
            inputs: locked.inputs().clone(),
            summary: LockSummary {
                qp_status: r.qp.status.to_string(),
                qp_iterations: r.qp.iterations,
                min_position_margin_deg: r
                    .joints
                    .iter()
                    .map(|j| j.position_margin_rad.to_degrees())
                    .fold(f64::INFINITY, f64::min),
                peak_tcp_speed_in_zone_m_s: r.tcp_speed.peak_in_zone_m_s,
                tcp_speed_limit_m_s: r.tcp_speed.limit_in_zone_m_s,
                min_separation_m: r.separation.min_separation_m,
                required_separation_m: r.separation.required_m,
                min_singular_value: r.singularity.min_singular_value,
                handover_station_m: r.handover.target_station_m,
                path_tolerance_rad: r.path_tolerance_rad.clone(),
                monitor: r.monitor,
            },
            trajectory: LockTrajectory {
                joint_names: locked.joint_names().to_vec(),
                dt_s: locked.dt_s(),
                point,
            },
        };
        lock.lock_sha256 = lock.content_sha256();
        lock
    }

    /// SHA-256 of the canonical (compact JSON, field order as declared) content without `lock_sha256`.
    pub fn content_sha256(&self) -> String {
        let content = LockContent {
            format: &self.format,
            class: self.class,
            note: &self.note,
            inputs: &self.inputs,
            summary: &self.summary,
            trajectory: &self.trajectory,
        };
        sha256_hex(&serde_json::to_vec(&content).unwrap_or_default())
    }

    /// Serialise as TOML with an explanatory header.
    pub fn to_toml(&self) -> Result<String, RobotError> {
        let body = toml::to_string(self).map_err(|e| RobotError::LockCorrupt {
            class: self.class.to_string(),
            reason: format!("cannot serialise: {e}"),
        })?;
        Ok(format!(
            "# ergocell trajectory lock for class {} — written by `ergocell trajectories lock`.\n\
             # Do not edit: `ergocell trajectories verify` recomputes lock_sha256 over this content and the\n\
             # input hashes over the current files. Approve with `ergocell trajectories approve --class {} --by <principal> --key <ssh key>`.\n\
             # Units: radians, rad/s, rad/s², seconds, metres.\n\n{body}",
            self.class, self.class
        ))
    }

    /// Parse a lock file and check its format, class and own hash.
    pub fn from_toml_str(class: TrajectoryClass, text: &str) -> Result<Self, RobotError> {
        // The format first: a lock of an earlier format says so, not which field it lacks.
        #[derive(Deserialize)]
        struct Format {
            format: String,
        }
        let corrupt = |reason: String| RobotError::LockCorrupt {
            class: class.to_string(),
            reason,
        };
        let stale = |format: &str| {
            corrupt(format!(
                "format `{}`, expected `{LOCK_FORMAT}`: lock it again with this version \
                 (`ergocell trajectories lock`) and have it approved again",
                signing::printable(format)
            ))
        };
        if let Ok(f) = toml::from_str::<Format>(text) {
            if f.format != LOCK_FORMAT {
                return Err(stale(&f.format));
            }
        }
        let lock: Self = toml::from_str(text).map_err(|e| {
            corrupt(format!(
                "does not parse: {}",
                signing::printable(&e.to_string())
            ))
        })?;
        if lock.format != LOCK_FORMAT {
            return Err(stale(&lock.format));
        }
        if lock.class != class {
            return Err(corrupt(format!("file is for class {}", lock.class)));
        }
        let actual = lock.content_sha256();
        if actual != lock.lock_sha256 {
            return Err(corrupt(format!(
                "content was edited: recorded lock_sha256 {}, content hashes to {actual}",
                lock.lock_sha256
            )));
        }
        let tol = &lock.summary.path_tolerance_rad;
        if tol.len() != lock.trajectory.joint_names.len()
            || !tol.iter().all(|t| t.is_finite() && *t > 0.0)
        {
            return Err(corrupt(format!(
                "path_tolerance_rad {tol:?}: expected one finite positive tolerance per joint ({})",
                lock.trajectory.joint_names.len()
            )));
        }
        lock.summary
            .monitor
            .check()
            .map_err(|e| corrupt(e.to_string()))?;
        Ok(lock)
    }
}

/// One sign-off.
#[derive(Debug, Clone, PartialEq, Eq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Approval {
    pub class: TrajectoryClass,
    /// An approval (the default, and then not written) or a withdrawal of the approval of
    /// `lock_sha256`.
    #[serde(default, skip_serializing_if = "Action::is_approve")]
    pub action: Action,
    pub lock_sha256: String,
    /// The approver's principal, as the allowed-signers file lists it.
    pub approved_by: String,
    /// RFC 3339 UTC, taken from the clock by the binary.
    pub approved_at_utc: String,
    /// SHA-256 of the previous entry (canonical JSON), 64 zeros for the first: the file is a hash chain,
    /// so an edited or removed earlier entry is detected.
    pub previous_sha256: String,
    /// The approver's SSH signature (armored SSHSIG, namespace
    /// [`signing::APPROVAL_NAMESPACE`]) over [`Approval::message`].
    pub signature: String,
}

impl Approval {
    /// The fields the signature covers.
    pub fn claim(&self) -> ApprovalClaim<'_> {
        ApprovalClaim {
            action: self.action,
            class: self.class.as_str(),
            lock_sha256: &self.lock_sha256,
            approved_by: &self.approved_by,
            approved_at_utc: &self.approved_at_utc,
            previous_sha256: &self.previous_sha256,
        }
    }

    /// The exact bytes the signature covers (`ssh-keygen -Y verify` reads them on its standard input).
    pub fn message(&self) -> String {
        signing::approval_message(&self.claim())
    }

    /// SHA-256 of this entry's canonical JSON (what the next entry's `previous_sha256` records).
    pub fn entry_sha256(&self) -> String {
        sha256_hex(&serde_json::to_vec(self).unwrap_or_default())
    }
}

const CHAIN_START: &str = "0000000000000000000000000000000000000000000000000000000000000000";

/// An append-only approvals file.
#[derive(Debug, Clone, PartialEq, Eq, Serialize, Deserialize, Default)]
#[serde(deny_unknown_fields)]
pub struct ApprovalsFile {
    #[serde(default)]
    pub approval: Vec<Approval>,
}

impl ApprovalsFile {
    pub fn from_toml_str(text: &str) -> Result<Self, RobotError> {
        toml::from_str(text).map_err(|e| RobotError::Config {
            reason: format!(
                "approvals file does not parse: {}",
                signing::printable(&e.to_string())
            ),
        })
    }

    pub fn to_toml(&self) -> Result<String, RobotError> {
        let body = toml::to_string(self).map_err(|e| RobotError::Config {
            reason: format!("cannot serialise approvals: {e}"),
        })?;
        Ok(format!(
            "# ergocell trajectory approvals — append-only, written by `ergocell trajectories approve`.\n\
             # Each entry signs off exactly one lock_sha256 of trajectories/locks/<class>.lock.toml.\n\n{body}"
        ))
    }

    /// Check the hash chain: entry i records the SHA-256 of entry i − 1.
    pub fn check_chain(&self) -> Result<(), RobotError> {
        let mut previous = CHAIN_START.to_owned();
        for (i, entry) in self.approval.iter().enumerate() {
            if entry.previous_sha256 != previous {
                return Err(RobotError::Config {
                    reason: format!(
                        "approvals hash chain broken at entry {i} (approved by {}): an earlier entry was edited or removed",
                        signing::printable(&entry.approved_by)
                    ),
                });
            }
            previous = entry.entry_sha256();
        }
        Ok(())
    }

    /// The `previous_sha256` the next entry must record (the chain's head).
    pub fn head_sha256(&self) -> String {
        self.approval
            .last()
            .map_or_else(|| CHAIN_START.to_owned(), Approval::entry_sha256)
    }

    /// The checked principal (trimmed) and the chain head the next entry by `principal` at
    /// `approved_at_utc` records.
    fn next_fields<'p>(
        &self,
        principal: &'p str,
        approved_at_utc: &str,
    ) -> Result<(&'p str, String), RobotError> {
        let principal = principal.trim();
        signing::check_principal(principal)?;
        signing::check_utc_time(approved_at_utc).map_err(|e| RobotError::Config {
            reason: e.to_string(),
        })?;
        self.check_chain()?;
        Ok((principal, self.head_sha256()))
    }

    /// What the chain says of `class` now: which lock its last approval names, who approved it
    /// since, and whether that approval was withdrawn after. Entries for another class are passed
    /// over (they are [`verify`]'s business). Signatures are not checked here.
    pub fn standing(&self, class: TrajectoryClass) -> Standing {
        let mut standing = Standing::default();
        for (i, e) in self.approval.iter().enumerate() {
            if e.class != class {
                continue;
            }
            let same = standing.lock_sha256.as_deref() == Some(e.lock_sha256.as_str());
            match e.action {
                Action::Approve if same && standing.withdrawn.is_none() => {
                    standing.approvals.push(i);
                }
                Action::Approve => {
                    standing = Standing {
                        lock_sha256: Some(e.lock_sha256.clone()),
                        approvals: vec![i],
                        withdrawn: None,
                    };
                }
                Action::Withdraw if same && standing.withdrawn.is_none() => {
                    standing.withdrawn = Some(i);
                }
                // Withdrawing what does not stand changes nothing (and is refused when written).
                Action::Withdraw => {}
            }
        }
        standing
    }

    /// The lock hash a withdrawal of `class` now takes back: the standing, not withdrawn approval's.
    fn withdrawable(&self, class: TrajectoryClass) -> Result<String, RobotError> {
        let standing = self.standing(class);
        match (standing.lock_sha256, standing.withdrawn) {
            (Some(lock), None) => Ok(lock),
            (Some(_), Some(i)) => Err(RobotError::Config {
                reason: format!(
                    "nothing to withdraw: the approval of {class} was already withdrawn (entry {i}, by {})",
                    signing::printable(&self.approval[i].approved_by)
                ),
            }),
            (None, _) => Err(RobotError::Config {
                reason: format!("nothing to withdraw: no approval of {class} in this file"),
            }),
        }
    }

    /// The exact message the next approval of `lock` by `principal` at `approved_at_utc` signs, for
    /// signing outside ergocell (`ssh-keygen -Y sign`, then [`ApprovalsFile::append_signed`]).
    pub fn next_message(
        &self,
        lock: &LockFile,
        principal: &str,
        approved_at_utc: &str,
    ) -> Result<String, RobotError> {
        let (principal, previous_sha256) = self.next_fields(principal, approved_at_utc)?;
        Ok(signing::approval_message(&ApprovalClaim {
            action: Action::Approve,
            class: lock.class.as_str(),
            lock_sha256: &lock.lock_sha256,
            approved_by: principal,
            approved_at_utc,
            previous_sha256: &previous_sha256,
        }))
    }

    /// The exact message the withdrawal of `class`'s standing approval by `principal` at
    /// `withdrawn_at_utc` signs (then [`ApprovalsFile::append_signed_withdrawal`]).
    pub fn next_withdrawal_message(
        &self,
        class: TrajectoryClass,
        principal: &str,
        withdrawn_at_utc: &str,
    ) -> Result<String, RobotError> {
        let (principal, previous_sha256) = self.next_fields(principal, withdrawn_at_utc)?;
        let lock_sha256 = self.withdrawable(class)?;
        Ok(signing::approval_message(&ApprovalClaim {
            action: Action::Withdraw,
            class: class.as_str(),
            lock_sha256: &lock_sha256,
            approved_by: principal,
            approved_at_utc: withdrawn_at_utc,
            previous_sha256: &previous_sha256,
        }))
    }

    /// Append a sign-off of `lock` (which must have passed [`verify_integrity`]) by `principal` at
    /// `approved_at_utc`, signed with `key` (which `trusted` must list for `principal`, unrevoked).
    pub fn approve(
        &mut self,
        lock: &LockFile,
        principal: &str,
        approved_at_utc: &str,
        trusted: &TrustedSigners,
        key: &ssh_key::PrivateKey,
    ) -> Result<&Approval, RobotError> {
        let (principal, previous_sha256) = self.next_fields(principal, approved_at_utc)?;
        self.sign_and_push(
            Action::Approve,
            lock.class,
            lock.lock_sha256.clone(),
            principal,
            approved_at_utc,
            previous_sha256,
            trusted,
            key,
        )
    }

    /// Append the withdrawal of `class`'s standing approval by `principal` at `withdrawn_at_utc`,
    /// signed with `key`: any trusted approver may withdraw (stopping a motion is the safe way), and
    /// the lock does not run again until an approval of it follows. Needs no lock file: the
    /// withdrawal names the hash the chain approved.
    pub fn withdraw(
        &mut self,
        class: TrajectoryClass,
        principal: &str,
        withdrawn_at_utc: &str,
        trusted: &TrustedSigners,
        key: &ssh_key::PrivateKey,
    ) -> Result<&Approval, RobotError> {
        let (principal, previous_sha256) = self.next_fields(principal, withdrawn_at_utc)?;
        let lock_sha256 = self.withdrawable(class)?;
        self.sign_and_push(
            Action::Withdraw,
            class,
            lock_sha256,
            principal,
            withdrawn_at_utc,
            previous_sha256,
            trusted,
            key,
        )
    }

    #[allow(clippy::too_many_arguments)]
    fn sign_and_push(
        &mut self,
        action: Action,
        class: TrajectoryClass,
        lock_sha256: String,
        principal: &str,
        at_utc: &str,
        previous_sha256: String,
        trusted: &TrustedSigners,
        key: &ssh_key::PrivateKey,
    ) -> Result<&Approval, RobotError> {
        let claim = ApprovalClaim {
            action,
            class: class.as_str(),
            lock_sha256: &lock_sha256,
            approved_by: principal,
            approved_at_utc: at_utc,
            previous_sha256: &previous_sha256,
        };
        let signature = trusted.sign(&claim, key)?;
        self.push_checked(
            Approval {
                class,
                action,
                lock_sha256,
                approved_by: principal.to_owned(),
                approved_at_utc: at_utc.to_owned(),
                previous_sha256,
                signature,
            },
            trusted,
        )
    }

    /// Append an approval signed outside ergocell (`ssh-keygen -Y sign` over the message that
    /// [`signing::approval_message`] wrote): `message` must be such a message for exactly `lock` and
    /// this file's current head, and `signature` valid for it.
    pub fn append_signed(
        &mut self,
        lock: &LockFile,
        message: &str,
        signature: &str,
        trusted: &TrustedSigners,
    ) -> Result<&Approval, RobotError> {
        self.append_signed_as(
            Action::Approve,
            lock.class,
            &lock.lock_sha256,
            message,
            signature,
            trusted,
        )
    }

    /// Append a withdrawal signed outside ergocell: `message` must be the withdrawal of `class`'s
    /// standing approval at this file's current head ([`ApprovalsFile::next_withdrawal_message`]).
    pub fn append_signed_withdrawal(
        &mut self,
        class: TrajectoryClass,
        message: &str,
        signature: &str,
        trusted: &TrustedSigners,
    ) -> Result<&Approval, RobotError> {
        let lock_sha256 = self.withdrawable(class)?;
        self.append_signed_as(
            Action::Withdraw,
            class,
            &lock_sha256,
            message,
            signature,
            trusted,
        )
    }

    fn append_signed_as(
        &mut self,
        expected: Action,
        expected_class: TrajectoryClass,
        expected_lock: &str,
        message: &str,
        signature: &str,
        trusted: &TrustedSigners,
    ) -> Result<&Approval, RobotError> {
        let (action, [class, lock_sha256, approved_by, approved_at_utc, previous_sha256]) =
            signing::parse_approval_message(message)?;
        let refuse = |reason: String| RobotError::Config {
            reason: format!("the signed message does not fit: {reason}"),
        };
        if action != expected {
            return Err(refuse(format!(
                "it is {}, not {} (approve a lock with `approve --signed`, withdraw with \
                 `withdraw --signed`)",
                action.message_noun(),
                expected.message_noun()
            )));
        }
        if class != expected_class.as_str() {
            return Err(refuse(format!(
                "it is for class {}, not {expected_class}",
                signing::printable(&class),
            )));
        }
        if lock_sha256 != expected_lock {
            return Err(refuse(match action {
                Action::Approve => format!(
                    "it approves lock {}, the current lock is {expected_lock} (re-lock since? write a new message)",
                    signing::printable(&lock_sha256),
                ),
                Action::Withdraw => format!(
                    "it withdraws lock {}, the approval standing is of lock {expected_lock} (write a new message)",
                    signing::printable(&lock_sha256),
                ),
            }));
        }
        self.check_chain()?;
        if previous_sha256 != self.head_sha256() {
            return Err(refuse(
                "its previous_sha256 is not the approvals file's last entry (another entry was \
                 added since the message was written: write a new message)"
                    .to_owned(),
            ));
        }
        self.push_checked(
            Approval {
                class: expected_class,
                action,
                lock_sha256,
                approved_by,
                approved_at_utc,
                previous_sha256,
                signature: signature.trim().to_owned() + "\n",
            },
            trusted,
        )
    }

    /// Verifies `entry`'s signature like [`verify`] will, then appends it.
    fn push_checked(
        &mut self,
        entry: Approval,
        trusted: &TrustedSigners,
    ) -> Result<&Approval, RobotError> {
        trusted
            .verify(&entry.claim(), &entry.signature)
            .map_err(|reason| RobotError::ApprovalRefused {
                class: entry.class.to_string(),
                entry: self.approval.len(),
                approved_by: signing::printable(&entry.approved_by),
                reason: Box::new(reason),
            })?;
        self.approval.push(entry);
        Ok(&self.approval[self.approval.len() - 1])
    }
}

/// What an approvals file's chain says of one class now ([`ApprovalsFile::standing`]).
#[derive(Debug, Clone, PartialEq, Eq, Default)]
pub struct Standing {
    /// The lock hash the class's last approval names (`None`: never approved). An approval of
    /// another lock earlier in the chain is superseded: only this lock may run.
    pub lock_sha256: Option<String>,
    /// The entries approving that lock since it was last approved anew (after a withdrawal or an
    /// approval of another lock).
    pub approvals: Vec<usize>,
    /// The entry that withdrew those approvals, if one did.
    pub withdrawn: Option<usize>,
}

/// Everything [`verify`] compares. The caller reads the files and hashes the current inputs with
/// [`InputHashes::new`].
#[derive(Debug, Clone, Copy)]
pub struct VerifyInputs<'a> {
    pub class: TrajectoryClass,
    pub lock_toml: &'a str,
    pub current_inputs: &'a InputHashes,
    /// The model from the current URDF: the locked samples are re-checked against its limits.
    pub model: &'a RobotModel,
    /// The approvals file's text, `None` if it does not exist.
    pub approvals_toml: Option<&'a str>,
    /// The approvers the cell trusts now (from the files whose hashes are in `current_inputs`).
    pub trusted: &'a TrustedSigners,
}

/// Every problem found for one class.
#[derive(Debug, Clone, PartialEq)]
pub struct VerifyFailure {
    pub class: TrajectoryClass,
    pub problems: Vec<RobotError>,
}

impl fmt::Display for VerifyFailure {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "class {} failed verification:", self.class)?;
        for p in &self.problems {
            write!(f, "\n  - {p}")?;
        }
        Ok(())
    }
}

impl std::error::Error for VerifyFailure {}

/// A locked, approved and verified trajectory: only [`verify`] builds one.
#[derive(Debug, Clone, PartialEq)]
pub struct ApprovedTrajectory {
    lock: LockFile,
    approvals: Vec<Approval>,
}

impl ApprovedTrajectory {
    pub fn class(&self) -> TrajectoryClass {
        self.lock.class
    }
    pub fn lock(&self) -> &LockFile {
        &self.lock
    }
    /// The approvals that name this lock's hash.
    pub fn approvals(&self) -> &[Approval] {
        &self.approvals
    }
    pub fn joint_names(&self) -> &[String] {
        &self.lock.trajectory.joint_names
    }
    /// The execution monitor's path tolerance per joint, radians, as locked and approved.
    pub fn path_tolerance_rad(&self) -> &[f64] {
        &self.lock.summary.path_tolerance_rad
    }

    /// The execution monitor's other limits, as locked and approved.
    pub fn monitor_limits(&self) -> MonitorLimits {
        self.lock.summary.monitor
    }
    pub fn points(&self) -> &[LockPoint] {
        &self.lock.trajectory.point
    }

    /// Check that the trajectory starts where the robot is (`/joint_states`, mapped to the controller's
    /// joint order by name by the caller): every joint within `tolerance_rad`.
    pub fn check_start(
        &self,
        current_positions_rad: &[f64],
        tolerance_rad: f64,
    ) -> Result<(), RobotError> {
        let start = &self.lock.trajectory.point[0].positions_rad;
        if current_positions_rad.len() != start.len() {
            return Err(RobotError::DofMismatch {
                what: "current joint positions".to_owned(),
                expected: start.len(),
                got: current_positions_rad.len(),
            });
        }
        for ((name, &current), &first) in self
            .joint_names()
            .iter()
            .zip(current_positions_rad)
            .zip(start)
        {
            if !((current - first).abs() <= tolerance_rad) {
                return Err(RobotError::StartMismatch {
                    joint: name.clone(),
                    current_rad: current,
                    start_rad: first,
                });
            }
        }
        Ok(())
    }
}

/// Check the lock's own hash, the input hashes and the samples against the limits (no approval needed).
pub fn verify_integrity(inputs: &VerifyInputs<'_>) -> Result<LockFile, VerifyFailure> {
    let class = inputs.class;
    let fail = |problems| VerifyFailure { class, problems };
    let lock = LockFile::from_toml_str(class, inputs.lock_toml).map_err(|e| fail(vec![e]))?;
    let mut problems = Vec::new();
    let (l, c) = (&lock.inputs, inputs.current_inputs);
    for (what, locked, current) in [
        (
            format!("trajectory file trajectories/{class}.toml"),
            &l.trajectory_sha256,
            &c.trajectory_sha256,
        ),
        ("URDF".to_owned(), &l.urdf_sha256, &c.urdf_sha256),
        (
            "cell config ([robot]/[station])".to_owned(),
            &l.cell_sha256,
            &c.cell_sha256,
        ),
        (
            format!(
                "trusted approvers' file {} (a key added or removed: re-lock and re-approve)",
                signing::ALLOWED_SIGNERS
            ),
            &l.allowed_signers_sha256,
            &c.allowed_signers_sha256,
        ),
        (
            format!(
                "revoked approvers' keys {} (re-lock and re-approve)",
                signing::REVOKED_KEYS
            ),
            &l.revoked_keys_sha256,
            &c.revoked_keys_sha256,
        ),
        (
            "ergocell version".to_owned(),
            &l.ergocell_version,
            &c.ergocell_version,
        ),
        (
            "planner version".to_owned(),
            &l.planner_version,
            &c.planner_version,
        ),
    ] {
        if locked != current {
            problems.push(RobotError::LockMismatch {
                class: class.to_string(),
                what,
                locked_sha256: locked.clone(),
                current_sha256: current.clone(),
            });
        }
    }
    problems.extend(check_samples(class, &lock, inputs.model));
    if problems.is_empty() {
        Ok(lock)
    } else {
        Err(fail(problems))
    }
}

/// Re-check the stored samples against the model's limits and the rest conditions.
fn check_samples(class: TrajectoryClass, lock: &LockFile, model: &RobotModel) -> Vec<RobotError> {
    let mut problems = Vec::new();
    let dof = model.dof();
    let t = &lock.trajectory;
    let corrupt = |reason: String| RobotError::LockCorrupt {
        class: class.to_string(),
        reason,
    };
    if t.joint_names.len() != dof {
        problems.push(RobotError::DofMismatch {
            what: "locked joint names".to_owned(),
            expected: dof,
            got: t.joint_names.len(),
        });
        return problems;
    }
    if t.point.len() < 2 {
        problems.push(corrupt("fewer than two points".to_owned()));
        return problems;
    }
    for (k, p) in t.point.iter().enumerate() {
        if p.positions_rad.len() != dof
            || p.velocities_rad_s.len() != dof
            || p.accelerations_rad_s2.len() != dof
        {
            problems.push(corrupt(format!(
                "point {k} does not have {dof} values per field"
            )));
            return problems;
        }
        if k > 0 && !(p.time_s > t.point[k - 1].time_s) {
            problems.push(corrupt(format!(
                "time_s not strictly increasing at point {k}"
            )));
        }
        if let Err(e) = model.check_positions(&p.positions_rad) {
            problems.push(e);
        }
        for (j, lim) in model.joints().iter().enumerate() {
            if !(p.velocities_rad_s[j].abs() <= lim.velocity_rad_s) {
                problems.push(corrupt(format!(
                    "point {k}: {} velocity {:.4} rad/s over URDF limit {:.4}",
                    lim.name, p.velocities_rad_s[j], lim.velocity_rad_s
                )));
            }
        }
    }
    for (label, p) in [
        ("first", &t.point[0]),
        ("last", &t.point[t.point.len() - 1]),
    ] {
        if p.velocities_rad_s
            .iter()
            .chain(&p.accelerations_rad_s2)
            .any(|x| *x != 0.0)
        {
            problems.push(corrupt(format!("{label} point is not at rest")));
        }
    }
    problems
}

/// How far a locked sample may differ from what validation produces now (rad, rad/s, rad/s²; s for
/// times): far below anything that matters physically, far above the last-bit differences of the
/// solver between machines.
pub const REVALIDATION_TOLERANCE: f64 = 1e-6;

/// Check that `lock` holds the trajectory that validation produces from the current inputs
/// (`validated`, from [`crate::plan_and_validate`] on the same files), sample by sample within
/// [`REVALIDATION_TOLERANCE`].
///
/// [`verify_integrity`] only proves that the lock is self-consistent and names the current inputs: a
/// lock whose samples were edited and whose `lock_sha256` was recomputed passes it. This check ties
/// the samples to validation, so such a lock is never approved or verified. It re-plans (IK and QP),
/// so it belongs to the review commands (`approve`, `verify`), not to the run-time start, which must
/// not re-run IK: there the approval of this exact hash carries the guarantee.
pub fn check_matches_validation(
    lock: &LockFile,
    validated: &LockedTrajectory,
) -> Result<(), RobotError> {
    let class = lock.class;
    let differs = |what: String| {
        Err(RobotError::LockCorrupt {
            class: class.to_string(),
            reason: format!("does not hold the validated trajectory: {what}"),
        })
    };
    if validated.class() != class {
        return differs(format!("validation is for class {}", validated.class()));
    }
    if &lock.inputs != validated.inputs() {
        return differs("its input hashes differ from the current inputs".to_owned());
    }
    let close = |a: f64, b: f64| (a - b).abs() <= REVALIDATION_TOLERANCE;
    let report = validated.report();
    if lock.summary.monitor != report.monitor {
        return differs(format!(
            "monitor limits {:?}, the cell's [monitor] gives {:?}",
            lock.summary.monitor, report.monitor
        ));
    }
    let tolerances = &lock.summary.path_tolerance_rad;
    if tolerances.len() != report.path_tolerance_rad.len()
        || tolerances
            .iter()
            .zip(&report.path_tolerance_rad)
            .any(|(a, b)| !close(*a, *b))
    {
        return differs(format!(
            "path tolerances {tolerances:?}, validation gives {:?}",
            report.path_tolerance_rad
        ));
    }
    let t = &lock.trajectory;
    if t.joint_names != validated.joint_names() {
        return differs(format!(
            "joint names {:?}, validation gives {:?}",
            t.joint_names,
            validated.joint_names()
        ));
    }
    if t.point.len() != validated.time_s().len() {
        return differs(format!(
            "{} points, validation gives {}",
            t.point.len(),
            validated.time_s().len()
        ));
    }
    if !close(t.dt_s, validated.dt_s()) {
        return differs(format!("dt_s {} vs {}", t.dt_s, validated.dt_s()));
    }
    for (k, p) in t.point.iter().enumerate() {
        if !close(p.time_s, validated.time_s()[k]) {
            return differs(format!(
                "point {k}: time_s {} vs {}",
                p.time_s,
                validated.time_s()[k]
            ));
        }
        for (field, locked, now) in [
            (
                "positions_rad",
                &p.positions_rad,
                &validated.positions_rad()[k],
            ),
            (
                "velocities_rad_s",
                &p.velocities_rad_s,
                &validated.velocities_rad_s()[k],
            ),
            (
                "accelerations_rad_s2",
                &p.accelerations_rad_s2,
                &validated.accelerations_rad_s2()[k],
            ),
        ] {
            if locked.len() != now.len() {
                return differs(format!("point {k}: {field} has {} values", locked.len()));
            }
            for (j, (a, b)) in locked.iter().zip(now).enumerate() {
                if !close(*a, *b) {
                    return differs(format!(
                        "point {k}: {field}[{j}] = {a}, validation gives {b}"
                    ));
                }
            }
        }
    }
    Ok(())
}

/// Full verification: integrity plus an approval of exactly this lock hash.
pub fn verify(inputs: &VerifyInputs<'_>) -> Result<ApprovedTrajectory, VerifyFailure> {
    let class = inputs.class;
    let lock = verify_integrity(inputs)?;
    let not_approved = |detail: String| VerifyFailure {
        class,
        problems: vec![RobotError::NotApproved {
            class: class.to_string(),
            lock_sha256: lock.lock_sha256.clone(),
            detail,
        }],
    };
    let Some(text) = inputs.approvals_toml else {
        return Err(not_approved(format!(
            "no approvals file approvals/{class}.toml in the trajectories folder; a safety engineer runs \
             `ergocell trajectories approve --class {class} --by <principal> --key <ssh key>` after reviewing the lock"
        )));
    };
    let file = ApprovalsFile::from_toml_str(text)
        .and_then(|f| f.check_chain().map(|()| f))
        .map_err(|e| VerifyFailure {
            class,
            problems: vec![e],
        })?;
    let standing = file.standing(class);
    let entry = |i: usize| &file.approval[i];
    let who = |i: usize| {
        format!(
            "entry {i}, by {} at {}",
            signing::printable(&entry(i).approved_by),
            signing::printable(&entry(i).approved_at_utc)
        )
    };
    // The entries that decide for this lock, checked: one forged or broken among them refuses the
    // lock, whatever else the file holds. (Superseded entries and those of another lock are not:
    // revoking a former approver's key must not unmake the history.)
    let deciding: Vec<usize> = if standing.lock_sha256.as_deref() == Some(&lock.lock_sha256) {
        standing
            .approvals
            .iter()
            .copied()
            .chain(standing.withdrawn)
            .collect()
    } else {
        Vec::new()
    };
    let refused: Vec<RobotError> = deciding
        .iter()
        .filter_map(|&i| {
            let a = entry(i);
            inputs
                .trusted
                .verify(&a.claim(), &a.signature)
                .err()
                .map(|reason| RobotError::ApprovalRefused {
                    class: class.to_string(),
                    entry: i,
                    approved_by: signing::printable(&a.approved_by),
                    reason: Box::new(reason),
                })
        })
        .collect();
    if !refused.is_empty() {
        return Err(VerifyFailure {
            class,
            problems: refused,
        });
    }
    match standing.lock_sha256.as_deref() {
        Some(approved) if approved == lock.lock_sha256 => {}
        Some(approved) => {
            let earlier = file
                .approval
                .iter()
                .rposition(|a| a.class == class && a.lock_sha256 == lock.lock_sha256);
            let last = standing.approvals.last().copied().unwrap_or_default();
            return Err(not_approved(match earlier {
                Some(i) => format!(
                    "this lock was approved ({}), but a later approval ({}) is of another lock, \
                     {approved}: this lock file is older than the approvals (restored from a backup \
                     or from git?). Restore that lock, or have this one reviewed and approved again",
                    who(i),
                    who(last)
                ),
                None => format!(
                    "the approvals file has {} entries, none for this hash; its last approval is of \
                     lock {approved} ({}). An approval of an earlier lock does not carry over",
                    file.approval.len(),
                    who(last)
                ),
            }));
        }
        None => {
            return Err(not_approved(format!(
                "the approvals file has {} entries, none approving class {class}",
                file.approval.len()
            )))
        }
    }
    if let Some(w) = standing.withdrawn {
        return Err(not_approved(format!(
            "its approval was withdrawn ({}); it runs again only once a safety engineer approves it anew",
            who(w)
        )));
    }
    let approvals = standing
        .approvals
        .iter()
        .map(|&i| entry(i).clone())
        .collect();
    Ok(ApprovedTrajectory { lock, approvals })
}

/// A refused request to change the session's trajectory.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct RefusedChange {
    pub requested: TrajectoryClass,
}

/// The trajectory of one operator session: locked from start to end.
#[derive(Debug, Clone)]
pub struct SessionLock {
    trajectory: ApprovedTrajectory,
    refused: Vec<RefusedChange>,
}

impl SessionLock {
    pub fn start(trajectory: ApprovedTrajectory) -> Self {
        Self {
            trajectory,
            refused: Vec::new(),
        }
    }
    pub fn trajectory(&self) -> &ApprovedTrajectory {
        &self.trajectory
    }
    /// A request for a class: the locked trajectory if it is the same class, otherwise refused and recorded.
    pub fn request(
        &mut self,
        requested: TrajectoryClass,
    ) -> Result<&ApprovedTrajectory, RobotError> {
        if requested == self.trajectory.class() {
            Ok(&self.trajectory)
        } else {
            self.refused.push(RefusedChange { requested });
            Err(RobotError::SessionLocked {
                locked_class: self.trajectory.class().to_string(),
                requested_class: requested.to_string(),
            })
        }
    }
    /// Requests refused so far (for the binary's log).
    pub fn refused(&self) -> &[RefusedChange] {
        &self.refused
    }
    /// End the session: only when the operator has gone and the robot is at home.
    pub fn end(
        self,
        operator_gone: bool,
        robot_at_home: bool,
    ) -> Result<Vec<RefusedChange>, (Box<Self>, RobotError)> {
        if operator_gone && robot_at_home {
            Ok(self.refused)
        } else {
            let class = self.trajectory.class().to_string();
            Err((
                Box::new(self),
                RobotError::SessionLocked {
                    locked_class: class,
                    requested_class: format!(
                        "session end (operator gone: {operator_gone}, robot at home: {robot_at_home})"
                    ),
                },
            ))
        }
    }
}
