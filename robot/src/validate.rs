//! Planning and validation of one class's handover trajectory: IK for the via points and the handover,
//! the joint-space QP, then every check re-run on the solution, densely between knots. Only a `Solved`
//! QP with every check passing yields a [`LockedTrajectory`], a type nothing else can construct.
//!
//! The lock is a software guarantee on top of the robot's own safety controller (its safety
//! configuration, speed monitoring and stops), never a replacement for it.

use std::fmt::{self, Write as _};

use nalgebra::{Isometry3, Matrix3, Matrix6, Point3, Rotation3, UnitQuaternion, Vector3};
use serde::{Deserialize, Serialize};
use sha2::{Digest, Sha256};

use crate::config::{CellConfig, TrajectoryClass, TrajectorySpec};
use crate::ik::{solve_ik, IkSettings};
use crate::model::{tool_transform, RobotModel};
use crate::pose::pose_error;
use crate::qp::{self, QpProblem, QpStatus};
use crate::RobotError;

/// Said in every report and lock file.
pub const SAFETY_NOTE: &str =
    "This validation and lock are a software guarantee on top of the robot's own \
safety controller (safety configuration, monitored speeds and stops); they do not replace it.";

/// Anthropometric fractions of stature (Drillis & Contini 1966, tabulated by Winter).
mod anthropometry {
    pub const HIP: f64 = 0.530;
    pub const SHOULDER: f64 = 0.818;
    pub const CHIN: f64 = 0.870;
    pub const SHOULDER_WIDTH: f64 = 0.259;
    pub const UPPER_ARM: f64 = 0.186;
    pub const FOREARM: f64 = 0.146;
    pub const HAND: f64 = 0.108;
}

/// The posture a handover point is derived for: RULA's score-1 zones of the upper and lower arm.
///
/// Upper arm flexed 0–20° (RULA upper arm 1: within 20° of the trunk line, on the flexion side, where
/// a hand reaching forward is), forearm 0–20° below horizontal, elbow flexion 60–100° (RULA lower
/// arm 1), the part held at the middle of the hand. Elbow flexion is 90° − (upper arm flexion +
/// forearm angle below horizontal), so the elbow limit keeps their sum at most 30°.
pub mod grasp_posture {
    /// Upper arm flexion, radians: RULA's upper-arm score-1 zone on the flexion side.
    pub const UPPER_ARM_FLEXION_RAD: [f64; 2] = [0.0, 20.0 * std::f64::consts::PI / 180.0];
    /// Forearm angle below horizontal, radians.
    pub const FOREARM_BELOW_HORIZONTAL_RAD: [f64; 2] = [0.0, 20.0 * std::f64::consts::PI / 180.0];
    /// Elbow flexion, radians: RULA's lower-arm score-1 zone.
    pub const ELBOW_FLEXION_RAD: [f64; 2] = [
        60.0 * std::f64::consts::PI / 180.0,
        100.0 * std::f64::consts::PI / 180.0,
    ];
}

/// Where one handover point may lie for a class: height and forward distance of the grasp point, and
/// the largest lateral offset, in the station frame (metres).
///
/// Each coordinate is within what some posture of the [`grasp_posture`] zone reaches for every
/// stature of the class: a necessary condition, checked coordinate by coordinate. It is not
/// sufficient: one operator's reachable set in the zone is not a box (its low-far and high-near
/// corners are out of reach), so a point inside the band can need an elbow a little outside 60–100°
/// or a forearm a little above level for some stature. [`ArmPosture::holding`] says which;
/// the validation report lists it at both ends and the middle of the class, and the RULA outcome is
/// what the digital twin measures (`ergocell sim adaptation`).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct GraspBand {
    /// Height above the floor, [low, high]; empty when low > high.
    pub height_m: [f64; 2],
    /// Forward of the shoulder joint, [near, far]; empty when near > far.
    pub forward_m: [f64; 2],
    /// Largest |lateral| offset: half the narrowest operator's shoulder width.
    pub lateral_max_m: f64,
}

impl GraspBand {
    /// Whether the station-frame point (forward, lateral, height) lies inside the band, edges
    /// included.
    pub fn contains(&self, forward_m: f64, lateral_m: f64, height_m: f64) -> bool {
        (self.height_m[0]..=self.height_m[1]).contains(&height_m)
            && (self.forward_m[0]..=self.forward_m[1]).contains(&forward_m)
            && lateral_m.abs() <= self.lateral_max_m
    }
}

/// One operator's arm holding a point, in the sagittal plane the band is derived in: shoulder joint at
/// 0.818 H on the shoulder line, upper arm 0.186 H, forearm + half hand 0.200 H, elbow below the line
/// from shoulder to hand (angles in radians, as in [`grasp_posture`]).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct ArmPosture {
    pub stature_m: f64,
    pub upper_arm_flexion_rad: f64,
    pub forearm_below_horizontal_rad: f64,
    pub elbow_flexion_rad: f64,
}

impl ArmPosture {
    /// The posture holding a point `forward_m` ahead of the shoulder line and `height_m` above the
    /// floor; `None` when the two-link arm cannot reach it or an input is not finite.
    pub fn holding(stature_m: f64, forward_m: f64, height_m: f64) -> Option<Self> {
        use anthropometry::{FOREARM, HAND, SHOULDER, UPPER_ARM};
        let (a, b) = (UPPER_ARM * stature_m, (FOREARM + 0.5 * HAND) * stature_m);
        let (dx, dz) = (forward_m, SHOULDER * stature_m - height_m);
        let d = dx.hypot(dz);
        if !(d.is_finite() && d > 1e-9 && d <= a + b && d >= (a - b).abs()) {
            return None;
        }
        // d² = a² + b² + 2ab·cos(elbow flexion); the upper arm sits β below the shoulder–hand line.
        let elbow = ((d * d - a * a - b * b) / (2.0 * a * b))
            .clamp(-1.0, 1.0)
            .acos();
        let beta = ((a * a + d * d - b * b) / (2.0 * a * d))
            .clamp(-1.0, 1.0)
            .acos();
        let upper = dx.atan2(dz) - beta;
        Some(Self {
            stature_m,
            upper_arm_flexion_rad: upper,
            forearm_below_horizontal_rad: std::f64::consts::FRAC_PI_2 - upper - elbow,
            elbow_flexion_rad: elbow,
        })
    }

    /// Whether every angle lies in the [`grasp_posture`] zone (edges included, to 1e-9 rad).
    pub fn in_zone(&self) -> bool {
        use grasp_posture::{
            ELBOW_FLEXION_RAD, FOREARM_BELOW_HORIZONTAL_RAD, UPPER_ARM_FLEXION_RAD,
        };
        let within = |[lo, hi]: [f64; 2], x: f64| (lo - 1e-9..=hi + 1e-9).contains(&x);
        within(UPPER_ARM_FLEXION_RAD, self.upper_arm_flexion_rad)
            && within(
                FOREARM_BELOW_HORIZONTAL_RAD,
                self.forearm_below_horizontal_rad,
            )
            && within(ELBOW_FLEXION_RAD, self.elbow_flexion_rad)
    }
}

/// Grasp height and forward reach of the [`grasp_posture`] zone, as fractions of stature:
/// `([height_min, height_max], [forward_min, forward_max])`.
///
/// Shoulder joint at 0.818 H, upper arm 0.186 H, forearm 0.146 H, half the hand 0.054 H. The
/// extremes lie on the zone's corners; the zone is swept on a 0.1° grid so the elbow limit is
/// honoured wherever it cuts a corner off.
pub fn grasp_fractions() -> ([f64; 2], [f64; 2]) {
    use anthropometry::{FOREARM, HAND, SHOULDER, UPPER_ARM};
    use grasp_posture::{ELBOW_FLEXION_RAD, FOREARM_BELOW_HORIZONTAL_RAD, UPPER_ARM_FLEXION_RAD};
    let reach = FOREARM + 0.5 * HAND;
    let steps = 200_u32;
    let lerp = |[a, b]: [f64; 2], i: u32| a + (b - a) * f64::from(i) / f64::from(steps);
    let (mut height, mut forward) = (
        [f64::INFINITY, f64::NEG_INFINITY],
        [f64::INFINITY, f64::NEG_INFINITY],
    );
    for i in 0..=steps {
        let upper = lerp(UPPER_ARM_FLEXION_RAD, i);
        for j in 0..=steps {
            let below = lerp(FOREARM_BELOW_HORIZONTAL_RAD, j);
            let elbow = std::f64::consts::FRAC_PI_2 - upper - below;
            if !(ELBOW_FLEXION_RAD[0] - 1e-12..=ELBOW_FLEXION_RAD[1] + 1e-12).contains(&elbow) {
                continue;
            }
            let h = SHOULDER - UPPER_ARM * upper.cos() - reach * below.sin();
            let f = UPPER_ARM * upper.sin() + reach * below.cos();
            height = [height[0].min(h), height[1].max(h)];
            forward = [forward[0].min(f), forward[1].max(f)];
        }
    }
    (height, forward)
}

/// The band one handover point must lie in to suit every operator of stature `h_min..=h_max`: the
/// intersection of each operator's [`grasp_fractions`] scaled by stature, so the highest low edge
/// (the tallest operator's) and the lowest high edge (the shortest's).
pub fn grasp_band(h_min: f64, h_max: f64) -> GraspBand {
    let (height, forward) = grasp_fractions();
    GraspBand {
        height_m: [height[0] * h_max, height[1] * h_min],
        forward_m: [forward[0] * h_max, forward[1] * h_min],
        lateral_max_m: 0.5 * anthropometry::SHOULDER_WIDTH * h_min,
    }
}

/// Dense re-check: samples per knot interval (joint limits, Cartesian checks).
pub const JOINT_SAMPLES_PER_INTERVAL: usize = 8;
pub const CARTESIAN_SAMPLES_PER_INTERVAL: usize = 4;
/// QP limits are this fraction of the checked limits, so a cubic between knots cannot overshoot them.
const QP_LIMIT_FRACTION: f64 = 0.97;

/// SHA-256 of `bytes`, lower-case hex.
pub fn sha256_hex(bytes: &[u8]) -> String {
    let digest = Sha256::digest(bytes);
    let mut s = String::with_capacity(64);
    for b in digest {
        let _ = write!(s, "{b:02x}");
    }
    s
}

/// Hashes of everything a trajectory depends on.
#[derive(Debug, Clone, PartialEq, Eq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct InputHashes {
    /// SHA-256 of the trajectory file's bytes.
    pub trajectory_sha256: String,
    /// SHA-256 of the URDF file's bytes.
    pub urdf_sha256: String,
    /// SHA-256 of [`CellConfig::canonical_bytes`] (the `[robot]` and `[station]` tables).
    pub cell_sha256: String,
    /// The ergocell binary's version.
    pub ergocell_version: String,
    /// This crate's version (the planner and checks).
    pub planner_version: String,
}

impl InputHashes {
    pub fn new(
        trajectory_file: &[u8],
        urdf_file: &[u8],
        cell: &CellConfig,
        ergocell_version: &str,
    ) -> Self {
        Self {
            trajectory_sha256: sha256_hex(trajectory_file),
            urdf_sha256: sha256_hex(urdf_file),
            cell_sha256: sha256_hex(&cell.canonical_bytes()),
            ergocell_version: ergocell_version.to_owned(),
            planner_version: env!("CARGO_PKG_VERSION").to_owned(),
        }
    }
}

/// Per-joint limits and the margins the trajectory keeps to them.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct JointMargins {
    pub urdf_name: String,
    pub controller_name: String,
    pub lower_rad: f64,
    pub upper_rad: f64,
    pub position_min_rad: f64,
    pub position_max_rad: f64,
    /// min(position_min − lower, upper − position_max).
    pub position_margin_rad: f64,
    /// The trajectory's velocity limit: `velocity_scale` × URDF limit.
    pub velocity_limit_rad_s: f64,
    pub velocity_peak_rad_s: f64,
    pub velocity_margin_rad_s: f64,
    /// The trajectory's acceleration limit: `acceleration_scale` × cell limit.
    pub acceleration_limit_rad_s2: f64,
    pub acceleration_peak_rad_s2: f64,
    pub acceleration_margin_rad_s2: f64,
}

/// Handover point against the class's anthropometric band.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct HandoverCheck {
    /// Target in the station frame: forward, lateral, height (m).
    pub target_station_m: [f64; 3],
    pub height_band_m: [f64; 2],
    pub forward_band_m: [f64; 2],
    pub lateral_max_m: f64,
    pub inside_band: bool,
    /// The planar arm holding the target at the class's shortest, middle and tallest stature
    /// (information for the reviewer; `None` where the arm cannot reach it). See [`GraspBand`].
    pub arm_postures: Vec<(f64, Option<ArmPosture>)>,
    /// FK of the final knot against the target.
    pub fk_position_error_m: f64,
    pub fk_orientation_error_rad: f64,
}

/// Cartesian TCP speed.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct TcpSpeedCheck {
    pub zone_radius_m: f64,
    pub limit_in_zone_m_s: f64,
    pub peak_in_zone_m_s: f64,
    pub peak_anywhere_m_s: f64,
    pub samples_in_zone: usize,
    pub samples: usize,
}

/// Minimum distance between the arm's capsules and the class's body envelope.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct SeparationCheck {
    pub min_separation_m: f64,
    pub required_m: f64,
    pub arm_segment: String,
    pub body_part: String,
    pub at_time_s: f64,
}

/// Smallest singular value of the Jacobian along the trajectory.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct SingularityCheck {
    pub min_singular_value: f64,
    pub required: f64,
    pub at_time_s: f64,
}

/// Boundary conditions and the consistency of the stored samples.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct BoundaryCheck {
    pub start_equals_home: bool,
    pub end_at_rest: bool,
    /// Largest |q(t_{k+1}) − cubic from knot k| over all intervals (rad).
    pub integration_residual_rad: f64,
    pub time_strictly_increasing: bool,
}

/// The QP's outcome.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct QpSummary {
    pub status: QpStatus,
    pub iterations: u32,
    pub solve_time_ms: f64,
    pub variables: usize,
    pub equality_rows: usize,
    pub inequality_rows: usize,
    pub knots: usize,
    pub dt_s: f64,
    pub duration_s: f64,
}

/// One IK solve (via points, then the handover).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct IkSummary {
    pub label: String,
    pub time_s: f64,
    pub positions_rad: Vec<f64>,
    pub seed_index: usize,
    pub iterations: usize,
}

/// What a safety engineer reads. Text via `Display` (degrees), JSON via serde (SI units).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ValidationReport {
    pub class: TrajectoryClass,
    pub description: String,
    pub accepted: bool,
    pub reasons: Vec<String>,
    pub robot: String,
    pub stature_m: [f64; 2],
    pub tool: String,
    pub handover: HandoverCheck,
    pub joints: Vec<JointMargins>,
    pub tcp_speed: TcpSpeedCheck,
    pub separation: SeparationCheck,
    pub singularity: SingularityCheck,
    pub boundary: BoundaryCheck,
    pub qp: QpSummary,
    pub ik: Vec<IkSummary>,
    /// False when the QP was not solved: the check values below are then not a trajectory's.
    pub checks_run: bool,
    pub dense_samples_per_interval: usize,
    pub inputs: InputHashes,
    pub note: String,
}

/// A validated trajectory: only [`plan_and_validate`] builds one, and only from a `Solved` QP with
/// every check passing.
#[derive(Debug, Clone, PartialEq)]
pub struct LockedTrajectory {
    class: TrajectoryClass,
    joint_names: Vec<String>,
    dt_s: f64,
    time_s: Vec<f64>,
    positions_rad: Vec<Vec<f64>>,
    velocities_rad_s: Vec<Vec<f64>>,
    accelerations_rad_s2: Vec<Vec<f64>>,
    inputs: InputHashes,
    report: ValidationReport,
}

impl LockedTrajectory {
    pub fn class(&self) -> TrajectoryClass {
        self.class
    }
    /// The controller's joint names (from the cell config), in column order.
    pub fn joint_names(&self) -> &[String] {
        &self.joint_names
    }
    pub fn dt_s(&self) -> f64 {
        self.dt_s
    }
    /// `time_from_start` of each knot.
    pub fn time_s(&self) -> &[f64] {
        &self.time_s
    }
    /// `[knot][joint]`.
    pub fn positions_rad(&self) -> &[Vec<f64>] {
        &self.positions_rad
    }
    pub fn velocities_rad_s(&self) -> &[Vec<f64>] {
        &self.velocities_rad_s
    }
    pub fn accelerations_rad_s2(&self) -> &[Vec<f64>] {
        &self.accelerations_rad_s2
    }
    pub fn inputs(&self) -> &InputHashes {
        &self.inputs
    }
    pub fn report(&self) -> &ValidationReport {
        &self.report
    }
}

/// The outcome of [`plan_and_validate`]: always a report; a lock only if accepted.
#[derive(Debug, Clone)]
pub struct Validation {
    pub report: ValidationReport,
    locked: Option<LockedTrajectory>,
}

impl Validation {
    pub fn locked(&self) -> Option<&LockedTrajectory> {
        self.locked.as_ref()
    }
    /// The locked trajectory, or [`RobotError::Rejected`] with the report's reasons.
    pub fn into_locked(self) -> Result<LockedTrajectory, RobotError> {
        match self.locked {
            Some(l) => Ok(l),
            None => Err(RobotError::Rejected {
                class: self.report.class.to_string(),
                reasons: self.report.reasons,
            }),
        }
    }
}

/// Everything [`plan_and_validate`] needs. The binary reads the files and computes the hashes.
#[derive(Debug, Clone, Copy)]
pub struct PlanInputs<'a> {
    pub model: &'a RobotModel,
    pub cell: &'a CellConfig,
    pub spec: &'a TrajectorySpec,
    pub hashes: &'a InputHashes,
}

/// `R_station_tool`: tool z along the approach direction, tool x as close to "down" as possible.
fn approach_rotation(approach: [f64; 3]) -> UnitQuaternion<f64> {
    let z = Vector3::from(approach).normalize();
    let down = Vector3::new(0.0, 0.0, -1.0);
    let mut x = down - z * z.dot(&down);
    if x.norm() < 1e-6 {
        let fwd = Vector3::x();
        x = fwd - z * z.dot(&fwd);
    }
    let x = x.normalize();
    let y = z.cross(&x);
    UnitQuaternion::from_rotation_matrix(&Rotation3::from_matrix_unchecked(Matrix3::from_columns(
        &[x, y, z],
    )))
}

/// Body capsules of the class in the cell frame: (name, a, b, radius).
fn body_capsules(
    cell: &CellConfig,
    spec: &TrajectorySpec,
) -> Vec<(&'static str, Point3<f64>, Point3<f64>, f64)> {
    use anthropometry::{CHIN, HIP, SHOULDER};
    let T_cell_station = cell.T_cell_station();
    let (h_min, h_max) = (spec.stature.min_m, spec.stature.max_m);
    let at = |z: f64| T_cell_station * Point3::new(0.0, 0.0, z);
    let r_head = spec.envelope.head_radius_m;
    let head_lo = CHIN * h_min + r_head;
    let head_hi = (h_max - r_head).max(head_lo);
    vec![
        (
            "torso",
            at(HIP * h_min),
            at(SHOULDER * h_max),
            spec.envelope.torso_radius_m,
        ),
        ("head", at(head_lo), at(head_hi), r_head),
    ]
}

/// Distance between segments [p1,q1] and [p2,q2] (Ericson, Real-Time Collision Detection, 5.1.9).
fn segment_distance(p1: &Point3<f64>, q1: &Point3<f64>, p2: &Point3<f64>, q2: &Point3<f64>) -> f64 {
    let d1 = q1 - p1;
    let d2 = q2 - p2;
    let r = p1 - p2;
    let a = d1.dot(&d1);
    let e = d2.dot(&d2);
    let f = d2.dot(&r);
    let eps = 1e-12;
    let (s, t);
    if a <= eps && e <= eps {
        return r.norm();
    }
    if a <= eps {
        s = 0.0;
        t = (f / e).clamp(0.0, 1.0);
    } else {
        let c = d1.dot(&r);
        if e <= eps {
            t = 0.0;
            s = (-c / a).clamp(0.0, 1.0);
        } else {
            let b = d1.dot(&d2);
            let denom = a * e - b * b;
            let mut s0 = if denom > eps {
                ((b * f - c * e) / denom).clamp(0.0, 1.0)
            } else {
                0.0
            };
            let mut t0 = (b * s0 + f) / e;
            if t0 < 0.0 {
                t0 = 0.0;
                s0 = (-c / a).clamp(0.0, 1.0);
            } else if t0 > 1.0 {
                t0 = 1.0;
                s0 = ((b - c) / a).clamp(0.0, 1.0);
            }
            s = s0;
            t = t0;
        }
    }
    let c1 = p1 + d1 * s;
    let c2 = p2 + d2 * t;
    (c1 - c2).norm()
}

/// State of joint `j` at `tau` seconds into interval `k` (cubic with constant jerk).
fn cubic(
    q: &[Vec<f64>],
    v: &[Vec<f64>],
    a: &[Vec<f64>],
    k: usize,
    j: usize,
    tau: f64,
    dt: f64,
) -> (f64, f64, f64) {
    let jerk = (a[k + 1][j] - a[k][j]) / dt;
    let pos = q[k][j] + v[k][j] * tau + 0.5 * a[k][j] * tau * tau + jerk * tau * tau * tau / 6.0;
    let vel = v[k][j] + a[k][j] * tau + 0.5 * jerk * tau * tau;
    let acc = a[k][j] + jerk * tau;
    (pos, vel, acc)
}

/// Plan and validate one class. `Err` for unusable input (a target out of reach, a home pose outside the
/// limits, malformed sizes); a plan that fails a check is an `Ok` whose report says why.
pub fn plan_and_validate(inputs: &PlanInputs<'_>) -> Result<Validation, RobotError> {
    let PlanInputs {
        model,
        cell,
        spec,
        hashes,
    } = *inputs;
    let dof = model.dof();
    let controller_names = cell.robot.controller_joint_names.names(dof)?;
    if cell.robot.max_acceleration_rad_s2.len() != dof {
        return Err(RobotError::DofMismatch {
            what: "robot.max_acceleration_rad_s2".to_owned(),
            expected: dof,
            got: cell.robot.max_acceleration_rad_s2.len(),
        });
    }
    let home = spec.home.positions_rad.clone();
    model.check_positions(&home)?;

    // Frames.
    let T_cell_base = cell.T_cell_base();
    let T_cell_station = cell.T_cell_station();
    let T_base_station = T_cell_base.inverse() * T_cell_station;
    let T_flange_tcp = tool_transform(spec.tool.tcp_from_flange_m);
    let R_station_tool = approach_rotation(spec.handover.approach_direction);
    let h = &spec.handover;
    let p_station_handover = Vector3::new(h.forward_m, h.lateral_m, h.height_m);
    let T_station_handover = Isometry3::from_parts(p_station_handover.into(), R_station_tool);
    let T_base_handover = T_base_station * T_station_handover;

    // IK: via points in time order, then the handover; each seeded from the previous solution.
    let margin = cell.robot.position_margin_rad;
    let ik_settings = IkSettings {
        limit_margin_rad: margin + 0.01,
        ..IkSettings::default()
    };
    let duration = spec.timing.duration_s;
    let n = spec.timing.knots;
    let dt = duration / (n - 1) as f64;
    let mut targets: Vec<(String, f64, Isometry3<f64>)> = spec
        .via
        .iter()
        .enumerate()
        .map(|(i, v)| {
            let T_station_via = Isometry3::from_parts(
                (p_station_handover + Vector3::from(v.offset_m)).into(),
                R_station_tool,
            );
            (
                format!("via[{i}]"),
                v.time_s,
                T_base_station * T_station_via,
            )
        })
        .collect();
    targets.push(("handover".to_owned(), duration, T_base_handover));
    let mut ik = Vec::new();
    let mut previous = home.clone();
    for (label, time_s, T_base_target) in &targets {
        let sol = solve_ik(
            model,
            T_base_target,
            &T_flange_tcp,
            std::slice::from_ref(&previous),
            &ik_settings,
        )?;
        previous.clone_from(&sol.positions_rad);
        ik.push(IkSummary {
            label: label.clone(),
            time_s: *time_s,
            positions_rad: sol.positions_rad,
            seed_index: sol.seed_index,
            iterations: sol.iterations,
        });
    }
    let q_end = previous;

    // QP.
    let v_lim: Vec<f64> = model
        .joints()
        .iter()
        .map(|j| spec.limits.velocity_scale * j.velocity_rad_s)
        .collect();
    let a_lim: Vec<f64> = cell
        .robot
        .max_acceleration_rad_s2
        .iter()
        .map(|a| spec.limits.acceleration_scale * a)
        .collect();
    let vias: Vec<(usize, Vec<f64>)> = ik[..ik.len() - 1]
        .iter()
        .map(|s| {
            (
                ((s.time_s / dt).round() as usize).clamp(1, n - 2),
                s.positions_rad.clone(),
            )
        })
        .collect();
    let problem = QpProblem {
        dt_s: dt,
        knots: n,
        q_start: home.clone(),
        q_end: q_end.clone(),
        vias,
        q_lower: model
            .joints()
            .iter()
            .map(|j| j.lower_rad + margin)
            .collect(),
        q_upper: model
            .joints()
            .iter()
            .map(|j| j.upper_rad - margin)
            .collect(),
        v_max: v_lim.iter().map(|v| v * QP_LIMIT_FRACTION).collect(),
        a_max: a_lim.iter().map(|a| a * QP_LIMIT_FRACTION).collect(),
        jerk_weight_s2: spec.timing.jerk_weight_s2,
    };
    let sol = qp::solve(&problem)?;
    let (q, mut v, mut a) = (sol.q.clone(), sol.v.clone(), sol.a.clone());
    // Snap the boundary to exact rest (the solver meets it to ~1e-9); the checks below run on what is stored.
    let mut q = q;
    for (pos, target) in q[0].iter_mut().zip(&home) {
        if (*pos - target).abs() < 1e-6 {
            *pos = *target;
        }
    }
    for (pos, target) in q[n - 1].iter_mut().zip(&q_end) {
        if (*pos - target).abs() < 1e-6 {
            *pos = *target;
        }
    }
    for k in [0, n - 1] {
        for x in v[k].iter_mut().chain(a[k].iter_mut()) {
            if x.abs() < 1e-6 {
                *x = 0.0;
            }
        }
    }
    let time_s: Vec<f64> = (0..n).map(|k| k as f64 * dt).collect();
    let mut reasons = Vec::new();
    if sol.status != QpStatus::Solved {
        reasons.push(format!(
            "QP status {} after {} iterations (only Solved is accepted{})",
            sol.status,
            sol.iterations,
            if sol.status == QpStatus::PrimalInfeasible {
                ": the limits cannot be met in this duration, or the via points are inconsistent"
            } else {
                ""
            }
        ));
    }
    let finite = q
        .iter()
        .chain(&v)
        .chain(&a)
        .all(|row| row.iter().all(|x| x.is_finite()));
    if !finite {
        reasons.push("QP returned non-finite values".to_owned());
    }
    // The checks below only mean something on a solved QP (otherwise x is a certificate, not a
    // trajectory); they still run so the report shows numbers, but only a solved QP adds reasons.
    let checks_run = sol.status == QpStatus::Solved && finite;
    let mut check_reasons = Vec::new();

    // Boundary and integration consistency.
    let start_equals_home = q[0] == home;
    let end_at_rest = v[n - 1]
        .iter()
        .chain(&a[n - 1])
        .chain(&v[0])
        .chain(&a[0])
        .all(|x| *x == 0.0);
    let mut residual = 0.0_f64;
    for k in 0..n - 1 {
        for j in 0..dof {
            let (pos, vel, _) = cubic(&q, &v, &a, k, j, dt, dt);
            residual = residual
                .max((pos - q[k + 1][j]).abs())
                .max((vel - v[k + 1][j]).abs() * dt);
        }
    }
    let time_strictly_increasing = time_s.windows(2).all(|w| w[1] > w[0]);
    if !start_equals_home {
        check_reasons.push("first point differs from the home pose".to_owned());
    }
    if !end_at_rest {
        check_reasons.push("trajectory does not start and end at rest".to_owned());
    }
    if !(residual <= 1e-6) {
        check_reasons.push(format!(
            "stored samples inconsistent with the cubic model (residual {residual:.2e} rad)"
        ));
    }
    if !time_strictly_increasing {
        check_reasons.push("time_from_start not strictly increasing".to_owned());
    }

    // Dense joint-limit re-check.
    let mut joints = Vec::with_capacity(dof);
    for (j, lim) in model.joints().iter().enumerate() {
        let (mut qmin, mut qmax, mut vpk, mut apk) =
            (f64::INFINITY, f64::NEG_INFINITY, 0.0_f64, 0.0_f64);
        for k in 0..n - 1 {
            for s in 0..=JOINT_SAMPLES_PER_INTERVAL {
                let tau = dt * s as f64 / JOINT_SAMPLES_PER_INTERVAL as f64;
                let (pos, vel, acc) = cubic(&q, &v, &a, k, j, tau, dt);
                qmin = qmin.min(pos);
                qmax = qmax.max(pos);
                vpk = vpk.max(vel.abs());
                apk = apk.max(acc.abs());
            }
        }
        let m = JointMargins {
            urdf_name: lim.name.clone(),
            controller_name: controller_names[j].clone(),
            lower_rad: lim.lower_rad,
            upper_rad: lim.upper_rad,
            position_min_rad: qmin,
            position_max_rad: qmax,
            position_margin_rad: (qmin - lim.lower_rad).min(lim.upper_rad - qmax),
            velocity_limit_rad_s: v_lim[j],
            velocity_peak_rad_s: vpk,
            velocity_margin_rad_s: v_lim[j] - vpk,
            acceleration_limit_rad_s2: a_lim[j],
            acceleration_peak_rad_s2: apk,
            acceleration_margin_rad_s2: a_lim[j] - apk,
        };
        if !(m.position_margin_rad >= 0.0) {
            let (pos, limit) = if qmin - lim.lower_rad < lim.upper_rad - qmax {
                (qmin, lim.lower_rad)
            } else {
                (qmax, lim.upper_rad)
            };
            check_reasons.push(format!(
                "{}: position {:.2}° outside limit {:.2}°",
                lim.name,
                pos.to_degrees(),
                limit.to_degrees()
            ));
        }
        if !(m.velocity_margin_rad_s >= 0.0) {
            check_reasons.push(format!(
                "{}: velocity {:.2}°/s over limit {:.2}°/s",
                lim.name,
                vpk.to_degrees(),
                v_lim[j].to_degrees()
            ));
        }
        if !(m.acceleration_margin_rad_s2 >= 0.0) {
            check_reasons.push(format!(
                "{}: acceleration {:.2}°/s² over limit {:.2}°/s²",
                lim.name,
                apk.to_degrees(),
                a_lim[j].to_degrees()
            ));
        }
        joints.push(m);
    }

    // Dense Cartesian checks: TCP speed in the collaborative zone, separation, singularity margin.
    let body = body_capsules(cell, spec);
    let T_station_cell = T_cell_station.inverse();
    let zone_r = cell.robot.collaborative_zone_radius_m;
    let mut tcp = TcpSpeedCheck {
        zone_radius_m: zone_r,
        limit_in_zone_m_s: cell.robot.collaborative_tcp_speed_max_m_s,
        peak_in_zone_m_s: 0.0,
        peak_anywhere_m_s: 0.0,
        samples_in_zone: 0,
        samples: 0,
    };
    let mut sep = SeparationCheck {
        min_separation_m: f64::INFINITY,
        required_m: spec.envelope.min_separation_m,
        arm_segment: String::new(),
        body_part: String::new(),
        at_time_s: 0.0,
    };
    let mut sing = SingularityCheck {
        min_singular_value: f64::INFINITY,
        required: cell.robot.min_singular_value,
        at_time_s: 0.0,
    };
    let mut qs = vec![0.0; dof];
    let mut qds = vec![0.0; dof];
    if checks_run {
        for k in 0..n - 1 {
            let last = k == n - 2;
            let samples = CARTESIAN_SAMPLES_PER_INTERVAL + usize::from(last);
            for s in 0..samples {
                let tau = dt * s as f64 / CARTESIAN_SAMPLES_PER_INTERVAL as f64;
                let t = time_s[k] + tau;
                for j in 0..dof {
                    let (pos, vel, _) = cubic(&q, &v, &a, k, j, tau, dt);
                    qs[j] = pos;
                    qds[j] = vel;
                }
                let (T_base_tcp, J) = model.jacobian_unchecked(&qs, &T_flange_tcp);
                let qd = nalgebra::DVector::from_column_slice(&qds);
                let twist = &J * qd;
                let speed = twist.fixed_rows::<3>(0).norm();
                let p_station_tcp =
                    T_station_cell * (T_cell_base * Point3::from(T_base_tcp.translation.vector));
                let in_zone = p_station_tcp.x.hypot(p_station_tcp.y) <= zone_r;
                tcp.samples += 1;
                tcp.peak_anywhere_m_s = tcp.peak_anywhere_m_s.max(speed);
                if in_zone {
                    tcp.samples_in_zone += 1;
                    tcp.peak_in_zone_m_s = tcp.peak_in_zone_m_s.max(speed);
                }
                let JJt: Matrix6<f64> = &J * J.transpose();
                let sigma_min = JJt.symmetric_eigenvalues().min().max(0.0).sqrt();
                if sigma_min < sing.min_singular_value {
                    sing.min_singular_value = sigma_min;
                    sing.at_time_s = t;
                }
                let pts: Vec<Point3<f64>> = model
                    .link_points_unchecked(&qs, &T_flange_tcp)
                    .into_iter()
                    .map(|p| T_cell_base * p)
                    .collect();
                let n_seg = pts.len() - 1;
                for (i, w) in pts.windows(2).enumerate() {
                    let r_arm = if i + 1 == n_seg {
                        spec.tool.radius_m
                    } else {
                        cell.robot.link_radius_m
                    };
                    for (name, b0, b1, r_body) in &body {
                        let d = segment_distance(&w[0], &w[1], b0, b1) - r_arm - r_body;
                        if d < sep.min_separation_m {
                            sep.min_separation_m = d;
                            sep.arm_segment = segment_name(model, i, n_seg);
                            (*name).clone_into(&mut sep.body_part);
                            sep.at_time_s = t;
                        }
                    }
                }
            }
        }
    }
    if !(tcp.peak_in_zone_m_s <= tcp.limit_in_zone_m_s) {
        check_reasons.push(format!(
            "TCP speed {:.3} m/s in the collaborative zone exceeds {:.3} m/s",
            tcp.peak_in_zone_m_s, tcp.limit_in_zone_m_s
        ));
    }
    if !(sep.min_separation_m >= sep.required_m) {
        check_reasons.push(format!(
            "separation {:.3} m between {} and the operator's {} at t = {:.2} s is below {:.3} m",
            sep.min_separation_m, sep.arm_segment, sep.body_part, sep.at_time_s, sep.required_m
        ));
    }
    if !(sing.min_singular_value >= sing.required) {
        check_reasons.push(format!(
            "Jacobian's smallest singular value {:.4} at t = {:.2} s is below {:.4} (near a singularity)",
            sing.min_singular_value, sing.at_time_s, sing.required
        ));
    }

    // Handover inside the class's band, and the final knot's FK on the target.
    let (h_min, h_max) = (spec.stature.min_m, spec.stature.max_m);
    let band = grasp_band(h_min, h_max);
    let (height_band_m, forward_band_m, lateral_max_m) =
        (band.height_m, band.forward_m, band.lateral_max_m);
    let inside_band = band.contains(h.forward_m, h.lateral_m, h.height_m);
    let T_base_end = model.fk_flange_unchecked(&q[n - 1]) * T_flange_tcp;
    let (fk_dp, fk_dr) = pose_error(&T_base_end, &T_base_handover);
    if !inside_band {
        // An input check: reported whether or not the QP solved.
        reasons.push(format!(
            "handover (forward {:.3}, lateral {:.3}, height {:.3}) m is outside the class band: height {:.3}–{:.3} m, \
             forward {:.3}–{:.3} m, |lateral| ≤ {:.3} m",
            h.forward_m,
            h.lateral_m,
            h.height_m,
            height_band_m[0],
            height_band_m[1],
            forward_band_m[0],
            forward_band_m[1],
            lateral_max_m
        ));
    }
    if !(fk_dp <= 1e-3 && fk_dr <= 1e-2) {
        check_reasons.push(format!(
            "final point misses the handover target by {fk_dp:.4} m / {:.2}°",
            fk_dr.to_degrees()
        ));
    }

    if checks_run {
        reasons.extend(check_reasons);
    }

    let report = ValidationReport {
        class: spec.class,
        description: spec.description.clone(),
        accepted: reasons.is_empty(),
        reasons,
        robot: model.name().to_owned(),
        stature_m: [h_min, h_max],
        tool: spec.tool.name.clone(),
        handover: HandoverCheck {
            target_station_m: [h.forward_m, h.lateral_m, h.height_m],
            height_band_m,
            forward_band_m,
            lateral_max_m,
            inside_band,
            arm_postures: [h_min, 0.5 * (h_min + h_max), h_max]
                .into_iter()
                .map(|stature| {
                    (
                        stature,
                        ArmPosture::holding(stature, h.forward_m, h.height_m),
                    )
                })
                .collect(),
            fk_position_error_m: fk_dp,
            fk_orientation_error_rad: fk_dr,
        },
        joints,
        tcp_speed: tcp,
        separation: sep,
        singularity: sing,
        boundary: BoundaryCheck {
            start_equals_home,
            end_at_rest,
            integration_residual_rad: residual,
            time_strictly_increasing,
        },
        qp: QpSummary {
            status: sol.status,
            iterations: sol.iterations,
            solve_time_ms: sol.solve_time_s * 1e3,
            variables: sol.variables,
            equality_rows: sol.equality_rows,
            inequality_rows: sol.inequality_rows,
            knots: n,
            dt_s: dt,
            duration_s: duration,
        },
        ik,
        checks_run,
        dense_samples_per_interval: JOINT_SAMPLES_PER_INTERVAL,
        inputs: hashes.clone(),
        note: SAFETY_NOTE.to_owned(),
    };
    let locked = report.accepted.then(|| LockedTrajectory {
        class: spec.class,
        joint_names: controller_names,
        dt_s: dt,
        time_s,
        positions_rad: q,
        velocities_rad_s: v,
        accelerations_rad_s2: a,
        inputs: hashes.clone(),
        report: report.clone(),
    });
    Ok(Validation { report, locked })
}

fn segment_name(model: &RobotModel, i: usize, n_seg: usize) -> String {
    if i + 1 == n_seg {
        "tool (flange→TCP)".to_owned()
    } else if i == 0 {
        format!("{} link", model.base_link())
    } else {
        format!("segment {i} (chain element {i}→{})", i + 1)
    }
}

impl fmt::Display for ValidationReport {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let verdict = if self.accepted {
            "ACCEPTED"
        } else {
            "REJECTED"
        };
        writeln!(
            f,
            "Trajectory validation — class {} — {verdict}",
            self.class
        )?;
        writeln!(f, "  {}", self.description)?;
        writeln!(
            f,
            "  robot {}; tool {}; stature {:.2}–{:.2} m",
            self.robot, self.tool, self.stature_m[0], self.stature_m[1]
        )?;
        for r in &self.reasons {
            writeln!(f, "  REJECTED because: {r}")?;
        }
        if !self.checks_run {
            writeln!(
                f,
                "  (QP not solved: the check values below describe the solver's last iterate, not a trajectory)"
            )?;
        }
        let q = &self.qp;
        writeln!(
            f,
            "QP (clarabel): status {}, {} iterations, {:.2} ms; {} variables, {} equality + {} inequality rows; \
             {} knots, dt {:.4} s, duration {:.2} s",
            q.status,
            q.iterations,
            q.solve_time_ms,
            q.variables,
            q.equality_rows,
            q.inequality_rows,
            q.knots,
            q.dt_s,
            q.duration_s
        )?;
        writeln!(
            f,
            "Joint margins (re-checked at {} samples per knot interval):",
            self.dense_samples_per_interval
        )?;
        writeln!(
            f,
            "  {:<10} {:<10} {:>17} {:>17} {:>9} | {:>8} {:>8} {:>8} | {:>9} {:>9} {:>9}",
            "joint",
            "controller",
            "range used [°]",
            "limits [°]",
            "margin°",
            "v pk°/s",
            "v lim",
            "margin",
            "a pk°/s²",
            "a lim",
            "margin"
        )?;
        for j in &self.joints {
            writeln!(
                f,
                "  {:<10} {:<10} {:>8.2}..{:<7.2} {:>8.1}..{:<7.1} {:>9.2} | {:>8.2} {:>8.2} {:>8.2} | {:>9.2} {:>9.2} {:>9.2}",
                j.urdf_name,
                j.controller_name,
                j.position_min_rad.to_degrees(),
                j.position_max_rad.to_degrees(),
                j.lower_rad.to_degrees(),
                j.upper_rad.to_degrees(),
                j.position_margin_rad.to_degrees(),
                j.velocity_peak_rad_s.to_degrees(),
                j.velocity_limit_rad_s.to_degrees(),
                j.velocity_margin_rad_s.to_degrees(),
                j.acceleration_peak_rad_s2.to_degrees(),
                j.acceleration_limit_rad_s2.to_degrees(),
                j.acceleration_margin_rad_s2.to_degrees()
            )?;
        }
        let t = &self.tcp_speed;
        writeln!(
            f,
            "TCP speed: peak {:.3} m/s in the collaborative zone (limit {:.3} m/s, zone radius {:.2} m, {} of {} samples \
             in zone); peak anywhere {:.3} m/s",
            t.peak_in_zone_m_s, t.limit_in_zone_m_s, t.zone_radius_m, t.samples_in_zone, t.samples, t.peak_anywhere_m_s
        )?;
        let s = &self.separation;
        writeln!(
            f,
            "Separation: min {:.3} m (required {:.3} m) between {} and the operator's {} at t = {:.2} s",
            s.min_separation_m, s.required_m, s.arm_segment, s.body_part, s.at_time_s
        )?;
        let g = &self.singularity;
        writeln!(
            f,
            "Singularity margin: smallest singular value of J {:.4} (required {:.4}) at t = {:.2} s",
            g.min_singular_value, g.required, g.at_time_s
        )?;
        let h = &self.handover;
        writeln!(
            f,
            "Handover (station frame): forward {:.3} m, lateral {:.3} m, height {:.3} m; band: height {:.3}–{:.3} m, \
             forward {:.3}–{:.3} m, |lateral| ≤ {:.3} m: {}; FK error {:.2} mm / {:.3}°",
            h.target_station_m[0],
            h.target_station_m[1],
            h.target_station_m[2],
            h.height_band_m[0],
            h.height_band_m[1],
            h.forward_band_m[0],
            h.forward_band_m[1],
            h.lateral_max_m,
            if h.inside_band { "inside" } else { "OUTSIDE" },
            h.fk_position_error_m * 1e3,
            h.fk_orientation_error_rad.to_degrees()
        )?;
        for (stature, posture) in &h.arm_postures {
            match posture {
                Some(p) => writeln!(
                    f,
                    "  arm of a {stature:.2} m operator holding it (planar model): upper arm {:.1}°, forearm {:.1}° {} level, elbow {:.1}°{}",
                    p.upper_arm_flexion_rad.to_degrees(),
                    p.forearm_below_horizontal_rad.to_degrees().abs(),
                    if p.forearm_below_horizontal_rad < 0.0 {
                        "above"
                    } else {
                        "below"
                    },
                    p.elbow_flexion_rad.to_degrees(),
                    if p.in_zone() {
                        ""
                    } else {
                        " (outside the zone: upper arm 0–20°, forearm 0–20° down, elbow 60–100°)"
                    }
                )?,
                None => writeln!(
                    f,
                    "  arm of a {stature:.2} m operator holding it (planar model): out of reach"
                )?,
            }
        }
        let b = &self.boundary;
        writeln!(
            f,
            "Boundary: starts at home {}, starts and ends at rest {}, time strictly increasing {}, cubic residual {:.1e} rad",
            b.start_equals_home, b.end_at_rest, b.time_strictly_increasing, b.integration_residual_rad
        )?;
        for s in &self.ik {
            let deg: Vec<String> = s
                .positions_rad
                .iter()
                .map(|x| format!("{:.1}", x.to_degrees()))
                .collect();
            writeln!(
                f,
                "IK {} at t = {:.2} s: [{}]° (seed {}, {} iterations)",
                s.label,
                s.time_s,
                deg.join(", "),
                s.seed_index,
                s.iterations
            )?;
        }
        let i = &self.inputs;
        writeln!(f, "Inputs (SHA-256):")?;
        writeln!(f, "  trajectory file   {}", i.trajectory_sha256)?;
        writeln!(f, "  URDF              {}", i.urdf_sha256)?;
        writeln!(
            f,
            "  cell config       {}  ([robot] + [station], canonical JSON)",
            i.cell_sha256
        )?;
        writeln!(
            f,
            "  ergocell version  {} (planner {})",
            i.ergocell_version, i.planner_version
        )?;
        writeln!(f, "Note: {}", self.note)
    }
}
