#!/usr/bin/env bash
# Regenerates the offline-review figures in docs/review/: a demo session, its review page
# in headless Chromium (screenshot), its self-contained report, and a before/after-adaptation
# comparison from the digital twin. Needs chromium and `npm ci --prefix web`.
set -euo pipefail
cd "$(dirname "$0")/../.."
out=docs/review
tmp=$(mktemp -d)
trap 'kill "${server:-0}" 2>/dev/null || true; rm -rf "$tmp"' EXIT
cargo build --release --locked -p ergocell
bin=target/release/ergocell

# The README's demo (default seed and cycles).
"$bin" demo --out "$tmp/demo.mcap" >/dev/null
# The committed report and its CSV exports are regenerated in place: overwritten on purpose.
"$bin" report "$tmp/demo.mcap" --out "$out/demo-report.html" --force \
  --csv "$out/demo-frames.csv" --summary-csv "$out/demo-summary.csv"
"$bin" review "$tmp/demo.mcap" --port 0 >"$tmp/review.log" &
server=$!
for _ in $(seq 50); do grep -q '^review: ' "$tmp/review.log" && break; sleep 0.1; done
url=$(sed -n 's/^review: //p' "$tmp/review.log")
node web/e2e/review.e2e.mjs "$url" "$out/review.png"

# Before vs after adaptation for a 1.90 m operator (class c3, who gains: 3.30 → 3.00 on the truth), 5 handover cycles.
"$bin" sim adaptation --seed 1 --out-dir "$tmp" --record-height 1.90 >/dev/null
"$bin" report "$tmp/adaptation_1.90m_before.mcap" --compare "$tmp/adaptation_1.90m_after.mcap" \
  --out "$tmp/compare.html"
node web/e2e/report.e2e.mjs "$tmp/compare.html" "$out/compare-before-after.png"
