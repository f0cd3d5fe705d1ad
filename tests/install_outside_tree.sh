#!/usr/bin/env bash
# The program runs outside its source tree: `cmake --install` into a fresh
# prefix, then `planet capture` from there with the source tree hidden (a
# private mount namespace puts an empty tmpfs over it) gives the same bytes
# as the build tree's program, and `planet techniques` and `planet probe`
# work there too, and the lab's commands find their report writers there
# (each stops at its --out, a file, after it has looked for its writer).
# The second flight draws clouds, whose shaders are a room of their own.
#   install_outside_tree.sh BUILD_DIR SOURCE_DIR FLIGHT CLOUDS_FLIGHT
set -euo pipefail
build="$1"; source="$2"; flight="$3"; clouds_flight="$4"
unset PLANET_ROOT
work="$(mktemp -d /tmp/planet-install.XXXXXX)"
trap 'rm -rf "$work"' EXIT

if ! unshare -rm true 2>/dev/null; then
  echo "SKIP: this machine gives no private mount namespace (unshare -rm), so the source tree cannot be hidden"
  exit 77
fi

cmake --install "$build" --prefix "$work/prefix" > "$work/install.log"
cp "$flight" "$work/flight.json"
cp "$clouds_flight" "$work/clouds.json"
"$build/planet" capture --flight "$work/flight.json" --out "$work/from_build" --quiet
"$build/planet" capture --flight "$work/clouds.json" --out "$work/from_build_clouds" --quiet

# Hidden: the source tree (and the build tree inside it) is an empty folder.
unshare -rm bash -c '
  set -euo pipefail
  mount -t tmpfs none "$1"
  [ -z "$(ls -A "$1")" ] || { echo "FAIL: the source tree is still visible"; exit 1; }
  "$2/prefix/bin/planet" capture --flight "$2/flight.json" --out "$2/from_install" --quiet
  "$2/prefix/bin/planet" capture --flight "$2/clouds.json" --out "$2/from_install_clouds" --quiet
  "$2/prefix/bin/planet" techniques > "$2/techniques.txt"
  "$2/prefix/bin/planet" probe transmittance --planet mars --height 0 --zenith 30 > "$2/probe.txt"
  for lab in run stability measured; do
    ! "$2/prefix/bin/planet" lab $lab --out "$2/flight.json" --quiet 2>> "$2/lab.txt"
  done
' hide "$source" "$work"

count=0
for run in "" _clouds; do
  for f in "$work"/from_build$run/frame_*.exr "$work"/from_build$run/frame_*.png; do
    name="$(basename "$f")"
    cmp -s "$f" "$work/from_install$run/$name" ||
      { echo "FAIL: $name$run differs between the build tree's program and the installed one"; exit 1; }
    count=$((count + 1))
  done
  [ -f "$work/from_install$run/capture.json" ] ||
    { echo "FAIL: the installed capture$run did not finish"; exit 1; }
done
[ "$count" -ge 12 ] || { echo "FAIL: only $count frames"; exit 1; }
grep -q "^hillaire " "$work/techniques.txt" || { echo "FAIL: planet techniques lists no hillaire"; exit 1; }
grep -q "transmittance" "$work/probe.txt" || { echo "FAIL: probe printed nothing"; exit 1; }
[ "$(grep -c -- "--out $work/flight.json: cannot be a folder" "$work/lab.txt")" -eq 3 ] ||
  { echo "FAIL: the installed lab did not find its report writers:"; cat "$work/lab.txt"; exit 1; }
echo "the installed program, with the source tree hidden, captured $count files byte-identical to the build tree's"
