//! The digital twin's sessions as recordings (`ergocell sim adaptation --record-height`): the
//! messages a simulated session is recorded with, the same a session of the cell records.
//!
//! The demo's twin records its cameras' views, its robot's reports and its joint states with the
//! TCP markers as a real cell records them ([`record_views`], [`record_robot_report`],
//! [`record_robot_state`]).
//!
//! A twin's recording opens with a session state saying it is simulated, with the operator's true
//! stature and class ([`simulated_state`]); each tracked frame is recorded as a session records
//! it, its frame's messages then its warnings' ([`tracked_messages`]). ROS-message work, so it is
//! here beside [`crate::messages`] and [`crate::recording`]; the simulation is the caller's (this
//! crate does not depend on the twin, nor the twin on ROS).

use ergocell_bridge::msg::{Header, JointState, SessionState};
use ergocell_cell::session::{ReportEffect, RobotReport};
use ergocell_ergonomics::{FrameAssessment, HeightClass, WarningEvent};
use ergocell_perception::{CameraRig, View2};
use ergocell_skeleton::Skeleton3;

use crate::messages::{self, frame_messages, warning_message, Outgoing};
use crate::recording::{topics, Recording};
use crate::robot_markers::RobotGeometry;

/// The state a twin's recording opens with, at `now_nanos`: `simulated`, why (`reason`), and the
/// operator's true stature and class. The simulator knows them: the stature has no uncertainty and
/// the class is the truth's, not a decision, so it has no probability or expected cost (NaN).
pub fn simulated_state(
    now_nanos: i64,
    reason: String,
    stature_m: f64,
    class: HeightClass,
) -> SessionState {
    SessionState {
        header: Header::new(now_nanos, "world"),
        state: "simulated".to_owned(),
        reason,
        height_m: stature_m,
        height_uncertainty_m: f64::NAN,
        height_class: class.name().to_owned(),
        height_class_probability: f64::NAN,
        height_expected_rula_cost: f64::NAN,
        last_part_closest_m: f64::NAN,
        ..SessionState::default()
    }
}

/// One tracked frame as a session records it: its frame's messages ([`frame_messages`]: skeleton
/// markers, operator pose, RULA and REBA), then a `PostureWarning` per warning event it moved, in
/// order.
pub fn tracked_messages(
    skeleton: &Skeleton3,
    assessment: &FrameAssessment,
    warnings: &[WarningEvent],
) -> Vec<Outgoing> {
    let mut out = frame_messages(skeleton, Some(assessment));
    out.extend(
        warnings
            .iter()
            .map(|w| Outgoing::Warning(warning_message(w))),
    );
    out
}

/// The twin's camera views at `now`, recorded as the cameras' messages.
pub fn record_views(recording: &mut Recording, rig: &CameraRig, now: i64, views: &[View2]) {
    recording.with(|rec| {
        views.iter().try_for_each(|v| {
            let m = messages::landmarks_message(rig, v);
            rec.write(&topics::camera(&m.camera_id), now, &m)
        })
    });
}

/// A robot report applied at `t`, recorded as a real cell records its controller's events, and
/// the driver's readiness when the report changed it.
pub fn record_robot_report(
    recording: &mut Recording,
    t: i64,
    report: &RobotReport,
    effect: &ReportEffect,
) {
    if let Some(e) = messages::robot_report_message(t, report) {
        recording.with(|rec| rec.write(topics::CONTROLLER_EVENTS, t, &e));
    }
    if let Some(readiness) = &effect.driver_readiness {
        let e = messages::driver_readiness_message(t, readiness.as_ref());
        recording.with(|rec| rec.write(topics::CONTROLLER_EVENTS, t, &e));
    }
}

/// The twin robot's joint state at `now` (its `joints` at `positions`) and, with the served
/// class's `geometry`, its TCP and handover markers.
pub fn record_robot_state(
    recording: &mut Recording,
    now: i64,
    geometry: Option<&RobotGeometry>,
    joints: &[String],
    positions: Vec<f64>,
) {
    let js = JointState {
        header: Header::new(now, ""),
        name: joints.to_vec(),
        position: positions,
        ..JointState::default()
    };
    recording.with(|rec| {
        rec.write(topics::JOINT_STATES, now, &js)?;
        if let Some(g) = geometry {
            if let Some(p) = g.tcp_world(&js) {
                let m = messages::robot_markers_message(now, Some(p), Some(g.handover_world()));
                rec.write(topics::ROBOT_MARKERS, now, &m)?;
            }
        }
        Ok(())
    });
}

#[cfg(test)]
mod tests {
    use super::*;
    use ergocell_bridge::msg::PostureWarning;
    use ergocell_ergonomics::assess::BodyRegion;
    use ergocell_ergonomics::{BodyAngles, WarningKind};

    #[test]
    fn the_opening_state_says_simulated_with_the_true_stature_and_no_decision() {
        let s = simulated_state(42, "digital twin".to_owned(), 1.6, HeightClass::C1);
        assert_eq!(s.state, "simulated");
        assert_eq!(s.reason, "digital twin");
        assert_eq!(s.header, Header::new(42, "world"));
        assert_eq!((s.height_m, s.height_class.as_str()), (1.6, "c1"));
        for unknown in [
            s.height_uncertainty_m,
            s.height_class_probability,
            s.height_expected_rula_cost,
            s.last_part_closest_m,
        ] {
            assert!(unknown.is_nan());
        }
        // nothing of a session's robot side
        assert!(s.trajectory_sha256.is_empty() && !s.robot_held && s.parts_taken == 0);
    }

    #[test]
    fn a_tracked_frame_is_its_frame_then_each_warning_in_order() {
        let skeleton = Skeleton3::empty(7);
        let assessment = FrameAssessment {
            stamp_nanos: 7,
            angles: BodyAngles::default(),
            left: None,
            right: None,
            unscored_reasons: Vec::new(),
        };
        let warning = |kind, region| WarningEvent {
            stamp_nanos: 7,
            kind,
            region,
            side: None,
            region_score: 3,
            angle_deg: Some(25.0),
            action_level: 2,
            uncertain: false,
            band_probability: Some(0.9),
            near_limit: false,
            message: String::new(),
        };
        let warnings = [
            warning(WarningKind::Raised, BodyRegion::Neck),
            warning(WarningKind::Cleared, BodyRegion::Trunk),
        ];
        let out = tracked_messages(&skeleton, &assessment, &warnings);
        let frame = frame_messages(&skeleton, Some(&assessment)).len();
        assert_eq!(frame, 4, "skeleton, pose, RULA, REBA");
        assert_eq!(out.len(), frame + 2);
        assert!(matches!(out[0], Outgoing::Skeleton(_)));
        assert!(matches!(out[3], Outgoing::Reba(_)));
        let kinds: Vec<&str> = out[frame..]
            .iter()
            .filter_map(|m| match m {
                Outgoing::Warning(w) => Some(w.kind.as_str()),
                _ => None,
            })
            .collect();
        assert_eq!(kinds, [PostureWarning::RAISED, "cleared"]);
        assert_eq!(tracked_messages(&skeleton, &assessment, &[]).len(), frame);
    }
}
