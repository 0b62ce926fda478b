//! Test and simulator backends: a robot that follows trajectories by linear interpolation between knots
//! and stops where it is on a hold, and a scripted landmark source.

use ergocell_perception::View2;

use super::{BackendError, LandmarkSource, LegTrajectory, RobotCommand, RobotSink};

/// A simulated robot controller: follows the last trajectory from the time it was received, stops
/// where it is on a hold, and records every command.
#[derive(Debug, Clone)]
pub struct DummyRobot {
    joint_names: Vec<String>,
    held_positions: Vec<f64>,
    active: Option<(i64, LegTrajectory)>,
    /// The commands received, with their times: every one, or the newest `history` of them.
    pub received: Vec<(i64, RobotCommand)>,
    history: Option<usize>,
}

impl DummyRobot {
    /// A robot at rest at `positions_rad` (in the order of `joint_names`).
    pub fn new(joint_names: Vec<String>, positions_rad: Vec<f64>) -> Self {
        Self {
            joint_names,
            held_positions: positions_rad,
            active: None,
            received: Vec::new(),
            history: None,
        }
    }

    /// Keeps only the newest `n` commands in [`DummyRobot::received`] (at least one): a long
    /// simulated shift sends thousands of legs, each a whole trajectory.
    #[must_use]
    pub fn keeping_last(mut self, n: usize) -> Self {
        self.history = Some(n.max(1));
        self
    }

    /// Joint positions at `now_nanos`, in this robot's joint order.
    pub fn positions_at(&self, now_nanos: i64) -> Vec<f64> {
        let Some((start, traj)) = &self.active else {
            return self.held_positions.clone();
        };
        let t = (now_nanos - start) as f64 * 1e-9;
        let points = &traj.points;
        let Some(last) = points.last() else {
            return self.held_positions.clone();
        };
        let order: Vec<Option<usize>> = self
            .joint_names
            .iter()
            .map(|n| traj.joint_names.iter().position(|m| m == n))
            .collect();
        let pick = |values: &[f64]| -> Vec<f64> {
            order
                .iter()
                .zip(&self.held_positions)
                .map(|(i, held)| i.and_then(|i| values.get(i).copied()).unwrap_or(*held))
                .collect()
        };
        if t >= last.time_from_start_s {
            return pick(&last.positions_rad);
        }
        let k = points
            .iter()
            .position(|p| p.time_from_start_s > t)
            .unwrap_or(points.len() - 1);
        if k == 0 {
            return pick(&points[0].positions_rad);
        }
        let (a, b) = (&points[k - 1], &points[k]);
        let (ta, tb) = (a.time_from_start_s, b.time_from_start_s);
        let s = if tb > ta { (t - ta) / (tb - ta) } else { 1.0 };
        let mixed: Vec<f64> = a
            .positions_rad
            .iter()
            .zip(&b.positions_rad)
            .map(|(x, y)| x + s * (y - x))
            .collect();
        pick(&mixed)
    }
}

impl RobotSink for DummyRobot {
    fn send(&mut self, now_nanos: i64, command: &RobotCommand) -> Result<(), BackendError> {
        self.held_positions = self.positions_at(now_nanos);
        match command {
            RobotCommand::Execute { trajectory, .. } => {
                self.active = Some((now_nanos, trajectory.clone()));
            }
            RobotCommand::Hold { .. } => self.active = None,
        }
        self.received.push((now_nanos, command.clone()));
        if let Some(n) = self.history {
            let excess = self.received.len().saturating_sub(n);
            self.received.drain(..excess);
        }
        Ok(())
    }

    fn joint_positions(&mut self, now_nanos: i64, names: &[String]) -> Option<Vec<f64>> {
        let here = self.positions_at(now_nanos);
        names
            .iter()
            .map(|n| {
                self.joint_names
                    .iter()
                    .position(|m| m == n)
                    .and_then(|i| here.get(i).copied())
            })
            .collect()
    }
}

/// A source that plays back views by arrival time.
#[derive(Debug, Clone, Default)]
pub struct ScriptedSource {
    /// `(arrival_nanos, view)`, in arrival order.
    pub views: std::collections::VecDeque<(i64, View2)>,
}

impl LandmarkSource for ScriptedSource {
    fn poll(&mut self, now_nanos: i64) -> Result<Option<Vec<View2>>, BackendError> {
        if self.views.is_empty() {
            return Ok(None);
        }
        let mut out = Vec::new();
        while self.views.front().is_some_and(|(t, _)| *t <= now_nanos) {
            if let Some((_, v)) = self.views.pop_front() {
                out.push(v);
            }
        }
        Ok(Some(out))
    }
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)]
    use super::*;

    #[test]
    fn keeping_last_bounds_the_history_and_keeps_the_newest() {
        let hold = |k: i64| RobotCommand::Hold {
            reason: crate::session::HoldReason::NoStereoPair {
                cameras_fresh: usize::try_from(k).unwrap(),
            },
        };
        let mut all = DummyRobot::new(vec!["j".into()], vec![0.0]);
        let mut last2 = DummyRobot::new(vec!["j".into()], vec![0.0]).keeping_last(2);
        for k in 0..5 {
            all.send(k, &hold(k)).unwrap();
            last2.send(k, &hold(k)).unwrap();
        }
        assert_eq!(all.received.len(), 5);
        let debug = |r: &[(i64, RobotCommand)]| format!("{r:?}");
        assert_eq!(debug(&last2.received), debug(&all.received[3..]));
    }
}
