#!/usr/bin/env bash
# The console of `ergocell run` where the interface has no multicast (a network namespace with
# loopback only, as in a container): the cell's own lines, and what the missing multicast route means
# said once — not RustDDS's per-message warnings (about 140 lines of 1.2 KB in four seconds before).
#
#   bash .ci/interop/console.sh [path/to/ergocell]
#
# Asserts, for 5 s of `run` at the default log level: the multicast note exactly once, no RustDDS
# "No locators" or "leave_multicast_group" line, and the whole console (stdout + stderr) under 40
# lines and 8 KB. Prints the counts.
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
  # SIGINT after 5 s, like Ctrl-C; `run` then holds the robot and exits 130.
  timeout -s INT 5 "$1" run --config "$3/config/cell.toml" > out.txt 2> err.txt || true
' _ "$bin" "$tmp" "$PWD"
cat "$tmp/out.txt" "$tmp/err.txt" > "$tmp/console.txt"
lines=$(wc -l < "$tmp/console.txt")
bytes=$(wc -c < "$tmp/console.txt")
notes=$(grep -c "DDS discovery: no multicast on this machine" "$tmp/console.txt" || true)
noise=$(grep -c "No locators\|leave_multicast_group\|No multicast joins succeeded" "$tmp/console.txt" || true)
echo "ergocell run, 5 s, loopback only: $lines lines, $bytes bytes; multicast note $notes time(s); RustDDS noise $noise line(s)"
fail=0
[ "$notes" = 1 ] || { echo "expected the multicast note exactly once" >&2; fail=1; }
[ "$noise" = 0 ] || { echo "RustDDS's per-message warnings reached the console" >&2; fail=1; }
[ "$lines" -lt 40 ] || { echo "console too long: $lines lines" >&2; fail=1; }
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
