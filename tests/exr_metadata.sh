#!/usr/bin/env bash
# A captured EXR as another program reads it (OpenImageIO's oiiotool): the
# OpenEXR standard attributes of time, place and camera from the frame's own
# state, the sidecar's fields as planet: attributes, and a Z channel of
# distances along the rays.
set -uo pipefail
planet="$1"; flight="$2"
command -v oiiotool > /dev/null ||
  { echo "SKIPPED: oiiotool is not installed (scripts/install-deps.sh installs openimageio-tools)"; exit 77; }
work="$(mktemp -d /tmp/planet-exr.XXXXXX)"
trap 'rm -rf "$work"' EXIT
# The tiny flight with a clock.
sed 's/"sun": {"elevation_deg": 25.0, "azimuth_deg": 140.0}/"start_utc": "2026-06-21T09:30:00Z"/' \
  "$flight" > "$work/clock.json"
"$planet" capture --flight "$work/clock.json" --out "$work/c" --quiet || exit 1
oiiotool --info -v "$work/c/frame_00001.exr" > "$work/info.txt"
failed=0
want() {
  grep -qE -- "$1" "$work/info.txt" || { echo "FAIL: oiiotool shows no '$1'"; failed=1; }
}
want "channel list: R, G, B, Z"
want 'DateTime: "2026:06:21 09:30:10"'
want "utcOffset: 0"
want "latitude: 46\.2"
want "longitude: 9\.2"
want "altitude: 201556"
want "worldToCamera: "
want "worldToNDC: "
want 'planet:body: "Earth"'
want 'planet:utc: "2026-06-21T09:30:10.000Z"'
want "planet:camera:vertical_fov_deg: 60"
want "planet:frame: 1"
grep -q "gpu_ms" "$work/info.txt" && { echo "FAIL: the timings (which vary) are in the header"; failed=1; }
# From 2.4 m above the Alps: the nearest ground a few metres away, the sky
# infinitely far.
oiiotool "$work/c/frame_00000.exr" --ch Z --printstats > "$work/z.txt"
min=$(awk '/Stats Min:/ { print $3 }' "$work/z.txt")
awk -v m="$min" 'BEGIN { exit !(m > 2 && m < 50) }' || { echo "FAIL: nearest Z $min m"; failed=1; }
grep -qE "InfCount: [1-9]" "$work/z.txt" || { echo "FAIL: no sky at infinity in Z"; failed=1; }
[ "$failed" -eq 0 ] && cat "$work/info.txt" && echo "oiiotool reads the frame's time, place, camera and depth"
exit $failed
