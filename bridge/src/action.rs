//! `control_msgs/action/FollowJointTrajectory`: the controller's monitored way to run a trajectory
//! (the goal is accepted or rejected, feedback while it runs, a result with an error code), as
//! ros2_control's joint_trajectory_controller serves it under kuka_drivers. The topic
//! `<controller>/joint_trajectory` is fire-and-forget (no acceptance, no result, goal tolerances
//! unused); the action is what lets ergocell know the robot ran the locked trajectory.
//!
//! CDR is positional, and control_msgs changed the Feedback between ROS 2 distributions: control_msgs
//! 6.3 and later (Kilted) have `int32 index` after `error` and `int32 multi_dof_index` at the end;
//! Jazzy's 5.x (and 6.0–6.2) have neither. [`FeedbackLayout`] picks the layout from the configured
//! distribution. Goal and Result are the same in both. Field order below is exactly the upstream
//! `.action` and `.msg` files' (control_msgs 6.8.0; `.ci/interop/rclpy/control_msgs/`).

use serde::{Deserialize, Serialize};

use crate::msg::{Duration, Header, JointTrajectory, JointTrajectoryPoint, Quaternion, Vector3};

/// `control_msgs/JointTolerance`: 0 = the controller's default, −1 = no check.
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
pub struct JointTolerance {
    pub name: String,
    /// Radians (revolute joints).
    pub position: f64,
    pub velocity: f64,
    pub acceleration: f64,
}

/// `control_msgs/JointComponentTolerance` (multi-DOF joints; ergocell sends none).
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
pub struct JointComponentTolerance {
    pub joint_name: String,
    pub component: u16,
    pub position: f64,
    pub velocity: f64,
    pub acceleration: f64,
}

/// `geometry_msgs/Transform`.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
pub struct Transform {
    pub translation: Vector3,
    pub rotation: Quaternion,
}

/// `geometry_msgs/Twist`.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
pub struct Twist {
    pub linear: Vector3,
    pub angular: Vector3,
}

/// `trajectory_msgs/MultiDOFJointTrajectoryPoint`.
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
pub struct MultiDofJointTrajectoryPoint {
    pub transforms: Vec<Transform>,
    pub velocities: Vec<Twist>,
    pub accelerations: Vec<Twist>,
    pub time_from_start: Duration,
}

/// `trajectory_msgs/MultiDOFJointTrajectory` (empty in ergocell's goals).
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
pub struct MultiDofJointTrajectory {
    pub header: Header,
    pub joint_names: Vec<String>,
    pub points: Vec<MultiDofJointTrajectoryPoint>,
}

/// The action's goal.
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
pub struct FollowJointTrajectoryGoal {
    pub trajectory: JointTrajectory,
    pub multi_dof_trajectory: MultiDofJointTrajectory,
    pub path_tolerance: Vec<JointTolerance>,
    pub component_path_tolerance: Vec<JointComponentTolerance>,
    pub goal_tolerance: Vec<JointTolerance>,
    pub component_goal_tolerance: Vec<JointComponentTolerance>,
    pub goal_time_tolerance: Duration,
}

/// The action's result.
#[derive(Debug, Clone, PartialEq, Eq, Default, Serialize, Deserialize)]
pub struct FollowJointTrajectoryResult {
    pub error_code: i32,
    pub error_string: String,
}

/// The Feedback of control_msgs 6.3+ (ROS 2 Kilted).
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
pub struct FeedbackWithIndex {
    pub header: Header,
    pub joint_names: Vec<String>,
    pub desired: JointTrajectoryPoint,
    pub actual: JointTrajectoryPoint,
    pub error: JointTrajectoryPoint,
    pub index: i32,
    pub multi_dof_joint_names: Vec<String>,
    pub multi_dof_desired: MultiDofJointTrajectoryPoint,
    pub multi_dof_actual: MultiDofJointTrajectoryPoint,
    pub multi_dof_error: MultiDofJointTrajectoryPoint,
    pub multi_dof_index: i32,
}

/// The Feedback of control_msgs 5.x (ROS 2 Jazzy) and 6.0–6.2.
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
pub struct FeedbackWithoutIndex {
    pub header: Header,
    pub joint_names: Vec<String>,
    pub desired: JointTrajectoryPoint,
    pub actual: JointTrajectoryPoint,
    pub error: JointTrajectoryPoint,
    pub multi_dof_joint_names: Vec<String>,
    pub multi_dof_desired: MultiDofJointTrajectoryPoint,
    pub multi_dof_actual: MultiDofJointTrajectoryPoint,
    pub multi_dof_error: MultiDofJointTrajectoryPoint,
}

#[cfg(feature = "transport")]
impl ros2_client::Message for FollowJointTrajectoryGoal {}
#[cfg(feature = "transport")]
impl ros2_client::Message for FollowJointTrajectoryResult {}
#[cfg(feature = "transport")]
impl ros2_client::Message for FeedbackWithIndex {}
#[cfg(feature = "transport")]
impl ros2_client::Message for FeedbackWithoutIndex {}

/// What the feedback of one message says, whatever its layout.
pub trait FeedbackView {
    /// The largest absolute joint position error (radians), if the feedback carries errors.
    fn max_position_error_rad(&self) -> Option<f64>;
}

fn max_abs(values: &[f64]) -> Option<f64> {
    values
        .iter()
        .map(|v| v.abs())
        .fold(None, |m: Option<f64>, v| Some(m.map_or(v, |m| m.max(v))))
}

impl FeedbackView for FeedbackWithIndex {
    fn max_position_error_rad(&self) -> Option<f64> {
        max_abs(&self.error.positions)
    }
}
impl FeedbackView for FeedbackWithoutIndex {
    fn max_position_error_rad(&self) -> Option<f64> {
        max_abs(&self.error.positions)
    }
}

/// Which Feedback layout the controller's control_msgs has.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum FeedbackLayout {
    /// control_msgs 6.3+ (ROS 2 Kilted and later).
    WithIndex,
    /// control_msgs 5.x (ROS 2 Jazzy, Humble) and 6.0–6.2.
    WithoutIndex,
}

impl FeedbackLayout {
    /// The layout of a ROS 2 distribution's control_msgs (`jazzy`, `humble`, `kilted`, `rolling`).
    pub fn for_distro(distro: &str) -> Option<Self> {
        match distro {
            "humble" | "jazzy" => Some(Self::WithoutIndex),
            "kilted" | "rolling" => Some(Self::WithIndex),
            _ => None,
        }
    }
}

/// `FollowJointTrajectory.Result` error codes, by name.
pub fn error_code_name(code: i32) -> &'static str {
    match code {
        0 => "SUCCESSFUL",
        -1 => "INVALID_GOAL",
        -2 => "INVALID_JOINTS",
        -3 => "OLD_HEADER_TIMESTAMP",
        -4 => "PATH_TOLERANCE_VIOLATED",
        -5 => "GOAL_TOLERANCE_VIOLATED",
        _ => "unknown error code",
    }
}

/// The tolerances ergocell puts in every goal, per joint (radians) and for the goal's time (seconds).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct GoalTolerances {
    /// Largest deviation from the trajectory while it runs.
    pub path_position_rad: f64,
    /// Largest deviation from the last point when it should have arrived.
    pub goal_position_rad: f64,
    /// How late after the last point's time the goal may still arrive.
    pub goal_time_s: f64,
}

/// The goal for `trajectory`, with `tolerances` on every joint it names; `path_rad`, when it has one
/// value per joint of the trajectory (in its order), are the joints' own path tolerances (derived from
/// the lock) instead of `tolerances.path_position_rad`.
pub fn goal(
    trajectory: JointTrajectory,
    path_rad: &[f64],
    tolerances: GoalTolerances,
) -> FollowJointTrajectoryGoal {
    let per_joint = |position: &dyn Fn(usize) -> f64| {
        trajectory
            .joint_names
            .iter()
            .enumerate()
            .map(|(j, name)| JointTolerance {
                name: name.clone(),
                position: position(j),
                velocity: 0.0,
                acceleration: 0.0,
            })
            .collect::<Vec<_>>()
    };
    let own = path_rad.len() == trajectory.joint_names.len();
    FollowJointTrajectoryGoal {
        path_tolerance: per_joint(&|j| {
            if own {
                path_rad[j]
            } else {
                tolerances.path_position_rad
            }
        }),
        goal_tolerance: per_joint(&|_| tolerances.goal_position_rad),
        goal_time_tolerance: Duration::from_secs_f64(tolerances.goal_time_s),
        trajectory,
        ..FollowJointTrajectoryGoal::default()
    }
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used, clippy::expect_used)]
    use super::*;
    use crate::cdr;

    /// The Feedback layouts differ by exactly the two `int32`s: a Kilted feedback does not decode as
    /// a Jazzy one into the same values (CDR is positional), and each round-trips.
    #[test]
    fn the_two_feedback_layouts_round_trip_and_differ_on_the_wire() {
        let point = |p: f64| JointTrajectoryPoint {
            positions: vec![p; 7],
            ..JointTrajectoryPoint::default()
        };
        let kilted = FeedbackWithIndex {
            joint_names: vec!["joint_1".into()],
            desired: point(0.5),
            actual: point(0.4),
            error: point(-0.1),
            index: 42,
            multi_dof_index: 7,
            ..FeedbackWithIndex::default()
        };
        let bytes = cdr::encode(&kilted).unwrap();
        let back: FeedbackWithIndex = cdr::decode(&bytes).unwrap();
        assert_eq!(back, kilted);
        assert!((back.max_position_error_rad().unwrap() - 0.1).abs() < 1e-15);
        let jazzy = FeedbackWithoutIndex {
            joint_names: kilted.joint_names.clone(),
            desired: kilted.desired.clone(),
            actual: kilted.actual.clone(),
            error: kilted.error.clone(),
            ..FeedbackWithoutIndex::default()
        };
        let jazzy_bytes = cdr::encode(&jazzy).unwrap();
        // Two int32s (8 bytes) and their alignment are the whole difference.
        assert_eq!(bytes.len(), jazzy_bytes.len() + 8);
        let misread: Result<FeedbackWithoutIndex, _> = cdr::decode(&bytes);
        assert!(misread.map_or(true, |m| m != jazzy));
    }

    #[test]
    fn a_goal_carries_the_trajectory_and_a_tolerance_per_joint() {
        let trajectory = JointTrajectory {
            joint_names: (1..=7).map(|i| format!("joint_{i}")).collect(),
            ..JointTrajectory::default()
        };
        let t = GoalTolerances {
            path_position_rad: 0.05,
            goal_position_rad: 0.01,
            goal_time_s: 0.5,
        };
        let own: Vec<f64> = (1..=7).map(|j| 0.01 * f64::from(j)).collect();
        let derived = goal(trajectory.clone(), &own, t);
        assert_eq!(derived.path_tolerance[2].position, 0.03);
        assert_eq!(derived.path_tolerance[2].name, "joint_3");
        assert_eq!(derived.goal_tolerance[2].position, 0.01);
        let g = goal(
            trajectory.clone(),
            &[],
            GoalTolerances {
                path_position_rad: 0.05,
                goal_position_rad: 0.01,
                goal_time_s: 0.5,
            },
        );
        assert_eq!(g.trajectory, trajectory);
        assert_eq!(g.path_tolerance.len(), 7);
        assert_eq!(g.goal_tolerance[6].name, "joint_7");
        assert_eq!(g.path_tolerance[0].position, 0.05);
        assert_eq!(g.goal_tolerance[0].position, 0.01);
        assert_eq!(g.goal_time_tolerance.as_secs_f64(), 0.5);
        assert!(g.multi_dof_trajectory.points.is_empty());
        let back: FollowJointTrajectoryGoal = cdr::decode(&cdr::encode(&g).unwrap()).unwrap();
        assert_eq!(back, g);
    }

    #[test]
    fn layouts_by_distro_and_error_codes_by_name() {
        assert_eq!(
            FeedbackLayout::for_distro("kilted"),
            Some(FeedbackLayout::WithIndex)
        );
        assert_eq!(
            FeedbackLayout::for_distro("jazzy"),
            Some(FeedbackLayout::WithoutIndex)
        );
        assert_eq!(FeedbackLayout::for_distro("iron"), None);
        assert_eq!(error_code_name(-4), "PATH_TOLERANCE_VIOLATED");
        assert_eq!(error_code_name(3), "unknown error code");
    }
}
