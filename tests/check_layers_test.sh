#!/usr/bin/env bash
# scripts/check-layers.sh passes on the tree, and fails, naming the file and
# the floors, on a copy of the rooms with one bad include of each kind.
set -euo pipefail
source="$1"
check="$source/scripts/check-layers.sh"
"$check" "$source"

work="$(mktemp -d /tmp/planet-layers.XXXXXX)"
trap 'rm -rf "$work"' EXIT
mkdir -p "$work/sim" "$work/render" "$work/terrain/gpu/shaders" "$work/atmosphere/gpu"
echo '#pragma once' > "$work/render/frame.h"
expect_failure() {
  local what="$1" file="$2" line="$3" fragment="$4"
  mkdir -p "$(dirname "$work/$file")"
  printf '%s\n' "$line" > "$work/$file"
  set +e
  out="$("$check" "$work" 2>&1)"
  rc=$?
  set -e
  rm "$work/$file"
  [ "$rc" -ne 0 ] || { echo "FAIL: $what passed the check"; exit 1; }
  grep -q "$file:1: .*$fragment" <<< "$out" ||
    { echo "FAIL: $what: the check did not say '$fragment' for $file:"; echo "$out"; exit 1; }
  echo "refused, as it should be: $what"
}
expect_failure "sim including render" sim/bad.h '#include "render/frame.h"' "sim points up to render"
expect_failure "terrain/gpu including the atmosphere beyond its API" \
  terrain/gpu/shaders/bad.vert '#include "atmosphere/shaders/transmittance.glsl"' \
  "terrain/gpu reaches across to atmosphere"
expect_failure "a shader path of render named in atmosphere/gpu" atmosphere/gpu/bad.cpp \
  'auto p = Program::compute("render/shaders/tonemap.frag");' "atmosphere/gpu points up to render"
expect_failure "a GL header in the CPU half of terrain" terrain/bad.cpp '#include <epoxy/gl.h>' \
  "terrain does not draw"
expect_failure "the governor including render" governor/bad.cpp '#include "render/frame.h"' \
  "governor points up to render"
expect_failure "the governor including gl" governor/bad.h '#include "gl/context.h"' \
  "governor reaches across to gl"
expect_failure "a GL header in the governor" governor/bad.cpp '#include <epoxy/gl.h>' \
  "governor does not draw"
expect_failure "atmosphere including the governor" atmosphere/bad.h '#include "governor/governor.h"' \
  "atmosphere points up to governor"
expect_failure "the lab's CPU half including what draws" lab/bad.cpp '#include "lab/gpu/sweep.h"' \
  "lab points up to lab/gpu"
expect_failure "a GL header in the lab's CPU half" lab/bad.cpp '#include <epoxy/gl.h>' \
  "lab does not draw"
