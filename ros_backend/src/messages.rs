//! The ROS boundary: every conversion between the core's values (views, skeletons, assessments,
//! warnings, robot commands, the session's state) and the bridge's ROS 2 messages, in one place, and
//! the one mapping from a session step's events to the messages that leave the cell
//! ([`step_messages`]), which `ergocell run`'s publisher and every recorder send alike.

use ergocell_bridge::msg::{
    CameraLandmarks, ControllerEvent, ErgonomicState, Header, JointTrajectory, MarkerArray,
    OperatorPose, PostureWarning, RebaSide, RebaState, RulaSide, SessionState,
};
use ergocell_ergonomics::{FrameAssessment, SideAssessment, WarningEvent};
use ergocell_perception::video_geometry::{VideoGeometry, VideoMap};
use ergocell_perception::{CameraRig, Keypoint2, View2};
use ergocell_skeleton::LANDMARK_COUNT;

use ergocell_cell::session::{
    GoalAnswer, Leg, RobotCommand, RobotReport, RobotUnready, SessionEvent, SessionMachine,
};

use crate::robot::{controller_event, leg_label, no_leg};

/// One message a session step sends out, by its role (the topic comes from the publisher's
/// configuration or, in a recording, from [`ergocell_bridge::topics`]).
#[derive(Debug, Clone, PartialEq)]
pub enum Outgoing {
    SessionState(SessionState),
    Ergonomics(ErgonomicState),
    /// REBA beside RULA, for the same frame.
    Reba(RebaState),
    Warning(PostureWarning),
    Skeleton(MarkerArray),
    OperatorPose(OperatorPose),
    /// The command the robot sink was sent (recorded; the sink itself publishes it).
    Trajectory(JointTrajectory),
}

/// The messages of one step's events, in event order: state changes and session facts become
/// `SessionState` (each as of its event), a fused frame its skeleton markers, operator pose and RULA
/// state, a warning its `PostureWarning`, a robot command its `JointTrajectory`.
pub fn step_messages(
    machine: &SessionMachine,
    now_nanos: i64,
    events: &[SessionEvent],
) -> Vec<Outgoing> {
    use SessionEvent as E;
    let mut states = session_state_messages(machine, now_nanos, events).into_iter();
    let mut out = Vec::new();
    for e in events {
        match e {
            E::StateChanged { .. }
            | E::ClassDecided { .. }
            | E::TrajectoryLocked { .. }
            | E::ChangeRefused { .. }
            | E::PartTaken { .. }
            | E::CameraDegraded { .. }
            | E::CameraRestored { .. } => {
                if let Some(m) = states.next() {
                    out.push(Outgoing::SessionState(m));
                }
            }
            E::RobotCommandSent { command, .. } => {
                out.push(Outgoing::Trajectory(command_message(command, now_nanos)));
            }
            E::Warning(w) => out.push(Outgoing::Warning(warning_message(w))),
            E::Frame {
                skeleton,
                assessment,
                ..
            } => out.extend(frame_messages(skeleton, assessment.as_deref())),
        }
    }
    out
}

/// The messages of one fused frame: its skeleton markers (coloured by the headline action level),
/// its operator pose and, when it was assessed, its RULA and REBA states. The session's frames
/// ([`step_messages`]) and the twin's recordings (`sim adaptation --record-height`) both send these.
pub fn frame_messages(
    skeleton: &ergocell_skeleton::Skeleton3,
    assessment: Option<&FrameAssessment>,
) -> Vec<Outgoing> {
    let level = assessment
        .and_then(|a| a.headline().map(|h| h.scores.action_level))
        .unwrap_or(0);
    let mut out = vec![
        Outgoing::Skeleton(skeleton_message(skeleton, level)),
        Outgoing::OperatorPose(operator_pose_message(skeleton, assessment)),
    ];
    if let Some(a) = assessment {
        out.push(Outgoing::Ergonomics(ergonomic_message(a)));
        out.push(Outgoing::Reba(reba_message(a)));
    }
    out
}

/// A camera's view as the Jetson publishes it: 33 entries in BlazePose order (unobserved: NaN pixels,
/// visibility and presence 0), or none when nobody is detected.
pub fn landmarks_message(rig: &CameraRig, view: &View2) -> CameraLandmarks {
    let camera = rig.camera(view.camera);
    let id = camera.map_or_else(|| format!("{}", view.camera), |c| c.id.as_str().to_owned());
    let (w, h) = camera.map_or((0, 0), |c| (c.intrinsics.width_px, c.intrinsics.height_px));
    let mut m = CameraLandmarks {
        header: Header::new(view.stamp_nanos, &format!("camera_{id}")),
        camera_id: id,
        image_width: w,
        image_height: h,
        ..CameraLandmarks::default()
    };
    if view.observed_count() == 0 {
        return m;
    }
    for k in view.keypoints() {
        if let Some(k) = k {
            let p = k.pixel();
            m.x_px.push(p.x as f32);
            m.y_px.push(p.y as f32);
            m.visibility.push(k.confidence() as f32);
            m.presence.push(1.0);
        } else {
            m.x_px.push(f32::NAN);
            m.y_px.push(f32::NAN);
            m.visibility.push(0.0);
            m.presence.push(0.0);
        }
    }
    m
}

/// Why a landmark message was not turned into a view.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum LandmarksRejected {
    #[error("unknown camera `{0}` (not in the rig)")]
    UnknownCamera(String),
    #[error("camera `{camera}`: {got} landmarks, expected 0 or {LANDMARK_COUNT} in each array")]
    BadLength { camera: String, got: usize },
    /// A landmark said to be present and visible at a non-finite pixel: the node is broken, and
    /// nothing else in its message is trusted either (an unobserved landmark has NaN pixels with
    /// presence and visibility 0).
    #[error("camera `{camera}`: landmark {landmark} present at a non-finite pixel ({x}, {y})")]
    NonFinitePixel {
        camera: String,
        landmark: &'static str,
        x: f32,
        y: f32,
    },
    /// The node's images are not the calibrated image and no video geometry says how they relate:
    /// its pixels would put every ray of that camera off.
    #[error(
        "camera `{camera}`: its images are {got_width}x{got_height} but it was calibrated at \
         {width}x{height}; declare how they relate (run --video-geometry {camera}=fit, or \
         {camera}=affine:SX,SY,OX,OY)"
    )]
    ImageSize {
        camera: String,
        got_width: u32,
        got_height: u32,
        width: u32,
        height: u32,
    },
    /// A declared video geometry that cannot apply to this message's image size.
    #[error("camera `{camera}`: video geometry: {why}")]
    VideoGeometry { camera: String, why: String },
}

/// Each rig camera's declared video geometry (`run --video-geometry`), by camera index; `None`: the
/// node's images must be the calibrated image.
pub type VideoGeometries = [Option<VideoGeometry>];

/// A camera's message back to a view (the inverse of [`landmarks_message`]), for a rig whose
/// cameras all send their calibrated image ([`view_from_message_with`] with no declarations).
pub fn view_from_message(rig: &CameraRig, m: &CameraLandmarks) -> Result<View2, LandmarksRejected> {
    view_from_message_with(rig, &[], m)
}

/// A camera's message back to a view: a landmark is observed when its presence and visibility are
/// positive; its confidence is the visibility; its pixel is mapped into the calibrated image by the
/// camera's declared video geometry (`geometries[camera]`, sized by the message's image size). A
/// message is rejected whole when it names a camera not in the rig, its arrays are not 0 or 33 long,
/// a landmark it says is present has a non-finite pixel, or (with landmarks) its image size is not
/// the calibrated one and no geometry is declared for the camera.
pub fn view_from_message_with(
    rig: &CameraRig,
    geometries: &VideoGeometries,
    m: &CameraLandmarks,
) -> Result<View2, LandmarksRejected> {
    let camera = rig
        .index_of_name(&m.camera_id)
        .ok_or_else(|| LandmarksRejected::UnknownCamera(m.camera_id.clone()))?;
    let mut view = View2::empty(camera, m.header.stamp.to_nanos());
    let n = m.x_px.len();
    if n == 0 {
        return Ok(view);
    }
    let calibrated = rig
        .camera(camera)
        .map_or((0, 0), |c| (c.intrinsics.width_px, c.intrinsics.height_px));
    let image = (m.image_width, m.image_height);
    let map = match geometries.get(camera).copied().flatten() {
        Some(g) => g
            .map(image, calibrated)
            .map_err(|e| LandmarksRejected::VideoGeometry {
                camera: m.camera_id.clone(),
                why: e.to_string(),
            })?,
        None if image == calibrated => VideoMap::IDENTITY,
        None => {
            return Err(LandmarksRejected::ImageSize {
                camera: m.camera_id.clone(),
                got_width: image.0,
                got_height: image.1,
                width: calibrated.0,
                height: calibrated.1,
            })
        }
    };
    if n != LANDMARK_COUNT
        || [m.y_px.len(), m.visibility.len(), m.presence.len()]
            .iter()
            .any(|&l| l != n)
    {
        return Err(LandmarksRejected::BadLength {
            camera: m.camera_id.clone(),
            got: n,
        });
    }
    for lm in ergocell_skeleton::Landmark::ALL {
        let i = lm.index();
        let (x, y) = (f64::from(m.x_px[i]), f64::from(m.y_px[i]));
        let (vis, pres) = (f64::from(m.visibility[i]), f64::from(m.presence[i]));
        if pres > 0.0 && vis > 0.0 {
            if !(x.is_finite() && y.is_finite()) {
                return Err(LandmarksRejected::NonFinitePixel {
                    camera: m.camera_id.clone(),
                    landmark: lm.name(),
                    x: m.x_px[i],
                    y: m.y_px[i],
                });
            }
            view.set(lm, Keypoint2::new(x, y, vis.min(1.0)).ok());
        }
    }
    map.apply_view(&mut view);
    Ok(view)
}

fn side_message(side: Option<&SideAssessment>) -> RulaSide {
    let Some(s) = side else {
        return RulaSide::default();
    };
    let r = &s.scores;
    RulaSide {
        scored: true,
        uncertain: s.uncertain,
        upper_arm_score: r.upper_arm_score,
        lower_arm_score: r.lower_arm_score,
        wrist_score: r.wrist_score,
        wrist_twist_score: r.wrist_twist_score,
        posture_score_a: r.posture_score_a,
        score_c_wrist_arm: r.score_c_wrist_arm,
        neck_score: r.neck_score,
        trunk_score: r.trunk_score,
        legs_score: r.legs_score,
        posture_score_b: r.posture_score_b,
        score_d_neck_trunk_legs: r.score_d_neck_trunk_legs,
        final_score: r.final_score,
        action_level: r.action_level,
    }
}

/// The fused skeleton as RViz/Foxglove markers in the `world` frame: the landmarks as a sphere list
/// (colour by action level: green 1, yellow 2, orange 3, red 4) and the rigid bones as a line list.
pub fn skeleton_message(
    skeleton: &ergocell_skeleton::Skeleton3,
    action_level: u8,
) -> ergocell_bridge::msg::MarkerArray {
    use ergocell_bridge::msg::{ColorRGBA, Marker, MarkerArray, Point, Vector3};
    let color = match action_level {
        0 => ColorRGBA {
            r: 0.6,
            g: 0.6,
            b: 0.6,
            a: 1.0,
        },
        1 => ColorRGBA {
            r: 0.1,
            g: 0.8,
            b: 0.2,
            a: 1.0,
        },
        2 => ColorRGBA {
            r: 0.9,
            g: 0.8,
            b: 0.1,
            a: 1.0,
        },
        3 => ColorRGBA {
            r: 1.0,
            g: 0.5,
            b: 0.0,
            a: 1.0,
        },
        _ => ColorRGBA {
            r: 0.9,
            g: 0.1,
            b: 0.1,
            a: 1.0,
        },
    };
    let point = |p: nalgebra::Point3<f64>| Point {
        x: p.x,
        y: p.y,
        z: p.z,
    };
    let joints = Marker {
        header: Header::new(skeleton.stamp_nanos, "world"),
        ns: "operator".to_owned(),
        id: 0,
        r#type: Marker::SPHERE_LIST,
        action: Marker::ADD,
        scale: Vector3 {
            x: 0.04,
            y: 0.04,
            z: 0.04,
        },
        color,
        points: ergocell_skeleton::Landmark::ALL
            .iter()
            .filter_map(|lm| skeleton.position(*lm))
            .map(point)
            .collect(),
        ..Marker::default()
    };
    let bones = Marker {
        header: Header::new(skeleton.stamp_nanos, "world"),
        ns: "operator".to_owned(),
        id: 1,
        r#type: Marker::LINE_LIST,
        action: Marker::ADD,
        scale: Vector3 {
            x: 0.015,
            ..Vector3::default()
        },
        color,
        points: ergocell_skeleton::BONES
            .iter()
            .filter_map(|(a, b)| Some([skeleton.position(*a)?, skeleton.position(*b)?]))
            .flatten()
            .map(point)
            .collect(),
        ..Marker::default()
    };
    MarkerArray {
        markers: vec![joints, bones],
    }
}

/// The joint angles recorded in [`OperatorPose::angle_names`], in this order.
pub const ANGLE_NAMES: [&str; 18] = [
    "trunk_flexion",
    "trunk_side_bend",
    "trunk_twist",
    "neck_flexion",
    "neck_side_bend",
    "neck_twist",
    "left_upper_arm_flexion",
    "left_upper_arm_abduction",
    "left_elbow_flexion",
    "left_wrist_flexion",
    "left_wrist_deviation",
    "right_upper_arm_flexion",
    "right_upper_arm_abduction",
    "right_elbow_flexion",
    "right_wrist_flexion",
    "right_wrist_deviation",
    "left_upper_arm_elevation",
    "right_upper_arm_elevation",
];

/// The fused skeleton by landmark index (NaN where not fused) and, when the frame was assessed, the
/// joint angles RULA was scored from (radians, NaN where not observed).
pub fn operator_pose_message(
    skeleton: &ergocell_skeleton::Skeleton3,
    assessment: Option<&FrameAssessment>,
) -> OperatorPose {
    let mut m = OperatorPose {
        header: Header::new(skeleton.stamp_nanos, "world"),
        x: Vec::with_capacity(LANDMARK_COUNT),
        y: Vec::with_capacity(LANDMARK_COUNT),
        z: Vec::with_capacity(LANDMARK_COUNT),
        ..OperatorPose::default()
    };
    for lm in ergocell_skeleton::Landmark::ALL {
        let p = skeleton
            .position(lm)
            .unwrap_or_else(|| nalgebra::Point3::new(f64::NAN, f64::NAN, f64::NAN));
        m.x.push(p.x);
        m.y.push(p.y);
        m.z.push(p.z);
    }
    if let Some(a) = assessment {
        let b = &a.angles;
        let values = [
            b.trunk_flexion_rad,
            b.trunk_side_bend_rad,
            b.trunk_twist_rad,
            b.neck_flexion_rad,
            b.neck_side_bend_rad,
            b.neck_twist_rad,
            b.left.upper_arm_flexion_rad,
            b.left.upper_arm_abduction_rad,
            b.left.elbow_flexion_rad,
            b.left.wrist_flexion_rad,
            b.left.wrist_deviation_rad,
            b.right.upper_arm_flexion_rad,
            b.right.upper_arm_abduction_rad,
            b.right.elbow_flexion_rad,
            b.right.wrist_flexion_rad,
            b.right.wrist_deviation_rad,
            b.left.upper_arm_elevation_rad,
            b.right.upper_arm_elevation_rad,
        ];
        m.angle_names = ANGLE_NAMES.iter().map(|&n| n.to_owned()).collect();
        m.angle_rad = values.iter().map(|v| v.unwrap_or(f64::NAN)).collect();
    }
    m
}

/// The robot's TCP (sphere, id 0) and the locked handover point (sphere, id 1) as markers in the
/// `world` frame, for Foxglove and `ergocell review`.
pub fn robot_markers_message(
    stamp_nanos: i64,
    tcp_world: Option<nalgebra::Point3<f64>>,
    handover_world: Option<nalgebra::Point3<f64>>,
) -> ergocell_bridge::msg::MarkerArray {
    use ergocell_bridge::msg::{ColorRGBA, Marker, MarkerArray, Point, Pose, Quaternion, Vector3};
    let sphere = |id: i32, p: nalgebra::Point3<f64>, size: f64, color: ColorRGBA| Marker {
        header: Header::new(stamp_nanos, "world"),
        ns: "robot".to_owned(),
        id,
        r#type: Marker::SPHERE,
        action: Marker::ADD,
        pose: Pose {
            position: Point {
                x: p.x,
                y: p.y,
                z: p.z,
            },
            orientation: Quaternion::default(),
        },
        scale: Vector3 {
            x: size,
            y: size,
            z: size,
        },
        color,
        ..Marker::default()
    };
    let mut markers = Vec::new();
    if let Some(p) = tcp_world {
        markers.push(sphere(
            0,
            p,
            0.06,
            ColorRGBA {
                r: 0.2,
                g: 0.6,
                b: 1.0,
                a: 1.0,
            },
        ));
    }
    if let Some(h) = handover_world {
        markers.push(sphere(
            1,
            h,
            0.05,
            ColorRGBA {
                r: 1.0,
                g: 0.2,
                b: 0.8,
                a: 0.8,
            },
        ));
    }
    MarkerArray { markers }
}

/// The per-frame RULA state.
pub fn ergonomic_message(a: &FrameAssessment) -> ErgonomicState {
    use ergocell_ergonomics::confidence::{BandConfidence, ANGLED_REGIONS};
    // per angled region, one field of its confidence; NaN where not known, empty when not scored
    let per_region = |s: Option<&SideAssessment>, f: fn(&BandConfidence) -> f64| -> Vec<f64> {
        s.map_or_else(Vec::new, |s| {
            ANGLED_REGIONS
                .iter()
                .map(|r| s.confidence.get(*r).map_or(f64::NAN, |c| f(&c)))
                .collect()
        })
    };
    let (l, r) = (a.left.as_ref(), a.right.as_ref());
    ErgonomicState {
        header: Header::new(a.stamp_nanos, "world"),
        left: side_message(l),
        right: side_message(r),
        action_level: a.headline().map_or(0, |h| h.scores.action_level),
        left_band_probability: per_region(l, |c| c.probability),
        right_band_probability: per_region(r, |c| c.probability),
        left_angle_sd_deg: per_region(l, |c| c.sd_deg),
        right_angle_sd_deg: per_region(r, |c| c.sd_deg),
    }
}

/// The per-frame REBA state, beside [`ergonomic_message`] with the same stamp.
pub fn reba_message(a: &FrameAssessment) -> RebaState {
    let side = |s: Option<&SideAssessment>| {
        s.map_or_else(RebaSide::default, |s| {
            let r = &s.reba.scores;
            RebaSide {
                scored: true,
                uncertain: s.reba.uncertain,
                trunk_score: r.trunk_score,
                neck_score: r.neck_score,
                legs_score: r.legs_score,
                score_a: r.score_a,
                upper_arm_score: r.upper_arm_score,
                lower_arm_score: r.lower_arm_score,
                wrist_score: r.wrist_score,
                score_b: r.score_b,
                table_c: r.table_c,
                activity_score: r.activity_score,
                reba_score: r.reba_score,
                action_level: r.action_level,
            }
        })
    };
    let (left, right) = (side(a.left.as_ref()), side(a.right.as_ref()));
    let worse = [left, right]
        .into_iter()
        .filter(|s| s.scored)
        .max_by_key(|s| (s.reba_score, s.uncertain));
    RebaState {
        header: Header::new(a.stamp_nanos, "world"),
        left,
        right,
        action_level: worse.map_or(0, |s| s.action_level),
    }
}

/// A warning event.
pub fn warning_message(w: &WarningEvent) -> PostureWarning {
    let kind = match w.kind {
        ergocell_ergonomics::warnings::WarningKind::Raised => PostureWarning::RAISED,
        ergocell_ergonomics::warnings::WarningKind::Changed => "changed",
        ergocell_ergonomics::warnings::WarningKind::Cleared => "cleared",
    };
    PostureWarning {
        header: Header::new(w.stamp_nanos, "world"),
        kind: kind.to_owned(),
        region: w.region.name().to_owned(),
        side: w.side.map_or(String::new(), |s| s.name().to_owned()),
        region_score: w.region_score,
        angle_deg: w.angle_deg.unwrap_or(f64::NAN),
        action_level: w.action_level,
        uncertain: w.uncertain,
        message: w.message.clone(),
        band_probability: w.band_probability.unwrap_or(f64::NAN),
        near_limit: w.near_limit,
    }
}

/// The session state message of `machine` now.
pub fn session_state_message(
    machine: &SessionMachine,
    stamp_nanos: i64,
    reason: &str,
) -> SessionState {
    let decision = machine.decision();
    let estimate = decision.map(|d| &d.estimate);
    SessionState {
        header: Header::new(stamp_nanos, "world"),
        state: machine.state().name().to_owned(),
        reason: reason.to_owned(),
        height_m: estimate.map_or(f64::NAN, |e| e.height_m),
        height_uncertainty_m: estimate.map_or(f64::NAN, |e| e.uncertainty_m),
        height_class: machine
            .decision()
            .map_or(String::new(), |d| d.class.name().to_owned()),
        trajectory_sha256: machine.lock_sha256().unwrap_or_default().to_owned(),
        robot_held: machine.hold_reason().is_some(),
        cameras_fresh: u32::try_from(machine.cameras_fresh()).unwrap_or(u32::MAX),
        stereo_pairs_tracking: u32::try_from(machine.pairs_tracking()).unwrap_or(u32::MAX),
        trajectory_approved_by: machine.approved_by(),
        height_decision_basis: decision.map_or(String::new(), |d| d.basis.name().to_owned()),
        height_class_probability: decision.map_or(f64::NAN, |d| d.probability),
        height_expected_rula_cost: decision
            .and_then(|d| d.expected_rula_cost)
            .unwrap_or(f64::NAN),
        parts_taken: machine.summary().parts_taken,
        last_part_hand: machine
            .summary()
            .last_part
            .map_or(String::new(), |p| p.hand.name().to_owned()),
        last_part_closest_m: machine
            .summary()
            .last_part
            .map_or(f64::NAN, |p| p.closest_m),
    }
}

/// The session-state message of each event that has one (state changes, class decided, lock,
/// refused change, camera degraded/restored), in order, each with the state **as of that event**
/// (by the end of the step the machine may have moved on: decided → locked → working in one step).
pub fn session_state_messages(
    machine: &SessionMachine,
    now_nanos: i64,
    events: &[SessionEvent],
) -> Vec<SessionState> {
    use SessionEvent as E;
    let mut current = events
        .iter()
        .find_map(|e| match e {
            E::StateChanged { from, .. } => Some(*from),
            _ => None,
        })
        .unwrap_or_else(|| machine.state());
    let mut out = Vec::new();
    for e in events {
        let reason = match e {
            E::StateChanged { to, reason, .. } => {
                current = *to;
                reason.clone()
            }
            E::ClassDecided { .. }
            | E::TrajectoryLocked { .. }
            | E::ChangeRefused { .. }
            | E::PartTaken { .. }
            | E::CameraDegraded { .. }
            | E::CameraRestored { .. } => describe(e),
            E::RobotCommandSent { .. } | E::Warning(_) | E::Frame { .. } => continue,
        };
        let mut m = session_state_message(machine, now_nanos, &reason);
        current.name().clone_into(&mut m.state);
        if let E::PartTaken {
            part,
            hand,
            closest_m,
            ..
        } = e
        {
            m.parts_taken = *part;
            hand.name().clone_into(&mut m.last_part_hand);
            m.last_part_closest_m = *closest_m;
        }
        out.push(m);
    }
    out
}

/// The controller event of a report of the robot side, as `run` publishes and records it and
/// `demo` records it: kind, leg, status and numbers as fields, the words in `text` (a failure's own
/// words). The driver's raw state (`is_configured`, hardware events) has none of its own: what it
/// changes is [`driver_readiness_message`].
pub fn robot_report_message(stamp_nanos: i64, report: &RobotReport) -> Option<ControllerEvent> {
    use ergocell_bridge::msg::ControllerEventKind as K;
    let label = |leg: &Option<Leg>| leg.map_or_else(no_leg, leg_label);
    let event = |kind: K, leg: &Option<Leg>, text: String| {
        controller_event(stamp_nanos, kind, &label(leg), text)
    };
    let failure = |answer: &GoalAnswer| answer.failure().map(|f| f.to_string()).unwrap_or_default();
    Some(match report {
        RobotReport::Goal(answer) => match answer {
            GoalAnswer::Accepted { leg } => event(K::Accepted, leg, String::new()),
            GoalAnswer::Rejected { leg } => event(K::Rejected, leg, failure(answer)),
            GoalAnswer::Unanswered { leg, .. } => event(K::NoResponse, leg, failure(answer)),
            GoalAnswer::Lost { leg, .. } => event(K::Failed, leg, failure(answer)),
            GoalAnswer::CancelRequested { leg } => event(K::CancelRequested, leg, String::new()),
            GoalAnswer::Feedback {
                leg,
                count,
                max_error_rad,
            } => ControllerEvent {
                feedback_count: u32::try_from(*count).unwrap_or(u32::MAX),
                max_error: max_error_rad.unwrap_or(f64::NAN),
                ..event(K::Feedback, leg, String::new())
            },
            GoalAnswer::Finished {
                leg,
                status,
                result,
                error_string,
                feedback_count,
            } => ControllerEvent {
                status: status.name().to_owned(),
                error_code: result.code(),
                feedback_count: u32::try_from(*feedback_count).unwrap_or(u32::MAX),
                ..event(K::Finished, leg, error_string.clone())
            },
        },
        RobotReport::Deviation(d) => event(K::Monitor, &None, d.to_string()),
        RobotReport::JointStatesStale { timeout_s } => event(
            K::Monitor,
            &None,
            RobotUnready::JointStatesStale {
                timeout_s: *timeout_s,
            }
            .to_string(),
        ),
        RobotReport::JointStatesBack => event(K::Monitor, &None, "joint states back".to_owned()),
        RobotReport::DriverConfigured(_) | RobotReport::DriverEvent(_) => return None,
    })
}

/// The driver's readiness changed: `unready` (`None`: configured and controlling), status
/// `not_ready` or `ready`.
pub fn driver_readiness_message(
    stamp_nanos: i64,
    unready: Option<&RobotUnready>,
) -> ControllerEvent {
    ControllerEvent {
        status: if unready.is_some() {
            "not_ready"
        } else {
            "ready"
        }
        .to_owned(),
        ..controller_event(
            stamp_nanos,
            ergocell_bridge::msg::ControllerEventKind::Driver,
            &no_leg(),
            unready.map_or_else(
                || "configured and controlling".to_owned(),
                ToString::to_string,
            ),
        )
    }
}

/// The message on the controller's `joint_trajectory` topic for a command (a hold is the empty
/// trajectory: the joint trajectory controller drops its goal and stops).
///
/// A trajectory goes out with a zero `header.stamp`: the joint trajectory controller then starts it
/// on receipt, on its own clock. A stamp from this PC's clock would shift or cut the start if the
/// two clocks disagree (a past stamp skips points). `stamp_nanos` only stamps the hold.
pub fn command_message(
    command: &ergocell_cell::session::RobotCommand,
    stamp_nanos: i64,
) -> JointTrajectory {
    use ergocell_cell::session::RobotCommand;
    use JointTrajectory;
    match command {
        RobotCommand::Execute { trajectory, .. } => leg_message(trajectory),
        RobotCommand::Hold { .. } => JointTrajectory {
            header: Header::new(stamp_nanos, ""),
            ..JointTrajectory::default()
        },
    }
}

/// A leg of the locked trajectory as a `trajectory_msgs/JointTrajectory` (zero stamp).
pub fn leg_message(leg: &ergocell_cell::session::LegTrajectory) -> JointTrajectory {
    use ergocell_bridge::msg::{Duration, JointTrajectory, JointTrajectoryPoint};
    JointTrajectory {
        header: Header::default(),
        joint_names: leg.joint_names.clone(),
        points: leg
            .points
            .iter()
            .map(|p| JointTrajectoryPoint {
                positions: p.positions_rad.clone(),
                velocities: p.velocities_rad_s.clone(),
                accelerations: p.accelerations_rad_s2.clone(),
                effort: Vec::new(),
                time_from_start: Duration::from_secs_f64(p.time_from_start_s),
            })
            .collect(),
    }
}

/// ", expected RULA cost +0.02" for a class decision's expected cost, or nothing without one.
pub use ergocell_ergonomics::height_text::rula_cost_clause;

/// The console's lines for one step's events (frames left out): each event as [`describe`] says
/// it, except that cameras degraded in the same step for the same reason share one line (a cell
/// started before its camera nodes names them all at once, not six times), and a hold sent in the
/// step that holds or ends the session leaves its reason to the state change's line (a session
/// ended for an unverified trajectory said it twice).
pub fn describe_step(events: &[SessionEvent]) -> Vec<String> {
    let mut lines = Vec::new();
    let mut i = 0;
    while i < events.len() {
        match &events[i] {
            SessionEvent::Frame { .. } => i += 1,
            SessionEvent::CameraDegraded { why, .. } => {
                let mut cameras = Vec::new();
                while let Some(SessionEvent::CameraDegraded {
                    camera, why: same, ..
                }) = events.get(i)
                {
                    if same != why {
                        break;
                    }
                    cameras.push(camera.as_str());
                    i += 1;
                }
                lines.push(if cameras.len() == 1 {
                    format!("camera {} degraded: {why}", cameras[0])
                } else {
                    format!("cameras {} degraded: {why}", cameras.join(", "))
                });
            }
            SessionEvent::RobotCommandSent {
                command: RobotCommand::Hold { .. },
                ..
            } if events.iter().any(|e| {
                matches!(
                    e,
                    SessionEvent::StateChanged {
                        to: ergocell_cell::session::SessionState::Held
                            | ergocell_cell::session::SessionState::SessionEnded,
                        ..
                    }
                )
            }) =>
            {
                lines.push(HOLD_LINE.to_owned());
                i += 1;
            }
            e => {
                lines.push(describe(e));
                i += 1;
            }
        }
    }
    lines
}

/// How the console names a hold: what the robot does, not how it is stopped.
const HOLD_LINE: &str = "robot ← HOLD (stopped where it is; not an e-stop)";

/// One line for a person reading the terminal or the log.
pub fn describe(e: &SessionEvent) -> String {
    use ergocell_cell::session::SessionEvent as E;
    use ergocell_ergonomics::height::DecisionBasis;
    match e {
        E::StateChanged {
            from, to, reason, ..
        } => format!("state {from} → {to}: {reason}"),
        E::ClassDecided {
            height_m,
            uncertainty_m,
            class,
            basis,
            probability,
            expected_rula_cost,
            ..
        } => format!(
            "height measured {height_m:.3} ± {uncertainty_m:.3} m → class {} ({}; probability {probability:.2}{})",
            class.name(),
            match basis {
                DecisionBasis::Interval => "the interval lies inside the class",
                DecisionBasis::ExpectedRula => "across a boundary: the lowest expected RULA",
                DecisionBasis::MostProbable => "across a boundary: the most probable class",
            },
            rula_cost_clause(*expected_rula_cost)
        ),
        E::TrajectoryLocked {
            class,
            lock_sha256,
            approved_by,
            ..
        } => format!(
            "trajectory {class} validated, verified and locked: sha256 {lock_sha256} (approved by {})",
            approved_by.join(", ")
        ),
        E::ChangeRefused {
            requested, reason, ..
        } => format!("change to {requested} refused: {reason}"),
        E::PartTaken {
            part,
            hand,
            closest_m,
            ..
        } => format!(
            "part {part} taken: the operator's {} hand came to {closest_m:.3} m of the handover \
             point and left it; robot going home for the next part",
            hand.name()
        ),
        E::CameraDegraded { camera, why, .. } => format!("camera {camera} degraded: {why}"),
        E::CameraRestored { camera, .. } => format!("camera {camera} restored"),
        E::RobotCommandSent { command, .. } => match command {
            RobotCommand::Execute {
                leg, trajectory, ..
            } => format!(
                "robot ← trajectory {leg:?} ({} points, {:.1} s)",
                trajectory.points.len(),
                trajectory
                    .points
                    .last()
                    .map_or(0.0, |p| p.time_from_start_s)
            ),
            RobotCommand::Hold { reason } => format!("{HOLD_LINE}: {reason}"),
        },
        E::Warning(w) => format!("RULA warning: {}", w.message),
        E::Frame { .. } => "frame".to_owned(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use ergocell_cell::session::SessionState;

    fn degraded(camera: &str, why: &str) -> SessionEvent {
        SessionEvent::CameraDegraded {
            stamp_nanos: 1,
            camera: camera.to_owned(),
            why: why.to_owned(),
        }
    }

    /// The names the review and exposure compare with are the names the cell writes.
    /// A controller's report becomes its event with the status, the result code, the counts and
    /// the leg as fields (the one conversion, `run`'s and `demo`'s).
    #[test]
    fn a_robot_report_becomes_its_controller_event_with_its_facts_as_fields() {
        use ergocell_bridge::controller::{ControllerReport, GoalStatusEnum};
        use ergocell_bridge::msg::ControllerEvent;
        let label = crate::robot::leg_label(ergocell_cell::session::Leg::ToHandover);
        let event = |r: ControllerReport, t: i64| {
            robot_report_message(t, &RobotReport::Goal(crate::robot::goal_answer(&r))).unwrap()
        };
        let m = event(
            ControllerReport::Finished {
                label: label.clone(),
                status: GoalStatusEnum::Aborted,
                error_code: -4,
                error_string: "joint_2 0.3 rad off".into(),
                feedback_count: 10,
            },
            7,
        );
        assert_eq!(
            (
                m.kind.as_str(),
                m.status.as_str(),
                m.error_code,
                m.feedback_count
            ),
            ("finished", "aborted", -4, 10)
        );
        assert_eq!(m.text, "joint_2 0.3 rad off");
        assert_eq!(m.header.stamp.to_nanos(), 7);
        assert_eq!(
            (m.leg.as_str(), m.leg_id),
            ("home → handover", ControllerEvent::LEG_TO_HANDOVER),
            "the leg in words and as the constant"
        );
        let m = event(
            ControllerReport::Feedback {
                label: label.clone(),
                count: 25,
                max_error_rad: Some(0.002),
            },
            0,
        );
        assert_eq!(
            (m.kind.as_str(), m.feedback_count, m.max_error),
            ("feedback", 25, 0.002)
        );
        let m = event(
            ControllerReport::Rejected {
                label: label.clone(),
            },
            0,
        );
        assert_eq!(
            (m.kind.as_str(), m.leg_id, m.max_error.is_nan()),
            ("rejected", ControllerEvent::LEG_TO_HANDOVER, true)
        );
        assert_eq!(
            robot_report_message(0, &RobotReport::DriverConfigured(true)),
            None,
            "the driver's raw state has no event of its own"
        );
        let d = driver_readiness_message(0, Some(&RobotUnready::DriverSilent));
        assert_eq!(
            (d.kind.as_str(), d.status.as_str()),
            ("driver", "not_ready")
        );
        let d = driver_readiness_message(0, None);
        assert_eq!(
            (d.status.as_str(), d.text.as_str()),
            ("ready", "configured and controlling")
        );
    }

    #[test]
    fn the_recorded_names_programs_compare_are_the_cells() {
        assert_eq!(
            SessionState::SessionEnded.name(),
            ergocell_bridge::msg::SessionState::SESSION_ENDED
        );
        let raised = warning_message(&ergocell_ergonomics::warnings::WarningEvent {
            stamp_nanos: 1,
            kind: ergocell_ergonomics::warnings::WarningKind::Raised,
            region: ergocell_ergonomics::assess::BodyRegion::Neck,
            side: None,
            region_score: 3,
            angle_deg: Some(25.0),
            action_level: 2,
            uncertain: false,
            band_probability: Some(0.9),
            near_limit: false,
            message: String::new(),
        });
        assert_eq!(raised.kind, PostureWarning::RAISED);
    }

    #[test]
    fn cameras_degraded_together_for_one_reason_share_a_line() {
        let never = "no view at all since the session started (500 ms ago)";
        let events = [
            degraded("s1_left", never),
            degraded("s1_right", never),
            degraded("s2_left", never),
            degraded("s2_right", "no view for more than 500 ms"),
            SessionEvent::CameraRestored {
                stamp_nanos: 2,
                camera: "s3_left".to_owned(),
            },
            degraded("s3_right", never),
        ];
        assert_eq!(
            describe_step(&events),
            vec![
                format!("cameras s1_left, s1_right, s2_left degraded: {never}"),
                "camera s2_right degraded: no view for more than 500 ms".to_owned(),
                describe(&events[4]),
                format!("camera s3_right degraded: {never}"),
            ]
        );
        assert!(describe_step(&[]).is_empty());
    }

    #[test]
    fn a_hold_whose_reason_the_state_line_gives_says_it_once() {
        use ergocell_cell::session::{HoldReason, RobotUnready};
        let stale = HoldReason::RobotNotReady {
            unready: RobotUnready::JointStatesStale { timeout_s: 0.1 },
        };
        let why = stale.to_string();
        let hold = || SessionEvent::RobotCommandSent {
            stamp_nanos: 1,
            command: RobotCommand::Hold {
                reason: stale.clone(),
            },
        };
        let held = SessionEvent::StateChanged {
            stamp_nanos: 1,
            from: SessionState::Working,
            to: SessionState::Held,
            reason: why.clone(),
        };
        let lines = describe_step(&[hold(), held.clone()]);
        assert_eq!(lines, vec![HOLD_LINE.to_owned(), describe(&held)]);
        assert_eq!(lines.iter().filter(|l| l.contains(&why)).count(), 1);
        // A hold alone keeps its reason.
        assert_eq!(
            describe_step(&[hold()]),
            vec![format!("{HOLD_LINE}: {why}")]
        );
    }
}
