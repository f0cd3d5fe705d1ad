#!/usr/bin/env bash
# `planet capture`'s command line over the flight script: --technique,
# --width/--height and --scale replace the script's own, and the sidecars
# and capture.json say so; bad values are one line, exit status 2, before
# any frame. The first line says where the capture starts, above the
# ellipsoid and above the ground, whichever the script gave ("height_m" or
# "height_above_ground_m"), names no sky for an airless body, and one frame
# is "1 frame"; --pass-table prints the table of passes. `--refusals-only` as a fifth argument: the bad values
# alone (no GL, a second).
set -uo pipefail
planet="$1"; flight="$2"; moon="$3"; work="$4"; only="${5:-}"
rm -rf "$work"; mkdir -p "$work"
source "$(dirname "$0")/expect_refusal.sh"
fail() { echo "FAIL: $*"; failed=1; }
png_size() { /usr/bin/python3 -c "import struct,sys; d=open(sys.argv[1],'rb').read(24); print('%dx%d' % struct.unpack('>II', d[16:24]))" "$1"; }
field() {  # FILE PYTHON-EXPRESSION-OF-d
  /usr/bin/python3 -c "import json,sys; d=json.load(open(sys.argv[1])); print($2)" "$1"
}

# Bad values: one line, exit 2, no folder.
cap=("$planet" capture --flight "$flight" --out "$work/bad" --quiet)
expect "--scale: 0 is not above 0 and at most 16" "${cap[@]}" --scale 0
expect "--width: -3 is not an image side (1 to 16384 pixels)" "${cap[@]}" --width -3
expect "--height: 20000 is not an image side (1 to 16384 pixels)" "${cap[@]}" --height 20000
expect "--scale 0.001: makes $flight's 64x32 image 0x0 pixels" "${cap[@]}" --scale 0.001
expect "--scale and --width/--height both given" "${cap[@]}" --scale 0.5 --width 10
expect "--technique: unknown atmosphere technique 'nope'" "${cap[@]}" --technique nope
sed 's/"height_m": 3112.7,/"height_m": 3112.7, "height_above_ground_m": 2,/' "$flight" > "$work/both.json"
expect "both.json: keyframes.0.: \"height_m\" (above the ellipsoid) and \"height_above_ground_m\" (above the ground) both given" \
  "$planet" capture --flight "$work/both.json" --out "$work/bad" --quiet
sed 's/"height_m": 3112.7,/"height_above_ground_m": -5,/' "$flight" > "$work/under.json"
expect "under.json: keyframes.0.: the camera is 5.0 m below the ground (height_above_ground_m -5.0" \
  "$planet" capture --flight "$work/under.json" --out "$work/bad" --quiet
[ -e "$work/bad" ] && fail "a refused capture left its folder"
[ "$only" = "--refusals-only" ] && exit $failed

# A quarter of the size, with another technique than the script's.
"$planet" capture --flight "$flight" --out "$work/small" --frames 0:1 --scale 0.25 \
  --technique raymarch > "$work/small.txt" 2> "$work/small.err" || fail "capture --scale --technique"
[ "$(png_size "$work/small/frame_00000.png")" = 16x8 ] ||
  fail "--scale 0.25 of 64x32 gave $(png_size "$work/small/frame_00000.png")"
[ "$(field "$work/small/frame_00000.json" "d['technique']")" = raymarch ] || fail "--technique not drawn"
for f in "$work/small/frame_00000.json" "$work/small/capture.json"; do
  [ "$(field "$f" "d['overrides']['technique']['command_line']")" = "--technique raymarch" ] &&
    [ "$(field "$f" "d['overrides']['image_size']['command_line']")" = "--scale 0.25" ] &&
    [ "$(field "$f" "d['overrides']['image_size']['script']")" = "64x32" ] ||
    fail "$(basename "$f") does not say what the command line overrode"
done
grep -q "^captured 1 frame in " "$work/small.txt" || fail "not '1 frame': $(cat "$work/small.txt")"
grep -q "^planet: Earth, 16x8, 3 frames at 0.1 fps, raymarch sky on .*; frame 0 at 3112.7 m above the ellipsoid, 2.0 m above the ground$" \
  "$work/small.err" || fail "first line: $(head -1 "$work/small.err")"
echo "ok: $(head -1 "$work/small.err")"

# One side alone keeps the script's aspect ratio; --pass-table ends with
# each pass's wall and GPU time and counts, the frame's last.
"$planet" capture --flight "$flight" --out "$work/wide" --frames 0:2 --width 24 --pass-table \
  > "$work/wide.txt" 2> /dev/null || fail "capture --width --pass-table"
[ "$(png_size "$work/wide/frame_00000.png")" = 24x12 ] ||
  fail "--width 24 of 64x32 gave $(png_size "$work/wide/frame_00000.png")"
grep -qE "^  pass +wall ms +GPU ms +ran +reused +skipped$" "$work/wide.txt" &&
  grep -qE "^  surface +[0-9.]+ +[0-9.]+ +2 +0 +0$" "$work/wide.txt" &&
  grep -qE "^  fade:frame +0.00 +0.00 +0 +0 +2$" "$work/wide.txt" &&
  grep -qE "^  frame +[0-9.]+ +[0-9.]+ +2$" "$work/wide.txt" &&
  grep -q "^captured 2 frames in " "$work/wide.txt" ||
  fail "--pass-table: $(cat "$work/wide.txt")"

# Heights above the ground: the same place given the other way round.
sed -e 's/"width": *64/"width": 16/' -e 's/"height": *32/"height": 8/' \
    -e 's/"height_m": 3112.7,/"height_above_ground_m": 2.0,/' "$flight" > "$work/ground.json"
"$planet" capture --flight "$work/ground.json" --out "$work/ground" --frames 0:1 \
  > /dev/null 2> "$work/ground.err" || fail "capture with height_above_ground_m: $(cat "$work/ground.err")"
grep -q "; frame 0 at 3112.7 m above the ellipsoid, 2.0 m above the ground$" "$work/ground.err" ||
  fail "height_above_ground_m 2: $(head -1 "$work/ground.err")"

# The Moon has no air: no sky technique named.
sed -e 's/"width": *480/"width": 16/' -e 's/"height": *270/"height": 9/' "$moon" > "$work/moon.json"
"$planet" capture --flight "$work/moon.json" --out "$work/moon" --frames 0:1 \
  > /dev/null 2> "$work/moon.err" || fail "capture of the Moon"
head -1 "$work/moon.err" | grep -q "^planet: Moon, 16x9, 41 frames at 1 fps, no atmosphere on " ||
  fail "the Moon's first line: $(head -1 "$work/moon.err")"

exit $failed
