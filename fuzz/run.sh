#!/usr/bin/env bash
# Runs every fuzz target for SECS seconds (default 600), JOBS at a time (default 1), from the
# committed corpus, and prints each target's final libFuzzer statistics. New corpus inputs land in
# corpus/<target>/ (minimise with `cargo fuzz cmin` before committing), crashes in artifacts/<target>/.
# Needs cargo-fuzz (`cargo install cargo-fuzz`); RUSTC_BOOTSTRAP=1 lets the one stable toolchain take
# the -Z flags cargo-fuzz passes.
set -euo pipefail
cd "$(dirname "$0")"
SECS=${SECS:-600}
JOBS=${JOBS:-1}
TARGETS=${TARGETS:-$(cargo fuzz list)}
export RUSTC_BOOTSTRAP=1
FLAGS=(-s none -a -O)
cargo fuzz build "${FLAGS[@]}"
mkdir -p logs
run_one() {
  local t=$1
  cargo fuzz run "${FLAGS[@]}" "$t" "corpus/$t" -- -max_total_time="$SECS" -print_final_stats=1 \
    -rss_limit_mb=2048 -timeout=10 -max_len=1048576 >"logs/$t.log" 2>&1 && rc=0 || rc=$?
  local done_line execs
  done_line=$(grep -E '^#[0-9]+ +DONE' "logs/$t.log" | tail -1 || true)
  execs=$(grep -E '^stat::number_of_executed_units' "logs/$t.log" | awk '{print $2}' || true)
  echo "$t rc=$rc execs=${execs:-?} ${done_line}"
}
export -f run_one
export SECS
export FLAGS_STR="${FLAGS[*]}"
printf '%s\n' $TARGETS | xargs -P "$JOBS" -I{} bash -c 'FLAGS=($FLAGS_STR); run_one {}'
