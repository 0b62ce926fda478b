#!/usr/bin/env bash
# Issue 17, the live path: three `ergocell-edge publish` nodes play Pose2Sim's real videos (cam01, which
# is letterboxed, cam03, cam04) as cameras over ROS 2 (rclpy on Fast DDS), and `ergocell run` — on the
# videos' Qualisys calibration, with cam01's video geometry declared — fuses them over loopback in a
# private network namespace. Asserts the session reaches measuring_height from real pixels, that frames
# were fused and tracked, and that no camera message was rejected (an undeclared letterbox would be).
# Prints the posture warnings' latency from a frame's capture stamp to the operator display painted in
# headless Chromium, beyond the dwell and the fixed lag (docs/measurements.md).
# Needs .ci/edge.sh run with a ROS_DIR first (rclpy, ergocell_msgs and the edge package in
# ROS_DIR/venv, the environment in ROS_DIR/env.sh).
# Usage: .ci/edge-live.sh target/release/ergocell ROS_DIR
set -euo pipefail
cd "$(dirname "$0")/.."
bin=$(realpath "$1")
ros=$(realpath "$2")
[ -f "$ros/env.sh" ] || { echo "error: $ros/env.sh missing: run .ci/edge.sh with ROS_DIR=$2 first" >&2; exit 1; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
# The cameras that publish (cam02 is calibrated but has no video node here): a camera the cell
# expects and never hears makes every frame wait out the assembly's deadline for it.
sed 's/^cameras = \[.*\]/cameras = ["cam01", "cam03", "cam04"]/' config/cell.toml > "$tmp/cell.toml"
grep -q '^cameras = \["cam01", "cam03", "cam04"\]' "$tmp/cell.toml"

unshare -n -- bash -s "$bin" "$ros" "$tmp" <<'NS'
set -euo pipefail
bin=$1 ros=$2 tmp=$3
ip link set lo up
source "$ros/env.sh"
export ROS_DOMAIN_ID=0 ROS_AUTOMATIC_DISCOVERY_RANGE=SUBNET
calib=../shared/data/pose2sim-demo-videos/calibration/Calib.qca.txt
videos=../shared/data/pose2sim-demo-videos/videos
"$bin" --log error run --config "$tmp/cell.toml" --rig "$calib" --video-geometry cam01=fit \
  --max-secs 18 --record "$tmp/live.mcap" --display 127.0.0.1:0 > "$tmp/run.out" 2> "$tmp/run.err" &
run=$!
# the operator display's snapshot (what a page gets first), every second from 8 s in until it shows
# the operator being measured with their skeleton (a snapshot between two tracked frames has none),
# for the check below
( for _ in $(seq 50); do grep -q "operator display: http" "$tmp/run.out" && break; sleep 0.2; done
  url=$(grep -o "operator display: http[^ ]*" "$tmp/run.out" | head -1 | cut -d' ' -f3)
  sleep 8
  for _ in $(seq 9); do
    curl -s -m 2 "${url}events" | grep -m1 "^data: " > "$tmp/display.json" || true
    python3 -c 'import json, sys
s = json.loads(open(sys.argv[1]).read()[len("data: "):])
sys.exit(s["state"] != "measuring_height" or sum(p is not None for p in s["skeleton"]) < 20)' \
      "$tmp/display.json" 2>/dev/null && break
    sleep 1
  done ) &
# From a frame's capture stamp to its posture warning painted in headless Chromium (the page's own
# measurement, web/e2e/display-latency.mjs; the fixed lag is [pipeline]'s default 0.55 s): printed
# below, not asserted.
( for _ in $(seq 50); do grep -q "operator display: http" "$tmp/run.out" && break; sleep 0.2; done
  url=$(grep -o "operator display: http[^ ]*" "$tmp/run.out" | head -1 | cut -d' ' -f3)
  node web/e2e/display-latency.mjs "$url" 16 0.55 > "$tmp/latency.out" 2>&1 \
    || echo "exit $?" >> "$tmp/latency.out" ) &
latency=$!
start=$(python3 -c 'import time; print(time.time() + 5)')
pubs=()
for c in cam01 cam03 cam04; do
  timeout -k 5 40 "$ros/venv/bin/ergocell-edge" publish --camera "$c" --source "$videos/$c.mp4" --rig "$calib" \
    --cell "$tmp/cell.toml" --loop --start-at "$start" --max-frames 600 > "$tmp/$c.log" 2>&1 &
  pubs+=($!)
done
status=0
wait "$run" || status=$?
wait "$latency" || true
for p in "${pubs[@]}"; do wait "$p" || echo "publisher exit $?" >> "$tmp/pub.exit"; done
echo "run exit $status" >> "$tmp/run.out"
NS
grep -E "state |session:|camera message|RULA warning" "$tmp/run.out" | head -20
grep -q "^warning latency: " "$tmp/latency.out" \
  || { cat "$tmp/latency.out" >&2; echo "FAIL: the warnings' capture-to-screen latency was not measured" >&2; exit 1; }
echo "   $(grep "^warning latency: " "$tmp/latency.out")"
for c in cam01 cam03 cam04; do tail -1 "$tmp/$c.log"; done
[ ! -f "$tmp/pub.exit" ] || { cat "$tmp/pub.exit" "$tmp"/cam0*.log >&2; echo "FAIL: a publisher failed" >&2; exit 1; }
grep -q "state waiting_for_operator → measuring_height: operator tracked" "$tmp/run.out" \
  || { cat "$tmp/run.out" "$tmp/run.err" >&2; echo "FAIL: the session did not reach measuring_height" >&2; exit 1; }
python3 - "$tmp/run.out" <<'PY'
import re, sys
text = open(sys.argv[1]).read()
m = re.search(r"session: \w+ — (\d+) frames fused, (\d+) tracked, .* (\d+) camera message\(s\) rejected", text)
assert m, text
fused, tracked, rejected = map(int, m.groups())
assert fused > 50 and tracked > 20, (fused, tracked)
assert rejected == 0, f"{rejected} camera messages rejected"
print(f"   ok: measuring_height reached from real video; {fused} frames fused, {tracked} tracked, 0 messages rejected")
PY
python3 - "$tmp/display.json" <<'PY'
import json, sys
line = open(sys.argv[1]).read().strip()
assert line.startswith("data: "), f"no snapshot from run's operator display: {line!r}"
s = json.loads(line[len("data: "):])
seen = sum(p is not None for p in s["skeleton"])
assert s["state"] == "measuring_height" and seen >= 20, (s["state"], seen)
print(f"   ok: run's operator display (--display) pushed the live state: {s['state']}, {seen} landmarks, "
      f"{len(s['warnings'])} warning(s) on screen, update {s['seq']}")
PY
