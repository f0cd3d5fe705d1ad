#!/usr/bin/env bash
# `planet reference --quiet` prints errors alone: a render, the same again
# from the cache, a share and a merge all write their files and print
# nothing; bad input still gets its one line and exit 2.
set -uo pipefail
planet="$1"; work="$2"
rm -rf "$work"; mkdir -p "$work"
export PLANET_CACHE_DIR="$work/cache"
source "$(dirname "$0")/expect_refusal.sh"  # expect(), failed=0
fail() { echo "FAIL: $*"; failed=1; }
tiny=(--scene earth_noon --width 2 --height 1 --spp 16 --quiet)
silent() {  # silent FILE COMMAND...: it runs well, says nothing and writes FILE
  local file=$1; shift
  "$@" > "$work/out.txt" 2>&1
  local rc=$?
  if [ "$rc" -ne 0 ] || [ -s "$work/out.txt" ] || [ ! -s "$file" ]; then
    fail "'$*' gave exit $rc, $(wc -c < "$work/out.txt") bytes of output, ${file} $([ -s "$file" ] && echo written || echo missing):"
    cat "$work/out.txt"
  else
    echo "ok: silent: ${*:2}"
  fi
}
silent "$work/a.exr" "$planet" reference "${tiny[@]}" --out "$work/a.exr"
silent "$work/b.exr" "$planet" reference "${tiny[@]}" --out "$work/b.exr"  # from the cache
silent "$work/c.shares/share-0-of-1.sums" "$planet" reference "${tiny[@]}" --out "$work/c.exr" --shard 0/1
silent "$work/c.exr" "$planet" reference --merge "$work/c.shares" --out "$work/c.exr" --quiet
cmp -s "$work/a.exr" "$work/c.exr" || fail "the merged share differs from the render at once"
expect "'nope' is not a canonical scene" "$planet" reference --scene nope --out "$work/d.exr" --quiet
exit $failed
