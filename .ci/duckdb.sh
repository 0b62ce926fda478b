#!/usr/bin/env bash
# The exposure store queried as an ergonomist would: DuckDB's Python wheel (PyPI; no server, no engine
# compiled here) runs SQL over `ergocell exposure`'s sessions.parquet. Four demo shifts of two operators
# over two ISO weeks; the SQL's weekly share of RULA-scored time at action level 3 or more per operator,
# its mean posture cost, its daily hours and its parts taken must equal exposure.csv's own numbers, and the store's schema must
# be what the docs promise (no landmark, angle or name column).
# Usage: .ci/duckdb.sh target/release/ergocell [venv folder]
set -euo pipefail
cd "$(dirname "$0")/.."
bin=$(realpath "${1:-target/release/ergocell}")
venv=${2:-target/duckdb-venv}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
[ -x "$venv/bin/python" ] || python3 -m venv "$venv"
"$venv/bin/pip" install --quiet --disable-pip-version-check duckdb==1.4.3
mkdir -p "$tmp/shifts"
# seed operator start: Monday and Tuesday of week 48 and Monday of week 49 for op-a, Tuesday for op-b.
while read -r seed op start; do
  "$bin" demo --cycles 2 --seed "$seed" --operator "$op" --start-time "$start" \
    --out "$tmp/shifts/$op-$seed.mcap" > /dev/null
done <<'LIST'
11 op-a 2026-11-23T06:00:00Z
12 op-a 2026-11-24T06:00:00Z
13 op-a 2026-11-30T06:00:00Z
14 op-b 2026-11-24T14:00:00Z
LIST
"$bin" exposure "$tmp/shifts" --out "$tmp/out"
"$venv/bin/python" - "$tmp/out" <<'PY'
import csv, sys, duckdb
out = sys.argv[1]
store = f"{out}/sessions.parquet"
fail = []
def check(ok, what):
    print(("ok   " if ok else "FAIL ") + what)
    if not ok:
        fail.append(what)
groups = list(csv.DictReader(open(f"{out}/exposure.csv")))
def ours(period):
    return {(g["operator"], g["period_start"]): g for g in groups
            if g["period"] == period and g["class"] == "all" and g["segment"] == "all"}
cols = [r[0] for r in duckdb.sql(f"DESCRIBE SELECT * FROM '{store}'").fetchall()]
types = dict(duckdb.sql(f"SELECT column_name, column_type FROM (DESCRIBE SELECT * FROM '{store}')").fetchall())
check(types.get("start", "").startswith("TIMESTAMP") and types.get("day") == "DATE",
      f"the store's times are typed: start {types.get('start')}, day {types.get('day')}")
check(not any(w in c for c in cols for w in ("angle", "landmark", "name")),
      f"no landmark, angle or name among its {len(cols)} columns")
weekly = duckdb.sql(f"""
    SELECT operator, week, count(*) AS sessions,
           sum(rula_al3_s + rula_al4_s) / sum(rula_scored_s) AS al3plus,
           sum(parts_taken) AS parts,
           sum(posture_cost_point_s) / sum(posture_cost_s) AS cost
    FROM '{store}' WHERE segment = 'all'
    GROUP BY operator, week ORDER BY operator, week""").fetchall()
print("SQL, weekly action level 3+ share per operator:")
for row in weekly:
    print("    ", row)
mine = ours("week")
check(len(weekly) == 3 and len(weekly) == len(mine), f"3 operator-weeks in both ({len(weekly)} in SQL, {len(mine)} in exposure.csv)")
for op, week, n, share, parts, cost in weekly:
    g = mine.get((op, week))
    same = g is not None and int(g["sessions"]) == n and abs(float(g["rula_al3plus_share"]) - share) < 1e-12 \
        and int(g["parts_taken"]) == parts and 1.0 <= cost < 8.0 \
        and abs(float(g["mean_posture_cost"]) - cost) < 1e-9
    check(same, f"{op} {week}: {n} session(s), AL3+ {share:.6f}, {parts} parts, mean posture cost {cost:.4f} — exposure.csv says "
          + (f"{g['sessions']}, {float(g['rula_al3plus_share']):.6f}, {g['parts_taken']}, {g['mean_posture_cost']}" if g else "nothing"))
daily = duckdb.sql(f"""
    SELECT operator, strftime(day, '%Y-%m-%d'), sum(duration_s) / 3600
    FROM '{store}' WHERE segment = 'all' GROUP BY ALL""").fetchall()
mine = ours("day")
check(all(abs(float(mine[(op, d)]["hours"]) - h) < 1e-12 for op, d, h in daily) and len(daily) == len(mine),
      f"daily hours per operator: {len(daily)} operator-days agree")
seg = duckdb.sql(f"""
    SELECT segment, sum(duration_s) FROM '{store}' WHERE segment <> 'all' GROUP BY segment""").fetchall()
total = duckdb.sql(f"SELECT sum(duration_s) FROM '{store}' WHERE segment = 'all'").fetchone()[0]
in_segments = sum(s for _, s in seg)
check(len(seg) >= 3 and 0.9 * total < in_segments <= total * (1 + 1e-12),
      f"the task segments ({len(seg)}) hold {in_segments:.1f} s of the sessions' {total:.1f} s (frames without a pose are in none)")
sys.exit(1 if fail else 0)
PY
