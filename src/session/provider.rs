//! Trajectories from the files: `config/cell.toml`, the URDF, `trajectories/<class>.toml`, its lock
//! file and its approvals. Every [`TrajectoryProvider::verify`] call re-reads and re-verifies them all,
//! so a file changed during a session is noticed before the robot resumes.

use std::path::{Path, PathBuf};

use ergocell_robot::lock::{self, ApprovalsFile, VerifyInputs};
use ergocell_robot::{
    ApprovedTrajectory, CellConfig, InputHashes, RobotModel, TrajectoryClass, TrajectoryLayout,
    TrajectorySpec,
};

use super::{ProviderError, TrajectoryProvider};
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
}

impl FileTrajectories {
    /// `approvals_dir` holds `<class>.toml` approvals (normally `<trajectories_dir>/approvals`).
    pub fn new(cell_path: &Path, trajectories_dir: &Path, approvals_dir: &Path) -> Self {
        Self {
            cell_path: cell_path.to_owned(),
            layout: TrajectoryLayout::new(trajectories_dir).with_approvals_dir(approvals_dir),
            cell_shipped: false,
            trajectories_shipped: false,
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
        }
    }

    fn read_from(path: &Path, shipped: bool) -> Result<String, ProviderError> {
        if shipped {
            return crate::shipped::file(path)
                .map(str::to_owned)
                .ok_or_else(|| {
                    ProviderError(format!(
                        "{} is not among the files shipped in the binary",
                        path.display()
                    ))
                });
        }
        std::fs::read_to_string(path)
            .map_err(|e| ProviderError(format!("cannot read {}: {e}", path.display())))
    }

    /// A file of the cell (the cell file or its URDF).
    fn read_cell(&self, path: &Path) -> Result<String, ProviderError> {
        Self::read_from(path, self.cell_shipped)
    }

    /// A file of the trajectories folder (a trajectory file or a lock).
    fn read(&self, path: &Path) -> Result<String, ProviderError> {
        Self::read_from(path, self.trajectories_shipped)
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

    /// The lock file of `class`.
    pub fn lock_text(&self, class: TrajectoryClass) -> Result<String, ProviderError> {
        self.read(&self.layout.lock(class))
    }

    /// The cell config (text and parsed), the URDF's path and its text.
    fn cell_and_urdf(&self) -> Result<(String, CellConfig, PathBuf, String), ProviderError> {
        let cell_text = self.read_cell(&self.cell_path)?;
        let cell = CellConfig::from_toml_str(&cell_text)
            .map_err(|e| ProviderError(format!("{}: {e}", self.cell_path.display())))?;
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
        RobotGeometry::from_texts(&cell_text, &urdf_text, &spec_text)
            .map_err(|e| ProviderError(format!("robot geometry for the recording ({class}): {e}")))
    }

    /// Reads the cell, the URDF and the class's trajectory file: the model and the current hashes.
    fn current(&self, class: TrajectoryClass) -> Result<(RobotModel, InputHashes), ProviderError> {
        let (_, cell, urdf_path, urdf_text) = self.cell_and_urdf()?;
        let model =
            RobotModel::from_urdf_str(&urdf_text, &cell.robot.base_link, &cell.robot.flange_link)
                .map_err(|e| ProviderError(format!("{}: {e}", urdf_path.display())))?;
        let spec_text = self.read(&self.layout.spec(class))?;
        let hashes = InputHashes::new(
            spec_text.as_bytes(),
            urdf_text.as_bytes(),
            &cell,
            env!("CARGO_PKG_VERSION"),
        );
        Ok((model, hashes))
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
            return Err(ProviderError(format!(
                "refusing to write a demo approval into {}: demo approvals live in a temporary folder",
                approvals_dir.display()
            )));
        }
        let (model, hashes) = self.current(class)?;
        let lock_text = self.read(&self.layout.lock(class))?;
        let inputs = VerifyInputs {
            class,
            lock_toml: &lock_text,
            current_inputs: &hashes,
            model: &model,
            approvals_toml: None,
        };
        let lock = lock::verify_integrity(&inputs).map_err(|f| ProviderError(f.to_string()))?;
        let mut file = ApprovalsFile::default();
        file.approve(
            &lock,
            "DEMO APPROVAL (ergocell demo, simulator only; not a safety engineer's sign-off)",
            stamp_utc,
        )
        .map_err(|e| ProviderError(e.to_string()))?;
        let text = file.to_toml().map_err(|e| ProviderError(e.to_string()))?;
        std::fs::create_dir_all(approvals_dir).map_err(|e| {
            ProviderError(format!("cannot create {}: {e}", approvals_dir.display()))
        })?;
        let path = self.layout.approvals(class);
        let text = format!(
            "# DEMO APPROVAL written by `ergocell demo` for the simulator. Not a safety sign-off;\n\
             # never copy into trajectories/approvals/.\n{text}"
        );
        std::fs::write(&path, text)
            .map_err(|e| ProviderError(format!("cannot write {}: {e}", path.display())))?;
        Ok(lock.lock_sha256)
    }
}

impl TrajectoryProvider for FileTrajectories {
    fn stature_bounds_m(&mut self, class: TrajectoryClass) -> Result<(f64, f64), ProviderError> {
        let path = self.layout.spec(class);
        let spec = TrajectorySpec::from_toml_str(&self.read(&path)?)
            .map_err(|e| ProviderError(format!("{}: {e}", path.display())))?;
        Ok((spec.stature.min_m, spec.stature.max_m))
    }

    fn verify(&mut self, class: TrajectoryClass) -> Result<ApprovedTrajectory, ProviderError> {
        let (model, hashes) = self.current(class)?;
        let lock_text = self.read(&self.layout.lock(class))?;
        let approvals = std::fs::read_to_string(self.layout.approvals(class)).ok();
        let inputs = VerifyInputs {
            class,
            lock_toml: &lock_text,
            current_inputs: &hashes,
            model: &model,
            approvals_toml: approvals.as_deref(),
        };
        lock::verify(&inputs).map_err(|f| ProviderError(f.to_string()))
    }
}
