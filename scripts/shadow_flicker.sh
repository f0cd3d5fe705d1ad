#!/usr/bin/env bash
# How much the terrain's shadows flicker as the camera moves: captures a
# slow flight (tests/data/flights/slow_shadows.json: 20 m a frame at 3000 m
# over the Alps, the sun 3 deg up, 25 frames) with and without shadows and
# compares each frame's ratio of the two with the frame before. Shadows
# that move with the ground change the ratio along their edges alone; a
# shadow that popped would show as a frame whose changes stand out.
#   scripts/shadow_flicker.sh [OUT_DIR]     (default out/shadow_flicker)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
out="${1:-$root/out/shadow_flicker}"
planet="${PLANET:-$root/build/planet}"
flight="$root/tests/data/flights/slow_shadows.json"
mkdir -p "$out"
sed 's/"height": 270}/"height": 270, "terrain_shadows": false}/' "$flight" > "$out/no_shadows.json"
grep -q '"terrain_shadows": false' "$out/no_shadows.json" || { echo "shadow_flicker: cannot edit $flight" >&2; exit 1; }
"$planet" capture --flight "$flight" --out "$out/on"
"$planet" capture --flight "$out/no_shadows.json" --out "$out/off"
/usr/bin/python3 - "$out/on" "$out/off" <<'PY'
import glob, sys
import numpy as np
from PIL import Image

on_dir, off_dir = sys.argv[1], sys.argv[2]
frames = len(glob.glob(f"{on_dir}/frame_*.png"))

def luminance(path):
    rgb = (np.asarray(Image.open(path).convert("RGB"), dtype=float) / 255.0) ** 2.2
    return rgb.mean(-1)

ratio, lit = [], []
for t in range(frames):
    off = luminance(f"{off_dir}/frame_{t:05d}.png")
    on = luminance(f"{on_dir}/frame_{t:05d}.png")
    ground = off > 1e-3
    ratio.append(np.where(ground, on / np.maximum(off, 1e-6), np.nan))
    lit.append(off)
shadowed, changed, moved = [], [], []
for t in range(1, frames):
    both = ~np.isnan(ratio[t]) & ~np.isnan(ratio[t - 1])
    d = np.abs(ratio[t] - ratio[t - 1])[both]
    shadowed.append((ratio[t][both] < 0.9).mean())
    changed.append((d > 0.1).mean())
    moved.append((np.abs(lit[t] - lit[t - 1])[both] / np.maximum(lit[t][both], 1e-6)).mean())
print(f"{frames} frames: {100 * np.mean(shadowed):.1f} % of the ground in shadow (below 0.9 of its "
      f"radiance without); from one frame to the next, {100 * np.mean(changed):.2f} % of ground pixels "
      f"change their shadow by more than 0.1 (worst frame {100 * np.max(changed):.2f} %); "
      f"the image itself changes by {100 * np.mean(moved):.1f} % a frame")
PY
