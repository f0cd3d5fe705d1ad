#!/usr/bin/env bash
# `planet fly` keeps drawing while a technique's tables are built. With an
# empty table cache (so bruneton's tables are computed, the slow path, not
# read back), T goes from hillaire to bruneton: F12 answers while the
# tables are built, before the switch; the switch says how many frames were
# drawn meanwhile. A second T while bruneton is being built drops it and
# goes on to the next technique (oneil). The window's pass list shows that
# its frames are antialiased and that the sun glares. Exit 77 (skipped)
# without Xvfb or xdotool.
set -uo pipefail
planet="$1"; work="$2"
rm -rf "$work"; mkdir -p "$work"
source "$(dirname "$0")/virtual_display.sh"  # $xvfb and DISPLAY, or skipped
fly=""
trap 'kill "$xvfb" 2>/dev/null; [ -n "$fly" ] && kill "$fly" 2>/dev/null' EXIT

# fly_start RUN: a window at a tenth of its size, with its own empty cache.
fly_start() {
  run="$work/$1"
  mkdir -p "$run/cache"
  PLANET_CACHE_DIR="$run/cache" timeout 600 "$planet" fly --render-scale 0.1 --out "$run" \
    > "$run/fly.txt" 2> "$run/fly.err" &
  fly=$!
  await_fly_window "$run/fly.txt" "$run/fly.err"
}
# wait_for FILE PATTERN SECONDS
wait_for() {
  for _ in $(seq 1 $(( $3 * 5 ))); do grep -q "$2" "$1" && return 0; sleep 0.2; done
  echo "FAIL: no '$2' in $1 within $3 s"; cat "$run/fly.txt" "$run/fly.err"; exit 1
}
fly_quit() {
  hold_key Escape
  wait "$fly"; local rc=$?
  fly=""
  cat "$run/fly.txt"
  [ "$rc" -eq 0 ] || { echo "FAIL: planet fly exited $rc"; cat "$run/fly.err"; exit 1; }
}

# A second T while bruneton's tables are built: they are dropped, and the
# next technique comes instead.
fly_start cancel
hold_key t
wait_for "$run/fly.err" "bruneton tables" 120
hold_key t
wait_for "$run/fly.txt" "^technique: oneil" 120
fly_quit
grep -q "^technique: bruneton" "$run/fly.txt" &&
  { echo "FAIL: bruneton was switched to after a second T dropped it"; exit 1; }

# T to bruneton, the slow path: the window answers F12 while the tables are built.
fly_start build
hold_key t
wait_for "$run/fly.err" "bruneton tables" 120
hold_key F12
wait_for "$run/fly.txt" "^screenshot: " 60
wait_for "$run/fly.txt" "^technique: bruneton" 500
fly_quit
shot=$(grep -n "^screenshot: " "$run/fly.txt" | head -1 | cut -d: -f1)
switched=$(grep -n "^technique: bruneton" "$run/fly.txt" | head -1 | cut -d: -f1)
[ "$shot" -lt "$switched" ] ||
  { echo "FAIL: the screenshot waited for bruneton's tables: the window stopped while they were built"; exit 1; }
frames=$(sed -n 's/^technique: bruneton (built in [0-9.]* s while \([0-9]*\) frames were drawn.*/\1/p' "$run/fly.txt")
if [ -z "$frames" ] || [ "$frames" -lt 10 ]; then
  echo "FAIL: fewer than 10 frames drawn while bruneton's tables were built"; exit 1
fi
# The window's own pass antialiases the ground's edges: multisampled as a
# capture is, or on llvmpipe smoothed in the image; and the sun glares.
grep -q "^  glare " "$run/fly.txt" || { echo "FAIL: the window's frames have no glare pass"; exit 1; }
{ grep -q "^  resolve " "$run/fly.txt" && grep -q "^  antialias " "$run/fly.txt"; } ||
  grep -q "^  smooth_edges " "$run/fly.txt" ||
  { echo "FAIL: the window's frames are not antialiased (no resolve and antialias, nor smooth_edges pass)"; exit 1; }
# The build's progress in the HUD leaves the view as free as ever.
read -r hud_w hud_h win_w win_h < <(sed -n 's/.*the HUD took at most \([0-9]*\) x \([0-9]*\) px of the \([0-9]*\) x \([0-9]*\) window.*/\1 \2 \3 \4/p' "$run/fly.txt")
[ -n "${hud_w:-}" ] || { echo "FAIL: no word of the HUD's size"; exit 1; }
if [ $((hud_w * hud_h * 100)) -gt $((win_w * win_h * 12)) ] || [ $((hud_w * 2)) -gt "$win_w" ]; then
  echo "FAIL: with the build's progress the HUD covers more than an eighth of the view or half its width"; exit 1
fi
echo "the window drew $frames frames while bruneton's tables were built, then switched to it"
