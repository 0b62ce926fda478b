//! Trajectories from the files: `config/cell.toml`, the URDF, `trajectories/<class>.toml`, its lock
//! file and its approvals. Every [`TrajectoryProvider::verify`] call re-reads and re-verifies them all,
//! so a file changed during a session is noticed before the robot resumes.

use std::path::{Path, PathBuf};
use std::sync::Arc;

use ergocell_robot::lock::{self, ApprovalsFile, LockFile, VerifyInputs};
use ergocell_robot::signing::{self, TrustedSigners};
use ergocell_robot::{
    plan_and_validate, ApprovedTrajectory, CellConfig, InputHashes, PlanInputs, RobotModel,
    TrajectoryClass, TrajectoryLayout, TrajectorySpec, TrustFiles,
};

use super::{Cause, ProviderError, TrajectoryProvider};
use crate::robot_markers::RobotGeometry;

/// Reads and verifies the locked trajectories.
#[derive(Debug, Clone)]
pub struct FileTrajectories {
    cell_path: PathBuf,
    /// The trajectories folder's files, approvals in the folder given (not necessarily inside it).
    layout: TrajectoryLayout,
    /// The cell file and its URDF are the ones shipped in the binary ([`crate::shipped`]).
    cell_shipped: bool,
    /// The trajectory files and locks are the shipped ones.
    trajectories_shipped: bool,
    /// `ergocell demo` (and tests): a throwaway key trusted instead of the cell's approvers.
    demo: Option<DemoSigner>,
    /// The folder of the site's approvers authority ([`crate::trust_anchor`]).
    anchor_dir: PathBuf,
    /// The clock an approval's time is checked against and the witness's sightings are stamped
    /// with: seconds since the Unix epoch ([`crate::trust_anchor::now_unix`], or a test's).
    now_unix: fn() -> i64,
}

/// The demo's throwaway approver: its key, the one-line trust list naming it, and the locks made
/// under that trust list (a lock covers the trust files, so the shipped locks do not apply to it).
#[derive(Debug, Clone)]
struct DemoSigner {
    key: signing::PrivateKey,
    allowed_signers: String,
    /// Per class: the demo lock's text, its hash and the reviewed (shipped or on-disk) lock's hash.
    locks: Vec<(TrajectoryClass, String, String, String)>,
}

/// The classes' RULA-versus-stature curves, in the trajectories folder (`ergocell sim handover-rula`
/// writes it).
pub const HANDOVER_RULA_FILE: &str = "handover_rula.toml";

/// The principal of the demo's throwaway key.
pub const DEMO_PRINCIPAL: &str = "ergocell-demo-key@simulator.invalid";

impl FileTrajectories {
    /// `approvals_dir` holds `<class>.toml` approvals (normally `<trajectories_dir>/approvals`). A
    /// relative cell path or trajectories folder that is not in the working directory but names a
    /// shipped one is read from the binary ([`crate::shipped::falls_back`]).
    pub fn new(cell_path: &Path, trajectories_dir: &Path, approvals_dir: &Path) -> Self {
        Self {
            cell_path: cell_path.to_owned(),
            layout: TrajectoryLayout::new(trajectories_dir).with_approvals_dir(approvals_dir),
            cell_shipped: crate::shipped::falls_back(cell_path),
            trajectories_shipped: crate::shipped::dir_falls_back(trajectories_dir),
            demo: None,
            anchor_dir: crate::trust_anchor::anchor_dir(),
            now_unix: crate::trust_anchor::now_unix,
        }
    }

    /// `cell_path` / `trajectories_dir` of `None` are the files shipped in the binary; approvals are
    /// always read from `approvals_dir` on disk.
    pub fn with_shipped_defaults(
        cell_path: Option<&Path>,
        trajectories_dir: Option<&Path>,
        approvals_dir: &Path,
    ) -> Self {
        Self {
            cell_path: cell_path
                .map_or_else(|| PathBuf::from(crate::shipped::CELL), Path::to_owned),
            // Shipped: the relative `trajectories/…` paths are the keys of `crate::shipped::FILES`.
            layout: TrajectoryLayout::new(
                trajectories_dir.unwrap_or_else(|| Path::new(crate::shipped::TRAJECTORIES)),
            )
            .with_approvals_dir(approvals_dir),
            cell_shipped: cell_path.is_none(),
            trajectories_shipped: trajectories_dir.is_none(),
            demo: None,
            anchor_dir: crate::trust_anchor::anchor_dir(),
            now_unix: crate::trust_anchor::now_unix,
        }
    }

    /// Checks approvals against `now_unix` instead of the wall clock (a test's fixed time).
    #[must_use]
    pub fn with_clock(mut self, now_unix: fn() -> i64) -> Self {
        self.now_unix = now_unix;
        self
    }

    fn read_from(path: &Path, shipped: bool) -> Result<String, ProviderError> {
        if shipped {
            return crate::shipped::file(path)
                .map(str::to_owned)
                .ok_or_else(|| ProviderError::Unreadable {
                    path: path.to_owned(),
                    cause: Arc::new(NotShipped(path.to_owned())),
                });
        }
        crate::input::read_text(path, crate::input::Kind::Config).map_err(|e| {
            ProviderError::Unreadable {
                path: path.to_owned(),
                cause: Arc::new(e),
            }
        })
    }

    /// A file of the cell (the cell file or its URDF).
    fn read_cell(&self, path: &Path) -> Result<String, ProviderError> {
        Self::read_from(path, self.cell_shipped)
    }

    /// A file of the trajectories folder (a trajectory file or a lock).
    fn read(&self, path: &Path) -> Result<String, ProviderError> {
        Self::read_from(path, self.trajectories_shipped)
    }

    /// Every file on disk this provider reads (or would, once it exists): the cell file, its URDF,
    /// the approvers' files and the authority's signature, the trust anchor's files, and per class
    /// the trajectory file, its lock and its approvals, and the classes' RULA curves. An output
    /// must be none of them (`--force` or not).
    pub fn input_files(&self) -> Vec<PathBuf> {
        // Shipped files are listed by their place in a cell folder too: a run from this folder
        // would read them there, and they are the user's files either way.
        let dir = self.cell_path.parent().unwrap_or_else(|| Path::new("."));
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
        for name in [
            crate::trust_anchor::AUTHORITY_FILE,
            crate::trust_anchor::ANCHOR_REVOKED,
        ] {
            files.push(self.anchor_dir.join(name));
        }
        for class in TrajectoryClass::ALL {
            files.push(self.layout.spec(class));
            files.push(self.layout.lock(class));
            files.push(self.layout.approvals(class));
        }
        files.push(self.layout.dir().join(HANDOVER_RULA_FILE));
        files.push(crate::witness::witness_path(self.layout.approvals_dir()));
        files
    }

    /// The cell file's text.
    pub fn cell_text(&self) -> Result<String, ProviderError> {
        self.read_cell(&self.cell_path)
    }

    /// The cell file's name in messages.
    pub fn cell_label(&self) -> String {
        if self.cell_shipped {
            crate::shipped::label(crate::shipped::CELL)
        } else {
            self.cell_path.display().to_string()
        }
    }

    /// The lock file of `class` (in a demo, the lock made under the demo's trust list).
    pub fn lock_text(&self, class: TrajectoryClass) -> Result<String, ProviderError> {
        if let Some(demo) = &self.demo {
            if let Some((_, text, _, _)) = demo.locks.iter().find(|(c, ..)| *c == class) {
                return Ok(text.clone());
            }
        }
        self.read(&self.layout.lock(class))
    }

    /// The cell config (text and parsed), the URDF's path and its text.
    fn cell_and_urdf(&self) -> Result<(String, CellConfig, PathBuf, String), ProviderError> {
        let cell_text = self.read_cell(&self.cell_path)?;
        let cell =
            CellConfig::from_toml_str(&cell_text).map_err(|cause| ProviderError::Invalid {
                path: self.cell_path.clone(),
                cause: Box::new(cause),
            })?;
        let urdf_path = self
            .cell_path
            .parent()
            .unwrap_or_else(|| Path::new("."))
            .join(&cell.robot.urdf);
        let urdf_text = self.read_cell(&urdf_path)?;
        Ok((cell_text, cell, urdf_path, urdf_text))
    }

    /// The robot's geometry for the recording's markers (TCP and handover point) of `class`.
    pub fn robot_geometry(&self, class: TrajectoryClass) -> Result<RobotGeometry, ProviderError> {
        let (cell_text, _, _, urdf_text) = self.cell_and_urdf()?;
        let spec_text = self.read(&self.layout.spec(class))?;
        RobotGeometry::from_texts(&cell_text, &urdf_text, &spec_text).map_err(|cause| {
            ProviderError::Geometry {
                class,
                cause: Box::new(cause),
            }
        })
    }

    /// The trusted approvers' files (`approvers/allowed_signers` and `approvers/revoked_keys` beside
    /// the cell file; in a demo, the demo key's one-line list and no revocations).
    fn trust_texts(&self) -> Result<(String, String), ProviderError> {
        if let Some(demo) = &self.demo {
            return Ok((demo.allowed_signers.clone(), String::new()));
        }
        let dir = self.cell_path.parent().unwrap_or_else(|| Path::new("."));
        let read = |name: &str| {
            self.read_cell(&dir.join(name)).map_err(|e| match e {
                ProviderError::Unreadable { path, cause } => {
                    ProviderError::ApproversUnreadable { path, cause }
                }
                other => other,
            })
        };
        Ok((
            read(signing::ALLOWED_SIGNERS)?,
            read(signing::REVOKED_KEYS)?,
        ))
    }

    /// Reads the cell, the URDF, the trusted approvers and the class's trajectory file: the model, the
    /// current hashes, the trust list, the cell and the spec.
    fn current(&self, class: TrajectoryClass) -> Result<Current, ProviderError> {
        let (_, cell, urdf_path, urdf_text) = self.cell_and_urdf()?;
        let model =
            RobotModel::from_urdf_str(&urdf_text, &cell.robot.base_link, &cell.robot.flange_link)
                .map_err(|cause| ProviderError::Invalid {
                path: urdf_path.clone(),
                cause: Box::new(cause),
            })?;
        let spec_path = self.layout.spec(class);
        let spec_text = self.read(&spec_path)?;
        let spec =
            TrajectorySpec::from_toml_str(&spec_text).map_err(|cause| ProviderError::Invalid {
                path: spec_path.clone(),
                cause: Box::new(cause),
            })?;
        let (allowed, revoked) = self.trust_texts()?;
        let trusted = if self.demo.is_some() {
            TrustedSigners::parse(&allowed, &revoked)
                .map_err(|e| ProviderError::TrustList { cause: Arc::new(e) })
        } else {
            let dir = self.cell_path.parent().unwrap_or_else(|| Path::new("."));
            crate::trust_anchor::trusted_signers(dir, &allowed, &revoked, &self.anchor_dir)
                .map_err(|e| ProviderError::TrustList { cause: Arc::new(e) })
        }?;
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

    /// In a demo: per class, the demo lock's hash and the reviewed lock's hash it stands for.
    pub fn demo_locks(&self) -> Vec<(TrajectoryClass, String, String)> {
        self.demo.as_ref().map_or_else(Vec::new, |d| {
            d.locks
                .iter()
                .map(|(c, _, demo, reviewed)| (*c, demo.clone(), reviewed.clone()))
                .collect()
        })
    }

    /// The folder of the site's approvers authority, instead of the environment's or the default
    /// ([`crate::trust_anchor::anchor_dir`]).
    #[must_use]
    pub fn with_anchor_dir(mut self, dir: &Path) -> Self {
        dir.clone_into(&mut self.anchor_dir);
        self
    }

    /// For `ergocell demo` and tests: trust only a throwaway Ed25519 key made from `seed` (principal
    /// [`DEMO_PRINCIPAL`]) instead of the cell's approvers, and lock every class under that trust list
    /// in memory. Each demo lock is checked to hold exactly the samples of the lock on disk (or
    /// shipped), so the demo runs the reviewed trajectory; only its trust inputs differ.
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
            let c = self.current(class)?;
            let locked = plan_and_validate(&PlanInputs {
                model: &c.model,
                cell: &c.cell,
                spec: &c.spec,
                hashes: &c.hashes,
            })
            .and_then(ergocell_robot::Validation::into_locked)
            .map_err(|cause| ProviderError::DemoLock {
                class,
                cause: Box::new(cause),
            })?;
            let reviewed_path = self.layout.lock(class);
            let reviewed = self.read(&reviewed_path)?;
            let reviewed = LockFile::from_toml_str(class, &reviewed).map_err(|cause| {
                ProviderError::Invalid {
                    path: reviewed_path.clone(),
                    cause: Box::new(cause),
                }
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
            let mut reviewed = reviewed;
            reviewed.inputs = locked.inputs().clone();
            lock::check_matches_validation(&reviewed, &locked).map_err(|cause| {
                ProviderError::DemoLock {
                    class,
                    cause: Box::new(cause),
                }
            })?;
            let demo_lock = LockFile::from_locked(&locked);
            let text = demo_lock
                .to_toml()
                .map_err(|cause| ProviderError::DemoLock {
                    class,
                    cause: Box::new(cause),
                })?;
            locks.push((
                class,
                text,
                demo_lock.lock_sha256.clone(),
                reviewed.lock_sha256.clone(),
            ));
        }
        if let Some(demo) = &mut self.demo {
            demo.locks = locks;
        }
        Ok(self)
    }

    /// Writes a **demo** approval of the class's current lock into the approvals folder (which must
    /// not be the repository's `trajectories/approvals/`): integrity is verified first, exactly as
    /// `ergocell trajectories approve` does, and the approver is named as a demo.
    pub fn approve_for_demo(
        &self,
        class: TrajectoryClass,
        stamp_utc: &str,
    ) -> Result<String, ProviderError> {
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
        let mut file = ApprovalsFile::default();
        file.approve(&lock, DEMO_PRINCIPAL, stamp_utc, &c.trusted, &demo.key)
            .map_err(|cause| ProviderError::DemoLock {
                class,
                cause: Box::new(cause),
            })?;
        let text = file.to_toml().map_err(|cause| ProviderError::DemoLock {
            class,
            cause: Box::new(cause),
        })?;
        std::fs::create_dir_all(approvals_dir).map_err(|e| ProviderError::Write {
            path: approvals_dir.to_owned(),
            cause: Arc::new(e),
        })?;
        let path = self.layout.approvals(class);
        let text = format!(
            "# DEMO APPROVAL written by `ergocell demo` for the simulator. Not a safety sign-off;\n\
             # never copy into trajectories/approvals/.\n{text}"
        );
        std::fs::write(&path, text).map_err(|e| ProviderError::Write {
            path: path.clone(),
            cause: Arc::new(e),
        })?;
        Ok(lock.lock_sha256)
    }
}

impl TrajectoryProvider for FileTrajectories {
    fn handover_rula(
        &mut self,
    ) -> Result<Option<ergocell_ergonomics::height::HandoverRula>, ProviderError> {
        let path = self.layout.dir().join(HANDOVER_RULA_FILE);
        let present = if self.trajectories_shipped {
            crate::shipped::file(&path).is_some()
        } else {
            path.exists()
        };
        if !present {
            tracing::warn!(
                "no {} beside the trajectories: an operator whose stature interval straddles a \
                 class boundary is served by the more probable class, not the one with the lower \
                 expected RULA (`ergocell sim handover-rula --out-dir {}` writes it)",
                path.display(),
                self.layout.dir().display()
            );
            return Ok(None);
        }
        let text = self.read(&path)?;
        let curves = |cause: Cause| ProviderError::Curves {
            path: path.clone(),
            cause,
        };
        let rula: ergocell_ergonomics::height::HandoverRula =
            toml::from_str(&text).map_err(|e| curves(Arc::new(e)))?;
        rula.check().map_err(|e| curves(Arc::new(e)))?;
        Ok(Some(rula))
    }

    fn stature_bounds_m(&mut self, class: TrajectoryClass) -> Result<(f64, f64), ProviderError> {
        let path = self.layout.spec(class);
        let spec = TrajectorySpec::from_toml_str(&self.read(&path)?).map_err(|cause| {
            ProviderError::Invalid {
                path,
                cause: Box::new(cause),
            }
        })?;
        Ok(spec.stature.served_m())
    }

    fn verify(&mut self, class: TrajectoryClass) -> Result<ApprovedTrajectory, ProviderError> {
        let Current {
            model,
            hashes,
            trusted,
            ..
        } = self.current(class)?;
        let lock_text = self.lock_text(class)?;
        let approvals_path = self.layout.approvals(class);
        let approvals = crate::input::read_text(&approvals_path, crate::input::Kind::Config).ok();
        // The demo's approvals are its own, written afresh each run: no witness of them.
        let seen = match self.demo {
            None => witness_check(
                &approvals_path,
                class,
                approvals.as_deref(),
                &trusted,
                (self.now_unix)(),
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
        check_approval_times(&approved, (self.now_unix)())?;
        Ok(approved)
    }
}

/// Checks an approvals file against the cell's witness and records it there
/// ([`crate::witness::observe_text`]), its notes as warnings.
fn witness_check(
    path: &Path,
    class: TrajectoryClass,
    text: Option<&str>,
    trusted: &TrustedSigners,
    now_unix: i64,
) -> Result<(), ProviderError> {
    let notes =
        crate::witness::observe_text(path, class, text, trusted, now_unix).map_err(|cause| {
            ProviderError::Witness {
                path: path.to_owned(),
                cause: Box::new(cause),
            }
        })?;
    for note in notes {
        tracing::warn!("{note}");
    }
    Ok(())
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

/// A file asked of the shipped set that is not in it.
#[derive(Debug, thiserror::Error)]
#[error("{} is not among the files shipped in the binary", .0.display())]
struct NotShipped(PathBuf);

/// What [`FileTrajectories::current`] read.
struct Current {
    model: RobotModel,
    hashes: InputHashes,
    trusted: TrustedSigners,
    cell: CellConfig,
    spec: TrajectorySpec,
}
