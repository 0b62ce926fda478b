"""The cell's configuration files: the rig's camera ids (ergocell rig TOML or Qualisys .qca.txt XML)
and the [ros] section of the cell TOML (domain, landmark topic)."""

from __future__ import annotations

import sys
import xml.etree.ElementTree as ET
from dataclasses import dataclass
from pathlib import Path
from typing import List, Optional, Sequence

from . import EdgeError

if sys.version_info >= (3, 11):
    import tomllib
else:  # pragma: no cover
    import tomli as tomllib

DEFAULT_TOPIC = "/ergocell/camera/{id}/landmarks"
DEFAULT_RIG = "config/rig.toml"
DEFAULT_CELL = "config/cell.toml"


def _read_toml(path: Path) -> dict:
    try:
        with open(path, "rb") as f:
            return tomllib.load(f)
    except FileNotFoundError:
        raise EdgeError(f"{path}: file not found") from None
    except tomllib.TOMLDecodeError as e:
        raise EdgeError(f"{path}: not valid TOML: {e}") from None


def rig_camera_ids(path) -> List[str]:
    """Camera ids of a rig: an ergocell rig TOML ([[camera]] id = "...") or a Qualisys calibration
    export (.qca.txt, XML: <camera serial="..."> elements)."""
    path = Path(path)
    if not path.is_file():
        raise EdgeError(f"rig {path}: file not found")
    head = path.read_bytes()[:256].lstrip()
    if head.startswith(b"<") or path.name.lower().endswith((".qca.txt", ".xml")):
        try:
            root = ET.parse(path).getroot()
        except ET.ParseError as e:
            raise EdgeError(f"rig {path}: not valid XML: {e}") from None
        ids = [c.get("serial") for c in root.iter("camera") if c.get("serial")]
        kind = "Qualisys calibration (camera serial attributes)"
    else:
        data = _read_toml(path)
        cams = data.get("camera", [])
        if not isinstance(cams, list):
            raise EdgeError(f"rig {path}: [[camera]] must be an array of tables")
        ids = [str(c["id"]) for c in cams if isinstance(c, dict) and "id" in c]
        kind = "ergocell rig ([[camera]] id)"
    if not ids:
        raise EdgeError(f"rig {path}: no camera ids found (read as {kind})")
    return ids


def check_camera(camera_id: str, known: Sequence[str], rig_path) -> None:
    if camera_id not in known:
        raise EdgeError(f"camera {camera_id!r} is not in the rig {rig_path}; its cameras are: "
                        + ", ".join(known))


@dataclass(frozen=True)
class RosSettings:
    domain_id: int = 0
    camera_topic: str = DEFAULT_TOPIC
    cameras: Optional[tuple] = None

    def topic(self, camera_id: str) -> str:
        return self.camera_topic.replace("{id}", camera_id)


def ros_settings(path) -> RosSettings:
    path = Path(path)
    ros = _read_toml(path).get("ros", {})
    if not isinstance(ros, dict):
        raise EdgeError(f"{path}: [ros] must be a table")
    domain = ros.get("domain_id", 0)
    if isinstance(domain, bool) or not isinstance(domain, int) or not 0 <= domain <= 232:
        raise EdgeError(f"{path}: [ros] domain_id must be an integer 0..232, got {domain!r}")
    topic = ros.get("camera_topic", DEFAULT_TOPIC)
    if not isinstance(topic, str) or "{id}" not in topic:
        raise EdgeError(f"{path}: [ros] camera_topic must be a string with {{id}}, got {topic!r}")
    cams = ros.get("cameras")
    return RosSettings(domain, topic, tuple(str(c) for c in cams) if isinstance(cams, list) else None)


def find_default(relative: str) -> Path:
    """A config file relative to the current directory or to one of its parents (the repo's root)."""
    here = Path.cwd()
    for d in (here, *here.parents):
        if (d / relative).is_file():
            return d / relative
    raise EdgeError(f"{relative} not found in {here} or its parents: give its path")
