//! Recordings made before a message carried a fact as a field: the one place the review reads
//! them. Each decoder tries the current layout first and falls back to the older one (the field then
//! unknown: NaN, empty or 0), and the only facts read from words are here: a leg from the words
//! `ergocell run` wrote for it, and a part taken from its session state's reason.

use ergocell_bridge::cdr;
use ergocell_bridge::msg::{
    ControllerEvent, ErgonomicState, PostureWarning, RosMessage, SessionState,
};

use crate::analysis::finite;
use crate::read::{take, Stamped};

/// `SessionState` as recorded before it carried the height decision (basis, probability, expected
/// RULA cost) and the parts taken as fields (the same fields, without those six): such recordings
/// stay reviewable.
#[derive(serde::Deserialize)]
#[cfg_attr(test, derive(serde::Serialize))]
pub(crate) struct SessionStateWithoutDecision {
    pub(crate) header: ergocell_bridge::msg::Header,
    pub(crate) state: String,
    pub(crate) reason: String,
    pub(crate) height_m: f64,
    pub(crate) height_uncertainty_m: f64,
    pub(crate) height_class: String,
    pub(crate) trajectory_sha256: String,
    pub(crate) robot_held: bool,
    pub(crate) cameras_fresh: u32,
    pub(crate) stereo_pairs_tracking: u32,
    pub(crate) trajectory_approved_by: Vec<String>,
}

/// Decodes a `SessionState`, or one of the layout before the decision's and the parts' fields (those
/// then NaN, empty or 0: unknown; the review reads such a recording's parts from the reasons).
pub(crate) fn take_session_state(
    schema: &str,
    data: &[u8],
    log_time_nanos: u64,
) -> Result<Stamped<SessionState>, String> {
    let current = take(schema, data, log_time_nanos);
    if current.is_ok() || schema != SessionState::type_name() {
        return current;
    }
    let Ok(old) = cdr::decode::<SessionStateWithoutDecision>(data) else {
        return current;
    };
    Ok(Stamped {
        log_time_nanos,
        logged_nanos: log_time_nanos,
        message: SessionState {
            header: old.header,
            state: old.state,
            reason: old.reason,
            height_m: old.height_m,
            height_uncertainty_m: old.height_uncertainty_m,
            height_class: old.height_class,
            trajectory_sha256: old.trajectory_sha256,
            robot_held: old.robot_held,
            cameras_fresh: old.cameras_fresh,
            stereo_pairs_tracking: old.stereo_pairs_tracking,
            trajectory_approved_by: old.trajectory_approved_by,
            height_decision_basis: String::new(),
            height_class_probability: f64::NAN,
            height_expected_rula_cost: f64::NAN,
            parts_taken: 0,
            last_part_hand: String::new(),
            last_part_closest_m: f64::NAN,
        },
    })
}

/// `ErgonomicState` as recorded before it carried how sure each region's band is: such recordings
/// stay reviewable, their confidences unknown (empty).
#[derive(serde::Deserialize)]
#[cfg_attr(test, derive(serde::Serialize))]
pub(crate) struct ErgonomicStateWithoutConfidence {
    pub(crate) header: ergocell_bridge::msg::Header,
    pub(crate) left: ergocell_bridge::msg::RulaSide,
    pub(crate) right: ergocell_bridge::msg::RulaSide,
    pub(crate) action_level: u8,
}

/// Decodes an `ErgonomicState`, or one of the layout before the band probabilities.
pub(crate) fn take_ergonomic_state(
    schema: &str,
    data: &[u8],
    log_time_nanos: u64,
) -> Result<Stamped<ErgonomicState>, String> {
    let current = take(schema, data, log_time_nanos);
    if current.is_ok() || schema != ErgonomicState::type_name() {
        return current;
    }
    let Ok(old) = cdr::decode::<ErgonomicStateWithoutConfidence>(data) else {
        return current;
    };
    Ok(Stamped {
        log_time_nanos,
        logged_nanos: log_time_nanos,
        message: ErgonomicState {
            header: old.header,
            left: old.left,
            right: old.right,
            action_level: old.action_level,
            ..ErgonomicState::default()
        },
    })
}

/// `PostureWarning` as recorded before it carried its band's probability: such recordings stay
/// reviewable, the probability unknown (NaN) and never "near the limit".
#[derive(serde::Deserialize)]
#[cfg_attr(test, derive(serde::Serialize))]
pub(crate) struct PostureWarningWithoutConfidence {
    pub(crate) header: ergocell_bridge::msg::Header,
    pub(crate) kind: String,
    pub(crate) region: String,
    pub(crate) side: String,
    pub(crate) region_score: u8,
    pub(crate) angle_deg: f64,
    pub(crate) action_level: u8,
    pub(crate) uncertain: bool,
    pub(crate) message: String,
}

/// Decodes a `PostureWarning`, or one of the layout before the band's probability.
pub(crate) fn take_posture_warning(
    schema: &str,
    data: &[u8],
    log_time_nanos: u64,
) -> Result<Stamped<PostureWarning>, String> {
    let current = take(schema, data, log_time_nanos);
    if current.is_ok() || schema != PostureWarning::type_name() {
        return current;
    }
    let Ok(old) = cdr::decode::<PostureWarningWithoutConfidence>(data) else {
        return current;
    };
    Ok(Stamped {
        log_time_nanos,
        logged_nanos: log_time_nanos,
        message: PostureWarning {
            header: old.header,
            kind: old.kind,
            region: old.region,
            side: old.side,
            region_score: old.region_score,
            angle_deg: old.angle_deg,
            action_level: old.action_level,
            uncertain: old.uncertain,
            message: old.message,
            band_probability: f64::NAN,
            near_limit: false,
        },
    })
}

/// `ControllerEvent` as recorded before it carried the leg as a constant (`leg_id`): such recordings
/// stay reviewable.
#[derive(serde::Deserialize)]
#[cfg_attr(test, derive(serde::Serialize))]
pub(crate) struct ControllerEventWithoutLegId {
    pub(crate) header: ergocell_bridge::msg::Header,
    pub(crate) kind: String,
    pub(crate) leg: String,
    pub(crate) status: String,
    pub(crate) error_code: i32,
    pub(crate) text: String,
    pub(crate) feedback_count: u32,
    pub(crate) max_error: f64,
    pub(crate) sample_stamp: ergocell_bridge::msg::Time,
}

/// The leg constant of an event recorded before `leg_id`, from the words `ergocell run` wrote for
/// the two legs then (the only place the review reads a leg from words).
pub(crate) fn legacy_leg_id(words: &str) -> u8 {
    match words {
        "home → handover" => ControllerEvent::LEG_TO_HANDOVER,
        "handover → home" => ControllerEvent::LEG_TO_HOME,
        _ => ControllerEvent::LEG_NONE,
    }
}

/// Decodes a `ControllerEvent`, or one of the layout before `leg_id` (the leg's constant then from
/// its words).
pub(crate) fn take_controller_event(
    schema: &str,
    data: &[u8],
    log_time_nanos: u64,
) -> Result<Stamped<ControllerEvent>, String> {
    let current = take(schema, data, log_time_nanos);
    if current.is_ok() || schema != ControllerEvent::type_name() {
        return current;
    }
    let Ok(old) = cdr::decode::<ControllerEventWithoutLegId>(data) else {
        return current;
    };
    Ok(Stamped {
        log_time_nanos,
        logged_nanos: log_time_nanos,
        message: ControllerEvent {
            leg_id: legacy_leg_id(&old.leg),
            header: old.header,
            kind: old.kind,
            leg: old.leg,
            status: old.status,
            error_code: old.error_code,
            text: old.text,
            feedback_count: old.feedback_count,
            max_error: old.max_error,
            sample_stamp: old.sample_stamp,
        },
    })
}

/// A part taken, as the reason of a session state recorded before the states carried it as fields
/// said it: `part N taken: the operator's <hand> hand came to <d> m of …`.
pub(crate) fn legacy_part_from_reason(reason: &str) -> Option<(u32, Option<String>, Option<f64>)> {
    let (part, rest) = reason
        .strip_prefix("part ")
        .and_then(|r| r.split_once(' '))
        .and_then(|(n, rest)| Some((n.parse::<u32>().ok()?, rest)))?;
    if !rest.starts_with("taken") {
        return None;
    }
    let hand = rest
        .split_once("operator's ")
        .and_then(|(_, r)| r.split_whitespace().next())
        .filter(|h| matches!(*h, "left" | "right"))
        .map(str::to_owned);
    let distance_m = rest
        .split_once("came to ")
        .and_then(|(_, r)| r.split_once(" m"))
        .and_then(|(d, _)| d.trim().parse::<f64>().ok())
        .and_then(finite);
    Some((part, hand, distance_m))
}
