//! Every file in `config/` and `trajectories/` parses, and every URDF loads.

// Test and bench helpers panic on purpose: a panic is the failure report.
#![allow(clippy::unwrap_used, clippy::expect_used)]

mod common;

use std::path::{Path, PathBuf};

use ergocell_robot::lock::{ApprovalsFile, LockFile};
use ergocell_robot::{
    CellConfig, RobotModel, TrajectoryClass, TrajectoryFile, TrajectoryLayout, TrajectorySpec,
};

fn files(dir: &Path, out: &mut Vec<PathBuf>) {
    for entry in std::fs::read_dir(dir).unwrap() {
        let path = entry.unwrap().path();
        if path.is_dir() {
            files(&path, out);
        } else {
            out.push(path);
        }
    }
}

#[test]
fn every_file_in_config_and_trajectories_parses() {
    let root = common::repo_root();
    let layout = TrajectoryLayout::new(root.join(TrajectoryLayout::DEFAULT_DIR));
    let mut all = Vec::new();
    files(&root.join("config"), &mut all);
    files(layout.dir(), &mut all);
    let mut checked = 0;
    for path in &all {
        let text =
            std::fs::read_to_string(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
        let name = path.file_name().unwrap().to_string_lossy().to_string();
        match path.extension().and_then(|e| e.to_str()) {
            Some("toml") => {
                let _: toml::Table =
                    toml::from_str(&text).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
                if name == "cell.toml" {
                    CellConfig::from_toml_str(&text)
                        .unwrap_or_else(|e| panic!("{}: {e}", path.display()));
                } else if let Some((file, class)) = layout.identify(path) {
                    match file {
                        TrajectoryFile::Spec => {
                            let spec = TrajectorySpec::from_toml_str(&text)
                                .unwrap_or_else(|e| panic!("{}: {e}", path.display()));
                            assert_eq!(spec.class, class, "{}", path.display());
                        }
                        TrajectoryFile::Lock => {
                            LockFile::from_toml_str(class, &text)
                                .unwrap_or_else(|e| panic!("{}: {e}", path.display()));
                        }
                        TrajectoryFile::Approvals => {
                            ApprovalsFile::from_toml_str(&text)
                                .unwrap_or_else(|e| panic!("{}: {e}", path.display()));
                        }
                    }
                } else if name == "handover_rula.toml" {
                    // The classes' RULA curves (read by the height decision, not the robot): a
                    // stature list and one equally long list per class.
                    let t: toml::Table = toml::from_str(&text).unwrap();
                    let len = |k: &str| t[k].as_array().map(Vec::len).unwrap_or_default();
                    assert!(len("statures_m") >= 2, "{}", path.display());
                    for class in ["c1", "c2", "c3"] {
                        assert_eq!(len(class), len("statures_m"), "{}: {class}", path.display());
                    }
                } else {
                    assert!(
                        !path.starts_with(layout.dir()),
                        "{}: not a file of the trajectories layout (<class>.toml, \
                         locks/<class>.lock.toml, approvals/<class>.toml)",
                        path.display()
                    );
                }
            }
            Some("urdf") => {
                let robot = urdf_rs::read_from_string(&text)
                    .unwrap_or_else(|e| panic!("{}: {e}", path.display()));
                assert!(!robot.joints.is_empty(), "{}", path.display());
            }
            Some("json") => {
                let _: serde_json::Value = serde_json::from_str(&text)
                    .unwrap_or_else(|e| panic!("{}: {e}", path.display()));
            }
            _ => continue,
        }
        checked += 1;
    }
    assert!(checked >= 5, "checked only {checked} files");
}

#[test]
fn the_cell_config_urdf_loads_with_its_links() {
    let s = common::shipped();
    assert_eq!(s.model.dof(), 7);
    assert_eq!(s.model.name(), "lbr_iiwa_14_r820");
    let again = RobotModel::from_urdf_str(&s.urdf, "link_0", "flange").unwrap();
    assert_eq!(again.joints(), s.model.joints());
}

#[test]
fn unknown_fields_are_rejected_in_robot_tables() {
    let s = common::shipped();
    let bad = s
        .cell_text
        .replace("\n[station]\n", "\n[station]\nheight = 1\n");
    let err = CellConfig::from_toml_str(&bad).unwrap_err();
    assert!(err.to_string().contains("unknown field"), "{err}");
    let spec = common::spec_text(TrajectoryClass::C1).replace("[tool]", "[tool]\ncolor = \"red\"");
    assert!(TrajectorySpec::from_toml_str(&spec).is_err());
}
