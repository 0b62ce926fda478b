//! The demo's simulated session as data (`ergocell demo`): the operator's script at the cell's pace,
//! the frame period, a camera knocked out of calibration. The binary checks its flags and prints;
//! the timing and the angles are set here.

use nalgebra::{Isometry3, Point3};

use crate::{CameraBump, FloorPick, SessionScript};

/// How long the simulated operator works on a part between handovers: the robot's way home and back
/// (twice the locked leg of `leg_s`), its wait for the next part (`next_part_after_nanos`), and 3 s
/// of slack, so that the robot stands at the handover point before the operator reaches for the
/// next part (and the demo's camera blackout, 0.3 s after it arrives, is over).
pub fn operator_rest_secs(leg_s: f64, next_part_after_nanos: i64) -> f64 {
    2.0 * leg_s + next_part_after_nanos as f64 * 1e-9 + 3.0
}

/// What the demo's operator does: `cycles` handovers at `handover_m` (world), at the cell's pace
/// (its leg of `leg_s`, the next part after `next_part_after_nanos`), a floor pick after the first
/// handover unless `no_floor_pick`, standing at the cell's station `T_world_station`.
#[allow(non_snake_case)]
pub fn demo_script(
    handover_m: Point3<f64>,
    cycles: usize,
    leg_s: f64,
    next_part_after_nanos: i64,
    no_floor_pick: bool,
    T_world_station: &Isometry3<f64>,
) -> SessionScript {
    let mut script = SessionScript::new(handover_m);
    script.cycles = cycles;
    // The class is decided after 30 upright frames at the station (1 s at 30 Hz) and the first leg
    // takes 5 s: the operator stands a second longer before reaching, so the part is there, and at
    // rest, before their hand is.
    script.idle_secs += 1.0;
    // The cell's cycle sets the operator's: after taking a part the operator works on it at the
    // station (the script's rest) while the robot goes home, takes the next part and brings it.
    script.rest_secs = operator_rest_secs(leg_s, next_part_after_nanos);
    if !no_floor_pick {
        script.floor_pick = Some(FloorPick::new(cycles.min(1)));
    }
    // The operator stands at the cell's station (`[station]`), not at the world's origin.
    script.place_at_station(T_world_station);
    script
}

/// Simulated time after the script's end for the robot's way home and the exit detection; a session
/// still running then is stopped (robot held), and the demo says so.
pub const MARGIN_SECS: f64 = 30.0;

/// The demo session's time limit: the script, the tasks drawn between its handovers, then
/// [`MARGIN_SECS`] for the robot's way home.
pub fn time_limit_secs(script: &SessionScript, tasks: &[crate::tasks::TaskOccurrence]) -> f64 {
    script.duration_secs() + crate::tasks::total_secs(tasks) + MARGIN_SECS
}

/// The frame period of `fps` frames a second, nanoseconds; at least 1 (a rate that is not a
/// positive finite number gives the 1 ns floor, never a clock that does not advance).
pub fn frame_period_nanos(fps: f64) -> i64 {
    ((1e9 / fps).round() as i64).max(1)
}

/// The largest bump the demo plays, degrees.
pub const MAX_BUMP_DEG: f64 = 45.0;
/// The latest bump, seconds into the session (a day).
pub const MAX_BUMP_AT_S: f64 = 86_400.0;

/// A camera bump the demo does not play.
#[derive(Debug, Clone, Copy, PartialEq, thiserror::Error)]
pub enum BadBump {
    /// The angle is not finite, or beyond ±[`MAX_BUMP_DEG`].
    #[error("expected a finite angle within ±45°")]
    Angle { deg: f64 },
    /// The time is outside 0..=[`MAX_BUMP_AT_S`].
    #[error("expected 0..=86400 s")]
    Time { at_s: f64 },
}

/// `camera` turned by `deg` degrees about its y axis, `at_s` seconds after `start_nanos`: a camera
/// knocked out of calibration.
pub fn camera_bump(
    camera: usize,
    start_nanos: i64,
    at_s: f64,
    deg: f64,
) -> Result<CameraBump, BadBump> {
    if !(deg.is_finite() && deg.abs() <= MAX_BUMP_DEG) {
        return Err(BadBump::Angle { deg });
    }
    if !(at_s.is_finite() && (0.0..=MAX_BUMP_AT_S).contains(&at_s)) {
        return Err(BadBump::Time { at_s });
    }
    Ok(CameraBump {
        camera,
        from_nanos: start_nanos.saturating_add((at_s * 1e9) as i64),
        rotation_rad: [0.0, deg.to_radians(), 0.0],
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_operator_rests_while_the_robot_goes_home_and_back() {
        // a 5 s leg, the next part after 2 s: 10 + 2 + 3 s
        assert_eq!(operator_rest_secs(5.0, 2_000_000_000), 15.0);
        let script = demo_script(
            Point3::new(0.4, -0.1, 1.1),
            3,
            5.0,
            2_000_000_000,
            false,
            &Isometry3::identity(),
        );
        assert_eq!(script.cycles, 3);
        assert_eq!(script.rest_secs, 15.0);
        assert_eq!(script.floor_pick.map(|p| p.after_cycle), Some(1));
        let none = demo_script(
            Point3::new(0.4, -0.1, 1.1),
            0,
            5.0,
            0,
            true,
            &Isometry3::identity(),
        );
        assert!(none.floor_pick.is_none());
    }

    #[test]
    fn a_bump_is_turned_to_radians_and_bounded() {
        let b = camera_bump(2, 1_000, 1.5, 10.0).unwrap();
        assert_eq!(b.camera, 2);
        assert_eq!(b.from_nanos, 1_000 + 1_500_000_000);
        assert!((b.rotation_rad[1] - 10f64.to_radians()).abs() < 1e-15);
        assert_eq!(
            camera_bump(0, 0, 1.0, 45.5).unwrap_err(),
            BadBump::Angle { deg: 45.5 }
        );
        assert!(matches!(
            camera_bump(0, 0, 1.0, f64::NAN),
            Err(BadBump::Angle { .. })
        ));
        assert_eq!(
            camera_bump(0, 0, -1.0, 1.0).unwrap_err(),
            BadBump::Time { at_s: -1.0 }
        );
        assert_eq!(
            camera_bump(0, 0, 86_401.0, 1.0).unwrap_err(),
            BadBump::Time { at_s: 86_401.0 }
        );
        // a start near the end of time saturates, never wraps
        assert_eq!(
            camera_bump(0, i64::MAX - 1, 1.0, 1.0).unwrap().from_nanos,
            i64::MAX
        );
        assert_eq!(frame_period_nanos(30.0), 33_333_333);
    }
}
