//! Trajectories from the files: `config/cell.toml`, the URDF, `trajectories/<class>.toml`, its lock
//! file and its approvals. Every [`TrajectoryProvider::verify`] call re-reads and re-verifies them all,
//! so a file changed during a session is noticed before the robot resumes.

use std::path::{Path, PathBuf};

use ergocell_robot::lock::{self, ApprovalsFile, VerifyInputs};
use ergocell_robot::{
    ApprovedTrajectory, CellConfig, InputHashes, RobotModel, TrajectoryClass, TrajectorySpec,
};

use super::{ProviderError, TrajectoryProvider};
use crate::robot_markers::RobotGeometry;

/// Reads and verifies the locked trajectories.
#[derive(Debug, Clone)]
pub struct FileTrajectories {
    cell_path: PathBuf,
    trajectories_dir: PathBuf,
    approvals_dir: PathBuf,
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
            trajectories_dir: trajectories_dir.to_owned(),
            approvals_dir: approvals_dir.to_owned(),
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
            trajectories_dir: trajectories_dir.map_or_else(
                || PathBuf::from(crate::shipped::TRAJECTORIES),
                Path::to_owned,
            ),
            approvals_dir: approvals_dir.to_owned(),
            cell_shipped: cell_path.is_none(),
            trajectories_shipped: trajectories_dir.is_none(),
        }
    }

    fn read_from(path: &Path, shipped: bool) -> Result<String, String> {
        if shipped {
            return crate::shipped::file(path)
                .map(str::to_owned)
                .ok_or_else(|| {
                    format!(
                        "{} is not among the files shipped in the binary",
                        path.display()
                    )
                });
        }
        std::fs::read_to_string(path).map_err(|e| format!("cannot read {}: {e}", path.display()))
    }

    /// A file of the cell (the cell file or its URDF).
    fn read_cell(&self, path: &Path) -> Result<String, String> {
        Self::read_from(path, self.cell_shipped)
    }

    /// A file of the trajectories folder (a trajectory file or a lock).
    fn read(&self, path: &Path) -> Result<String, String> {
        Self::read_from(path, self.trajectories_shipped)
    }

    /// The cell file's text.
    pub fn cell_text(&self) -> Result<String, String> {
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
    pub fn lock_text(&self, class: TrajectoryClass) -> Result<String, String> {
        self.read(&self.lock_path(class))
    }

    fn lock_path(&self, class: TrajectoryClass) -> PathBuf {
        self.trajectories_dir
            .join("locks")
            .join(format!("{class}.lock.toml"))
    }

    /// The cell config (text and parsed), the URDF's path and its text.
    fn cell_and_urdf(&self) -> Result<(String, CellConfig, PathBuf, String), String> {
        let cell_text = self.read_cell(&self.cell_path)?;
        let cell = CellConfig::from_toml_str(&cell_text)
            .map_err(|e| format!("{}: {e}", self.cell_path.display()))?;
        let urdf_path = self
            .cell_path
            .parent()
            .unwrap_or_else(|| Path::new("."))
            .join(&cell.robot.urdf);
        let urdf_text = self.read_cell(&urdf_path)?;
        Ok((cell_text, cell, urdf_path, urdf_text))
    }

    /// The robot's geometry for the recording's markers (TCP and handover point) of `class`.
    pub fn robot_geometry(&self, class: TrajectoryClass) -> Result<RobotGeometry, String> {
        let (cell_text, _, _, urdf_text) = self.cell_and_urdf()?;
        let spec_text = self.read(&self.trajectories_dir.join(format!("{class}.toml")))?;
        RobotGeometry::from_texts(&cell_text, &urdf_text, &spec_text)
            .map_err(|e| format!("robot geometry for the recording ({class}): {e}"))
    }

    /// Reads the cell, the URDF and the class's trajectory file: the model and the current hashes.
    fn current(&self, class: TrajectoryClass) -> Result<(RobotModel, InputHashes), String> {
        let (_, cell, urdf_path, urdf_text) = self.cell_and_urdf()?;
        let model =
            RobotModel::from_urdf_str(&urdf_text, &cell.robot.base_link, &cell.robot.flange_link)
                .map_err(|e| format!("{}: {e}", urdf_path.display()))?;
        let spec_text = self.read(&self.trajectories_dir.join(format!("{class}.toml")))?;
        let hashes = InputHashes::new(
            spec_text.as_bytes(),
            urdf_text.as_bytes(),
            &cell,
            env!("CARGO_PKG_VERSION"),
        );
        Ok((model, hashes))
    }

    /// Writes a **demo** approval of the class's current lock into `self.approvals_dir` (which must
    /// not be the repository's `trajectories/approvals/`): integrity is verified first, exactly as
    /// `ergocell trajectories approve` does, and the approver is named as a demo.
    pub fn approve_for_demo(
        &self,
        class: TrajectoryClass,
        stamp_utc: &str,
    ) -> Result<String, String> {
        if self.approvals_dir.ends_with("trajectories/approvals") {
            return Err(format!(
                "refusing to write a demo approval into {}: demo approvals live in a temporary folder",
                self.approvals_dir.display()
            ));
        }
        let (model, hashes) = self.current(class)?;
        let lock_text = self.read(&self.lock_path(class))?;
        let inputs = VerifyInputs {
            class,
            lock_toml: &lock_text,
            current_inputs: &hashes,
            model: &model,
            approvals_toml: None,
        };
        let lock = lock::verify_integrity(&inputs).map_err(|f| f.to_string())?;
        let mut file = ApprovalsFile::default();
        file.approve(
            &lock,
            "DEMO APPROVAL (ergocell demo, simulator only; not a safety engineer's sign-off)",
            stamp_utc,
        )
        .map_err(|e| e.to_string())?;
        let text = file.to_toml().map_err(|e| e.to_string())?;
        std::fs::create_dir_all(&self.approvals_dir)
            .map_err(|e| format!("cannot create {}: {e}", self.approvals_dir.display()))?;
        let path = self.approvals_dir.join(format!("{class}.toml"));
        let text = format!(
            "# DEMO APPROVAL written by `ergocell demo` for the simulator. Not a safety sign-off;\n\
             # never copy into trajectories/approvals/.\n{text}"
        );
        std::fs::write(&path, text).map_err(|e| format!("cannot write {}: {e}", path.display()))?;
        Ok(lock.lock_sha256)
    }
}

impl TrajectoryProvider for FileTrajectories {
    fn stature_bounds_m(&mut self, class: TrajectoryClass) -> Result<(f64, f64), ProviderError> {
        let path = self.trajectories_dir.join(format!("{class}.toml"));
        let spec = TrajectorySpec::from_toml_str(&self.read(&path).map_err(ProviderError)?)
            .map_err(|e| ProviderError(format!("{}: {e}", path.display())))?;
        Ok((spec.stature.min_m, spec.stature.max_m))
    }

    fn verify(&mut self, class: TrajectoryClass) -> Result<ApprovedTrajectory, ProviderError> {
        let (model, hashes) = self.current(class).map_err(ProviderError)?;
        let lock_text = self.read(&self.lock_path(class)).map_err(ProviderError)?;
        let approvals =
            std::fs::read_to_string(self.approvals_dir.join(format!("{class}.toml"))).ok();
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
