//! The execution monitor's own task: it alone reads `/joint_states`, judges every sample as it
//! arrives and, on the first deviation, cancels the goal and publishes the hold itself (the cell loop
//! may be busy verifying a lock or fusing a frame; the robot must not wait for it), then tells the
//! loop, which ends the session. Every 5 ms it checks for stale joint states.
//!
//! The judging is [`Judge`], synchronous and on an injected clock (tested without DDS);
//! [`monitor_task`] only feeds it from the subscription and a timer.

use std::sync::{Arc, Mutex};
use std::time::Duration;

use ergocell_bridge::controller::ControllerCommand;
use ergocell_bridge::msg::{ControllerEvent, ControllerEventKind, JointState};
use ergocell_cell::session::RobotCommand;
use futures::StreamExt as _;

use crate::clock::{instant, now_nanos, SessionClock};
use crate::messages;
use crate::robot::{controller_event, no_leg, SharedMonitor, TrajectoryTopic};

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

/// Judges joint states against the shared monitor and holds the robot on the first deviation.
pub struct Judge<T: TrajectoryTopic> {
    pub monitor: SharedMonitor,
    pub latest: Arc<Mutex<Option<JointState>>>,
    /// The controller's trajectory topic: a deviation publishes the empty trajectory (hold) at once.
    pub hold: Arc<T>,
    /// Action mode: a deviation cancels the goal at once.
    pub cancel: Option<tokio::sync::mpsc::UnboundedSender<ControllerCommand>>,
    pub stats: Arc<Mutex<MonitorStats>>,
    /// Joint states older than this are stale, seconds.
    pub timeout_s: f64,
    tripped: bool,
    stale: bool,
}

impl<T: TrajectoryTopic> Judge<T> {
    pub fn new(
        monitor: SharedMonitor,
        latest: Arc<Mutex<Option<JointState>>>,
        hold: Arc<T>,
        cancel: Option<tokio::sync::mpsc::UnboundedSender<ControllerCommand>>,
        timeout_s: f64,
    ) -> Self {
        Self {
            monitor,
            latest,
            hold,
            cancel,
            stats: Arc::new(Mutex::new(MonitorStats::default())),
            timeout_s,
            tripped: false,
            stale: false,
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
        let stale = self.stale;
        let judged = self.monitor.lock().ok().and_then(|mut g| {
            let m = g.as_mut()?;
            if stale {
                m.resync_rest();
            }
            let verdict = match js.positions_for(m.joints()) {
                Some(p) => m.observe(now, &p),
                None => Err(ergocell_robot::monitor::Deviation::BadSample {
                    reason: format!(
                        "a joint state without every joint of the lock ({})",
                        m.joints().join(", ")
                    ),
                }),
            };
            Some((verdict, m.worst_path_ratio().0))
        });
        if let Some((verdict, worst)) = judged {
            if let Ok(mut st) = self.stats.lock() {
                st.verdict_us.push(arrival.elapsed().as_secs_f64() * 1e6);
                st.transit_us.push(transit_us);
            }
            if self.stale {
                self.stale = false;
                notes.push(MonitorNote::Back(controller_event(
                    now,
                    ControllerEventKind::Monitor,
                    &no_leg(),
                    "joint states back".to_owned(),
                )));
            }
            if let (Err(d), false) = (verdict, self.tripped) {
                self.tripped = true;
                if let Some(tx) = &self.cancel {
                    // The controller task is gone only when the session is over.
                    let _ = tx.send(ControllerCommand::Cancel);
                }
                let hold = messages::command_message(
                    &RobotCommand::Hold {
                        reason: d.to_string(),
                    },
                    now,
                );
                if let Err(e) = self.hold.publish(hold) {
                    tracing::error!(error = %e, "the execution monitor's hold was not published");
                }
                let held_after_ms = arrival.elapsed().as_secs_f64() * 1e3;
                let mut event =
                    controller_event(now, ControllerEventKind::Monitor, &no_leg(), d.to_string());
                event.max_error = worst;
                event.sample_stamp = js.header.stamp;
                notes.push(MonitorNote::Deviation {
                    deviation: d,
                    event,
                    held_after_ms,
                });
            }
        }
        if let Ok(mut l) = self.latest.lock() {
            *l = Some(js.clone());
        }
        notes.push(MonitorNote::Sample(js, now));
        notes
    }

    /// The timer at session time `now`: a note when the joint states have just gone stale.
    pub fn tick(&mut self, now: i64) -> Option<MonitorNote> {
        let timeout_s = self.timeout_s;
        let age = self
            .monitor
            .lock()
            .ok()
            .and_then(|g| g.as_ref()?.stale_for_s(now, timeout_s))?;
        if self.stale {
            return None;
        }
        self.stale = true;
        let why = format!("joint states stale (none for more than {timeout_s} s)");
        tracing::warn!(age_s = age, "{why}");
        Some(MonitorNote::Stale {
            event: controller_event(now, ControllerEventKind::Monitor, &no_leg(), why),
            timeout_s,
        })
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
