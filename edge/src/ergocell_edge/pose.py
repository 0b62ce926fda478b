"""MediaPipe's legacy BlazePose solution (mediapipe.solutions.pose), in video (tracking) mode.

Only model_complexity=1 (pose_landmark_full.tflite) is bundled in the mediapipe wheels; lite (0) and
heavy (2) would be downloaded on first use, which an offline camera node cannot do: they are refused.
"""

from __future__ import annotations

import os
import sys
import tempfile
import time
from typing import Optional

from . import EdgeError
from .landmarks import Landmarks, to_pixels

SUPPORTED_COMPLEXITY = 1
_MODEL_FILES = {0: "pose_landmark_lite.tflite", 1: "pose_landmark_full.tflite", 2: "pose_landmark_heavy.tflite"}


def check_complexity(model_complexity: int) -> None:
    if model_complexity != SUPPORTED_COMPLEXITY:
        name = _MODEL_FILES.get(model_complexity, "no such model")
        raise EdgeError(
            f"model complexity {model_complexity} ({name}) is not supported: only model_complexity=1 "
            "(pose_landmark_full.tflite) ships inside the mediapipe wheel; 0 (lite) and 2 (heavy) would be "
            "downloaded at run time, and this node runs offline")


def _import_mediapipe():
    # Quieter native logging (glog/absl); must be set before mediapipe's libraries load.
    os.environ.setdefault("GLOG_minloglevel", "2")
    os.environ.setdefault("TF_CPP_MIN_LOG_LEVEL", "2")
    try:
        import mediapipe
        from mediapipe.python.solutions import pose as mp_pose
    except ImportError as e:  # pragma: no cover - depends on the install
        raise EdgeError(f"cannot import mediapipe ({e}): install this package with its dependencies "
                        "(see edge/README.md)") from e
    return mediapipe, mp_pose


def mediapipe_version() -> str:
    mediapipe, _ = _import_mediapipe()
    return getattr(mediapipe, "__version__", "unknown")


def model_description() -> str:
    return f"mediapipe {mediapipe_version()} pose_landmark_full (model_complexity=1)"


class _StderrCapture:
    """MediaPipe's C++ side prints start-up lines on file descriptor 2 (XNNPACK delegate, feedback
    tensors, NORM_RECT). While captured (reference-counted), file descriptor 2 points at a temporary
    file; what was captured is shown when the captured call failed, dropped otherwise."""

    _count = 0
    _saved = None
    _tmp = None
    _failed = False

    @classmethod
    def acquire(cls) -> None:
        if cls._count == 0:
            sys.stderr.flush()
            cls._tmp = tempfile.TemporaryFile(mode="w+b")
            cls._saved = os.dup(2)
            os.dup2(cls._tmp.fileno(), 2)
            cls._failed = False
        cls._count += 1

    @classmethod
    def release(cls, failed: bool = False) -> None:
        if cls._count == 0:
            return
        cls._failed = cls._failed or failed
        cls._count -= 1
        if cls._count == 0:
            sys.stderr.flush()
            os.dup2(cls._saved, 2)
            os.close(cls._saved)
            if cls._failed:
                cls._tmp.seek(0)
                sys.stderr.write(cls._tmp.read().decode(errors="replace"))
                sys.stderr.flush()
            cls._tmp.close()
            cls._saved = cls._tmp = None


class PoseDetector:
    """One camera's tracker: one mediapipe Pose instance (it tracks between consecutive frames, so a
    camera needs its own). ``detect(bgr)`` returns pixel landmarks or None, and the inference time."""

    def __init__(self, model_complexity: int = 1, min_detection_confidence: float = 0.5,
                 min_tracking_confidence: float = 0.5, quiet: bool = True):
        check_complexity(model_complexity)
        self._pose = None
        _, mp_pose = _import_mediapipe()
        import cv2  # opencv-contrib-python, a dependency of mediapipe
        import numpy as np
        self._cv2 = cv2
        # While quiet, file descriptor 2 is captured during the graph's start (with one blank warm-up
        # frame, which starts every calculator) and around process() until the first person is found
        # (the landmark projection's one-time NORM_RECT warning). Never while waiting for a camera.
        self._quiet_until_person = quiet
        if quiet:
            _StderrCapture.acquire()
        failed = True
        try:
            self._pose = mp_pose.Pose(
                static_image_mode=False,
                model_complexity=model_complexity,
                smooth_landmarks=True,
                enable_segmentation=False,
                min_detection_confidence=min_detection_confidence,
                min_tracking_confidence=min_tracking_confidence,
            )
            self._pose.process(np.zeros((64, 64, 3), np.uint8))
            failed = False
        finally:
            if quiet:
                _StderrCapture.release(failed)

    def detect(self, bgr) -> "tuple[Optional[Landmarks], float]":
        """Landmarks of the tracked person in a BGR image (pixels of that image), or None; and the
        inference time in ms (MediaPipe's process call only)."""
        h, w = bgr.shape[:2]
        rgb = self._cv2.cvtColor(bgr, self._cv2.COLOR_BGR2RGB)
        rgb.flags.writeable = False
        quiet = self._quiet_until_person
        if quiet:
            _StderrCapture.acquire()
        failed = True
        try:
            t0 = time.perf_counter()
            result = self._pose.process(rgb)
            ms = (time.perf_counter() - t0) * 1000.0
            failed = False
        finally:
            if quiet:
                _StderrCapture.release(failed)
        if result.pose_landmarks is None:
            return None, ms
        self._quiet_until_person = False
        return to_pixels(result.pose_landmarks.landmark, w, h), ms

    def close(self) -> None:
        if self._pose is not None:
            self._pose.close()
            self._pose = None

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()
