"""The real MediaPipe detector on the first frames of a real video (skipped without the demo data)."""

import json

from conftest import demo_video
from ergocell_edge.detect import run_detect


def test_cam03_first_three_frames(tmp_path):
    video = demo_video("cam03.mp4")
    jobs = run_detect([str(video)], str(tmp_path), max_frames=3, progress=False)
    out = jobs[0].outputs[0]
    assert out.frames == 3 and out.with_person == 3
    side = json.loads((tmp_path / "cam03" / "video.json").read_text())
    assert (side["width"], side["height"]) == (1088, 1920)
    assert side["model"].startswith("mediapipe ") and "pose_landmark_full (model_complexity=1)" in side["model"]
    for k in range(3):
        doc = json.loads((tmp_path / "cam03" / f"cam03_{k:012d}_keypoints.json").read_text())
        assert len(doc["people"]) == 1
        flat = doc["people"][0]["pose_keypoints_2d"]
        assert len(flat) == 99
        xs, ys, cs = flat[0::3], flat[1::3], flat[2::3]
        assert all(0 <= x < 1088 for x in xs), xs
        assert all(0 <= y < 1920 for y in ys), ys
        assert all(0 <= c <= 1 for c in cs)
        # a standing person: the nose above the hips above the ankles (image y grows downwards)
        assert ys[0] < ys[23] < ys[27] and ys[0] < ys[24] < ys[28]
