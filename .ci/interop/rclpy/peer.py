#!/usr/bin/env python3
"""A real ROS 2 peer: ROS 2 Kilted's rclpy on Fast DDS (rmw_fastrtps_cpp), from PyPI wheels, with
ergocell_msgs generated for it by rosidl (`setup.sh`). Plays the cell's other side for `ergocell run`:

  * six rclpy camera nodes' worth of publishers: each `/ergocell/camera/<id>/landmarks` message of an
    MCAP recording (from `ergocell demo`), deserialised by rclpy itself, re-stamped to now, at the
    recorded pace (sensor data QoS: best effort, keep last 5);
  * the controller: `/joint_states` at 50 Hz from the lock's home, following each JointTrajectory by
    linear interpolation, stopping where it is on an empty one (a hold);
  * readers of `/ergocell/session_events` (every event, reliable, transient local, depth 100),
    `/ergocell/ergonomics` and `/ergocell/warnings`; and a late joiner on `/ergocell/session_state`
    (transient local, keep last 1), created once the robot works.

Prints a JSON report on stdout.
Usage: peer.py <recording.mcap> <lock.toml> <timeout s>
"""

import json
import sys
import time
import tomllib

import rclpy
from builtin_interfaces.msg import Time
from ergocell_msgs.msg import CameraLandmarks, ErgonomicState, PostureWarning, SessionState
from mcap.reader import make_reader
from rclpy.qos import DurabilityPolicy, HistoryPolicy, QoSProfile, ReliabilityPolicy
from rclpy.serialization import deserialize_message
from sensor_msgs.msg import JointState
from trajectory_msgs.msg import JointTrajectory


def qos(reliable, transient, depth):
    return QoSProfile(
        reliability=ReliabilityPolicy.RELIABLE if reliable else ReliabilityPolicy.BEST_EFFORT,
        durability=DurabilityPolicy.TRANSIENT_LOCAL if transient else DurabilityPolicy.VOLATILE,
        history=HistoryPolicy.KEEP_LAST,
        depth=depth,
    )


def stamp(ns):
    return Time(sec=ns // 1_000_000_000, nanosec=ns % 1_000_000_000)


def main():
    recording, lock_path, timeout_s = sys.argv[1], sys.argv[2], float(sys.argv[3])
    with open(lock_path, "rb") as f:
        lock = tomllib.load(f)
    names = lock["trajectory"]["joint_names"]
    home = list(lock["trajectory"]["point"][0]["positions_rad"])
    frames = []
    with open(recording, "rb") as f:
        for _schema, channel, message in make_reader(f).iter_messages():
            if channel.topic.startswith("/ergocell/camera/"):
                frames.append((message.log_time, deserialize_message(message.data, CameraLandmarks)))
    frames.sort(key=lambda x: x[0])

    rclpy.init()
    node = rclpy.create_node("rclpy_peer", namespace="/ci")
    cams = {}
    for _, m in frames:
        if m.camera_id not in cams:
            cams[m.camera_id] = node.create_publisher(
                CameraLandmarks, f"/ergocell/camera/{m.camera_id}/landmarks", qos(False, False, 5))
    js_pub = node.create_publisher(JointState, "/joint_states", qos(True, False, 5))
    report = {
        "rmw": rclpy.get_rmw_implementation_identifier(),
        "camera_messages_sent": 0,
        "trajectories": [],
        "holds": 0,
        "events": [],
        "ergonomics": 0,
        "ergonomics_scores": [],
        "warnings": [],
        "lock_sha256": lock["lock_sha256"],
    }
    active = {"t0": None, "traj": None, "pos": list(home)}

    def positions_now(now):
        traj = active["traj"]
        if traj is None:
            return active["pos"]
        t = now - active["t0"]
        pts = traj.points
        tt = [p.time_from_start.sec + p.time_from_start.nanosec * 1e-9 for p in pts]
        order = [list(traj.joint_names).index(n) for n in names]
        if t >= tt[-1]:
            return [pts[-1].positions[i] for i in order]
        k = next(i for i, x in enumerate(tt) if x > t)
        if k == 0:
            return [pts[0].positions[i] for i in order]
        s = (t - tt[k - 1]) / (tt[k] - tt[k - 1])
        return [pts[k - 1].positions[i] + s * (pts[k].positions[i] - pts[k - 1].positions[i]) for i in order]

    def on_trajectory(traj):
        now = time.monotonic()
        active["pos"] = positions_now(now)
        if len(traj.points) == 0:
            active["traj"] = None
            report["holds"] += 1
        else:
            active["t0"], active["traj"] = now, traj
            report["trajectories"].append({
                "points": len(traj.points),
                "joint_names": list(traj.joint_names),
                "end_s": traj.points[-1].time_from_start.sec + traj.points[-1].time_from_start.nanosec * 1e-9,
            })

    def on_event(m):
        report["events"].append({"state": m.state, "reason": m.reason, "height_class": m.height_class,
                                 "trajectory_sha256": m.trajectory_sha256, "robot_held": m.robot_held})

    def on_ergonomics(m):
        report["ergonomics"] += 1
        if len(report["ergonomics_scores"]) < 5:
            report["ergonomics_scores"].append([m.left.final_score, m.right.final_score])

    node.create_subscription(JointTrajectory, "/joint_trajectory_controller/joint_trajectory",
                             on_trajectory, qos(True, False, 10))
    node.create_subscription(SessionState, "/ergocell/session_events", on_event, qos(True, True, 100))
    # For comparison only: the latched state's reader (keep last 1) from the start.
    report["session_state_reader_saw"] = []
    node.create_subscription(SessionState, "/ergocell/session_state",
                             lambda m: report["session_state_reader_saw"].append(m.state), qos(True, True, 1))
    node.create_subscription(ErgonomicState, "/ergocell/ergonomics", on_ergonomics, qos(True, False, 10))
    node.create_subscription(PostureWarning, "/ergocell/warnings",
                             lambda m: report["warnings"].append(m.region), qos(True, True, 20))

    def joint_state():
        js = JointState()
        js.header.stamp = stamp(time.time_ns())
        js.name = names
        js.position = [float(x) for x in positions_now(time.monotonic())]
        js_pub.publish(js)

    node.create_timer(0.02, joint_state)
    # Let discovery settle (the robot at home meanwhile).
    end = time.monotonic() + 2.0
    while time.monotonic() < end:
        rclpy.spin_once(node, timeout_sec=0.01)

    t_log0, t_play0, wall0 = frames[0][0], time.monotonic(), time.time_ns()
    i = 0
    late, late_sub, late_t0 = [], None, [0.0]
    deadline = t_play0 + timeout_s
    while time.monotonic() < deadline:
        now = time.monotonic()
        while i < len(frames) and (frames[i][0] - t_log0) * 1e-9 <= now - t_play0:
            log_time, m = frames[i]
            m.header.stamp = stamp(wall0 + (log_time - t_log0))
            cams[m.camera_id].publish(m)
            report["camera_messages_sent"] += 1
            i += 1
        rclpy.spin_once(node, timeout_sec=0.002)
        # A late joiner on the latched state, once the robot works: it must get the state at once.
        if late_sub is None and any(e["state"] == "working" for e in report["events"]):
            report["late_joiner_joined_after"] = len(report["events"])
            late_sub = node.create_subscription(
                SessionState, "/ergocell/session_state",
                lambda m: late.append({"state": m.state, "after_s": round(time.monotonic() - late_t0[0], 3)}),
                qos(True, True, 1))
            late_t0[0] = time.monotonic()
        if any(e["state"] == "session_ended" for e in report["events"]):
            break
    # Drain what is still on its way.
    end = time.monotonic() + 1.0
    while time.monotonic() < end:
        rclpy.spin_once(node, timeout_sec=0.01)
    report["late_joiner_session_state"] = late
    print(json.dumps(report))
    node.destroy_node()
    rclpy.shutdown()


if __name__ == "__main__":
    main()
