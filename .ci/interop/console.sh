#!/usr/bin/env bash
# The console of `ergocell run` where the interface has no multicast (a network namespace with
# loopback only, as in a container): the cell's own lines, and what the missing multicast route means
# said once — not RustDDS's per-message warnings (about 140 lines of 1.2 KB in four seconds before).
#
#   bash .ci/interop/console.sh [path/to/ergocell]
#
# Asserts, for 15 s of `run` at the default log level with no edge node running: the reference
# cell's start-up says in its first 10 lines that no class can run and why; the multicast note
# exactly once, no RustDDS "No locators" or "leave_multicast_group" line, and the whole console
# (stdout + stderr) at most 12 lines and under 8 KB. Prints the counts.
set -euo pipefail
cd "$(dirname "$0")/../.."
bin=${1:-target/release/ergocell}
bin=$(realpath "$bin")
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
unshare -n -- bash -c '
  set -euo pipefail
  ip link set lo up
  cd "$2"
  # SIGINT after 15 s, like Ctrl-C; `run` then holds the robot and exits 130.
  # stdout and stderr as a terminal shows them, interleaved.
  timeout -s INT 15 "$1" run --config "$3/config/cell.toml" > console.txt 2>&1 || true
' _ "$bin" "$tmp" "$PWD"
lines=$(wc -l < "$tmp/console.txt")
bytes=$(wc -c < "$tmp/console.txt")
notes=$(grep -c "DDS discovery: no multicast on this machine" "$tmp/console.txt" || true)
noise=$(grep -c "No locators\|leave_multicast_group\|No multicast joins succeeded" "$tmp/console.txt" || true)
early=$(head -10 "$tmp/console.txt" | grep -c "robot: no class can run, the robot will not move for any operator: c1, c2, c3: not approved" || true)
echo "ergocell run, 15 s, loopback only, no edge node: $lines lines, $bytes bytes; multicast note $notes time(s); RustDDS noise $noise line(s); no class can run said in the first 10 lines: $early"
fail=0
[ "$early" = 1 ] || { echo "the first 10 lines do not say that no class can run and why" >&2; fail=1; }
[ "$notes" = 1 ] || { echo "expected the multicast note exactly once" >&2; fail=1; }
[ "$noise" = 0 ] || { echo "RustDDS's per-message warnings reached the console" >&2; fail=1; }
[ "$lines" -le 12 ] || { echo "console too long: $lines lines" >&2; fail=1; }
[ "$bytes" -lt 8192 ] || { echo "console too long: $bytes bytes" >&2; fail=1; }
grep -q "session: session_ended" "$tmp/console.txt" || { echo "run did not end its session" >&2; fail=1; }
# A console that goes away (`ergocell run 2>&1 | head -3`): the cell goes on and Ctrl-C still holds
# the robot and exits 130, no panic on the closed pipe (exit 101).
piped=$(unshare -n -- bash -c '
  ip link set lo up
  cd "$2"
  timeout --preserve-status -s INT 5 "$1" run --config "$3/config/cell.toml" 2>&1 | head -3 >/dev/null
  echo "${PIPESTATUS[0]}"
' _ "$bin" "$tmp" "$PWD")
echo "ergocell run 2>&1 | head -3: exit $piped"
[ "$piped" = 130 ] || { echo "run with its console closed exited $piped, not 130 (Ctrl-C)" >&2; fail=1; }
if [ "$fail" != 0 ]; then
  cat "$tmp/console.txt" >&2
  exit 1
fi
