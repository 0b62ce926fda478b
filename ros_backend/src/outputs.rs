//! The cell's ROS 2 outputs and its recording, as one [`CellOutputs`]: for every step, the robot
//! side's controller events first (published and recorded, in order), then the step's messages
//! ([`messages::step_messages`]), published and recorded alike.

use ergocell_bridge::msg::ControllerEvent;
pub use ergocell_bridge::transport::CellPublishers as Publishers;
use ergocell_bridge::transport::Publisher;
use ergocell_cell::session::{CellOutputs, OutputError, SessionEvent, SessionMachine};

use crate::messages::{self, Outgoing};
use crate::recording::{self, topics, Recording};
use crate::robot::EventQueue;

fn published<M: serde::Serialize + std::fmt::Debug + Send + Sync + 'static>(
    p: &Publisher<M>,
    message: M,
) -> Result<(), OutputError> {
    p.publish(message).map_err(|e| OutputError {
        output: "ROS 2 publisher",
        cause: std::sync::Arc::new(e),
    })
}

/// The ROS 2 outputs and the recording.
pub struct RosOutputs {
    pub publishers: Publishers,
    pub recording: Recording,
    /// The robot side's events to publish and record.
    pub events: EventQueue,
    /// The last step published a RULA state (for the latency figure).
    pub published_frame: bool,
}

impl RosOutputs {
    /// Publishes and records the robot side's events, in order.
    pub fn flush_events(&mut self, now: i64) -> Result<(), OutputError> {
        let events: Vec<ControllerEvent> = self
            .events
            .lock()
            .map(|mut q| q.drain(..).collect())
            .unwrap_or_default();
        for e in events {
            self.recording
                .with(|rec| rec.write(topics::CONTROLLER_EVENTS, now, &e));
            published(&self.publishers.controller_events, e)?;
        }
        Ok(())
    }

    fn publish(&mut self, outgoing: &[Outgoing]) -> Result<(), OutputError> {
        let p = &self.publishers;
        self.published_frame = false;
        for m in outgoing {
            match m {
                Outgoing::SessionState(m) => {
                    published(&p.session_state, m.clone())?;
                    published(&p.session_events, m.clone())?;
                }
                Outgoing::Ergonomics(m) => {
                    published(&p.ergonomics, m.clone())?;
                    self.published_frame = true;
                }
                Outgoing::Reba(m) => published(&p.reba, m.clone())?,
                Outgoing::Warning(m) => published(&p.warnings, m.clone())?,
                Outgoing::Skeleton(m) => published(&p.skeleton, m.clone())?,
                // the operator pose is recorded only; the robot command is the robot sink's
                Outgoing::OperatorPose(_) | Outgoing::Trajectory(_) => {}
            }
        }
        Ok(())
    }
}

impl CellOutputs for RosOutputs {
    fn session_step(
        &mut self,
        now: i64,
        machine: &SessionMachine,
        events: &[SessionEvent],
    ) -> Result<(), OutputError> {
        self.flush_events(now)?;
        let outgoing = messages::step_messages(machine, now, events);
        self.publish(&outgoing)?;
        self.recording
            .with(|rec| recording::record(rec, now, &outgoing));
        self.recording.new_failure().map_or(Ok(()), Err)
    }

    fn take_failure(&mut self) -> Option<OutputError> {
        self.recording.new_failure()
    }
}
