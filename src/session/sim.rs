//! The simulator backend: camera views from `ergocell_sim`, with scheduled camera faults.

use ergocell_perception::{CameraIndex, View2};
use ergocell_sim::{Simulation, Tick};

use super::{BackendError, LandmarkSource};

/// A camera fault: `cameras` send nothing from `from_nanos` (inclusive) to `to_nanos` (exclusive).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct CameraOutage {
    pub cameras: Vec<CameraIndex>,
    pub from_nanos: i64,
    pub to_nanos: i64,
}

/// Views from a running simulation; a view arrives at its tick's time.
#[derive(Debug)]
pub struct SimSource {
    sim: Simulation,
    pending: Option<Tick>,
    outages: Vec<CameraOutage>,
    /// The ground truth of the last tick delivered.
    pub last_tick: Option<Tick>,
}

impl SimSource {
    pub fn new(sim: Simulation, outages: Vec<CameraOutage>) -> Self {
        Self {
            sim,
            pending: None,
            outages,
            last_tick: None,
        }
    }

    /// The simulation, to move the operator's handover point once the cell has decided a class.
    pub fn simulation_mut(&mut self) -> &mut Simulation {
        &mut self.sim
    }

    fn silenced(&self, camera: CameraIndex, t: i64) -> bool {
        self.outages
            .iter()
            .any(|o| o.cameras.contains(&camera) && (o.from_nanos..o.to_nanos).contains(&t))
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
                        return Err(BackendError {
                            backend: "simulator",
                            reason: e.to_string(),
                        })
                    }
                },
            };
            if tick.frame.stamp_nanos > now_nanos {
                self.pending = Some(tick);
                return Ok(Some(out));
            }
            let t = tick.frame.stamp_nanos;
            out.extend(
                tick.frame
                    .views
                    .iter()
                    .filter(|v| !self.silenced(v.camera, t))
                    .cloned(),
            );
            self.last_tick = Some(tick);
        }
    }
}
