#!/usr/bin/env python3
"""Independent ROS 2 peer on Eclipse Cyclone DDS (the `cyclonedds` Python binding, no ROS install).

Plays the cell's other side for the interop test:
  * the six camera nodes: publishes each `/ergocell/camera/<id>/landmarks` message of an MCAP recording
    (written by `ergocell demo`), re-stamped to now, at the recorded pace;
  * the KUKA controller: publishes `/joint_states` at 50 Hz (starting at the trajectory's home), follows
    each `JointTrajectory` it receives by linear interpolation in real time, and stops where it is on an
    empty one (a hold);
  * a listener on `/ergocell/session_state` (reliable, transient local).

Types are declared by hand in the ROS 2 DDS naming (`pkg::msg::dds_::Name_`, topics `rt/...`), field by
field as in the .msg files; Cyclone serialises XCDR1 for these plain types. Prints a JSON report on
stdout at the end.
"""

import math
import json
import os
import sys
import time
import tomllib
from dataclasses import dataclass, field

from cyclonedds.core import Qos, Policy
from cyclonedds.domain import DomainParticipant
from cyclonedds.idl import IdlStruct
from cyclonedds.idl.types import float32, float64, int32, sequence, uint8, uint32
from cyclonedds.pub import DataWriter
from cyclonedds.sub import DataReader
from cyclonedds.topic import Topic
from mcap.reader import make_reader


@dataclass
class Time(IdlStruct, typename="builtin_interfaces::msg::dds_::Time_"):
    sec: int32
    nanosec: uint32


@dataclass
class Duration(IdlStruct, typename="builtin_interfaces::msg::dds_::Duration_"):
    sec: int32
    nanosec: uint32


@dataclass
class Header(IdlStruct, typename="std_msgs::msg::dds_::Header_"):
    stamp: Time
    frame_id: str


@dataclass
class CameraLandmarks(IdlStruct, typename="ergocell_msgs::msg::dds_::CameraLandmarks_"):
    header: Header
    camera_id: str
    image_width: uint32
    image_height: uint32
    x_px: sequence[float32]
    y_px: sequence[float32]
    visibility: sequence[float32]
    presence: sequence[float32]


@dataclass
class JointState(IdlStruct, typename="sensor_msgs::msg::dds_::JointState_"):
    header: Header
    name: sequence[str]
    position: sequence[float64]
    velocity: sequence[float64]
    effort: sequence[float64]


@dataclass
class JointTrajectoryPoint(IdlStruct, typename="trajectory_msgs::msg::dds_::JointTrajectoryPoint_"):
    positions: sequence[float64]
    velocities: sequence[float64]
    accelerations: sequence[float64]
    effort: sequence[float64]
    time_from_start: Duration


@dataclass
class JointTrajectory(IdlStruct, typename="trajectory_msgs::msg::dds_::JointTrajectory_"):
    header: Header
    joint_names: sequence[str]
    points: sequence[JointTrajectoryPoint]


@dataclass
class SessionState(IdlStruct, typename="ergocell_msgs::msg::dds_::SessionState_"):
    header: Header
    state: str
    reason: str
    height_m: float64
    height_uncertainty_m: float64
    height_class: str
    trajectory_sha256: str
    robot_held: bool
    cameras_fresh: uint32
    stereo_pairs_tracking: uint32
    trajectory_approved_by: sequence[str]
    height_decision_basis: str
    height_class_probability: float64
    height_expected_rula_cost: float64
    parts_taken: uint32
    last_part_hand: str
    last_part_closest_m: float64


@dataclass
class Point(IdlStruct, typename="geometry_msgs::msg::dds_::Point_"):
    x: float64
    y: float64
    z: float64


@dataclass
class Quaternion(IdlStruct, typename="geometry_msgs::msg::dds_::Quaternion_"):
    x: float64
    y: float64
    z: float64
    w: float64


@dataclass
class Pose(IdlStruct, typename="geometry_msgs::msg::dds_::Pose_"):
    position: Point
    orientation: Quaternion


@dataclass
class Vector3(IdlStruct, typename="geometry_msgs::msg::dds_::Vector3_"):
    x: float64
    y: float64
    z: float64


@dataclass
class ColorRGBA(IdlStruct, typename="std_msgs::msg::dds_::ColorRGBA_"):
    r: float32
    g: float32
    b: float32
    a: float32


@dataclass
class CompressedImage(IdlStruct, typename="sensor_msgs::msg::dds_::CompressedImage_"):
    header: Header
    format: str
    data: sequence[uint8]


@dataclass
class UVCoordinate(IdlStruct, typename="visualization_msgs::msg::dds_::UVCoordinate_"):
    u: float32
    v: float32


@dataclass
class MeshFile(IdlStruct, typename="visualization_msgs::msg::dds_::MeshFile_"):
    filename: str
    data: sequence[uint8]


@dataclass
class Marker(IdlStruct, typename="visualization_msgs::msg::dds_::Marker_"):
    """Jazzy layout (Iron added texture_resource, texture, uv_coordinates, mesh_file)."""

    header: Header
    ns: str
    id: int32
    type: int32
    action: int32
    pose: Pose
    scale: Vector3
    color: ColorRGBA
    lifetime: Duration
    frame_locked: bool
    points: sequence[Point]
    colors: sequence[ColorRGBA]
    texture_resource: str
    texture: CompressedImage
    uv_coordinates: sequence[UVCoordinate]
    text: str
    mesh_resource: str
    mesh_file: MeshFile
    mesh_use_embedded_materials: bool


@dataclass
class MarkerArray(IdlStruct, typename="visualization_msgs::msg::dds_::MarkerArray_"):
    markers: sequence[Marker]


def stamp(ns):
    return Time(sec=ns // 1_000_000_000, nanosec=ns % 1_000_000_000)


# PEER_STORM=N: send every camera message N times over (malformed ones mixed in); 1 = no storm.
STORM = max(1, int(os.environ.get("PEER_STORM", "1")))


def main():
    recording, lock_path, timeout_s = sys.argv[1], sys.argv[2], float(sys.argv[3])
    with open(lock_path, "rb") as f:
        lock = tomllib.load(f)
    names = lock["trajectory"]["joint_names"]
    home = list(lock["trajectory"]["point"][0]["positions_rad"])

    with open(recording, "rb") as f:
        frames = []
        for _schema, channel, message in make_reader(f).iter_messages():
            if channel.topic.startswith("/ergocell/camera/"):
                frames.append((message.log_time, CameraLandmarks.deserialize(message.data)))
    frames.sort(key=lambda x: x[0])
    # PEER_SKIP_S=S: start the playback S seconds into the recording (a camera node restarting
    # mid-session continues the operator's session, it does not start it again).
    skip_ns = int(float(os.environ.get("PEER_SKIP_S", "0")) * 1e9)
    frames = [f for f in frames if f[0] - frames[0][0] >= skip_ns]

    dp = DomainParticipant(0)
    sensor = Qos(Policy.Reliability.BestEffort, Policy.Durability.Volatile, Policy.History.KeepLast(5))
    command = Qos(
        Policy.Reliability.Reliable(max_blocking_time=1_000_000_000),
        Policy.Durability.Volatile,
        Policy.History.KeepLast(10),
    )
    state_qos = Qos(
        Policy.Reliability.Reliable(max_blocking_time=1_000_000_000),
        Policy.Durability.TransientLocal,
        Policy.History.KeepLast(50),
    )
    cams = {}
    for _, m in frames:
        if m.camera_id not in cams:
            t = Topic(dp, f"rt/ergocell/camera/{m.camera_id}/landmarks", CameraLandmarks)
            cams[m.camera_id] = DataWriter(dp, t, qos=sensor)
    js_writer = DataWriter(dp, Topic(dp, "rt/joint_states", JointState), qos=sensor)
    traj_reader = DataReader(
        dp, Topic(dp, "rt/joint_trajectory_controller/joint_trajectory", JointTrajectory), qos=command
    )
    state_reader = DataReader(dp, Topic(dp, "rt/ergocell/session_state", SessionState), qos=state_qos)
    per_frame = Qos(
        Policy.Reliability.Reliable(max_blocking_time=1_000_000_000),
        Policy.Durability.Volatile,
        Policy.History.KeepLast(10),
    )
    skeleton_reader = DataReader(dp, Topic(dp, "rt/ergocell/skeleton", MarkerArray), qos=per_frame)

    report = {
        "camera_messages_sent": 0,
        "joint_states_sent": 0,
        "trajectories": [],
        "holds": 0,
        "states": [],
        "lock_sha256": lock["lock_sha256"],
        "trajectory_sha256_seen": [],
        "height_class_seen": [],
        "class_decisions_seen": [],
        "skeletons": 0,
        "skeleton_points_max": 0,
        "skeleton_frame_ids": [],
    }
    position = list(home)
    active = None  # (start monotonic, JointTrajectory, names order)

    def positions_now(now):
        if active is None:
            return position
        t0, traj = active
        t = now - t0
        pts = traj.points
        tt = [p.time_from_start.sec + p.time_from_start.nanosec * 1e-9 for p in pts]
        order = [traj.joint_names.index(n) for n in names]
        if t >= tt[-1]:
            return [pts[-1].positions[i] for i in order]
        k = next(i for i, x in enumerate(tt) if x > t)
        if k == 0:
            return [pts[0].positions[i] for i in order]
        s = (t - tt[k - 1]) / (tt[k] - tt[k - 1])
        return [pts[k - 1].positions[i] + s * (pts[k].positions[i] - pts[k - 1].positions[i]) for i in order]

    # Let discovery settle, publishing the robot at home meanwhile.
    start = time.monotonic()
    next_js = start
    while time.monotonic() - start < 2.0:
        js_writer.write(JointState(Header(stamp(time.time_ns()), ""), names, home, [], []))
        report["joint_states_sent"] += 1
        time.sleep(0.02)

    t_log0 = frames[0][0]
    t_play0 = time.monotonic()
    wall0 = time.time_ns()
    i = 0
    ended = False
    deadline = t_play0 + timeout_s
    while time.monotonic() < deadline and not ended:
        now = time.monotonic()
        while i < len(frames) and (frames[i][0] - t_log0) * 1e-9 <= now - t_play0:
            log_time, m = frames[i]
            m.header.stamp = stamp(wall0 + (log_time - t_log0))
            cams[m.camera_id].write(m)
            report["camera_messages_sent"] += 1
            # A storm (PEER_STORM=N): N − 1 more messages per camera message, cycling through a
            # duplicate, a wrong-length one, one with NaN pixels and one naming an unknown camera.
            for k in range(STORM - 1):
                kind = k % 4
                if kind == 0:
                    bad = m
                elif kind == 1:
                    bad = CameraLandmarks(m.header, m.camera_id, m.image_width, m.image_height,
                                          m.x_px[:5], m.y_px, m.visibility, m.presence)
                elif kind == 2:
                    bad = CameraLandmarks(m.header, m.camera_id, m.image_width, m.image_height,
                                          [float("nan")] * len(m.x_px), m.y_px, m.visibility, m.presence)
                else:
                    bad = CameraLandmarks(m.header, "no_such_camera", m.image_width, m.image_height,
                                          m.x_px, m.y_px, m.visibility, m.presence)
                cams[m.camera_id].write(bad)
                report["storm_messages_sent"] = report.get("storm_messages_sent", 0) + 1
            i += 1
        for traj in traj_reader.take(N=10):
            if not isinstance(traj, JointTrajectory):  # InvalidSample: a writer went away
                continue
            position = positions_now(now)
            if len(traj.points) == 0:
                active = None
                report["holds"] += 1
            else:
                active = (now, traj)
                p0, p1 = traj.points[0], traj.points[-1]
                report["trajectories"].append(
                    {
                        "points": len(traj.points),
                        "joint_names": list(traj.joint_names),
                        "first": list(p0.positions),
                        "last": list(p1.positions),
                        "duration_s": p1.time_from_start.sec + p1.time_from_start.nanosec * 1e-9,
                    }
                )
        for sk in skeleton_reader.take(N=50):
            if not isinstance(sk, MarkerArray):
                continue
            report["skeletons"] += 1
            if sk.markers:
                report["skeleton_points_max"] = max(report["skeleton_points_max"], len(sk.markers[0].points))
                fid = sk.markers[0].header.frame_id
                if fid not in report["skeleton_frame_ids"]:
                    report["skeleton_frame_ids"].append(fid)
        for s in state_reader.take(N=50):
            if not isinstance(s, SessionState):
                continue
            if not report["states"] or report["states"][-1] != s.state:
                report["states"].append(s.state)
            if s.trajectory_sha256 and s.trajectory_sha256 not in report["trajectory_sha256_seen"]:
                report["trajectory_sha256_seen"].append(s.trajectory_sha256)
            if s.height_class and s.height_class not in report["height_class_seen"]:
                report["height_class_seen"].append(s.height_class)
            if s.height_decision_basis:
                finite = lambda x: round(x, 3) if math.isfinite(x) else None
                d = [s.height_class, s.height_decision_basis, finite(s.height_class_probability),
                     finite(s.height_expected_rula_cost)]
                if d not in report["class_decisions_seen"]:
                    report["class_decisions_seen"].append(d)
            if s.state == "session_ended":
                ended = True
        if now >= next_js:
            pos = positions_now(now)
            js_writer.write(JointState(Header(stamp(time.time_ns()), ""), names, pos, [], []))
            report["joint_states_sent"] += 1
            next_js = now + 0.02
        # After the recording, the cameras keep publishing "nobody" (empty landmark lists).
        if i >= len(frames) and int(now * 10) != int((now - 0.002) * 10):
            for cid, w in cams.items():
                w.write(
                    CameraLandmarks(Header(stamp(time.time_ns()), f"camera_{cid}"), cid, 1280, 720, [], [], [], [])
                )
        time.sleep(0.002)
    report["ended"] = ended
    print(json.dumps(report))


if __name__ == "__main__":
    main()
