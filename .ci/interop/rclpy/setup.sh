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
    ros-kilted-trajectory-msgs mcap \
    ros-kilted-rosidl-generator-py ros-kilted-rosidl-generator-c ros-kilted-rosidl-typesupport-c \
    ros-kilted-rosidl-typesupport-fastrtps-c ros-kilted-rosidl-typesupport-introspection-c \
    ros-kilted-rosidl-adapter ros-kilted-rosidl-cli catkin_pkg
fi
P=ergocell_msgs
gen=$root/gen
rm -rf "$gen" && mkdir -p "$gen/src/$P" "$gen/lib" "$gen/python/$P"
cp -r ros2/$P/msg "$gen/src/$P/"
( cd "$gen/src/$P" && AMENT_PREFIX_PATH=$V "$V/bin/python" "$OLDPWD/.ci/interop/rclpy/rosidl_generate.py" \
    $P "$gen/out" "$V/share" msg/*.msg 2>&1 | grep -v "duplicate entry point" | tail -1 )
O=$gen/out
inc=()
for k in c fastrtps_c introspection_c; do
  mkdir -p "$gen/inc_$k" && ln -sfn "$O/$k" "$gen/inc_$k/$P" && inc+=("-I$gen/inc_$k")
done
inc+=("-I$V/include"); for d in "$V"/include/*/; do inc+=("-I$d"); done
pyinc=$("$V/bin/python" -c 'import sysconfig; print(sysconfig.get_paths()["include"])')
npinc=$("$V/bin/python" -c 'import numpy; print(numpy.get_include())')
L=(-L"$V/lib" -L"$gen/lib" -Wl,-rpath,"$V/lib" -Wl,-rpath,"$gen/lib")
cc() { gcc -O1 -shared -fPIC -w "${inc[@]}" -I"$pyinc" -I"$npinc" "$@" "${L[@]}"; }
cxx() { g++ -O1 -shared -fPIC -w -std=c++17 "${inc[@]}" "$@" "${L[@]}"; }
cc -o "$gen/lib/lib${P}__rosidl_generator_c.so" "$O"/c/msg/detail/*.c \
  -lrosidl_runtime_c -lrcutils -lstd_msgs__rosidl_generator_c -lbuiltin_interfaces__rosidl_generator_c
cxx -o "$gen/lib/lib${P}__rosidl_typesupport_c.so" "$O"/c/msg/*__type_support.cpp \
  -l${P}__rosidl_generator_c -lrosidl_typesupport_c -lrosidl_runtime_c -lrcutils
cxx -o "$gen/lib/lib${P}__rosidl_typesupport_fastrtps_c.so" "$O"/fastrtps_c/msg/detail/*.cpp \
  -l${P}__rosidl_generator_c -lrosidl_typesupport_fastrtps_c -lfastcdr -lrmw -lrosidl_runtime_c -lrcutils \
  -lstd_msgs__rosidl_typesupport_fastrtps_c -lbuiltin_interfaces__rosidl_typesupport_fastrtps_c \
  -lstd_msgs__rosidl_generator_c -lbuiltin_interfaces__rosidl_generator_c
cc -o "$gen/lib/lib${P}__rosidl_typesupport_introspection_c.so" "$O"/introspection_c/msg/detail/*.c \
  -l${P}__rosidl_generator_c -lrosidl_typesupport_introspection_c -lrosidl_runtime_c -lrcutils \
  -lstd_msgs__rosidl_typesupport_introspection_c -lbuiltin_interfaces__rosidl_typesupport_introspection_c
cc -o "$gen/lib/lib${P}__rosidl_generator_py.so" "$O"/py/msg/*_s.c \
  -l${P}__rosidl_generator_c -lrosidl_runtime_c -lrcutils \
  -lstd_msgs__rosidl_generator_py -lbuiltin_interfaces__rosidl_generator_py \
  -lstd_msgs__rosidl_generator_c -lbuiltin_interfaces__rosidl_generator_c
for ts in c fastrtps_c introspection_c; do
  cc -o "$gen/python/$P/${P}_s__rosidl_typesupport_${ts}.so" "$O/py/_${P}_s.ep.rosidl_typesupport_${ts}.c" \
    -l${P}__rosidl_generator_py -l${P}__rosidl_typesupport_${ts} -l${P}__rosidl_generator_c -lrosidl_runtime_c
done
cp -r "$O/py/msg" "$gen/python/$P/msg"
: > "$gen/python/$P/__init__.py"
echo "export PYTHONPATH=$gen/python LD_LIBRARY_PATH=$gen/lib RMW_IMPLEMENTATION=rmw_fastrtps_cpp ROS_DISTRO=kilted"
