//! The session state machine on the simulator with an injected clock: every transition and every
//! message sent to the robot, for a whole session with a refused change request, one camera dropped
//! (degraded), all cameras dropped (held), recovery and the session's end; plus Ctrl-C, an unapproved
//! lock, and a hold in mid-motion that must not resume on its own.
#![allow(clippy::unwrap_used, clippy::expect_used)]

use std::path::{Path, PathBuf};

mod common;

use ergocell::session::dummy::DummyRobot;
use ergocell::session::provider::FileTrajectories;
use ergocell::session::{
    AbortReason, HoldReason, Interruption, LandmarkSource, Leg, RobotCommand, RobotUnready,
    SessionEnd, SessionEvent, SessionMachine, SessionState, StopSignal, TrajectoryProvider,
};
use ergocell_cell::CellSettings;
use ergocell_perception::{CameraRig, View2};
use ergocell_robot::TrajectoryClass;
use ergocell_sim::{Operator, Phase, SessionScript, SimConfig, Simulation};
use ergocell_skeleton::Landmark;
use nalgebra::Point3;

const PERIOD: i64 = 100_000_000;

fn root() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

fn rig() -> CameraRig {
    common::reference_rig()
}

fn provider(name: &str, approve: Option<TrajectoryClass>) -> FileTrajectories {
    common::demo_provider(&format!("session-{name}"), approve)
}

fn simulation(cycles: usize) -> Simulation {
    simulation_idle(cycles, SessionScript::new(Point3::origin()).idle_secs)
}

/// [`simulation`] with the operator standing idle at the station for `idle_secs` before the first
/// reach.
fn simulation_idle(cycles: usize, idle_secs: f64) -> Simulation {
    // c2's handover point (trajectories/locks/c2.lock.toml, station frame = world here).
    let mut script = SessionScript::new(Point3::new(0.41, -0.10, 1.055));
    script.cycles = cycles;
    script.idle_secs = idle_secs;
    Simulation::new(
        rig(),
        Operator::new(1.75).unwrap(),
        script,
        SimConfig::new(7),
    )
    .unwrap()
}

/// The c2 trajectory's home (first point) and joint names.
fn home() -> (Vec<String>, Vec<f64>) {
    let approved = provider("home", Some(TrajectoryClass::C2))
        .verify(TrajectoryClass::C2)
        .unwrap();
    (
        approved.joint_names().to_vec(),
        approved.points()[0].positions_rad.clone(),
    )
}

/// A whole session of one simulated operator of `stature_m` reaching for `handover`, on the cell
/// file's defaults with `approve`'s lock approved, until it ends or `limit_nanos`.
fn operator_session(
    name: &str,
    approve: TrajectoryClass,
    stature_m: f64,
    handover: Point3<f64>,
    cycles: usize,
    seed: u64,
    limit_nanos: i64,
) -> (SessionMachine, DummyRobot, Vec<SessionEvent>) {
    let (names, home) = home();
    let mut machine = SessionMachine::from_settings(
        rig(),
        &CellSettings::default(),
        Box::new(provider(name, Some(approve))),
    )
    .unwrap();
    let mut robot = DummyRobot::new(names, home);
    let mut script = SessionScript::new(handover);
    script.cycles = cycles;
    let mut sim = Simulation::new(
        rig(),
        Operator::new(stature_m).unwrap(),
        script,
        SimConfig::new(seed),
    )
    .unwrap();
    let mut events = Vec::new();
    let mut now = 0;
    while now <= limit_nanos && machine.state() != SessionState::SessionEnded {
        let views = sim
            .step()
            .unwrap()
            .map(|t| t.frame.views)
            .unwrap_or_default();
        events.extend(machine.step(now, views, &mut robot));
        now += PERIOD;
    }
    (machine, robot, events)
}

struct Run {
    machine: SessionMachine,
    robot: DummyRobot,
    sim: Simulation,
    events: Vec<SessionEvent>,
    now: i64,
    sim_done: bool,
}

impl Run {
    fn new(name: &str, approve: Option<TrajectoryClass>, cycles: usize) -> Self {
        Self::with_settings(name, approve, cycles, &CellSettings::default())
    }

    fn with_settings(
        name: &str,
        approve: Option<TrajectoryClass>,
        cycles: usize,
        settings: &CellSettings,
    ) -> Self {
        Self::with_provider(provider(name, approve), cycles, settings)
    }

    fn with_provider(provider: FileTrajectories, cycles: usize, settings: &CellSettings) -> Self {
        let (names, home) = home();
        Self {
            machine: SessionMachine::from_settings(rig(), settings, Box::new(provider)).unwrap(),
            robot: DummyRobot::new(names, home),
            sim: simulation(cycles),
            events: Vec::new(),
            now: 0,
            sim_done: false,
        }
    }

    /// One 100 ms step of the injected clock; `keep` filters the cameras' views (faults).
    fn step(&mut self, keep: &dyn Fn(&View2) -> bool) {
        let tick = if self.sim_done {
            None
        } else {
            self.sim.step().unwrap()
        };
        let views: Vec<View2> = if let Some(tick) = tick {
            assert_eq!(tick.frame.stamp_nanos, self.now, "sim and clock agree");
            tick.frame.views.into_iter().filter(|v| keep(v)).collect()
        } else {
            self.sim_done = true;
            Vec::new()
        };
        let ev = self.machine.step(self.now, views, &mut self.robot);
        self.events.extend(ev);
        self.now += PERIOD;
    }

    fn run_until(&mut self, limit_nanos: i64, stop: &dyn Fn(&SessionMachine) -> bool) {
        while self.now <= limit_nanos && !stop(&self.machine) {
            self.step(&|_| true);
        }
    }

    fn transitions(&self) -> Vec<SessionState> {
        self.events
            .iter()
            .filter_map(|e| match e {
                SessionEvent::StateChanged { to, .. } => Some(*to),
                _ => None,
            })
            .collect()
    }

    fn first_stamp(&self, f: impl Fn(&SessionEvent) -> bool) -> Option<i64> {
        self.events.iter().find(|e| f(e)).map(|e| match e {
            SessionEvent::StateChanged { stamp_nanos, .. }
            | SessionEvent::CameraDegraded { stamp_nanos, .. }
            | SessionEvent::CameraRestored { stamp_nanos, .. }
            | SessionEvent::ClassDecided { stamp_nanos, .. }
            | SessionEvent::TrajectoryLocked { stamp_nanos, .. }
            | SessionEvent::ChangeRefused { stamp_nanos, .. }
            | SessionEvent::PartTaken { stamp_nanos, .. }
            | SessionEvent::RobotCommandSent { stamp_nanos, .. }
            | SessionEvent::Frame { stamp_nanos, .. } => *stamp_nanos,
            SessionEvent::Warning(w) => w.stamp_nanos,
        })
    }
}

/// Why the session was aborted, when it was.
fn aborted(machine: &ergocell::session::SessionMachine) -> Option<&AbortReason> {
    match &machine.summary().end {
        Some(SessionEnd::Aborted { reason }) => Some(reason),
        _ => None,
    }
}

#[test]
fn whole_session_with_refused_change_degrade_hold_recovery_and_end() {
    let mut run = Run::new("whole", Some(TrajectoryClass::C2), 3);
    // The height is measured once the operator stands at the station (4.4 s): standing idle for 10 s
    // keeps the first reach after the camera faults below, so the hold comes while the robot waits
    // at the handover point with the part.
    run.sim = simulation_idle(3, 10.0);

    // Walk in, measure, decide, verify, lock, start working.
    run.run_until(12_000_000_000, &|m| m.state() == SessionState::Working);
    assert_eq!(run.machine.state(), SessionState::Working);
    assert_eq!(
        run.transitions(),
        [
            SessionState::MeasuringHeight,
            SessionState::ClassDecided,
            SessionState::TrajectoryLocked,
            SessionState::Working
        ]
    );
    let decided = run
        .events
        .iter()
        .find_map(|e| match e {
            SessionEvent::ClassDecided {
                height_m, class, ..
            } => Some((*height_m, *class)),
            _ => None,
        })
        .unwrap();
    assert_eq!(decided.1, ergocell_ergonomics::HeightClass::C2);
    assert!((decided.0 - 1.75).abs() < 0.05, "height {}", decided.0);
    let sha = run.machine.lock_sha256().unwrap().to_owned();
    assert!(run.events.iter().any(|e| matches!(e,
        SessionEvent::TrajectoryLocked { class: TrajectoryClass::C2, lock_sha256, .. } if *lock_sha256 == sha)));
    // Exactly one command so far: the locked trajectory, home → handover, as locked.
    assert_eq!(run.robot.received.len(), 1);
    match &run.robot.received[0].1 {
        RobotCommand::Execute {
            leg: Leg::ToHandover,
            lock_sha256,
            trajectory,
        } => {
            assert_eq!(*lock_sha256, sha);
            assert_eq!(trajectory.points.len(), 100);
            assert_eq!(trajectory.joint_names[0], "joint_1");
            let wire = ergocell::messages::command_message(&run.robot.received[0].1, 123);
            assert_eq!(wire.header.stamp.to_nanos(), 0, "start on receipt");
            assert_eq!(wire.points.len(), trajectory.points.len());
            for (w, p) in wire.points.iter().zip(&trajectory.points) {
                assert_eq!(w.positions, p.positions_rad);
                assert_eq!(w.velocities, p.velocities_rad_s);
                assert!((w.time_from_start.as_secs_f64() - p.time_from_start_s).abs() < 1e-9);
            }
            let hold = ergocell::messages::command_message(
                &RobotCommand::Hold {
                    reason: HoldReason::StoppedBetweenEnds,
                },
                123,
            );
            assert!(hold.points.is_empty() && hold.joint_names.is_empty());
        }
        other => panic!("expected the locked trajectory, got {other:?}"),
    }
    let t_work = run.now - PERIOD;

    // A mid-session change request is refused, logged, and sends nothing to the robot.
    let refused = run.machine.request_class(run.now, TrajectoryClass::C3);
    assert!(
        matches!(&refused, SessionEvent::ChangeRefused { requested: TrajectoryClass::C3, reason, .. } if reason.contains("c2")),
        "{refused:?}"
    );
    assert_eq!(run.robot.received.len(), 1);
    assert_eq!(run.machine.lock_sha256(), Some(sha.as_str()));

    // Let the robot reach the handover point (5 s trajectory).
    run.run_until(t_work + 5_500_000_000, &|_| false);
    assert_eq!(run.machine.state(), SessionState::Working);

    // One camera (s1_left) silent for 1 s: degraded and reported, fusion goes on, no hold.
    let t0 = run.now;
    while run.now < t0 + 1_000_000_000 {
        run.step(&|v| v.camera != 0);
    }
    assert!(run
        .events
        .iter()
        .any(|e| matches!(e, SessionEvent::CameraDegraded { camera, .. } if camera == "s1_left")));
    assert_eq!(run.machine.state(), SessionState::Working);
    assert_eq!(
        run.robot.received.len(),
        1,
        "a degraded camera does not stop the robot"
    );
    run.run_until(t0 + 1_500_000_000, &|_| false);
    assert!(run
        .events
        .iter()
        .any(|e| matches!(e, SessionEvent::CameraRestored { camera, .. } if camera == "s1_left")));

    // Every camera silent for 1.2 s: held (goal cancelled), with the reason.
    let t1 = run.now;
    while run.now < t1 + 1_200_000_000 {
        run.step(&|_| false);
    }
    assert_eq!(run.machine.state(), SessionState::Held);
    assert_eq!(run.robot.received.len(), 2);
    let (held_at, hold) = &run.robot.received[1];
    assert!(matches!(hold, RobotCommand::Hold { .. }), "{hold:?}");
    assert!(
        *held_at <= t1 + 700_000_000,
        "held within the 500 ms bound plus one step"
    );
    // Held for the cameras, and the hold command says the same words.
    let reason = run.machine.held_for().unwrap();
    assert!(
        matches!(
            reason,
            HoldReason::CamerasLost { .. } | HoldReason::NoStereoPair { .. }
        ),
        "{reason:?}"
    );
    // the hold sent carries the machine's reason, every field
    assert!(
        matches!(hold, RobotCommand::Hold { reason: sent } if format!("{sent:?}") == format!("{reason:?}"))
    );

    // Cameras back: resumes after the 500 ms of tracking, with the lock re-verified; the robot is at
    // the handover point, so nothing new is sent.
    run.run_until(t1 + 3_000_000_000, &|m| m.state() == SessionState::Working);
    assert_eq!(run.machine.state(), SessionState::Working);
    assert_eq!(run.robot.received.len(), 2);
    assert!(run.machine.hold_reason().is_none());

    // The operator finishes the cycles and walks out: a part taken sends the robot home for the next
    // (the cell's cycle), the legs alternate; once the operator has left the robot goes home and the
    // session ends.
    run.run_until(90_000_000_000, &|m| m.state() == SessionState::SessionEnded);
    assert_eq!(run.machine.state(), SessionState::SessionEnded);
    let legs = legs_sent(&run.robot);
    assert!(legs.len() >= 2 && legs.len().is_multiple_of(2), "{legs:?}");
    assert!(legs.iter().enumerate().all(|(k, l)| *l
        == if k % 2 == 0 {
            Leg::ToHandover
        } else {
            Leg::ToHome
        }));
    assert_eq!(
        legs.len(),
        2 + 2 * run.machine.summary().parts_taken as usize
    );
    match &run.robot.received.last().unwrap().1 {
        RobotCommand::Execute {
            leg: Leg::ToHome,
            lock_sha256,
            trajectory,
        } => {
            assert_eq!(*lock_sha256, sha);
            let first = &trajectory.points[0];
            assert_eq!(first.time_from_start_s, 0.0);
            assert!(first.velocities_rad_s.iter().all(|v| *v == 0.0));
        }
        other => panic!("expected the way home, got {other:?}"),
    }
    assert_eq!(
        run.transitions(),
        [
            SessionState::MeasuringHeight,
            SessionState::ClassDecided,
            SessionState::TrajectoryLocked,
            SessionState::Working,
            SessionState::Held,
            SessionState::Working,
            SessionState::SessionEnded
        ]
    );
    let s = run.machine.summary();
    assert!(s.ended);
    assert_eq!((s.holds, s.changes_refused), (1, 1));
    assert!(s.camera_degradations >= 1);
    // RULA ran on every tracked frame.
    let assessed = run
        .events
        .iter()
        .filter(|e| {
            matches!(
                e,
                SessionEvent::Frame {
                    assessment: Some(_),
                    ..
                }
            )
        })
        .count();
    assert!(assessed > 150, "{assessed} assessed frames");
    // The session ends once the robot is at home (within the machine's at-knot tolerance), and the
    // way home's last point is home exactly.
    let (names, home) = home();
    let at_end = {
        let mut r = run.robot.clone();
        ergocell::session::RobotSink::joint_positions(&mut r, run.now, &names).unwrap()
    };
    let tolerance = ergocell::session::SessionConfig::default().at_knot_tolerance_rad;
    for (a, b) in at_end.iter().zip(&home) {
        assert!((a - b).abs() <= tolerance, "{at_end:?} vs {home:?}");
    }
    let settled = {
        let mut r = run.robot.clone();
        ergocell::session::RobotSink::joint_positions(&mut r, run.now + 10_000_000_000, &names)
            .unwrap()
    };
    for (a, b) in settled.iter().zip(&home) {
        assert!((a - b).abs() < 1e-9, "{settled:?} vs {home:?}");
    }
    // Frames were tracked before the lock and after it.
    let first_frame = run
        .first_stamp(|e| matches!(e, SessionEvent::Frame { .. }))
        .unwrap();
    assert!(first_frame < t_work);
}

#[test]
fn ctrl_c_holds_the_robot_and_ends_the_session() {
    let mut run = Run::new("ctrlc", Some(TrajectoryClass::C2), 1);
    run.run_until(12_000_000_000, &|m| m.state() == SessionState::Working);
    assert_eq!(run.machine.state(), SessionState::Working);
    run.run_until(run.now + 1_000_000_000, &|_| false);
    let ev = run.machine.shutdown(
        run.now,
        &mut run.robot,
        ergocell::session::Interruption::Stopped {
            signal: ergocell::session::StopSignal::Interrupt,
        },
    );
    assert!(matches!(
        ev.last(),
        Some(SessionEvent::StateChanged {
            to: SessionState::SessionEnded,
            ..
        })
    ));
    assert!(matches!(
        run.robot.received.last(),
        Some((
            _,
            RobotCommand::Hold {
                reason: HoldReason::Ended {
                    end: SessionEnd::Interrupted {
                        by: Interruption::Stopped {
                            signal: StopSignal::Interrupt
                        }
                    }
                }
            }
        ))
    ));
    // Nothing moves after the end.
    let n = run.robot.received.len();
    run.run_until(run.now + 2_000_000_000, &|_| false);
    assert_eq!(run.robot.received.len(), n);
}

#[test]
fn an_unapproved_lock_never_moves_the_robot() {
    let mut run = Run::new("unapproved", None, 1);
    run.run_until(12_000_000_000, &|m| m.state() == SessionState::SessionEnded);
    assert_eq!(run.machine.state(), SessionState::SessionEnded);
    assert!(run
        .robot
        .received
        .iter()
        .all(|(_, c)| matches!(c, RobotCommand::Hold { .. })));
    assert!(
        matches!(
            aborted(&run.machine),
            Some(AbortReason::NotVerified {
                class: TrajectoryClass::C2,
                ..
            })
        ),
        "{}",
        run.machine.summary().end_reason
    );
    assert!(run.machine.lock_sha256().is_none());
}

/// `ergocell run`'s session on a cell where a hostile user appended her key to the approvers,
/// loosened the cell, re-locked and approved c2 herself: the session ends without moving the robot,
/// saying the approvers' files are not what the site's authority signed.
#[test]
fn the_mallory_attack_never_moves_the_robot() {
    let Some(cell) = common::AnchoredCell::new("session-mallory") else {
        return;
    };
    let (code, out, err) = cell.ergocell(&["trajectories", "lock", "--class", "c2"]);
    assert_eq!(code, 0, "{out}{err}");
    cell.mallory_attack(TrajectoryClass::C2);
    let mut run = Run::with_provider(cell.provider(), 1, &CellSettings::default());
    run.run_until(12_000_000_000, &|m| m.state() == SessionState::SessionEnded);
    assert_eq!(run.machine.state(), SessionState::SessionEnded);
    assert!(run
        .robot
        .received
        .iter()
        .all(|(_, c)| matches!(c, RobotCommand::Hold { .. })));
    // Not verified because the trust list is not what the site's authority signed.
    let reason = &run.machine.summary().end_reason;
    let Some(AbortReason::NotVerified {
        class: TrajectoryClass::C2,
        error: ergocell::session::ProviderError::TrustList { cause },
    }) = aborted(&run.machine)
    else {
        panic!("{reason}");
    };
    assert!(
        matches!(
            cause.as_ref(),
            ergocell::trust_anchor::TrustListError::Authority(
                ergocell_robot::authority::AuthorityError::Edited
            )
        ),
        "{reason}"
    );
}

#[test]
fn a_hold_in_mid_motion_does_not_resume_by_itself() {
    let mut run = Run::new("midmotion", Some(TrajectoryClass::C2), 3);
    run.run_until(12_000_000_000, &|m| m.state() == SessionState::Working);
    // 2 s into the 5 s trajectory, every camera goes silent.
    run.run_until(run.now + 2_000_000_000, &|_| false);
    let t = run.now;
    while run.now < t + 1_000_000_000 {
        run.step(&|_| false);
    }
    assert_eq!(run.machine.state(), SessionState::Held);
    // Tracking back for 2 s: still held, and the reason says why.
    run.run_until(run.now + 2_000_000_000, &|_| false);
    assert_eq!(run.machine.state(), SessionState::Held);
    assert!(
        matches!(run.machine.held_for(), Some(HoldReason::StoppedBetweenEnds)),
        "{:?}",
        run.machine.hold_reason()
    );
    assert_eq!(run.robot.received.len(), 2, "no command after the hold");
}

#[test]
fn views_round_trip_through_the_camera_message() {
    let rig = rig();
    let mut sim = simulation(1);
    let tick = (0..60).filter_map(|_| sim.step().unwrap()).last().unwrap();
    for v in &tick.frame.views {
        let m = ergocell::messages::landmarks_message(&rig, v);
        let back = ergocell::messages::view_from_message(&rig, &m).unwrap();
        assert_eq!(back.camera, v.camera);
        assert_eq!(back.observed_count(), v.observed_count());
        for (a, b) in back.keypoints().iter().zip(v.keypoints()) {
            if let (Some(a), Some(b)) = (a, b) {
                assert!((a.pixel() - b.pixel()).norm() < 1e-3);
            }
        }
    }
    let mut source = ergocell::session::dummy::ScriptedSource::default();
    assert!(source.poll(0).unwrap().is_none());
    // Malformed messages are rejected whole, each with its reason (the CI's message storm sends
    // all three): a NaN pixel on a landmark said to be present is a broken node, not an empty view.
    let v = &tick.frame.views[0];
    let good = ergocell::messages::landmarks_message(&rig, v);
    let mut nan = good.clone();
    nan.x_px[11] = f32::NAN;
    nan.presence[11] = 1.0;
    nan.visibility[11] = 0.9;
    let mut short = good.clone();
    short.x_px.truncate(5);
    let mut stranger = good.clone();
    stranger.camera_id = "no_such_camera".into();
    for (m, needle) in [
        (&nan, "left_shoulder present at a non-finite pixel"),
        (&short, "5 landmarks"),
        (&stranger, "unknown camera `no_such_camera`"),
    ] {
        let e = ergocell::messages::view_from_message(&rig, m).unwrap_err();
        assert!(e.to_string().contains(needle), "{e}");
    }
    // a node whose images are not the calibrated image: refused, unless its geometry is declared,
    // then mapped into the calibrated image (here the rig's 1280x720 shown in a 1920x1080 frame)
    let mut scaled = good.clone();
    scaled.image_width = 1920;
    scaled.image_height = 1080;
    for x in &mut scaled.x_px {
        *x = (*x + 0.5) * 1.5 - 0.5;
    }
    for y in &mut scaled.y_px {
        *y = (*y + 0.5) * 1.5 - 0.5;
    }
    let e = ergocell::messages::view_from_message(&rig, &scaled).unwrap_err();
    assert!(
        e.to_string()
            .contains("1920x1080 but it was calibrated at 1280x720"),
        "{e}"
    );
    let mut declared = vec![None; rig.len()];
    declared[v.camera] = Some(ergocell_perception::video_geometry::VideoGeometry::Fit);
    let mapped = ergocell::messages::view_from_message_with(&rig, &declared, &scaled).unwrap();
    let plain = ergocell::messages::view_from_message(&rig, &good).unwrap();
    for (a, b) in mapped.keypoints().iter().zip(plain.keypoints()) {
        match (a, b) {
            (Some(a), Some(b)) => assert!((a.pixel() - b.pixel()).norm() < 1e-3),
            (a, b) => assert_eq!(a.is_some(), b.is_some()),
        }
    }
    // an empty message (nobody seen) says nothing about pixels: accepted whatever its size
    let mut nobody = ergocell::messages::landmarks_message(
        &rig,
        &ergocell_perception::View2::empty(v.camera, 0),
    );
    nobody.image_width = 1;
    assert_eq!(
        ergocell::messages::view_from_message(&rig, &nobody)
            .unwrap()
            .observed_count(),
        0
    );
    // an unobserved landmark (NaN, presence 0) is simply not seen
    let mut unseen = good.clone();
    unseen.x_px[11] = f32::NAN;
    unseen.presence[11] = 0.0;
    let back = ergocell::messages::view_from_message(&rig, &unseen).unwrap();
    assert!(back
        .get(ergocell_skeleton::Landmark::LeftShoulder)
        .is_none());
}

#[test]
fn same_seed_same_clock_same_session() {
    let run = |name: &str| {
        let mut r = Run::new(name, Some(TrajectoryClass::C2), 1);
        r.run_until(8_000_000_000, &|_| false);
        (r.events, r.robot.received)
    };
    let (a_events, a_robot) = run("det-a");
    let (b_events, b_robot) = run("det-b");
    assert!(a_events.len() > 80);
    // Every field of every event and command, floats to the last bit (Debug prints them exactly).
    assert_eq!(format!("{a_events:?}"), format!("{b_events:?}"));
    assert_eq!(format!("{a_robot:?}"), format!("{b_robot:?}"));
}

#[test]
fn one_camera_of_every_pair_dropped_holds_although_frames_are_fresh() {
    let mut run = Run::new("halfpairs", Some(TrajectoryClass::C2), 3);
    run.run_until(12_000_000_000, &|m| m.state() == SessionState::Working);
    run.run_until(run.now + 5_500_000_000, &|_| false); // at the handover point
    let rig = rig();
    let lefts: Vec<usize> = rig.pairs().iter().map(|p| p.left).collect();
    assert_eq!(lefts.len(), 3);
    let t = run.now;
    while run.now < t + 1_000_000_000 {
        run.step(&|v| !lefts.contains(&v.camera));
    }
    assert_eq!(run.machine.state(), SessionState::Held);
    assert_eq!(run.machine.pairs_tracking(), 0);
    assert_eq!(run.machine.cameras_fresh(), 3);
    assert!(matches!(
        run.robot.received.last(),
        Some((
            _,
            RobotCommand::Hold {
                reason: HoldReason::NoStereoPair { cameras_fresh: 3 }
            }
        ))
    ));
    // One pair back is enough.
    let first_left = lefts[0];
    let t = run.now;
    while run.now < t + 1_500_000_000 {
        run.step(&|v| v.camera == first_left || !lefts.contains(&v.camera));
    }
    assert_eq!(run.machine.state(), SessionState::Working);
    assert_eq!(run.machine.pairs_tracking(), 1);
}

#[test]
fn a_camera_silent_from_the_start_is_reported_and_the_session_goes_on() {
    let mut run = Run::new("deadcam", Some(TrajectoryClass::C2), 1);
    while run.now < 12_000_000_000 && run.machine.state() != SessionState::Working {
        run.step(&|v| v.camera != 5);
    }
    assert_eq!(run.machine.state(), SessionState::Working);
    let degraded: Vec<(i64, &str)> = run
        .events
        .iter()
        .filter_map(|e| match e {
            SessionEvent::CameraDegraded {
                stamp_nanos,
                camera,
                why,
            } => {
                assert!(why.contains("since the session started"), "{why}");
                Some((*stamp_nanos, camera.as_str()))
            }
            _ => None,
        })
        .collect();
    assert_eq!(degraded, [(600_000_000, "s3_right")]);
    assert_eq!(run.machine.cameras_fresh(), 5);
    assert_eq!(run.machine.pairs_tracking(), 2);
}

#[test]
fn an_operator_outside_every_validated_stature_is_never_given_a_class() {
    // 1.35 m is below the statures any trajectory serves (c1's: 1.44–1.74 m, trajectories/c1.toml):
    // no class is chosen although c1's lock is approved, the session ends at the height timeout
    // with the reason, and the robot never moves.
    let (machine, robot, events) = operator_session(
        "short-operator",
        TrajectoryClass::C1,
        1.35,
        Point3::new(0.394, -0.10, 0.963),
        1,
        11,
        30_000_000_000,
    );
    assert!(
        !events
            .iter()
            .any(|e| matches!(e, SessionEvent::ClassDecided { .. })),
        "no class for an operator no trajectory serves"
    );
    assert_eq!(machine.state(), SessionState::SessionEnded);
    let reason = &machine.summary().end_reason;
    assert!(reason.contains("no class serves this operator"), "{reason}");
    assert!(machine.lock_sha256().is_none());
    assert!(robot
        .received
        .iter()
        .all(|(_, c)| matches!(c, RobotCommand::Hold { .. })));
}

/// A provider whose trajectory file is narrowed after the session started (someone edits
/// `trajectories/c2.toml` mid-session): the bounds the height decision was given are not the ones
/// at lock time, and the session's own check must still refuse to serve outside them.
struct NarrowedAfterStart {
    inner: FileTrajectories,
    calls: usize,
}

impl TrajectoryProvider for NarrowedAfterStart {
    fn verify(
        &mut self,
        class: TrajectoryClass,
    ) -> Result<ergocell_robot::ApprovedTrajectory, ergocell::session::ProviderError> {
        self.inner.verify(class)
    }

    fn stature_bounds_m(
        &mut self,
        class: TrajectoryClass,
    ) -> Result<(f64, f64), ergocell::session::ProviderError> {
        self.calls += 1;
        // The first three answers are the session's start (one per class); later ones are narrow.
        if self.calls > 3 {
            return Ok((1.80, 1.82));
        }
        self.inner.stature_bounds_m(class)
    }
}

#[test]
fn the_session_never_serves_outside_the_statures_it_verifies_at_lock_time() {
    let (names, home) = home();
    let mut machine = SessionMachine::from_settings(
        rig(),
        &CellSettings::default(),
        Box::new(NarrowedAfterStart {
            inner: provider("narrowed", Some(TrajectoryClass::C2)),
            calls: 0,
        }),
    )
    .unwrap();
    let mut robot = DummyRobot::new(names, home);
    let mut sim = simulation(1);
    let mut events = Vec::new();
    let mut now = 0;
    while now <= 20_000_000_000 && machine.state() != SessionState::SessionEnded {
        let views = sim
            .step()
            .unwrap()
            .map(|t| t.frame.views)
            .unwrap_or_default();
        events.extend(machine.step(now, views, &mut robot));
        now += PERIOD;
    }
    assert!(events
        .iter()
        .any(|e| matches!(e, SessionEvent::ClassDecided { .. })));
    assert_eq!(machine.state(), SessionState::SessionEnded);
    let reason = &machine.summary().end_reason;
    let Some(AbortReason::StatureOutsideServed {
        class: TrajectoryClass::C2,
        interval_m,
        served_m,
    }) = aborted(&machine)
    else {
        panic!("{reason}");
    };
    assert!(
        interval_m[0] < served_m[0] || interval_m[1] > served_m[1],
        "{interval_m:?} inside {served_m:?}"
    );
    assert!(machine.lock_sha256().is_none());
    assert!(robot
        .received
        .iter()
        .all(|(_, c)| matches!(c, RobotCommand::Hold { .. })));
}

#[test]
fn an_operator_measured_while_walking_in_has_not_left_the_station() {
    // At 30 Hz the height is decided before the operator reaches the station (more frames sooner).
    // Found in the interop run: the operator, still 1.3 m out, counted as "departed", and the robot
    // was sent home as soon as it reached the handover point. The robot must wait for them.
    const PERIOD_30HZ: i64 = 33_333_333;
    let (names, home) = home();
    let mut machine = SessionMachine::from_settings(
        rig(),
        &CellSettings::default(),
        Box::new(provider("walking-in", Some(TrajectoryClass::C2))),
    )
    .unwrap();
    let mut robot = DummyRobot::new(names, home);
    let mut script = SessionScript::new(Point3::new(0.41, -0.10, 1.055));
    script.cycles = 2;
    let mut config = SimConfig::new(42);
    config.frame_period_nanos = PERIOD_30HZ;
    let mut sim = Simulation::new(rig(), Operator::new(1.75).unwrap(), script, config).unwrap();
    let mut events = Vec::new();
    let mut walk_out_from = None;
    let mut phase_at_decision = None;
    let mut now = 0;
    while now <= 60_000_000_000 && machine.state() != SessionState::SessionEnded {
        let tick = sim.step().unwrap();
        let phase = tick.as_ref().map(|t| t.truth.phase);
        if walk_out_from.is_none() && phase == Some(ergocell_sim::Phase::WalkOut) {
            walk_out_from = Some(now);
        }
        let views = tick.map(|t| t.frame.views).unwrap_or_default();
        let ev = machine.step(now, views, &mut robot);
        if phase_at_decision.is_none()
            && ev
                .iter()
                .any(|e| matches!(e, SessionEvent::ClassDecided { .. }))
        {
            phase_at_decision = phase;
            // Published and recorded session states carry the state as of each event, in order,
            // although the machine is already working at the end of this step.
            let states: Vec<String> =
                ergocell::messages::session_state_messages(&machine, now, &ev)
                    .into_iter()
                    .map(|m| m.state)
                    .collect();
            let order = [
                "measuring_height",
                "class_decided",
                "trajectory_locked",
                "working",
            ];
            let rank: Vec<usize> = states
                .iter()
                .map(|s| order.iter().position(|o| o == s).unwrap())
                .collect();
            assert!(rank.windows(2).all(|w| w[0] <= w[1]), "{states:?}");
            assert_eq!(rank.first(), Some(&0), "{states:?}");
            assert_eq!(rank.last(), Some(&3), "{states:?}");
        }
        events.extend(ev);
        now += PERIOD_30HZ;
    }
    assert_eq!(
        phase_at_decision,
        Some(ergocell_sim::Phase::WalkIn),
        "the scenario: decided while walking in"
    );
    // The robot goes home only for the next part (a part taken in that step) or once the operator has
    // left: never because the operator, still walking in, counted as gone.
    let taken_at: Vec<i64> = events
        .iter()
        .filter_map(|e| match e {
            SessionEvent::PartTaken { stamp_nanos, .. } => Some(*stamp_nanos),
            _ => None,
        })
        .collect();
    let home_sent = events.iter().find_map(|e| match e {
        SessionEvent::RobotCommandSent {
            stamp_nanos,
            command:
                RobotCommand::Execute {
                    leg: ergocell::session::Leg::ToHome,
                    ..
                },
        } if !taken_at.contains(stamp_nanos) => Some(*stamp_nanos),
        _ => None,
    });
    let walk_out_from = walk_out_from.unwrap();
    assert!(
        home_sent.is_some_and(|t| t >= walk_out_from),
        "robot sent home at {:?} s, the operator leaves at {:.1} s; session: {}",
        home_sent.map(|t| t as f64 * 1e-9),
        walk_out_from as f64 * 1e-9,
        machine.summary().end_reason
    );
    assert_eq!(machine.state(), SessionState::SessionEnded);
}

/// `[station]` of the cell file reaches the session: the same operator, who works at the world
/// origin, is measured at a station at the origin and leaves it (the session ends, the robot home);
/// with the station 3 m away they never stood there, so their height is never measured, no class is
/// decided and the robot never moves.
#[test]
fn a_station_offset_in_cell_toml_moves_where_the_operator_is_measured() {
    let shipped = std::fs::read_to_string(root().join("config/cell.toml")).unwrap();
    let moved = shipped.replace("xyz_m = [0.0, 0.0, 0.0]", "xyz_m = [3.0, 0.0, 0.0]");
    assert_ne!(
        moved, shipped,
        "the shipped station line changed: update this test"
    );
    let settings = CellSettings::from_toml_str(&moved, "cell.toml with the station moved").unwrap();
    assert_eq!(settings.session.station_xy_m, [3.0, 0.0]);

    let mut at_origin = Run::new("station-origin", Some(TrajectoryClass::C2), 1);
    let mut away = Run::with_settings("station-away", Some(TrajectoryClass::C2), 1, &settings);
    for run in [&mut at_origin, &mut away] {
        run.run_until(60_000_000_000, &|m| m.state() == SessionState::SessionEnded);
    }
    assert_eq!(at_origin.machine.state(), SessionState::SessionEnded);
    assert!(
        matches!(
            at_origin.machine.summary().end,
            Some(SessionEnd::OperatorLeft { .. })
        ),
        "{}",
        at_origin.machine.summary().end_reason
    );
    // Nobody stood at the station 3 m away: the session ends undecided, saying why.
    assert_eq!(away.machine.state(), SessionState::SessionEnded);
    let reason = &away.machine.summary().end_reason;
    let Some(AbortReason::HeightUndecided {
        upright_frames: 0,
        missing,
        ..
    }) = aborted(&away.machine)
    else {
        panic!("{reason}");
    };
    assert!(missing.contains("away from the station"), "{reason}");
    // The height is measured only where the station is (the operator gate's zone): the operator never
    // stood 3 m away, so no class was decided there and the robot never moved.
    let class = |r: &Run| r.machine.summary().class;
    assert!(class(&at_origin).is_some());
    assert_eq!(class(&away), None);
    assert!(away
        .robot
        .received
        .iter()
        .all(|(_, c)| !matches!(c, RobotCommand::Execute { .. })));
}

#[test]
fn the_shipped_provider_finds_the_shipped_files_by_their_repository_paths() {
    // With no folders given the provider looks its files up in the binary by relative path
    // (`trajectories/c2.toml`, `trajectories/locks/c2.lock.toml`): the layout must keep building
    // exactly those keys. Approvals are still read from, and written to, the folder given.
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("session-shipped");
    let _ = std::fs::remove_dir_all(&dir);
    let shipped = ergocell::session::provider::with_shipped_defaults(None, None, &dir);
    for class in TrajectoryClass::ALL {
        let key = format!("trajectories/locks/{class}.lock.toml");
        assert_eq!(
            shipped.lock_text(class).unwrap(),
            ergocell::shipped::file(Path::new(&key)).unwrap(),
            "{key}"
        );
    }
    // The shipped approvers trust no one: a demo trusts its own throwaway key (and re-locks under it,
    // after checking the shipped locks hold the same trajectories).
    let shipped = shipped.with_demo_key(&[7; 32]).unwrap();
    for class in TrajectoryClass::ALL {
        assert!(
            shipped.stature_bounds_m(class).is_ok(),
            "trajectories/{class}.toml"
        );
        // No approval yet: refused by the lock's verification, naming the class, not approved.
        match shipped.verify(class) {
            Err(ergocell::session::ProviderError::NotVerified { failure, witness }) => {
                assert_eq!(failure.class, class);
                assert!(
                    matches!(
                        failure.problems.as_slice(),
                        [ergocell_robot::RobotError::NotApproved { .. }]
                    ),
                    "{failure}"
                );
                assert!(witness.is_none(), "the demo keeps no witness");
            }
            other => panic!("{class}: {other:?}"),
        }
        ergocell::session::provider::approve_for_demo(&shipped, class, "2026-01-01T00:00:00Z")
            .unwrap();
        assert!(dir.join(format!("{class}.toml")).exists());
        assert_eq!(shipped.verify(class).unwrap().class(), class);
    }
}

/// An operator the cell cannot class for certain is served at once: a 1.69 m operator's stated
/// interval (± 2σ ≈ 4.5 cm) straddles the 1.68 m boundary, and the cell serves them with the class of
/// the lower expected RULA there (the shipped curves: c1), saying how probable that class is.
#[test]
fn an_operator_whose_interval_straddles_a_boundary_is_served_at_once() {
    // The operator reaches where c1's robot brings the part (the reference cell's station is the
    // world's origin).
    let c1 = ergocell_robot::TrajectorySpec::from_toml_str(
        &std::fs::read_to_string(root().join("trajectories/c1.toml")).unwrap(),
    )
    .unwrap()
    .handover;
    let (machine, robot, events) = operator_session(
        "near-boundary-operator",
        TrajectoryClass::C1,
        1.69,
        Point3::new(c1.forward_m, c1.lateral_m, c1.height_m),
        1,
        13,
        40_000_000_000,
    );
    let measuring = events
        .iter()
        .find_map(|e| match e {
            SessionEvent::StateChanged {
                to: SessionState::MeasuringHeight,
                stamp_nanos,
                ..
            } => Some(*stamp_nanos),
            _ => None,
        })
        .unwrap();
    let (decided_at, class, probability) = events
        .iter()
        .find_map(|e| match e {
            SessionEvent::ClassDecided {
                stamp_nanos,
                class,
                probability,
                ..
            } => Some((*stamp_nanos, *class, *probability)),
            _ => None,
        })
        .expect("a near-boundary operator is served");
    assert_eq!(class.name(), "c1");
    assert!(
        (0.05..0.95).contains(&probability),
        "across a boundary the class is not certain: {probability}"
    );
    // Decided within the walk in and a few seconds at the station, not at a 20 s timeout.
    assert!(
        decided_at - measuring < 10_000_000_000,
        "{measuring} → {decided_at}"
    );
    assert!(
        events.iter().any(|e| matches!(
            e,
            SessionEvent::TrajectoryLocked {
                class: TrajectoryClass::C1,
                ..
            }
        )),
        "{}",
        machine.summary().end_reason
    );
    assert!(robot
        .received
        .iter()
        .any(|(_, c)| !matches!(c, RobotCommand::Hold { .. })));
}

#[test]
fn a_robot_that_is_not_ready_is_held_before_its_first_goal_and_the_session_resumes_once_it_is() {
    let mut run = Run::new("unready", Some(TrajectoryClass::C2), 1);
    run.machine
        .set_robot_unready(Some(RobotUnready::DriverNotConfigured));
    run.run_until(15_000_000_000, &|m| m.state() == SessionState::Held);
    assert_eq!(run.machine.state(), SessionState::Held);
    assert!(run.machine.lock_sha256().is_some(), "locked, then held");
    // Held for 2 s: no goal sent, the reason kept.
    run.run_until(run.now + 2_000_000_000, &|_| false);
    assert!(run
        .robot
        .received
        .iter()
        .all(|(_, c)| matches!(c, RobotCommand::Hold { .. })));
    assert!(matches!(
        run.machine.held_for(),
        Some(HoldReason::RobotNotReady {
            unready: RobotUnready::DriverNotConfigured
        })
    ));
    // Ready: the session resumes from home and sends the first leg.
    run.machine.set_robot_unready(None);
    run.run_until(run.now + 2_000_000_000, &|m| {
        m.state() == SessionState::Working
    });
    assert_eq!(run.machine.state(), SessionState::Working);
    assert!(matches!(
        run.robot.received.last(),
        Some((_, RobotCommand::Execute { .. }))
    ));
    // Unready again mid-leg (joint states stale): held at once.
    run.step(&|_| true);
    let stale = RobotUnready::JointStatesStale { timeout_s: 0.1 };
    run.machine.set_robot_unready(Some(stale.clone()));
    run.step(&|_| true);
    assert_eq!(run.machine.state(), SessionState::Held);
    assert!(matches!(
        run.machine.held_for(),
        Some(HoldReason::RobotNotReady { unready }) if *unready == stale
    ));
    assert!(matches!(
        run.robot.received.last(),
        Some((_, RobotCommand::Hold {
            reason: HoldReason::RobotNotReady { unready }
        })) if *unready == stale
    ));
}

/// A session of the cell's cycle: c2's lock, the operator's script waiting between handovers as long
/// as the robot's round trip (as the demo's does), `cycles` reaches. With `hide_hands`, once the
/// robot waits at the handover point and the operator's hand has held the part (the script's hold
/// phase is over), no camera reports either hand's wrist, index or pinky any more.
fn cycle_session(
    name: &str,
    seed: u64,
    cycles: usize,
    hide_hands: bool,
) -> (
    SessionMachine,
    DummyRobot,
    Simulation,
    Vec<SessionEvent>,
    Point3<f64>,
) {
    let (names, home) = home();
    let settings = CellSettings::default();
    let cfg = settings.session;
    let mut machine = SessionMachine::from_settings(
        rig(),
        &settings,
        Box::new(provider(name, Some(TrajectoryClass::C2))),
    )
    .unwrap();
    let mut robot = DummyRobot::new(names, home);
    // c2's handover point as locked (station frame = world in the shipped cell).
    let lock = std::fs::read_to_string(root().join("trajectories/locks/c2.lock.toml")).unwrap();
    let lock = ergocell_robot::LockFile::from_toml_str(TrajectoryClass::C2, &lock).unwrap();
    let [hx, hy, hz] = lock.summary.handover_station_m;
    let handover = Point3::new(hx, hy, hz);
    let leg_nanos = (lock.trajectory.point.last().unwrap().time_s * 1e9) as i64;
    let mut script = SessionScript::new(handover);
    script.cycles = cycles;
    script.rest_secs =
        2.0 * leg_nanos as f64 * 1e-9 + cfg.next_part_after_nanos as f64 * 1e-9 + 1.0;
    // The class is decided after 30 upright frames at the station (3 s at this test's 10 Hz) and
    // the first leg takes the lock's 5 s: the operator reaches once the part is there.
    script.idle_secs += 2.0;
    let limit = ((script.duration_secs() + 30.0) * 1e9) as i64;
    let mut sim = Simulation::new(
        rig(),
        Operator::new(1.75).unwrap(),
        script,
        SimConfig::new(seed),
    )
    .unwrap();
    let mut hiding = false;
    let mut events = Vec::new();
    let mut now = 0;
    while now <= limit && machine.state() != SessionState::SessionEnded {
        let mut views = match sim.step().unwrap() {
            Some(tick) => {
                let first_leg_at = robot.received.first().map(|(t, _)| *t);
                hiding |= hide_hands
                    && matches!(tick.truth.phase, Phase::Return { .. })
                    && first_leg_at.is_some_and(|t| now - t > leg_nanos);
                tick.frame.views
            }
            None => Vec::new(),
        };
        if hiding {
            for v in &mut views {
                for m in HANDS.into_iter().flatten() {
                    v.set(m, None);
                }
            }
        }
        events.extend(machine.step(now, views, &mut robot));
        now += PERIOD;
    }
    (machine, robot, sim, events, handover)
}

/// The landmarks of each hand's palm centre (wrist, index, pinky), left then right.
const HANDS: [[Landmark; 3]; 2] = [
    [
        Landmark::LeftWrist,
        Landmark::LeftIndex,
        Landmark::LeftPinky,
    ],
    [
        Landmark::RightWrist,
        Landmark::RightIndex,
        Landmark::RightPinky,
    ],
];

fn legs_sent(robot: &DummyRobot) -> Vec<Leg> {
    robot
        .received
        .iter()
        .filter_map(|(_, c)| match c {
            RobotCommand::Execute { leg, .. } => Some(*leg),
            RobotCommand::Hold { .. } => None,
        })
        .collect()
}

/// The cell's cycle (#15): the robot brings a part to the handover point, waits there until the
/// cameras see the operator take it (a hand at the point, then both hands away), goes home, brings
/// the next part, and so on until the operator leaves; then home and the session ends.
#[test]
fn the_cell_cycles_home_handover_part_taken_home_until_the_operator_leaves() {
    let cfg = CellSettings::default().session;
    let (machine, robot, sim, events, handover) = cycle_session("cycle", 11, 3, false);
    assert_eq!(machine.state(), SessionState::SessionEnded);
    assert!(machine.summary().ended, "{}", machine.summary().end_reason);

    // The legs alternate, starting and ending at home: a round trip per part taken, the next part
    // brought out after the third, and home once the operator left.
    let legs = legs_sent(&robot);
    assert_eq!(legs.len(), 8, "{legs:?}");
    for (k, leg) in legs.iter().enumerate() {
        let expected = if k % 2 == 0 {
            Leg::ToHandover
        } else {
            Leg::ToHome
        };
        assert_eq!(*leg, expected, "leg {k} of {legs:?}");
    }
    let taken: Vec<(i64, u32, f64)> = events
        .iter()
        .filter_map(|e| match e {
            SessionEvent::PartTaken {
                stamp_nanos,
                part,
                closest_m,
                ..
            } => Some((*stamp_nanos, *part, *closest_m)),
            _ => None,
        })
        .collect();
    // Each of the operator's three reaches took a part, in order; each hand came close.
    assert_eq!(
        taken.iter().map(|t| t.1).collect::<Vec<_>>(),
        [1, 2, 3],
        "{taken:?}"
    );
    assert_eq!(machine.summary().parts_taken, 3);
    assert!(taken.iter().all(|t| t.2 <= cfg.take_radius_m), "{taken:?}");
    // Safety: the robot left the handover point only when the operator's hands (the truth, not the
    // cameras) were away from it, never while a hand was at the part; and the way home was the next
    // command, sent in the same step.
    for (stamp, part, _) in &taken {
        let truth = sim.truth_at(*stamp).unwrap();
        for marks in HANDS {
            let palm = marks
                .iter()
                .map(|m| truth.skeleton.position(*m).unwrap().coords)
                .sum::<nalgebra::Vector3<f64>>()
                / 3.0;
            let d = (Point3::from(palm) - handover).norm();
            assert!(
                d > cfg.take_radius_m,
                "part {part}: the robot left with a hand {d:.3} m from the handover point"
            );
        }
        let next = robot.received.iter().find(|(t, _)| t >= stamp);
        assert!(
            matches!(next, Some((t, RobotCommand::Execute { leg: Leg::ToHome, .. })) if t == stamp),
            "part {part}: {next:?}"
        );
    }
}

/// A hand the cameras lose at the part does not count as away: the same session with the hands
/// hidden from the end of the first hold on takes no part, and the robot waits at the handover point
/// (until the operator leaves, then it goes home).
#[test]
fn a_hand_lost_from_view_at_the_part_does_not_send_the_robot_home_for_the_next() {
    let (machine, robot, _, events, _) = cycle_session("cycle-lost-hand", 11, 3, true);
    assert!(!events
        .iter()
        .any(|e| matches!(e, SessionEvent::PartTaken { .. })));
    assert_eq!(machine.summary().parts_taken, 0);
    assert_eq!(legs_sent(&robot), [Leg::ToHandover, Leg::ToHome]);
    assert!(machine.summary().ended, "{}", machine.summary().end_reason);
}

/// The approvals' time is checked against the provider's clock, injected: an approval dated
/// 2026-01-01 is refused by a clock two days before it (more than the day of skew a signing
/// machine's clock may have) and accepted by one the day after.
#[test]
fn an_approvals_time_is_checked_against_the_injected_clock() {
    fn two_days_before() -> i64 {
        1_767_052_800 // 2025-12-30T00:00:00Z
    }
    fn the_day_after() -> i64 {
        1_767_312_000 // 2026-01-02T00:00:00Z
    }
    let early =
        common::demo_provider("clock-early", Some(TrajectoryClass::C2)).with_clock(two_days_before);
    let refused = early.verify(TrajectoryClass::C2);
    assert!(
        matches!(
            &refused,
            Err(ergocell::session::ProviderError::ApprovalTime { .. })
        ),
        "{refused:?}"
    );
    let late =
        common::demo_provider("clock-late", Some(TrajectoryClass::C2)).with_clock(the_day_after);
    assert!(late.verify(TrajectoryClass::C2).is_ok());
}
