"""The OpenPose-layout files the Rust reader parses: names, content, empty frames, sidecar."""

import json
import re
from types import SimpleNamespace

import pytest

from ergocell_edge.landmarks import Landmarks, to_pixels
from ergocell_edge.openpose import (KEYPOINTS_RE, is_ours, keypoints_document, keypoints_file_name,
                                    write_keypoints, write_sidecar)

# What the Rust side (formats/src/import.rs) expects: <stem>_<12 digits>_keypoints.json
RUST_NAME = re.compile(r"^(?P<stem>.+)_(?P<frame>[0-9]{12})_keypoints\.json$")


def landmarks(k=0.0):
    return Landmarks(tuple(10.0 + i + k for i in range(33)), tuple(20.0 + 2 * i for i in range(33)),
                     tuple(i / 40 for i in range(33)))


def test_file_name_is_stem_and_12_digit_frame():
    assert keypoints_file_name("cam01", 0) == "cam01_000000000000_keypoints.json"
    assert keypoints_file_name("cam01", 1234) == "cam01_000000001234_keypoints.json"
    m = RUST_NAME.match(keypoints_file_name("s1_left", 99))
    assert m and m["stem"] == "s1_left" and int(m["frame"]) == 99
    assert KEYPOINTS_RE.match(keypoints_file_name("a_b", 7))["name"] == "a_b"
    with pytest.raises(ValueError):
        keypoints_file_name("cam01", -1)


def test_document_has_33_triplets_in_blazepose_order(tmp_path):
    path = write_keypoints(tmp_path, "cam01", 5, landmarks())
    assert path.name == "cam01_000000000005_keypoints.json"
    doc = json.loads(path.read_text())
    assert doc["version"] == 1.3
    assert len(doc["people"]) == 1
    person = doc["people"][0]
    assert person["person_id"] == [-1]
    flat = person["pose_keypoints_2d"]
    assert len(flat) == 33 * 3 and all(isinstance(v, (int, float)) for v in flat)
    for i in range(33):
        assert flat[3 * i] == pytest.approx(10.0 + i)
        assert flat[3 * i + 1] == pytest.approx(20.0 + 2 * i)
        assert flat[3 * i + 2] == pytest.approx(i / 40, abs=1e-5)


def test_empty_frame_has_no_people(tmp_path):
    assert keypoints_document(None) == {"version": 1.3, "people": []}
    doc = json.loads(write_keypoints(tmp_path, "cam02", 0, None).read_text())
    assert doc == {"version": 1.3, "people": []}


def test_sidecar_and_ownership(tmp_path):
    info = {"source": "cam01.mp4", "width": 1080, "height": 1920, "fps": 60.0, "frames": 3,
            "frames_with_person": 2, "model": "m", "ms_per_frame": 1.5}
    p = write_sidecar(tmp_path, info)
    assert p.name == "video.json" and json.loads(p.read_text()) == info
    assert is_ours("video.json") and is_ours("x_000000000001_keypoints.json")
    assert not is_ours("notes.txt") and not is_ours("x_0001_keypoints.json")


def test_pixel_conversion():
    pts = [SimpleNamespace(x=i / 32, y=1 - i / 32, visibility=0.9, presence=0.0) for i in range(33)]
    lm = to_pixels(pts, 1088, 1920)
    # 0..1 spans the outer edges; pixel coordinates have their origin at the top-left pixel's centre
    assert lm.x_px[0] == -0.5 and lm.x_px[32] == pytest.approx(1087.5)
    assert lm.y_px[0] == pytest.approx(1919.5) and lm.y_px[32] == -0.5
    assert lm.x_px[16] == pytest.approx(543.5) and lm.y_px[16] == pytest.approx(959.5)
    assert lm.visibility == (0.9,) * 33
    # x scales with the width, y with the height (not the other way round)
    off = to_pixels([SimpleNamespace(x=0.25, y=0.75, visibility=1.0)] * 33, 400, 200)
    assert (off.x_px[0], off.y_px[0]) == (99.5, 149.5)
    # points MediaPipe extrapolates off the image keep their coordinates
    out = to_pixels([SimpleNamespace(x=-0.1, y=1.2, visibility=0.1)] * 33, 100, 100)
    assert out.x_px[0] == pytest.approx(-10.5) and out.y_px[0] == pytest.approx(119.5)
    with pytest.raises(ValueError):
        to_pixels(pts[:32], 10, 10)


def test_presence_only_when_reported():
    class Proto(SimpleNamespace):
        def HasField(self, name):
            return name == "presence" and self.has

    unset = [Proto(x=0.5, y=0.5, visibility=0.7, presence=0.0, has=False)] * 33
    assert to_pixels(unset, 10, 10).presence is None
    set_ = [Proto(x=0.5, y=0.5, visibility=0.7, presence=0.8, has=True)] * 33
    assert to_pixels(set_, 10, 10).presence == (0.8,) * 33
