#!/usr/bin/env bash
# planet reference goes on from the sums of a smaller render of the same
# view, says so, and ends with the bytes of a render from nothing; a render
# in the cache is read back, not rendered again.
set -uo pipefail
planet="$1"; work="$2"
rm -rf "$work"; mkdir -p "$work/a" "$work/b"
failed=0
fail() { echo "FAIL: $*"; failed=1; }
render() {  # render CACHE SPP
  PLANET_CACHE_DIR="$work/$1" "$planet" reference --scene earth_sunset --width 4 --height 2 \
    --spp "$2" --out "$work/$1/out.exr"
}
render a 3000,600,3000 > "$work/small.txt" || fail "the small render failed"
render a 20000,600,20000 > "$work/on.txt" || fail "the render that goes on failed"
render b 20000,600,20000 > "$work/fresh.txt" || fail "the render from nothing failed"
grep -q "went on from .*earth_sunset-4x2-3000,600,3000spp-rgb-.*\.sums (16.3% of the paths)" \
  "$work/on.txt" || fail "no 'went on from' line: $(cat "$work/on.txt")"
grep -q "went on" "$work/fresh.txt" && fail "a render with no sums went on from some"
for f in "$work"/b/reference/earth_sunset-4x2-20000,600,20000spp-*; do
  cmp -s "$f" "$work/a/reference/$(basename "$f")" || fail "$(basename "$f") differs"
done
ls "$work"/b/reference/*.sums > /dev/null 2>&1 || fail "the finished render left no sums"
render a 20000,600,20000 > "$work/again.txt" || fail "the cached render failed"
grep -q "from the cache" "$work/again.txt" || fail "the cached render was not read back"

# Ctrl-C: the render stops at once, keeps its last checkpoint, says how to
# go on and exits with 130; the same command goes on from there.
PLANET_CACHE_DIR="$work/c" "$planet" reference --scene earth_sunset --width 4 --height 2 \
  --spp 2000000 --out "$work/c/out.exr" > /dev/null 2> "$work/cut.txt" &
pid=$!
for _ in $(seq 1 600); do
  ls "$work"/c/reference/*.sums > /dev/null 2>&1 && break
  sleep 0.1
done
kill -INT "$pid"
wait "$pid"; rc=$?
[ "$rc" -eq 130 ] || fail "the interrupted render exited $rc: $(cat "$work/cut.txt")"
grep -q "interrupted: .*% of the paths of earth_sunset are kept in .*\.sums; run the same command again to go on" \
  "$work/cut.txt" || fail "no word of what was kept: $(cat "$work/cut.txt")"
grep -q "is cached in .*takes about .* on .* threads" "$work/cut.txt" ||
  fail "no word before the render of what it would cost: $(cat "$work/cut.txt")"
[ -e "$work/c/out.exr" ] && fail "an interrupted render wrote its image"
# The same command, stopped once it has said where it goes on from (polled,
# not timed: a busy machine may take many seconds to get there).
PLANET_CACHE_DIR="$work/c" "$planet" reference --scene earth_sunset --width 4 \
  --height 2 --spp 2000000 --out "$work/c/out.exr" > /dev/null 2> "$work/again_cut.txt" &
pid=$!
for _ in $(seq 1 1200); do
  grep -q "going on from sums that hold" "$work/again_cut.txt" && break
  kill -0 "$pid" 2> /dev/null || break
  sleep 0.1
done
kill -INT "$pid" 2> /dev/null
wait "$pid"
grep -q "going on from sums that hold" "$work/again_cut.txt" ||
  fail "the second run did not go on from the sums: $(cat "$work/again_cut.txt")"
[ "$failed" -eq 0 ] && echo "ok: went on from the smaller render to the same bytes, and Ctrl-C kept its paths"
exit $failed
