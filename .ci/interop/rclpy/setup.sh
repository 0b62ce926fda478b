#!/usr/bin/env bash
# A real ROS 2 stack for CI, with no ROS install: ROS 2 Kilted's rclpy with Fast DDS
# (rmw_fastrtps_cpp) from PyPI wheels, in a venv, and ergocell_msgs generated for it from
# ros2/ergocell_msgs with the rosidl generators from those wheels (no colcon, no cmake), compiled
# with gcc. ../shared/reference/ros2-peers.md has what was verified and the traps.
# Usage: .ci/interop/rclpy/setup.sh DIR   (creates DIR/venv and DIR/ws; prints the env to source)
set -euo pipefail
cd "$(dirname "$0")/../../.."
root=$(realpath -m "${1:?usage: setup.sh DIR}")
V=$root/venv
mkdir -p "$root"
if [ ! -x "$V/bin/python" ]; then
  python3 -m venv "$V"
  "$V/bin/pip" install -q --disable-pip-version-check \
    ros-kilted-rclpy ros-kilted-std-msgs ros-kilted-rmw-fastrtps-cpp ros-kilted-sensor-msgs \
    ros-kilted-trajectory-msgs ros-kilted-action-msgs mcap \
    ros-kilted-rosidl-generator-py ros-kilted-rosidl-generator-c ros-kilted-rosidl-typesupport-c \
    ros-kilted-rosidl-typesupport-fastrtps-c ros-kilted-rosidl-typesupport-introspection-c \
    ros-kilted-rosidl-adapter ros-kilted-rosidl-cli catkin_pkg
fi
# build_pkg <package> <source dir with msg/ and action/>: generate C and Python code and typesupports
# with rosidl, compile them into $gen/lib (C libraries) and $gen/python/<package> (the Python package).
build_pkg() {
  local P=$1 src=$2
  local g=$gen/$P
  rm -rf "$g" && mkdir -p "$g/src/$P" "$gen/python/$P"
  cp -r "$src"/msg "$g/src/$P/" 2>/dev/null || true
  cp -r "$src"/action "$g/src/$P/" 2>/dev/null || true
  ( cd "$g/src/$P" && AMENT_PREFIX_PATH=$V "$V/bin/python" "$repo/.ci/interop/rclpy/rosidl_generate.py" \
      "$P" "$g/out" "$V/share" $(ls msg/*.msg action/*.action 2>/dev/null) 2>&1 | grep -v "duplicate entry point" | tail -1 )
  local O=$g/out
  local inc=()
  for k in c fastrtps_c introspection_c; do
    mkdir -p "$g/inc_$k" && ln -sfn "$O/$k" "$g/inc_$k/$P" && inc+=("-I$g/inc_$k")
  done
  for d in "$gen"/*/inc_c "$gen"/*/inc_fastrtps_c "$gen"/*/inc_introspection_c; do inc+=("-I$d"); done
  inc+=("-I$V/include"); for d in "$V"/include/*/; do inc+=("-I$d"); done
  local deps=(std_msgs builtin_interfaces geometry_msgs trajectory_msgs action_msgs unique_identifier_msgs service_msgs)
  local L=(-L"$V/lib" -L"$gen/lib" -Wl,-rpath,"$V/lib" -Wl,-rpath,"$gen/lib")
  local dl=() d
  for d in "${deps[@]}"; do [ -e "$V/lib/lib${d}__rosidl_generator_c.so" ] && dl+=("$d"); done
  lib() { local suffix=$1; local out=(); for d in "${dl[@]}"; do out+=("-l${d}__$suffix"); done; echo "${out[@]}"; }
  local dirs=""
  for k in msg action; do [ -d "$O/c/$k" ] && dirs="$dirs $k"; done
  local cc=(gcc -O1 -shared -fPIC -w "${inc[@]}" -I"$pyinc" -I"$npinc")
  local cxx=(g++ -O1 -shared -fPIC -w -std=c++17 "${inc[@]}")
  "${cc[@]}" -o "$gen/lib/lib${P}__rosidl_generator_c.so" $(for k in $dirs; do ls "$O"/c/$k/detail/*.c; done) \
    "${L[@]}" -lrosidl_runtime_c -lrcutils $(lib rosidl_generator_c)
  "${cxx[@]}" -o "$gen/lib/lib${P}__rosidl_typesupport_c.so" $(for k in $dirs; do ls "$O"/c/$k/*__type_support.cpp; done) \
    "${L[@]}" -l${P}__rosidl_generator_c -lrosidl_typesupport_c -lrosidl_runtime_c -lrcutils $(lib rosidl_typesupport_c)
  "${cxx[@]}" -o "$gen/lib/lib${P}__rosidl_typesupport_fastrtps_c.so" $(for k in $dirs; do ls "$O"/fastrtps_c/$k/detail/*.cpp; done) \
    "${L[@]}" -l${P}__rosidl_generator_c -lrosidl_typesupport_fastrtps_c -lfastcdr -lrmw -lrosidl_runtime_c -lrcutils \
    $(lib rosidl_typesupport_fastrtps_c) $(lib rosidl_generator_c)
  "${cc[@]}" -o "$gen/lib/lib${P}__rosidl_typesupport_introspection_c.so" $(for k in $dirs; do ls "$O"/introspection_c/$k/detail/*.c; done) \
    "${L[@]}" -l${P}__rosidl_generator_c -lrosidl_typesupport_introspection_c -lrosidl_runtime_c -lrcutils \
    $(lib rosidl_typesupport_introspection_c)
  "${cc[@]}" -o "$gen/lib/lib${P}__rosidl_generator_py.so" $(for k in $dirs; do ls "$O"/py/$k/*_s.c; done) \
    "${L[@]}" -l${P}__rosidl_generator_c -lrosidl_runtime_c -lrcutils $(lib rosidl_generator_py) $(lib rosidl_generator_c)
  local ts
  for ts in c fastrtps_c introspection_c; do
    "${cc[@]}" -o "$gen/python/$P/${P}_s__rosidl_typesupport_${ts}.so" "$O/py/_${P}_s.ep.rosidl_typesupport_${ts}.c" \
      "${L[@]}" -l${P}__rosidl_generator_py -l${P}__rosidl_typesupport_${ts} -l${P}__rosidl_generator_c -lrosidl_runtime_c
  done
  for k in $dirs; do cp -r "$O/py/$k" "$gen/python/$P/$k"; done
  : > "$gen/python/$P/__init__.py"
}
repo=$PWD
gen=$root/gen
rm -rf "$gen" && mkdir -p "$gen/lib" "$gen/python"
pyinc=$("$V/bin/python" -c 'import sysconfig; print(sysconfig.get_paths()["include"])')
npinc=$("$V/bin/python" -c 'import numpy; print(numpy.get_include())')
build_pkg ergocell_msgs ros2/ergocell_msgs
# control_msgs is not on PyPI: its FollowJointTrajectory action and the two tolerance messages, from
# upstream control_msgs 6.8.0 (BSD-3-Clause, LICENSE beside them; 6.3+ has Feedback.index).
build_pkg control_msgs .ci/interop/rclpy/control_msgs
# kuka_driver_interfaces' HardwareEvent (two fields, ros2/kuka_driver_interfaces), for the driver's
# event_broadcaster/hardware_event.
build_pkg kuka_driver_interfaces ros2/kuka_driver_interfaces
echo "export PYTHONPATH=$gen/python LD_LIBRARY_PATH=$gen/lib RMW_IMPLEMENTATION=rmw_fastrtps_cpp ROS_DISTRO=kilted"
