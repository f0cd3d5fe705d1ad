#!/usr/bin/env bash
# `planet fly` switching bodies with B on a virtual display: each switch
# keeps the latitude, longitude, height above the ground and local solar
# time (Earth's 10:30 in the morning had been -41.1 deg of sun on Mars and
# a black screen, 3396.2 m up); on the asteroid the camera's height counts
# from its real ground, below its ellipsoid; where a switch lands at night
# the terminal says so, the exposure follows the scene and the stars show.
# Exit 77 (skipped) without Xvfb, xdotool or a python with matplotlib.
set -uo pipefail
planet="$1"; work="$2"
source "$(dirname "$0")/matplotlib_python.sh"  # $python, or skipped
rm -rf "$work"; mkdir -p "$work"
source "$(dirname "$0")/virtual_display.sh"  # $xvfb and DISPLAY, or skipped
trap 'kill "$xvfb" 2>/dev/null' EXIT
fail() { echo "FAIL: $1"; cat "$out" "$out.err"; exit 1; }

# Flies with the options given, presses each key and waits for its line.
fly() {
  local name=$1; shift
  local keys=$1; shift
  out="$work/$name.txt"
  timeout 300 "$planet" fly --render-scale 0.25 --size 640x360 --out "$work/$name" "$@" \
    > "$out" 2> "$out.err" &
  local pid=$!
  await_fly_window "$out" "$out.err"
  for key in $keys; do
    # "settle": the new body's first tiles load for two seconds (for a few
    # frames after a switch its coarsest tiles can fill the view).
    [ "$key" = settle ] && { sleep 2; continue; }
    local want=$(( $(wc -l < "$out") + 1 ))
    hold_key "$key"
    for _ in $(seq 1 300); do
      [ "$(wc -l < "$out")" -ge "$want" ] && break
      sleep 0.2
    done
    [ "$(wc -l < "$out")" -ge "$want" ] || fail "no answer to $key"
  done
  hold_key Escape
  wait "$pid" || fail "planet fly exited $?"
  grep "^body: " "$out"
}

# By day: Earth -> Mars -> asteroid -> Moon -> Eros -> Earth, 2 m up over the Alps
# at 10:00 UTC (10:30 local solar time).
fly day "b b b b b"
[ "$(grep -c "^body: " "$out")" -eq 6 ] || fail "not six bodies"
grep "^body: " "$out" | tail -n 5 | while read -r line; do
  echo "$line" | grep -q ", 2\.0 m above the ground (.*kept from [0-9A-Za-z ]*: lat 46\.5500 lon 7\.9800, the height above the ground, local solar time 10:3[01] " ||
    { echo "FAIL: the switch did not keep the place, height or time: $line"; exit 1; }
  elevation=$(echo "$line" | sed -n 's/.*; sun \(-*[0-9.]*\) deg: day$/\1/p')
  [ -n "$elevation" ] || { echo "FAIL: not day after the switch: $line"; exit 1; }
done || exit 1
# The asteroid's ground lies below its ellipsoid here: 2 m above it.
grep -q "^body: Asteroid, 2\.0 m above the ground (-30[0-9]\.[0-9] m above the ellipsoid)" "$out" ||
  fail "the asteroid's height does not count from its ground"

# By night: the Alps at 01:30 local solar time, then Mars at the same hour.
fly night "b settle F12" --time 2026-06-21T23:00:00Z --height 100
grep -q "^body: Earth, .*; sun -[0-9.]* deg: night, the exposure follows the scene (auto)$" "$out" ||
  fail "the night start does not say night or turn the exposure automatic"
grep -q "^body: Mars, 100\.0 m above the ground .*local solar time 23:3[01] .*; sun -[0-9.]* deg: night$" "$out" ||
  fail "Mars is not at the same night hour"
shot="$work/night/screenshot_0000.png"
[ -s "$shot" ] || fail "no screenshot"
# Stars: single bright pixels in the sky (the top third of the view).
"$python" - "$shot" << 'PY' || fail "no stars in the night sky after the switch"
import sys
import matplotlib.image as mpimg
img = mpimg.imread(sys.argv[1])[..., :3].max(axis=2)
sky = img[: img.shape[0] // 3]
stars = int((sky > 0.1).sum())
print(f"{stars} bright pixels in the top third of the night view")
sys.exit(0 if stars >= 10 else 1)
PY
echo "each switch kept the place, the height above the ground and the local solar time; the night showed its stars"
