#!/usr/bin/env bash
# The floors of the house, checked: every #include (C++ and GLSL), every
# shader path named in C++ ("x/y.frag"), and every GL header, against the
# table of rooms below. Arrows point down only:
#   apps -> lab/gpu -> render -> {atmosphere/gpu, clouds/gpu, terrain/gpu} -> gl -> core
#   {atmosphere, terrain} -> sim -> core; clouds -> atmosphere (its shared math: phase,
#   geometry) and clouds/gpu -> atmosphere/gpu (the technique that lights the clouds)
#   {apps, lab/gpu, render} -> governor -> atmosphere (its choice is made on the CPU)
#   {apps, lab/gpu} -> lab -> atmosphere (the scenes, references and metrics, CPU only)
# atmosphere and terrain are kept apart, but for the one file of the
# atmosphere's surface-lighting API that terrain/gpu may include (its CMake
# target, planet_atmosphere_surface_lighting, declares it). Only the rooms
# that draw may include a GL header.
#
#   scripts/check-layers.sh [ROOT]    exit 0 when every include points down
set -euo pipefail
root="${1:-$(dirname "$0")/..}"
cd "$root"

rooms=(core gl sim atmosphere clouds terrain governor render lab apps)
files=()
for dir in "${rooms[@]}"; do
  [ -d "$dir" ] || continue
  while IFS= read -r f; do files+=("$f"); done < <(
    find "$dir" -type f \( -name '*.h' -o -name '*.cpp' -o -name '*.glsl' -o -name '*.vert' \
      -o -name '*.frag' -o -name '*.comp' \) | sort)
done
if [ ${#files[@]} -eq 0 ]; then
  echo "check-layers: no sources under $(pwd)" >&2
  exit 2
fi

grep -HnoE '#[[:space:]]*include[[:space:]]*("[^"]+"|<[^>]+>)|"[A-Za-z0-9_./-]+\.(glsl|vert|frag|comp)"' \
  "${files[@]}" | awk -F: '
function room(path) {
  if (path ~ /^atmosphere\/gpu\//) return "atmosphere/gpu"
  if (path ~ /^clouds\/gpu\//) return "clouds/gpu"
  if (path ~ /^terrain\/gpu\//) return "terrain/gpu"
  if (path ~ /^lab\/gpu\//) return "lab/gpu"
  n = index(path, "/")
  return n ? substr(path, 1, n - 1) : ""
}
BEGIN {
  # What each room may include besides itself.
  may["core"] = ""
  may["gl"] = "core"
  may["sim"] = "core"
  may["atmosphere"] = "sim core"
  may["terrain"] = "sim core"
  may["clouds"] = "atmosphere sim core"
  may["clouds/gpu"] = "clouds atmosphere/gpu atmosphere gl sim core"
  may["atmosphere/gpu"] = "atmosphere gl sim core"
  may["terrain/gpu"] = "terrain gl sim core"
  may["governor"] = "atmosphere sim core"
  may["render"] = "governor clouds/gpu clouds atmosphere/gpu terrain/gpu atmosphere terrain gl sim core"
  may["lab"] = "atmosphere sim core"
  may["lab/gpu"] = "lab render governor clouds/gpu clouds atmosphere/gpu terrain/gpu atmosphere terrain gl sim core"
  may["apps"] = "lab/gpu lab render governor clouds/gpu clouds atmosphere/gpu terrain/gpu atmosphere terrain gl sim core"
  # Rooms that draw, and so may include GL headers.
  draws["gl"] = draws["atmosphere/gpu"] = draws["clouds/gpu"] = draws["terrain/gpu"] = 1
  draws["render"] = draws["lab/gpu"] = draws["apps"] = 1
  # The atmosphere surface-lighting API, for the terrain that it lights.
  api["terrain/gpu", "atmosphere/shaders/surface_lighting.glsl"] = 1
  bad = 0
}
{
  file = $1; line = $2; text = substr($0, length($1) + length($2) + 3)
  from = room(file)
  if (text ~ /^#[[:space:]]*include[[:space:]]*</) {
    header = text; sub(/^[^<]*</, "", header); sub(/>.*/, "", header)
    if (header ~ /^(epoxy|GLFW|EGL|GL|KHR)\// && !(from in draws)) {
      printf "%s:%s: includes <%s>, but %s does not draw: GL stays in gl/ and the gpu/ rooms\n", file, line, header, from
      bad++
    }
    next
  }
  target = text; sub(/^[^"]*"/, "", target); sub(/".*/, "", target)
  to = room(target)
  if (to == "" || to == from || !(to in may)) next
  if ((from, target) in api) next
  split(may[from], allowed, " ")
  ok = 0
  for (i in allowed) if (allowed[i] == to) ok = 1
  if (!ok) {
    up = 0
    split(may[to], below, " ")
    for (i in below) if (below[i] == from) up = 1
    printf "%s:%s: includes \"%s\": %s %s %s\n", file, line, target, from,
           up ? "points up to" : "reaches across to", to
    bad++
  }
}
END {
  if (bad) {
    printf "check-layers: %d include%s point up a floor or across rooms\n", bad, bad == 1 ? "" : "s"
    exit 1
  }
  print "check-layers: every include points down"
}'
