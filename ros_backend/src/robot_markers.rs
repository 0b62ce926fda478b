//! The robot as the recording shows it: the TCP in the world from the recorded joint states (forward
//! kinematics of the cell's URDF and the trajectory's tool) and the class's handover point — the
//! `/ergocell/robot_markers` topic that Foxglove and `ergocell review` draw.

use ergocell_bridge::msg::JointState;
use ergocell_robot::{CellConfig, RobotError, RobotModel, TrajectorySpec};
use nalgebra::{Isometry3, Point3};

/// What the recorder needs of the robot to place its TCP and handover point in the world.
#[derive(Debug, Clone)]
pub struct RobotGeometry {
    model: RobotModel,
    /// The controller's joint names, in the model's joint order.
    joint_names: Vec<String>,
    T_world_base: Isometry3<f64>,
    T_flange_tcp: Isometry3<f64>,
    handover_world: Point3<f64>,
}

impl RobotGeometry {
    /// From the texts of `config/cell.toml`, its URDF and the class's trajectory file.
    pub fn from_texts(cell: &str, urdf: &str, spec: &str) -> Result<Self, RobotError> {
        let cell = CellConfig::from_toml_str(cell)?;
        let model =
            RobotModel::from_urdf_str(urdf, &cell.robot.base_link, &cell.robot.flange_link)?;
        let spec = TrajectorySpec::from_toml_str(spec)?;
        let joint_names = cell.robot.controller_joint_names.names(model.dof())?;
        let [x, y, z] = spec.tool.tcp_from_flange_m;
        let h = &spec.handover;
        Ok(Self {
            joint_names,
            T_world_base: cell.T_cell_base(),
            T_flange_tcp: Isometry3::translation(x, y, z),
            handover_world: cell.handover_world([h.forward_m, h.lateral_m, h.height_m]),
            model,
        })
    }

    /// The class's handover point in the world.
    pub fn handover_world(&self) -> Point3<f64> {
        self.handover_world
    }

    /// The TCP in the world for a joint state (matched by joint name); `None` when a joint is
    /// missing or a position is not finite.
    pub fn tcp_world(&self, js: &JointState) -> Option<Point3<f64>> {
        let q: Vec<f64> = self
            .joint_names
            .iter()
            .map(|n| {
                let i = js.name.iter().position(|m| m == n)?;
                js.position.get(i).copied().filter(|v| v.is_finite())
            })
            .collect::<Option<_>>()?;
        let T_base_tcp = self.model.fk_tcp(&q, &self.T_flange_tcp).ok()?;
        Some(self.T_world_base * T_base_tcp * Point3::origin())
    }
}

/// The robot's geometry for the recording's markers (TCP and handover point) of `class`.
pub fn robot_geometry(
    provider: &ergocell_approvals::FileTrajectories,
    class: ergocell_robot::TrajectoryClass,
) -> Result<RobotGeometry, ergocell_cell::session::ProviderError> {
    let texts = provider.geometry_texts(class)?;
    RobotGeometry::from_texts(&texts.cell, &texts.urdf, &texts.spec).map_err(|cause| {
        ergocell_cell::session::ProviderError::Geometry {
            class,
            cause: Box::new(cause),
        }
    })
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)]
    use super::*;

    fn geometry() -> RobotGeometry {
        let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
        let read = |p: &str| std::fs::read_to_string(root.join(p)).unwrap();
        RobotGeometry::from_texts(
            &read("config/cell.toml"),
            &read("config/robots/iiwa14_r820.urdf"),
            &read("trajectories/c2.toml"),
        )
        .unwrap()
    }

    #[test]
    fn the_tcp_at_zero_is_above_the_base_and_joints_are_matched_by_name() {
        let g = geometry();
        let names: Vec<String> = (1..=7).map(|i| format!("joint_{i}")).collect();
        let js = JointState {
            name: names.clone(),
            position: vec![0.0; 7],
            ..JointState::default()
        };
        // q = 0: the arm stands straight up, flange 1.306 m above the base, tool 0.15 m further;
        // the base is at (1.35, 0, 0.65) in the cell.
        let p = g.tcp_world(&js).unwrap();
        assert!(
            (p - Point3::new(1.35, 0.0, 0.65 + 1.306 + 0.15)).norm() < 1e-6,
            "{p}"
        );
        // The same joint state listed in another order gives the same TCP.
        let mut rev = js.clone();
        rev.name.reverse();
        assert_eq!(g.tcp_world(&rev), Some(p));
        // A missing joint or a NaN: no TCP.
        let mut short = js.clone();
        short.name.pop();
        short.position.pop();
        assert_eq!(g.tcp_world(&short), None);
        let mut nan = js;
        nan.position[3] = f64::NAN;
        assert_eq!(g.tcp_world(&nan), None);
    }
}
