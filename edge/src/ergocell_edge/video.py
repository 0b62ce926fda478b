"""Video sources (files, V4L2 devices, GStreamer pipelines) and the side-by-side stereo split."""

from __future__ import annotations

import math
import os
import re
from dataclasses import dataclass
from pathlib import Path
from typing import Optional, Union

from . import EdgeError


def split_side_by_side(frame):
    """A side-by-side stereo frame (left image | right image) to its two halves, as views. Each half is
    floor(width / 2) wide (an odd last column is dropped); a pixel (x, y) of the right half is
    (x + floor(width / 2), y) in the full frame."""
    w = frame.shape[1]
    half = w // 2
    if half < 1:
        raise EdgeError(f"frame {w} px wide: too narrow to split side by side")
    return frame[:, :half], frame[:, half:2 * half]


@dataclass(frozen=True)
class SourceSpec:
    kind: str  # "file", "device", "gstreamer"
    target: Union[str, int]

    @property
    def live(self) -> bool:
        return self.kind != "file"

    def describe(self) -> str:
        return {"file": "file", "device": "device", "gstreamer": "GStreamer pipeline"}[self.kind] + f" {self.target}"


def parse_source(src: str) -> SourceSpec:
    """A video file, a camera device (/dev/videoN, or its index N), or a GStreamer pipeline (has '!')."""
    s = src.strip()
    if "!" in s:
        return SourceSpec("gstreamer", s)
    if re.fullmatch(r"\d+", s):
        return SourceSpec("device", int(s))
    if s.startswith("/dev/"):
        return SourceSpec("device", s)
    return SourceSpec("file", s)


def check_file(path: Union[str, Path]) -> Path:
    p = Path(path)
    if not p.exists():
        raise EdgeError(f"{p}: file not found")
    if not p.is_file():
        raise EdgeError(f"{p}: not a video file")
    if not os.access(p, os.R_OK):
        raise EdgeError(f"{p}: not readable")
    return p


def open_capture(spec: SourceSpec):
    """cv2.VideoCapture for the source, or None when it does not open."""
    import cv2
    if spec.kind == "gstreamer":
        cap = cv2.VideoCapture(spec.target, cv2.CAP_GSTREAMER)
    elif spec.kind == "device":
        cap = cv2.VideoCapture(spec.target)
        if cap.isOpened():
            # Keep the driver's queue short: a frame's grab time is then close to its capture time.
            cap.set(cv2.CAP_PROP_BUFFERSIZE, 1)
    else:
        cap = cv2.VideoCapture(str(spec.target))
    if not cap.isOpened():
        cap.release()
        return None
    return cap


def capture_fps(cap) -> Optional[float]:
    import cv2
    fps = cap.get(cv2.CAP_PROP_FPS)
    if fps is None or not math.isfinite(fps) or fps <= 0 or fps > 1000:
        return None
    return float(fps)


def capture_frame_count(cap) -> Optional[int]:
    import cv2
    n = cap.get(cv2.CAP_PROP_FRAME_COUNT)
    if n is None or not math.isfinite(n) or n <= 0:
        return None
    return int(n)


@dataclass(frozen=True)
class VideoInfo:
    """What opening a video file and decoding its first frame tells."""

    width: int
    height: int
    fps: Optional[float]
    frame_count: Optional[int]


def probe_file(path: Union[str, Path]) -> VideoInfo:
    """Opens a video file and decodes its first frame, so that an input that cannot be read fails
    before any output is written or anything is published."""
    cap = open_capture(SourceSpec("file", str(path)))
    if cap is None:
        raise EdgeError(f"{path}: cannot open it as a video (OpenCV/FFmpeg)")
    try:
        ok, frame = cap.read()
        if not ok or frame is None:
            raise EdgeError(f"{path}: cannot decode a frame from it")
        height, width = frame.shape[:2]
        return VideoInfo(int(width), int(height), capture_fps(cap), capture_frame_count(cap))
    finally:
        cap.release()


def gstreamer_available() -> bool:
    import cv2
    info = cv2.getBuildInformation()
    m = re.search(r"GStreamer:\s*(\S+)", info)
    return bool(m and m.group(1).upper() not in ("NO", "OFF"))
