//! The execution monitor's own task: it alone reads `/joint_states`, has every sample judged as it
//! arrives by the cell's [`ergocell_cell::session::ExecutionWatch`] (the rules the twin runs too)
//! and, on the first deviation, sends the hold at once through the robot's own port (the cancel and
//! the empty trajectory `RosRobot` sends for every hold: the cell loop may be busy verifying a lock
//! or fusing a frame, and the robot must not wait for it), then tells the loop, which ends the
//! session. Every 5 ms it checks for stale joint states.
//!
//! [`Judge`] is synchronous and on an injected clock (tested without DDS); [`monitor_task`] only
//! feeds it from the subscription and a timer.

use std::sync::{Arc, Mutex};
use std::time::Duration;

use ergocell_bridge::msg::{ControllerEvent, JointState};
use ergocell_cell::session::{HoldReason, RobotCommand, RobotReport};
use futures::StreamExt as _;

use crate::clock::{instant, now_nanos, SessionClock};
use crate::messages;
use crate::robot::{CommandPort, SharedMonitor, TrajectoryTopic};

/// What the monitor tells the cell loop.
#[derive(Debug)]
pub enum MonitorNote {
    /// A joint state as it arrived (session time), for the recording.
    Sample(JointState, i64),
    /// The execution deviated: the goal was cancelled and the robot held already.
    Deviation {
        deviation: ergocell_robot::monitor::Deviation,
        event: ControllerEvent,
        held_after_ms: f64,
    },
    /// No joint state for longer than `timeout_s`.
    Stale {
        event: ControllerEvent,
        timeout_s: f64,
    },
    /// Joint states again after a stale spell.
    Back(ControllerEvent),
}

/// The monitor's timing, every judged sample.
#[derive(Debug, Default)]
pub struct MonitorStats {
    /// Arrival → verdict, microseconds.
    pub verdict_us: Vec<f64>,
    /// The sample's stamp → its arrival here on the wall clock, microseconds: the controller's
    /// publish → ergocell's read, when the controller stamps on this host's clock (a peer on this
    /// machine; on a real cell it includes the two clocks' offset).
    pub transit_us: Vec<f64>,
}

/// Has joint states judged by the shared execution watch and holds the robot on the first
/// deviation.
pub struct Judge<T: TrajectoryTopic> {
    pub monitor: SharedMonitor,
    pub latest: Arc<Mutex<Option<JointState>>>,
    /// The controller's command port: a deviation holds the robot through it at once.
    pub port: CommandPort<T>,
    pub stats: Arc<Mutex<MonitorStats>>,
}

impl<T: TrajectoryTopic> Judge<T> {
    pub fn new(
        monitor: SharedMonitor,
        latest: Arc<Mutex<Option<JointState>>>,
        port: CommandPort<T>,
    ) -> Self {
        Self {
            monitor,
            latest,
            port,
            stats: Arc::new(Mutex::new(MonitorStats::default())),
        }
    }

    /// A joint state that arrived at session time `now` (`arrival`: the monotonic instant, for the
    /// hold's latency; `transit_us`: its stamp → arrival). The notes for the loop, in order.
    pub fn sample(
        &mut self,
        now: i64,
        js: JointState,
        arrival: std::time::Instant,
        transit_us: f64,
    ) -> Vec<MonitorNote> {
        let mut notes = Vec::new();
        let judged = self.monitor.lock().ok().and_then(|mut w| {
            let positions = js.positions_for(w.joints()?);
            let reports = w.sample(now, positions.as_deref());
            let worst = w.monitor().map_or(0.0, |m| m.worst_path_ratio().0);
            Some((reports, worst))
        });
        if let Some((reports, worst)) = judged {
            if let Ok(mut st) = self.stats.lock() {
                st.verdict_us.push(arrival.elapsed().as_secs_f64() * 1e6);
                st.transit_us.push(transit_us);
            }
            for report in reports {
                match report {
                    RobotReport::JointStatesBack => {
                        if let Some(event) = messages::robot_report_message(now, &report) {
                            notes.push(MonitorNote::Back(event));
                        }
                    }
                    RobotReport::Deviation(deviation) => {
                        notes.push(self.hold(now, &js, deviation, worst, arrival));
                    }
                    _ => {}
                }
            }
        }
        if let Ok(mut l) = self.latest.lock() {
            *l = Some(js.clone());
        }
        notes.push(MonitorNote::Sample(js, now));
        notes
    }

    /// The first deviation: the goal cancelled and the empty trajectory published at once, the
    /// note for the loop.
    fn hold(
        &self,
        now: i64,
        js: &JointState,
        deviation: ergocell_robot::monitor::Deviation,
        worst: f64,
        arrival: std::time::Instant,
    ) -> MonitorNote {
        let hold = messages::command_message(
            &RobotCommand::Hold {
                reason: HoldReason::deviation(deviation.clone()),
            },
            now,
        );
        if let Err(e) = self.port.hold(hold) {
            tracing::error!(error = %e, "the execution monitor's hold was not sent");
        }
        let held_after_ms = arrival.elapsed().as_secs_f64() * 1e3;
        let mut event =
            messages::robot_report_message(now, &RobotReport::Deviation(deviation.clone()))
                .unwrap_or_default();
        event.max_error = worst;
        event.sample_stamp = js.header.stamp;
        MonitorNote::Deviation {
            deviation,
            event,
            held_after_ms,
        }
    }

    /// The timer at session time `now`: a note when the joint states have just gone stale.
    pub fn tick(&mut self, now: i64) -> Option<MonitorNote> {
        let report = self.monitor.lock().ok()?.tick(now)?;
        let RobotReport::JointStatesStale { timeout_s } = report else {
            return None;
        };
        let event = messages::robot_report_message(now, &report)?;
        tracing::warn!("{}", event.text);
        Some(MonitorNote::Stale { event, timeout_s })
    }
}

/// Runs `judge` on every sample of `joint_states` and every 5 ms, sending its notes to the loop.
pub async fn monitor_task<T: TrajectoryTopic>(
    joint_states: ergocell_bridge::transport::Subscription<JointState>,
    mut judge: Judge<T>,
    notes: tokio::sync::mpsc::UnboundedSender<MonitorNote>,
    clock: SessionClock,
) {
    let mut stream = Box::pin(joint_states.async_stream());
    let mut tick = tokio::time::interval(Duration::from_millis(5));
    let note = |n: MonitorNote| {
        // The loop is gone when nobody listens: the session is over.
        let _ = notes.send(n);
    };
    loop {
        tokio::select! {
            item = stream.next() => {
                let Some(Ok((js, _))) = item else {
                    if item.is_none() {
                        return;
                    }
                    continue;
                };
                let js: JointState = js;
                let arrival = instant();
                let transit_us = (now_nanos() - js.header.stamp.to_nanos()) as f64 * 1e-3;
                for n in judge.sample(clock.now(), js, arrival, transit_us) {
                    note(n);
                }
            }
            _ = tick.tick() => {
                if let Some(n) = judge.tick(clock.now()) {
                    note(n);
                }
            }
        }
    }
}
