//! Joint angles from the fused BlazePose-33 skeleton, in radians.
//!
//! # Frames
//! - **World**: the cell calibration's frame, metres. Its "up" is *not* assumed: it is an
//!   [`UpVector`] from the cell config (`u`, unit length).
//! - **Pelvis frame** (for the trunk): origin at the hip midpoint; `r_p` = the right-hip minus left-hip
//!   direction with its vertical part removed (horizontal, towards the person's right); `f_p = u × r_p`
//!   (horizontal, forwards); `u`.
//! - **Trunk (body) frame** (for arms, neck, head): `t` = unit vector from the hip midpoint to the
//!   shoulder midpoint (the trunk axis); `r` = right-shoulder minus left-shoulder with its `t` part
//!   removed (towards the person's right); `f = t × r` (forwards, out of the chest).
//!
//! Left and right are the person's own, as in MediaPipe. The side's "outward" direction `o` is `r`
//! for the right side and `−r` for the left.
//!
//! # Angle definitions
//! - **Trunk flexion**: the trunk axis `t` in the pelvis's sagittal plane, from vertical:
//!   `atan2(t·f_p, t·u)`; positive = bent forward, negative = extension.
//!   **Side bend**: `asin(t·r_p)` (trunk axis out of the sagittal plane). **Twist**: signed angle about
//!   `t` from the hip line to the shoulder line, both projected onto the plane normal to `t`.
//! - **Upper-arm flexion** (relative to the trunk): the elevation of the upper arm
//!   `a = elbow − shoulder` from the trunk's downward axis, `acos(â·(−t))`, in `0..=π`. It is counted
//!   as **extension** (negative) when the arm is below shoulder level and points more backwards than
//!   sideways (`â·t < 0` and `−â·f > |â·r|`). An arm raised sideways therefore scores by its elevation
//!   (and the abduction adjustment adds 1), which never under-states the risk. Near the back/side
//!   diagonal that sign is decided with hysteresis over frames by [`crate::RulaAssessor`]
//!   ([`SideAngles::upper_arm_backwardness`], `assess::UPPER_ARM_SIGN_BAND`); one frame alone (this module,
//!   `rula score`) uses the rule as stated.
//! - **Upper-arm abduction**: `asin(â·o)`, the angle of the arm out of the trunk's sagittal plane,
//!   towards the outside (negative = across the chest).
//! - **Shoulder raise ratio**: distance from the shoulder to the ear on the same side divided by the
//!   shoulder width. A shrug shortens it; a neutral adult is near 0.4 (Drillis & Contini: ear ≈ 0.92 H,
//!   shoulder 0.818 H, shoulder width 0.259 H).
//! - **Elbow flexion**: angle between the upper arm `a` and the forearm `b = wrist − elbow`; 0 =
//!   straight.
//! - **Wrist flexion / deviation** from the wrist, index and pinky landmarks: the hand direction
//!   `h = mid(index, pinky) − wrist`; the knuckle axis `k = index − pinky` with its forearm part removed
//!   (`k⊥`); `n = b̂ × k⊥`. Deviation (radial/ulnar) = `atan2(h·k⊥, h·b̂)`; flexion =
//!   `atan2(∓h·n, h·b̂)` with the sign chosen per side so that positive is towards the palm
//!   (`−` for the right hand, `+` for the left, given BlazePose's landmark placement).
//! - **Wrist lateral offset**: `(wrist − shoulder midpoint)·o`, metres; negative means the hand works
//!   across the body's midline.
//! - **Neck flexion** (relative to the trunk): the vector from the shoulder midpoint to the ear
//!   midpoint, `v`, in the trunk's sagittal plane: `atan2(v·f, v·t)`; positive = forward, negative =
//!   extension. **Side bend**: `atan2(|v·r|, v·t)`. **Twist**: signed angle about `t` from `r` to the
//!   head's left-to-right axis projected on the plane normal to `t`; the axis is the sum of
//!   `right − left` over the face's mirror pairs (ears, outer/centre/inner eyes, mouth corners), all
//!   parallel to the ear line on a rigid head ([`head_lateral_axis`]). If an ear is missing, from `f`
//!   to the nose direction (nose − shoulder midpoint) projected the same way.
//! - **Upper-arm elevation** (for ISO 11226's static postures): the angle between the upper arm
//!   `a` and the world's downward vertical `−u`, in any direction (not relative to the trunk).
//! - **Knee flexion** (for REBA): angle between the thigh `knee − hip` and the shank `ankle − knee`;
//!   0 = straight.
//! - **Legs**: each foot's lowest point (ankle, heel, foot index) above the floor along `u`; the floor
//!   is the configured height along `u`, or the lowest foot landmark of the frame when unknown. Weight
//!   balance: horizontal distance from the hip midpoint to the midpoint of the ankles, divided by half
//!   the ankle spread (at least 0.1 m): 0 = centred, 1 = over one foot.

use ergocell_skeleton::{Landmark, Skeleton3};
use nalgebra::{Point3, Unit, Vector3};
use serde::Serialize;

use crate::{ErgonomicsError, Side};

/// The world's "up" direction, unit length. Comes from the cell config.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct UpVector(Unit<Vector3<f64>>);

impl UpVector {
    /// Normalises `v`; fails when it is zero or not finite.
    pub fn new(v: Vector3<f64>) -> Result<Self, ErgonomicsError> {
        let n = v.norm();
        if !n.is_finite() || n < 1e-9 {
            return Err(ErgonomicsError::DegenerateUp {
                x: v.x,
                y: v.y,
                z: v.z,
            });
        }
        Ok(Self(Unit::new_unchecked(v / n)))
    }

    /// World z up (the reference cell's and the digital twin's convention).
    pub fn z() -> Self {
        Self(Vector3::z_axis())
    }

    /// The unit vector.
    pub fn vector(&self) -> Vector3<f64> {
        self.0.into_inner()
    }

    /// Height of a point along up (metres, relative to the world origin).
    pub fn height_of(&self, p: &Point3<f64>) -> f64 {
        p.coords.dot(&self.0)
    }
}

/// Angles of one arm, radians (ratios and metres where named). `None` = the landmarks it needs were
/// not observed.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize)]
pub struct SideAngles {
    pub upper_arm_flexion_rad: Option<f64>,
    /// How clearly the upper arm points backwards rather than sideways or forwards, for
    /// [`crate::RulaAssessor`]'s hysteresis on the flexion/extension sign: `(−â·f − |â·r|) / |â⊥|`,
    /// with `â⊥` the arm's part across the trunk axis, in `[−√2, 1]` — positive where the sign rule
    /// above counts extension, 0 on the back/side diagonal, where the sign of a hanging arm flips
    /// from one frame to the next with the detector's noise. `None` when the arm is not below
    /// shoulder level (never extension), hangs straight along the trunk (no direction, no sign to
    /// keep) or is not observed. Not an angle of the worksheet: not serialised.
    #[serde(skip)]
    pub upper_arm_backwardness: Option<f64>,
    pub upper_arm_abduction_rad: Option<f64>,
    pub shoulder_raise_ratio: Option<f64>,
    pub elbow_flexion_rad: Option<f64>,
    pub wrist_flexion_rad: Option<f64>,
    pub wrist_deviation_rad: Option<f64>,
    pub wrist_lateral_offset_m: Option<f64>,
    /// Knee flexion (REBA's legs), radians; 0 = straight.
    pub knee_flexion_rad: Option<f64>,
    /// The upper arm's elevation from the world's vertical (ISO 11226's upper arm elevation, in any
    /// direction), radians; 0 = hanging straight down.
    pub upper_arm_elevation_rad: Option<f64>,
}

/// What the feet say about the legs.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct LegsObservation {
    /// Lowest point of the left foot above the floor, metres.
    pub left_foot_lift_m: f64,
    /// Lowest point of the right foot above the floor, metres.
    pub right_foot_lift_m: f64,
    /// 0 = hips centred over the feet, 1 = over one foot (see the module docs).
    pub weight_offset: f64,
}

/// All angles of one frame.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize)]
pub struct BodyAngles {
    pub trunk_flexion_rad: Option<f64>,
    pub trunk_side_bend_rad: Option<f64>,
    pub trunk_twist_rad: Option<f64>,
    pub neck_flexion_rad: Option<f64>,
    pub neck_side_bend_rad: Option<f64>,
    pub neck_twist_rad: Option<f64>,
    pub left: SideAngles,
    pub right: SideAngles,
    pub legs: Option<LegsObservation>,
    /// Shoulder width, metres (used to normalise lateral offsets).
    pub shoulder_width_m: Option<f64>,
}

impl BodyAngles {
    /// The angles of one side.
    pub fn side(&self, side: Side) -> &SideAngles {
        match side {
            Side::Left => &self.left,
            Side::Right => &self.right,
        }
    }
}

/// The trunk frame of one skeleton.
#[derive(Debug, Clone, Copy)]
struct TrunkFrame {
    t: Vector3<f64>,
    r: Vector3<f64>,
    f: Vector3<f64>,
    shoulder_mid: Point3<f64>,
    shoulder_width_m: f64,
}

fn unit(v: Vector3<f64>) -> Option<Vector3<f64>> {
    let n = v.norm();
    (n > 1e-9).then(|| v / n)
}

/// `v` with its component along unit `axis` removed, normalised.
fn perp(v: Vector3<f64>, axis: &Vector3<f64>) -> Option<Vector3<f64>> {
    unit(v - axis * v.dot(axis))
}

fn mid(a: Point3<f64>, b: Point3<f64>) -> Point3<f64> {
    Point3::from((a.coords + b.coords) * 0.5)
}

/// Signed angle about unit `axis` from `from` to `to` (both projected on the plane normal to it).
fn signed_angle_about(from: Vector3<f64>, to: Vector3<f64>, axis: &Vector3<f64>) -> Option<f64> {
    let a = perp(from, axis)?;
    let b = perp(to, axis)?;
    Some(a.cross(&b).dot(axis).atan2(a.dot(&b)))
}

fn angle_between(a: Vector3<f64>, b: Vector3<f64>) -> Option<f64> {
    let (a, b) = (unit(a)?, unit(b)?);
    Some(a.cross(&b).norm().atan2(a.dot(&b)))
}

fn trunk_frame(s: &Skeleton3) -> Option<TrunkFrame> {
    let (hl, hr) = (
        s.position(Landmark::LeftHip)?,
        s.position(Landmark::RightHip)?,
    );
    let (sl, sr) = (
        s.position(Landmark::LeftShoulder)?,
        s.position(Landmark::RightShoulder)?,
    );
    let shoulder_mid = mid(sl, sr);
    let t = unit(shoulder_mid - mid(hl, hr))?;
    let r = perp(sr - sl, &t)?;
    Some(TrunkFrame {
        t,
        r,
        f: t.cross(&r),
        shoulder_mid,
        shoulder_width_m: (sr - sl).norm(),
    })
}

fn trunk_angles(s: &Skeleton3, up: &UpVector) -> Option<(f64, f64, f64)> {
    let u = up.vector();
    let (hl, hr) = (
        s.position(Landmark::LeftHip)?,
        s.position(Landmark::RightHip)?,
    );
    let frame = trunk_frame(s)?;
    let r_p = perp(hr - hl, &u)?;
    let f_p = u.cross(&r_p);
    let t = frame.t;
    let flexion = t.dot(&f_p).atan2(t.dot(&u));
    let side_bend = t.dot(&r_p).clamp(-1.0, 1.0).asin();
    let (sl, sr) = (
        s.position(Landmark::LeftShoulder)?,
        s.position(Landmark::RightShoulder)?,
    );
    let twist = signed_angle_about(hr - hl, sr - sl, &t)?;
    Some((flexion, side_bend, twist))
}

struct SideLandmarks {
    shoulder: Landmark,
    elbow: Landmark,
    wrist: Landmark,
    index: Landmark,
    pinky: Landmark,
    ear: Landmark,
}

fn side_landmarks(side: Side) -> SideLandmarks {
    match side {
        Side::Left => SideLandmarks {
            shoulder: Landmark::LeftShoulder,
            elbow: Landmark::LeftElbow,
            wrist: Landmark::LeftWrist,
            index: Landmark::LeftIndex,
            pinky: Landmark::LeftPinky,
            ear: Landmark::LeftEar,
        },
        Side::Right => SideLandmarks {
            shoulder: Landmark::RightShoulder,
            elbow: Landmark::RightElbow,
            wrist: Landmark::RightWrist,
            index: Landmark::RightIndex,
            pinky: Landmark::RightPinky,
            ear: Landmark::RightEar,
        },
    }
}

/// The landmarks each side's arm angles use (for confidence checks).
pub fn arm_landmarks(side: Side) -> [Landmark; 6] {
    let l = side_landmarks(side);
    [l.shoulder, l.elbow, l.wrist, l.index, l.pinky, l.ear]
}

fn side_angles(s: &Skeleton3, frame: Option<&TrunkFrame>, side: Side) -> SideAngles {
    let lm = side_landmarks(side);
    let mut out = SideAngles::default();
    let Some(fr) = frame else {
        return out;
    };
    let sign = match side {
        Side::Right => 1.0,
        Side::Left => -1.0,
    };
    let o = fr.r * sign;
    let shoulder = s.position(lm.shoulder);
    let elbow = s.position(lm.elbow);
    let wrist = s.position(lm.wrist);

    if let (Some(sh), Some(el)) = (shoulder, elbow) {
        if let Some(a) = unit(el - sh) {
            let elevation = a.dot(&-fr.t).clamp(-1.0, 1.0).acos();
            let backwards = -a.dot(&fr.f) > a.dot(&fr.r).abs() && a.dot(&fr.t) < 0.0;
            out.upper_arm_flexion_rad = Some(if backwards { -elevation } else { elevation });
            let across = (a - fr.t * a.dot(&fr.t)).norm();
            out.upper_arm_backwardness = (a.dot(&fr.t) < 0.0 && across > 1e-3)
                .then(|| (-a.dot(&fr.f) - a.dot(&fr.r).abs()) / across);
            out.upper_arm_abduction_rad = Some(a.dot(&o).clamp(-1.0, 1.0).asin());
        }
    }
    if let (Some(sh), Some(ear)) = (shoulder, s.position(lm.ear)) {
        if fr.shoulder_width_m > 1e-6 {
            out.shoulder_raise_ratio = Some((ear - sh).norm() / fr.shoulder_width_m);
        }
    }
    if let (Some(sh), Some(el), Some(wr)) = (shoulder, elbow, wrist) {
        out.elbow_flexion_rad = angle_between(el - sh, wr - el);
    }
    let (hip, knee, ankle) = match side {
        Side::Left => (Landmark::LeftHip, Landmark::LeftKnee, Landmark::LeftAnkle),
        Side::Right => (
            Landmark::RightHip,
            Landmark::RightKnee,
            Landmark::RightAnkle,
        ),
    };
    if let (Some(h), Some(k), Some(a)) = (s.position(hip), s.position(knee), s.position(ankle)) {
        out.knee_flexion_rad = angle_between(k - h, a - k);
    }
    if let Some(wr) = wrist {
        out.wrist_lateral_offset_m = Some((wr - fr.shoulder_mid).dot(&o));
    }
    if let (Some(el), Some(wr), Some(ix), Some(pk)) =
        (elbow, wrist, s.position(lm.index), s.position(lm.pinky))
    {
        if let Some(b) = unit(wr - el) {
            if let Some(k) = perp(ix - pk, &b) {
                let n = b.cross(&k);
                let h = mid(ix, pk) - wr;
                out.wrist_deviation_rad = Some(h.dot(&k).atan2(h.dot(&b)));
                // Right hand: the palm faces −n; left hand: +n (see the module docs).
                out.wrist_flexion_rad = Some((-sign * h.dot(&n)).atan2(h.dot(&b)));
            }
        }
    }
    out
}

fn neck_angles(s: &Skeleton3, frame: &TrunkFrame) -> (Option<f64>, Option<f64>, Option<f64>) {
    let ears = s
        .position(Landmark::LeftEar)
        .zip(s.position(Landmark::RightEar));
    let Some((el, er)) = ears else {
        let twist = s
            .position(Landmark::Nose)
            .and_then(|n| signed_angle_about(frame.f, n - frame.shoulder_mid, &frame.t));
        return (None, None, twist);
    };
    let v = mid(el, er) - frame.shoulder_mid;
    let flexion = v.dot(&frame.f).atan2(v.dot(&frame.t));
    let side_bend = v.dot(&frame.r).abs().atan2(v.dot(&frame.t));
    let twist = head_lateral_axis(s).and_then(|l| signed_angle_about(frame.r, l, &frame.t));
    (Some(flexion), Some(side_bend), twist)
}

/// The face's left/right landmark pairs, all mirror images across the head's midsagittal plane.
const FACE_PAIRS: [(Landmark, Landmark); 5] = [
    (Landmark::LeftEar, Landmark::RightEar),
    (Landmark::LeftEyeOuter, Landmark::RightEyeOuter),
    (Landmark::LeftEye, Landmark::RightEye),
    (Landmark::LeftEyeInner, Landmark::RightEyeInner),
    (Landmark::MouthLeft, Landmark::MouthRight),
];

/// The head's left-to-right axis (not normalised): the sum of `right − left` over every observed pair
/// of `FACE_PAIRS`. Each pair is parallel to the same axis on a rigid head, so the sum has the
/// direction of the ear line, while an error of a few millimetres in one landmark (the ears are
/// hidden from most cameras) moves it far less than it moves the 15 cm ear line alone. Each pair is
/// weighted by its own length, i.e. the longer (better conditioned) baselines count more.
pub fn head_lateral_axis(s: &Skeleton3) -> Option<Vector3<f64>> {
    let mut sum = Vector3::zeros();
    let mut any = false;
    for (l, r) in FACE_PAIRS {
        if let (Some(pl), Some(pr)) = (s.position(l), s.position(r)) {
            sum += pr - pl;
            any = true;
        }
    }
    any.then_some(sum).filter(|v| v.norm() > 1e-9)
}

fn lowest(s: &Skeleton3, up: &UpVector, lms: [Landmark; 3]) -> Option<f64> {
    lms.iter()
        .filter_map(|l| s.position(*l))
        .map(|p| up.height_of(&p))
        .min_by(f64::total_cmp)
}

fn legs(s: &Skeleton3, up: &UpVector, floor_height_m: Option<f64>) -> Option<LegsObservation> {
    let left = lowest(
        s,
        up,
        [
            Landmark::LeftAnkle,
            Landmark::LeftHeel,
            Landmark::LeftFootIndex,
        ],
    )?;
    let right = lowest(
        s,
        up,
        [
            Landmark::RightAnkle,
            Landmark::RightHeel,
            Landmark::RightFootIndex,
        ],
    )?;
    let floor = floor_height_m.unwrap_or(left.min(right));
    let u = up.vector();
    let (al, ar) = (
        s.position(Landmark::LeftAnkle)?,
        s.position(Landmark::RightAnkle)?,
    );
    let hips = mid(
        s.position(Landmark::LeftHip)?,
        s.position(Landmark::RightHip)?,
    );
    let horizontal = |v: Vector3<f64>| v - u * v.dot(&u);
    let half_spread = (horizontal(ar - al).norm() * 0.5).max(0.1);
    let offset = horizontal(hips - mid(al, ar)).norm() / half_spread;
    Some(LegsObservation {
        left_foot_lift_m: left - floor,
        right_foot_lift_m: right - floor,
        weight_offset: offset,
    })
}

/// Extracts every angle of one frame. `floor_height_m` is the floor's height along `up`, when known.
pub fn body_angles(s: &Skeleton3, up: &UpVector, floor_height_m: Option<f64>) -> BodyAngles {
    let frame = trunk_frame(s);
    let u = up.vector();
    let elevation = |shoulder: Landmark, elbow: Landmark| {
        angle_between(s.position(elbow)? - s.position(shoulder)?, -u)
    };
    let mut left = side_angles(s, frame.as_ref(), Side::Left);
    left.upper_arm_elevation_rad = elevation(Landmark::LeftShoulder, Landmark::LeftElbow);
    let mut right = side_angles(s, frame.as_ref(), Side::Right);
    right.upper_arm_elevation_rad = elevation(Landmark::RightShoulder, Landmark::RightElbow);
    let mut out = BodyAngles {
        left,
        right,
        legs: legs(s, up, floor_height_m),
        shoulder_width_m: frame.map(|f| f.shoulder_width_m),
        ..BodyAngles::default()
    };
    if let Some((flexion, side_bend, twist)) = trunk_angles(s, up) {
        out.trunk_flexion_rad = Some(flexion);
        out.trunk_side_bend_rad = Some(side_bend);
        out.trunk_twist_rad = Some(twist);
    }
    if let Some(fr) = frame.as_ref() {
        let (flexion, side_bend, twist) = neck_angles(s, fr);
        out.neck_flexion_rad = flexion;
        out.neck_side_bend_rad = side_bend;
        out.neck_twist_rad = twist;
    }
    out
}
