//! An in-memory cell for tests (feature `fixtures`): the reference cell's files, two trusted
//! engineers and an outsider (keys from fixed seeds), the site's approvers authority installed as
//! root's, locks planned and written in memory, approvals and withdrawals signed here. No disk, no
//! root, no `ssh-keygen`: every refusal the provider makes can be staged by editing a file.

use std::path::{Path, PathBuf};
use std::sync::{Arc, OnceLock};

use ergocell_robot::authority::{self, APPROVERS_SIGNATURE};
use ergocell_robot::lock::{ApprovalsFile, LockFile};
use ergocell_robot::signing::{self, PrivateKey, TrustedSigners};
use ergocell_robot::{
    plan_and_validate, CellConfig, InputHashes, PlanInputs, RobotError, RobotModel,
    TrajectoryClass, TrajectoryLayout, TrajectorySpec, TrustFiles,
};

use crate::anchor::{ANCHOR_REVOKED, AUTHORITY_FILE};
use crate::files::{AnchorFile, Ownership};
use crate::{FileTrajectories, MemoryFiles};

/// The reference cell's file.
pub const CELL: &str = include_str!("../../config/cell.toml");
/// Its URDF.
pub const URDF: &str = include_str!("../../config/robots/iiwa14_r820.urdf");
/// Its trajectory files, by class.
pub const SPECS: [(TrajectoryClass, &str); 3] = [
    (
        TrajectoryClass::C1,
        include_str!("../../trajectories/c1.toml"),
    ),
    (
        TrajectoryClass::C2,
        include_str!("../../trajectories/c2.toml"),
    ),
    (
        TrajectoryClass::C3,
        include_str!("../../trajectories/c3.toml"),
    ),
];

/// The trusted engineers' principals.
pub const ALICE: &str = "alice@plant.example";
pub const BOB: &str = "bob@plant.example";

/// Where the fixture's files are.
pub const CELL_PATH: &str = "/cell/config/cell.toml";
pub const TRAJECTORIES_DIR: &str = "/cell/trajectories";
pub const ANCHOR_DIR: &str = "/etc/ergocell";
pub const WITNESS_PATH: &str = "/var/lib/ergocell/witness.jsonl";

/// The approvals' default time, and a clock a day after it.
pub const APPROVED_AT: &str = "2026-01-01T00:00:00Z";
pub fn a_day_later() -> i64 {
    1_767_225_600 + 86_400
}

/// The in-memory cell.
#[derive(Debug, Clone)]
pub struct Fixture {
    pub files: MemoryFiles,
    pub layout: TrajectoryLayout,
    pub alice: PrivateKey,
    pub bob: PrivateKey,
    /// Not in the trust list.
    pub mallory: PrivateKey,
    /// The site's approvers authority.
    pub authority: PrivateKey,
    pub allowed_signers: String,
    pub trusted: TrustedSigners,
}

/// One allowed-signers line for `key` as `principal`.
pub fn allowed_line(principal: &str, key: &PrivateKey) -> Result<String, RobotError> {
    Ok(format!(
        "{principal} namespaces=\"{}\" {}\n",
        signing::APPROVAL_NAMESPACE,
        signing::public_key_openssh(key)?
    ))
}

/// A file owned by root, mode 0644, in root's folders.
fn roots(path: &Path) -> Vec<Ownership> {
    path.ancestors()
        .enumerate()
        .map(|(i, p)| Ownership {
            path: p.to_owned(),
            uid: 0,
            mode: if i == 0 { 0o644 } else { 0o755 },
            regular_file: i == 0,
        })
        .collect()
}

impl Fixture {
    /// The reference cell, its approvers (alice and bob) signed by the authority, the authority
    /// installed as root's; no lock and no approval yet.
    pub fn new() -> Result<Self, RobotError> {
        let alice = signing::key_from_seed(&[1; 32], "alice");
        let bob = signing::key_from_seed(&[2; 32], "bob");
        let mallory = signing::key_from_seed(&[3; 32], "mallory");
        let authority = signing::key_from_seed(&[90; 32], "site authority");
        let allowed_signers = format!(
            "# test approvers\n{}{}",
            allowed_line(ALICE, &alice)?,
            allowed_line(BOB, &bob)?
        );
        let trusted = TrustedSigners::parse(&allowed_signers, "")?;
        let files = MemoryFiles::new();
        let cell_dir = Path::new(CELL_PATH)
            .parent()
            .unwrap_or_else(|| Path::new("/"));
        files.put(CELL_PATH, CELL);
        let cell = CellConfig::from_toml_str(CELL)?;
        files.put(cell_dir.join(&cell.robot.urdf), URDF);
        files.put(
            cell_dir.join(signing::ALLOWED_SIGNERS),
            allowed_signers.as_str(),
        );
        files.put(cell_dir.join(signing::REVOKED_KEYS), "");
        files.put(
            cell_dir.join(APPROVERS_SIGNATURE),
            authority::sign_approvers(&allowed_signers, "", &authority)?,
        );
        let anchor = Path::new(ANCHOR_DIR).join(AUTHORITY_FILE);
        files.put_anchor(
            &anchor,
            AnchorFile {
                bytes: signing::public_key_openssh(&authority)?.into_bytes(),
                chain: roots(&anchor),
            },
        );
        let layout = TrajectoryLayout::new(Path::new(TRAJECTORIES_DIR));
        for (class, text) in SPECS {
            files.put(layout.spec(class), text);
        }
        Ok(Self {
            files,
            layout,
            alice,
            bob,
            mallory,
            authority,
            allowed_signers,
            trusted,
        })
    }

    /// The provider over these files, on the clock `now_unix`.
    pub fn provider(&self, now_unix: fn() -> i64) -> FileTrajectories {
        FileTrajectories::new(
            Arc::new(self.files.clone()),
            Path::new(CELL_PATH),
            self.layout.clone(),
            Path::new(ANCHOR_DIR),
            Path::new(WITNESS_PATH),
            now_unix,
        )
    }

    /// Revocations in the anchor folder (root's), for keys that must stay revoked.
    pub fn revoke_at_anchor(&self, keys: &str) {
        let path = Path::new(ANCHOR_DIR).join(ANCHOR_REVOKED);
        self.files.put_anchor(
            &path,
            AnchorFile {
                bytes: keys.as_bytes().to_vec(),
                chain: roots(&path),
            },
        );
    }

    /// Plans, validates and locks `class` from the current files, and writes its lock file. The
    /// plan for the shipped inputs is made once per process.
    pub fn lock(&self, class: TrajectoryClass) -> Result<LockFile, RobotError> {
        let text = |path: PathBuf| {
            self.files
                .get(&path)
                .and_then(|b| String::from_utf8(b).ok())
                .ok_or_else(|| RobotError::Config {
                    reason: format!("fixture: no {}", path.display()),
                })
        };
        let cell_dir = Path::new(CELL_PATH)
            .parent()
            .unwrap_or_else(|| Path::new("/"));
        let cell_text = text(PathBuf::from(CELL_PATH))?;
        let cell = CellConfig::from_toml_str(&cell_text)?;
        let urdf = text(cell_dir.join(&cell.robot.urdf))?;
        let spec_text = text(self.layout.spec(class))?;
        let allowed = text(cell_dir.join(signing::ALLOWED_SIGNERS))?;
        let revoked = text(cell_dir.join(signing::REVOKED_KEYS))?;
        let hashes = InputHashes::new(
            spec_text.as_bytes(),
            urdf.as_bytes(),
            &cell,
            TrustFiles {
                allowed_signers: allowed.as_bytes(),
                revoked_keys: revoked.as_bytes(),
            },
            env!("CARGO_PKG_VERSION"),
        );
        let lock = planned(class, &hashes, || {
            let model =
                RobotModel::from_urdf_str(&urdf, &cell.robot.base_link, &cell.robot.flange_link)?;
            let spec = TrajectorySpec::from_toml_str(&spec_text)?;
            let locked = plan_and_validate(&PlanInputs {
                model: &model,
                cell: &cell,
                spec: &spec,
                hashes: &hashes,
            })?
            .into_locked()?;
            Ok(LockFile::from_locked(&locked))
        })?;
        self.files.put(self.layout.lock(class), lock.to_toml()?);
        Ok(lock)
    }

    /// The class's approvals file as it is now (empty when there is none).
    pub fn approvals(&self, class: TrajectoryClass) -> Result<ApprovalsFile, RobotError> {
        match self.files.get(&self.layout.approvals(class)) {
            None => Ok(ApprovalsFile::default()),
            Some(bytes) => ApprovalsFile::from_toml_str(&String::from_utf8_lossy(&bytes)),
        }
    }

    /// Replaces the class's approvals file (a rollback, an edit).
    pub fn put_approvals(
        &self,
        class: TrajectoryClass,
        file: &ApprovalsFile,
    ) -> Result<(), RobotError> {
        self.files
            .put(self.layout.approvals(class), file.to_toml()?);
        Ok(())
    }

    /// Appends `principal`'s approval of the class's current lock at `at_utc`, signed with `key`.
    pub fn approve(
        &self,
        class: TrajectoryClass,
        principal: &str,
        key: &PrivateKey,
        at_utc: &str,
    ) -> Result<(), RobotError> {
        let lock = self.current_lock(class)?;
        let mut file = self.approvals(class)?;
        file.approve(&lock, principal, at_utc, &self.trusted, key)?;
        self.put_approvals(class, &file)
    }

    /// Appends `principal`'s withdrawal of the class's standing approval.
    pub fn withdraw(
        &self,
        class: TrajectoryClass,
        principal: &str,
        key: &PrivateKey,
        at_utc: &str,
    ) -> Result<(), RobotError> {
        let mut file = self.approvals(class)?;
        file.withdraw(class, principal, at_utc, &self.trusted, key)?;
        self.put_approvals(class, &file)
    }

    /// The class's lock file as it is now.
    pub fn current_lock(&self, class: TrajectoryClass) -> Result<LockFile, RobotError> {
        let text = self
            .files
            .get(&self.layout.lock(class))
            .map(|b| String::from_utf8_lossy(&b).into_owned())
            .ok_or_else(|| RobotError::Config {
                reason: format!("fixture: {class} is not locked"),
            })?;
        LockFile::from_toml_str(class, &text)
    }

    /// `class` locked and approved by alice at [`APPROVED_AT`].
    pub fn approved(class: TrajectoryClass) -> Result<Self, RobotError> {
        let fixture = Self::new()?;
        fixture.lock(class)?;
        fixture.approve(class, ALICE, &fixture.alice.clone(), APPROVED_AT)?;
        Ok(fixture)
    }
}

/// The lock of `class` for `hashes`: planned once per process and input set (a plan takes a QP).
fn planned(
    class: TrajectoryClass,
    hashes: &InputHashes,
    plan: impl FnOnce() -> Result<LockFile, RobotError>,
) -> Result<LockFile, RobotError> {
    type Plans = std::sync::Mutex<Vec<(TrajectoryClass, InputHashes, LockFile)>>;
    static PLANS: OnceLock<Plans> = OnceLock::new();
    let plans = PLANS.get_or_init(Plans::default);
    let known = plans
        .lock()
        .unwrap_or_else(std::sync::PoisonError::into_inner)
        .iter()
        .find(|(c, h, _)| *c == class && h == hashes)
        .map(|(_, _, l)| l.clone());
    if let Some(lock) = known {
        return Ok(lock);
    }
    let lock = plan()?;
    plans
        .lock()
        .unwrap_or_else(std::sync::PoisonError::into_inner)
        .push((class, hashes.clone(), lock.clone()));
    Ok(lock)
}
