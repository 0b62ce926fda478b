"""ergocell_msgs/msg/CameraLandmarks, as plain fields (testable without rclpy), and the stamps."""

from __future__ import annotations

import math
from typing import Optional

from .landmarks import Landmarks


def file_stamp_ns(start_ns: int, frame_index: int, fps: float) -> int:
    """A file frame's capture time when the file plays as a camera: start + frame_index / fps."""
    return int(start_ns) + int(round(frame_index * 1e9 / fps))


def split_stamp(stamp_ns: int) -> "tuple[int, int]":
    if stamp_ns < 0:
        raise ValueError("negative stamp")
    return stamp_ns // 1_000_000_000, stamp_ns % 1_000_000_000


def landmark_fields(camera_id: str, stamp_ns: int, width: int, height: int,
                    landmarks: Optional[Landmarks]) -> dict:
    """The message's fields. Nobody detected: all four arrays empty. The legacy MediaPipe solution
    reports no per-landmark presence; every landmark of a detected person is then published with
    presence 1.0 (the Rust side uses a landmark only when presence and visibility are both > 0)."""
    sec, nanosec = split_stamp(stamp_ns)
    fields = {
        "stamp_sec": sec,
        "stamp_nanosec": nanosec,
        "frame_id": f"camera_{camera_id}",
        "camera_id": camera_id,
        "image_width": int(width),
        "image_height": int(height),
        "x_px": [],
        "y_px": [],
        "visibility": [],
        "presence": [],
    }
    if landmarks is not None:
        fields["x_px"] = [float(v) for v in landmarks.x_px]
        fields["y_px"] = [float(v) for v in landmarks.y_px]
        fields["visibility"] = [_unit(v) for v in landmarks.visibility]
        fields["presence"] = ([_unit(v) for v in landmarks.presence] if landmarks.presence is not None
                              else [1.0] * len(landmarks.x_px))
    return fields


def _unit(v: float) -> float:
    v = float(v)
    return 0.0 if math.isnan(v) else min(1.0, max(0.0, v))


def to_message(fields: dict, message_type):
    """Fills an instance of ``message_type`` (ergocell_msgs.msg.CameraLandmarks, or anything with the
    same attributes) from ``landmark_fields``."""
    m = message_type()
    m.header.stamp.sec = fields["stamp_sec"]
    m.header.stamp.nanosec = fields["stamp_nanosec"]
    m.header.frame_id = fields["frame_id"]
    m.camera_id = fields["camera_id"]
    m.image_width = fields["image_width"]
    m.image_height = fields["image_height"]
    m.x_px = fields["x_px"]
    m.y_px = fields["y_px"]
    m.visibility = fields["visibility"]
    m.presence = fields["presence"]
    return m
