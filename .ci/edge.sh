#!/usr/bin/env bash
# The edge camera node (edge/, Python package ergocell-edge) in CI: a venv with the package, its pytest,
# and `ergocell-edge detect` on the first N frames of the four Pose2Sim demo videos
# (../shared/data/pose2sim-demo-videos/videos/cam01..04.mp4), printing the per-camera summary.
#
# Usage (from anywhere; paths are relative to the repo root):
#   bash .ci/edge.sh [VENV_DIR] [OUT_DIR] [N] [ROS_DIR]
#     VENV_DIR  the venv, reused when present          (default target/edge-venv)
#     OUT_DIR   detect's output, replaced (--force)     (default target/edge-out)
#     N         frames per video                        (default 10)
#     ROS_DIR   optional: also run the live ROS 2 test (publish from cam03.mp4, an rclpy subscriber):
#               builds/reuses ROS_DIR with .ci/interop/rclpy/setup.sh (rclpy + generated ergocell_msgs)
#               and installs the package into ROS_DIR/venv (numpy goes down to 1.26 there, which rclpy
#               and the generated messages accept). Use a directory of its own, e.g. target/edge-ros.
#
# Install path: mediapipe and this package with --no-deps, then edge/requirements-nojax.txt: mediapipe's
# run-time dependencies without jax/jaxlib (+scipy, ml_dtypes), sentencepiece and sounddevice, which the
# pose solution never imports (about half the size and time of a plain `pip install ./edge`).
set -euo pipefail
cd "$(dirname "$0")/.."
venv=$(realpath -m "${1:-target/edge-venv}")
out=$(realpath -m "${2:-target/edge-out}")
n=${3:-10}
ros=${4:-}
data=../shared/data/pose2sim-demo-videos/videos
t0=$SECONDS
case "$(uname -m)" in aarch64|arm64) mp=0.10.18 ;; *) mp=0.10.21 ;; esac

# pip's closing "dependency conflicts" report names the packages left out on purpose: drop those lines.
pip_q() {
  local log
  log=$("$1" -m pip install -q --disable-pip-version-check "${@:2}" 2>&1) || { echo "$log"; return 1; }
  printf "%s" "$log" | grep -v -E "dependency resolver does not currently take into account|requires (jax|jaxlib|ml_dtypes|sentencepiece|sounddevice)\b" || true
}
install_edge() {  # $1: the venv's python
  pip_q "$1" --no-deps "mediapipe==$mp"
  pip_q "$1" --no-deps --force-reinstall ./edge
  pip_q "$1" -r edge/requirements-nojax.txt pytest
}

echo "== edge: venv $venv (mediapipe $mp, without jax)"
[ -x "$venv/bin/python" ] || python3 -m venv "$venv"
install_edge "$venv/bin/python"
echo "   installed in $((SECONDS - t0)) s ($(du -sh "$venv" | cut -f1))"

echo "== edge: pytest"
# No bytecode or cache files in the source tree.
PYTHONDONTWRITEBYTECODE=1 "$venv/bin/python" -m pytest -q -p no:cacheprovider edge/tests

if [ -n "$ros" ]; then
  echo "== edge: live ROS 2 test (rclpy + Fast DDS in $ros)"
  env_line=$(bash .ci/interop/rclpy/setup.sh "$ros" | tail -1)
  # for .ci/edge-live.sh: the environment that has rclpy, ergocell_msgs and this package
  echo "$env_line" > "$(realpath -m "$ros")/env.sh"
  rpy=$(realpath -m "$ros")/venv/bin/python
  install_edge "$rpy"
  # A live test that skips would prove nothing here: require rclpy and ergocell_msgs.
  ( eval "$env_line"
    "$rpy" -c 'import rclpy, ergocell_msgs.msg'
    ROS_AUTOMATIC_DISCOVERY_RANGE=LOCALHOST PYTHONDONTWRITEBYTECODE=1 \
      "$rpy" -m pytest -q -p no:cacheprovider -rs -W ignore::DeprecationWarning edge/tests/test_publish_live.py )
fi

echo "== edge: ergocell-edge detect, first $n frames of the four demo videos -> $out"
videos=()
for k in 1 2 3 4; do videos+=("$data/cam0$k.mp4"); done
if [ ! -f "${videos[0]}" ]; then
  echo "   demo videos not found in $data: skipped"
else
  "$venv/bin/ergocell-edge" detect "${videos[@]}" --out "$out" --max-frames "$n" --force --no-progress
fi
echo "== edge: done in $((SECONDS - t0)) s"
