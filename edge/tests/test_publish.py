"""`publish` without ROS: planning checks, pacing, stamps, and the frame loop with a stand-in node."""

import subprocess
import sys

import pytest

from ergocell_edge import EdgeError
from ergocell_edge.publish import MonotonicStamps, Pacer, PublishOptions, node_name, plan_publish, run_publish
from ergocell_edge.stop import StopFlag
from helpers import FakeDetector, make_video


def write_cell(tmp_path, domain=7, cameras=None):
    p = tmp_path / "cell.toml"
    cams = "" if cameras is None else "cameras = [" + ", ".join(f'"{c}"' for c in cameras) + "]\n"
    p.write_text(f'[ros]\ndomain_id = {domain}\ncamera_topic = "/ergocell/camera/{{id}}/landmarks"\n{cams}')
    return p


def write_rig(tmp_path, ids=("camL", "camR", "cam03")):
    p = tmp_path / "rig.toml"
    p.write_text("".join(f'[[camera]]\nid = "{i}"\n' for i in ids))
    return p


class FakeNode:
    instances = []

    def __init__(self, plan):
        self.plan = plan
        self.sent = []
        self.closed = False
        FakeNode.instances.append(self)

    def wait_for_subscriber(self, seconds, stop):
        return True

    def publish(self, k, fields):
        self.sent.append((k, fields))

    def close(self):
        self.closed = True


def opts(tmp_path, video, **kw):
    base = dict(camera="camL", source=str(video), rig=str(write_rig(tmp_path)), cell=str(write_cell(tmp_path)),
                stats_every_s=0)
    base.update(kw)
    return PublishOptions(**base)


def test_plan_checks_camera_topic_domain(tmp_path):
    v = make_video(tmp_path / "v.avi", 2, 32, 32, fps=25)
    plan = plan_publish(opts(tmp_path, v))
    assert plan.camera_ids == ["camL"] and plan.topics == ["/ergocell/camera/camL/landmarks"]
    assert plan.domain_id == 7 and plan.fps == pytest.approx(25.0) and plan.spec.kind == "file"
    with pytest.raises(EdgeError, match="camL, camR, cam03"):
        plan_publish(opts(tmp_path, v, camera="nope"))
    with pytest.raises(EdgeError, match="not in the rig"):
        plan_publish(opts(tmp_path, v, right_camera="nope"))
    with pytest.raises(EdgeError, match="differ"):
        plan_publish(opts(tmp_path, v, right_camera="camL"))
    with pytest.raises(EdgeError, match="not found"):
        plan_publish(opts(tmp_path, tmp_path / "missing.mp4"))
    bad = tmp_path / "bad.mp4"
    bad.write_bytes(b"garbage")
    with pytest.raises(EdgeError, match="bad.mp4"):
        plan_publish(opts(tmp_path, bad))


def test_file_loop_publishes_every_frame_with_file_stamps(tmp_path):
    v = make_video(tmp_path / "v.avi", 5, 40, 30, fps=100, left=(0, 0, 255), right=(0, 0, 255))
    FakeNode.instances.clear()
    stats = run_publish(opts(tmp_path, v), StopFlag(), detector_factory=FakeDetector, node_factory=FakeNode)
    node = FakeNode.instances[-1]
    assert node.closed and stats[0].published == len(node.sent)
    stamps = [f["stamp_sec"] * 10**9 + f["stamp_nanosec"] for _, f in node.sent]
    assert len(stamps) >= 2 and stamps[0] > 1_600_000_000 * 10**9
    # realtime from a file: start + index / fps, so gaps are multiples of 10 ms (a late frame is dropped)
    gaps = [b - a for a, b in zip(stamps, stamps[1:])]
    assert all(g > 0 and abs(g / 10_000_000 - round(g / 10_000_000)) < 1e-3 for g in gaps)
    assert all(len(f["x_px"]) == 33 and f["image_width"] == 40 for _, f in node.sent)


def test_no_realtime_loop_and_max_frames(tmp_path):
    v = make_video(tmp_path / "v.avi", 3, 40, 30, fps=30, left=(255, 0, 0), right=(255, 0, 0))
    FakeNode.instances.clear()
    run_publish(opts(tmp_path, v, realtime=False, loop=True, max_frames=7), StopFlag(),
                detector_factory=FakeDetector, node_factory=FakeNode)
    sent = FakeNode.instances[-1].sent
    assert len(sent) == 7  # 3 + 3 + 1: looped
    stamps = [f["stamp_sec"] * 10**9 + f["stamp_nanosec"] for _, f in sent]
    assert all(b > a for a, b in zip(stamps, stamps[1:]))
    # nobody (blue frames): empty messages, not silence
    assert all(f["x_px"] == [] and f["presence"] == [] for _, f in sent)


def test_side_by_side_publishes_two_cameras(tmp_path):
    v = make_video(tmp_path / "v.avi", 2, 64, 20, left=(0, 0, 255), right=(255, 0, 0))
    FakeNode.instances.clear()
    run_publish(opts(tmp_path, v, right_camera="camR", realtime=False), StopFlag(),
                detector_factory=FakeDetector, node_factory=FakeNode)
    node = FakeNode.instances[-1]
    assert node.plan.topics == ["/ergocell/camera/camL/landmarks", "/ergocell/camera/camR/landmarks"]
    left = [f for k, f in node.sent if k == 0]
    right = [f for k, f in node.sent if k == 1]
    assert len(left) == len(right) == 2
    assert left[0]["camera_id"] == "camL" and right[0]["frame_id"] == "camera_camR"
    assert left[0]["image_width"] == right[0]["image_width"] == 32
    assert len(left[0]["x_px"]) == 33 and right[0]["x_px"] == []
    assert [f["stamp_nanosec"] for f in left] == [f["stamp_nanosec"] for f in right]


def test_stop_ends_the_loop(tmp_path):
    v = make_video(tmp_path / "v.avi", 50, 32, 32, fps=30)
    stop = StopFlag()

    class StopNode(FakeNode):
        def publish(self, k, fields):
            super().publish(k, fields)
            if len(self.sent) == 3:
                stop.set("SIGINT")

    FakeNode.instances.clear()
    run_publish(opts(tmp_path, v, realtime=False), stop, detector_factory=FakeDetector, node_factory=StopNode)
    node = FakeNode.instances[-1]
    assert len(node.sent) == 3 and node.closed


def test_pacer_and_stamps():
    p = Pacer(50.0, 100.0)
    assert p.due(0) == 100.0 and p.due(50) == pytest.approx(101.0)
    assert p.latest_due(99.0) == -50 and p.latest_due(100.0) == 0 and p.latest_due(100.039) == 1
    s = MonotonicStamps()
    assert [s(10), s(5), s(20), s(20)] == [10, 11, 20, 21]
    assert node_name("s1-left") == "ergocell_edge_s1_left"


def test_publish_without_ros_names_what_to_source(tmp_path):
    try:
        import rclpy  # noqa: F401
        from ergocell_msgs.msg import CameraLandmarks  # noqa: F401
        pytest.skip("rclpy and ergocell_msgs are importable here")
    except ImportError:
        pass
    v = make_video(tmp_path / "v.avi", 2, 32, 32)
    r = subprocess.run([sys.executable, "-m", "ergocell_edge", "publish", "--camera", "camL", "--source", str(v),
                        "--rig", str(write_rig(tmp_path)), "--cell", str(write_cell(tmp_path))],
                       capture_output=True, text=True, timeout=120)
    assert r.returncode == 2 and "Traceback" not in r.stderr
    assert "setup.sh" in r.stderr and "PYTHONPATH" in r.stderr


def test_live_source_reconnects_after_a_lost_camera(tmp_path, monkeypatch, caplog):
    """A device that delivers 2 frames, fails, cannot be opened once, then delivers again."""
    import numpy as np

    import ergocell_edge.publish as pub

    script = iter(["open", "frame", "frame", "fail", "noopen", "open", "frame", "frame", "frame"])
    opened = []

    class FakeCap:
        def grab(self):
            return next(script) == "frame"

        def retrieve(self):
            return True, np.zeros((24, 32, 3), np.uint8)

        def release(self):
            pass

    def fake_open(spec):
        step = next(script)
        opened.append(step)
        return FakeCap() if step == "open" else None

    monkeypatch.setattr(pub, "open_capture", fake_open)
    monkeypatch.setattr(pub, "capture_fps", lambda cap: 30.0)
    FakeNode.instances.clear()
    caplog.set_level("INFO", logger="ergocell_edge")
    o = PublishOptions(camera="camL", source="/dev/video9", rig=str(write_rig(tmp_path)),
                       cell=str(write_cell(tmp_path)), max_frames=5, stats_every_s=0)
    t0 = __import__("time").monotonic()
    run_publish(o, StopFlag(), detector_factory=FakeDetector, node_factory=FakeNode)
    sent = FakeNode.instances[-1].sent
    assert len(sent) == 5 and opened == ["open", "noopen", "open"]
    assert all(f["image_width"] == 32 and f["x_px"] == [] for _, f in sent)
    stamps = [f["stamp_sec"] * 10**9 + f["stamp_nanosec"] for _, f in sent]
    assert all(b > a for a, b in zip(stamps, stamps[1:]))
    text = caplog.text
    assert "lost" in text and "cannot open" in text and "frames again" in text
    # backoff: 0.5 s after the loss, then 1 s after the failed open
    assert __import__("time").monotonic() - t0 >= 1.4
