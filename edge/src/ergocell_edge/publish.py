"""`ergocell-edge publish`: the live camera node. Frames from a file, a device or a GStreamer pipeline,
BlazePose-33 landmarks per frame, published as ergocell_msgs/msg/CameraLandmarks over ROS 2 (rclpy).

Stamps (header.stamp, the image's capture time):
  * device / GStreamer pipeline: the wall time (time.time_ns) when the frame was grabbed, before it is
    decoded and processed (the driver queue is kept to one frame);
  * file with --realtime (default): start + frame_index / fps, where start is the wall time at which
    playback began (or --start-at), the file playing as a camera would; the file is paced at its fps,
    and frames whose time has already passed when the detector is ready are skipped (counted as
    dropped) as a live camera would drop them;
  * file with --no-realtime: frames as fast as the detector goes, stamped with the wall time at which
    each frame was read.
Stamps always increase (a clock step backwards is absorbed).
"""

from __future__ import annotations

import logging
import math
import re
import time
from dataclasses import dataclass
from typing import Callable, List, Optional

from . import EdgeError
from .config import check_camera, find_default, rig_camera_ids, ros_settings, DEFAULT_CELL, DEFAULT_RIG
from .message import file_stamp_ns, landmark_fields, to_message
from .stop import StopFlag
from .video import (SourceSpec, capture_fps, check_file, gstreamer_available, open_capture, parse_source,
                    probe_file, split_side_by_side)

log = logging.getLogger("ergocell_edge")

ROS_HINT = (
    "run it with a Python that has ROS 2's rclpy and the generated ergocell_msgs: e.g. the venv that "
    "`bash .ci/interop/rclpy/setup.sh DIR` builds (install this package into DIR/venv) with the "
    "environment line that script prints (export PYTHONPATH=DIR/gen/python LD_LIBRARY_PATH=DIR/gen/lib "
    "RMW_IMPLEMENTATION=rmw_fastrtps_cpp ...); on a ROS 2 install: source /opt/ros/<distro>/setup.bash "
    "and the install/setup.bash of a workspace that built ros2/ergocell_msgs")


def import_ros():
    """rclpy and ergocell_msgs, imported only here (they are not pip dependencies)."""
    try:
        import rclpy  # noqa: F401
        from rclpy.qos import DurabilityPolicy, HistoryPolicy, QoSProfile, ReliabilityPolicy  # noqa: F401
    except ImportError as e:
        raise EdgeError(f"rclpy is not importable ({e}): {ROS_HINT}") from None
    try:
        from ergocell_msgs.msg import CameraLandmarks
    except ImportError as e:
        raise EdgeError(f"ergocell_msgs is not importable ({e}): {ROS_HINT}") from None
    return rclpy, CameraLandmarks


class Pacer:
    """A file played as a camera: frame i is due at start + i / fps on the monotonic clock."""

    def __init__(self, fps: float, start_mono: float):
        self.fps, self.start = fps, start_mono

    def due(self, index: int) -> float:
        return self.start + index / self.fps

    def latest_due(self, now: float) -> int:
        """The newest frame index already due at ``now`` (-1 before the start)."""
        return math.floor((now - self.start) * self.fps + 1e-9)


class MonotonicStamps:
    """Wall-time stamps that strictly increase."""

    def __init__(self):
        self.last = -1

    def __call__(self, ns: int) -> int:
        self.last = max(int(ns), self.last + 1)
        return self.last


@dataclass
class CameraStats:
    camera_id: str
    published: int = 0
    with_person: int = 0
    inference_ms: float = 0.0

    def line(self) -> str:
        ms = self.inference_ms / self.published if self.published else 0.0
        pct = 100.0 * self.with_person / self.published if self.published else 0.0
        return (f"{self.camera_id}: {self.published} messages, {self.with_person} with a person "
                f"({pct:.1f} %), {ms:.1f} ms/frame inference")


@dataclass
class PublishOptions:
    camera: str
    source: str
    right_camera: Optional[str] = None
    rig: Optional[str] = None
    cell: Optional[str] = None
    max_frames: Optional[int] = None
    loop: bool = False
    realtime: bool = True
    fps: Optional[float] = None
    start_at: Optional[float] = None
    wait_for_subscriber: float = 0.0
    stats_every_s: float = 10.0
    model_complexity: int = 1
    verbose: bool = False


@dataclass
class Plan:
    camera_ids: List[str]
    spec: SourceSpec
    topics: List[str]
    domain_id: int
    fps: Optional[float]
    rig_path: str
    cell_path: str


def plan_publish(o: PublishOptions) -> Plan:
    """Everything that can be checked before ROS starts: cameras in the rig, the cell's topic and
    domain, the source."""
    if o.max_frames is not None and o.max_frames < 1:
        raise EdgeError("--max-frames must be at least 1")
    if o.fps is not None and not (o.fps > 0 and math.isfinite(o.fps)):
        raise EdgeError("--fps must be positive")
    rig_path = o.rig or str(find_default(DEFAULT_RIG))
    cell_path = o.cell or str(find_default(DEFAULT_CELL))
    known = rig_camera_ids(rig_path)
    ids = [o.camera] + ([o.right_camera] if o.right_camera else [])
    for cid in ids:
        check_camera(cid, known, rig_path)
    if len(ids) == 2 and ids[0] == ids[1]:
        raise EdgeError("--camera and --right-camera must differ")
    ros = ros_settings(cell_path)
    for cid in ids:
        if ros.cameras is not None and cid not in ros.cameras:
            log.warning("camera %s is not in %s's [ros] cameras (%s): ergocell will not subscribe to it",
                        cid, cell_path, ", ".join(ros.cameras))
    spec = parse_source(o.source)
    fps = o.fps
    if spec.kind == "file":
        check_file(spec.target)
        fps = fps or probe_file(spec.target).fps
        if fps is None and o.realtime:
            raise EdgeError(f"{spec.target}: the file does not say its frame rate: give --fps or --no-realtime")
    elif spec.kind == "gstreamer" and not gstreamer_available():
        raise EdgeError("this OpenCV was built without GStreamer (the opencv-contrib-python wheel is): "
                        "use an OpenCV built with it (e.g. JetPack's) for a pipeline source, or a device")
    topics = [ros.topic(cid) for cid in ids]
    return Plan(ids, spec, topics, ros.domain_id, fps, rig_path, cell_path)


def node_name(camera_id: str) -> str:
    return "ergocell_edge_" + re.sub(r"[^A-Za-z0-9_]", "_", camera_id)


def sensor_qos():
    from rclpy.qos import DurabilityPolicy, HistoryPolicy, QoSProfile, ReliabilityPolicy
    return QoSProfile(reliability=ReliabilityPolicy.BEST_EFFORT, durability=DurabilityPolicy.VOLATILE,
                      history=HistoryPolicy.KEEP_LAST, depth=5)


class Node:
    """The ROS side: one rclpy node, one publisher per camera."""

    def __init__(self, plan: Plan):
        rclpy, self.msg_type = import_ros()
        self.rclpy = rclpy
        kwargs = {"domain_id": plan.domain_id}
        try:
            from rclpy.signals import SignalHandlerOptions
            kwargs["signal_handler_options"] = SignalHandlerOptions.NO  # ours handle Ctrl-C/SIGTERM
        except ImportError:  # pragma: no cover - old rclpy
            pass
        try:
            rclpy.init(**kwargs)
        except Exception as e:
            raise EdgeError(f"rclpy.init failed ({e}): {ROS_HINT}") from None
        self.node = None
        try:
            self.node = rclpy.create_node(node_name(plan.camera_ids[0]))
            self.pubs = [self.node.create_publisher(self.msg_type, t, sensor_qos()) for t in plan.topics]
        except Exception as e:
            self.close()
            raise EdgeError(f"cannot create the node's publishers on {', '.join(plan.topics)} "
                            f"({type(e).__name__}: {e}); {ROS_HINT}") from None

    def wait_for_subscriber(self, seconds: float, stop: StopFlag) -> bool:
        deadline = time.monotonic() + seconds
        while time.monotonic() < deadline and not stop:
            if all(p.get_subscription_count() > 0 for p in self.pubs):
                return True
            stop.sleep(0.05)
        return False

    def publish(self, k: int, fields: dict) -> None:
        self.pubs[k].publish(to_message(fields, self.msg_type))

    def close(self) -> None:
        try:
            if self.node is not None:
                self.node.destroy_node()
                self.node = None
        finally:
            try:
                self.rclpy.try_shutdown()
            except AttributeError:  # pragma: no cover
                if self.rclpy.ok():
                    self.rclpy.shutdown()


class FileFrames:
    """A video file's frames; at its end, None, or with loop=True the file again from its start."""

    def __init__(self, spec: SourceSpec, loop: bool):
        self.spec, self.loop = spec, loop
        self.cap = open_capture(spec)
        if self.cap is None:
            raise EdgeError(f"{spec.target}: cannot open it as a video")
        self.file_index = 0
        self.loops = 0

    def next(self, decode: bool = True):
        """The next frame (decode=False: skip it, returns True); None at the end."""
        for _ in range(2):
            if self.cap.grab():
                self.file_index += 1
                if not decode:
                    return True
                ok, frame = self.cap.retrieve()
                if ok and frame is not None:
                    return frame
            if not self.loop or self.file_index == 0:
                return None
            self.cap.release()
            self.cap = open_capture(self.spec)
            if self.cap is None:
                raise EdgeError(f"{self.spec.target}: cannot reopen it to loop")
            self.file_index = 0
            self.loops += 1
            log.info("%s: end of file, playing it again (loop %d)", self.spec.target, self.loops)
        return None

    def close(self):
        if self.cap is not None:
            self.cap.release()


def run_publish(o: PublishOptions, stop: StopFlag, detector_factory: Optional[Callable] = None,
                node_factory: Callable = Node) -> List[CameraStats]:
    plan = plan_publish(o)
    if detector_factory is None:
        from .pose import PoseDetector, check_complexity
        check_complexity(o.model_complexity)
        detector_factory = lambda: PoseDetector(o.model_complexity, quiet=not o.verbose)  # noqa: E731
    node = node_factory(plan)
    stats = [CameraStats(cid) for cid in plan.camera_ids]
    try:
        for cid, topic in zip(plan.camera_ids, plan.topics):
            log.info("camera %s: publishing CameraLandmarks on %s (domain %d) from %s",
                     cid, topic, plan.domain_id, plan.spec.describe())
        if o.wait_for_subscriber > 0:
            if not node.wait_for_subscriber(o.wait_for_subscriber, stop) and not stop:
                log.warning("no subscriber after %.1f s: publishing anyway", o.wait_for_subscriber)
        # (MediaPipe's start-up lines are held back until each detector's first frame: log nothing
        # between here and the first frame.)
        detectors = [detector_factory() for _ in plan.camera_ids]
        loop = _file_loop if plan.spec.kind == "file" else _live_loop
        loop(o, plan, node, detectors, stats, stop)
        for d in detectors:
            d.close()
    finally:
        node.close()
    if stop:
        log.info("stopped (%s)", stop.signal_name)
    for s in stats:
        log.info("%s", s.line())
    return stats


def _process(frame, plan, node, detectors, stats, stamp_ns):
    images = split_side_by_side(frame) if len(plan.camera_ids) == 2 else (frame,)
    for k, (cid, det, img) in enumerate(zip(plan.camera_ids, detectors, images)):
        landmarks, ms = det.detect(img)
        h, w = img.shape[:2]
        node.publish(k, landmark_fields(cid, stamp_ns, w, h, landmarks))
        s = stats[k]
        s.published += 1
        s.with_person += landmarks is not None
        s.inference_ms += ms


class _Periodic:
    def __init__(self, every_s: float):
        self.every, self.next = every_s, time.monotonic() + every_s

    def __call__(self, stats, extra=""):
        if self.every > 0 and time.monotonic() >= self.next:
            self.next += self.every
            for s in stats:
                log.info("%s%s", s.line(), extra)


def _file_loop(o, plan, node, detectors, stats, stop):
    frames = FileFrames(plan.spec, o.loop)
    periodic = _Periodic(o.stats_every_s)
    wall_stamps = MonotonicStamps()
    index, dropped = 0, 0  # index: frames consumed since the start (over loops): the stamp's frame number
    try:
        if o.realtime:
            if o.start_at is not None:
                start_ns = int(o.start_at * 1e9)
                start_mono = time.monotonic() + (start_ns - time.time_ns()) / 1e9
                if stop.sleep(start_mono - time.monotonic()):
                    return
            else:
                start_ns, start_mono = time.time_ns(), time.monotonic()
            pacer = Pacer(plan.fps, start_mono)
        while not stop and (o.max_frames is None or index < o.max_frames):
            if o.realtime:
                # Late: skip the frames whose time has passed (keep the newest due one).
                behind = pacer.latest_due(time.monotonic()) - index
                if o.max_frames is not None:
                    behind = min(behind, o.max_frames - 1 - index)
                ended = False
                for _ in range(max(0, behind)):
                    if frames.next(decode=False) is None:
                        ended = True
                        break
                    index += 1
                    dropped += 1
                if ended or stop.sleep(pacer.due(index) - time.monotonic()):
                    break
            frame = frames.next()
            if frame is None:
                break
            stamp = file_stamp_ns(start_ns, index, plan.fps) if o.realtime else wall_stamps(time.time_ns())
            _process(frame, plan, node, detectors, stats, stamp)
            index += 1
            periodic(stats, f", {dropped} dropped" if o.realtime else "")
    finally:
        frames.close()
    if not stop:
        log.info("%s: end of input after %d frames%s", plan.spec.target, index,
                 f" ({dropped} dropped to keep real time)" if dropped else "")


def _live_loop(o, plan, node, detectors, stats, stop):
    periodic = _Periodic(o.stats_every_s)
    stamps = MonotonicStamps()
    cap, backoff, failures, n = None, 0.5, 0, 0
    try:
        while not stop and (o.max_frames is None or n < o.max_frames):
            if cap is None:
                cap = open_capture(plan.spec)
                if cap is None:
                    failures += 1
                    log.warning("camera %s: cannot open %s; retrying in %.1f s (attempt %d)",
                                plan.camera_ids[0], plan.spec.describe(), backoff, failures)
                    stop.sleep(backoff)
                    backoff = min(backoff * 2, 10.0)
                    continue
                fps = capture_fps(cap)
                log.info("camera %s: %s open%s", plan.camera_ids[0], plan.spec.describe(),
                         f" ({fps:g} fps)" if fps else "")
            ok = cap.grab()
            grabbed_ns = time.time_ns()
            frame = None
            if ok:
                ok, frame = cap.retrieve()
            if not ok or frame is None:
                log.warning("camera %s: lost (read failed on %s); reconnecting in %.1f s",
                            plan.camera_ids[0], plan.spec.describe(), backoff)
                cap.release()
                cap = None
                failures += 1
                stop.sleep(backoff)
                backoff = min(backoff * 2, 10.0)
                continue
            if failures:
                log.info("camera %s: frames again after %d failed attempt(s)", plan.camera_ids[0], failures)
            failures, backoff = 0, 0.5
            _process(frame, plan, node, detectors, stats, stamps(grabbed_ns))
            n += 1
            periodic(stats)
    finally:
        if cap is not None:
            cap.release()
