#!/usr/bin/env bash
# A full disk, as a file-size limit (ulimit -f) makes it: the write that
# fails is one line naming the file, exit status 1, and nothing half
# written is left looking finished (no partial file, no frame without its
# sidecar, no capture.json, no reference image, no table).
set -uo pipefail
planet="$1"; flight="$2"; work="$3"
rm -rf "$work"; mkdir -p "$work"
failed=0

expect_full() {  # NAME FRAGMENT LIMIT_KIB COMMAND...
  local name="$1" fragment="$2" limit="$3"
  shift 3
  (ulimit -f "$limit"; "$@") > "$work/$name.out" 2> "$work/$name.err"
  local rc=$?
  local err
  err="$(cat "$work/$name.err")"
  if [ "$rc" -ne 1 ]; then
    echo "FAIL: $name: exit $rc, expected 1: $err"; failed=1; return
  fi
  if [ "$(printf '%s\n' "$err" | grep -c .)" -ne 1 ] || ! grep -q -- "$fragment" "$work/$name.err"; then
    echo "FAIL: $name: expected one line with '$fragment', got: $err"; failed=1; return
  fi
  local partials
  partials=$(find "$work" -name '.partial-*' -o -name '.staging-*' | wc -l)
  [ "$partials" -eq 0 ] || { echo "FAIL: $name: $partials partial files left"; failed=1; }
  echo "$name: $err"
}

# A capture whose first frame's image does not fit.
expect_full capture "capture/frame_00000.exr: cannot write" 12 \
  "$planet" capture --flight "$flight" --out "$work/capture" --quiet
if [ -d "$work/capture" ]; then
  [ -e "$work/capture/capture.json" ] && { echo "FAIL: a capture that failed has capture.json"; failed=1; }
  for f in "$work"/capture/frame_*; do
    [ -e "$f" ] || continue
    stem="${f%.*}"
    [ -f "$stem.json" ] || { echo "FAIL: $(basename "$f") is left of an incomplete frame"; failed=1; }
  done
fi

# A reference render: its first checkpoint of sums.
expect_full reference ".sums: cannot write: File too large" 1 \
  env PLANET_CACHE_DIR="$work/cache" "$planet" reference --scene earth_noon --width 32 --height 16 \
  --spp 16 --out "$work/ref.exr" --quiet
[ -e "$work/ref.exr" ] && { echo "FAIL: a reference that could not be written exists"; failed=1; }

exit $failed
