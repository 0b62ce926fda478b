//! Configuration the robot crate owns: the `[robot]`, `[station]` and `[monitor]` tables of `config/cell.toml`
//! and the per-class trajectory files `trajectories/c1.toml`… Parsed from strings; the binary reads the
//! files and puts the path into every error it reports.
//!
//! Frames: `cell` is the world frame of the cell (z up, floor at z = 0). `T_cell_base` places the robot's
//! `base_link`; `T_cell_station` places the operator station: origin on the floor below the midpoint of
//! the operator's shoulders, x toward the robot (forward for the operator), y to the operator's left, z up.

use std::fmt;
use std::str::FromStr;

use nalgebra::{Isometry3, Point3, Translation3, UnitQuaternion};
use serde::{Deserialize, Serialize};

use crate::monitor::MonitorLimits;
use crate::pose::isometry_from_xyz_rpy;
use crate::RobotError;

/// A trajectory class: one handover trajectory per operator height class.
///
/// The ergonomics crate decides an operator's height class; this crate only knows the three trajectory
/// classes and the stature bounds written in each trajectory file.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum TrajectoryClass {
    C1,
    C2,
    C3,
}

impl TrajectoryClass {
    pub const ALL: [Self; 3] = [Self::C1, Self::C2, Self::C3];
    /// `c1`, `c2`, `c3`: also the file stem in `trajectories/`.
    pub fn as_str(self) -> &'static str {
        match self {
            Self::C1 => "c1",
            Self::C2 => "c2",
            Self::C3 => "c3",
        }
    }
}

impl fmt::Display for TrajectoryClass {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.as_str())
    }
}

impl FromStr for TrajectoryClass {
    type Err = RobotError;
    fn from_str(s: &str) -> Result<Self, Self::Err> {
        match s.trim().to_ascii_lowercase().as_str() {
            "c1" => Ok(Self::C1),
            "c2" => Ok(Self::C2),
            "c3" => Ok(Self::C3),
            other => Err(RobotError::Config {
                reason: format!("unknown trajectory class `{other}` (expected c1, c2 or c3)"),
            }),
        }
    }
}

/// Joint names the robot controller uses.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize, Default)]
#[serde(rename_all = "snake_case")]
pub enum JointNaming {
    /// `joint_1..joint_n` (kroshu/kuka_drivers).
    #[default]
    KukaDrivers,
    /// `lbr_A1..lbr_An` (lbr-stack/lbr_fri_ros2_stack).
    LbrFriRos2Stack,
}

/// Either a naming convention or an explicit list.
#[derive(Debug, Clone, PartialEq, Eq, Serialize, Deserialize)]
#[serde(untagged)]
pub enum ControllerJointNames {
    Convention(JointNaming),
    Explicit(Vec<String>),
}

impl Default for ControllerJointNames {
    fn default() -> Self {
        Self::Convention(JointNaming::KukaDrivers)
    }
}

impl ControllerJointNames {
    /// The controller's joint names for an arm with `dof` joints.
    pub fn names(&self, dof: usize) -> Result<Vec<String>, RobotError> {
        match self {
            Self::Convention(JointNaming::KukaDrivers) => {
                Ok((1..=dof).map(|i| format!("joint_{i}")).collect())
            }
            Self::Convention(JointNaming::LbrFriRos2Stack) => {
                Ok((1..=dof).map(|i| format!("lbr_A{i}")).collect())
            }
            Self::Explicit(names) if names.len() == dof => Ok(names.clone()),
            Self::Explicit(names) => Err(RobotError::DofMismatch {
                what: "robot.controller_joint_names".to_owned(),
                expected: dof,
                got: names.len(),
            }),
        }
    }
}

/// `[robot]` table of `config/cell.toml`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RobotCellConfig {
    /// URDF path, relative to the directory of the cell config file.
    pub urdf: String,
    pub base_link: String,
    pub flange_link: String,
    /// `T_cell_base`: translation (m).
    pub base_xyz_m: [f64; 3],
    /// `T_cell_base`: roll, pitch, yaw (rad).
    pub base_rpy_rad: [f64; 3],
    #[serde(default)]
    pub controller_joint_names: ControllerJointNames,
    /// Per-joint acceleration limits (rad/s²); URDF has none.
    pub max_acceleration_rad_s2: Vec<f64>,
    /// Radius of the capsules around the arm's joint-to-joint segments (m).
    pub link_radius_m: f64,
    /// The collaborative zone: a vertical cylinder of this radius around the station's z axis (m).
    pub collaborative_zone_radius_m: f64,
    /// Reduced TCP speed inside the collaborative zone (m/s; ISO 10218-2:2025 / ISO/TS 15066: 0.25).
    pub collaborative_tcp_speed_max_m_s: f64,
    /// Smallest allowed singular value of the 6×n Jacobian along the trajectory (singularity margin).
    pub min_singular_value: f64,
    /// The QP keeps positions this far inside the URDF limits (rad).
    pub position_margin_rad: f64,
}

/// `[station]` table: the operator station's pose in the cell.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct StationConfig {
    pub xyz_m: [f64; 3],
    pub yaw_rad: f64,
}

/// The parts of `config/cell.toml` this crate reads. Other top-level tables belong to other crates and
/// are ignored here; the tables read are strict (`deny_unknown_fields`).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct CellConfig {
    pub robot: RobotCellConfig,
    pub station: StationConfig,
    /// `[monitor]` (optional, [`MonitorLimits::default`] without it): the execution monitor's
    /// limits, which a lock records and its approval signs.
    #[serde(default)]
    pub monitor: MonitorLimits,
}

impl CellConfig {
    pub fn from_toml_str(text: &str) -> Result<Self, RobotError> {
        let cfg: Self = toml::from_str(text).map_err(|e| RobotError::Config {
            reason: e.to_string(),
        })?;
        cfg.check()?;
        Ok(cfg)
    }

    fn check(&self) -> Result<(), RobotError> {
        let r = &self.robot;
        let all_finite = r
            .base_xyz_m
            .iter()
            .chain(&r.base_rpy_rad)
            .chain(&self.station.xyz_m)
            .all(|v| v.is_finite())
            && self.station.yaw_rad.is_finite();
        if !all_finite {
            return config_err("robot.base_* and station.* must be finite numbers");
        }
        positive("robot.link_radius_m", r.link_radius_m)?;
        positive(
            "robot.collaborative_zone_radius_m",
            r.collaborative_zone_radius_m,
        )?;
        positive(
            "robot.collaborative_tcp_speed_max_m_s",
            r.collaborative_tcp_speed_max_m_s,
        )?;
        positive("robot.min_singular_value", r.min_singular_value)?;
        positive("robot.position_margin_rad", r.position_margin_rad)?;
        for (i, a) in r.max_acceleration_rad_s2.iter().enumerate() {
            positive(&format!("robot.max_acceleration_rad_s2[{i}]"), *a)?;
        }
        self.monitor.check().map_err(|e| RobotError::Config {
            reason: e.to_string(),
        })?;
        Ok(())
    }

    /// `T_cell_base`.
    pub fn T_cell_base(&self) -> Isometry3<f64> {
        isometry_from_xyz_rpy(self.robot.base_xyz_m, self.robot.base_rpy_rad)
    }

    /// `T_cell_station`.
    pub fn T_cell_station(&self) -> Isometry3<f64> {
        station_pose(self.station.xyz_m, self.station.yaw_rad)
    }

    /// A class's handover point (the station's frame: forward, lateral, height) in the cell's
    /// world frame ([`handover_world`]).
    pub fn handover_world(&self, handover_station_m: [f64; 3]) -> Point3<f64> {
        handover_world(&self.T_cell_station(), handover_station_m)
    }

    /// Canonical bytes of the robot-relevant configuration (what the lock's `cell_sha256` covers):
    /// compact JSON of the `[robot]`, `[station]` and `[monitor]` tables as parsed. Comments, formatting and other
    /// crates' tables do not change it; any value that changes the motion does.
    pub fn canonical_bytes(&self) -> Vec<u8> {
        serde_json::to_vec(self).unwrap_or_default()
    }
}

/// `T_world_station` of a station at `xyz_m` (world frame, metres) turned `yaw_rad` about the
/// world's vertical: the `[station]` table. The session and the robot side both build it here.
pub fn station_pose(xyz_m: [f64; 3], yaw_rad: f64) -> Isometry3<f64> {
    let [x, y, z] = xyz_m;
    Isometry3::from_parts(
        Translation3::new(x, y, z),
        UnitQuaternion::from_euler_angles(0.0, 0.0, yaw_rad),
    )
}

/// The handover point in the world: `T_world_station` applied to the point the trajectory and its
/// lock give in the station's frame (`[forward, lateral, height]`, metres; the lock's
/// `handover_station_m`). The one place a handover point is put in the world: the session machine,
/// `demo`, `sim` and the robot markers all call it, so a cell whose station is turned or moved
/// sees one point everywhere.
#[allow(non_snake_case)]
pub fn handover_world(
    T_world_station: &Isometry3<f64>,
    handover_station_m: [f64; 3],
) -> Point3<f64> {
    let [forward, lateral, height] = handover_station_m;
    T_world_station * Point3::new(forward, lateral, height)
}

/// Stature bounds (m) of a class. `min_m..=max_m` is the class itself, for which the handover
/// point is derived (the grasp band); `served_min_m..=served_max_m`, wider, is what the trajectory
/// is validated and served for (the body envelope of the separation check covers it): the height
/// decision may choose a neighbouring class for an operator near a boundary, and this is how far it
/// may reach. Left out, the served range is the class's own.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct StatureBounds {
    pub min_m: f64,
    pub max_m: f64,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub served_min_m: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub served_max_m: Option<f64>,
}

impl StatureBounds {
    /// The statures the trajectory is validated and served for, `(min_m, max_m)`.
    pub fn served_m(&self) -> (f64, f64) {
        (
            self.served_min_m.unwrap_or(self.min_m),
            self.served_max_m.unwrap_or(self.max_m),
        )
    }
}

/// The handover point in the station frame and the direction of the final approach.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Handover {
    /// Forward of the shoulder line (station x), m.
    pub forward_m: f64,
    /// To the operator's left (station y), m; negative = right-hand side.
    pub lateral_m: f64,
    /// Above the floor (station z), m.
    pub height_m: f64,
    /// Direction of the TCP's final motion in the station frame (robot → operator); the tool's z axis.
    pub approach_direction: [f64; 3],
}

/// A via point: an offset from the handover point (station frame, same orientation) and when to pass it.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ViaPoint {
    pub offset_m: [f64; 3],
    pub time_s: f64,
}

/// The tool on the flange.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Tool {
    pub name: String,
    /// TCP position in the flange frame (m).
    pub tcp_from_flange_m: [f64; 3],
    /// Capsule radius of the flange→TCP segment (tool + part), m.
    pub radius_m: f64,
}

/// Speed limits of this trajectory as fractions of the robot's limits.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SpeedLimits {
    /// Fraction of each joint's URDF velocity limit, in (0, 1].
    pub velocity_scale: f64,
    /// Fraction of each joint's acceleration limit from the cell config, in (0, 1].
    pub acceleration_scale: f64,
}

/// Time grid of the QP.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Timing {
    pub duration_s: f64,
    /// Number of knots including both ends.
    pub knots: usize,
    /// Weight of ∫ jerk² relative to ∫ acceleration² (s²).
    pub jerk_weight_s2: f64,
}

/// The home pose the trajectory starts from.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Home {
    pub positions_rad: Vec<f64>,
}

/// The class's body envelope around the station and the required clearance.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Envelope {
    /// Torso capsule radius (m), vertical axis at the station origin, from the hip of the shortest to
    /// the shoulder of the tallest operator of the class.
    pub torso_radius_m: f64,
    /// Head capsule radius (m), from the chin of the shortest to the vertex of the tallest operator.
    pub head_radius_m: f64,
    /// Minimum distance between any arm capsule and the envelope (m).
    pub min_separation_m: f64,
}

/// One trajectory file, `trajectories/<class>.toml`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct TrajectorySpec {
    pub class: TrajectoryClass,
    pub description: String,
    pub stature: StatureBounds,
    pub handover: Handover,
    #[serde(default)]
    pub via: Vec<ViaPoint>,
    pub tool: Tool,
    pub limits: SpeedLimits,
    pub timing: Timing,
    pub home: Home,
    pub envelope: Envelope,
}

impl TrajectorySpec {
    pub fn from_toml_str(text: &str) -> Result<Self, RobotError> {
        let spec: Self = toml::from_str(text).map_err(|e| RobotError::Config {
            reason: e.to_string(),
        })?;
        spec.check()?;
        Ok(spec)
    }

    fn check(&self) -> Result<(), RobotError> {
        let s = &self.stature;
        if !(s.min_m.is_finite()
            && s.max_m.is_finite()
            && 1.0 < s.min_m
            && s.min_m < s.max_m
            && s.max_m < 2.5)
        {
            return config_err(&format!(
                "stature bounds must satisfy 1.0 < min_m < max_m < 2.5 (got {} .. {})",
                s.min_m, s.max_m
            ));
        }
        let (lo, hi) = s.served_m();
        if !(lo.is_finite()
            && hi.is_finite()
            && 1.0 < lo
            && lo <= s.min_m
            && s.max_m <= hi
            && hi < 2.5)
        {
            return config_err(&format!(
                "served statures must contain the class's: 1.0 < served_min_m <= min_m < max_m <= \
                 served_max_m < 2.5 (got served {lo} .. {hi}, class {} .. {})",
                s.min_m, s.max_m
            ));
        }
        let h = &self.handover;
        if ![h.forward_m, h.lateral_m, h.height_m]
            .iter()
            .all(|v| v.is_finite())
        {
            return config_err("handover position must be finite");
        }
        let d = h.approach_direction;
        let n = (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt();
        if !(n.is_finite() && n > 1e-6) {
            return config_err("handover.approach_direction must be a non-zero vector");
        }
        for (name, v) in [
            ("limits.velocity_scale", self.limits.velocity_scale),
            ("limits.acceleration_scale", self.limits.acceleration_scale),
        ] {
            if !(v > 0.0 && v <= 1.0) {
                return config_err(&format!("{name} must be in (0, 1], got {v}"));
            }
        }
        positive("timing.duration_s", self.timing.duration_s)?;
        if !(self.timing.jerk_weight_s2.is_finite() && self.timing.jerk_weight_s2 >= 0.0) {
            return config_err("timing.jerk_weight_s2 must be ≥ 0");
        }
        if !(10..=1000).contains(&self.timing.knots) {
            return config_err(&format!(
                "timing.knots must be in 10..=1000, got {}",
                self.timing.knots
            ));
        }
        let mut last = 0.0;
        for (i, v) in self.via.iter().enumerate() {
            if !(v.time_s > last
                && v.time_s < self.timing.duration_s
                && v.offset_m.iter().all(|x| x.is_finite()))
            {
                return config_err(&format!(
                    "via[{i}].time_s = {} must increase strictly inside (0, duration_s = {})",
                    v.time_s, self.timing.duration_s
                ));
            }
            last = v.time_s;
        }
        positive("tool.radius_m", self.tool.radius_m)?;
        if !self.tool.tcp_from_flange_m.iter().all(|x| x.is_finite()) {
            return config_err("tool.tcp_from_flange_m must be finite");
        }
        positive("envelope.torso_radius_m", self.envelope.torso_radius_m)?;
        positive("envelope.head_radius_m", self.envelope.head_radius_m)?;
        positive("envelope.min_separation_m", self.envelope.min_separation_m)?;
        if !self.home.positions_rad.iter().all(|x| x.is_finite()) {
            return config_err("home.positions_rad must be finite");
        }
        Ok(())
    }
}

fn config_err<T>(reason: &str) -> Result<T, RobotError> {
    Err(RobotError::Config {
        reason: reason.to_owned(),
    })
}

fn positive(name: &str, v: f64) -> Result<(), RobotError> {
    if v.is_finite() && v > 0.0 {
        Ok(())
    } else {
        config_err(&format!("{name} must be a positive number, got {v}"))
    }
}
