"""Live: `ergocell-edge publish` from cam03.mp4 over ROS 2 (rclpy, Fast DDS), received by an rclpy
subscriber. Skipped unless rclpy and ergocell_msgs are importable (the venv of
.ci/interop/rclpy/setup.sh with this package installed, and the environment line it prints)."""

import os
import subprocess
import sys
import threading
import time

import pytest

from conftest import DATA, demo_video


def ros():
    try:
        import rclpy
        from ergocell_msgs.msg import CameraLandmarks
        from rclpy.qos import qos_profile_sensor_data
    except ImportError as e:
        pytest.skip(f"rclpy/ergocell_msgs not importable: {e}")
    return rclpy, CameraLandmarks, qos_profile_sensor_data


def test_publish_cam03_received_by_rclpy(tmp_path):
    rclpy, CameraLandmarks, sensor_qos = ros()
    video = demo_video("cam03.mp4")
    rig = DATA / "calibration" / "Calib.qca.txt"
    domain = 150 + os.getpid() % 70  # away from the cell's domain 0 and other tests
    cell = tmp_path / "cell.toml"
    cell.write_text(f'[ros]\ndomain_id = {domain}\ncamera_topic = "/ergocell/camera/{{id}}/landmarks"\n'
                    'cameras = ["cam03"]\n')
    env = dict(os.environ, ROS_AUTOMATIC_DISCOVERY_RANGE="LOCALHOST")
    os.environ["ROS_AUTOMATIC_DISCOVERY_RANGE"] = "LOCALHOST"
    ctx = rclpy.Context()
    rclpy.init(context=ctx, domain_id=domain)
    got = []
    try:
        node = rclpy.create_node("edge_test_listener", context=ctx)
        node.create_subscription(CameraLandmarks, "/ergocell/camera/cam03/landmarks", got.append, sensor_qos)
        from rclpy.executors import SingleThreadedExecutor
        ex = SingleThreadedExecutor(context=ctx)
        ex.add_node(node)
        spinning = threading.Thread(target=ex.spin, daemon=True)
        spinning.start()
        proc = subprocess.run(
            [sys.executable, "-m", "ergocell_edge", "publish", "--camera", "cam03", "--source", str(video),
             "--rig", str(rig), "--cell", str(cell), "--max-frames", "20", "--no-realtime",
             "--wait-for-subscriber", "20", "--stats-every", "0"],
            capture_output=True, text=True, timeout=180, env=env)
        time.sleep(0.5)
        assert proc.returncode == 0, proc.stderr
        assert "Traceback" not in proc.stderr
    finally:
        ex.shutdown(timeout_sec=2)
        node.destroy_node()
        rclpy.try_shutdown(context=ctx)
    assert len(got) >= 15, (len(got), proc.stderr)
    stamps = [m.header.stamp.sec * 10**9 + m.header.stamp.nanosec for m in got]
    assert all(b > a for a, b in zip(stamps, stamps[1:])), stamps
    assert abs(stamps[-1] / 1e9 - time.time()) < 120
    for m in got:
        assert m.camera_id == "cam03" and m.header.frame_id == "camera_cam03"
        assert (m.image_width, m.image_height) == (1088, 1920)
        assert len(m.x_px) == len(m.y_px) == len(m.visibility) == len(m.presence) == 33
        assert all(0 <= x < 1088 for x in m.x_px) and all(0 <= y < 1920 for y in m.y_px)
        assert all(0 < p <= 1 for p in m.presence)
