#!/usr/bin/env bash
# Hashes of what the program produces: every shipped flight captured at its
# size (EXR and PNG frames; sidecars hold GPU timings, which vary, so only
# their fields other than timings are hashed), `planet accuracy` on every
# shipped reference (its table and images) and `planet probe` outputs.
# A restructure that claims to change no behaviour runs this before and
# after and compares the two lists:
#   scripts/output-hashes.sh build/planet WORKDIR > before.txt
#   ... change, rebuild ...
#   scripts/output-hashes.sh build/planet WORKDIR > after.txt && diff before.txt after.txt
# Takes about ten minutes on two cores (the captures dominate).
set -euo pipefail

planet="$(realpath "${1:?usage: output-hashes.sh PLANET WORKDIR}")"
work="${2:?usage: output-hashes.sh PLANET WORKDIR}"
root="$(cd "$(dirname "$0")/.." && pwd)"
mkdir -p "$work"
work="$(realpath "$work")"
cd "$root"

hash() { sha256sum "$@" | sed "s|$work/||"; }

# Sidecars without their timings (gpu_ms) and capture.json without its wall
# time: what remains is the frame's deterministic state.
deterministic_json() {
  WORK="$work" /usr/bin/python3 - "$@" <<'EOF'
import hashlib, json, os, sys
for path in sys.argv[1:]:
    d = json.load(open(path))
    for timing in ("gpu_ms", "wall_seconds"):
        d.pop(timing, None)
    text = json.dumps(d, sort_keys=True).encode()
    print(hashlib.sha256(text).hexdigest(), os.path.relpath(path, os.environ["WORK"]), "(timings left out)")
EOF
}

for flight in data/flights/*.json; do
  name="$(basename "$flight" .json)"
  out="$work/capture/$name"
  rm -rf "$out"
  "$planet" capture --flight "$flight" --out "$out" --quiet >/dev/null
  hash "$out"/*.exr "$out"/*.png
  deterministic_json "$out"/*.json
done

mkdir -p "$work/accuracy"
for ref in data/reference/*.exr; do
  case "$ref" in *.noise.exr) continue ;; esac
  base="$(basename "$ref")"
  # The canonical scenes' 32x16 references: not the lab's 64x32 ones, the
  # first orders or the stability map's cells.
  case "$base" in *-order1-*|stability-*) continue ;; *-32x16-*) ;; *) continue ;; esac
  scene="${base%%-32x16-*}"
  spp="${base#*-32x16-}"; spp="${spp%%spp-*}"
  for technique in hillaire hillaire2020 raymarch; do
    out="$work/accuracy/$scene-$technique"
    rm -rf "$out"
    PLANET_CACHE_DIR=data "$planet" accuracy --technique "$technique" --scene "$scene" \
      --spp "$spp" --width 32 --height 16 --out "$out" > "$out.txt"
    hash "$out.txt" "$out"/*
  done
done

mkdir -p "$work/probe"
probe() {
  local name="$1"; shift
  "$planet" probe "$@" > "$work/probe/$name.txt"
  hash "$work/probe/$name.txt"
}
probe transmittance_earth transmittance --planet earth --height 0 --zenith 60
probe transmittance_mars transmittance --planet mars --height 1000 --zenith 85 --mode spectral
probe sky_earth sky --planet earth --height 0 --view-zenith 45 --view-azimuth 90 --sun-zenith 30 --paths 2000
probe sky_mars sky --planet mars --height 10 --view-zenith 80 --view-azimuth 10 --sun-zenith 70 --paths 2000 --mode spectral
probe sun_paris sun --planet earth --lat 48.85 --lon 2.35 --time 2026-06-21T12:00:00Z
probe sun_mars sun --planet mars --lat -4.7 --lon 137.1 --time 2026-06-21T23:25:00Z
probe ground_alps ground --planet earth --lat 46.55 --lon 7.98
probe ground_asteroid ground --planet asteroid --lat 9.95 --lon 29.95
