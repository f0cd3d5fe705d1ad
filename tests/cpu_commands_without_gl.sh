#!/usr/bin/env bash
# `planet reference`, `planet probe` and `planet eclipse` never create a GL context: on a
# machine with no EGL device (glvnd pointed at no vendor library, no
# display) they still work, while `planet capture` there says it has no EGL;
# and the CPU test binary, which links every CPU library (sim, the
# atmosphere's model and ground truth, terrain's CPU half, the lab's
# reference cache), links no GL library itself (OpenCV, which OpenImageIO
# pulls in, may: that is Debian's build of it, not ours).
#   cpu_commands_without_gl.sh PLANET CPU_TESTS FLIGHT
set -euo pipefail
planet="$1"; cpu_tests="$2"; flight="$3"
work="$(mktemp -d /tmp/planet-nogl.XXXXXX)"
trap 'rm -rf "$work"' EXIT
no_gl=(env -u DISPLAY -u WAYLAND_DISPLAY "__EGL_VENDOR_LIBRARY_FILENAMES=$work/none.json"
       "PLANET_CACHE_DIR=$work/cache")

set +e
"${no_gl[@]}" "$planet" capture --flight "$flight" --out "$work/capture" --quiet 2> "$work/capture.txt"
rc=$?
set -e
[ "$rc" -eq 1 ] && grep -q "EGL" "$work/capture.txt" ||
  { echo "FAIL: capture without EGL gave exit $rc:"; cat "$work/capture.txt"; exit 1; }

run() {
  "${no_gl[@]}" "$planet" "$@" > "$work/out.txt" 2>&1 ||
    { echo "FAIL: planet $* without EGL:"; cat "$work/out.txt"; exit 1; }
  echo "without EGL: planet $* ok"
}
run reference --scene earth_sunset --width 8 --height 4 --spp 12 --out "$work/ref.exr" --quiet
[ -s "$work/ref.exr" ] || { echo "FAIL: no reference image"; exit 1; }
run probe transmittance --planet earth --height 0 --zenith 60
run probe sky --planet mars --height 0 --view-zenith 45 --view-azimuth 90 --sun-zenith 30 --paths 200
run probe sun --planet earth --lat 48.85 --lon 2.35 --time 2026-06-21T12:00:00Z
run probe ground --planet earth --lat 46.55 --lon 7.98
run probe oneil-fit --planet asteroid
run eclipse 2024-04-08

if linked="$(readelf -d "$cpu_tests" | grep NEEDED | grep -E 'lib(EGL|GL|GLX|OpenGL|epoxy|glfw)\.')"; then
  echo "FAIL: the CPU tests link GL:"; echo "$linked"; exit 1
fi
echo "the CPU libraries link no GL"
