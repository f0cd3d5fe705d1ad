#!/usr/bin/env bash
# `planet capture` as a user runs it: two slices of a flight equal the whole
# run byte for byte (`--slices-only` as a fourth argument: that alone), and Ctrl-C (SIGINT) leaves only complete frames and
# says where to resume.
set -euo pipefail
planet="$1"; flight="$2"; work="$3"
rm -rf "$work"; mkdir -p "$work"

"$planet" capture --flight "$flight" --out "$work/whole" --quiet
"$planet" capture --flight "$flight" --out "$work/sliced" --frames 0:2 --quiet
"$planet" capture --flight "$flight" --out "$work/sliced" --frames 2: --quiet
count=0
for f in "$work"/whole/frame_*.png "$work"/whole/frame_*.exr; do
  name=$(basename "$f")
  cmp -s "$f" "$work/sliced/$name" || { echo "FAIL: $name differs between the whole run and the slices"; exit 1; }
  count=$((count + 1))
done
[ "$count" -ge 6 ] || { echo "FAIL: only $count frames"; exit 1; }
echo "$count frames of two slices equal the whole run"

# Only the slices (a flight whose own clock the interrupt test below would
# not keep).
[ "${4:-}" = "--slices-only" ] && exit 0

# A slice outside the flight is refused with exit status 2.
set +e
"$planet" capture --flight "$flight" --out "$work/bad" --frames 2:99 --quiet 2> "$work/bad.txt"
rc=$?
set -e
[ "$rc" -eq 2 ] || { echo "FAIL: slice outside the flight gave exit $rc"; exit 1; }
grep -q "outside the flight" "$work/bad.txt" || { echo "FAIL: no message"; cat "$work/bad.txt"; exit 1; }

# Interrupt after the first frame is complete, in a longer flight (41
# frames) whose sun follows a clock.
sed -e 's/"frame_rate": *[0-9.]*/"frame_rate": 2/' \
    -e 's/"sun": *{[^}]*}/"start_utc": "2026-06-21T06:00:00Z"/' "$flight" > "$work/long.json"
flight="$work/long.json"
"$planet" capture --flight "$flight" --out "$work/whole" --quiet
grep -q '"utc": "2026-06-21T06:00:05.000Z"' "$work/whole/frame_00010.json" ||
  { echo "FAIL: frame 10 (5 s in) has no UTC in its sidecar"; cat "$work/whole/frame_00010.json"; exit 1; }
"$planet" capture --flight "$flight" --out "$work/cut" --quiet 2> "$work/cut.txt" &
pid=$!
for _ in $(seq 1 600); do
  [ -f "$work/cut/frame_00000.json" ] && break
  sleep 0.1
done
kill -INT "$pid"
set +e
wait "$pid"
rc=$?
set -e
if [ -f "$work/cut/capture.json" ]; then
  echo "capture finished before the interrupt arrived; nothing to check"; exit 0
fi
[ "$rc" -eq 130 ] || { echo "FAIL: interrupted capture exited $rc"; cat "$work/cut.txt"; exit 1; }
grep -q -- "resume with --frames" "$work/cut.txt" || { echo "FAIL: no resume hint"; cat "$work/cut.txt"; exit 1; }
for png in "$work"/cut/frame_*.png; do
  stem="${png%.png}"
  [ -f "$stem.exr" ] && [ -f "$stem.json" ] || { echo "FAIL: $png is an incomplete frame"; exit 1; }
  cmp -s "$png" "$work/whole/$(basename "$png")" || { echo "FAIL: $png differs"; exit 1; }
done
resume=$(grep -o -- "--frames [0-9]*:" "$work/cut.txt" | head -1 | cut -d' ' -f2)
"$planet" capture --flight "$flight" --out "$work/cut" --frames "$resume" --quiet
for f in "$work"/whole/frame_*.png; do
  cmp -s "$f" "$work/cut/$(basename "$f")" || { echo "FAIL: resumed $(basename "$f") differs"; exit 1; }
done
cat "$work/cut.txt"
echo "interrupted capture kept complete frames and resumed to the whole"
