"""CameraLandmarks filling, as plain fields (no rclpy needed)."""

from types import SimpleNamespace

import pytest

from ergocell_edge.landmarks import Landmarks
from ergocell_edge.message import file_stamp_ns, landmark_fields, split_stamp, to_message


def lm(presence=None):
    return Landmarks(tuple(float(i) for i in range(33)), tuple(100.0 + i for i in range(33)),
                     tuple(min(1.0, i / 30) for i in range(33)), presence)


def test_fields_with_a_person():
    f = landmark_fields("s1_left", 1_700_000_000_123_456_789, 1280, 720, lm())
    assert (f["stamp_sec"], f["stamp_nanosec"]) == (1_700_000_000, 123_456_789)
    assert f["frame_id"] == "camera_s1_left" and f["camera_id"] == "s1_left"
    assert (f["image_width"], f["image_height"]) == (1280, 720)
    for k in ("x_px", "y_px", "visibility", "presence"):
        assert len(f[k]) == 33
    assert f["x_px"][5] == 5.0 and f["y_px"][5] == 105.0 and f["visibility"][3] == pytest.approx(0.1)
    # the legacy solution reports no presence: 1.0 for every landmark of a detected person, so that the
    # Rust side (presence > 0 and visibility > 0) uses them
    assert f["presence"] == [1.0] * 33


def test_reported_presence_is_kept_and_clamped():
    f = landmark_fields("c", 0, 10, 10, lm(presence=tuple([0.25] * 32 + [1.5])))
    assert f["presence"][:32] == [0.25] * 32 and f["presence"][32] == 1.0


def test_nobody_is_an_empty_message():
    f = landmark_fields("cam03", 5, 1088, 1920, None)
    assert f["x_px"] == f["y_px"] == f["visibility"] == f["presence"] == []
    assert f["camera_id"] == "cam03" and (f["image_width"], f["image_height"]) == (1088, 1920)


def test_to_message_fills_every_field():
    class Msg:
        def __init__(self):
            self.header = SimpleNamespace(stamp=SimpleNamespace(sec=0, nanosec=0), frame_id="")

    m = to_message(landmark_fields("c1", 3_000_000_007, 640, 480, lm()), Msg)
    assert (m.header.stamp.sec, m.header.stamp.nanosec, m.header.frame_id) == (3, 7, "camera_c1")
    assert m.camera_id == "c1" and (m.image_width, m.image_height) == (640, 480)
    assert len(m.x_px) == len(m.y_px) == len(m.visibility) == len(m.presence) == 33


def test_stamps():
    assert file_stamp_ns(1_000, 0, 60.0) == 1_000
    assert file_stamp_ns(0, 60, 60.0) == 1_000_000_000
    assert file_stamp_ns(0, 1, 60.0) == 16_666_667
    assert file_stamp_ns(0, 3, 29.97) == round(3 / 29.97 * 1e9)
    assert split_stamp(1_500_000_000) == (1, 500_000_000)
    with pytest.raises(ValueError):
        split_stamp(-1)
