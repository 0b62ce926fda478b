# Runs rosidl's generators from the ROS 2 wheels without colcon/cmake (the `rosidl` CLI refuses the
# wheels' duplicate entry points: they ship both .dist-info and .egg-info).
import pathlib, sys
import rosidl_cli.entry_points as ep
_get = ep.get_entry_points
ep.get_entry_points = lambda group, specs=None, strict=False: _get(group, specs=specs, strict=False)
from rosidl_cli.command.generate.api import generate
pkg, out, inc = sys.argv[1], pathlib.Path(sys.argv[2]), sys.argv[3]
files = sys.argv[4:]
res = generate(package_name=pkg, interface_files=files, include_paths=[inc], output_path=out,
               types=["c", "py"], typesupports=["c", "fastrtps_c", "introspection_c"])
print(sum(len(r) for r in res), "files")
