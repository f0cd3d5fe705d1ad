#!/usr/bin/env bash
# A tiny sweep (two techniques, two quality points, two scenes at 16x8):
# its tables (the error split by order too), charts and report; a second run goes on from the kept cells
# without timing them again; a real browser (Debian's headless chromium)
# opens the report, which must render (a chart that is not blank, one table
# row per cell) with no console errors; bad input is refused in one line
# before any work. Exit 77 (skipped) without matplotlib or chromium.
set -uo pipefail
planet="$1"; work="$2"
source "$(dirname "$0")/matplotlib_python.sh"  # $python, or skipped
browser=$(command -v chromium || command -v chromium-browser || true)
[ -n "$browser" ] ||
  { echo "SKIPPED: chromium is not installed (scripts/install-deps.sh installs it)"; exit 77; }
rm -rf "$work"; mkdir -p "$work"
export PLANET_CACHE_DIR="$work/cache"
source "$(dirname "$0")/expect_refusal.sh"  # expect(), failed=0
fail() { echo "FAIL: $*"; failed=1; }
# Bad input: one line and exit 2, before any work, and nothing written.
expect "unknown atmosphere technique 'nope'" "$planet" lab run --techniques nope --out "$work/x"
expect "no technique of the sweep has a quality point 'nope'" \
  "$planet" lab run --quality nope --out "$work/x"
expect "'nope' is not a canonical scene" "$planet" lab run --scenes nope --out "$work/x"
expect "lab run --frames: 0 is not 1 to 1000" "$planet" lab run --frames 0 --out "$work/x"
touch "$work/a_file"
expect "is a file" "$planet" lab run --scenes earth_noon --out "$work/a_file"
[ -e "$work/x" ] && fail "a refused sweep left $work/x"
sweep() {
  "$planet" lab run --techniques raymarch oneil --quality cheap default \
    --scenes earth_noon mars_noon --width 16 --height 8 --time-width 64 --time-height 32 \
    --frames 2 --spp 256 --out "$work/lab" --quiet
}
sweep > "$work/first.txt" 2>&1 || fail "the sweep failed: $(cat "$work/first.txt")"
grep -q "8 cells (8 timed now, 0 kept from before)" "$work/first.txt" ||
  fail "the first sweep did not time 8 cells: $(cat "$work/first.txt")"
rows=$(($(wc -l < "$work/lab/results.csv") - 1))
[ "$rows" -eq 8 ] || fail "results.csv has $rows rows, not 8"
for f in results.json report.html pareto_overall.png pareto_overall.svg pareto_earth_noon.png \
         pareto_mars_noon.svg orders.png orders.svg cells/earth_noon/reference.png \
         cells/mars_noon/oneil-cheap_error.png; do
  [ -s "$work/lab/$f" ] || fail "no $f"
done
"$python" - "$work/lab/results.json" << 'PY' || fail "results.json does not hold the cells' figures"
import json, sys
r = json.load(open(sys.argv[1]))
cells = r["cells"]
assert len(cells) == 8, len(cells)
assert all(c["wall_ms"] > 0 and all(x >= 0 for x in c["debiased_relative_rmse"]) for c in cells)
assert all(c["debiased_low"][k] <= c["debiased_relative_rmse"][k] <= c["debiased_high"][k]
           for c in cells for k in range(3))
# raymarch is single scattering: tens of percent from the ground truth at noon
assert all(c["error"] > 0.1 for c in cells if c["technique"] == "raymarch"), cells
# ... and its error is the orders above the first: its single scattering
# is close to the ground truth's first order, the rest is what it leaves out.
for c in cells:
    if c["technique"] == "raymarch":
        assert max(c["single_error"]) < 0.25 * c["error"] < max(c["higher_error"]), c
assert any(c["on_front"] for c in cells if c["scene"] == "earth_noon")
assert len(r["overall"]) == 4 and r["renderer"] and r["commit"]
# Points whose frames' spreads, centred on their times, overlap tie in time.
for a in cells:
    for b in cells:
        if a is not b and a["scene"] == b["scene"]:
            tie = abs(a["wall_ms"] - b["wall_ms"]) <= 0.5 * (a["wall_spread_ms"] + b["wall_spread_ms"])
            assert (f'{b["technique"]}:{b["quality"]}' in a["time_ties"]) == tie, (a, b)
assert all("time_ties" in p and "wall_spread_ms" in p for p in r["overall"])
PY
# Again: every cell kept, none timed, the same tables.
cp "$work/lab/results.csv" "$work/first.csv"
sweep > "$work/second.txt" 2>&1 || fail "the second sweep failed: $(cat "$work/second.txt")"
grep -q "8 cells (0 timed now, 8 kept from before)" "$work/second.txt" ||
  fail "the second sweep timed cells again: $(cat "$work/second.txt")"
cmp -s "$work/first.csv" "$work/lab/results.csv" || fail "the kept cells gave other tables"
# The report in a real browser.
"$browser" --headless --no-sandbox --disable-gpu --hide-scrollbars --window-size=1000,900 \
  --enable-logging=stderr --v=0 --screenshot="$work/shot.png" "file://$work/lab/report.html" \
  > "$work/browser.txt" 2>&1 || fail "chromium failed: $(tail -5 "$work/browser.txt")"
"$browser" --headless --no-sandbox --disable-gpu --dump-dom "file://$work/lab/report.html" \
  > "$work/dom.html" 2> /dev/null || fail "chromium could not dump the page"
grep -qi "CONSOLE" "$work/browser.txt" && fail "console messages: $(grep -i CONSOLE "$work/browser.txt")"
"$python" - "$work/shot.png" "$work/dom.html" << 'PY' || fail "the report did not render"
import re, sys
import matplotlib.image as mpimg
shot = mpimg.imread(sys.argv[1])
# The overall chart sits near the top: its area must hold marks, not a blank page.
area = shot[100:600, 0:800, :3]
dark = (area.sum(axis=2) < 1.5).mean()
assert 0.002 < dark < 0.5, f"chart area dark fraction {dark}"
dom = open(sys.argv[2], encoding="utf-8").read()
body = dom.split('<table id="cells">', 1)[1].split("</tbody>", 1)[0]
rows = len(re.findall(r"<tr class=", body))
assert rows == 8, f"{rows} table rows"
PY
[ "$failed" -eq 0 ] && echo "ok: 8 cells, charts and a report that renders; the second run kept every cell"
exit $failed
