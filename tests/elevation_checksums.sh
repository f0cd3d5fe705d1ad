#!/usr/bin/env bash
# Every file of data/elevation/<body>/ is the one its SOURCE.md names, by
# its sha256 ("sha256 of `FILE`: HEX"), and every file there has such a
# line. Then the check itself fails on a copy with one byte changed.
#   tests/elevation_checksums.sh SOURCE_DIR
set -euo pipefail
root="$1"

check() {  # check DIR...: 0 when every file matches its SOURCE.md
  local bad=0
  for dir in "$@"; do
    local source="$dir/SOURCE.md"
    [ -f "$source" ] || { echo "$dir: no SOURCE.md"; bad=1; continue; }
    for f in "$dir"/*; do
      local name; name="$(basename "$f")"
      [ "$name" = SOURCE.md ] && continue
      local want
      want="$(sed -n "s/^sha256 of \`$name\`: \([0-9a-f]\{64\}\)\$/\1/p" "$source")"
      if [ -z "$want" ]; then echo "$f: SOURCE.md gives no sha256 for it"; bad=1; continue; fi
      local got; got="$(sha256sum "$f" | cut -d' ' -f1)"
      if [ "$got" != "$want" ]; then echo "$f: sha256 $got, SOURCE.md says $want"; bad=1; fi
    done
  done
  return $bad
}

dirs=("$root"/data/elevation/*/)
[ ${#dirs[@]} -ge 3 ] || { echo "data/elevation holds ${#dirs[@]} grids, not Earth's, Mars's and the Moon's"; exit 1; }
check "${dirs[@]%/}"
echo "ok: ${#dirs[@]} grids match their SOURCE.md"

work="$(mktemp -d "${TMPDIR:-/tmp}/planet-elevation.XXXXXX")"
trap 'rm -rf "$work"' EXIT
mkdir "$work/moon"
cp "$root/data/elevation/moon/SOURCE.md" "$root/data/elevation/moon/LDEM_4.LBL" "$work/moon/"
printf 'X' | dd of="$work/moon/LDEM_4.LBL" bs=1 seek=100 conv=notrunc status=none
if out="$(check "$work/moon")"; then echo "a changed byte went unnoticed"; exit 1; fi
grep -q "LDEM_4.LBL: sha256 .*, SOURCE.md says b5a197b4" <<<"$out" || { echo "unexpected: $out"; exit 1; }
echo "ok: a changed byte is found"
