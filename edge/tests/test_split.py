"""Side-by-side stereo frames: the halves' geometry."""

import numpy as np
import pytest

from ergocell_edge import EdgeError
from ergocell_edge.video import parse_source, split_side_by_side


def test_even_width_halves():
    frame = np.arange(4 * 10 * 3, dtype=np.uint16).reshape(4, 10, 3)
    left, right = split_side_by_side(frame)
    assert left.shape == (4, 5, 3) and right.shape == (4, 5, 3)
    assert (left == frame[:, 0:5]).all() and (right == frame[:, 5:10]).all()
    # right-half pixel (x, y) is (x + 5, y) in the full frame
    assert (right[2, 0] == frame[2, 5]).all()


def test_odd_width_drops_last_column():
    frame = np.zeros((3, 11, 3), np.uint8)
    frame[:, 10] = 255  # the odd last column
    left, right = split_side_by_side(frame)
    assert left.shape[1] == right.shape[1] == 5
    assert right.max() == 0


def test_too_narrow():
    with pytest.raises(EdgeError):
        split_side_by_side(np.zeros((2, 1, 3), np.uint8))


def test_parse_source():
    assert parse_source("0").kind == "device" and parse_source("0").target == 0
    assert parse_source("/dev/video2").kind == "device"
    g = parse_source("v4l2src device=/dev/video0 ! videoconvert ! appsink")
    assert g.kind == "gstreamer" and g.live
    f = parse_source("videos/cam01.mp4")
    assert f.kind == "file" and not f.live
