#!/usr/bin/env bash
# The shipped systemd units are hardened (systemd-analyze security, offline: at most 4.0, "OK"), and a
# recording made under the cell unit's UMask=0027 cannot be read by another account.
#   .ci/units.sh target/release/ergocell
set -euo pipefail
cd "$(dirname "$0")/.."
bin=$(realpath "$1")
if ! command -v systemd-analyze >/dev/null 2>&1; then
  apt-get update -qq
  DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends systemd >/dev/null
fi
for unit in deploy/systemd/ergocell.service deploy/systemd/ergocell-edge.service; do
  score=$(systemd-analyze security --offline=yes "$unit" 2>/dev/null | sed -n 's/.*Overall exposure level for [^:]*: \([0-9.]*\) .*/\1/p')
  echo "$unit: exposure $score"
  awk -v s="$score" 'BEGIN { exit !(s != "" && s + 0 <= 4.0) }' || { echo "$unit: exposure $score is above 4.0" >&2; exit 1; }
done
grep -qx 'UMask=0027' deploy/systemd/ergocell.service || { echo "ergocell.service lost UMask=0027" >&2; exit 1; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
chmod 0755 "$work"
(cd "$work" && umask 0027 && "$bin" demo --cycles 1 --no-faults --out rec.mcap >/dev/null)
mode=$(stat -c %a "$work/rec.mcap")
[ "$mode" = 640 ] || { echo "a recording under UMask=0027 has mode $mode, not 640" >&2; exit 1; }
if [ "$(id -u)" = 0 ] && command -v setpriv >/dev/null 2>&1; then
  if setpriv --reuid=65534 --regid=65534 --clear-groups cat "$work/rec.mcap" >/dev/null 2>&1; then
    echo "another account (nobody) could read a recording made under UMask=0027" >&2
    exit 1
  fi
  echo "a recording under UMask=0027: mode $mode, unreadable by another account"
else
  echo "a recording under UMask=0027: mode $mode (not root: the read as another account is not tried)"
fi
