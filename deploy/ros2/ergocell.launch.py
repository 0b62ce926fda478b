"""The cell as one ROS 2 launch: an `ergocell-edge publish` node per camera (or side-by-side stereo
camera) and `ergocell run`, with the commands and the state folder of the systemd units beside it
(deploy/systemd/), without their hardening. For a bench or a cell whose cameras are on the cell PC; on a plant cell each
edge device runs its own node (docs/integrator.md).

    ros2 launch deploy/ros2/ergocell.launch.py site:=/srv/ergocell \\
        edge_nodes:='s1_left:s1_right@/dev/video0;s2_left:s2_right@/dev/video2;s3_left:s3_right@/dev/video4'

Start the robot driver first, and configure and activate it once the cell runs (docs/integrator.md,
section 5). Ctrl-C (SIGINT) holds the robot, closes the recording and stops every node.

`commands` is the whole plan and needs no ROS: `.ci/launch_check.py` checks every executable and
option in it against the programs' own `--help`.
"""

import os
import time

# name, default, description: the launch arguments (`ros2 launch ... name:=value`)
ARGUMENTS = [
    ("site", "/srv/ergocell",
     "the site folder: config/cell.toml, config/rig.toml and trajectories/ (locks and approvals)"),
    ("state_dir", "/var/lib/ergocell",
     "ERGOCELL_STATE_DIR: the approvals witness, as the systemd unit keeps it"),
    ("recordings", "/var/lib/ergocell/recordings",
     "where `ergocell run` records; one file per launch, named by its UTC start time"),
    ("edge_nodes", "s1_left:s1_right@/dev/video0;s2_left:s2_right@/dev/video2;s3_left:s3_right@/dev/video4",
     "the edge nodes, ';'-separated: CAMERA@SOURCE, or LEFT:RIGHT@SOURCE for a side-by-side stereo "
     "camera (camera ids as in the rig; SOURCE a /dev/videoN, a video file or a GStreamer pipeline); "
     "empty: no edge node here"),
    ("display", "", "the operator display's address, e.g. 127.0.0.1:8090; empty: none"),
    ("ergocell", "ergocell", "the cell controller's executable"),
    ("edge", "ergocell-edge", "the edge node's executable (e.g. /opt/ergocell-edge/venv/bin/ergocell-edge)"),
]


class BadEdgeNodes(ValueError):
    """An `edge_nodes` entry that is not CAMERA@SOURCE or LEFT:RIGHT@SOURCE."""


def edge_nodes(text):
    """`edge_nodes` as (camera, right camera or None, source) triples."""
    out = []
    for entry in (e.strip() for e in text.split(";")):
        if not entry:
            continue
        cameras, at, source = entry.partition("@")
        left, colon, right = cameras.strip().partition(":")
        if not at or not source.strip() or not left.strip() or (colon and not right.strip()):
            raise BadEdgeNodes(
                f"edge_nodes entry {entry!r}: expected CAMERA@SOURCE or LEFT:RIGHT@SOURCE")
        out.append((left.strip(), right.strip() or None, source.strip()))
    return out


def commands(values, now=None):
    """The processes to start, as (name, argv), from the launch arguments' `values` (every name of
    ARGUMENTS); `now` (seconds since the epoch) names the recording."""
    site = values["site"]
    cell = os.path.join(site, "config", "cell.toml")
    rig = os.path.join(site, "config", "rig.toml")
    out = []
    for camera, right, source in edge_nodes(values["edge_nodes"]):
        argv = [values["edge"], "publish", "--camera", camera]
        if right:
            argv += ["--right-camera", right]
        argv += ["--source", source, "--rig", rig, "--cell", cell]
        out.append((f"edge_{camera}", argv))
    stamp = time.strftime("%Y%m%dT%H%M%SZ", time.gmtime(time.time() if now is None else now))
    argv = [values["ergocell"], "run", "--config", cell, "--rig", rig,
            "--trajectories", os.path.join(site, "trajectories"),
            "--record", os.path.join(values["recordings"], f"cell-{stamp}.mcap")]
    if values["display"]:
        argv += ["--display", values["display"]]
    out.append(("ergocell_run", argv))
    return out


def _actions(context):
    from launch.actions import EmitEvent, ExecuteProcess
    from launch.events import Shutdown
    from launch.substitutions import LaunchConfiguration

    values = {name: LaunchConfiguration(name).perform(context) for name, _, _ in ARGUMENTS}
    try:
        os.makedirs(values["recordings"], exist_ok=True)
    except OSError as e:
        raise RuntimeError(f"recordings:={values['recordings']}: {e.strerror}; give a folder this "
                           "user can write (recordings:=<folder>)") from None
    actions = []
    for name, argv in commands(values):
        # Ctrl-C: SIGINT to every process (ergocell holds the robot and closes the recording),
        # SIGTERM after 10 s. When `ergocell run` ends (a held robot, exit 1 or 2, needs a person),
        # the whole launch ends with it.
        on_exit = ([EmitEvent(event=Shutdown(reason="ergocell run ended"))]
                   if name == "ergocell_run" else None)
        actions.append(ExecuteProcess(
            cmd=argv, name=name, output="screen", sigterm_timeout="10",
            additional_env={"ERGOCELL_STATE_DIR": values["state_dir"]}, on_exit=on_exit))
    return actions


def generate_launch_description():
    from launch import LaunchDescription
    from launch.actions import DeclareLaunchArgument, OpaqueFunction

    return LaunchDescription(
        [DeclareLaunchArgument(name, default_value=default, description=text)
         for name, default, text in ARGUMENTS]
        + [OpaqueFunction(function=_actions)])
