//! The session script and the simulation clock.
//!
//! A session is what the cell controller sees from one operator: walk into the cell → stand idle at
//! the station (the height measurement happens here) → `cycles` handovers, each reach → hold → return
//! → rest, reaching to a handover point given in world coordinates → turn and walk out. The body's
//! posture is a pure function of time ([`Simulation::truth_at`]); the reaching posture of each cycle is
//! solved once at construction ([`crate::reach::solve_reach`]) for that cycle's target (the handover
//! point plus a small seeded variation of where the hand meets the part).
//!
//! Optionally ([`SessionScript::floor_pick`], default none) the operator bends down for a dropped part
//! after a given number of cycles: reach → hold → return to a low target, its posture solved by
//! the same reach optimisation (the arm alone cannot get that low, so the trunk bends far forward), the
//! bad-posture episode RULA warnings are for. The robot is not involved.
//!
//! The simulator has its own clock: tick `k` is at `k · frame_period_nanos` (10 Hz by default, as in
//! the seed paper). It never reads wall time.

use ergocell_perception::{CameraIndex, CameraRig, Frame2};
use ergocell_skeleton::{Landmark, Skeleton3};
use nalgebra::{Isometry3, Point3, Vector3};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use serde::Serialize;

use crate::body::{LegPosture, Operator, Posture};
use crate::detector::{gaussian, jitter_nanos, render_view, DetectorNoise, PersistentOffsets};
use crate::reach::{solve_reach, ReachConfig};
use crate::tasks::{TaskKind, TaskOccurrence};
use crate::SimError;

/// What the operator is doing.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(tag = "phase", rename_all = "snake_case")]
pub enum Phase {
    WalkIn,
    /// Standing upright at the station (height measurement).
    Idle,
    /// Moving the hand to the handover point of cycle `cycle` (0-based).
    Reach {
        cycle: usize,
    },
    /// Holding the hand at the handover point.
    Hold {
        cycle: usize,
    },
    /// Bringing the part back.
    Return {
        cycle: usize,
    },
    /// Standing between cycles.
    Rest {
        cycle: usize,
    },
    /// Picking a dropped part off the floor ([`SessionScript::floor_pick`]).
    FloorPick {
        stage: PickStage,
    },
    /// One of the station's other tasks ([`crate::tasks`]): occurrence `index` of the session.
    Task {
        index: usize,
        kind: TaskKind,
        stage: TaskStage,
    },
    WalkOut,
    /// After the script: nobody in the cell.
    Gone,
}

/// The stages of a [`Phase::FloorPick`].
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum PickStage {
    /// Bending down to the part.
    Reach,
    /// Holding the bent posture (gripping the part).
    Hold,
    /// Standing back up.
    Return,
}

/// The stages of a [`Phase::Task`].
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum TaskStage {
    /// Moving into the task's posture.
    Reach,
    /// Holding it.
    Hold,
    /// Moving back to the resting posture.
    Return,
    /// Standing before what comes next.
    Rest,
}

/// What a stretch of the session's timeline is, once tasks are in it.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Segment {
    Handover(usize),
    FloorPick,
    Task(usize),
}

/// A floor pick: after `after_cycle` handover cycles the operator bends down to pick up a dropped
/// part (reach → hold → return to the resting posture), then the next cycle (or the walk out) follows.
/// The posture is solved by [`crate::reach::solve_reach`] for `target_m`. Durations in seconds.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct FloorPick {
    /// Number of handover cycles done before the pick (0 = right after the idle phase; at most
    /// [`SessionScript::cycles`]: after the last cycle, before the walk out).
    pub after_cycle: usize,
    /// Where the hand grasps the part, same frame as [`SessionScript::handover_m`] (default
    /// (0.45, −0.20, 0.40): in front of the working hand's foot, 40 cm above the floor, where it lies
    /// on the parts tray). The simulated legs stay straight while reaching (a stoop, no squat), so
    /// much lower targets are out of reach: a 1.75 m operator misses one at 0.25 m by 6 cm with the
    /// trunk at its 90° limit; this one is reached by statures 1.55–1.95 m with the trunk at 73–85°.
    pub target_m: Point3<f64>,
    /// Default 1.5 s.
    pub reach_secs: f64,
    /// Default 4.0 s: twice the warnings' default dwell time (2 s,
    /// `ergocell_ergonomics::warnings::WarningConfig`), so a posture warning is raised.
    pub hold_secs: f64,
    /// Default 1.5 s.
    pub return_secs: f64,
}

impl FloorPick {
    /// The default pick after `after_cycle` handover cycles.
    pub fn new(after_cycle: usize) -> Self {
        Self {
            after_cycle,
            target_m: Point3::new(0.45, -0.20, 0.40),
            reach_secs: 1.5,
            hold_secs: 4.0,
            return_secs: 1.5,
        }
    }

    /// Total duration, seconds.
    pub fn duration_secs(&self) -> f64 {
        self.reach_secs + self.hold_secs + self.return_secs
    }
}

/// The session script. Durations in seconds.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct SessionScript {
    /// Handover point (where the grasp point meets the part), world frame, metres.
    pub handover_m: Point3<f64>,
    /// Where the operator stands (floor point below the hips), world x, y (default the origin).
    pub station_m: [f64; 2],
    /// Facing direction at the station (default 0: facing +x, the robot).
    pub station_heading_rad: f64,
    /// Where the walk starts and ends (default (−2.5, 0.3)).
    pub entry_m: [f64; 2],
    /// Default 4 s.
    pub walk_in_secs: f64,
    /// Default 4 s (40 frames at 10 Hz: the height estimator needs 15 upright ones).
    pub idle_secs: f64,
    /// Number of handover cycles (default 5).
    pub cycles: usize,
    /// Default 1.2 s.
    pub reach_secs: f64,
    /// Default 1.0 s.
    pub hold_secs: f64,
    /// Default 1.2 s.
    pub return_secs: f64,
    /// Default 1.6 s.
    pub rest_secs: f64,
    /// Default 4 s.
    pub walk_out_secs: f64,
    /// σ of the per-cycle variation of the hand's target around the handover point, metres
    /// (default 0.01).
    pub target_sigma_m: f64,
    /// Walking: step frequency, Hz (default 1.8).
    pub step_hz: f64,
    /// Habitual posture, drawn once per session (see [`Habits`]).
    pub habits: Habits,
    /// An optional floor pick (default none: the session is the handover cycles only).
    pub floor_pick: Option<FloorPick>,
}

/// A person's habitual posture, `(mean, σ)` in radians, drawn once per session from the motion
/// stream and clipped to mean ± 2σ. Nobody stands at exactly 0.000°; RULA's bands have edges at
/// exactly 0° (neck extension scores 4, any trunk flexion 2, any wrist flexion 2), so a simulated
/// person frozen at the edge would make every measurement look wrong.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Habits {
    /// Head flexion while standing straight for the height measurement (default 3° ± 1.5°).
    pub idle_neck_flexion_rad: (f64, f64),
    /// Head flexion while resting between handovers (default 8° ± 3°: looking at the workstation).
    pub rest_neck_flexion_rad: (f64, f64),
    /// Forward lean of the trunk while standing (default 2° ± 1°).
    pub trunk_flexion_rad: (f64, f64),
    /// Flexion of the relaxed, hanging wrists (default 6° ± 3°).
    pub wrist_flexion_rad: (f64, f64),
}

impl Default for Habits {
    fn default() -> Self {
        let d = f64::to_radians;
        Self {
            idle_neck_flexion_rad: (d(3.0), d(1.5)),
            rest_neck_flexion_rad: (d(8.0), d(3.0)),
            trunk_flexion_rad: (d(2.0), d(1.0)),
            wrist_flexion_rad: (d(6.0), d(3.0)),
        }
    }
}

fn draw(rng: &mut ChaCha8Rng, (mean, sigma): (f64, f64)) -> f64 {
    mean + sigma * gaussian(rng).clamp(-2.0, 2.0)
}

impl SessionScript {
    /// The default script around a handover point.
    pub fn new(handover_m: Point3<f64>) -> Self {
        Self {
            handover_m,
            station_m: [0.0, 0.0],
            station_heading_rad: 0.0,
            entry_m: [-2.5, 0.3],
            walk_in_secs: 4.0,
            idle_secs: 4.0,
            cycles: 5,
            reach_secs: 1.2,
            hold_secs: 1.0,
            return_secs: 1.2,
            rest_secs: 1.6,
            walk_out_secs: 4.0,
            target_sigma_m: 0.01,
            step_hz: 1.8,
            habits: Habits::default(),
            floor_pick: None,
        }
    }

    /// Moves where the operator stands, faces and walks in from (and the floor pick's part) with a
    /// station at `T_world_station`: those are written for a station at the world's origin facing
    /// +x, as [`SessionScript::new`] and [`FloorPick::new`] give them. The handover point is the
    /// world's already (the cell puts each lock's station-frame point there) and stays.
    pub fn place_at_station(&mut self, T_world_station: &Isometry3<f64>) {
        let on_floor = |xy: [f64; 2]| {
            let p = T_world_station * Point3::new(xy[0], xy[1], 0.0);
            [p.x, p.y]
        };
        self.station_m = on_floor(self.station_m);
        self.entry_m = on_floor(self.entry_m);
        let facing = T_world_station.rotation
            * Vector3::new(
                self.station_heading_rad.cos(),
                self.station_heading_rad.sin(),
                0.0,
            );
        self.station_heading_rad = facing.y.atan2(facing.x);
        if let Some(pick) = &mut self.floor_pick {
            pick.target_m = T_world_station * pick.target_m;
        }
    }

    fn cycle_secs(&self) -> f64 {
        self.reach_secs + self.hold_secs + self.return_secs + self.rest_secs
    }

    /// Total duration, seconds.
    pub fn duration_secs(&self) -> f64 {
        let d = self.walk_in_secs
            + self.idle_secs
            + self.cycles as f64 * self.cycle_secs()
            + self.walk_out_secs;
        match &self.floor_pick {
            Some(p) => d + p.duration_secs(),
            None => d,
        }
    }

    fn validate(&self) -> Result<(), SimError> {
        for (name, v) in [
            ("walk_in_secs", self.walk_in_secs),
            ("idle_secs", self.idle_secs),
            ("reach_secs", self.reach_secs),
            ("hold_secs", self.hold_secs),
            ("return_secs", self.return_secs),
            ("rest_secs", self.rest_secs),
            ("walk_out_secs", self.walk_out_secs),
            ("target_sigma_m", self.target_sigma_m),
            ("step_hz", self.step_hz),
        ] {
            if !(v.is_finite() && v >= 0.0) {
                return Err(SimError::BadParameter {
                    name,
                    value: v,
                    why: "must be finite and >= 0",
                });
            }
        }
        if let Some(p) = &self.floor_pick {
            for (name, v) in [
                ("floor_pick.reach_secs", p.reach_secs),
                ("floor_pick.hold_secs", p.hold_secs),
                ("floor_pick.return_secs", p.return_secs),
            ] {
                if !(v.is_finite() && v >= 0.0) {
                    return Err(SimError::BadParameter {
                        name,
                        value: v,
                        why: "must be finite and >= 0",
                    });
                }
            }
            if p.after_cycle > self.cycles {
                return Err(SimError::BadParameter {
                    name: "floor_pick.after_cycle",
                    value: p.after_cycle as f64,
                    why: "must be at most the number of cycles",
                });
            }
            let t = p.target_m;
            for v in [t.x, t.y, t.z] {
                if !v.is_finite() {
                    return Err(SimError::BadParameter {
                        name: "floor_pick.target_m",
                        value: v,
                        why: "not finite",
                    });
                }
            }
        }
        let h = self.handover_m;
        for v in [
            h.x,
            h.y,
            h.z,
            self.station_m[0],
            self.station_m[1],
            self.entry_m[0],
            self.entry_m[1],
        ] {
            if !v.is_finite() {
                return Err(SimError::BadParameter {
                    name: "position",
                    value: v,
                    why: "not finite",
                });
            }
        }
        Ok(())
    }
}

/// Simulation settings.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SimConfig {
    /// Seed of every random draw (detector noise and motion variation).
    pub seed: u64,
    /// Frame period, nanoseconds (default 100 ms: 10 Hz, as the seed paper's cameras).
    pub frame_period_nanos: i64,
    /// Stamp of tick 0, nanoseconds (default 0).
    pub start_nanos: i64,
    pub noise: DetectorNoise,
    pub reach: ReachConfig,
    /// A camera knocked out of its calibration mid-session (default none).
    pub bump: Option<CameraBump>,
    /// A second person whom some cameras' detector follows instead of the operator (default none).
    pub bystander: Option<Bystander>,
}

/// A second person in the cell — a colleague, a visitor — standing still, whom the single-person
/// detector of some cameras locks onto instead of the operator (what MediaPipe's legacy BlazePose
/// does: it tracks one person per camera, and on Pose2Sim's two-person video one of four cameras
/// followed the other person). Those cameras report the bystander's landmarks, with the same
/// detector noise, from `from_nanos` on; the others still see the operator.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Bystander {
    pub person: Operator,
    /// Where they stand (the floor point below mid-hip, world x and y) and which way they face.
    pub position_m: [f64; 2],
    pub heading_rad: f64,
    /// Bit `k` set: camera `k` reports the bystander.
    pub cameras: u64,
    pub from_nanos: i64,
}

/// A camera bumped at `from_nanos`: from then on it sees the scene through a pose rotated by
/// `rotation_rad` (axis × angle, in the camera's own frame, about its optical centre), while the
/// rig — its calibration — stays as it was. What a knock on the mount does.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CameraBump {
    pub camera: CameraIndex,
    pub from_nanos: i64,
    pub rotation_rad: [f64; 3],
}

impl CameraBump {
    /// `camera` as it sees the world after this bump.
    pub fn apply(&self, camera: &ergocell_perception::Camera) -> ergocell_perception::Camera {
        let [x, y, z] = self.rotation_rad;
        let delta = nalgebra::UnitQuaternion::from_scaled_axis(nalgebra::Vector3::new(x, y, z));
        let centre = camera.position_world();
        let rotation = delta * camera.T_camera_world.rotation;
        let translation = -(rotation * centre.coords);
        let mut bumped = camera.clone();
        bumped.T_camera_world = nalgebra::Isometry3::from_parts(translation.into(), rotation);
        bumped
    }
}

impl SimConfig {
    /// Defaults with this seed.
    pub fn new(seed: u64) -> Self {
        Self {
            seed,
            frame_period_nanos: 100_000_000,
            start_nanos: 0,
            noise: DetectorNoise::default(),
            reach: ReachConfig::default(),
            bump: None,
            bystander: None,
        }
    }
}

/// Ground truth of one instant.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct GroundTruth {
    pub stamp_nanos: i64,
    pub phase: Phase,
    /// True stature, metres.
    pub stature_m: f64,
    /// True joint angles and placement.
    pub posture: Posture,
    /// The 33 true landmarks (confidence 1).
    pub skeleton: Skeleton3,
    /// The hand's target of the current cycle, if in a handover cycle, or of the floor pick.
    pub target_m: Option<Point3<f64>>,
}

/// One simulated frame: the truth at the tick and what the cameras reported.
#[derive(Debug, Clone, PartialEq)]
pub struct Tick {
    /// Tick index from 0.
    pub index: u64,
    pub truth: GroundTruth,
    /// The views that arrived, in camera order, each with its own jittered `stamp_nanos`; the
    /// frame's stamp is the tick time.
    pub frame: Frame2,
    /// Cameras whose view was dropped this tick.
    pub dropped: Vec<CameraIndex>,
}

/// A running simulation: a rig, an operator, a script, a seed. Step it with [`Simulation::step`]
/// or iterate it.
#[derive(Debug, Clone)]
pub struct Simulation {
    rig: CameraRig,
    operator: Operator,
    script: SessionScript,
    config: SimConfig,
    rest: Posture,
    idle: Posture,
    reach: Vec<(Point3<f64>, Posture)>,
    /// Each cycle's drawn offset of the hand's target from the handover point (kept so a retarget
    /// moves the point and keeps the operator's variation).
    reach_offsets_m: Vec<nalgebra::Vector3<f64>>,
    /// The floor pick's solved posture, if the script has one.
    pick: Option<Posture>,
    /// The station's other tasks, each with the posture it holds ([`crate::tasks`]).
    tasks: Vec<(TaskOccurrence, Posture)>,
    /// With tasks: every stretch after the idle phase, `(start, kind)`, start in seconds from the
    /// end of the idle phase, in time order, then the end of the last one. Empty without tasks (the
    /// handover cycles and the floor pick are then placed by arithmetic, as they always were).
    timeline: Vec<(f64, Segment)>,
    timeline_end_secs: f64,
    rng: ChaCha8Rng,
    /// The detector's persistent offsets, when its noise is relative ([`RelativeNoise`]).
    persistent: Option<PersistentOffsets>,
    next: u64,
    ticks: u64,
}

fn smoothstep(s: f64) -> f64 {
    let s = s.clamp(0.0, 1.0);
    s * s * (3.0 - 2.0 * s)
}

impl Simulation {
    /// Builds the session: validates the inputs and solves each cycle's reaching posture.
    pub fn new(
        rig: CameraRig,
        operator: Operator,
        script: SessionScript,
        config: SimConfig,
    ) -> Result<Self, SimError> {
        Self::with_tasks(rig, operator, script, config, Vec::new())
    }

    /// [`Simulation::new`] with the station's other tasks between the handover cycles (drawn by
    /// [`crate::tasks::TaskMix::draw`]; each placed after its `after_cycle` cycles, at most
    /// [`SessionScript::cycles`]).
    pub fn with_tasks(
        rig: CameraRig,
        operator: Operator,
        script: SessionScript,
        config: SimConfig,
        tasks: Vec<TaskOccurrence>,
    ) -> Result<Self, SimError> {
        script.validate()?;
        for t in &tasks {
            if t.after_cycle > script.cycles {
                return Err(SimError::BadParameter {
                    name: "task.after_cycle",
                    value: t.after_cycle as f64,
                    why: "must be at most the number of cycles",
                });
            }
            for v in [t.reach_secs, t.hold_secs, t.return_secs, t.rest_secs] {
                if !(v.is_finite() && v >= 0.0) {
                    return Err(SimError::BadParameter {
                        name: "task duration",
                        value: v,
                        why: "must be finite and >= 0",
                    });
                }
            }
        }
        config.noise.validate()?;
        if config.frame_period_nanos <= 0 {
            return Err(SimError::BadParameter {
                name: "frame_period_nanos",
                value: config.frame_period_nanos as f64,
                why: "must be positive",
            });
        }
        // Motion variation has its own stream, so changing the noise never changes the motion.
        let mut motion = ChaCha8Rng::seed_from_u64(config.seed);
        motion.set_stream(1);
        let habits = script.habits;
        let mut rest = Posture {
            position_m: script.station_m,
            heading_rad: script.station_heading_rad,
            trunk_flexion_rad: draw(&mut motion, habits.trunk_flexion_rad),
            ..Posture::default()
        };
        let wrist = draw(&mut motion, habits.wrist_flexion_rad);
        rest.left_arm.wrist_flexion_rad = wrist;
        rest.right_arm.wrist_flexion_rad = wrist;
        let idle = Posture {
            neck_flexion_rad: draw(&mut motion, habits.idle_neck_flexion_rad),
            ..rest
        };
        rest.neck_flexion_rad = draw(&mut motion, habits.rest_neck_flexion_rad);
        let mut reach = Vec::with_capacity(script.cycles);
        let mut reach_offsets_m = Vec::with_capacity(script.cycles);
        for _ in 0..script.cycles {
            let offset = nalgebra::Vector3::new(
                gaussian(&mut motion),
                gaussian(&mut motion),
                gaussian(&mut motion),
            ) * script.target_sigma_m;
            let target = script.handover_m + offset;
            let sol = solve_reach(&operator, &rest, &target, &config.reach)?;
            reach.push((target, sol.posture));
            reach_offsets_m.push(offset);
        }
        // No random draws: a script without a pick is unchanged, one with it differs only there.
        let pick = match &script.floor_pick {
            Some(p) => Some(solve_reach(&operator, &rest, &p.target_m, &config.reach)?.posture),
            None => None,
        };
        let tasks: Vec<(TaskOccurrence, Posture)> = tasks
            .into_iter()
            .map(|t| {
                let q = t.posture(&rest, operator.right_handed);
                (t, q)
            })
            .collect();
        let (timeline, timeline_end_secs) = timeline(&script, &tasks);
        let mut rng = ChaCha8Rng::seed_from_u64(config.seed);
        rng.set_stream(2);
        let period_secs = config.frame_period_nanos as f64 * 1e-9;
        let duration =
            script.duration_secs() + tasks.iter().map(|(t, _)| t.duration_secs()).sum::<f64>();
        let ticks = (duration / period_secs).floor() as u64 + 1;
        let persistent = config
            .noise
            .relative
            .as_ref()
            .map(|_| PersistentOffsets::new(rig.len(), config.seed));
        Ok(Self {
            rig,
            operator,
            script,
            config,
            rest,
            idle,
            reach,
            reach_offsets_m,
            pick,
            tasks,
            timeline,
            timeline_end_secs,
            rng,
            persistent,
            next: 0,
            ticks,
        })
    }

    /// The rig.
    pub fn rig(&self) -> &CameraRig {
        &self.rig
    }

    /// The operator.
    pub fn operator(&self) -> &Operator {
        &self.operator
    }

    /// The script.
    pub fn script(&self) -> &SessionScript {
        &self.script
    }

    /// Number of ticks in the session.
    pub fn tick_count(&self) -> u64 {
        self.ticks
    }

    /// Each cycle's hand target and solved reaching posture.
    pub fn reach_postures(&self) -> &[(Point3<f64>, Posture)] {
        &self.reach
    }

    /// The floor pick's solved posture, if the script has one.
    pub fn floor_pick_posture(&self) -> Option<&Posture> {
        self.pick.as_ref()
    }

    /// The station's other tasks of this session, each with the posture it holds.
    pub fn tasks(&self) -> &[(TaskOccurrence, Posture)] {
        &self.tasks
    }

    /// When cycle `cycle`'s reach begins, nanoseconds (the script's clock).
    fn cycle_start_nanos(&self, cycle: usize) -> i64 {
        let sc = &self.script;
        if let Some((start, _)) = self
            .timeline
            .iter()
            .find(|(_, s)| *s == Segment::Handover(cycle))
        {
            let t = sc.walk_in_secs + sc.idle_secs + start;
            return self.config.start_nanos + (t * 1e9).round() as i64;
        }
        let mut t = sc.walk_in_secs + sc.idle_secs + cycle as f64 * sc.cycle_secs();
        if let Some(p) = &sc.floor_pick {
            if p.after_cycle <= cycle {
                t += p.duration_secs();
            }
        }
        self.config.start_nanos + (t * 1e9).round() as i64
    }

    /// Moves the handover point for every cycle whose reach begins at or after `from_nanos` (the
    /// operator reaches where the robot brings the part: the cell may decide a class other than the
    /// operator's own near a boundary). Each cycle keeps its own drawn variation around the point;
    /// the reaching postures are solved again. A cycle already begun keeps its target. Returns the
    /// number of cycles moved.
    pub fn retarget_handover(
        &mut self,
        handover_m: Point3<f64>,
        from_nanos: i64,
    ) -> Result<usize, SimError> {
        for v in [handover_m.x, handover_m.y, handover_m.z] {
            if !v.is_finite() {
                return Err(SimError::BadParameter {
                    name: "handover_m",
                    value: v,
                    why: "not finite",
                });
            }
        }
        let first = (0..self.script.cycles)
            .find(|&c| self.cycle_start_nanos(c) >= from_nanos)
            .unwrap_or(self.script.cycles);
        let mut moved = Vec::with_capacity(self.script.cycles - first);
        for c in first..self.script.cycles {
            let target = handover_m + self.reach_offsets_m[c];
            let sol = solve_reach(&self.operator, &self.rest, &target, &self.config.reach)?;
            moved.push((target, sol.posture));
        }
        let n = moved.len();
        for (k, r) in moved.into_iter().enumerate() {
            self.reach[first + k] = r;
        }
        if first == 0 {
            self.script.handover_m = handover_m;
        }
        Ok(n)
    }

    /// The phase and posture at time `t_nanos` (pure: no randomness, no state).
    pub fn posture_at(&self, t_nanos: i64) -> (Phase, Posture, Option<Point3<f64>>) {
        let sc = &self.script;
        let mut t = (t_nanos - self.config.start_nanos) as f64 * 1e-9;
        if t < sc.walk_in_secs {
            return (Phase::WalkIn, self.walk(t, true), None);
        }
        t -= sc.walk_in_secs;
        if t < sc.idle_secs {
            return (Phase::Idle, self.idle, None);
        }
        t -= sc.idle_secs;
        if !self.timeline.is_empty() {
            return self.timeline_at(t);
        }
        let cycle_secs = sc.cycle_secs();
        if let (Some(p), Some(pick)) = (&sc.floor_pick, &self.pick) {
            let from = p.after_cycle as f64 * cycle_secs;
            if t >= from {
                let u = t - from;
                if u < p.duration_secs() {
                    let target = Some(p.target_m);
                    let stage = |stage| Phase::FloorPick { stage };
                    if u < p.reach_secs {
                        let s = smoothstep(u / p.reach_secs.max(1e-9));
                        return (stage(PickStage::Reach), self.rest.lerp(pick, s), target);
                    }
                    if u < p.reach_secs + p.hold_secs {
                        return (stage(PickStage::Hold), *pick, target);
                    }
                    let s = smoothstep((u - p.reach_secs - p.hold_secs) / p.return_secs.max(1e-9));
                    return (stage(PickStage::Return), pick.lerp(&self.rest, s), target);
                }
                t -= p.duration_secs();
            }
        }
        if sc.cycles > 0 && t < cycle_secs * sc.cycles as f64 {
            let cycle = ((t / cycle_secs).floor() as usize).min(sc.cycles - 1);
            let u = t - cycle as f64 * cycle_secs;
            return self.handover_at(cycle, u);
        }
        t -= cycle_secs * sc.cycles as f64;
        self.walk_out_at(t)
    }

    fn walk_out_at(&self, t: f64) -> (Phase, Posture, Option<Point3<f64>>) {
        let sc = &self.script;
        if t < sc.walk_out_secs {
            return (Phase::WalkOut, self.walk(t, false), None);
        }
        (Phase::Gone, self.walk(sc.walk_out_secs, false), None)
    }

    /// Handover cycle `cycle`, `u` seconds after its reach began.
    fn handover_at(&self, cycle: usize, mut u: f64) -> (Phase, Posture, Option<Point3<f64>>) {
        let sc = &self.script;
        let (target, reach) = self.reach[cycle];
        if u < sc.reach_secs {
            let s = smoothstep(u / sc.reach_secs.max(1e-9));
            return (
                Phase::Reach { cycle },
                self.rest.lerp(&reach, s),
                Some(target),
            );
        }
        u -= sc.reach_secs;
        if u < sc.hold_secs {
            return (Phase::Hold { cycle }, reach, Some(target));
        }
        u -= sc.hold_secs;
        if u < sc.return_secs {
            let s = smoothstep(u / sc.return_secs.max(1e-9));
            return (
                Phase::Return { cycle },
                reach.lerp(&self.rest, s),
                Some(target),
            );
        }
        (Phase::Rest { cycle }, self.rest, Some(target))
    }

    /// With tasks: the posture `t` seconds after the idle phase, from the timeline.
    fn timeline_at(&self, t: f64) -> (Phase, Posture, Option<Point3<f64>>) {
        if t >= self.timeline_end_secs {
            return self.walk_out_at(t - self.timeline_end_secs);
        }
        let i = self
            .timeline
            .partition_point(|(start, _)| *start <= t)
            .saturating_sub(1);
        let Some(&(start, segment)) = self.timeline.get(i) else {
            return self.walk_out_at(t - self.timeline_end_secs);
        };
        let u = t - start;
        match segment {
            Segment::Handover(cycle) => self.handover_at(cycle, u),
            Segment::FloorPick => match (&self.script.floor_pick, &self.pick) {
                (Some(p), Some(pick)) => {
                    let target = Some(p.target_m);
                    let stage = |stage| Phase::FloorPick { stage };
                    if u < p.reach_secs {
                        let s = smoothstep(u / p.reach_secs.max(1e-9));
                        (stage(PickStage::Reach), self.rest.lerp(pick, s), target)
                    } else if u < p.reach_secs + p.hold_secs {
                        (stage(PickStage::Hold), *pick, target)
                    } else {
                        let s =
                            smoothstep((u - p.reach_secs - p.hold_secs) / p.return_secs.max(1e-9));
                        (stage(PickStage::Return), pick.lerp(&self.rest, s), target)
                    }
                }
                _ => (Phase::Idle, self.rest, None),
            },
            Segment::Task(index) => {
                let Some((task, held)) = self.tasks.get(index) else {
                    return (Phase::Idle, self.rest, None);
                };
                let phase = |stage| Phase::Task {
                    index,
                    kind: task.kind,
                    stage,
                };
                if u < task.reach_secs {
                    let s = smoothstep(u / task.reach_secs.max(1e-9));
                    return (phase(TaskStage::Reach), self.rest.lerp(held, s), None);
                }
                let u = u - task.reach_secs;
                if u < task.hold_secs {
                    return (phase(TaskStage::Hold), *held, None);
                }
                let u = u - task.hold_secs;
                if u < task.return_secs {
                    let s = smoothstep(u / task.return_secs.max(1e-9));
                    return (phase(TaskStage::Return), held.lerp(&self.rest, s), None);
                }
                (phase(TaskStage::Rest), self.rest, None)
            }
        }
    }

    /// Walking between the entry and the station; `t` from the start of the walk.
    fn walk(&self, t: f64, inbound: bool) -> Posture {
        let sc = &self.script;
        let dur = if inbound {
            sc.walk_in_secs
        } else {
            sc.walk_out_secs
        }
        .max(1e-9);
        let (from, to) = if inbound {
            (sc.entry_m, sc.station_m)
        } else {
            (sc.station_m, sc.entry_m)
        };
        let travel = (to[1] - from[1]).atan2(to[0] - from[0]);
        // Walk for 80 % of the time, turn on the spot for the rest (at the end inbound, at the
        // start outbound).
        let (walk_start, walk_end) = if inbound { (0.0, 0.8) } else { (0.2, 1.0) };
        let s = t / dur;
        let w = ((s - walk_start) / (walk_end - walk_start)).clamp(0.0, 1.0);
        let mut q = self.idle;
        q.position_m = [
            from[0] + (to[0] - from[0]) * w,
            from[1] + (to[1] - from[1]) * w,
        ];
        let turn = if inbound {
            smoothstep((s - 0.8) / 0.2)
        } else {
            smoothstep(s / 0.2)
        };
        let (h0, h1) = if inbound {
            (travel, sc.station_heading_rad)
        } else {
            (sc.station_heading_rad, travel)
        };
        let dh = (h1 - h0 + std::f64::consts::PI).rem_euclid(std::f64::consts::TAU)
            - std::f64::consts::PI;
        q.heading_rad = h0 + dh * turn;
        // Gait while moving: legs and arms swing in antiphase, amplitude ramps at both ends.
        let moving = w > 0.0 && w < 1.0;
        if moving {
            let ramp = (w * 8.0).min((1.0 - w) * 8.0).min(1.0);
            let phase = std::f64::consts::TAU * sc.step_hz * 0.5 * t;
            let d = f64::to_radians;
            let leg = |ph: f64| LegPosture {
                hip_flexion_rad: ramp * d(20.0) * ph.sin(),
                knee_flexion_rad: ramp * d(35.0) * (ph + 0.9).sin().max(0.0) + d(5.0) * ramp,
            };
            q.left_leg = leg(phase);
            q.right_leg = leg(phase + std::f64::consts::PI);
            q.left_arm.flexion_rad = -ramp * d(15.0) * phase.sin();
            q.right_arm.flexion_rad = ramp * d(15.0) * phase.sin();
        }
        q
    }

    /// Ground truth at time `t_nanos`.
    pub fn truth_at(&self, t_nanos: i64) -> Result<GroundTruth, SimError> {
        let (phase, posture, target) = self.posture_at(t_nanos);
        let points = self.operator.landmarks(&posture);
        Ok(GroundTruth {
            stamp_nanos: t_nanos,
            phase,
            stature_m: self.operator.stature_m(),
            posture,
            skeleton: Skeleton3::from_points(t_nanos, &points)?,
            target_m: target,
        })
    }

    /// The next tick, or `None` after the last one.
    pub fn step(&mut self) -> Result<Option<Tick>, SimError> {
        if self.next >= self.ticks {
            return Ok(None);
        }
        let index = self.next;
        self.next += 1;
        let t = self.config.start_nanos + index as i64 * self.config.frame_period_nanos;
        let truth = self.truth_at(t)?;
        let mut views = Vec::with_capacity(self.rig.len());
        let mut dropped = Vec::new();
        let persistent = match (&self.config.noise.relative, &mut self.persistent) {
            (Some(r), Some(p)) => {
                let hip = |l| truth.skeleton.position(l);
                let centre = match (hip(Landmark::LeftHip), hip(Landmark::RightHip)) {
                    (Some(a), Some(b)) => nalgebra::center(&a, &b),
                    _ => Point3::origin(),
                };
                Some(p.at(t, r, self.rig.cameras(), &centre))
            }
            _ => None,
        };
        for (k, camera) in self.rig.cameras().iter().enumerate() {
            let u_drop = self.rng.random::<f64>();
            let dt = jitter_nanos(&self.config.noise, &mut self.rng);
            if u_drop < self.config.noise.drop_probability {
                dropped.push(k);
                continue;
            }
            let stamp = t + dt;
            let posture = if dt == 0 {
                truth.posture
            } else {
                self.truth_at(stamp)?.posture
            };
            let bystander = self
                .config
                .bystander
                .filter(|b| b.cameras & (1 << k) != 0 && stamp >= b.from_nanos);
            let kin = match bystander {
                Some(b) => b.person.kinematics(&Posture {
                    position_m: b.position_m,
                    heading_rad: b.heading_rad,
                    ..Posture::default()
                }),
                None => self.operator.kinematics(&posture),
            };
            let bumped = self
                .config
                .bump
                .filter(|b| b.camera == k && stamp >= b.from_nanos)
                .map(|b| b.apply(camera));
            let offsets = persistent.as_ref().and_then(|o| o.get(k));
            views.push(render_view(
                bumped.as_ref().unwrap_or(camera),
                k,
                stamp,
                &kin,
                &self.config.noise,
                offsets,
                &mut self.rng,
            ));
        }
        Ok(Some(Tick {
            index,
            truth,
            frame: Frame2 {
                stamp_nanos: t,
                views,
            },
            dropped,
        }))
    }
}

/// The timeline of a session with tasks: for each slot `k` (after `k` handover cycles) the floor
/// pick if it is there, then the tasks placed there, then handover cycle `k`. Empty without tasks.
fn timeline(
    script: &SessionScript,
    tasks: &[(TaskOccurrence, Posture)],
) -> (Vec<(f64, Segment)>, f64) {
    if tasks.is_empty() {
        return (Vec::new(), 0.0);
    }
    let mut out = Vec::new();
    let mut t = 0.0;
    for slot in 0..=script.cycles {
        if let Some(p) = script.floor_pick.filter(|p| p.after_cycle == slot) {
            out.push((t, Segment::FloorPick));
            t += p.duration_secs();
        }
        for (i, (task, _)) in tasks.iter().enumerate() {
            if task.after_cycle == slot {
                out.push((t, Segment::Task(i)));
                t += task.duration_secs();
            }
        }
        if slot < script.cycles {
            out.push((t, Segment::Handover(slot)));
            t += script.cycle_secs();
        }
    }
    (out, t)
}

impl Iterator for Simulation {
    type Item = Result<Tick, SimError>;

    fn next(&mut self) -> Option<Self::Item> {
        self.step().transpose()
    }
}
