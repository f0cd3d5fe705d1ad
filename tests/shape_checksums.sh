#!/usr/bin/env bash
# Every file of data/shapes/<body>/ is the one its SOURCE.md names, by its
# sha256 ("sha256 of `FILE`: HEX"), as data/elevation's are; Eros's OBJ
# gives the PDS table back byte for byte by the command its SOURCE.md
# gives; and the check fails on a copy with one byte changed.
#   tests/shape_checksums.sh SOURCE_DIR
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

dirs=("$root"/data/shapes/*/)
[ -d "${dirs[0]}" ] || { echo "data/shapes holds no measured shape model"; exit 1; }
check "${dirs[@]%/}"
echo "ok: ${#dirs[@]} shape models match their SOURCE.md"

eros="$root/data/shapes/eros"
tab="$(grep -v '^#' "$eros/eros007790.obj" |
  awk '$1=="v"{printf "%s\r\n", $0; next} {printf "f %14d%14d%14d\r\n", $2-1, $3-1, $4-1}' |
  sha256sum | cut -d' ' -f1)"
grep -q "^sha256 of \`EROS007790.TAB\` (not shipped): $tab\$" "$eros/SOURCE.md" ||
  { echo "eros007790.obj does not give the PDS table back (sha256 $tab)"; exit 1; }
echo "ok: eros007790.obj gives EROS007790.TAB back byte for byte"

work="$(mktemp -d "${TMPDIR:-/tmp}/planet-shapes.XXXXXX")"
trap 'rm -rf "$work"' EXIT
mkdir "$work/eros"
cp "$eros/SOURCE.md" "$eros/EROS007790.LBL" "$work/eros/"
printf 'X' | dd of="$work/eros/EROS007790.LBL" bs=1 seek=100 conv=notrunc status=none
if out="$(check "$work/eros")"; then echo "a changed byte went unnoticed"; exit 1; fi
grep -q "EROS007790.LBL: sha256 .*, SOURCE.md says 9966474b" <<<"$out" || { echo "unexpected: $out"; exit 1; }
echo "ok: a changed byte is found"
