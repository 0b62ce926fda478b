//! The tasks of a real station, as data: a task mix (`sim/tasks/default.toml`, or the user's own
//! file) says how many times each task occurs in a session and the ranges its posture and timing are
//! drawn from; [`TaskMix::draw`] turns it into the concrete tasks of one seeded session.
//!
//! Why: the handover alone keeps the operator near RULA's band edges, so it cannot say how reliably
//! an operator is warned of a posture that deserves a warning. Bending to a low bin, reaching above
//! the shoulder, reading a label, turning to a side table, a long reach, fastening with a bent wrist
//! and kneeling each take one body region well past its band edge for seconds at a time, as at a
//! real station. The posture is set joint by joint (the one body model, [`crate::body::Posture`]),
//! so the truth's angles are the declared ones and the measurement can tell a clear warning from a
//! borderline one.
//!
//! A task occurrence is reach (from the resting posture, smoothstep in joint space) → hold →
//! return → rest, like a handover cycle. Nothing here reads a clock or a file: the binary reads the
//! file and hands its text to [`TaskMix::from_toml_str`].

use std::collections::BTreeMap;

use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use serde::{Deserialize, Serialize};

use crate::body::Posture;

/// The shipped default mix (`sim/tasks/default.toml`).
pub const DEFAULT_MIX_TOML: &str = include_str!("../tasks/default.toml");

/// The name by which the shipped mix is chosen (`--tasks default`).
pub const DEFAULT_MIX_NAME: &str = "default";

/// A task of the station besides the handover.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum TaskKind {
    /// Picking from a low bin (trunk flexion).
    LowBin,
    /// Placing on a high shelf (upper arm above the shoulder).
    HighShelf,
    /// Reading a screen or label below eye level (neck flexion).
    ReadLabel,
    /// Turning to a side table (trunk twist).
    SideTable,
    /// A long reach across the table (upper arm, trunk lean).
    LongReach,
    /// Wrist-heavy fastening (wrist flexion and deviation).
    Fastening,
    /// Kneeling on one knee (legs).
    Kneel,
}

impl TaskKind {
    /// Every task, in file order.
    pub const ALL: [TaskKind; 7] = [
        TaskKind::LowBin,
        TaskKind::HighShelf,
        TaskKind::ReadLabel,
        TaskKind::SideTable,
        TaskKind::LongReach,
        TaskKind::Fastening,
        TaskKind::Kneel,
    ];

    /// The task's name in a mix file.
    pub fn name(self) -> &'static str {
        match self {
            TaskKind::LowBin => "low_bin",
            TaskKind::HighShelf => "high_shelf",
            TaskKind::ReadLabel => "read_label",
            TaskKind::SideTable => "side_table",
            TaskKind::LongReach => "long_reach",
            TaskKind::Fastening => "fastening",
            TaskKind::Kneel => "kneel",
        }
    }

    fn from_name(name: &str) -> Option<Self> {
        Self::ALL.into_iter().find(|k| k.name() == name)
    }
}

/// A task mix that cannot be used: what is wrong, naming the key.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum TaskMixError {
    /// Not TOML, a key the format does not have, or a value of the wrong type (the TOML reader's
    /// message names the key and the line).
    #[error("{message}")]
    Toml { message: String },
    /// A `[task.<name>]` that is not a task of the library.
    #[error("[task.{name}]: no such task (known: {known})")]
    UnknownTask { name: String, known: String },
    /// A range whose bounds are reversed, not finite, or outside what the body can do.
    #[error("[task.{task}] {key} = [{lo}, {hi}]: {why}")]
    BadRange {
        task: String,
        key: &'static str,
        lo: f64,
        hi: f64,
        why: String,
    },
    /// A timing range the task must have.
    #[error("[task.{task}]: {key} is missing")]
    Missing { task: String, key: &'static str },
    /// A count outside its bounds.
    #[error("{key} = {value}: {why}")]
    BadCount {
        key: String,
        value: u64,
        why: &'static str,
    },
}

/// One task as declared in a mix: every field a range `[lo, hi]` drawn uniformly per occurrence;
/// an absent posture field leaves that joint as the operator rests.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct TaskSpec {
    /// Occurrences per session.
    pub count: Option<u64>,
    pub trunk_flexion_deg: Option<[f64; 2]>,
    pub trunk_twist_deg: Option<[f64; 2]>,
    pub trunk_side_bend_deg: Option<[f64; 2]>,
    pub neck_flexion_deg: Option<[f64; 2]>,
    pub neck_yaw_deg: Option<[f64; 2]>,
    pub arm_flexion_deg: Option<[f64; 2]>,
    pub arm_abduction_deg: Option<[f64; 2]>,
    pub elbow_flexion_deg: Option<[f64; 2]>,
    pub wrist_flexion_deg: Option<[f64; 2]>,
    pub wrist_deviation_deg: Option<[f64; 2]>,
    pub shoulder_raise_m: Option<[f64; 2]>,
    pub front_hip_flexion_deg: Option<[f64; 2]>,
    pub front_knee_flexion_deg: Option<[f64; 2]>,
    pub back_hip_flexion_deg: Option<[f64; 2]>,
    pub back_knee_flexion_deg: Option<[f64; 2]>,
    /// The arm angles apply to both arms (default: the working arm only).
    pub both_arms: Option<bool>,
    pub reach_s: Option<[f64; 2]>,
    pub hold_s: Option<[f64; 2]>,
    pub return_s: Option<[f64; 2]>,
    pub rest_s: Option<[f64; 2]>,
}

/// The posture fields: key, the range the body allows (degrees or metres), and how a drawn value is
/// put on the posture.
type Apply = fn(&mut Posture, f64, bool, bool);

fn arm_fields(q: &mut Posture, right_handed: bool, both: bool, f: impl Fn(&mut crate::ArmPosture)) {
    f(q.working_arm_mut(right_handed));
    if both {
        f(q.working_arm_mut(!right_handed));
    }
}

fn front_leg(q: &mut Posture, right_handed: bool) -> &mut crate::LegPosture {
    if right_handed {
        &mut q.right_leg
    } else {
        &mut q.left_leg
    }
}

fn back_leg(q: &mut Posture, right_handed: bool) -> &mut crate::LegPosture {
    if right_handed {
        &mut q.left_leg
    } else {
        &mut q.right_leg
    }
}

const POSTURE_FIELDS: [(&str, [f64; 2], Apply); 15] = [
    ("trunk_flexion_deg", [-30.0, 90.0], |q, v, _, _| {
        q.trunk_flexion_rad = v.to_radians();
    }),
    ("trunk_twist_deg", [-70.0, 70.0], |q, v, _, _| {
        q.trunk_twist_rad = v.to_radians();
    }),
    ("trunk_side_bend_deg", [-45.0, 45.0], |q, v, _, _| {
        q.trunk_side_bend_rad = v.to_radians();
    }),
    ("neck_flexion_deg", [-60.0, 70.0], |q, v, _, _| {
        q.neck_flexion_rad = v.to_radians();
    }),
    ("neck_yaw_deg", [-80.0, 80.0], |q, v, _, _| {
        q.neck_yaw_rad = v.to_radians();
    }),
    ("arm_flexion_deg", [-50.0, 180.0], |q, v, r, b| {
        arm_fields(q, r, b, |a| a.flexion_rad = v.to_radians());
    }),
    ("arm_abduction_deg", [-30.0, 150.0], |q, v, r, b| {
        arm_fields(q, r, b, |a| a.abduction_rad = v.to_radians());
    }),
    ("elbow_flexion_deg", [0.0, 150.0], |q, v, r, b| {
        arm_fields(q, r, b, |a| a.elbow_flexion_rad = v.to_radians());
    }),
    ("wrist_flexion_deg", [-70.0, 80.0], |q, v, r, b| {
        arm_fields(q, r, b, |a| a.wrist_flexion_rad = v.to_radians());
    }),
    ("wrist_deviation_deg", [-40.0, 30.0], |q, v, r, b| {
        arm_fields(q, r, b, |a| a.wrist_deviation_rad = v.to_radians());
    }),
    ("shoulder_raise_m", [0.0, 0.06], |q, v, r, b| {
        arm_fields(q, r, b, |a| a.shoulder_raise_m = v);
    }),
    ("front_hip_flexion_deg", [-30.0, 120.0], |q, v, r, _| {
        front_leg(q, r).hip_flexion_rad = v.to_radians();
    }),
    ("front_knee_flexion_deg", [0.0, 150.0], |q, v, r, _| {
        front_leg(q, r).knee_flexion_rad = v.to_radians();
    }),
    ("back_hip_flexion_deg", [-30.0, 120.0], |q, v, r, _| {
        back_leg(q, r).hip_flexion_rad = v.to_radians();
    }),
    ("back_knee_flexion_deg", [0.0, 150.0], |q, v, r, _| {
        back_leg(q, r).knee_flexion_rad = v.to_radians();
    }),
];

impl TaskSpec {
    /// The posture ranges in [`POSTURE_FIELDS`] order.
    fn posture_ranges(&self) -> [Option<[f64; 2]>; 15] {
        [
            self.trunk_flexion_deg,
            self.trunk_twist_deg,
            self.trunk_side_bend_deg,
            self.neck_flexion_deg,
            self.neck_yaw_deg,
            self.arm_flexion_deg,
            self.arm_abduction_deg,
            self.elbow_flexion_deg,
            self.wrist_flexion_deg,
            self.wrist_deviation_deg,
            self.shoulder_raise_m,
            self.front_hip_flexion_deg,
            self.front_knee_flexion_deg,
            self.back_hip_flexion_deg,
            self.back_knee_flexion_deg,
        ]
    }

    fn timing_ranges(&self) -> [(&'static str, Option<[f64; 2]>); 4] {
        [
            ("reach_s", self.reach_s),
            ("hold_s", self.hold_s),
            ("return_s", self.return_s),
            ("rest_s", self.rest_s),
        ]
    }

    /// `self`'s fields where present, `base`'s elsewhere.
    fn over(self, base: &TaskSpec) -> TaskSpec {
        macro_rules! pick {
            ($($f:ident),*) => { TaskSpec { $($f: self.$f.or(base.$f)),* } };
        }
        pick!(
            count,
            trunk_flexion_deg,
            trunk_twist_deg,
            trunk_side_bend_deg,
            neck_flexion_deg,
            neck_yaw_deg,
            arm_flexion_deg,
            arm_abduction_deg,
            elbow_flexion_deg,
            wrist_flexion_deg,
            wrist_deviation_deg,
            shoulder_raise_m,
            front_hip_flexion_deg,
            front_knee_flexion_deg,
            back_hip_flexion_deg,
            back_knee_flexion_deg,
            both_arms,
            reach_s,
            hold_s,
            return_s,
            rest_s
        )
    }

    fn validate(&self, task: &str) -> Result<(), TaskMixError> {
        let bad = |key: &'static str, [lo, hi]: [f64; 2], why: String| TaskMixError::BadRange {
            task: task.to_owned(),
            key,
            lo,
            hi,
            why,
        };
        let check = |key: &'static str, r: [f64; 2], limits: [f64; 2]| {
            let [lo, hi] = r;
            if !(lo.is_finite() && hi.is_finite()) {
                return Err(bad(key, r, "not finite".to_owned()));
            }
            if lo > hi {
                return Err(bad(key, r, "the lower bound is above the upper".to_owned()));
            }
            if lo < limits[0] || hi > limits[1] {
                return Err(bad(
                    key,
                    r,
                    format!("outside {} to {}", limits[0], limits[1]),
                ));
            }
            Ok(())
        };
        for ((key, limits, _), range) in POSTURE_FIELDS.iter().zip(self.posture_ranges()) {
            if let Some(r) = range {
                check(key, r, *limits)?;
            }
        }
        for (key, range) in self.timing_ranges() {
            match range {
                Some(r) => check(key, r, [0.0, 600.0])?,
                None => {
                    return Err(TaskMixError::Missing {
                        task: task.to_owned(),
                        key,
                    })
                }
            }
        }
        if let Some(n) = self.count {
            if n > MAX_COUNT {
                return Err(TaskMixError::BadCount {
                    key: format!("[task.{task}] count"),
                    value: n,
                    why: "at most 100 occurrences of a task per session",
                });
            }
        }
        Ok(())
    }
}

const MAX_COUNT: u64 = 100;
const MAX_HANDOVERS: u64 = 10_000;

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct RawMix {
    handovers: Option<u64>,
    #[serde(default)]
    task: BTreeMap<String, TaskSpec>,
}

/// A task mix: the handover cycles of a session and the tasks between them.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct TaskMix {
    /// Handover cycles per session.
    pub handovers: usize,
    /// Every task the mix declares, with its ranges (the shipped default's where the file is
    /// silent), in [`TaskKind::ALL`] order; a task the file does not name is absent.
    pub tasks: Vec<(TaskKind, TaskSpec)>,
}

fn toml_error(e: &toml::de::Error) -> TaskMixError {
    TaskMixError::Toml {
        message: e.to_string().trim_end().to_owned(),
    }
}

impl TaskMix {
    /// The shipped default mix.
    pub fn default_mix() -> Result<Self, TaskMixError> {
        Self::parse(DEFAULT_MIX_TOML, None)
    }

    /// A mix from a file's text: every task named takes the shipped default's ranges for the fields
    /// it does not give; `handovers` defaults to the shipped default's.
    pub fn from_toml_str(text: &str) -> Result<Self, TaskMixError> {
        let base = Self::default_mix()?;
        Self::parse(text, Some(&base))
    }

    fn parse(text: &str, base: Option<&TaskMix>) -> Result<Self, TaskMixError> {
        let raw: RawMix = toml::from_str(text).map_err(|e| toml_error(&e))?;
        let handovers = match raw.handovers {
            Some(n) if n > MAX_HANDOVERS => {
                return Err(TaskMixError::BadCount {
                    key: "handovers".to_owned(),
                    value: n,
                    why: "at most 10000 handover cycles per session",
                })
            }
            Some(n) => usize::try_from(n).unwrap_or(usize::MAX),
            None => base.map_or(5, |b| b.handovers),
        };
        let mut tasks = Vec::new();
        for (name, spec) in raw.task {
            let Some(kind) = TaskKind::from_name(&name) else {
                return Err(TaskMixError::UnknownTask {
                    name,
                    known: TaskKind::ALL.map(TaskKind::name).join(", "),
                });
            };
            let spec = match base.and_then(|b| b.spec(kind)) {
                Some(b) => spec.over(b),
                None => spec,
            };
            spec.validate(&name)?;
            tasks.push((kind, spec));
        }
        tasks.sort_by_key(|(k, _)| *k);
        Ok(Self { handovers, tasks })
    }

    /// The declared ranges of a task, if the mix has it.
    pub fn spec(&self, kind: TaskKind) -> Option<&TaskSpec> {
        self.tasks.iter().find(|(k, _)| *k == kind).map(|(_, s)| s)
    }

    /// Occurrences of every task in one session.
    pub fn occurrences(&self) -> usize {
        self.tasks
            .iter()
            .map(|(_, s)| usize::try_from(s.count.unwrap_or(1)).unwrap_or(0))
            .sum()
    }

    /// The tasks of one session, drawn from `seed` (its own random stream: the same seed gives the
    /// same tasks, and the detector's and the handovers' draws are unchanged by them). Each task
    /// occurrence is placed after a seeded number of the `handovers` cycles (0: before the first);
    /// occurrences are in the order they happen.
    pub fn draw(&self, seed: u64) -> Vec<TaskOccurrence> {
        self.draw_between(seed, self.handovers)
    }

    /// [`TaskMix::draw`] placed among `handovers` cycles instead of the mix's own count (the demo's
    /// `--cycles`).
    pub fn draw_between(&self, seed: u64, handovers: usize) -> Vec<TaskOccurrence> {
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        rng.set_stream(3);
        let mut out = Vec::with_capacity(self.occurrences());
        for (kind, spec) in &self.tasks {
            for _ in 0..spec.count.unwrap_or(1) {
                let mut draw = |r: Option<[f64; 2]>| {
                    r.map(|[lo, hi]| {
                        let u: f64 = rng.random();
                        lo + (hi - lo) * u
                    })
                };
                let targets = spec.posture_ranges().map(&mut draw);
                let [reach, hold, ret, rest] = spec.timing_ranges().map(|(_, r)| draw(r));
                out.push(TaskOccurrence {
                    kind: *kind,
                    after_cycle: 0,
                    targets,
                    both_arms: spec.both_arms.unwrap_or(false),
                    reach_secs: reach.unwrap_or(1.0),
                    hold_secs: hold.unwrap_or(4.0),
                    return_secs: ret.unwrap_or(1.0),
                    rest_secs: rest.unwrap_or(1.0),
                });
            }
        }
        // A seeded shuffle (Fisher–Yates) and a seeded slot for each occurrence among the handover
        // cycles, then in time order (stable: the shuffle decides the order within a slot).
        for i in (1..out.len()).rev() {
            let j = rng.random_range(0..=i);
            out.swap(i, j);
        }
        let n = out.len();
        for (i, t) in out.iter_mut().enumerate() {
            // Spread evenly over the slots 0..=handovers, in shuffled order.
            t.after_cycle = (i * (handovers + 1))
                .checked_div(n)
                .unwrap_or(0)
                .min(handovers);
        }
        out
    }
}

/// One drawn occurrence of a task in a session.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct TaskOccurrence {
    pub kind: TaskKind,
    /// Handover cycles done before it.
    pub after_cycle: usize,
    /// The drawn value of each posture field (degrees or metres), `None` where the task leaves the
    /// joint as it rests.
    targets: [Option<f64>; 15],
    both_arms: bool,
    pub reach_secs: f64,
    pub hold_secs: f64,
    pub return_secs: f64,
    pub rest_secs: f64,
}

impl TaskOccurrence {
    /// The posture held: `rest` with the task's joints set.
    pub fn posture(&self, rest: &Posture, right_handed: bool) -> Posture {
        let mut q = *rest;
        for ((_, _, apply), v) in POSTURE_FIELDS.iter().zip(self.targets) {
            if let Some(v) = v {
                apply(&mut q, v, right_handed, self.both_arms);
            }
        }
        q
    }

    /// The drawn target of a posture field by its key (`"trunk_flexion_deg"`), if the task sets it.
    pub fn target(&self, key: &str) -> Option<f64> {
        POSTURE_FIELDS
            .iter()
            .zip(self.targets)
            .find(|((k, _, _), _)| *k == key)
            .and_then(|(_, v)| v)
    }

    /// Total duration, seconds.
    pub fn duration_secs(&self) -> f64 {
        self.reach_secs + self.hold_secs + self.return_secs + self.rest_secs
    }
}

/// The total duration of `tasks`, seconds.
pub fn total_secs(tasks: &[TaskOccurrence]) -> f64 {
    tasks.iter().map(TaskOccurrence::duration_secs).sum()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_shipped_mix_parses_with_every_task() {
        let mix = TaskMix::default_mix().unwrap();
        let kinds: Vec<TaskKind> = mix.tasks.iter().map(|(k, _)| *k).collect();
        assert_eq!(kinds, TaskKind::ALL.to_vec());
        assert_eq!(mix.handovers, 6);
        assert_eq!(mix.occurrences(), 13);
    }

    #[test]
    fn a_draw_is_seeded_in_range_and_placed_between_handovers() {
        let mix = TaskMix::default_mix().unwrap();
        let a = mix.draw(7);
        assert_eq!(a, mix.draw(7));
        assert_ne!(a, mix.draw(8));
        assert_eq!(a.len(), 13);
        for t in &a {
            let spec = mix.spec(t.kind).unwrap();
            let [lo, hi] = spec.hold_s.unwrap();
            assert!((lo..=hi).contains(&t.hold_secs));
            if let Some([lo, hi]) = spec.trunk_flexion_deg {
                let v = t.target("trunk_flexion_deg").unwrap();
                assert!((lo..=hi).contains(&v), "{v} outside {lo}..{hi}");
            }
            assert!(t.after_cycle <= mix.handovers);
        }
        assert!(a.windows(2).all(|w| w[0].after_cycle <= w[1].after_cycle));
    }

    #[test]
    fn the_posture_sets_the_declared_joints_only() {
        let mix = TaskMix::default_mix().unwrap();
        let t = mix
            .draw(1)
            .into_iter()
            .find(|t| t.kind == TaskKind::Fastening)
            .unwrap();
        let rest = Posture::default();
        let q = t.posture(&rest, true);
        let wf = t.target("wrist_flexion_deg").unwrap();
        assert!((q.right_arm.wrist_flexion_rad.to_degrees() - wf).abs() < 1e-9);
        assert_eq!(q.left_arm, rest.left_arm, "one arm only");
        assert_eq!(q.trunk_twist_rad, rest.trunk_twist_rad);
        let left = t.posture(&rest, false);
        assert!((left.left_arm.wrist_flexion_rad.to_degrees() - wf).abs() < 1e-9);
    }

    #[test]
    fn a_user_mix_takes_the_defaults_where_silent() {
        let mix = TaskMix::from_toml_str(
            "handovers = 2\n[task.read_label]\ncount = 3\nneck_flexion_deg = [30.0, 31.0]\n",
        )
        .unwrap();
        assert_eq!(mix.handovers, 2);
        assert_eq!(mix.tasks.len(), 1);
        let spec = mix.spec(TaskKind::ReadLabel).unwrap();
        assert_eq!(spec.count, Some(3));
        assert_eq!(spec.neck_flexion_deg, Some([30.0, 31.0]));
        let shipped = TaskMix::default_mix().unwrap();
        assert_eq!(
            spec.hold_s,
            shipped.spec(TaskKind::ReadLabel).unwrap().hold_s
        );
    }

    #[test]
    fn bad_mixes_are_refused_naming_the_key() {
        let err = |text: &str| TaskMix::from_toml_str(text).unwrap_err();
        assert!(matches!(
            err("[task.low_bin]\ntrunk_flexion_deg = [60.0, 30.0]\n"),
            TaskMixError::BadRange { ref task, key: "trunk_flexion_deg", .. } if task == "low_bin"
        ));
        assert!(matches!(
            err("[task.low_bin]\ntrunk_flexion_deg = [30.0, 130.0]\n"),
            TaskMixError::BadRange {
                key: "trunk_flexion_deg",
                ..
            }
        ));
        assert!(matches!(
            err("[task.kneel]\nhold_s = [-1.0, 2.0]\n"),
            TaskMixError::BadRange { key: "hold_s", .. }
        ));
        assert!(matches!(
            err("[task.juggling]\ncount = 1\n"),
            TaskMixError::UnknownTask { ref name, .. } if name == "juggling"
        ));
        assert!(matches!(
            err("[task.kneel]\ncount = 1000\n"),
            TaskMixError::BadCount { .. }
        ));
        assert!(matches!(
            err("handovers = 100000\n"),
            TaskMixError::BadCount { ref key, .. } if key == "handovers"
        ));
        // An unknown key is named by the TOML reader.
        match err("[task.kneel]\nknee_deg = [1.0, 2.0]\n") {
            TaskMixError::Toml { message } => assert!(message.contains("knee_deg"), "{message}"),
            other => panic!("{other:?}"),
        }
        assert!(matches!(
            err("[task.kneel]\nhold_s = [nan, 2.0]\n"),
            TaskMixError::BadRange { key: "hold_s", .. }
        ));
    }
}
