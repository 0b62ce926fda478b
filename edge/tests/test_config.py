"""Rig and cell files: camera ids (ergocell TOML, Qualisys XML), [ros] domain and topic."""

import pytest

from ergocell_edge import EdgeError
from ergocell_edge.config import check_camera, rig_camera_ids, ros_settings

QCA = """<?xml version='1.0' encoding='ASCII'?>
<calibration type="regular">
  <cameras>
    <camera active="1" serial="cam01"><intrinsic focalLengthU="1"/></camera>
    <camera active="1" serial="cam02"/>
  </cameras>
</calibration>
"""


def test_repo_rig_and_cell(repo):
    ids = rig_camera_ids(repo / "config" / "rig.toml")
    assert ids == ["s1_left", "s1_right", "s2_left", "s2_right", "s3_left", "s3_right"]
    ros = ros_settings(repo / "config" / "cell.toml")
    assert ros.domain_id == 0
    assert ros.topic("s1_left") == "/ergocell/camera/s1_left/landmarks"
    assert ros.cameras == tuple(ids)


def test_toml_rig(tmp_path):
    p = tmp_path / "rig.toml"
    p.write_text('up = [0.0, 0.0, 1.0]\n[[camera]]\nid = "a"\n[[camera]]\nid = "b"\n[[stereo_pair]]\nname = "x"\n')
    assert rig_camera_ids(p) == ["a", "b"]
    p.write_text('up = [0.0, 0.0, 1.0]\n')
    with pytest.raises(EdgeError, match="no camera ids"):
        rig_camera_ids(p)
    p.write_text('[[camera]\n')
    with pytest.raises(EdgeError, match="TOML"):
        rig_camera_ids(p)


def test_qca_rig(tmp_path):
    p = tmp_path / "Calib.qca.txt"
    p.write_text(QCA)
    assert rig_camera_ids(p) == ["cam01", "cam02"]
    # any name: XML is recognised by its content
    q = tmp_path / "calib"
    q.write_text(QCA)
    assert rig_camera_ids(q) == ["cam01", "cam02"]


def test_demo_qca(repo):
    p = repo.parent / "shared" / "data" / "pose2sim-demo-videos" / "calibration" / "Calib.qca.txt"
    if not p.is_file():
        pytest.skip("demo data not present")
    assert rig_camera_ids(p) == ["cam01", "cam02", "cam03", "cam04"]


def test_unknown_camera_lists_known():
    with pytest.raises(EdgeError) as e:
        check_camera("cam9", ["cam01", "cam02"], "rig.toml")
    assert "cam9" in str(e.value) and "cam01, cam02" in str(e.value)
    check_camera("cam02", ["cam01", "cam02"], "rig.toml")


def test_missing_rig(tmp_path):
    with pytest.raises(EdgeError, match="not found"):
        rig_camera_ids(tmp_path / "none.toml")


def test_cell_ros(tmp_path):
    p = tmp_path / "cell.toml"
    p.write_text('[ros]\ndomain_id = 42\ncamera_topic = "/x/{id}/lm"\n')
    ros = ros_settings(p)
    assert ros.domain_id == 42 and ros.topic("c1") == "/x/c1/lm" and ros.cameras is None
    p.write_text('[robot]\nurdf = "x"\n')
    ros = ros_settings(p)
    assert ros.domain_id == 0 and ros.topic("c") == "/ergocell/camera/c/landmarks"
    p.write_text('[ros]\ndomain_id = 300\n')
    with pytest.raises(EdgeError, match="domain_id"):
        ros_settings(p)
    p.write_text('[ros]\ncamera_topic = "/no/placeholder"\n')
    with pytest.raises(EdgeError, match="camera_topic"):
        ros_settings(p)
