#!/usr/bin/env bash
# A reference render killed at any moment (SIGKILL, KILLS times in a row,
# each run going on from what the last one kept) leaves in its cache only
# files that are whole: sums the next run reads, and no image that looks
# finished before the render is; the run that finishes writes the bytes of
# a render never stopped, and nothing of the killed runs is left.
set -uo pipefail
planet="$1"; work="$2"; kills="${3:-20}"
rm -rf "$work"; mkdir -p "$work"
failed=0
fail() { echo "FAIL: $*"; failed=1; }
spp=8000,600,8000
render() {  # CACHE: in the background, pid in $pid
  PLANET_CACHE_DIR="$work/$1" "$planet" reference --scene earth_sunset --width 4 --height 2 \
    --spp "$spp" --out "$work/$1/out.exr" --quiet > "$work/$1.txt" 2>&1 &
  pid=$!
}
now_ms() { echo $(( $(date +%s%N) / 1000000 )); }

start=$(now_ms)
render whole; wait "$pid" || { echo "FAIL: the uninterrupted render failed: $(cat "$work/whole.txt")"; exit 1; }
window_ms=$(( $(now_ms) - start ))
echo "uninterrupted: $window_ms ms"
ref="$work/whole/reference"
stem=$(basename "$(ls "$ref"/*.sums)" .sums)

went_on=0; done_before=""
for i in $(seq 1 "$kills"); do
  # Spread over the render, in an order that mixes short and long runs:
  # a short one may die before its first checkpoint, a long one after many.
  delay_ms=$(( window_ms * ((i * 7) % kills + 1) / (kills + 1) ))
  render cut
  sleep "$(printf '%d.%03d' $((delay_ms / 1000)) $((delay_ms % 1000)))"
  kill -KILL "$pid" 2> /dev/null || true
  wait "$pid" 2> /dev/null
  # How far the kept sums have come (their header's line of paths done).
  done_now=$(sed -n 4p "$work/cut/reference/$stem.sums" 2> /dev/null | tr -d '\0' | head -c 200)
  [ -n "$done_now" ] && [ "$done_now" != "$done_before" ] && went_on=$((went_on + 1))
  done_before="$done_now"
  # What looks finished is whole: an image is there only with its noise,
  # each the uninterrupted render's bytes.
  for pair in "reference/$stem.exr" "out.exr" "out.png"; do
    f="$work/cut/$pair"
    [ -e "$f" ] || continue
    case "$pair" in reference/*) [ -e "${f%.exr}.noise.exr" ] ||
      fail "kill $i ($delay_ms ms in): $(basename "$f") is there without its noise" ;; esac
    cmp -s "$f" "$work/whole/$pair" ||
      fail "kill $i ($delay_ms ms in): $pair differs from the uninterrupted render's"
  done
  [ "$failed" -eq 0 ] || exit 1
done

# Under a loaded machine the kills above may all come before a run's
# first checkpoint; then one more run is killed only once its sums have
# moved on, so that a kept checkpoint is still shown to be read again.
if [ "$went_on" -eq 0 ]; then
  render cut
  for _ in $(seq 1 $(( 3 * window_ms / 50 + 200 ))); do
    done_now=$(sed -n 4p "$work/cut/reference/$stem.sums" 2> /dev/null | tr -d '\0' | head -c 200)
    [ -n "$done_now" ] && [ "$done_now" != "$done_before" ] && break
    sleep 0.05
  done
  kill -KILL "$pid" 2> /dev/null || true
  wait "$pid" 2> /dev/null
  done_now=$(sed -n 4p "$work/cut/reference/$stem.sums" 2> /dev/null | tr -d '\0' | head -c 200)
  [ -n "$done_now" ] && [ "$done_now" != "$done_before" ] && went_on=1 &&
    echo "the timed kills all came before a checkpoint; one more, killed after its sums moved on"
fi

# The run that finishes.
render cut; wait "$pid" || { echo "FAIL: the last run failed: $(cat "$work/cut.txt")"; exit 1; }
for f in "$ref"/*; do
  cmp -s "$f" "$work/cut/reference/$(basename "$f")" || fail "$(basename "$f") differs from the uninterrupted render's"
done
for f in out.exr out.png; do
  cmp -s "$work/whole/$f" "$work/cut/$f" || fail "$f differs from the uninterrupted render's"
done
leftovers=$(find "$work/cut" -name '.partial-*' | wc -l)
[ "$leftovers" -eq 0 ] || fail "the finished cache keeps $leftovers partial files"
[ "$went_on" -gt 0 ] || fail "no killed run kept more paths than the one before"
[ "$failed" -eq 0 ] &&
  echo "ok: $kills kills, $went_on of them after the run had kept more paths than the one before; the finished render is byte for byte the uninterrupted one"
exit $failed
