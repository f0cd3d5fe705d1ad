#!/usr/bin/env bash
# `planet fly` in a real window on a virtual display: synthetic key presses
# take a screenshot on Earth, switch to the next body and technique, take a
# second screenshot and quit. Exit 77 (skipped) without Xvfb or xdotool.
set -uo pipefail
planet="$1"; work="$2"
rm -rf "$work"; mkdir -p "$work"
source "$(dirname "$0")/virtual_display.sh"  # $xvfb and DISPLAY, or skipped
trap 'kill "$xvfb" 2>/dev/null' EXIT

# The default window, drawn at a tenth of its size to keep llvmpipe quick.
timeout 500 "$planet" fly --render-scale 0.1 --out "$work" > "$work/fly.txt" 2> "$work/fly.err" &
fly=$!
await_fly_window "$work/fly.txt" "$work/fly.err"
press() {
  hold_key "$1"
  # Wait until the program has answered (a line more on its output).
  # (up to $3 s, 60 by default: a switch to bruneton builds its tables
  # first, which took over 200 s on a machine running other tests beside it).
  local want=$2
  for _ in $(seq 1 $(( ${3:-60} * 5 ))); do
    [ "$(wc -l < "$work/fly.txt")" -ge "$want" ] && return 0
    sleep 0.2
  done
  echo "FAIL: no answer to $1"; cat "$work/fly.txt" "$work/fly.err"; exit 1
}
press F12 2      # body: Earth, screenshot
press b 3        # body: Mars
press t 4 330    # technique: ...
press F12 5      # screenshot
press F9 6       # recording
started=$(date +%s.%N)
# Down at ten times the speed for a while (3.4 km at 2 h per second): the
# camera lands on the ground and stays above it (the replay's capture
# refuses a keyframe below it).
xdotool keydown Shift_L keydown f; sleep 5; xdotool keyup f keyup Shift_L
press F9 7       # recorded N frames into ...
recorded_wall=$(awk -v a="$started" -v b="$(date +%s.%N)" 'BEGIN { print b - a }')
hold_key Escape
wait "$fly"; rc=$?
cat "$work/fly.txt"
[ "$rc" -eq 0 ] || { echo "FAIL: planet fly exited $rc"; cat "$work/fly.err"; exit 1; }
grep -q "^body: Earth" "$work/fly.txt" && grep -q "^body: Mars" "$work/fly.txt" &&
  grep -q "^technique: " "$work/fly.txt" || { echo "FAIL: body or technique did not switch"; exit 1; }
# The default start: a few metres above the ground, not the ellipsoid.
# ETOPO5 and its detail put the ground at the Jungfraujoch 3111 m above the ellipsoid.
grep -q "^body: Earth, 2.0 m above the ground (3112.[0-9] m above the ellipsoid)" "$work/fly.txt" ||
  { echo "FAIL: the start is not 2 m above the Alps' ground"; exit 1; }
for n in 0000 0001; do
  for ext in png exr; do
    [ -s "$work/screenshot_$n.$ext" ] || { echo "FAIL: no screenshot_$n.$ext"; exit 1; }
  done
done
cmp -s "$work/screenshot_0000.png" "$work/screenshot_0001.png" &&
  { echo "FAIL: Earth and Mars screenshots are the same image"; exit 1; }
# The recorded flight replays headless.
recorded=$(grep -o "into [^ ]*flight_0000.json" "$work/fly.txt" | cut -d' ' -f2)
[ -n "$recorded" ] && [ -f "$recorded" ] || { echo "FAIL: no recorded flight"; exit 1; }
"$planet" capture --flight "$recorded" --out "$work/replay" --quiet 2> "$work/replay.err" ||
  { echo "FAIL: the recorded flight does not replay:"; cat "$work/replay.err"; exit 1; }
[ -f "$work/replay/frame_00001.png" ] || { echo "FAIL: replay has fewer than two frames"; exit 1; }
# The clock follows wall time: the recording spans (nearly) the seconds it
# took, however slowly frames came.
recorded_clock=$(grep -o '"time": [0-9.]*' "$recorded" | tail -1 | cut -d' ' -f2)
echo "recorded $recorded_clock s of flight in $recorded_wall s of wall time"
awk -v c="$recorded_clock" -v w="$recorded_wall" 'BEGIN { exit !(c > 0.8 * (w - 1)) }' ||
  { echo "FAIL: the clock ran slower than wall time"; exit 1; }
# The HUD leaves the view free: a corner of it, not a band across it.
read -r hud_w hud_h win_w win_h < <(sed -n 's/.*the HUD took at most \([0-9]*\) x \([0-9]*\) px of the \([0-9]*\) x \([0-9]*\) window.*/\1 \2 \3 \4/p' "$work/fly.txt")
[ -n "${hud_w:-}" ] || { echo "FAIL: no word of the HUD's size"; exit 1; }
echo "the HUD took $hud_w x $hud_h px of the $win_w x $win_h window"
[ $((hud_w * hud_h * 100)) -le $((win_w * win_h * 12)) ] && [ $((hud_w * 2)) -le "$win_w" ] ||
  { echo "FAIL: the HUD covers more than an eighth of the view or half its width"; exit 1; }
echo "window opened, switched body and technique, wrote two screenshots, recorded a flight that replays"
