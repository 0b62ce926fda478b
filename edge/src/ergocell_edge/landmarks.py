"""Landmarks of one image in pixels, and the conversion from MediaPipe's normalized coordinates."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Optional, Sequence

from . import LANDMARK_COUNT


@dataclass(frozen=True)
class Landmarks:
    """33 BlazePose landmarks of one person in one image, in pixels of that image (origin top-left,
    x right, y down; the origin at the top-left pixel's centre, as ergocell_msgs/CameraLandmarks
    and OpenCV use). ``presence`` is None when the model did not report it (the legacy solution)."""

    x_px: tuple
    y_px: tuple
    visibility: tuple
    presence: Optional[tuple] = None

    def __post_init__(self):
        for name in ("x_px", "y_px", "visibility") + (("presence",) if self.presence is not None else ()):
            if len(getattr(self, name)) != LANDMARK_COUNT:
                raise ValueError(f"{name}: {len(getattr(self, name))} values, expected {LANDMARK_COUNT}")


def to_pixels(normalized: Sequence, width: int, height: int) -> Landmarks:
    """MediaPipe's normalized landmarks (objects with .x, .y in 0..1 of the image, .visibility, and
    .presence when set) to pixels: x = nx * width - 0.5, y = ny * height - 0.5 (MediaPipe's 0..1 spans
    the image's outer edges; ergocell's pixel origin is the top-left pixel's centre). Points MediaPipe
    extrapolates off the image keep their coordinates outside the image."""
    if len(normalized) != LANDMARK_COUNT:
        raise ValueError(f"{len(normalized)} landmarks, expected {LANDMARK_COUNT}")
    xs = tuple(float(p.x) * width - 0.5 for p in normalized)
    ys = tuple(float(p.y) * height - 0.5 for p in normalized)
    vis = tuple(float(p.visibility) for p in normalized)
    # The legacy pose solution does not fill `presence` (a protobuf field: HasField tells).
    has_presence = all(_has_presence(p) for p in normalized)
    pres = tuple(float(p.presence) for p in normalized) if has_presence else None
    return Landmarks(xs, ys, vis, pres)


def _has_presence(p) -> bool:
    has_field = getattr(p, "HasField", None)
    if has_field is not None:
        try:
            return bool(has_field("presence"))
        except ValueError:
            return False
    return getattr(p, "presence", None) is not None
