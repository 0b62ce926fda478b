"""`detect` end to end with a stand-in detector (synthetic videos), and its refusals."""

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

from ergocell_edge import EdgeError
from ergocell_edge.cli import main
from ergocell_edge.detect import run_detect
from ergocell_edge.stop import StopFlag
from helpers import FakeDetector, make_video


def files(folder: Path):
    return sorted(p.name for p in folder.iterdir())


def test_one_folder_per_video_and_a_file_per_frame(tmp_path):
    red = make_video(tmp_path / "camA.avi", 4, 64, 48, left=(0, 0, 255), right=(0, 0, 255))
    blue = make_video(tmp_path / "camB.avi", 3, 64, 48, left=(255, 0, 0), right=(255, 0, 0))
    out = tmp_path / "out"
    jobs = run_detect([str(red), str(blue)], str(out), detector_factory=FakeDetector, model="fake",
                      progress=False)
    assert [o.name for j in jobs for o in j.outputs] == ["camA", "camB"]
    assert files(out / "camA") == [f"camA_{k:012d}_keypoints.json" for k in range(4)] + ["video.json"]
    assert files(out / "camB") == [f"camB_{k:012d}_keypoints.json" for k in range(3)] + ["video.json"]
    doc = json.loads((out / "camA" / "camA_000000000002_keypoints.json").read_text())
    flat = doc["people"][0]["pose_keypoints_2d"]
    assert len(flat) == 99 and flat[0] == pytest.approx(0.1 * 64) and flat[1] == pytest.approx(0.05 * 48)
    # nobody in the blue video: a file per frame all the same, with no people
    for k in range(3):
        assert json.loads((out / "camB" / f"camB_{k:012d}_keypoints.json").read_text())["people"] == []
    side = json.loads((out / "camA" / "video.json").read_text())
    assert side["source"] == "camA.avi" and (side["width"], side["height"]) == (64, 48)
    assert side["frames"] == 4 and side["frames_with_person"] == 4 and side["fps"] == pytest.approx(30.0)
    assert side["model"] == "fake" and side["ms_per_frame"] == pytest.approx(2.0)
    assert json.loads((out / "camB" / "video.json").read_text())["frames_with_person"] == 0


def test_max_frames(tmp_path):
    v = make_video(tmp_path / "c.avi", 6, 32, 32)
    run_detect([str(v)], str(tmp_path / "o"), max_frames=2, detector_factory=FakeDetector, model="f",
               progress=False)
    assert len([f for f in files(tmp_path / "o" / "c") if f.endswith("_keypoints.json")]) == 2
    assert json.loads((tmp_path / "o" / "c" / "video.json").read_text())["frames"] == 2


def test_side_by_side_halves_are_two_cameras(tmp_path):
    # left half red (a person for the fake detector), right half blue (nobody); 66 px -> two 33 px halves
    v = make_video(tmp_path / "zed.avi", 3, 66, 40, left=(0, 0, 255), right=(255, 0, 0))
    FakeDetector.instances.clear()
    run_detect([str(v)], str(tmp_path / "o"), side_by_side=True, detector_factory=FakeDetector, model="f",
               progress=False)
    left, right = tmp_path / "o" / "zed_left", tmp_path / "o" / "zed_right"
    assert "zed_left_000000000000_keypoints.json" in files(left)
    assert "zed_right_000000000002_keypoints.json" in files(right)
    # one detector (tracker) per half, each given only its half
    a, b = FakeDetector.instances
    assert a.shapes == [(40, 33)] * 3 and b.shapes == [(40, 33)] * 3
    assert a.means[0][2] > 200 and b.means[0][0] > 200
    sl, sr = (json.loads((d / "video.json").read_text()) for d in (left, right))
    assert (sl["width"], sl["height"], sl["x_offset_px"], sl["side_by_side"]) == (33, 40, 0, "left")
    assert (sr["width"], sr["x_offset_px"], sr["side_by_side"], sr["source_width"]) == (33, 33, "right", 66)
    assert sl["frames_with_person"] == 3 and sr["frames_with_person"] == 0
    # pixels of a half are in that half's own frame
    doc = json.loads((left / "zed_left_000000000001_keypoints.json").read_text())
    assert doc["people"][0]["pose_keypoints_2d"][0] == pytest.approx(0.1 * 33)


def test_side_by_side_ids(tmp_path):
    v = make_video(tmp_path / "zed.avi", 2, 40, 20)
    run_detect([str(v)], str(tmp_path / "o"), side_by_side=True, side_by_side_ids=["s1_left", "s1_right"],
               detector_factory=FakeDetector, model="f", progress=False)
    assert files(tmp_path / "o") == ["s1_left", "s1_right"]
    assert "s1_right_000000000001_keypoints.json" in files(tmp_path / "o" / "s1_right")
    with pytest.raises(EdgeError):
        run_detect([str(v)], str(tmp_path / "p"), side_by_side_ids=["a", "b"], detector_factory=FakeDetector)
    with pytest.raises(EdgeError):
        run_detect([str(v), str(v)], str(tmp_path / "p"), side_by_side=True, side_by_side_ids=["a", "b"],
                   detector_factory=FakeDetector)


def test_refuses_to_overwrite_unless_force(tmp_path):
    v = make_video(tmp_path / "cam.avi", 3, 32, 32)
    out = tmp_path / "o"
    run_detect([str(v)], str(out), detector_factory=FakeDetector, model="f", progress=False)
    before = (out / "cam" / "video.json").read_text()
    with pytest.raises(EdgeError, match="not empty"):
        run_detect([str(v)], str(out), max_frames=1, detector_factory=FakeDetector, model="f", progress=False)
    assert (out / "cam" / "video.json").read_text() == before
    assert len(files(out / "cam")) == 4
    # an empty existing folder is fine
    (tmp_path / "o2" / "cam").mkdir(parents=True)
    run_detect([str(v)], str(tmp_path / "o2"), detector_factory=FakeDetector, model="f", progress=False)
    # --force replaces the results (no stale frames left) and keeps foreign files
    (out / "cam" / "notes.txt").write_text("mine")
    run_detect([str(v)], str(out), force=True, max_frames=1, detector_factory=FakeDetector, model="f",
               progress=False)
    assert files(out / "cam") == ["cam_000000000000_keypoints.json", "notes.txt", "video.json"]


def test_refuses_output_equal_to_or_inside_an_input(tmp_path):
    v = make_video(tmp_path / "cam.avi", 2, 32, 32)
    with pytest.raises(EdgeError, match="input"):
        run_detect([str(v)], str(v), detector_factory=FakeDetector)
    with pytest.raises(EdgeError, match="input"):
        run_detect([str(v)], str(v / "sub"), detector_factory=FakeDetector)
    # an input inside its own output folder
    inner = tmp_path / "o" / "cam2"
    inner.mkdir(parents=True)
    w = make_video(inner / "cam2.avi", 2, 32, 32)
    with pytest.raises(EdgeError, match="inside"):
        run_detect([str(w)], str(tmp_path / "o"), force=True, detector_factory=FakeDetector)
    assert w.exists()


def test_duplicate_stems_refused(tmp_path):
    (tmp_path / "a").mkdir()
    (tmp_path / "b").mkdir()
    v1 = make_video(tmp_path / "a" / "cam.avi", 2, 32, 32)
    v2 = make_video(tmp_path / "b" / "cam.avi", 2, 32, 32)
    with pytest.raises(EdgeError, match="two outputs"):
        run_detect([str(v1), str(v2)], str(tmp_path / "o"), detector_factory=FakeDetector)


def test_stop_flag_stops_between_frames(tmp_path):
    v = make_video(tmp_path / "cam.avi", 5, 32, 32)
    stop = StopFlag()

    class StopAfterTwo(FakeDetector):
        def detect(self, bgr):
            r = super().detect(bgr)
            if len(self.shapes) == 2:
                stop.set("SIGTERM")
            return r

    jobs = run_detect([str(v)], str(tmp_path / "o"), detector_factory=StopAfterTwo, model="f", stop=stop,
                      progress=False)
    assert jobs[0].interrupted and jobs[0].outputs[0].frames == 2
    side = json.loads((tmp_path / "o" / "cam" / "video.json").read_text())
    assert side["frames"] == 2 and side["interrupted"] is True


def run_cli(*args, cwd=None):
    env = dict(os.environ)
    return subprocess.run([sys.executable, "-m", "ergocell_edge", *args], capture_output=True, text=True,
                          cwd=cwd, env=env, timeout=120)


def test_cli_user_errors_have_no_traceback(tmp_path):
    r = run_cli("detect", str(tmp_path / "missing.mp4"), "--out", str(tmp_path / "o"))
    assert r.returncode == 2 and "file not found" in r.stderr and "Traceback" not in r.stderr
    bad = tmp_path / "bad.mp4"
    bad.write_bytes(b"not a video at all")
    r = run_cli("detect", str(bad), "--out", str(tmp_path / "o"))
    assert r.returncode == 2 and "bad.mp4" in r.stderr and "Traceback" not in r.stderr
    assert not (tmp_path / "o").exists()
    r = run_cli("detect", str(bad), "--out", str(tmp_path / "o"), "--model-complexity", "2")
    assert r.returncode == 2 and "model complexity 2" in r.stderr and "Traceback" not in r.stderr
    v = make_video(tmp_path / "cam.avi", 2, 32, 32)
    (tmp_path / "o" / "cam").mkdir(parents=True)
    (tmp_path / "o" / "cam" / "cam_000000000000_keypoints.json").write_text("{}")
    r = run_cli("detect", str(v), "--out", str(tmp_path / "o"))
    assert r.returncode == 2 and "--force" in r.stderr and "Traceback" not in r.stderr


def test_cli_main_in_process(tmp_path, capsys):
    assert main(["detect", str(tmp_path / "nope.avi"), "--out", str(tmp_path / "o")]) == 2
    assert "file not found" in capsys.readouterr().err
