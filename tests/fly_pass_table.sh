#!/usr/bin/env bash
# `planet fly --flight` ends with the flight and prints each pass of its
# frames: how often it ran, was reused, and was skipped where the frame did
# not need it. Exit 77 (skipped) without Xvfb.
set -uo pipefail
planet="$1"; work="$2"
rm -rf "$work"; mkdir -p "$work"
source "$(dirname "$0")/virtual_display.sh"  # $xvfb and DISPLAY, or skipped
trap 'kill "$xvfb" 2>/dev/null' EXIT

timeout 200 "$planet" fly --flight "${PLANET_ROOT:-.}/data/flights/terrain_asteroid.json" --render-scale 0.25 \
  > "$work/fly.txt" 2> "$work/fly.err"
rc=$?
cat "$work/fly.txt"
[ "$rc" -eq 0 ] || { echo "FAIL: planet fly exited $rc"; cat "$work/fly.err"; exit 1; }
frames=$(sed -n 's/^flew \([0-9]*\) frames.*/\1/p' "$work/fly.txt")
[ -n "$frames" ] && [ "$frames" -gt 0 ] || { echo "FAIL: no frame count"; exit 1; }
row() { grep -qE "^  $1 +[0-9.]+ ms  $2\$" "$work/fly.txt" || { echo "FAIL: no row: $1 $2"; exit 1; }; }
row surface "ran $frames of $frames"
row tonemap "ran $frames of $frames"
# Where the edges were smoothed (llvmpipe) the multisampled passes were
# not needed, and where they were multisampled the smoothing was not.
if grep -qE "^  smooth_edges +[0-9.]+ ms  ran $frames of $frames\$" "$work/fly.txt"; then
  row resolve "ran 0 of $frames, skipped $frames"
  row antialias "ran 0 of $frames, skipped $frames"
else
  row smooth_edges "ran 0 of $frames, skipped $frames"
fi
# No switch of technique fades in a scripted flight.
row "fade:frame" "ran 0 of $frames, skipped $frames"
echo "OK: $frames frames, each pass ran, reused or skipped"
