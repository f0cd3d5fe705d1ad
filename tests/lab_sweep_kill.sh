#!/usr/bin/env bash
# The lab's sweep killed at any moment (SIGKILL, KILLS times in a row, each
# run going on from the cells and ground truths the last one kept) leaves
# only whole files: every cell kept is one the next run reads, every chart
# and table that is there is whole. The run that finishes has the figures
# of a sweep never stopped (all but the timings, which are measured anew
# for each cell a killed run did not keep) and leaves no partial file.
set -uo pipefail
planet="$1"; work="$2"; kills="${3:-20}"
source "$(dirname "$0")/matplotlib_python.sh"  # $python, or skipped
rm -rf "$work"; mkdir -p "$work"
failed=0
fail() { echo "FAIL: $*"; failed=1; }
sweep() {  # NAME: in the background, pid in $pid
  PLANET_CACHE_DIR="$work/$1/cache" "$planet" lab run --techniques raymarch oneil \
    --quality cheap --scenes mars_noon --width 16 --height 8 --time-width 32 \
    --time-height 16 --frames 1 --spp 64 --out "$work/$1/lab" --quiet > "$work/$1.txt" 2>&1 &
  pid=$!
}
now_ms() { echo $(( $(date +%s%N) / 1000000 )); }

start=$(now_ms)
sweep whole; wait "$pid" || { echo "FAIL: the uninterrupted sweep failed: $(cat "$work/whole.txt")"; exit 1; }
window_ms=$(( $(now_ms) - start ))
echo "uninterrupted: $window_ms ms"

# Every file there is whole: JSON that parses, images that decode, a
# report that ends, and no cell's images without the others of the run.
check_whole() {  # KILL DELAY
  "$python" - "$work/cut/lab" << 'PY' || fail "kill $1 ($2 ms in): a file is not whole"
import json, os, sys
import matplotlib.image as mpimg
root = sys.argv[1]
for d, _, files in os.walk(root):
    for n in files:
        p = os.path.join(d, n)
        if n.startswith(".partial-") or n.endswith(".part"):
            continue  # a killed writer's, never read: the next run removes it
        if n.endswith(".json"):
            json.load(open(p))
        elif n.endswith(".png"):
            mpimg.imread(p)
        elif n.endswith(".svg") or n.endswith(".html"):
            text = open(p, encoding="utf-8").read().rstrip()
            assert text.endswith("</svg>") or text.endswith("</html>"), p
        elif n.endswith(".csv"):
            lines = open(p).read().splitlines()
            assert len(lines) > 1 and all(l.count(",") >= lines[0].count(",") for l in lines), p
PY
}

kept=0
for i in $(seq 1 "$kills"); do
  # Longer and longer runs, up to half the sweep: the first die starting up
  # or in the ground truth's render, later ones while timing and measuring
  # cells, the last while writing tables and charts.
  delay_ms=$(( window_ms * i / (2 * kills) ))
  sweep cut
  sleep "$(printf '%d.%03d' $((delay_ms / 1000)) $((delay_ms % 1000)))"
  kill -KILL "$pid" 2> /dev/null || true
  wait "$pid" 2> /dev/null
  [ -d "$work/cut/lab" ] && check_whole "$i" "$delay_ms"
  [ "$failed" -eq 0 ] || exit 1
  now=$(find "$work/cut/lab/cells" -name '*-cheap.json' 2> /dev/null | wc -l)
  echo "kill $i $delay_ms ms in: $now of 2 cells kept"
  kept=$((kept + now))
done

sweep cut; wait "$pid" || { echo "FAIL: the last run failed: $(cat "$work/cut.txt")"; exit 1; }
grep -q "2 cells (" "$work/cut.txt" || fail "the last run said: $(cat "$work/cut.txt")"
"$python" - "$work/whole/lab" "$work/cut/lab" << 'PY' || fail "the finished sweep's figures differ"
import csv, sys
timing = {"wall_ms", "wall_spread_ms", "gpu_ms", "on_front", "time_ties"}
rows = lambda d: [{k: v for k, v in r.items() if k not in timing}
                  for r in csv.DictReader(open(f"{d}/results.csv"))]
a, b = rows(sys.argv[1]), rows(sys.argv[2])
assert a == b, (a, b)
PY
for f in "$work"/whole/lab/cells/*/*.png; do
  cmp -s "$f" "$work/cut/lab/${f#"$work"/whole/lab/}" || fail "${f#"$work"/whole/lab/} differs"
done
for f in "$work"/whole/cache/reference/*; do
  cmp -s "$f" "$work/cut/cache/reference/$(basename "$f")" || fail "reference $(basename "$f") differs"
done
leftovers=$(find "$work/cut" -name '.partial-*' -o -name '*.part' | wc -l)
[ "$leftovers" -eq 0 ] || fail "the finished sweep keeps $leftovers partial files"
[ "$failed" -eq 0 ] &&
  echo "ok: $kills kills ($kept cells kept over them); the finished sweep has the uninterrupted one's figures, images and ground truths"
exit $failed
