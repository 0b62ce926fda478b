//! Shared fixtures: the shipped cell config, URDF and trajectory files.
#![allow(dead_code, clippy::unwrap_used, clippy::expect_used)]

use std::path::{Path, PathBuf};

use ergocell_robot::{
    CellConfig, InputHashes, RobotModel, TrajectoryClass, TrajectoryLayout, TrajectorySpec,
};

pub fn repo_root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("..")
}

/// A file by its path relative to the repository root.
pub fn read(rel: impl AsRef<Path>) -> String {
    let rel = rel.as_ref();
    std::fs::read_to_string(repo_root().join(rel))
        .unwrap_or_else(|e| panic!("{}: {e}", rel.display()))
}

/// The repository's trajectories folder, relative to its root (read with [`read`]).
pub fn layout() -> TrajectoryLayout {
    TrajectoryLayout::default()
}

pub struct Shipped {
    pub cell_text: String,
    pub cell: CellConfig,
    pub urdf: String,
    pub model: RobotModel,
}

pub fn shipped() -> Shipped {
    let cell_text = read("config/cell.toml");
    let cell = CellConfig::from_toml_str(&cell_text).unwrap();
    let urdf = read(format!("config/{}", cell.robot.urdf));
    let model =
        RobotModel::from_urdf_str(&urdf, &cell.robot.base_link, &cell.robot.flange_link).unwrap();
    Shipped {
        cell_text,
        cell,
        urdf,
        model,
    }
}

pub fn spec_text(class: TrajectoryClass) -> String {
    read(layout().spec(class))
}

pub fn hashes(s: &Shipped, spec_text: &str) -> InputHashes {
    InputHashes::new(spec_text.as_bytes(), s.urdf.as_bytes(), &s.cell, "test")
}

pub fn spec(class: TrajectoryClass) -> TrajectorySpec {
    TrajectorySpec::from_toml_str(&spec_text(class)).unwrap()
}
