#!/usr/bin/env bash
# A capture killed at any moment (SIGKILL, KILLS times at spread-out
# points) leaves only whole frames, each byte for byte the uninterrupted
# run's, and `--frames N:` from the first frame without its sidecar ends in
# a folder the same as the uninterrupted run's: the same files, the same
# image bytes, and sidecars that differ only in what was measured (GPU
# times, tiles resident), nothing left of the killed run.
set -euo pipefail
planet="$1"; flight="$2"; work="$3"; kills="${4:-20}"
rm -rf "$work"; mkdir -p "$work"

# 21 frames of the tiny ascent at 32x16.
sed -e 's/"frame_rate": *[0-9.]*/"frame_rate": 1/' -e 's/"width": *64/"width": 32/' \
    -e 's/"height": *32/"height": 16/' "$flight" > "$work/flight.json"

now_ms() { echo $(( $(date +%s%N) / 1000000 )); }
# Starts a capture into $1 in the background (pid in $pid) and waits until
# its first frame is whole: the start-up (GL, shaders, tables) is over.
start_capture() {
  "$planet" capture --flight "$work/flight.json" --out "$1" --quiet 2> "$1.txt" &
  pid=$!
  while kill -0 "$pid" 2>/dev/null && [ ! -f "$1/frame_00000.json" ]; do sleep 0.01; done
}
start_capture "$work/whole"
first_ms=$(now_ms)
wait "$pid"
window_ms=$(( $(now_ms) - first_ms ))
frames=$(find "$work/whole" -maxdepth 1 -name "frame_*.json" | wc -l)
echo "uninterrupted: $frames frames, the last $((frames - 1)) in $window_ms ms"

same_folder() {  # A B: the same files; images equal; sidecars equal but for measurements
  python3 - "$1" "$2" <<'PY'
import json, os, sys
a, b = sys.argv[1], sys.argv[2]
names = lambda d: sorted(n for n in os.listdir(d) if n != "capture.json")
if names(a) != names(b):
    sys.exit(f"files differ: {sorted(set(names(a)) ^ set(names(b)))}")
for n in names(a):
    pa, pb = os.path.join(a, n), os.path.join(b, n)
    if n.endswith(".json"):
        ja, jb = json.load(open(pa)), json.load(open(pb))
        for j in (ja, jb):
            j.pop("gpu_ms", None); j.pop("wall_seconds", None); j.pop("passes_reused", None)
            j["terrain"].pop("tiles_resident", None); j["terrain"].pop("bytes_resident", None)
        if ja != jb:
            sys.exit(f"{n}: sidecars differ beyond their measurements")
    elif open(pa, "rb").read() != open(pb, "rb").read():
        sys.exit(f"{n}: bytes differ")
PY
}

caught_publishing=0
for i in $(seq 1 "$kills"); do
  cut="$work/cut$i"
  # Spread over the frames' writing: from just after the first frame to
  # just before the last.
  delay_ms=$(( window_ms * i / (kills + 1) ))
  start_capture "$cut"
  sleep "$(printf '%d.%03d' $((delay_ms / 1000)) $((delay_ms % 1000)))"
  kill -KILL "$pid" 2>/dev/null || true
  wait "$pid" 2>/dev/null || true
  # Only whole frames: a frame is its sidecar, moved into place after its
  # images. Every file is whole and the uninterrupted run's; images without
  # a sidecar may be there for one frame only, the one after the last whole
  # frame, when the kill fell between the renames that publish it (a few
  # microseconds); the resume writes that frame again.
  complete=0
  if [ -d "$cut" ]; then
    complete=$(find "$cut" -maxdepth 1 -name "frame_*.json" | wc -l)
    next=$(printf 'frame_%05d' "$complete")
    for f in "$cut"/frame_*; do
      [ -e "$f" ] || continue
      stem="${f%.*}"
      if [ ! -f "$stem.json" ]; then
        [ "$(basename "$stem")" = "$next" ] ||
          { echo "FAIL: kill $i ($delay_ms ms in) left $(basename "$f") of an incomplete frame"; exit 1; }
        caught_publishing=$((caught_publishing + 1))
      elif [ ! -f "$stem.png" ] || [ ! -f "$stem.exr" ]; then
        echo "FAIL: kill $i ($delay_ms ms in) left $(basename "$stem").json without its images"; exit 1
      fi
      case "$f" in *.png|*.exr) cmp -s "$f" "$work/whole/$(basename "$f")" ||
        { echo "FAIL: kill $i: $(basename "$f") differs from the uninterrupted run's"; exit 1; } ;; esac
    done
  fi
  if [ "$complete" -lt "$frames" ]; then
    "$planet" capture --flight "$work/flight.json" --out "$cut" --frames "$complete:" --quiet
  fi
  leftovers=$(find "$cut" -name '.partial-*' -o -name '.staging-*' | wc -l)
  [ "$leftovers" -eq 0 ] || { echo "FAIL: kill $i: the resumed folder keeps $leftovers partial files"; exit 1; }
  same_folder "$work/whole" "$cut" || { echo "FAIL: kill $i after $delay_ms ms, resumed from frame $complete"; exit 1; }
  if [ "$complete" -lt "$frames" ]; then
    echo "kill $i $delay_ms ms after the first frame: $complete whole frames, resumed with --frames $complete: to the same folder"
  else
    echo "kill $i $delay_ms ms after the first frame: all $frames frames whole, no resume needed, the same folder"
  fi
  rm -rf "$cut"
done
echo "$kills kills: each left whole frames only and resumed to the uninterrupted run's folder" \
  "($caught_publishing image files of a frame caught between its renames, rewritten by the resume)"
