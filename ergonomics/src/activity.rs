//! What the operator is doing, from the skeleton alone: walking, picking something off the floor, or
//! working in place — the task segments an ergonomist reads exposure by.
//!
//! A cell knows more than the skeleton (the robot's legs tell a handover; the offline review adds
//! that, see `ergocell_review`), but these two need only the body, so `ergocell rula track` of a bare
//! landmark file has them too:
//! - **Walking**: the hip midpoint's horizontal speed over the last [`ActivityConfig::window_nanos`]
//!   (0.5 s) is at least [`ActivityConfig::walking_speed_m_s`] (0.4 m/s). People walk at 1.0–1.5 m/s;
//!   an operator at a station sways and shifts a few centimetres a second. Horizontal is across the
//!   cell's up vector, never an assumed z.
//! - **Floor pick**: a wrist is below the knees (its height along up under the mean height of the
//!   observed knees). A hanging arm's wrist is at mid-thigh; to reach a knee's height the operator
//!   stoops or squats, which is what picking from the floor is.
//! - **In place**: neither.
//!
//! Walking wins over a floor pick (a hand swinging low while walking is not a pick). A frame without
//! hips is not classified (`None`), and a speed needs at least [`ActivityConfig::min_span_nanos`] of
//! history: until then walking is not decided, and the frame is a floor pick or in place.

use std::collections::VecDeque;

use ergocell_skeleton::{Landmark, Skeleton3};
use nalgebra::Vector3;
use serde::Serialize;

use crate::angles::UpVector;
use crate::ErgonomicsError;

/// The activity of one frame.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Activity {
    Walking,
    FloorPick,
    InPlace,
}

impl Activity {
    pub const ALL: [Self; 3] = [Self::Walking, Self::FloorPick, Self::InPlace];

    /// The name in reports: `walking`, `floor pick`, `in place`.
    pub const fn name(self) -> &'static str {
        match self {
            Self::Walking => "walking",
            Self::FloorPick => "floor pick",
            Self::InPlace => "in place",
        }
    }
}

/// Thresholds of [`ActivityTracker`].
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct ActivityConfig {
    /// Walking at or above this horizontal hip speed, m/s (default 0.4).
    pub walking_speed_m_s: f64,
    /// The speed is measured over this trailing window (default 0.5 s).
    pub window_nanos: i64,
    /// The shortest history a speed is measured over (default 0.2 s).
    pub min_span_nanos: i64,
}

impl Default for ActivityConfig {
    fn default() -> Self {
        Self {
            walking_speed_m_s: 0.4,
            window_nanos: 500_000_000,
            min_span_nanos: 200_000_000,
        }
    }
}

/// Classifies frames in time order (see the module docs).
#[derive(Debug, Clone)]
pub struct ActivityTracker {
    config: ActivityConfig,
    up: Vector3<f64>,
    /// `(stamp, hip midpoint with its up component removed)` within the window.
    hips: VecDeque<(i64, Vector3<f64>)>,
}

fn mid(s: &Skeleton3, a: Landmark, b: Landmark) -> Option<Vector3<f64>> {
    Some((s.position(a)?.coords + s.position(b)?.coords) * 0.5)
}

impl ActivityTracker {
    /// # Errors
    /// [`ErgonomicsError::OutOfRange`] for a speed that is not positive and finite or windows that
    /// are not positive (the span at most the window).
    pub fn new(config: ActivityConfig, up: &UpVector) -> Result<Self, ErgonomicsError> {
        if !(config.walking_speed_m_s.is_finite() && config.walking_speed_m_s > 0.0) {
            return Err(ErgonomicsError::OutOfRange {
                field: "walking_speed_m_s",
                value: config.walking_speed_m_s,
                min: 0.0,
                max: f64::INFINITY,
            });
        }
        if config.min_span_nanos <= 0 || config.window_nanos < config.min_span_nanos {
            return Err(ErgonomicsError::OutOfRange {
                field: "window_nanos",
                value: config.window_nanos as f64,
                min: config.min_span_nanos.max(1) as f64,
                max: f64::INFINITY,
            });
        }
        Ok(Self {
            config,
            up: up.vector(),
            hips: VecDeque::new(),
        })
    }

    /// The activity of `s` (frames in time order; a frame older than the last is not classified).
    pub fn update(&mut self, s: &Skeleton3) -> Option<Activity> {
        let t = s.stamp_nanos;
        if self.hips.back().is_some_and(|&(last, _)| t < last) {
            return None;
        }
        let hips = mid(s, Landmark::LeftHip, Landmark::RightHip)?;
        let horizontal = hips - self.up * hips.dot(&self.up);
        self.hips.push_back((t, horizontal));
        while self
            .hips
            .front()
            .is_some_and(|&(t0, _)| t.saturating_sub(t0) > self.config.window_nanos)
        {
            self.hips.pop_front();
        }
        let walking = self.hips.front().is_some_and(|&(t0, p0)| {
            let span = t.saturating_sub(t0);
            span >= self.config.min_span_nanos
                && (horizontal - p0).norm() / (span as f64 * 1e-9) >= self.config.walking_speed_m_s
        });
        if walking {
            return Some(Activity::Walking);
        }
        let height = |lm: Landmark| s.position(lm).map(|p| p.coords.dot(&self.up));
        let knees: Vec<f64> = [Landmark::LeftKnee, Landmark::RightKnee]
            .into_iter()
            .filter_map(height)
            .collect();
        let wrist = [Landmark::LeftWrist, Landmark::RightWrist]
            .into_iter()
            .filter_map(height)
            .reduce(f64::min);
        let floor_pick = match (wrist, knees.is_empty()) {
            (Some(w), false) => w < knees.iter().sum::<f64>() / knees.len() as f64,
            _ => false,
        };
        Some(if floor_pick {
            Activity::FloorPick
        } else {
            Activity::InPlace
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::pose::PoseSpec;
    use nalgebra::Rotation3;

    const MS: i64 = 1_000_000;

    fn tracker(spec: &PoseSpec) -> ActivityTracker {
        ActivityTracker::new(
            ActivityConfig::default(),
            &UpVector::new(spec.up()).unwrap(),
        )
        .unwrap()
    }

    /// The operator moved `speed` m/s along a horizontal direction of its (tilted) world.
    fn moved(spec: &PoseSpec, t_ms: i64, speed: f64) -> Skeleton3 {
        let across = spec.world_rotation * Vector3::x();
        PoseSpec {
            stamp_nanos: t_ms * MS,
            world_translation: spec.world_translation + across * speed * t_ms as f64 * 1e-3,
            ..spec.clone()
        }
        .skeleton()
    }

    fn tilted() -> PoseSpec {
        PoseSpec {
            world_rotation: Rotation3::from_euler_angles(0.4, -0.2, 1.1),
            ..PoseSpec::default()
        }
    }

    #[test]
    fn walking_is_a_horizontal_speed_in_any_world_frame() {
        for (speed, want) in [
            (1.2, Activity::Walking),
            (0.45, Activity::Walking),
            (0.3, Activity::InPlace),
            (0.0, Activity::InPlace),
        ] {
            let spec = tilted();
            let mut a = tracker(&spec);
            let got: Vec<_> = (0..20)
                .map(|k| a.update(&moved(&spec, k * 50, speed)))
                .collect();
            // Not decided before 0.2 s of history: in place until then.
            assert_eq!(got[0], Some(Activity::InPlace));
            assert!(
                got[4..].iter().all(|g| *g == Some(want)),
                "{speed} m/s: {got:?}"
            );
        }
    }

    #[test]
    fn rising_and_sinking_is_not_walking() {
        // 1 m/s straight up along the world's up: no horizontal speed.
        let spec = tilted();
        let up = spec.up();
        let mut a = tracker(&spec);
        for k in 0..20 {
            let s = PoseSpec {
                stamp_nanos: k * 50 * MS,
                world_translation: spec.world_translation + up * (k as f64 * 0.05),
                ..spec.clone()
            }
            .skeleton();
            assert_eq!(a.update(&s), Some(Activity::InPlace));
        }
    }

    #[test]
    fn a_deep_stoop_with_a_hand_below_the_knees_is_a_floor_pick() {
        let reach_down = |trunk_deg: f64| PoseSpec {
            trunk_flexion_rad: trunk_deg.to_radians(),
            right_arm: crate::pose::ArmPose {
                flexion_rad: trunk_deg.to_radians(),
                ..crate::pose::ArmPose::default()
            },
            ..tilted()
        };
        let mut a = tracker(&tilted());
        assert_eq!(
            a.update(&reach_down(0.0).skeleton()),
            Some(Activity::InPlace)
        );
        let mut a = tracker(&tilted());
        assert_eq!(
            a.update(&reach_down(30.0).skeleton()),
            Some(Activity::InPlace)
        );
        let mut a = tracker(&tilted());
        assert_eq!(
            a.update(&reach_down(90.0).skeleton()),
            Some(Activity::FloorPick)
        );
    }

    #[test]
    fn no_hips_no_activity_and_bad_configs_are_refused() {
        let spec = PoseSpec::default();
        let mut s = spec.skeleton();
        s.set(Landmark::LeftHip, None).unwrap();
        assert_eq!(tracker(&spec).update(&s), None);
        let up = UpVector::z();
        for bad in [
            ActivityConfig {
                walking_speed_m_s: f64::NAN,
                ..ActivityConfig::default()
            },
            ActivityConfig {
                window_nanos: 100 * MS,
                ..ActivityConfig::default()
            },
        ] {
            assert!(ActivityTracker::new(bad, &up).is_err());
        }
    }
}
