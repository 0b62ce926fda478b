//! The locked trajectories from the cell's files: the cell file, its URDF, `<class>.toml`, its lock
//! and its approvals, the approvers' files under the site's trust anchor, and the witness. Every
//! [`FileTrajectories::verify`] call re-reads and re-verifies them all, so a file changed during a
//! session is noticed before the robot resumes.

use std::path::{Path, PathBuf};
use std::sync::Arc;

use ergocell_ergonomics::height::HandoverRula;
use ergocell_robot::lock::{self, ApprovalsFile, LockFile, VerifyInputs};
use ergocell_robot::signing::{self, TrustedSigners};
use ergocell_robot::{
    plan_and_validate, ApprovedTrajectory, CellConfig, InputHashes, PlanInputs, RobotModel,
    TrajectoryClass, TrajectoryLayout, TrajectorySpec, TrustFiles,
};

use crate::anchor::{self, TrustListError};
use crate::files::{CellFiles, FileError, FileKind};
use crate::witness_store;
use crate::ProviderError;

/// The classes' RULA-versus-stature curves, in the trajectories folder (`ergocell sim handover-rula`
/// writes it).
pub const HANDOVER_RULA_FILE: &str = "handover_rula.toml";

/// The principal of the demo's throwaway key.
pub const DEMO_PRINCIPAL: &str = "ergocell-demo-key@simulator.invalid";

/// Reads and verifies the locked trajectories through a [`CellFiles`] port, on an injected clock.
#[derive(Debug, Clone)]
pub struct FileTrajectories {
    files: Arc<dyn CellFiles>,
    cell_path: PathBuf,
    /// The trajectories folder's files, approvals in the folder given (not necessarily inside it).
    layout: TrajectoryLayout,
    /// The folder of the site's approvers authority ([`crate::anchor`]).
    anchor_dir: PathBuf,
    /// The witness of the approvals files ([`crate::witness_store`]).
    witness_path: PathBuf,
    /// `ergocell demo` (and tests): a throwaway key trusted instead of the cell's approvers.
    demo: Option<DemoSigner>,
    /// The clock an approval's time is checked against and the witness's sightings are stamped
    /// with: seconds since the Unix epoch.
    now_unix: fn() -> i64,
}

/// The demo's throwaway approver: its key, the one-line trust list naming it, and the locks made
/// under that trust list (a lock covers the trust files, so the reviewed locks do not apply to it).
#[derive(Debug, Clone)]
struct DemoSigner {
    key: signing::PrivateKey,
    allowed_signers: String,
    locks: Vec<DemoLock>,
}

/// A class's lock made in memory under the demo's trust list.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct DemoLock {
    pub class: TrajectoryClass,
    /// The demo lock's text.
    pub text: String,
    /// Its hash.
    pub lock_sha256: String,
    /// The hash of the reviewed lock (on disk or shipped) whose samples it holds.
    pub reviewed_sha256: String,
}

/// A demo approval to be written: where, what, and the lock it approves.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct DemoApproval {
    pub path: PathBuf,
    pub text: String,
    pub lock_sha256: String,
}

/// The texts the robot's geometry of a class is built from.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct GeometryTexts {
    pub cell: String,
    pub urdf: String,
    pub spec: String,
}

impl FileTrajectories {
    /// The cell file `cell_path` (its URDF and approvers' folder beside it), the trajectories in
    /// `layout`, the site's trust anchor in `anchor_dir` and the witness at `witness_path`, read
    /// through `files`. The clock is `now_unix` (seconds since the Unix epoch).
    pub fn new(
        files: Arc<dyn CellFiles>,
        cell_path: &Path,
        layout: TrajectoryLayout,
        anchor_dir: &Path,
        witness_path: &Path,
        now_unix: fn() -> i64,
    ) -> Self {
        Self {
            files,
            cell_path: cell_path.to_owned(),
            layout,
            anchor_dir: anchor_dir.to_owned(),
            witness_path: witness_path.to_owned(),
            demo: None,
            now_unix,
        }
    }

    /// Checks approvals against `now_unix` instead (a test's fixed time).
    #[must_use]
    pub fn with_clock(mut self, now_unix: fn() -> i64) -> Self {
        self.now_unix = now_unix;
        self
    }

    /// The site's approvers authority in `dir` instead.
    #[must_use]
    pub fn with_anchor_dir(mut self, dir: &Path) -> Self {
        dir.clone_into(&mut self.anchor_dir);
        self
    }

    /// The port the files are read through.
    pub fn files(&self) -> &Arc<dyn CellFiles> {
        &self.files
    }

    /// The cell file's path.
    pub fn cell_path(&self) -> &Path {
        &self.cell_path
    }

    /// The trajectories' layout.
    pub fn layout(&self) -> &TrajectoryLayout {
        &self.layout
    }

    /// The folder of the approvers' files and the cell's URDF.
    fn cell_dir(&self) -> &Path {
        self.cell_path.parent().unwrap_or_else(|| Path::new("."))
    }

    fn read(&self, kind: FileKind, path: &Path) -> Result<String, ProviderError> {
        self.files
            .read(kind, path)
            .map_err(|cause| ProviderError::Unreadable {
                path: path.to_owned(),
                cause,
            })
    }

    /// Every file this provider reads (or would, once it exists): the cell file, its URDF, the
    /// approvers' files and the authority's signature, the trust anchor's files, and per class the
    /// trajectory file, its lock and its approvals, the classes' RULA curves and the witness. An
    /// output must be none of them.
    pub fn input_files(&self) -> Vec<PathBuf> {
        let dir = self.cell_dir();
        let mut files = vec![self.cell_path.clone()];
        if let Ok((_, cell, _, _)) = self.cell_and_urdf() {
            files.push(dir.join(&cell.robot.urdf));
        }
        for name in [
            signing::ALLOWED_SIGNERS,
            signing::REVOKED_KEYS,
            ergocell_robot::authority::APPROVERS_SIGNATURE,
        ] {
            files.push(dir.join(name));
        }
        for name in [anchor::AUTHORITY_FILE, anchor::ANCHOR_REVOKED] {
            files.push(self.anchor_dir.join(name));
        }
        for class in TrajectoryClass::ALL {
            files.push(self.layout.spec(class));
            files.push(self.layout.lock(class));
            files.push(self.layout.approvals(class));
        }
        files.push(self.layout.dir().join(HANDOVER_RULA_FILE));
        files.push(self.witness_path.clone());
        files
    }

    /// The cell file's name in messages.
    pub fn cell_label(&self) -> String {
        self.files.label(FileKind::Cell, &self.cell_path)
    }

    /// The cell file's text.
    pub fn cell_text(&self) -> Result<String, ProviderError> {
        self.read(FileKind::Cell, &self.cell_path)
    }

    /// The lock file of `class` (in a demo, the lock made under the demo's trust list).
    pub fn lock_text(&self, class: TrajectoryClass) -> Result<String, ProviderError> {
        if let Some(demo) = &self.demo {
            if let Some(lock) = demo.locks.iter().find(|l| l.class == class) {
                return Ok(lock.text.clone());
            }
        }
        self.read(FileKind::Trajectories, &self.layout.lock(class))
    }

    /// The cell config (text and parsed), the URDF's path and its text.
    fn cell_and_urdf(&self) -> Result<(String, CellConfig, PathBuf, String), ProviderError> {
        let cell_text = self.cell_text()?;
        let cell =
            CellConfig::from_toml_str(&cell_text).map_err(|cause| ProviderError::Invalid {
                path: self.cell_path.clone(),
                cause: Box::new(cause),
            })?;
        let urdf_path = self.cell_dir().join(&cell.robot.urdf);
        let urdf_text = self.read(FileKind::Cell, &urdf_path)?;
        Ok((cell_text, cell, urdf_path, urdf_text))
    }

    /// The texts the robot's geometry of `class` is built from (the recording's markers).
    pub fn geometry_texts(&self, class: TrajectoryClass) -> Result<GeometryTexts, ProviderError> {
        let (cell, _, _, urdf) = self.cell_and_urdf()?;
        let spec = self.read(FileKind::Trajectories, &self.layout.spec(class))?;
        Ok(GeometryTexts { cell, urdf, spec })
    }

    /// The trusted approvers' files (`approvers/allowed_signers` and `approvers/revoked_keys` beside
    /// the cell file; in a demo, the demo key's one-line list and no revocations).
    fn trust_texts(&self) -> Result<(String, String), ProviderError> {
        if let Some(demo) = &self.demo {
            return Ok((demo.allowed_signers.clone(), String::new()));
        }
        let read = |name: &str| {
            let path = self.cell_dir().join(name);
            self.files
                .read(FileKind::Cell, &path)
                .map_err(|cause| ProviderError::ApproversUnreadable { path, cause })
        };
        Ok((
            read(signing::ALLOWED_SIGNERS)?,
            read(signing::REVOKED_KEYS)?,
        ))
    }

    /// Reads the cell, the URDF, the trusted approvers and the class's trajectory file: the model,
    /// the current hashes, the trust list, the cell and the spec.
    fn current(&self, class: TrajectoryClass) -> Result<Current, ProviderError> {
        let (_, cell, urdf_path, urdf_text) = self.cell_and_urdf()?;
        let model =
            RobotModel::from_urdf_str(&urdf_text, &cell.robot.base_link, &cell.robot.flange_link)
                .map_err(|cause| ProviderError::Invalid {
                path: urdf_path.clone(),
                cause: Box::new(cause),
            })?;
        let spec_path = self.layout.spec(class);
        let spec_text = self.read(FileKind::Trajectories, &spec_path)?;
        let spec =
            TrajectorySpec::from_toml_str(&spec_text).map_err(|cause| ProviderError::Invalid {
                path: spec_path.clone(),
                cause: Box::new(cause),
            })?;
        let (allowed, revoked) = self.trust_texts()?;
        let trusted = if self.demo.is_some() {
            TrustedSigners::parse(&allowed, &revoked)
                .map_err(|e| TrustListError::Files(Box::new(e)))
        } else {
            anchor::trusted_signers(
                self.files.as_ref(),
                self.cell_dir(),
                &allowed,
                &revoked,
                &self.anchor_dir,
            )
        }
        .map_err(|cause| ProviderError::TrustList {
            cause: Box::new(cause),
        })?;
        let hashes = InputHashes::new(
            spec_text.as_bytes(),
            urdf_text.as_bytes(),
            &cell,
            TrustFiles {
                allowed_signers: allowed.as_bytes(),
                revoked_keys: revoked.as_bytes(),
            },
            env!("CARGO_PKG_VERSION"),
        );
        Ok(Current {
            model,
            hashes,
            trusted,
            cell,
            spec,
        })
    }

    /// In a demo: per class, the lock made in memory and the reviewed lock it stands for.
    pub fn demo_locks(&self) -> &[DemoLock] {
        self.demo.as_ref().map_or(&[], |d| d.locks.as_slice())
    }

    /// For `ergocell demo` and tests: trust only a throwaway Ed25519 key made from `seed` (principal
    /// [`DEMO_PRINCIPAL`]) instead of the cell's approvers, and lock every class under that trust list
    /// in memory. Each demo lock is checked to hold exactly the samples of the reviewed lock, so the
    /// demo runs the reviewed trajectory; only its trust inputs differ.
    pub fn with_demo_key(mut self, seed: &[u8; 32]) -> Result<Self, ProviderError> {
        let key = signing::key_from_seed(seed, "ergocell demo (throwaway key, simulator only)");
        let public = signing::public_key_openssh(&key).map_err(|cause| ProviderError::DemoKey {
            cause: Box::new(cause),
        })?;
        let allowed_signers = format!(
            "{DEMO_PRINCIPAL} namespaces=\"{}\" {public}\n",
            signing::APPROVAL_NAMESPACE
        );
        self.demo = Some(DemoSigner {
            key,
            allowed_signers,
            locks: Vec::new(),
        });
        let mut locks = Vec::new();
        for class in TrajectoryClass::ALL {
            locks.push(self.demo_lock(class)?);
        }
        if let Some(demo) = &mut self.demo {
            demo.locks = locks;
        }
        Ok(self)
    }

    /// `class` locked under the demo's trust list, checked against the reviewed lock.
    fn demo_lock(&self, class: TrajectoryClass) -> Result<DemoLock, ProviderError> {
        let demo_err = |cause| ProviderError::DemoLock {
            class,
            cause: Box::new(cause),
        };
        let c = self.current(class)?;
        let locked = plan_and_validate(&PlanInputs {
            model: &c.model,
            cell: &c.cell,
            spec: &c.spec,
            hashes: &c.hashes,
        })
        .and_then(ergocell_robot::Validation::into_locked)
        .map_err(demo_err)?;
        let reviewed_path = self.layout.lock(class);
        let reviewed = self.read(FileKind::Trajectories, &reviewed_path)?;
        let mut reviewed =
            LockFile::from_toml_str(class, &reviewed).map_err(|cause| ProviderError::Invalid {
                path: reviewed_path.clone(),
                cause: Box::new(cause),
            })?;
        // The reviewed lock covers the cell's approvers files; everything else must be the same
        // inputs, and the samples the same trajectory.
        let mut expected = locked.inputs().clone();
        expected
            .allowed_signers_sha256
            .clone_from(&reviewed.inputs.allowed_signers_sha256);
        expected
            .revoked_keys_sha256
            .clone_from(&reviewed.inputs.revoked_keys_sha256);
        if reviewed.inputs != expected {
            return Err(ProviderError::LockInputsChanged { class });
        }
        reviewed.inputs = locked.inputs().clone();
        lock::check_matches_validation(&reviewed, &locked).map_err(demo_err)?;
        let demo_lock = LockFile::from_locked(&locked);
        let text = demo_lock.to_toml().map_err(demo_err)?;
        Ok(DemoLock {
            class,
            text,
            lock_sha256: demo_lock.lock_sha256.clone(),
            reviewed_sha256: reviewed.lock_sha256.clone(),
        })
    }

    /// A **demo** approval of the class's current lock, for the caller to write into the approvals
    /// folder (which must not be the repository's `trajectories/approvals/`): integrity is verified
    /// first, exactly as `ergocell trajectories approve` does, and the approver is named as a demo.
    pub fn demo_approval(
        &self,
        class: TrajectoryClass,
        stamp_utc: &str,
    ) -> Result<DemoApproval, ProviderError> {
        let approvals_dir = self.layout.approvals_dir();
        if approvals_dir.ends_with(TrajectoryLayout::default().approvals_dir()) {
            return Err(ProviderError::DemoApprovalsInRepository {
                dir: approvals_dir.to_owned(),
            });
        }
        let Some(demo) = &self.demo else {
            return Err(ProviderError::NoDemoKey);
        };
        let c = self.current(class)?;
        let lock_text = self.lock_text(class)?;
        let inputs = VerifyInputs {
            class,
            lock_toml: &lock_text,
            current_inputs: &c.hashes,
            model: &c.model,
            approvals_toml: None,
            trusted: &c.trusted,
        };
        let lock =
            lock::verify_integrity(&inputs).map_err(|failure| ProviderError::NotVerified {
                failure,
                witness: None,
            })?;
        let demo_err = |cause| ProviderError::DemoLock {
            class,
            cause: Box::new(cause),
        };
        let mut file = ApprovalsFile::default();
        file.approve(&lock, DEMO_PRINCIPAL, stamp_utc, &c.trusted, &demo.key)
            .map_err(demo_err)?;
        let text = file.to_toml().map_err(demo_err)?;
        Ok(DemoApproval {
            path: self.layout.approvals(class),
            text: format!(
                "# DEMO APPROVAL written by `ergocell demo` for the simulator. Not a safety sign-off;\n\
                 # never copy into trajectories/approvals/.\n{text}"
            ),
            lock_sha256: lock.lock_sha256,
        })
    }

    /// The classes' RULA-versus-stature curves, `None` when the file is not there (the more
    /// probable class then serves an operator near a boundary; a warning says so).
    pub fn handover_rula(&self) -> Result<Option<HandoverRula>, ProviderError> {
        let path = self.layout.dir().join(HANDOVER_RULA_FILE);
        let text = match self.files.read(FileKind::Trajectories, &path) {
            Ok(text) => text,
            Err(FileError::Missing { .. }) => {
                tracing::warn!(
                    "no {} beside the trajectories: an operator whose stature interval straddles \
                     a class boundary is served by the more probable class, not the one with the \
                     lower expected RULA (`ergocell sim handover-rula --out-dir {}` writes it)",
                    path.display(),
                    self.layout.dir().display()
                );
                return Ok(None);
            }
            Err(cause) => return Err(ProviderError::Unreadable { path, cause }),
        };
        let curves = |cause: crate::files::Cause| ProviderError::Curves {
            path: path.clone(),
            cause,
        };
        let rula: HandoverRula = toml::from_str(&text).map_err(|e| curves(Arc::new(e)))?;
        rula.check().map_err(|e| curves(Arc::new(e)))?;
        Ok(Some(rula))
    }

    /// The statures the class's trajectory file says it serves, in metres.
    pub fn stature_bounds_m(&self, class: TrajectoryClass) -> Result<(f64, f64), ProviderError> {
        let path = self.layout.spec(class);
        let text = self.read(FileKind::Trajectories, &path)?;
        let spec =
            TrajectorySpec::from_toml_str(&text).map_err(|cause| ProviderError::Invalid {
                path,
                cause: Box::new(cause),
            })?;
        Ok(spec.stature.served_m())
    }

    /// The class's trajectory, when its lock verifies against the current files, its approvals
    /// (by trusted approvers, at times an approval can bear now) are intact, and the witness saw no
    /// more of them than there are.
    pub fn verify(&self, class: TrajectoryClass) -> Result<ApprovedTrajectory, ProviderError> {
        let Current {
            model,
            hashes,
            trusted,
            ..
        } = self.current(class)?;
        let lock_text = self.lock_text(class)?;
        let approvals_path = self.layout.approvals(class);
        let approvals = self.files.read(FileKind::Approvals, &approvals_path).ok();
        let now_unix = (self.now_unix)();
        // The demo's approvals are its own, written afresh each run: no witness of them.
        let seen = match self.demo {
            None => self.witness_check(
                &approvals_path,
                class,
                approvals.as_deref(),
                &trusted,
                now_unix,
            ),
            Some(_) => Ok(()),
        };
        let inputs = VerifyInputs {
            class,
            lock_toml: &lock_text,
            current_inputs: &hashes,
            model: &model,
            approvals_toml: approvals.as_deref(),
            trusted: &trusted,
        };
        // Both reasons when both fail (a forged entry is also one the witness did not see).
        let approved = match (lock::verify(&inputs), seen) {
            (Ok(approved), Ok(())) => approved,
            (Ok(_), Err(e)) => return Err(e),
            (Err(failure), seen) => {
                return Err(ProviderError::NotVerified {
                    failure,
                    witness: seen.err().map(Box::new),
                })
            }
        };
        check_approval_times(&approved, now_unix)?;
        Ok(approved)
    }

    /// Checks an approvals file against the cell's witness and records it there, stamped with the
    /// verification's one reading of the clock, its notes as warnings.
    fn witness_check(
        &self,
        path: &Path,
        class: TrajectoryClass,
        text: Option<&str>,
        trusted: &TrustedSigners,
        now_unix: i64,
    ) -> Result<(), ProviderError> {
        let notes = witness_store::observe_text(
            self.files.as_ref(),
            &self.witness_path,
            path,
            class,
            text,
            trusted,
            now_unix,
        )
        .map_err(|cause| ProviderError::Witness {
            path: path.to_owned(),
            cause: Box::new(cause),
        })?;
        for note in notes {
            tracing::warn!("{note}");
        }
        Ok(())
    }
}

/// Every approval's time is one an approval can bear now ([`signing::check_approval_time`]).
pub fn check_approval_times(
    approved: &ApprovedTrajectory,
    now_unix: i64,
) -> Result<(), ProviderError> {
    for a in approved.approvals() {
        signing::check_approval_time(&a.approved_at_utc, now_unix).map_err(|cause| {
            ProviderError::ApprovalTime {
                approver: signing::printable(&a.approved_by),
                cause,
            }
        })?;
    }
    Ok(())
}

/// What [`FileTrajectories::current`] read.
struct Current {
    model: RobotModel,
    hashes: InputHashes,
    trusted: TrustedSigners,
    cell: CellConfig,
    spec: TrajectorySpec,
}
