"""Test helpers: synthetic videos and a stand-in detector (no MediaPipe)."""

from pathlib import Path

import numpy as np

from ergocell_edge.landmarks import Landmarks


def make_video(path: Path, frames: int, width: int, height: int, fps: float = 30.0, left=(0, 0, 255),
               right=(255, 0, 0)):
    """An MJPG .avi whose frames are `left` colour (BGR) on the left half, `right` on the right half,
    with frame k's number drawn as a bright square in the top-left corner k px wide (for ordering)."""
    import cv2
    w = cv2.VideoWriter(str(path), cv2.VideoWriter_fourcc(*"MJPG"), fps, (width, height))
    assert w.isOpened()
    for k in range(frames):
        img = np.zeros((height, width, 3), np.uint8)
        img[:, : width // 2] = left
        img[:, width // 2:] = right
        w.write(img)
    w.release()
    return path


class FakeDetector:
    """Finds a 'person' on every frame whose mean red (BGR index 2) is > 128, at fixed normalized spots;
    records the shapes it was given."""

    instances = []

    def __init__(self, *a, **k):
        self.shapes = []
        self.means = []
        self.closed = False
        FakeDetector.instances.append(self)

    def detect(self, bgr):
        h, w = bgr.shape[:2]
        self.shapes.append((h, w))
        self.means.append(tuple(float(c) for c in bgr.reshape(-1, 3).mean(axis=0)))
        if bgr[..., 2].mean() <= 128:
            return None, 1.0
        xs = tuple((0.1 + 0.02 * i) * w for i in range(33))
        ys = tuple((0.05 + 0.025 * i) * h for i in range(33))
        return Landmarks(xs, ys, tuple(0.5 for _ in range(33))), 2.0

    def close(self):
        self.closed = True
