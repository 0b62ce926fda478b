//! The arm model: a URDF parsed by `urdf-rs` 0.9, turned into a `k` 0.32 chain, and reduced to an
//! immutable serial chain from `base_link` to `flange_link`.
//!
//! `k` keeps only position limits (and drops them when lower = upper); the velocity and effort limits
//! are read here from the URDF itself. Forward kinematics and the geometric Jacobian are computed from
//! the chain's joint origins and axes without `k`'s interior mutability, so a [`RobotModel`] is plain
//! immutable data that can be shared between threads (tests check it against `k`'s own FK).
//!
//! Frames: `T_base_x` is the pose of frame `x` in the robot's base frame (`base_link`); the flange is
//! `flange_link`; the tool centre point is `T_flange_tcp` from the trajectory's tool.

use nalgebra::{Isometry3, Matrix6xX, Point3, Translation3, Unit, UnitQuaternion, Vector3};
use serde::Serialize;

use crate::RobotError;

/// One movable joint's limits, SI units, as read from the URDF `<limit>` element.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct JointLimits {
    /// URDF joint name.
    pub name: String,
    pub lower_rad: f64,
    pub upper_rad: f64,
    pub velocity_rad_s: f64,
    pub effort_nm: f64,
}

#[derive(Debug, Clone)]
struct ChainElement {
    /// Pose of this joint's frame in its parent's frame at zero position (the URDF `<origin>`).
    T_parent_joint: Isometry3<f64>,
    /// Rotation axis in the joint frame; `None` for a fixed joint.
    axis: Option<Unit<Vector3<f64>>>,
}

/// An immutable serial arm from `base_link` to `flange_link`.
#[derive(Debug, Clone)]
pub struct RobotModel {
    name: String,
    base_link: String,
    flange_link: String,
    elements: Vec<ChainElement>,
    joints: Vec<JointLimits>,
}

impl RobotModel {
    /// Parse a URDF and extract the serial chain from `base_link` to `flange_link`.
    ///
    /// Rejects prismatic/continuous/floating joints on the chain and joints without finite,
    /// ordered position limits and positive velocity/effort limits. Every joint of the file (on the
    /// chain or not) is first checked for what `k`'s conversion would panic on or turn into NaN
    /// (NaN or inverted limits, non-finite origins, zero or non-finite axes, ambiguous names): those
    /// are errors naming the joint and the value, never a panic.
    pub fn from_urdf_str(
        urdf: &str,
        base_link: &str,
        flange_link: &str,
    ) -> Result<Self, RobotError> {
        // urdf-rs skips unknown elements recursively: bound the nesting before it reads.
        ergocell_nesting::check(urdf, ergocell_nesting::MAX_XML_DEPTH).map_err(|e| {
            RobotError::UnsupportedUrdf {
                reason: e.to_string(),
            }
        })?;
        let robot = urdf_rs::read_from_string(urdf).map_err(|e| RobotError::Urdf {
            reason: e.to_string(),
        })?;
        // `k`'s conversion panics on some inputs and silently turns others into NaN frames: check
        // every joint of the file (not only the arm's) before handing it over.
        check_urdf_for_k(&robot)?;
        if !robot.links.iter().any(|l| l.name == base_link) {
            return Err(RobotError::UnknownLink {
                link: base_link.to_owned(),
                context: "base_link".to_owned(),
            });
        }
        let chain = k::Chain::<f64>::from(&robot);
        let end = chain
            .find_link(flange_link)
            .ok_or_else(|| RobotError::UnknownLink {
                link: flange_link.to_owned(),
                context: "flange_link".to_owned(),
            })?;

        let mut elements = Vec::new();
        let mut names = Vec::new();
        let mut reached_base = false;
        for node in end.iter_ancestors() {
            if node.link().as_ref().is_some_and(|l| l.name == base_link) {
                reached_base = true;
                break;
            }
            let joint = node.joint();
            let axis = match &joint.joint_type {
                k::JointType::Fixed => None,
                k::JointType::Rotational { axis } => {
                    names.push(joint.name.clone());
                    Some(*axis)
                }
                k::JointType::Linear { .. } => {
                    return Err(RobotError::UnsupportedUrdf {
                        reason: format!("prismatic joint `{}` on the arm chain", joint.name),
                    })
                }
            };
            elements.push(ChainElement {
                T_parent_joint: *joint.origin(),
                axis,
            });
        }
        if !reached_base {
            return Err(RobotError::UnknownLink {
                link: base_link.to_owned(),
                context: format!("not an ancestor of flange_link `{flange_link}`"),
            });
        }
        elements.reverse();
        names.reverse();

        let mut joints = Vec::with_capacity(names.len());
        for name in names {
            let Some(urdf_joint) = robot.joints.iter().find(|j| j.name == name) else {
                return Err(RobotError::UnsupportedUrdf {
                    reason: format!("joint `{name}` vanished between urdf-rs and k"),
                });
            };
            if !matches!(urdf_joint.joint_type, urdf_rs::JointType::Revolute) {
                return Err(RobotError::UnsupportedUrdf {
                    reason: format!(
                        "joint `{name}` is {:?}; only revolute joints with limits are supported",
                        urdf_joint.joint_type
                    ),
                });
            }
            let l = &urdf_joint.limit;
            let bad = |reason: String| RobotError::InvalidLimit {
                joint: name.clone(),
                reason,
            };
            if !(l.lower.is_finite() && l.upper.is_finite() && l.lower < l.upper) {
                return Err(bad(format!(
                    "position limits lower {} / upper {} rad",
                    l.lower, l.upper
                )));
            }
            if !(l.velocity.is_finite() && l.velocity > 0.0) {
                return Err(bad(format!("velocity limit {} rad/s", l.velocity)));
            }
            if !(l.effort.is_finite() && l.effort > 0.0) {
                return Err(bad(format!("effort limit {} Nm", l.effort)));
            }
            joints.push(JointLimits {
                name: name.clone(),
                lower_rad: l.lower,
                upper_rad: l.upper,
                velocity_rad_s: l.velocity,
                effort_nm: l.effort,
            });
        }
        if joints.is_empty() {
            return Err(RobotError::UnsupportedUrdf {
                reason: format!("no movable joint between `{base_link}` and `{flange_link}`"),
            });
        }
        Ok(Self {
            name: robot.name,
            base_link: base_link.to_owned(),
            flange_link: flange_link.to_owned(),
            elements,
            joints,
        })
    }

    /// The URDF's robot name.
    pub fn name(&self) -> &str {
        &self.name
    }
    pub fn base_link(&self) -> &str {
        &self.base_link
    }
    pub fn flange_link(&self) -> &str {
        &self.flange_link
    }
    /// Number of movable joints.
    pub fn dof(&self) -> usize {
        self.joints.len()
    }
    /// Limits of the movable joints, base to flange.
    pub fn joints(&self) -> &[JointLimits] {
        &self.joints
    }

    /// Check a joint vector's length and that every entry is finite and inside the position limits.
    pub fn check_positions(&self, q: &[f64]) -> Result<(), RobotError> {
        self.check_dof(q, "joint positions")?;
        for (&qi, lim) in q.iter().zip(&self.joints) {
            if !qi.is_finite() || qi < lim.lower_rad {
                return Err(RobotError::OutOfLimit {
                    joint: lim.name.clone(),
                    position_rad: qi,
                    limit_rad: lim.lower_rad,
                });
            }
            if qi > lim.upper_rad {
                return Err(RobotError::OutOfLimit {
                    joint: lim.name.clone(),
                    position_rad: qi,
                    limit_rad: lim.upper_rad,
                });
            }
        }
        Ok(())
    }

    fn check_dof(&self, q: &[f64], what: &str) -> Result<(), RobotError> {
        if q.len() == self.dof() {
            Ok(())
        } else {
            Err(RobotError::DofMismatch {
                what: what.to_owned(),
                expected: self.dof(),
                got: q.len(),
            })
        }
    }

    /// `T_base_element` for every chain element (fixed ones included), base to flange.
    /// `q` must have `dof()` entries (checked by the public callers).
    fn element_frames(&self, q: &[f64]) -> Vec<Isometry3<f64>> {
        let mut frames = Vec::with_capacity(self.elements.len());
        let mut T_base_current = Isometry3::identity();
        let mut qi = q.iter();
        for el in &self.elements {
            T_base_current *= el.T_parent_joint;
            if let Some(axis) = el.axis {
                let angle = qi.next().copied().unwrap_or(0.0);
                T_base_current *= UnitQuaternion::from_axis_angle(&axis, angle);
            }
            frames.push(T_base_current);
        }
        frames
    }

    /// `T_base_flange` at joint positions `q` (no limit check: FK is defined everywhere).
    pub fn fk_flange(&self, q: &[f64]) -> Result<Isometry3<f64>, RobotError> {
        self.check_dof(q, "joint positions")?;
        Ok(self.fk_flange_unchecked(q))
    }

    pub(crate) fn fk_flange_unchecked(&self, q: &[f64]) -> Isometry3<f64> {
        self.element_frames(q)
            .last()
            .copied()
            .unwrap_or_else(Isometry3::identity)
    }

    /// `T_base_tcp = T_base_flange * T_flange_tcp`.
    pub fn fk_tcp(
        &self,
        q: &[f64],
        T_flange_tcp: &Isometry3<f64>,
    ) -> Result<Isometry3<f64>, RobotError> {
        Ok(self.fk_flange(q)? * T_flange_tcp)
    }

    /// Geometric Jacobian of the TCP in the base frame, 6 × dof, rows [linear; angular]
    /// (the same convention as `k::jacobian`).
    pub fn jacobian(
        &self,
        q: &[f64],
        T_flange_tcp: &Isometry3<f64>,
    ) -> Result<Matrix6xX<f64>, RobotError> {
        self.check_dof(q, "joint positions")?;
        Ok(self.jacobian_unchecked(q, T_flange_tcp).1)
    }

    /// (`T_base_tcp`, Jacobian) in one pass.
    pub(crate) fn jacobian_unchecked(
        &self,
        q: &[f64],
        T_flange_tcp: &Isometry3<f64>,
    ) -> (Isometry3<f64>, Matrix6xX<f64>) {
        let frames = self.element_frames(q);
        let T_base_tcp = frames.last().copied().unwrap_or_else(Isometry3::identity) * T_flange_tcp;
        let p_tcp = T_base_tcp.translation.vector;
        let mut J = Matrix6xX::zeros(self.dof());
        let mut col = 0;
        for (el, T_base_joint) in self.elements.iter().zip(&frames) {
            if let Some(axis) = el.axis {
                let a = T_base_joint.rotation * axis.into_inner();
                let p = T_base_joint.translation.vector;
                let lin = a.cross(&(p_tcp - p));
                for r in 0..3 {
                    J[(r, col)] = lin[r];
                    J[(r + 3, col)] = a[r];
                }
                col += 1;
            }
        }
        (T_base_tcp, J)
    }

    /// Per joint, in joint order, the largest distance from the joint's axis origin to any point of
    /// the arm beyond it (later chain origins and the TCP) at positions `q`: a position error of
    /// `δ` radians at that joint moves no point of the arm by more than `δ` times this (metres per
    /// radian; a rotation by `δ` moves a point at distance `r` by `2 r sin(δ/2) ≤ r δ`, and a point on
    /// a link segment is no farther than the farther of its ends).
    pub fn joint_lever_arms_m(
        &self,
        q: &[f64],
        T_flange_tcp: &Isometry3<f64>,
    ) -> Result<Vec<f64>, RobotError> {
        self.check_dof(q, "joint positions")?;
        let frames = self.element_frames(q);
        let T_base_flange = frames.last().copied().unwrap_or_else(Isometry3::identity);
        let tcp = (T_base_flange * T_flange_tcp).translation.vector;
        let mut arms = Vec::with_capacity(self.dof());
        for (i, (el, T_base_joint)) in self.elements.iter().zip(&frames).enumerate() {
            if el.axis.is_none() {
                continue;
            }
            let origin = T_base_joint.translation.vector;
            let farthest = frames[i + 1..]
                .iter()
                .map(|T| (T.translation.vector - origin).norm())
                .chain(std::iter::once((tcp - origin).norm()))
                .fold(0.0_f64, f64::max);
            arms.push(farthest);
        }
        Ok(arms)
    }

    /// Points along the arm in the base frame: the base origin, every chain element's origin
    /// (joints and fixed frames), then the TCP. Consecutive points bound the arm's link segments.
    pub fn link_points(
        &self,
        q: &[f64],
        T_flange_tcp: &Isometry3<f64>,
    ) -> Result<Vec<Point3<f64>>, RobotError> {
        self.check_dof(q, "joint positions")?;
        Ok(self.link_points_unchecked(q, T_flange_tcp))
    }

    pub(crate) fn link_points_unchecked(
        &self,
        q: &[f64],
        T_flange_tcp: &Isometry3<f64>,
    ) -> Vec<Point3<f64>> {
        let frames = self.element_frames(q);
        let mut points = Vec::with_capacity(frames.len() + 2);
        points.push(Point3::origin());
        points.extend(frames.iter().map(|T| Point3::from(T.translation.vector)));
        let T_base_flange = frames.last().copied().unwrap_or_else(Isometry3::identity);
        points.push(Point3::from(
            (T_base_flange * T_flange_tcp).translation.vector,
        ));
        points
    }
}

/// Checks a parsed URDF for everything `k` 0.32's `Chain::from(&urdf_rs::Robot)` panics on or turns
/// into NaN without a word, so that [`RobotModel::from_urdf_str`] can refuse it with the joint and the
/// value instead. Read from `k`'s `src/urdf.rs`:
///
/// - `Range::new(lower, upper)` asserts `lower <= upper` for every joint whose `upper - lower != 0`,
///   so a NaN limit or `lower > upper` on any joint (fixed ones included) panics;
/// - a mimic joint whose leader is missing panics (`unwrap_or_else(panic!)`);
/// - a revolute/continuous/prismatic axis is normalised with `Unit::new_normalize`: a zero or NaN
///   axis becomes NaN;
/// - `<origin xyz rpy>` goes through unchecked: NaN or infinite values become NaN frames;
/// - duplicate joint or link names, or a link that is the child of two joints, are silently
///   resolved by whichever entry comes last in `k` (and first in our own limit lookup).
///
/// Velocity and effort limits must be finite and ≥ 0 here (0 is urdf-rs's default for joints without
/// `<limit>`); the arm's own joints are held to the stricter rules of [`RobotModel::from_urdf_str`].
/// The most links (and joints) a URDF may have.
pub const MAX_URDF_LINKS: usize = 1000;

fn check_urdf_for_k(robot: &urdf_rs::Robot) -> Result<(), RobotError> {
    let unsupported = |reason: String| RobotError::UnsupportedUrdf { reason };
    // `k` builds its tree recursively: a chain thousands of links deep overflows the stack. A robot
    // cell's URDF has tens of links.
    if robot.links.len() > MAX_URDF_LINKS || robot.joints.len() > MAX_URDF_LINKS {
        return Err(unsupported(format!(
            "{} links and {} joints: at most {MAX_URDF_LINKS} of each",
            robot.links.len(),
            robot.joints.len()
        )));
    }
    for (i, link) in robot.links.iter().enumerate() {
        if robot.links[..i].iter().any(|l| l.name == link.name) {
            return Err(unsupported(format!(
                "link `{}` is defined more than once",
                link.name
            )));
        }
    }
    for (i, joint) in robot.joints.iter().enumerate() {
        let name = &joint.name;
        if robot.joints[..i].iter().any(|j| &j.name == name) {
            return Err(unsupported(format!(
                "joint `{name}` is defined more than once"
            )));
        }
        if let Some(other) = robot.joints[..i]
            .iter()
            .find(|j| j.child.link == joint.child.link)
        {
            return Err(unsupported(format!(
                "link `{}` is the child of both joint `{}` and joint `{name}`",
                joint.child.link, other.name
            )));
        }
        if let Some(mimic) = &joint.mimic {
            if !robot.joints.iter().any(|j| j.name == mimic.joint) {
                return Err(unsupported(format!(
                    "joint `{name}` mimics missing joint `{}`",
                    mimic.joint
                )));
            }
        }
        let l = &joint.limit;
        let bad_limit = |reason: String| RobotError::InvalidLimit {
            joint: name.clone(),
            reason,
        };
        for (what, value) in [("lower", l.lower), ("upper", l.upper)] {
            if !value.is_finite() {
                return Err(bad_limit(format!(
                    "position limit {what} = {value} rad is not a finite number"
                )));
            }
        }
        if l.lower > l.upper {
            return Err(bad_limit(format!(
                "position limit lower = {} rad is above upper = {} rad",
                l.lower, l.upper
            )));
        }
        for (what, value, unit) in [
            ("velocity", l.velocity, "rad/s"),
            ("effort", l.effort, "Nm"),
        ] {
            if !(value.is_finite() && value >= 0.0) {
                return Err(bad_limit(format!(
                    "{what} limit = {value} {unit} is not a finite number ≥ 0"
                )));
            }
        }
        for (what, values) in [
            ("origin xyz", &joint.origin.xyz.0),
            ("origin rpy", &joint.origin.rpy.0),
        ] {
            if let Some(value) = values.iter().find(|v| !v.is_finite()) {
                return Err(unsupported(format!(
                    "joint `{name}`: {what} = {values:?} has the non-finite value {value}"
                )));
            }
        }
        let movable = matches!(
            joint.joint_type,
            urdf_rs::JointType::Revolute
                | urdf_rs::JointType::Continuous
                | urdf_rs::JointType::Prismatic
        );
        if movable {
            let axis = &joint.axis.xyz.0;
            if let Some(value) = axis.iter().find(|v| !v.is_finite()) {
                return Err(unsupported(format!(
                    "joint `{name}`: axis xyz = {axis:?} has the non-finite value {value}"
                )));
            }
            let norm = Vector3::from(*axis).norm();
            if !(norm > 1e-9 && norm.is_finite()) {
                return Err(unsupported(format!(
                    "joint `{name}`: axis xyz = {axis:?} is not a direction (length {norm})"
                )));
            }
        }
    }
    Ok(())
}

/// `T_flange_tcp` for a tool whose TCP sits at `offset_m` in the flange frame (no rotation).
pub fn tool_transform(offset_m: [f64; 3]) -> Isometry3<f64> {
    Isometry3::from_parts(
        Translation3::new(offset_m[0], offset_m[1], offset_m[2]),
        UnitQuaternion::identity(),
    )
}
