//! The demo's faults as data: which camera views go missing when, when a supervisor asks for
//! another trajectory class, and what goes wrong on the robot side (a [`RobotFault`] of the twin's
//! controller), each timed from a moment of the cell's cycle (the robot starting to work, or the
//! robot arriving at the handover point with a given part). `ergocell demo` plays a
//! [`FaultSchedule`] (the default one, a TOML file with `--faults`, or none with `--no-faults`); a test
//! or a user changes the schedule, not the demo's loop.
//!
//! ```toml
//! [[fault]]
//! kind = "cameras_silent"      # or "class_change_request"
//! after = "working"            # or "arrived_with_part" (with `part = N`, 1 = the first part)
//! at_s = 5.5                   # seconds after that moment
//! for_s = 1.0                  # cameras_silent: how long
//! cameras = ["s1_left"]        # cameras_silent: which (absent or empty: every camera)
//!
//! [[fault]]
//! kind = "robot"               # the twin's controller misbehaves (`controller::RobotFault`)
//! after = "working"
//! at_s = 0.0
//! robot = { kind = "stall", at_fraction = 0.4 }
//! ```
//!
//! A robot fault strikes the leg the controller is running when its time comes (the faults that
//! strike partway: a stall, a path deviation, an abort, the driver stopping) or the next leg it is
//! sent (the others).
//!
//! A fault begins at the first step at or after its time and lasts `for_s` from that step; each
//! fires once. Times come from the caller's clock (the simulator's): no wall time, deterministic.

use serde::Deserialize;

use crate::controller::RobotFault;
use crate::SimError;

/// The moment a fault is timed from.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum After {
    /// The session started working (the robot's first leg sent).
    Working,
    /// The robot arrived at the handover point with part `part` (the end of its leg there).
    ArrivedWithPart,
}

/// What goes wrong.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum FaultKind {
    /// The cameras' views do not arrive.
    CamerasSilent,
    /// A supervisor asks for another trajectory class (the session must refuse it).
    ClassChangeRequest,
    /// The robot side misbehaves (`robot`).
    Robot,
}

/// One fault of the schedule.
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ScheduledFault {
    pub kind: FaultKind,
    pub after: After,
    /// With `after = "arrived_with_part"`: which part (1 = the first).
    #[serde(default)]
    pub part: Option<u32>,
    /// Seconds after the moment.
    pub at_s: f64,
    /// `cameras_silent`: how long, seconds.
    #[serde(default)]
    pub for_s: Option<f64>,
    /// `cameras_silent`: the cameras by name; empty = every camera.
    #[serde(default)]
    pub cameras: Vec<String>,
    /// `robot`: what goes wrong.
    #[serde(default)]
    pub robot: Option<RobotFault>,
}

impl std::fmt::Display for ScheduledFault {
    /// "s1_left silent for 1.0 s, 5.5 s after the robot starts working".
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self.kind {
            FaultKind::CamerasSilent => write!(
                f,
                "{} silent for {:.1} s",
                if self.cameras.is_empty() {
                    "every camera".to_owned()
                } else {
                    self.cameras.join(", ")
                },
                self.for_s.unwrap_or(0.0)
            )?,
            FaultKind::ClassChangeRequest => write!(f, "a request for another class")?,
            FaultKind::Robot => match &self.robot {
                Some(r) => write!(f, "the robot side: {r:?}")?,
                None => write!(f, "the robot side")?,
            },
        }
        match self.after {
            After::Working => write!(f, ", {:.1} s after the robot starts working", self.at_s),
            After::ArrivedWithPart => write!(
                f,
                ", {:.1} s after the robot arrives with part {}",
                self.at_s,
                self.part.unwrap_or(0)
            ),
        }
    }
}

/// The faults a session plays.
#[derive(Debug, Clone, PartialEq, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct FaultSchedule {
    #[serde(default, rename = "fault")]
    pub faults: Vec<ScheduledFault>,
}

impl FaultSchedule {
    /// The demo's faults: one camera (`s1_left`) silent for 1 s from 5.5 s after the robot starts
    /// working; a supervisor's request for another class 2 s after it starts; every camera silent
    /// for 1.2 s once the robot has brought the second part and stood 0.3 s at the handover point
    /// (the operator still works on the first).
    pub fn demo() -> Self {
        Self {
            faults: vec![
                ScheduledFault {
                    kind: FaultKind::CamerasSilent,
                    after: After::Working,
                    part: None,
                    at_s: 5.5,
                    for_s: Some(1.0),
                    cameras: vec!["s1_left".to_owned()],
                    robot: None,
                },
                ScheduledFault {
                    kind: FaultKind::ClassChangeRequest,
                    after: After::Working,
                    part: None,
                    at_s: 2.0,
                    for_s: None,
                    cameras: Vec::new(),
                    robot: None,
                },
                ScheduledFault {
                    kind: FaultKind::CamerasSilent,
                    after: After::ArrivedWithPart,
                    part: Some(2),
                    at_s: 0.3,
                    for_s: Some(1.2),
                    cameras: Vec::new(),
                    robot: None,
                },
            ],
        }
    }

    /// Parses and checks a schedule (`label` names the file in errors) against the rig's camera
    /// names.
    pub fn from_toml_str(text: &str, label: &str, cameras: &[&str]) -> Result<Self, SimError> {
        let schedule: Self = toml::from_str(text).map_err(|e| SimError::Faults {
            file: label.to_owned(),
            reason: e.to_string(),
        })?;
        schedule.check(cameras).map_err(|reason| SimError::Faults {
            file: label.to_owned(),
            reason,
        })?;
        Ok(schedule)
    }

    /// Every fault well formed: times finite and within a day, a part for `arrived_with_part`, a
    /// duration for silent cameras, and only cameras the rig has.
    fn check(&self, cameras: &[&str]) -> Result<(), String> {
        let seconds = |v: f64| v.is_finite() && (0.0..=86_400.0).contains(&v);
        for (i, f) in self.faults.iter().enumerate() {
            let at = |what: &str| format!("fault {} ({:?}): {what}", i + 1, f.kind);
            if !seconds(f.at_s) {
                return Err(at(&format!("at_s {} is not 0..=86400 s", f.at_s)));
            }
            match (f.after, f.part) {
                (After::ArrivedWithPart, None | Some(0)) => {
                    return Err(at("after = \"arrived_with_part\" needs part = 1 or more"));
                }
                (After::Working, Some(_)) => {
                    return Err(at("part is only for after = \"arrived_with_part\""));
                }
                _ => {}
            }
            if (f.kind == FaultKind::Robot) != f.robot.is_some() {
                return Err(at(
                    "robot = { kind = … } goes with kind = \"robot\", and only there",
                ));
            }
            match f.kind {
                FaultKind::Robot => {
                    if f.for_s.is_some() || !f.cameras.is_empty() {
                        return Err(at("robot takes neither for_s nor cameras"));
                    }
                    if let Some(r) = &f.robot {
                        r.check().map_err(|e| at(&e.to_string()))?;
                    }
                }
                FaultKind::CamerasSilent => {
                    if !f.for_s.is_some_and(|d| seconds(d) && d > 0.0) {
                        return Err(at("cameras_silent needs for_s > 0 (at most 86400 s)"));
                    }
                    if let Some(c) = f.cameras.iter().find(|c| !cameras.contains(&c.as_str())) {
                        return Err(at(&format!(
                            "no camera `{c}` in the rig (it has {})",
                            cameras.join(", ")
                        )));
                    }
                }
                FaultKind::ClassChangeRequest => {
                    if f.for_s.is_some() || !f.cameras.is_empty() {
                        return Err(at("class_change_request takes neither for_s nor cameras"));
                    }
                }
            }
        }
        Ok(())
    }
}

/// Which camera views a step drops.
#[derive(Debug, Clone, PartialEq, Eq, Default)]
pub enum Silenced {
    /// None.
    #[default]
    None,
    /// Every camera.
    All,
    /// These cameras, by name.
    Cameras(Vec<String>),
}

impl Silenced {
    /// Whether camera `name`'s view is dropped.
    pub fn drops(&self, name: &str) -> bool {
        match self {
            Silenced::None => false,
            Silenced::All => true,
            Silenced::Cameras(c) => c.iter().any(|n| n == name),
        }
    }
}

/// What a step of the schedule does.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct FaultStep {
    pub silenced: Silenced,
    /// A supervisor asks for another class now.
    pub class_change_request: bool,
    /// The robot side's faults that begin now.
    pub robot: Vec<RobotFault>,
}

/// A schedule being played: the cell's moments as they happen, each fault's start once it began.
#[derive(Debug, Clone)]
pub struct FaultPlayer {
    schedule: FaultSchedule,
    working_since_nanos: Option<i64>,
    /// When the robot arrived at the handover point with each part (index = part − 1).
    arrived_nanos: Vec<Option<i64>>,
    started_nanos: Vec<Option<i64>>,
}

impl FaultPlayer {
    pub fn new(schedule: FaultSchedule) -> Self {
        let n = schedule.faults.len();
        Self {
            schedule,
            working_since_nanos: None,
            arrived_nanos: Vec::new(),
            started_nanos: vec![None; n],
        }
    }

    /// The session started working at `nanos` (the first call counts).
    pub fn working(&mut self, nanos: i64) {
        self.working_since_nanos.get_or_insert(nanos);
    }

    /// The robot arrived at the handover point with part `part` (1 = the first) at `nanos` (the
    /// first call for a part counts).
    pub fn arrived_with_part(&mut self, part: u32, nanos: i64) {
        let Some(i) = (part as usize).checked_sub(1) else {
            return;
        };
        if self.arrived_nanos.len() <= i {
            self.arrived_nanos.resize(i + 1, None);
        }
        self.arrived_nanos[i].get_or_insert(nanos);
    }

    /// The schedule at step time `now_nanos`: faults whose time has come begin now.
    pub fn step(&mut self, now_nanos: i64) -> FaultStep {
        let mut out = FaultStep::default();
        let mut cameras: Vec<String> = Vec::new();
        let mut all = false;
        for (f, started) in self.schedule.faults.iter().zip(&mut self.started_nanos) {
            let moment = match f.after {
                After::Working => self.working_since_nanos,
                After::ArrivedWithPart => f
                    .part
                    .and_then(|p| (p as usize).checked_sub(1))
                    .and_then(|i| self.arrived_nanos.get(i).copied().flatten()),
            };
            let Some(moment) = moment else {
                continue;
            };
            let due = moment.saturating_add((f.at_s * 1e9).round() as i64);
            if started.is_none() && now_nanos >= due {
                *started = Some(now_nanos);
                if f.kind == FaultKind::ClassChangeRequest {
                    out.class_change_request = true;
                }
                out.robot.extend(f.robot);
            }
            let (Some(from), FaultKind::CamerasSilent) = (*started, f.kind) else {
                continue;
            };
            let until = from.saturating_add((f.for_s.unwrap_or(0.0) * 1e9).round() as i64);
            if (from..until).contains(&now_nanos) {
                if f.cameras.is_empty() {
                    all = true;
                } else {
                    cameras.extend(f.cameras.iter().cloned());
                }
            }
        }
        out.silenced = if all {
            Silenced::All
        } else if cameras.is_empty() {
            Silenced::None
        } else {
            Silenced::Cameras(cameras)
        };
        out
    }
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)]
    use super::*;

    const S: i64 = 1_000_000_000;
    const CAMERAS: [&str; 2] = ["s1_left", "s1_right"];

    #[test]
    fn the_demo_schedule_plays_at_its_moments() {
        let mut p = FaultPlayer::new(FaultSchedule::demo());
        // Nothing before the session works.
        assert_eq!(p.step(100 * S), FaultStep::default());
        p.working(10 * S);
        assert_eq!(p.step(11 * S), FaultStep::default());
        // 2 s in: the class change request, once.
        assert!(p.step(12 * S).class_change_request);
        assert!(!p.step(12 * S + 1).class_change_request);
        // 5.5–6.5 s in: s1_left silent, not before or after.
        assert_eq!(p.step(15 * S).silenced, Silenced::None);
        let s = p.step(15 * S + S / 2).silenced;
        assert!(s.drops("s1_left") && !s.drops("s1_right"));
        assert!(p.step(16 * S + S / 2 - 1).silenced.drops("s1_left"));
        assert_eq!(p.step(16 * S + S / 2).silenced, Silenced::None);
        // The second part brought at 30 s: every camera from the first step 0.3 s later, for 1.2 s.
        p.arrived_with_part(1, 20 * S);
        p.arrived_with_part(2, 30 * S);
        assert_eq!(p.step(30 * S + S / 5).silenced, Silenced::None);
        let from = 30 * S + S / 2; // the first step at or after 30.3 s
        assert_eq!(p.step(from).silenced, Silenced::All);
        assert_eq!(p.step(from + 1_199_999_999).silenced, Silenced::All);
        assert_eq!(p.step(from + 6 * S / 5).silenced, Silenced::None);
        // A later arrival of the same part changes nothing.
        p.arrived_with_part(2, 40 * S);
        assert_eq!(p.step(40 * S + S / 2).silenced, Silenced::None);
    }

    #[test]
    fn a_schedule_file_reads_and_bad_ones_say_why() {
        let text =
            "[[fault]]\nkind = \"cameras_silent\"\nafter = \"arrived_with_part\"\npart = 1\n\
                    at_s = 0.5\nfor_s = 2.0\ncameras = [\"s1_right\"]\n\n\
                    [[fault]]\nkind = \"class_change_request\"\nafter = \"working\"\nat_s = 1.0\n";
        let s = FaultSchedule::from_toml_str(text, "f.toml", &CAMERAS).unwrap();
        assert_eq!(s.faults.len(), 2);
        assert_eq!(s.faults[0].part, Some(1));
        assert_eq!(
            FaultSchedule::from_toml_str("", "empty.toml", &CAMERAS).unwrap(),
            FaultSchedule::default()
        );
        for (bad, why) in [
            (text.replace("s1_right", "s9"), "no camera `s9`"),
            (text.replace("part = 1\n", ""), "needs part = 1 or more"),
            (text.replace("for_s = 2.0\n", ""), "needs for_s > 0"),
            (text.replace("at_s = 0.5", "at_s = nan"), "at_s NaN"),
            (
                text.replace("at_s = 1.0", "at_s = 1.0\nfor_s = 3.0"),
                "neither for_s",
            ),
            (
                text.replace("kind = \"class", "kind = \"clas"),
                "unknown variant",
            ),
            (
                text.replace("at_s = 1.0", "at_s = 1.0\nwhen = 2"),
                "unknown field",
            ),
        ] {
            let e = FaultSchedule::from_toml_str(&bad, "f.toml", &CAMERAS)
                .unwrap_err()
                .to_string();
            assert!(e.contains("f.toml") && e.contains(why), "{why}: {e}");
        }
    }

    /// A robot fault is read with its facts, plays once at its time, and a malformed one is
    /// refused naming the file.
    #[test]
    fn a_robot_fault_is_read_and_played_once_and_a_bad_one_is_refused() {
        let text = "[[fault]]\nkind = \"robot\"\nafter = \"working\"\nat_s = 1.0\nrobot = { kind = \"stall\", at_fraction = 0.4 }\n";
        let s = FaultSchedule::from_toml_str(text, "f.toml", &CAMERAS).unwrap();
        assert_eq!(
            s.faults[0].robot,
            Some(RobotFault::Stall { at_fraction: 0.4 })
        );
        let mut p = FaultPlayer::new(s);
        p.working(10 * S);
        assert!(p.step(10 * S).robot.is_empty());
        assert_eq!(
            p.step(11 * S).robot,
            vec![RobotFault::Stall { at_fraction: 0.4 }]
        );
        assert!(p.step(12 * S).robot.is_empty(), "once");
        for bad in [
            text.replace("at_fraction = 0.4", "at_fraction = 1.4"),
            text.replace("\"stall\"", "\"stal\""),
            text.replace("robot = { kind = \"stall\", at_fraction = 0.4 }\n", ""),
            text.replace("kind = \"robot\"", "kind = \"class_change_request\""),
            text.replace("at_fraction = 0.4", "at_fraction = 0.4, speed = 2"),
        ] {
            let e = FaultSchedule::from_toml_str(&bad, "f.toml", &CAMERAS).unwrap_err();
            assert!(e.to_string().contains("f.toml"), "{bad}: {e}");
        }
    }
}
