#!/usr/bin/env bash
# planet lab stability on two cells whose ground truths ship (no path
# tracing): split into two shards that each draw their own cell and gather
# both; a run again keeps every draw; a choice of one's own is a point of
# its own; the tables, the maps and the report are written; bad input is
# refused in one line before any work. Exit 77 (skipped) without matplotlib.
set -uo pipefail
planet="$1"; work="$2"
source "$(dirname "$0")/matplotlib_python.sh"  # $python, or skipped
rm -rf "$work"; mkdir -p "$work"
export PLANET_CACHE_DIR="$work/cache"
source "$(dirname "$0")/expect_refusal.sh"  # expect(), failed=0
fail() { echo "FAIL: $*"; failed=1; }

expect "lab stability --shard: '3/2' is not K/N" "$planet" lab stability --shard 3/2 --out "$work/x"
expect "lab stability --shard: 'two' is not K/N" "$planet" lab stability --shard two --out "$work/x"
expect "'stability-earth-d7' is not a cell of the map" \
  "$planet" lab stability --cells stability-earth-d7 --out "$work/x"
expect "unknown atmosphere technique 'nope'" "$planet" lab stability --techniques nope --out "$work/x"
expect "'venus' is not one of earth, mars, asteroid" \
  "$planet" lab stability --bodies venus --out "$work/x"
expect "lab stability --budget: -1 is not a percentage above 0" \
  "$planet" lab stability --budget -1 --out "$work/x"
touch "$work/a_file"
expect "is a file" "$planet" lab stability --out "$work/a_file"
[ -e "$work/x" ] && fail "a refused sweep left $work/x"

cells="stability-mars-preset stability-asteroid-preset"
run() {
  # shellcheck disable=SC2086
  "$planet" lab stability --cells $cells --techniques raymarch oneil:scale=chapter \
    --out "$work/map" --quiet "$@"
}
run --shard 1/2 --no-report > "$work/shard1.txt" 2>&1 || fail "shard 1/2 failed: $(cat "$work/shard1.txt")"
grep -q "0 ground truths to render" "$work/shard1.txt" ||
  fail "shard 1/2 would path trace: $(cat "$work/shard1.txt")"
[ -d "$work/map/cells/stability-mars-preset" ] || fail "shard 1/2 did not draw its cell"
[ -d "$work/map/cells/stability-asteroid-preset" ] && fail "shard 1/2 drew the other shard's cell"
grep -q "3 results" "$work/shard1.txt" || fail "shard 1/2: $(cat "$work/shard1.txt")"
run --shard 2/2 > "$work/shard2.txt" 2>&1 || fail "shard 2/2 failed: $(cat "$work/shard2.txt")"
grep -q "6 results" "$work/shard2.txt" || fail "shard 2/2 did not gather both: $(cat "$work/shard2.txt")"
for f in stability.json stability.csv summary.json report.html \
         lines_mars.png lines_asteroid.svg cells/stability-mars-preset/reference.png \
         cells/stability-mars-preset/raymarch-default.png; do
  [ -s "$work/map/$f" ] || fail "no $f"
done
# map_* only where a plane has cells: these two cells are on none.
before=$(stat -c %Y "$work/map/cells/stability-mars-preset/raymarch-default.json")
sleep 1
run --no-report > "$work/again.txt" 2>&1 || fail "the run again failed: $(cat "$work/again.txt")"
grep -q "0 draws to make" "$work/again.txt" || fail "the run again drew: $(cat "$work/again.txt")"
[ "$(stat -c %Y "$work/map/cells/stability-mars-preset/raymarch-default.json")" = "$before" ] ||
  fail "the run again drew a kept cell"
"$python" - "$work/map/stability.json" << 'PY' || fail "stability.json does not hold the figures"
import json, sys
r = json.load(open(sys.argv[1]))
res = {(x["cell"], x["technique"], x["quality"]): x for x in r["results"]}
assert len(res) == 6, sorted(res)
for x in res.values():
    assert x["class"] in ("ok", "inaccurate"), x
    assert x["worst"] is not None and x["worst"] >= 0, x
# O'Neil's chapter scale on the asteroid: the pinned failure, 79 % in blue.
chapter = res[("stability-asteroid-preset", "oneil", "scale=chapter")]
assert 0.6 < chapter["error"][2] < 1.0, chapter
# raymarch is single scattering: tens of percent off everywhere.
assert res[("stability-mars-preset", "raymarch", "default")]["worst"] > 0.3
assert r["counts"]["inaccurate"] == 6, r["counts"]
PY
# A draw over the time limit is failed, with the reason.
"$planet" lab stability --cells stability-mars-preset --techniques raymarch:view_steps=8 \
  --time-limit 0.000001 --out "$work/slow" --no-report --quiet > "$work/slow.txt" 2>&1 ||
  fail "the timed-out sweep failed: $(cat "$work/slow.txt")"
grep -q "1 failed" "$work/slow.txt" || fail "no draw failed over the time limit: $(cat "$work/slow.txt")"
grep -q "over the 1e-06 s limit" "$work/slow/stability.csv" ||
  fail "the failed draw does not say why: $(cat "$work/slow/stability.csv")"
exit "$failed"
