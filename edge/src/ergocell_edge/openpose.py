"""The offline output: OpenPose-layout JSON files, one per frame, and a video.json sidecar per camera.

Layout (read by the Rust side): DIR/<name>/<name>_<frame, 12 digits>_keypoints.json with
{"version": 1.3, "people": [{"person_id": [-1], "pose_keypoints_2d": [x0, y0, c0, ..., x32, y32, c32]}]}
(pixels of the frame, c = MediaPipe's visibility), "people": [] when nobody was detected.
"""

from __future__ import annotations

import json
import os
import re
from pathlib import Path
from typing import Optional

from .landmarks import Landmarks

KEYPOINTS_RE = re.compile(r"^(?P<name>.+)_(?P<frame>\d{12})_keypoints\.json$")
SIDECAR = "video.json"


def keypoints_file_name(name: str, frame: int) -> str:
    if frame < 0 or frame >= 10**12:
        raise ValueError(f"frame number {frame} out of range")
    return f"{name}_{frame:012d}_keypoints.json"


def keypoints_document(landmarks: Optional[Landmarks]) -> dict:
    if landmarks is None:
        return {"version": 1.3, "people": []}
    flat = []
    for x, y, c in zip(landmarks.x_px, landmarks.y_px, landmarks.visibility):
        flat.extend((round(x, 3), round(y, 3), round(c, 5)))
    return {"version": 1.3, "people": [{"person_id": [-1], "pose_keypoints_2d": flat}]}


def write_keypoints(folder: Path, name: str, frame: int, landmarks: Optional[Landmarks]) -> Path:
    path = folder / keypoints_file_name(name, frame)
    path.write_text(json.dumps(keypoints_document(landmarks), separators=(",", ":")))
    return path


def write_sidecar(folder: Path, info: dict) -> Path:
    path = folder / SIDECAR
    tmp = folder / (SIDECAR + ".tmp")
    tmp.write_text(json.dumps(info, indent=2) + "\n")
    os.replace(tmp, path)
    return path


def is_ours(file_name: str) -> bool:
    """Files a previous run wrote into a camera folder (removed by --force)."""
    return file_name == SIDECAR or file_name == SIDECAR + ".tmp" or KEYPOINTS_RE.match(file_name) is not None
