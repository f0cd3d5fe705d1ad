#!/usr/bin/env bash
# A GL driver that stops answering (simulated: PLANET_GL_SIMULATE_STALL
# blocks the first wait on the driver whose name holds its text, for ever)
# ends the program within PLANET_GL_TIMEOUT_S seconds, with one line naming
# the wait and exit status 1; the capture it stopped leaves no frame that
# looks finished, and the same command then runs to its end with nothing
# of the stopped run left. A bad limit is refused before any work.
set -uo pipefail
planet="$1"; flight="$2"; work="$3"
rm -rf "$work"; mkdir -p "$work"
# The same flight under bruneton:cheap, whose tables are built on the GPU.
sed 's/"body": "earth",/"body": "earth", "technique": "bruneton:cheap",/' "$flight" > "$work/bruneton.json"
failed=0
fail() { echo "FAIL: $*"; failed=1; }
limit=3
stall() {  # TEXT OUT FLIGHT: the capture with a stall at TEXT
  local text="$1" out="$2" flight="$3"
  local began=$SECONDS
  PLANET_GL_TIMEOUT_S=$limit PLANET_GL_SIMULATE_STALL="$text" \
    "$planet" capture --flight "$flight" --out "$out" --quiet 2> "$out.txt"
  rc=$?
  took=$((SECONDS - began))
}
for text in "frame's image" "frame's depth" "bruneton tables"; do
  out="$work/$(echo "$text" | tr -c 'a-z\n' '_')"
  f="$flight"
  [ "$text" = "bruneton tables" ] && f="$work/bruneton.json"
  PLANET_CACHE_DIR="$work/cache" stall "$text" "$out" "$f"
  [ "$rc" -eq 1 ] || fail "stall at '$text': exit status $rc, not 1: $(cat "$out.txt")"
  grep -q "^planet: error: the GL driver has not answered for $limit s while .*$text" "$out.txt" ||
    fail "stall at '$text': no line naming the wait: $(cat "$out.txt")"
  [ "$(wc -l < "$out.txt")" -eq 1 ] || fail "stall at '$text': more than one line: $(cat "$out.txt")"
  # Start-up (GL, shaders, tables) takes a few seconds here; the watch
  # itself gives up $limit s into the stall.
  [ "$took" -le 60 ] || fail "stall at '$text': ended after $took s"
  for image in "$out"/frame_*.png "$out"/frame_*.exr; do
    [ -e "$image" ] || continue
    [ -f "${image%.*}.json" ] || fail "stall at '$text' left $(basename "$image") without its sidecar"
  done
  [ -e "$out/capture.json" ] && fail "stall at '$text' left capture.json, the mark of a finished capture"
  PLANET_CACHE_DIR="$work/cache" "$planet" capture --flight "$f" --out "$out" --quiet \
    || fail "stall at '$text': the capture run again failed"
  [ -e "$out/capture.json" ] || fail "stall at '$text': the capture run again did not finish"
  left=$(find "$out" -name '.staging-*' -o -name '.partial-*' | wc -l)
  [ "$left" -eq 0 ] || fail "stall at '$text': $left files of the stopped run are left"
  echo "stall at '$text': exit 1 after $took s: $(cat "$out.txt")"
done
# A limit that is not one: refused at once, nothing written.
PLANET_GL_TIMEOUT_S=soon "$planet" capture --flight "$flight" --out "$work/bad" --quiet 2> "$work/bad.txt"
rc=$?
[ "$rc" -eq 2 ] || fail "PLANET_GL_TIMEOUT_S=soon: exit status $rc, not 2"
grep -q "PLANET_GL_TIMEOUT_S='soon' is not a number of seconds" "$work/bad.txt" ||
  fail "PLANET_GL_TIMEOUT_S=soon: $(cat "$work/bad.txt")"
[ -e "$work/bad" ] && fail "PLANET_GL_TIMEOUT_S=soon left $work/bad"
[ "$failed" -eq 0 ] && echo "ok: every stall ended in one line within the limit; the captures then finished clean"
exit $failed
