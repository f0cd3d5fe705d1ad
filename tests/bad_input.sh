#!/usr/bin/env bash
# Bad input on the command line: one line naming the option and the reason,
# exit status 2, and no window or capture started.
set -uo pipefail
planet="$1"; flights="$2"; work="$3"
rm -rf "$work"; mkdir -p "$work"
failed=0
expect() {  # expect "fragment" command...
  local fragment=$1; shift
  "$@" > "$work/out.txt" 2> "$work/err.txt"
  local rc=$?
  local lines
  lines=$(wc -l < "$work/err.txt")
  if [ "$rc" -ne 2 ] || ! grep -q -- "$fragment" "$work/err.txt" || [ "$lines" -ne 1 ]; then
    echo "FAIL: '$*' gave exit $rc, expected 2 and one line with '$fragment':"; cat "$work/err.txt"
    failed=1
  else
    echo "ok: $(cat "$work/err.txt")"
  fi
}
sun=("$planet" probe sun --planet earth --lon 2.35 --time 2026-06-21T12:00:00Z)
expect "--lat: 91" "${sun[@]}" --lat 91
expect "--time: '2026-06-21T25:00:00Z'" "$planet" probe sun --lat 0 --lon 0 --time 2026-06-21T25:00:00Z
expect "--time: 'noon'" "$planet" probe sun --lat 0 --lon 0 --time noon
expect "vulcan" "$planet" probe sun --planet vulcan --lat 0 --lon 0 --time 2026-06-21T12:00:00Z
expect "--lat: 91" "$planet" fly --lat 91
expect "--height: -7000000 m is inside" "$planet" fly --height -7e6
expect "--technique: 'nope'" "$planet" fly --technique nope
expect "vulcan" "$planet" fly --planet vulcan
expect "--time: 'yesterday'" "$planet" fly --time yesterday
expect "never reaches latitude" "$planet" fly --lat 60 --height 400000 --orbit-inclination 30 --time 2026-01-01T00:00:00Z
expect "outside the flight" "$planet" capture --flight "$flights/ascent.json" --out "$work/c" --frames 40:99 --quiet
expect "not a frame number" "$planet" capture --flight "$flights/ascent.json" --out "$work/c" --frames x:3 --quiet
expect "--width: Value 0 not in range 1 to 8192" "$planet" reference --scene earth_noon --width 0 --out "$work/r.exr"
expect "not expected: --bogus" "$planet" reference --bogus
expect "A subcommand is required" "$planet"
mkdir -p "$work/cache/reference"
echo "not sums" > "$work/cache/reference/earth_noon-4x2-64spp-rgb-0123456789abcdef.sums"
expect "earth_noon-4x2-64spp-rgb-0123456789abcdef.sums: not the sums of a reference render" \
  env PLANET_CACHE_DIR="$work/cache" "$planet" reference --scene earth_noon --width 4 --height 2 \
  --spp 96 --out "$work/r.exr" --quiet
[ -e "$work/r.exr" ] && { echo "FAIL: a reference was written from broken sums"; failed=1; }
exit $failed
