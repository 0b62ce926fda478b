"""The ROS 2 launch file (deploy/ros2/ergocell.launch.py) checked where ROS 2's `launch` package does
not install (it is not on PyPI): loaded under stand-ins for `launch` that record what it declares
and starts, and every process it starts checked against the program's own `--help` (each option
it passes exists) and the reference rig (each camera id is one of its cameras).

Usage: python3 .ci/launch_check.py ERGOCELL_BIN ERGOCELL_EDGE_BIN
"""

import importlib.util
import re
import subprocess
import sys
import tempfile
import tomllib
import types

ergocell_bin, edge_bin = sys.argv[1], sys.argv[2]
declared, started = {}, []


class LaunchConfiguration:
    def __init__(self, name):
        self.name = name

    def perform(self, context):
        return context[self.name]


class DeclareLaunchArgument:
    def __init__(self, name, default_value, description):
        assert description, f"launch argument {name} has no description"
        declared[name] = default_value


class ExecuteProcess:
    def __init__(self, cmd, name, output, sigterm_timeout, additional_env, on_exit):
        assert additional_env.get("ERGOCELL_STATE_DIR"), f"{name}: no ERGOCELL_STATE_DIR"
        started.append((name, cmd))
        if name == "ergocell_run":
            assert on_exit and isinstance(on_exit[0].event, Shutdown), "the launch outlives run"


class Shutdown:
    def __init__(self, reason):
        self.reason = reason


class EmitEvent:
    def __init__(self, event):
        self.event = event


class OpaqueFunction:
    def __init__(self, function):
        self.function = function


class LaunchDescription:
    def __init__(self, entities):
        self.entities = entities


launch = types.ModuleType("launch")
launch.LaunchDescription = LaunchDescription
launch.actions = types.ModuleType("launch.actions")
launch.actions.DeclareLaunchArgument = DeclareLaunchArgument
launch.actions.ExecuteProcess = ExecuteProcess
launch.actions.OpaqueFunction = OpaqueFunction
launch.actions.EmitEvent = EmitEvent
launch.events = types.ModuleType("launch.events")
launch.events.Shutdown = Shutdown
launch.substitutions = types.ModuleType("launch.substitutions")
launch.substitutions.LaunchConfiguration = LaunchConfiguration
sys.modules.update({"launch": launch, "launch.actions": launch.actions,
                    "launch.events": launch.events, "launch.substitutions": launch.substitutions})

spec = importlib.util.spec_from_file_location("ergocell_launch", "deploy/ros2/ergocell.launch.py")
module = importlib.util.module_from_spec(spec)
spec.loader.exec_module(module)
description = module.generate_launch_description()
functions = [e for e in description.entities if isinstance(e, OpaqueFunction)]
assert len(functions) == 1, description.entities
with tempfile.TemporaryDirectory() as recordings:
    context = dict(declared, recordings=recordings, display="127.0.0.1:8090",
                   ergocell=ergocell_bin, edge=edge_bin)
    functions[0].function(context)
names = [name for name, _ in started]
assert names == ["edge_s1_left", "edge_s2_left", "edge_s3_left", "ergocell_run"], names

rig = tomllib.load(open("config/rig.toml", "rb"))
cameras = {c["id"] for c in rig["camera"]}
helps = {}
for name, argv in started:
    exe, sub = argv[0], argv[1]
    if (exe, sub) not in helps:
        helps[exe, sub] = subprocess.run([exe, sub, "--help"], capture_output=True, text=True,
                                         check=True).stdout
    for option in (a for a in argv[2:] if a.startswith("--")):
        assert re.search(rf"(?<![\w-]){re.escape(option)}(?![\w-])", helps[exe, sub]), \
            f"{name}: {sub} has no option {option}"
    for flag in ("--camera", "--right-camera"):
        if flag in argv:
            camera = argv[argv.index(flag) + 1]
            assert camera in cameras, f"{name}: {flag} {camera} is not a camera of config/rig.toml"
    print(f"   ok: {name}: {' '.join([exe.rsplit('/', 1)[-1]] + argv[1:])}")

# a bad edge_nodes entry is refused with the entry named, before anything starts
for bad in ["s1_left", "@/dev/video0", "s1_left:@/dev/video0", "s1_left@"]:
    try:
        module.edge_nodes(bad)
    except module.BadEdgeNodes as e:
        assert repr(bad) in str(e), e
    else:
        raise AssertionError(f"edge_nodes {bad!r} accepted")
print(f"   ok: the launch file loads, declares {len(declared)} arguments and starts "
      f"{len(started)} processes, every option in each program's --help")
