#!/usr/bin/env bash
# How far hillaire's froxels should reach above the ground, and how many
# steps the march past them needs. From a few km up, the terrain past the
# froxels' range (max(32 km, 4x the altitude)) is marched per pixel, and
# that march is most of the sky pass's time. This captures one view over
# the Alps (pitch -8 deg, 320x180, two frames: the second is timed) at
# 3, 10 and 30 km with the sun 5 and 30 deg up, drawn by:
#   shipped   hillaire as it ships
#   horizon   froxels out to the camera's horizon, sqrt(2 R h)
#   steps20   the march past the froxels with 20 steps (40 ship)
#   steps12   ... with 12 (hillaire:cheap's)
#   ref128    every pixel marched, 128 steps
#   ref256    every pixel marched, 256 steps: the reference, the same
#             model converged (ref128 against it shows how far)
# and prints each one's relative RMSE against ref256 (R G B, linear, from
# the PNGs) over the surfaces (pixels where shipped and horizon differ)
# and over the far terrain (where shipped and steps12 differ), and the
# sky pass's time in the second frame's sidecar.
#   scripts/aerial_range.sh [OUT_DIR]     (default out/aerial_range)
# A capture already in OUT_DIR is kept (an interrupted run goes on where it
# stopped): give a new OUT_DIR to measure a new build.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
out="${1:-$root/out/aerial_range}"
planet="${PLANET:-$root/build/planet}"
[ -x "$planet" ] || { echo "aerial_range: $planet is not built (./build.sh build)" >&2; exit 1; }
mkdir -p "$out"
views=()
for height in 3000 10000 30000; do
  horizon_km=$(awk -v h="$height" 'BEGIN { printf "%.1f", sqrt(2 * 6371e3 * h) / 1e3 }')
  for sun in 5 30; do
    view="${height}m_sun${sun}"
    views+=("$view")
    for variant in "shipped:hillaire" "horizon:hillaire:aerial_range_km=$horizon_km" \
                   "steps20:hillaire:per_pixel_steps=20" "steps12:hillaire:per_pixel_steps=12" \
                   "ref128:hillaire:path=per_pixel,per_pixel_steps=128" \
                   "ref256:hillaire:path=per_pixel,per_pixel_steps=256"; do
      name="${variant%%:*}"
      technique="${variant#*:}"
      dir="$out/$view/$name"
      if [ -f "$dir/frame_00001.json" ]; then continue; fi  # done in an earlier run
      echo "aerial_range: $view $name" >&2
      mkdir -p "$dir"
      cat > "$dir.flight.json" <<EOF
{
  "body": "earth",
  "image": {"width": 320, "height": 180},
  "frame_rate": 1.0,
  "exposure": 8.0,
  "vertical_fov_deg": 60.0,
  "technique": "$technique",
  "sun": {"elevation_deg": $sun, "azimuth_deg": 140.0},
  "keyframes": [
    {"time": 0, "lat_deg": 46.5, "lon_deg": 8.2, "height_m": $height, "heading_deg": 120.0, "pitch_deg": -8.0},
    {"time": 1, "lat_deg": 46.5, "lon_deg": 8.2, "height_m": $height, "heading_deg": 120.0, "pitch_deg": -8.0}
  ]
}
EOF
      "$planet" capture --quiet --flight "$dir.flight.json" --out "$dir"
    done
  done
done
/usr/bin/python3 - "$out" "${views[@]}" <<'PY'
import json, sys
import numpy as np
from PIL import Image

out, views = sys.argv[1], sys.argv[2:]
variants = ["shipped", "horizon", "steps20", "steps12", "ref128"]

def linear(path):
    c = np.asarray(Image.open(path).convert("RGB"), dtype=float) / 255.0
    return np.where(c <= 0.04045, c / 12.92, ((c + 0.055) / 1.055) ** 2.4)

def rel_rmse(x, ref, mask):
    if not mask.any():
        return "   -    -    -"
    errors = [np.sqrt(np.mean((x[..., k][mask] - ref[..., k][mask]) ** 2)) /
              np.sqrt(np.mean(ref[..., k][mask] ** 2)) for k in range(3)]
    return " ".join(f"{100 * e:4.2f}" for e in errors)

print("relative RMSE against ref256, %, R G B; the sky pass's ms (second frame)")
print(f"{'view':<14} {'variant':<8} {'surfaces':>14} {'far terrain':>14} {'sky ms':>7}")
for view in views:
    image = {v: linear(f"{out}/{view}/{v}/frame_00000.png") for v in variants + ["ref256"]}
    surfaces = np.any(image["shipped"] != image["horizon"], axis=2)
    far = np.any(image["shipped"] != image["steps12"], axis=2)
    for v in variants:
        sky_ms = json.load(open(f"{out}/{view}/{v}/frame_00001.json"))["gpu_ms"]["sky"]
        print(f"{view:<14} {v:<8} {rel_rmse(image[v], image['ref256'], surfaces):>14} "
              f"{rel_rmse(image[v], image['ref256'], far):>14} {sky_ms:7.1f}")
    print(f"{'':<14} surfaces {100 * surfaces.mean():.0f} % of the frame, far terrain "
          f"{100 * far.mean():.0f} %")
PY
