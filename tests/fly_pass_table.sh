#!/usr/bin/env bash
# `planet fly --flight --pass-table` ends with the flight and prints each
# pass of its frames: its mean wall and GPU time, how often it ran, was
# reused, and was skipped where the frame did not need it; the frame's
# mean last; and the frame rate with its slowest 1 %. Exit 77 (skipped)
# without Xvfb.
set -uo pipefail
planet="$1"; work="$2"
rm -rf "$work"; mkdir -p "$work"
source "$(dirname "$0")/virtual_display.sh"  # $xvfb and DISPLAY, or skipped
trap 'kill "$xvfb" 2>/dev/null' EXIT

timeout 200 "$planet" fly --flight "${PLANET_ROOT:-.}/data/flights/terrain_asteroid.json" --render-scale 0.25 \
  --pass-table > "$work/fly.txt" 2> "$work/fly.err"
rc=$?
cat "$work/fly.txt"
[ "$rc" -eq 0 ] || { echo "FAIL: planet fly exited $rc"; cat "$work/fly.err"; exit 1; }
frames=$(sed -n 's/^flew \([0-9]*\) frames.*/\1/p' "$work/fly.txt")
[ -n "$frames" ] && [ "$frames" -gt 0 ] || { echo "FAIL: no frame count"; exit 1; }
grep -qE "^flew $frames frames in [0-9.]+ s \([0-9.]+ frames/s, the slowest 1 % of frames [0-9]+ ms each\)" \
  "$work/fly.txt" || { echo "FAIL: no frame rate and slowest 1 %"; exit 1; }
grep -qE "^  pass +wall ms +GPU ms +ran +reused +skipped$" "$work/fly.txt" ||
  { echo "FAIL: no table header"; exit 1; }
# NAME RAN REUSED SKIPPED: its row, with a wall and a GPU time.
row() {
  grep -qE "^  $1 +[0-9.]+ +[0-9.]+ +$2 +$3 +$4\$" "$work/fly.txt" ||
    { echo "FAIL: no row: $1 ran $2, reused $3, skipped $4"; exit 1; }
}
row surface "$frames" 0 0
row tonemap "$frames" 0 0
# Where the edges were smoothed (llvmpipe) the multisampled passes were
# not needed, and where they were multisampled the smoothing was not.
if grep -qE "^  smooth_edges +[0-9.]+ +[0-9.]+ +$frames +0 +0\$" "$work/fly.txt"; then
  row resolve 0 0 "$frames"
  row antialias 0 0 "$frames"
else
  row smooth_edges 0 0 "$frames"
fi
# No switch of technique fades in a scripted flight.
row "fade:frame" 0 0 "$frames"
tail -1 "$work/fly.txt" | grep -qE "^  frame +[0-9.]+ +[0-9.]+ +$frames\$" ||
  { echo "FAIL: the frame's row is not last"; exit 1; }
echo "OK: $frames frames, each pass ran, reused or skipped"
