#!/usr/bin/env bash
# Issue 17, "from pixels": the path from real video to RULA, checked in CI on Pose2Sim's four-camera demo
# (../shared/data/pose2sim-demo-videos, a Qualisys calibration; cam01 and cam02 are the calibrated
# 1088x1920 image scaled to 1080 and letterboxed). Takes the frames `ergocell-edge detect` wrote
# (.ci/edge.sh) and asserts:
#  - triangulate refuses the letterboxed cameras until their video geometry is declared;
#  - with it, every camera's landmarks triangulate across the four cameras: >= 95 % of the landmarks,
#    a median reprojection error under MAX_MEDIAN_PX overall and MAX_CAMERA_PX per camera (measured
#    on all 100 frames: 15.2 px overall, 9.2-17.8 px per camera; caliscope's own
#    4-camera MediaPipe recording reads 16.0 px overall with the same code: BlazePose's joints are not
#    the same anatomical point in every view. A wrong pose, an axis flip or an undeclared letterbox
#    reads hundreds of pixels or nothing at all);
#  - the detector's error, each view against the other views, is measured and printed (its tables are
#    docs/detector-error.md's Pose2Sim figures);
#  - rula track scores every frame.
# Usage: .ci/pixels.sh target/release/ergocell DETECT_DIR
set -euo pipefail
cd "$(dirname "$0")/.."
bin=$(realpath "$1")
det=$(realpath "$2")
calib=../shared/data/pose2sim-demo-videos/calibration/Calib.qca.txt
MAX_MEDIAN_PX=25
MAX_CAMERA_PX=30
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

if "$bin" triangulate --calibration "$calib" --detections "$det" --rate-hz 60 --out "$tmp/x.trc" > "$tmp/refused.out" 2> "$tmp/refused.err"; then
  echo "FAIL: the letterboxed cameras were triangulated without a declared video geometry" >&2
  exit 1
fi
grep -q "its video is 1080x1920 (its folder's video.json) but it was calibrated at 1088x1920" "$tmp/refused.err" \
  || { cat "$tmp/refused.err" >&2; echo "FAIL: not the video-geometry refusal" >&2; exit 1; }
echo "   refused without --video-geometry: $(grep -o 'camera cam0[12]: its video is [0-9x]*' "$tmp/refused.err")"

"$bin" triangulate --calibration "$calib" --detections "$det" --rate-hz 60 \
  --video-geometry cam01=fit --video-geometry cam02=fit --out "$tmp/demo.trc" \
  --detector-error "$tmp/detector-error.json" > "$tmp/tri.out" 2> "$tmp/tri.err" \
  || { cat "$tmp/tri.err" >&2; exit 1; }
grep -E "frames:|triangulated|median reprojection|swaps|variation" "$tmp/tri.out"
sed -n '/^detector error/,/^wrote/p' "$tmp/tri.out"
python3 - "$tmp/tri.out" "$MAX_MEDIAN_PX" "$MAX_CAMERA_PX" <<'PY'
import re, sys
text = open(sys.argv[1]).read()
max_median, max_camera = float(sys.argv[2]), float(sys.argv[3])
share = float(re.search(r"landmarks triangulated: +\d+ of \d+ \(([\d.]+)%\)", text).group(1))
median = float(re.search(r"median reprojection err: +([\d.]+) px", text).group(1))
cameras = {c: float(m) for c, m in re.findall(r"camera (cam0\d) +median reprojection ([\d.]+) px", text)}
assert share >= 95.0, f"only {share} % of the landmarks triangulated"
assert median < max_median, f"median reprojection {median} px >= {max_median}"
assert sorted(cameras) == ["cam01", "cam02", "cam03", "cam04"], cameras
bad = {c: m for c, m in cameras.items() if m >= max_camera}
assert not bad, f"cameras over {max_camera} px: {bad}"
print(f"   ok: {share} % triangulated, median {median} px (< {max_median}), per camera {cameras} (< {max_camera})")
PY

"$bin" rula track --landmarks "$tmp/demo.trc" --rig "$calib" > "$tmp/rula.out"
frames=$(grep -oE "^summary: [0-9]+ frames over [0-9.]+ s, [0-9]+ scored" "$tmp/rula.out")
echo "   rula track: $frames"
python3 - "$frames" <<'PY'
import re, sys
n, scored = map(int, re.match(r"summary: (\d+) frames over [\d.]+ s, (\d+) scored", sys.argv[1]).groups())
assert n > 0 and scored == n, sys.argv[1]
PY
