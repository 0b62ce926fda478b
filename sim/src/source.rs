//! The simulator as the cell's landmark source: the twin's camera views, each arriving at its
//! tick's time, through the same [`LandmarkSource`] trait the ROS 2 camera subscriptions implement.
//! Faults (silent cameras) are the caller's to apply from a [`crate::faults::FaultPlayer`].

use ergocell_cell::session::{BackendError, LandmarkSource};
use ergocell_perception::View2;

use crate::{Simulation, Tick};

/// Views from a running simulation; a view arrives at its tick's time.
#[derive(Debug)]
pub struct SimSource {
    sim: Simulation,
    pending: Option<Tick>,
    /// The ground truth of the last tick delivered.
    pub last_tick: Option<Tick>,
}

impl SimSource {
    pub fn new(sim: Simulation) -> Self {
        Self {
            sim,
            pending: None,
            last_tick: None,
        }
    }

    /// The simulation, to move the operator's handover point once the cell has decided a class.
    pub fn simulation_mut(&mut self) -> &mut Simulation {
        &mut self.sim
    }
}

impl LandmarkSource for SimSource {
    fn poll(&mut self, now_nanos: i64) -> Result<Option<Vec<View2>>, BackendError> {
        let mut out = Vec::new();
        loop {
            let tick = match self.pending.take() {
                Some(t) => t,
                None => match self.sim.step() {
                    Ok(Some(t)) => t,
                    Ok(None) => {
                        return Ok(if out.is_empty() && self.last_tick.is_some() {
                            None
                        } else {
                            Some(out)
                        })
                    }
                    Err(e) => {
                        return Err(BackendError::Simulator {
                            cause: std::sync::Arc::new(e),
                        })
                    }
                },
            };
            if tick.frame.stamp_nanos > now_nanos {
                self.pending = Some(tick);
                return Ok(Some(out));
            }
            out.extend(tick.frame.views.iter().cloned());
            self.last_tick = Some(tick);
        }
    }
}
