//! Planning and validation of one class's handover trajectory: IK for the via points and the handover,
//! the joint-space QP, then every check re-run on the solution, densely between knots. Only a `Solved`
//! QP with every check passing yields a [`LockedTrajectory`], a type nothing else can construct.
//!
//! The lock is a software guarantee on top of the robot's own safety controller (its safety
//! configuration, speed monitoring and stops), never a replacement for it.

use std::fmt::{self, Write as _};

// Fractions of stature (Drillis & Contini 1966, tabulated by Winter): the workspace's one table.
use ergocell_anthropometry as anthropometry;
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
/// Two bands are built from the [`grasp_posture`] zone. [`class_band`], the one validation
/// checks: each coordinate within what the zone reaches for *some* stature of the class, so a point
/// outside it is, in some coordinate, out of every class operator's zone (a point inside may still
/// be out of everyone's: the band holds each coordinate's range, not the zone). Which
/// point inside it suits the class's people best is measured, not assumed: the posture cost on the
/// digital twin (`ergocell trajectories design`). [`grasp_band`]: within what it reaches for
/// *every* stature of the class (the bands' intersection), which for a class 14–18 cm wide is a
/// box 2–6 cm high and 8–10 cm forward, and on the twin costs the neck more than it spares the arm.
///
/// Either is a condition checked coordinate by coordinate. It is not
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
        use anthropometry::{FOREARM, HAND, SHOULDER_HEIGHT, UPPER_ARM};
        let (a, b) = (UPPER_ARM * stature_m, (FOREARM + 0.5 * HAND) * stature_m);
        let (dx, dz) = (forward_m, SHOULDER_HEIGHT * stature_m - height_m);
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
    use anthropometry::{FOREARM, HAND, SHOULDER_HEIGHT, UPPER_ARM};
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
            let h = SHOULDER_HEIGHT - UPPER_ARM * upper.cos() - reach * below.sin();
            let f = UPPER_ARM * upper.sin() + reach * below.cos();
            height = [height[0].min(h), height[1].max(h)];
            forward = [forward[0].min(f), forward[1].max(f)];
        }
    }
    (height, forward)
}

/// The band validation checks a class's handover against: the union of each operator's
/// [`grasp_fractions`] scaled by stature over `h_min..=h_max`, so the shortest operator's low edge
/// and the tallest's high edge. The lateral limit stays the narrowest operator's.
pub fn class_band(h_min: f64, h_max: f64) -> GraspBand {
    let (height, forward) = grasp_fractions();
    GraspBand {
        height_m: [height[0] * h_min, height[1] * h_max],
        forward_m: [forward[0] * h_min, forward[1] * h_max],
        lateral_max_m: 0.5 * anthropometry::SHOULDER_WIDTH * h_min,
    }
}

/// The band one handover point would lie in to suit every operator of stature `h_min..=h_max` in
/// the zone: the intersection of each operator's [`grasp_fractions`] scaled by stature, so the
/// highest low edge (the tallest operator's) and the lowest high edge (the shortest's). For
/// reference; validation checks [`class_band`].
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

/// The bytes of the approvers' trust files ([`crate::signing`]), which every lock covers.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct TrustFiles<'a> {
    /// [`crate::signing::ALLOWED_SIGNERS`]'s bytes.
    pub allowed_signers: &'a [u8],
    /// [`crate::signing::REVOKED_KEYS`]'s bytes.
    pub revoked_keys: &'a [u8],
}

/// Hashes of everything a trajectory depends on.
#[derive(Debug, Clone, PartialEq, Eq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct InputHashes {
    /// SHA-256 of the trajectory file's bytes.
    pub trajectory_sha256: String,
    /// SHA-256 of the URDF file's bytes.
    pub urdf_sha256: String,
    /// SHA-256 of [`CellConfig::canonical_bytes`] (the `[robot]`, `[station]` and `[monitor]` tables).
    pub cell_sha256: String,
    /// SHA-256 of the trusted approvers' file ([`crate::signing::ALLOWED_SIGNERS`]): adding a key
    /// is a change the lock sees.
    pub allowed_signers_sha256: String,
    /// SHA-256 of the revocation list ([`crate::signing::REVOKED_KEYS`]).
    pub revoked_keys_sha256: String,
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
        trust: TrustFiles<'_>,
        ergocell_version: &str,
    ) -> Self {
        Self {
            trajectory_sha256: sha256_hex(trajectory_file),
            urdf_sha256: sha256_hex(urdf_file),
            cell_sha256: sha256_hex(&cell.canonical_bytes()),
            allowed_signers_sha256: sha256_hex(trust.allowed_signers),
            revoked_keys_sha256: sha256_hex(trust.revoked_keys),
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
    /// The statures the trajectory is validated and served for (the body envelope's).
    pub served_stature_m: [f64; 2],
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
    /// The execution monitor's path tolerance per joint, radians, derived here from the separation
    /// margin this validation found and the arm's lever arms along the locked samples
    /// ([`crate::monitor::path_tolerances_of`], at most [`PATH_TOLERANCE_MAX_RAD`]); locked and
    /// signed with the trajectory. Empty when the checks did not run or left no margin.
    pub path_tolerance_rad: Vec<f64>,
    /// The execution monitor's other limits, the cell's `[monitor]`: locked and signed with the
    /// trajectory.
    pub monitor: crate::monitor::MonitorLimits,
    pub inputs: InputHashes,
    pub note: String,
}

/// The largest path tolerance a lock derives for a joint (a joint whose motion moves nothing: half a
/// turn is no tolerance at all); the cell caps it further (`[ros] path_tolerance_rad`).
pub const PATH_TOLERANCE_MAX_RAD: f64 = std::f64::consts::PI;

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
    use anthropometry::{CHIN_HEIGHT, HIP_HEIGHT, SHOULDER_HEIGHT};
    let T_cell_station = cell.T_cell_station();
    // Every operator the trajectory may serve, not only the class's own.
    let (h_min, h_max) = spec.stature.served_m();
    let at = |z: f64| T_cell_station * Point3::new(0.0, 0.0, z);
    let r_head = spec.envelope.head_radius_m;
    let head_lo = CHIN_HEIGHT * h_min + r_head;
    let head_hi = (h_max - r_head).max(head_lo);
    vec![
        (
            "torso",
            at(HIP_HEIGHT * h_min),
            at(SHOULDER_HEIGHT * h_max),
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
///
/// A composition of stages, each testable on its own: `check_inputs` → `resolve_targets` →
/// `solve_knots` → `plan_trajectory` → `check_qp`, then the check families on the planned trajectory:
/// `check_boundary`, `check_joint_limits`, `sample_cartesian` feeding `check_tcp_speed`,
/// `check_separation` and `check_singularity`, and `check_handover`. The report lists the reasons in
/// that order: the QP's, the handover band's (an input check, so reported whether or not the QP
/// solved), then the checks' — only when the QP solved, since otherwise its iterate is a certificate,
/// not a trajectory (the checks still run so the report shows numbers).
pub fn plan_and_validate(inputs: &PlanInputs<'_>) -> Result<Validation, RobotError> {
    let PlanInputs {
        model,
        cell,
        spec,
        hashes,
    } = *inputs;
    let controller_names = check_inputs(model, cell, spec)?;
    let home = &spec.home.positions_rad;
    let (frames, targets) = resolve_targets(cell, spec);
    let knots = solve_knots(
        model,
        &frames,
        &targets,
        home,
        cell.robot.position_margin_rad,
    )?;
    let limits = checked_limits(model, cell, spec);
    let (trajectory, qp) = plan_trajectory(model, cell, spec, &knots, &limits)?;

    let solved = check_qp(&qp, &trajectory);
    let checks_run = solved.value;
    let boundary = check_boundary(&trajectory, home);
    let joints = check_joint_limits(model, &controller_names, &trajectory, &limits);
    let samples = if checks_run {
        sample_cartesian(model, &frames, &trajectory)
    } else {
        Vec::new()
    };
    let tcp_speed = check_tcp_speed(&samples, cell);
    let separation = check_separation(&samples, &body_capsules(cell, spec), model, cell, spec);
    let singularity = check_singularity(&samples, cell);
    let handover = check_handover(model, spec, &frames, &trajectory);
    let margin_m = separation.value.min_separation_m - separation.value.required_m;
    let path_tolerance_rad = if checks_run && margin_m > 0.0 {
        let knots: Vec<&[f64]> = trajectory.q.iter().map(Vec::as_slice).collect();
        crate::monitor::path_tolerances_of(
            model,
            &frames.T_flange_tcp,
            &knots,
            margin_m,
            PATH_TOLERANCE_MAX_RAD,
        )?
    } else {
        Vec::new()
    };

    let mut reasons = solved.reasons;
    reasons.extend(handover.outside_band);
    if checks_run && path_tolerance_rad.is_empty() {
        reasons.push(format!(
            "no path tolerance for the execution monitor: the separation margin is {margin_m:.4} m"
        ));
    }
    if checks_run {
        reasons.extend(
            boundary
                .reasons
                .into_iter()
                .chain(joints.reasons)
                .chain(tcp_speed.reasons)
                .chain(separation.reasons)
                .chain(singularity.reasons)
                .chain(handover.fk_miss),
        );
    }
    let report = ValidationReport {
        class: spec.class,
        description: spec.description.clone(),
        accepted: reasons.is_empty(),
        reasons,
        robot: model.name().to_owned(),
        stature_m: [spec.stature.min_m, spec.stature.max_m],
        served_stature_m: {
            let (lo, hi) = spec.stature.served_m();
            [lo, hi]
        },
        tool: spec.tool.name.clone(),
        handover: handover.check,
        joints: joints.value,
        tcp_speed: tcp_speed.value,
        separation: separation.value,
        singularity: singularity.value,
        boundary: boundary.value,
        qp,
        ik: knots.ik,
        checks_run,
        dense_samples_per_interval: JOINT_SAMPLES_PER_INTERVAL,
        path_tolerance_rad,
        monitor: cell.monitor,
        inputs: hashes.clone(),
        note: SAFETY_NOTE.to_owned(),
    };
    Ok(seal(report, controller_names, trajectory))
}

/// One check family's outcome: the values the report shows, and the reasons it rejects the plan for
/// (empty when the family passes). Every family returns one, so each can be tested on its own and the
/// composition only has to order the reasons.
#[derive(Debug, Clone, PartialEq)]
struct Findings<T> {
    value: T,
    reasons: Vec<String>,
}

/// The frames a plan works in, resolved once from the cell config and the trajectory file so that the
/// IK, the Cartesian sampling and the handover check all use the same transforms.
// Transforms are named by their frames (`T_cell_base`), so every field starts with `T`.
#[allow(clippy::struct_field_names)]
#[derive(Debug, Clone, Copy, PartialEq)]
struct Frames {
    /// The robot base in the cell (the arm's link points are checked in the cell frame).
    T_cell_base: Isometry3<f64>,
    /// The cell in the station frame (the collaborative zone is a cylinder about the station's z).
    T_station_cell: Isometry3<f64>,
    /// The tool's TCP on the flange.
    T_flange_tcp: Isometry3<f64>,
    /// The handover pose in the base frame: the final knot's IK target and what its FK is checked against.
    T_base_handover: Isometry3<f64>,
}

/// One pose the IK must reach, and when.
#[derive(Debug, Clone, PartialEq)]
struct IkTarget {
    /// `via[i]` or `handover`, as in the report.
    label: String,
    time_s: f64,
    T_base_target: Isometry3<f64>,
}

/// A joint trajectory on the knot grid: `[knot][joint]` samples of a cubic with constant jerk per
/// interval, as the QP models it and the lock stores it.
#[derive(Debug, Clone, PartialEq)]
struct Trajectory {
    dt_s: f64,
    /// `time_from_start` of each knot.
    time_s: Vec<f64>,
    q: Vec<Vec<f64>>,
    v: Vec<Vec<f64>>,
    a: Vec<Vec<f64>>,
}

impl Trajectory {
    fn knots(&self) -> usize {
        self.time_s.len()
    }

    /// (position, velocity, acceleration) of joint `j` at `tau` seconds into interval `k`.
    fn at(&self, k: usize, j: usize, tau: f64) -> (f64, f64, f64) {
        cubic(&self.q, &self.v, &self.a, k, j, tau, self.dt_s)
    }
}

/// The IK solutions the trajectory must pass through.
#[derive(Debug, Clone, PartialEq)]
struct KnotSolutions {
    /// One per target, in target order (the vias, then the handover), as the report lists them.
    ik: Vec<IkSummary>,
    /// The handover's joint positions: where the trajectory ends.
    q_end: Vec<f64>,
}

/// Per-joint limits the trajectory is checked against: `velocity_scale` × the URDF's velocity limit and
/// `acceleration_scale` × the cell's acceleration limit. The QP plans to [`QP_LIMIT_FRACTION`] of them.
#[derive(Debug, Clone, PartialEq)]
struct CheckedLimits {
    velocity_rad_s: Vec<f64>,
    acceleration_rad_s2: Vec<f64>,
}

/// The arm at one dense sample between knots: what the TCP-speed, separation and singularity checks
/// need, computed once per sample (one FK, one Jacobian) and shared by the three.
#[derive(Debug, Clone, PartialEq)]
struct CartesianSample {
    time_s: f64,
    /// |linear part of J·q̇| (m/s).
    tcp_speed_m_s: f64,
    /// The TCP in the station frame.
    p_station_tcp: Point3<f64>,
    /// Smallest singular value of the 6 × dof Jacobian.
    min_singular_value: f64,
    /// The arm's link points (`RobotModel::link_points`) in the cell frame: consecutive points bound
    /// the capsule segments, the last segment is the tool.
    arm_points_cell: Vec<Point3<f64>>,
}

/// The handover check, with its two kinds of reason kept apart: the band is an input check (reported
/// whether or not the QP solved), the final knot's FK is a check on the solution.
#[derive(Debug, Clone, PartialEq)]
struct HandoverFindings {
    check: HandoverCheck,
    outside_band: Option<String>,
    fk_miss: Option<String>,
}

/// Input sizes and the home pose, checked before anything is solved; returns the controller's joint
/// names. These are `Err`s, not rejections: no trajectory can be planned from such inputs.
fn check_inputs(
    model: &RobotModel,
    cell: &CellConfig,
    spec: &TrajectorySpec,
) -> Result<Vec<String>, RobotError> {
    let dof = model.dof();
    let controller_names = cell.robot.controller_joint_names.names(dof)?;
    if cell.robot.max_acceleration_rad_s2.len() != dof {
        // Say where the expected count comes from: a URDF whose chain was cut reads as a wrong
        // acceleration list otherwise.
        return Err(RobotError::DofMismatch {
            what: format!(
                "robot.max_acceleration_rad_s2 (one per moving joint of the URDF's chain {} → {}: {})",
                cell.robot.base_link,
                cell.robot.flange_link,
                model
                    .joints()
                    .iter()
                    .map(|j| j.name.as_str())
                    .collect::<Vec<_>>()
                    .join(", ")
            ),
            expected: dof,
            got: cell.robot.max_acceleration_rad_s2.len(),
        });
    }
    model.check_positions(&spec.home.positions_rad)?;
    Ok(controller_names)
}

/// The frames of the plan and the IK targets in the base frame: the via points in time order, then
/// the handover at the end of the trajectory.
///
/// The handover sits at (forward, lateral, height) in the station frame with the tool's z axis along
/// the approach direction ([`approach_rotation`]); each via point is an offset from it in the station
/// frame with the same orientation, so the last stretch is a straight approach.
fn resolve_targets(cell: &CellConfig, spec: &TrajectorySpec) -> (Frames, Vec<IkTarget>) {
    let T_cell_base = cell.T_cell_base();
    let T_cell_station = cell.T_cell_station();
    let T_base_station = T_cell_base.inverse() * T_cell_station;
    let R_station_tool = approach_rotation(spec.handover.approach_direction);
    let h = &spec.handover;
    let p_station_handover = Vector3::new(h.forward_m, h.lateral_m, h.height_m);
    let T_station_handover = Isometry3::from_parts(p_station_handover.into(), R_station_tool);
    let T_base_handover = T_base_station * T_station_handover;
    let mut targets: Vec<IkTarget> = spec
        .via
        .iter()
        .enumerate()
        .map(|(i, v)| {
            let T_station_via = Isometry3::from_parts(
                (p_station_handover + Vector3::from(v.offset_m)).into(),
                R_station_tool,
            );
            IkTarget {
                label: format!("via[{i}]"),
                time_s: v.time_s,
                T_base_target: T_base_station * T_station_via,
            }
        })
        .collect();
    targets.push(IkTarget {
        label: "handover".to_owned(),
        time_s: spec.timing.duration_s,
        T_base_target: T_base_handover,
    });
    let frames = Frames {
        T_cell_base,
        T_station_cell: T_cell_station.inverse(),
        T_flange_tcp: tool_transform(spec.tool.tcp_from_flange_m),
        T_base_handover,
    };
    (frames, targets)
}

/// IK of every target in order, each seeded from the previous solution (the first from `home`).
///
/// Seeding from the previous knot keeps consecutive knots on the same IK branch, so the QP joins them
/// with a short joint-space move. The IK keeps 0.01 rad more than the QP's position margin from the
/// limits, so every knot is strictly inside the QP's bounds. An unreachable target is an `Err`.
fn solve_knots(
    model: &RobotModel,
    frames: &Frames,
    targets: &[IkTarget],
    home: &[f64],
    position_margin_rad: f64,
) -> Result<KnotSolutions, RobotError> {
    let ik_settings = IkSettings {
        limit_margin_rad: position_margin_rad + 0.01,
        ..IkSettings::default()
    };
    let mut ik = Vec::with_capacity(targets.len());
    let mut previous = home.to_vec();
    for target in targets {
        let sol = solve_ik(
            model,
            &target.T_base_target,
            &frames.T_flange_tcp,
            std::slice::from_ref(&previous),
            &ik_settings,
        )?;
        previous.clone_from(&sol.positions_rad);
        ik.push(IkSummary {
            label: target.label.clone(),
            time_s: target.time_s,
            positions_rad: sol.positions_rad,
            seed_index: sol.seed_index,
            iterations: sol.iterations,
        });
    }
    Ok(KnotSolutions {
        ik,
        q_end: previous,
    })
}

/// The velocity and acceleration limits of this class's trajectory, per joint (see [`CheckedLimits`]).
fn checked_limits(model: &RobotModel, cell: &CellConfig, spec: &TrajectorySpec) -> CheckedLimits {
    CheckedLimits {
        velocity_rad_s: model
            .joints()
            .iter()
            .map(|j| spec.limits.velocity_scale * j.velocity_rad_s)
            .collect(),
        acceleration_rad_s2: cell
            .robot
            .max_acceleration_rad_s2
            .iter()
            .map(|a| spec.limits.acceleration_scale * a)
            .collect(),
    }
}

/// The QP of one class: `knots` knots over `duration_s`, from home to the handover solution, through
/// each via solution at its nearest interior knot, inside the position limits less the cell's margin
/// and inside [`QP_LIMIT_FRACTION`] of the checked velocity and acceleration limits (so the cubic
/// between knots, re-checked densely, cannot overshoot them).
fn build_qp(
    model: &RobotModel,
    cell: &CellConfig,
    spec: &TrajectorySpec,
    knots: &KnotSolutions,
    limits: &CheckedLimits,
) -> QpProblem {
    let margin = cell.robot.position_margin_rad;
    let n = spec.timing.knots;
    let dt = spec.timing.duration_s / (n - 1) as f64;
    let via_ik = knots.ik.split_last().map_or(&[][..], |(_, vias)| vias);
    let vias = via_ik
        .iter()
        .map(|s| {
            (
                ((s.time_s / dt).round() as usize).clamp(1, n - 2),
                s.positions_rad.clone(),
            )
        })
        .collect();
    QpProblem {
        dt_s: dt,
        knots: n,
        q_start: spec.home.positions_rad.clone(),
        q_end: knots.q_end.clone(),
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
        v_max: limits
            .velocity_rad_s
            .iter()
            .map(|v| v * QP_LIMIT_FRACTION)
            .collect(),
        a_max: limits
            .acceleration_rad_s2
            .iter()
            .map(|a| a * QP_LIMIT_FRACTION)
            .collect(),
        jerk_weight_s2: spec.timing.jerk_weight_s2,
    }
}

/// The time parameterisation: build the QP, solve it with clarabel, and snap the ends to exact rest.
/// Returns the trajectory (the solver's last iterate when it did not solve) and the QP's summary; `Err`
/// only when the QP cannot be set up.
fn plan_trajectory(
    model: &RobotModel,
    cell: &CellConfig,
    spec: &TrajectorySpec,
    knots: &KnotSolutions,
    limits: &CheckedLimits,
) -> Result<(Trajectory, QpSummary), RobotError> {
    let problem = build_qp(model, cell, spec, knots, limits);
    let sol = qp::solve(&problem)?;
    let (n, dt) = (problem.knots, problem.dt_s);
    let summary = QpSummary {
        status: sol.status,
        iterations: sol.iterations,
        solve_time_ms: sol.solve_time_s * 1e3,
        variables: sol.variables,
        equality_rows: sol.equality_rows,
        inequality_rows: sol.inequality_rows,
        knots: n,
        dt_s: dt,
        duration_s: spec.timing.duration_s,
    };
    let mut trajectory = Trajectory {
        dt_s: dt,
        time_s: (0..n).map(|k| k as f64 * dt).collect(),
        q: sol.q,
        v: sol.v,
        a: sol.a,
    };
    snap_to_rest(&mut trajectory, &problem.q_start, &problem.q_end);
    Ok((trajectory, summary))
}

/// Snap the first and last knots to exact rest: positions within 1e-6 rad of their targets become the
/// targets, velocities and accelerations within 1e-6 become 0. The solver meets the boundary to ~1e-9;
/// the lock must store exact rest (the drivers must not receive a moving end point), and every check
/// runs on what is stored.
fn snap_to_rest(trajectory: &mut Trajectory, q_start: &[f64], q_end: &[f64]) {
    fn snap_positions(row: &mut [f64], targets: &[f64]) {
        for (pos, target) in row.iter_mut().zip(targets) {
            if (*pos - target).abs() < 1e-6 {
                *pos = *target;
            }
        }
    }
    fn snap_zero(row: &mut [f64]) {
        for x in row {
            if x.abs() < 1e-6 {
                *x = 0.0;
            }
        }
    }
    if let Some(first) = trajectory.q.first_mut() {
        snap_positions(first, q_start);
    }
    if let Some(last) = trajectory.q.last_mut() {
        snap_positions(last, q_end);
    }
    for rows in [&mut trajectory.v, &mut trajectory.a] {
        if let Some(first) = rows.first_mut() {
            snap_zero(first);
        }
        if let Some(last) = rows.last_mut() {
            snap_zero(last);
        }
    }
}

/// The QP's own verdict: only a `Solved` QP with finite values is a trajectory. `value` says whether
/// the checks' reasons count (`checks_run` in the report); the reasons say why not.
fn check_qp(qp: &QpSummary, trajectory: &Trajectory) -> Findings<bool> {
    let mut reasons = Vec::new();
    if qp.status != QpStatus::Solved {
        reasons.push(format!(
            "QP status {} after {} iterations (only Solved is accepted{})",
            qp.status,
            qp.iterations,
            if qp.status == QpStatus::PrimalInfeasible {
                ": the limits cannot be met in this duration, or the via points are inconsistent"
            } else {
                ""
            }
        ));
    }
    let finite = trajectory
        .q
        .iter()
        .chain(&trajectory.v)
        .chain(&trajectory.a)
        .all(|row| row.iter().all(|x| x.is_finite()));
    if !finite {
        reasons.push("QP returned non-finite values".to_owned());
    }
    Findings {
        value: qp.status == QpStatus::Solved && finite,
        reasons,
    }
}

/// Boundary conditions and the consistency of the stored samples: the trajectory starts exactly at
/// home, starts and ends exactly at rest, its time strictly increases, and each knot is what the cubic
/// from the previous knot reaches (the residual: position, and velocity × dt), so the stored samples
/// are the trajectory the dense checks examined.
fn check_boundary(trajectory: &Trajectory, home: &[f64]) -> Findings<BoundaryCheck> {
    let (q, v, a) = (&trajectory.q, &trajectory.v, &trajectory.a);
    let (n, dt) = (trajectory.knots(), trajectory.dt_s);
    let start_equals_home = q[0] == home;
    let end_at_rest = v[n - 1]
        .iter()
        .chain(&a[n - 1])
        .chain(&v[0])
        .chain(&a[0])
        .all(|x| *x == 0.0);
    let mut residual = 0.0_f64;
    for k in 0..n - 1 {
        for j in 0..q[k].len() {
            let (pos, vel, _) = trajectory.at(k, j, dt);
            residual = residual
                .max((pos - q[k + 1][j]).abs())
                .max((vel - v[k + 1][j]).abs() * dt);
        }
    }
    let time_strictly_increasing = trajectory.time_s.windows(2).all(|w| w[1] > w[0]);
    let mut reasons = Vec::new();
    if !start_equals_home {
        reasons.push("first point differs from the home pose".to_owned());
    }
    if !end_at_rest {
        reasons.push("trajectory does not start and end at rest".to_owned());
    }
    if !(residual <= 1e-6) {
        reasons.push(format!(
            "stored samples inconsistent with the cubic model (residual {residual:.2e} rad)"
        ));
    }
    if !time_strictly_increasing {
        reasons.push("time_from_start not strictly increasing".to_owned());
    }
    Findings {
        value: BoundaryCheck {
            start_equals_home,
            end_at_rest,
            integration_residual_rad: residual,
            time_strictly_increasing,
        },
        reasons,
    }
}

/// Dense joint-limit re-check: position range, peak |velocity| and peak |acceleration| of every joint
/// over [`JOINT_SAMPLES_PER_INTERVAL`] + 1 samples of each interval's cubic, against the URDF's
/// position limits and the [`CheckedLimits`]. The QP only constrains the knots; this catches an
/// overshoot between them.
fn check_joint_limits(
    model: &RobotModel,
    controller_names: &[String],
    trajectory: &Trajectory,
    limits: &CheckedLimits,
) -> Findings<Vec<JointMargins>> {
    let (v_lim, a_lim) = (&limits.velocity_rad_s, &limits.acceleration_rad_s2);
    let (n, dt) = (trajectory.knots(), trajectory.dt_s);
    let mut joints = Vec::with_capacity(model.dof());
    let mut reasons = Vec::new();
    for (j, lim) in model.joints().iter().enumerate() {
        let (mut qmin, mut qmax, mut vpk, mut apk) =
            (f64::INFINITY, f64::NEG_INFINITY, 0.0_f64, 0.0_f64);
        for k in 0..n - 1 {
            for s in 0..=JOINT_SAMPLES_PER_INTERVAL {
                let tau = dt * s as f64 / JOINT_SAMPLES_PER_INTERVAL as f64;
                let (pos, vel, acc) = trajectory.at(k, j, tau);
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
            reasons.push(format!(
                "{}: position {:.2}° outside limit {:.2}°",
                lim.name,
                pos.to_degrees(),
                limit.to_degrees()
            ));
        }
        if !(m.velocity_margin_rad_s >= 0.0) {
            reasons.push(format!(
                "{}: velocity {:.2}°/s over limit {:.2}°/s",
                lim.name,
                vpk.to_degrees(),
                v_lim[j].to_degrees()
            ));
        }
        if !(m.acceleration_margin_rad_s2 >= 0.0) {
            reasons.push(format!(
                "{}: acceleration {:.2}°/s² over limit {:.2}°/s²",
                lim.name,
                apk.to_degrees(),
                a_lim[j].to_degrees()
            ));
        }
        joints.push(m);
    }
    Findings {
        value: joints,
        reasons,
    }
}

/// The arm at [`CARTESIAN_SAMPLES_PER_INTERVAL`] samples of every interval, plus the final knot:
/// TCP speed, TCP position in the station frame, the Jacobian's smallest singular value and the link
/// points in the cell frame. Computed once here so the three Cartesian checks share one FK and one
/// Jacobian per sample.
fn sample_cartesian(
    model: &RobotModel,
    frames: &Frames,
    trajectory: &Trajectory,
) -> Vec<CartesianSample> {
    let (n, dt, dof) = (trajectory.knots(), trajectory.dt_s, model.dof());
    let mut samples = Vec::with_capacity((n - 1) * CARTESIAN_SAMPLES_PER_INTERVAL + 1);
    let mut qs = vec![0.0; dof];
    let mut qds = vec![0.0; dof];
    for k in 0..n - 1 {
        let last = k == n - 2;
        for s in 0..CARTESIAN_SAMPLES_PER_INTERVAL + usize::from(last) {
            let tau = dt * s as f64 / CARTESIAN_SAMPLES_PER_INTERVAL as f64;
            for j in 0..dof {
                let (pos, vel, _) = trajectory.at(k, j, tau);
                qs[j] = pos;
                qds[j] = vel;
            }
            let (T_base_tcp, J) = model.jacobian_unchecked(&qs, &frames.T_flange_tcp);
            let twist = &J * nalgebra::DVector::from_column_slice(&qds);
            let JJt: Matrix6<f64> = &J * J.transpose();
            samples.push(CartesianSample {
                time_s: trajectory.time_s[k] + tau,
                tcp_speed_m_s: twist.fixed_rows::<3>(0).norm(),
                p_station_tcp: frames.T_station_cell
                    * (frames.T_cell_base * Point3::from(T_base_tcp.translation.vector)),
                min_singular_value: JJt.symmetric_eigenvalues().min().max(0.0).sqrt(),
                arm_points_cell: model
                    .link_points_unchecked(&qs, &frames.T_flange_tcp)
                    .into_iter()
                    .map(|p| frames.T_cell_base * p)
                    .collect(),
            });
        }
    }
    samples
}

/// TCP speed: the peak over the samples inside the collaborative zone (a vertical cylinder about the
/// station's z axis) against the cell's reduced speed, and the peak anywhere for the report.
fn check_tcp_speed(samples: &[CartesianSample], cell: &CellConfig) -> Findings<TcpSpeedCheck> {
    let zone_r = cell.robot.collaborative_zone_radius_m;
    let mut tcp = TcpSpeedCheck {
        zone_radius_m: zone_r,
        limit_in_zone_m_s: cell.robot.collaborative_tcp_speed_max_m_s,
        peak_in_zone_m_s: 0.0,
        peak_anywhere_m_s: 0.0,
        samples_in_zone: 0,
        samples: 0,
    };
    for sample in samples {
        let speed = sample.tcp_speed_m_s;
        let in_zone = sample.p_station_tcp.x.hypot(sample.p_station_tcp.y) <= zone_r;
        tcp.samples += 1;
        tcp.peak_anywhere_m_s = tcp.peak_anywhere_m_s.max(speed);
        if in_zone {
            tcp.samples_in_zone += 1;
            tcp.peak_in_zone_m_s = tcp.peak_in_zone_m_s.max(speed);
        }
    }
    let mut reasons = Vec::new();
    if !(tcp.peak_in_zone_m_s <= tcp.limit_in_zone_m_s) {
        reasons.push(format!(
            "TCP speed {:.3} m/s in the collaborative zone exceeds {:.3} m/s",
            tcp.peak_in_zone_m_s, tcp.limit_in_zone_m_s
        ));
    }
    Findings {
        value: tcp,
        reasons,
    }
}

/// Separation: the smallest capsule-to-capsule distance between the arm (link capsules of the cell's
/// link radius, the last segment the tool's capsule) and the class's body capsules, over all samples,
/// against the class's required separation; the first sample, segment and body part reaching the
/// minimum are named.
fn check_separation(
    samples: &[CartesianSample],
    body: &[(&'static str, Point3<f64>, Point3<f64>, f64)],
    model: &RobotModel,
    cell: &CellConfig,
    spec: &TrajectorySpec,
) -> Findings<SeparationCheck> {
    let mut sep = SeparationCheck {
        min_separation_m: f64::INFINITY,
        required_m: spec.envelope.min_separation_m,
        arm_segment: String::new(),
        body_part: String::new(),
        at_time_s: 0.0,
    };
    for sample in samples {
        let pts = &sample.arm_points_cell;
        let n_seg = pts.len().saturating_sub(1);
        for (i, w) in pts.windows(2).enumerate() {
            let r_arm = if i + 1 == n_seg {
                spec.tool.radius_m
            } else {
                cell.robot.link_radius_m
            };
            for (name, b0, b1, r_body) in body {
                let d = segment_distance(&w[0], &w[1], b0, b1) - r_arm - r_body;
                if d < sep.min_separation_m {
                    sep.min_separation_m = d;
                    sep.arm_segment = segment_name(model, i, n_seg);
                    (*name).clone_into(&mut sep.body_part);
                    sep.at_time_s = sample.time_s;
                }
            }
        }
    }
    let mut reasons = Vec::new();
    if !(sep.min_separation_m >= sep.required_m) {
        reasons.push(format!(
            "separation {:.3} m between {} and the operator's {} at t = {:.2} s is below {:.3} m",
            sep.min_separation_m, sep.arm_segment, sep.body_part, sep.at_time_s, sep.required_m
        ));
    }
    Findings {
        value: sep,
        reasons,
    }
}

/// Singularity margin: the smallest singular value of the Jacobian over all samples (and the first
/// time it is reached) against the cell's minimum; near a singularity small TCP motions need large
/// joint speeds.
fn check_singularity(samples: &[CartesianSample], cell: &CellConfig) -> Findings<SingularityCheck> {
    let mut sing = SingularityCheck {
        min_singular_value: f64::INFINITY,
        required: cell.robot.min_singular_value,
        at_time_s: 0.0,
    };
    for sample in samples {
        if sample.min_singular_value < sing.min_singular_value {
            sing.min_singular_value = sample.min_singular_value;
            sing.at_time_s = sample.time_s;
        }
    }
    let mut reasons = Vec::new();
    if !(sing.min_singular_value >= sing.required) {
        reasons.push(format!(
            "Jacobian's smallest singular value {:.4} at t = {:.2} s is below {:.4} (near a singularity)",
            sing.min_singular_value, sing.at_time_s, sing.required
        ));
    }
    Findings {
        value: sing,
        reasons,
    }
}

/// The handover point against the class's [`class_band`], the planar arm holding it at the class's
/// shortest, middle and tallest stature (for the reviewer), and the final knot's FK against the
/// handover pose (within 1 mm and 0.01 rad).
fn check_handover(
    model: &RobotModel,
    spec: &TrajectorySpec,
    frames: &Frames,
    trajectory: &Trajectory,
) -> HandoverFindings {
    let h = &spec.handover;
    let (h_min, h_max) = (spec.stature.min_m, spec.stature.max_m);
    let band = class_band(h_min, h_max);
    let inside_band = band.contains(h.forward_m, h.lateral_m, h.height_m);
    let T_base_end =
        model.fk_flange_unchecked(&trajectory.q[trajectory.knots() - 1]) * frames.T_flange_tcp;
    let (fk_dp, fk_dr) = pose_error(&T_base_end, &frames.T_base_handover);
    let outside_band = (!inside_band).then(|| {
        format!(
            "handover (forward {:.3}, lateral {:.3}, height {:.3}) m is outside the class band (where some operator of \
             the class holds it in the arm's score-1 zone): height {:.3}–{:.3} m, forward {:.3}–{:.3} m, |lateral| ≤ {:.3} m",
            h.forward_m,
            h.lateral_m,
            h.height_m,
            band.height_m[0],
            band.height_m[1],
            band.forward_m[0],
            band.forward_m[1],
            band.lateral_max_m
        )
    });
    let fk_miss = (!(fk_dp <= 1e-3 && fk_dr <= 1e-2)).then(|| {
        format!(
            "final point misses the handover target by {fk_dp:.4} m / {:.2}°",
            fk_dr.to_degrees()
        )
    });
    HandoverFindings {
        check: HandoverCheck {
            target_station_m: [h.forward_m, h.lateral_m, h.height_m],
            height_band_m: band.height_m,
            forward_band_m: band.forward_m,
            lateral_max_m: band.lateral_max_m,
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
        outside_band,
        fk_miss,
    }
}

/// The outcome: the report always, and a [`LockedTrajectory`] of the stored samples only when the
/// report accepts them — the one place a `LockedTrajectory` is built.
fn seal(report: ValidationReport, joint_names: Vec<String>, trajectory: Trajectory) -> Validation {
    let locked = report.accepted.then(|| LockedTrajectory {
        class: report.class,
        joint_names,
        dt_s: trajectory.dt_s,
        time_s: trajectory.time_s,
        positions_rad: trajectory.q,
        velocities_rad_s: trajectory.v,
        accelerations_rad_s2: trajectory.a,
        inputs: report.inputs.clone(),
        report: report.clone(),
    });
    Validation { report, locked }
}

/// The report's name of arm segment `i` of `n_seg` (the last is the tool).
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
            "  robot {}; tool {}; stature {:.2}–{:.2} m (served and checked for {:.2}–{:.2} m)",
            self.robot,
            self.tool,
            self.stature_m[0],
            self.stature_m[1],
            self.served_stature_m[0],
            self.served_stature_m[1]
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
        if !self.path_tolerance_rad.is_empty() {
            writeln!(
                f,
                "Execution monitor's path tolerance per joint (the separation margin {:.3} m over the joints' lever arms; \
                 locked and signed with the trajectory; the cell may only tighten it): {} rad",
                s.min_separation_m - s.required_m,
                self.path_tolerance_rad
                    .iter()
                    .map(|t| format!("{t:.4}"))
                    .collect::<Vec<_>>()
                    .join(", ")
            )?;
        }
        let m = &self.monitor;
        writeln!(
            f,
            "Execution monitor's other limits (the cell's [monitor]; locked and signed with the trajectory; the cell may \
             only tighten them): goal {} rad, {} s late at most; at rest {} rad; stalls judged over {} s; {} s to stop \
             after a hold",
            m.goal_tolerance_rad, m.goal_time_tolerance_s, m.rest_tolerance_rad, m.stall_window_s, m.stop_time_s
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

#[cfg(test)]
mod tests {
    //! The stages of [`plan_and_validate`] one at a time: on the shipped cell and trajectory files, and
    //! on hand-built trajectories and samples whose answers are known. The whole pipeline is tested in
    //! `tests/plan.rs` and `tests/lock.rs`.

    // Test helpers panic on purpose: a panic is the failure report.
    #![allow(clippy::unwrap_used, clippy::expect_used)]

    use super::*;

    fn read(rel: &str) -> String {
        let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
        std::fs::read_to_string(root.join(rel)).unwrap_or_else(|e| panic!("{rel}: {e}"))
    }

    /// The shipped robot model and cell config, and the class's shipped trajectory file.
    fn shipped(class: TrajectoryClass) -> (RobotModel, CellConfig, TrajectorySpec) {
        let cell = CellConfig::from_toml_str(&read("config/cell.toml")).unwrap();
        let urdf = read(&format!("config/{}", cell.robot.urdf));
        let model =
            RobotModel::from_urdf_str(&urdf, &cell.robot.base_link, &cell.robot.flange_link)
                .unwrap();
        let spec =
            TrajectorySpec::from_toml_str(&read(&format!("trajectories/{class}.toml"))).unwrap();
        (model, cell, spec)
    }

    /// `dof` joints with the same knot accelerations, from rest at `q0`, integrated with the QP's own
    /// recurrences (see `qp`), so every stored knot is exactly where the cubic from the previous one ends.
    fn integrated(dof: usize, q0: f64, accelerations: &[f64], dt: f64) -> Trajectory {
        let n = accelerations.len();
        let (mut q, mut v) = (vec![q0], vec![0.0]);
        for k in 0..n - 1 {
            let (ak, ak1) = (accelerations[k], accelerations[k + 1]);
            q.push(q[k] + dt * v[k] + dt * dt * (ak / 3.0 + ak1 / 6.0));
            v.push(v[k] + dt * (ak + ak1) / 2.0);
        }
        let rows = |x: &[f64]| x.iter().map(|&x| vec![x; dof]).collect();
        Trajectory {
            dt_s: dt,
            time_s: (0..n).map(|k| k as f64 * dt).collect(),
            q: rows(&q),
            v: rows(&v),
            a: rows(accelerations),
        }
    }

    fn rotation_distance(a: &UnitQuaternion<f64>, b: &UnitQuaternion<f64>) -> f64 {
        (a.to_rotation_matrix().matrix() - b.to_rotation_matrix().matrix()).norm()
    }

    #[test]
    fn resolve_targets_puts_the_handover_at_the_station_point_along_the_approach() {
        for class in TrajectoryClass::ALL {
            let (_, cell, spec) = shipped(class);
            let (frames, targets) = resolve_targets(&cell, &spec);
            let h = &spec.handover;
            // Back to the station frame through the cell: an independent path to the same point.
            let T_station_base = frames.T_station_cell * frames.T_cell_base;
            let T_station_handover = T_station_base * frames.T_base_handover;
            let p = T_station_handover.translation.vector;
            let expected = Vector3::new(h.forward_m, h.lateral_m, h.height_m);
            assert!((p - expected).norm() < 1e-12, "{class}: {p} vs {expected}");
            // Tool z along the approach; for the shipped horizontal approaches, tool x straight down.
            let R = T_station_handover.rotation;
            let approach = Vector3::from(h.approach_direction).normalize();
            assert!((R * Vector3::z() - approach).norm() < 1e-12, "{class}");
            assert_eq!(h.approach_direction[2], 0.0);
            assert!((R * Vector3::x() - Vector3::new(0.0, 0.0, -1.0)).norm() < 1e-12);
            assert_eq!(
                frames.T_flange_tcp.translation.vector,
                Vector3::from(spec.tool.tcp_from_flange_m)
            );

            // The vias in order, each its offset from the handover in the station frame, same
            // orientation; the handover last, at the end of the trajectory.
            assert_eq!(targets.len(), spec.via.len() + 1);
            for (i, (target, via)) in targets.iter().zip(&spec.via).enumerate() {
                assert_eq!(target.label, format!("via[{i}]"));
                assert_eq!(target.time_s, via.time_s);
                let T_station_via = T_station_base * target.T_base_target;
                let offset = T_station_via.translation.vector - p;
                assert!((offset - Vector3::from(via.offset_m)).norm() < 1e-12);
                assert!(rotation_distance(&T_station_via.rotation, &R) < 1e-12);
            }
            let last = targets.last().unwrap();
            assert_eq!(last.label, "handover");
            assert_eq!(last.time_s, spec.timing.duration_s);
            assert_eq!(last.T_base_target, frames.T_base_handover);
        }
    }

    #[test]
    fn solve_knots_reaches_every_target_inside_the_margin_and_ends_on_the_handover() {
        let (model, cell, spec) = shipped(TrajectoryClass::C2);
        let (frames, targets) = resolve_targets(&cell, &spec);
        let margin = cell.robot.position_margin_rad;
        let home = &spec.home.positions_rad;
        let knots = solve_knots(&model, &frames, &targets, home, margin).unwrap();
        let tolerance = IkSettings::default();
        assert_eq!(knots.ik.len(), targets.len());
        for (s, target) in knots.ik.iter().zip(&targets) {
            assert_eq!((&s.label, s.time_s), (&target.label, target.time_s));
            let T_base_tcp = model
                .fk_tcp(&s.positions_rad, &frames.T_flange_tcp)
                .unwrap();
            let (dp, dr) = pose_error(&T_base_tcp, &target.T_base_target);
            assert!(
                dp <= tolerance.position_tolerance_m && dr <= tolerance.orientation_tolerance_rad,
                "{}: {dp} m, {dr} rad",
                s.label
            );
            for (x, lim) in s.positions_rad.iter().zip(model.joints()) {
                assert!(
                    (lim.lower_rad + margin..=lim.upper_rad - margin).contains(x),
                    "{}: {} = {x}",
                    s.label,
                    lim.name
                );
            }
        }
        assert_eq!(knots.q_end, knots.ik.last().unwrap().positions_rad);
        // Each solve is seeded from the previous one, which converges first (seed 0).
        assert!(knots.ik.iter().all(|s| s.seed_index == 0), "{:?}", knots.ik);

        // An unreachable target is an error, not a knot.
        let far = IkTarget {
            label: "far".to_owned(),
            time_s: 1.0,
            T_base_target: Isometry3::translation(3.0, 0.0, 0.0),
        };
        let err = solve_knots(&model, &frames, &[far], home, margin).unwrap_err();
        assert!(matches!(err, RobotError::Unreachable { .. }), "{err}");
    }

    #[test]
    fn build_qp_puts_each_via_on_its_nearest_interior_knot_and_tightens_the_limits() {
        let (model, cell, spec) = shipped(TrajectoryClass::C2);
        let dof = model.dof();
        // 100 knots over 5 s: dt = 5/99 s. A via at 3.0 s is at knot 59.4 → 59; one at 0.01 s (knot
        // 0.2) or 4.99 s (knot 98.8) would land on an end knot and is clamped to 1 or 98.
        assert_eq!((spec.timing.knots, spec.timing.duration_s), (100, 5.0));
        let summary = |label: &str, time_s: f64, x: f64| IkSummary {
            label: label.to_owned(),
            time_s,
            positions_rad: vec![x; dof],
            seed_index: 0,
            iterations: 0,
        };
        let knots = KnotSolutions {
            ik: vec![
                summary("via[0]", 0.01, 0.1),
                summary("via[1]", 3.0, 0.2),
                summary("via[2]", 4.99, 0.3),
                summary("handover", 5.0, 0.4),
            ],
            q_end: vec![0.4; dof],
        };
        let limits = checked_limits(&model, &cell, &spec);
        let p = build_qp(&model, &cell, &spec, &knots, &limits);
        assert_eq!((p.knots, p.dt_s), (100, 5.0 / 99.0));
        let vias: Vec<(usize, f64)> = p.vias.iter().map(|(k, q)| (*k, q[0])).collect();
        assert_eq!(vias, [(1, 0.1), (59, 0.2), (98, 0.3)]);
        assert_eq!(p.q_start, spec.home.positions_rad);
        assert_eq!(p.q_end, knots.q_end);
        assert_eq!(p.jerk_weight_s2, spec.timing.jerk_weight_s2);
        let margin = cell.robot.position_margin_rad;
        for (j, lim) in model.joints().iter().enumerate() {
            assert_eq!(p.q_lower[j], lim.lower_rad + margin);
            assert_eq!(p.q_upper[j], lim.upper_rad - margin);
            let (v, a) = (limits.velocity_rad_s[j], limits.acceleration_rad_s2[j]);
            assert_eq!(v, spec.limits.velocity_scale * lim.velocity_rad_s);
            assert_eq!(
                a,
                spec.limits.acceleration_scale * cell.robot.max_acceleration_rad_s2[j]
            );
            // Strictly inside the checked limits, so the dense re-check has room.
            assert!(p.v_max[j] == QP_LIMIT_FRACTION * v && p.v_max[j] < v);
            assert!(p.a_max[j] == QP_LIMIT_FRACTION * a && p.a_max[j] < a);
        }
    }

    #[test]
    fn snap_to_rest_moves_only_the_end_knots_and_only_within_a_micro_unit() {
        let exact = integrated(2, 0.5, &[0.0, 1.0, -1.0, 0.0], 0.5);
        let q_end = exact.q[3].clone();
        let mut t = exact.clone();
        t.q[0] = vec![0.5 + 4e-7, 0.5 + 3e-6];
        t.q[3] = vec![q_end[0] - 8e-7, q_end[1] - 2e-6];
        t.v[0] = vec![-9e-7, 2e-6];
        t.a[3] = vec![5e-7, -1.5e-6];
        t.v[1][0] = 1e-9; // interior: never snapped, however small
        snap_to_rest(&mut t, &[0.5, 0.5], &q_end);
        assert_eq!(t.q[0], [0.5, 0.5 + 3e-6]);
        assert_eq!(t.q[3], [q_end[0], q_end[1] - 2e-6]);
        assert_eq!(t.v[0], [0.0, 2e-6]);
        assert_eq!(t.a[3], [0.0, -1.5e-6]);
        assert_eq!(t.v[1], [1e-9, exact.v[1][1]]);
        assert_eq!((&t.q[1..3], &t.a[1..3]), (&exact.q[1..3], &exact.a[1..3]));
    }

    #[test]
    fn check_qp_accepts_only_a_solved_finite_iterate() {
        let summary = |status| QpSummary {
            status,
            iterations: 5,
            solve_time_ms: 1.0,
            variables: 0,
            equality_rows: 0,
            inequality_rows: 0,
            knots: 4,
            dt_s: 0.5,
            duration_s: 1.5,
        };
        let t = integrated(2, 0.5, &[0.0, 1.0, -1.0, 0.0], 0.5);
        let solved = check_qp(&summary(QpStatus::Solved), &t);
        assert!(solved.value && solved.reasons.is_empty());
        let infeasible = check_qp(&summary(QpStatus::PrimalInfeasible), &t);
        assert!(!infeasible.value);
        assert_eq!(
            infeasible.reasons,
            ["QP status PrimalInfeasible after 5 iterations (only Solved is accepted: the limits \
              cannot be met in this duration, or the via points are inconsistent)"]
        );
        let mut nan = t;
        nan.a[2][1] = f64::NAN;
        let f = check_qp(&summary(QpStatus::Solved), &nan);
        assert!(!f.value);
        assert_eq!(f.reasons, ["QP returned non-finite values"]);
    }

    #[test]
    fn check_boundary_passes_an_exact_cubic_and_names_each_defect() {
        let home = [0.5; 3];
        let good = integrated(3, 0.5, &[0.0, 1.0, -1.0, 0.0], 0.5);
        let f = check_boundary(&good, &home);
        assert!(f.reasons.is_empty(), "{:?}", f.reasons);
        let b = &f.value;
        assert!(b.start_equals_home && b.end_at_rest && b.time_strictly_increasing);
        assert!(b.integration_residual_rad < 1e-15, "{b:?}");

        // A knot moved by 1 mrad: the cubic from the knot before it misses it by exactly that.
        let mut moved = good.clone();
        moved.q[2][1] += 1e-3;
        let f = check_boundary(&moved, &home);
        assert!((f.value.integration_residual_rad - 1e-3).abs() < 1e-12);
        assert_eq!(
            f.reasons,
            ["stored samples inconsistent with the cubic model (residual 1.00e-3 rad)"]
        );

        // A velocity off by 1 mrad/s counts as 1 mrad/s × dt: the position error it makes over a knot.
        let mut fast = good.clone();
        fast.v[2][0] += 1e-3;
        let f = check_boundary(&fast, &home);
        assert!((f.value.integration_residual_rad - 0.5e-3).abs() < 1e-12);

        let f = check_boundary(&good, &[0.5, 0.5, 0.6]);
        assert_eq!(f.reasons, ["first point differs from the home pose"]);
        let mut stalled = good.clone();
        stalled.time_s[2] = stalled.time_s[1];
        let f = check_boundary(&stalled, &home);
        assert_eq!(f.reasons, ["time_from_start not strictly increasing"]);
        let mut moving = good;
        moving.a[3][0] = 1e-3;
        let f = check_boundary(&moving, &home);
        assert!(!f.value.end_at_rest);
        assert_eq!(f.reasons[0], "trajectory does not start and end at rest");
    }

    #[test]
    fn check_joint_limits_finds_the_peaks_of_a_constant_acceleration_interval() {
        let (model, cell, _) = shipped(TrajectoryClass::C2);
        let dof = model.dof();
        let names = cell.robot.controller_joint_names.names(dof).unwrap();
        // From rest at 0 with a constant −0.2 rad/s² for 1 s: q = −0.1 t², so the range is −0.1..0 rad
        // and the peaks are |velocity| 0.2 rad/s and |acceleration| 0.2 rad/s², at the interval's end.
        let mut t = integrated(dof, 0.0, &[-0.2, -0.2], 1.0);
        let limits = CheckedLimits {
            velocity_rad_s: vec![1.0; dof],
            acceleration_rad_s2: vec![1.0; dof],
        };
        let f = check_joint_limits(&model, &names, &t, &limits);
        assert!(f.reasons.is_empty(), "{:?}", f.reasons);
        assert_eq!(f.value.len(), dof);
        for (m, lim) in f.value.iter().zip(model.joints()) {
            assert_eq!((m.position_min_rad, m.position_max_rad), (-0.1, 0.0));
            assert_eq!(
                (m.velocity_peak_rad_s, m.acceleration_peak_rad_s2),
                (0.2, 0.2)
            );
            assert_eq!(m.position_margin_rad, -0.1 - lim.lower_rad);
            assert_eq!(
                (m.velocity_margin_rad_s, m.acceleration_margin_rad_s2),
                (0.8, 0.8)
            );
        }
        assert_eq!(f.value[0].controller_name, "joint_1");

        // joint_1 shifted to end at −3.0 rad (its limit is −170°), every joint over a 0.1 rad/s limit.
        for row in &mut t.q {
            row[0] -= 2.9;
        }
        let slow = CheckedLimits {
            velocity_rad_s: vec![0.1; dof],
            ..limits
        };
        let f = check_joint_limits(&model, &names, &t, &slow);
        assert_eq!(f.reasons.len(), 1 + dof, "{:?}", f.reasons);
        assert_eq!(
            f.reasons[0],
            "joint_1: position -171.89° outside limit -170.00°"
        );
        assert_eq!(
            f.reasons[1],
            "joint_1: velocity 11.46°/s over limit 5.73°/s"
        );
        assert_eq!(
            f.reasons[2],
            "joint_2: velocity 11.46°/s over limit 5.73°/s"
        );
        assert!(f.value[0].position_margin_rad < 0.0 && f.value[1].position_margin_rad > 0.0);
    }

    #[test]
    fn sample_cartesian_covers_every_interval_once_and_matches_the_models_kinematics() {
        let (model, cell, spec) = shipped(TrajectoryClass::C2);
        let (frames, _) = resolve_targets(&cell, &spec);
        let dof = model.dof();
        let t = integrated(dof, 0.3, &[0.0, 0.4, -0.4, 0.0], 0.5);
        let samples = sample_cartesian(&model, &frames, &t);
        // 4 per interval, then the final knot.
        assert_eq!(samples.len(), 3 * CARTESIAN_SAMPLES_PER_INTERVAL + 1);
        for (i, s) in samples.iter().enumerate() {
            assert!(
                (s.time_s - 0.125 * i as f64).abs() < 1e-15,
                "{i}: {}",
                s.time_s
            );
        }
        let (first, last) = (&samples[0], &samples[samples.len() - 1]);
        assert_eq!(first.tcp_speed_m_s, 0.0); // at rest
        assert!(last.tcp_speed_m_s < 1e-12);
        // Against the model's own (checked) FK and Jacobian at the first knot.
        let T_base_tcp = model.fk_tcp(&t.q[0], &frames.T_flange_tcp).unwrap();
        let p = frames.T_station_cell
            * (frames.T_cell_base * Point3::from(T_base_tcp.translation.vector));
        assert!((first.p_station_tcp - p).norm() < 1e-12);
        let J = model.jacobian(&t.q[0], &frames.T_flange_tcp).unwrap();
        let sigma = (&J * J.transpose())
            .symmetric_eigenvalues()
            .min()
            .max(0.0)
            .sqrt();
        assert!((first.min_singular_value - sigma).abs() < 1e-12);
        assert_eq!(
            first.arm_points_cell[0],
            Point3::from(frames.T_cell_base.translation.vector)
        );
        // Mid-motion, the TCP speed is |J_linear · q̇|, q̇ from the cubic.
        let mid = &samples[6]; // interval 1, tau = dt / 2
        let (q, qd): (Vec<f64>, Vec<f64>) = (0..dof)
            .map(|j| {
                let (pos, vel, _) = t.at(1, j, 0.25);
                (pos, vel)
            })
            .unzip();
        let J = model.jacobian(&q, &frames.T_flange_tcp).unwrap();
        let v = (&J * nalgebra::DVector::from_vec(qd))
            .fixed_rows::<3>(0)
            .norm();
        assert!(v > 0.01 && (mid.tcp_speed_m_s - v).abs() < 1e-12, "{v}");
    }

    /// A hand-built sample: the Cartesian checks only read these fields.
    fn sample(
        time_s: f64,
        tcp_speed_m_s: f64,
        p_station_tcp: [f64; 3],
        min_singular_value: f64,
        arm_points_cell: &[[f64; 3]],
    ) -> CartesianSample {
        CartesianSample {
            time_s,
            tcp_speed_m_s,
            p_station_tcp: Point3::from(p_station_tcp),
            min_singular_value,
            arm_points_cell: arm_points_cell.iter().map(|&p| Point3::from(p)).collect(),
        }
    }

    #[test]
    fn the_cartesian_checks_fold_their_samples_to_known_extremes() {
        let (model, mut cell, mut spec) = shipped(TrajectoryClass::C2);
        cell.robot.collaborative_zone_radius_m = 0.8;
        cell.robot.collaborative_tcp_speed_max_m_s = 0.25;
        cell.robot.min_singular_value = 0.05;
        // The arm: a link segment then the tool segment, along x at 1.2 m, ending `x` from the axis.
        let arm = |x: f64| [[x + 0.5, 0.0, 1.2], [x + 0.1, 0.0, 1.2], [x, 0.0, 1.2]];
        let samples = [
            sample(0.0, 0.20, [0.5, 0.0, 1.0], 0.30, &arm(0.6)), // in the zone (r = 0.5)
            sample(0.5, 0.40, [0.6, 0.6, 1.0], 0.04, &arm(0.4)), // outside (r = 0.85)
            sample(1.0, 0.10, [0.0, 0.79, 3.0], 0.04, &arm(0.4)), // inside: the zone is a cylinder
        ];

        let tcp = check_tcp_speed(&samples, &cell);
        assert_eq!((tcp.value.samples, tcp.value.samples_in_zone), (3, 2));
        assert_eq!(
            (tcp.value.peak_in_zone_m_s, tcp.value.peak_anywhere_m_s),
            (0.20, 0.40)
        );
        assert!(tcp.reasons.is_empty());
        cell.robot.collaborative_tcp_speed_max_m_s = 0.15;
        assert_eq!(
            check_tcp_speed(&samples, &cell).reasons,
            ["TCP speed 0.200 m/s in the collaborative zone exceeds 0.150 m/s"]
        );

        // The first sample reaching the minimum is the one named.
        let sing = check_singularity(&samples, &cell);
        assert_eq!(
            (sing.value.min_singular_value, sing.value.at_time_s),
            (0.04, 0.5)
        );
        assert_eq!(
            sing.reasons,
            ["Jacobian's smallest singular value 0.0400 at t = 0.50 s is below 0.0500 (near a singularity)"]
        );

        // A vertical torso capsule on the axis: the nearest arm capsule is the tool's, 0.4 m out.
        let body = [(
            "torso",
            Point3::new(0.0, 0.0, 0.9),
            Point3::new(0.0, 0.0, 1.5),
            0.15,
        )];
        let sep = check_separation(&samples, &body, &model, &cell, &spec);
        let expected = 0.4 - spec.tool.radius_m - 0.15;
        assert!(
            (sep.value.min_separation_m - expected).abs() < 1e-12,
            "{sep:?}"
        );
        assert_eq!(
            (sep.value.arm_segment.as_str(), sep.value.body_part.as_str()),
            ("tool (flange→TCP)", "torso")
        );
        assert_eq!(sep.value.at_time_s, 0.5);
        assert!(sep.reasons.is_empty());
        spec.envelope.min_separation_m = 0.25;
        assert_eq!(
            check_separation(&samples, &body, &model, &cell, &spec).reasons,
            [format!(
                "separation {expected:.3} m between tool (flange→TCP) and the operator's torso at t = 0.50 s \
                 is below 0.250 m"
            )]
        );

        // No samples (the QP did not solve): nothing measured, nothing to reject for.
        assert_eq!(check_tcp_speed(&[], &cell).value.samples, 0);
        let none = check_separation(&[], &body, &model, &cell, &spec);
        assert!(none.value.min_separation_m == f64::INFINITY && none.reasons.is_empty());
        let none = check_singularity(&[], &cell);
        assert!(none.value.min_singular_value == f64::INFINITY && none.reasons.is_empty());
    }

    #[test]
    fn check_handover_separates_the_band_from_the_final_knots_fk() {
        let (model, cell, mut spec) = shipped(TrajectoryClass::C2);
        let (frames, targets) = resolve_targets(&cell, &spec);
        let margin = cell.robot.position_margin_rad;
        let knots =
            solve_knots(&model, &frames, &targets, &spec.home.positions_rad, margin).unwrap();
        let mut t = integrated(model.dof(), 0.0, &[0.0, 0.0, 0.0], 1.0);
        t.q[2].clone_from(&knots.q_end);
        let f = check_handover(&model, &spec, &frames, &t);
        assert!(f.check.inside_band && f.outside_band.is_none() && f.fk_miss.is_none());
        assert!(f.check.fk_position_error_m <= 1e-4, "{:?}", f.check);
        let statures: Vec<f64> = f.check.arm_postures.iter().map(|(h, _)| *h).collect();
        assert_eq!(statures, [1.68, 0.5 * (1.68 + 1.82), 1.82]);

        // Ending at home misses the target: a check on the solution, not on the input.
        t.q[2].clone_from(&spec.home.positions_rad);
        let f = check_handover(&model, &spec, &frames, &t);
        assert!(f.outside_band.is_none());
        assert!(f
            .fk_miss
            .is_some_and(|r| r.starts_with("final point misses the handover target by")));

        // Above the tallest c2 operator's zone (0.643 × 1.82 m): an input check, whatever the
        // trajectory.
        spec.handover.height_m = 1.25;
        let f = check_handover(&model, &spec, &frames, &t);
        assert!(!f.check.inside_band);
        assert_eq!(
            f.outside_band.as_deref(),
            Some(
                format!(
                    "handover (forward {:.3}, lateral -0.100, height 1.250) m is outside the class band (where some \
                     operator of the class holds it in the arm's score-1 zone): height 0.947–1.171 m, forward \
                     0.316–0.480 m, |lateral| ≤ 0.218 m",
                    spec.handover.forward_m
                )
                .as_str()
            )
        );
    }
}
