#!/usr/bin/env bash
# Every file of data/elevation/<body>/ and data/shapes/<body>/ is the one
# its SOURCE.md names, by its sha256 ("sha256 of `FILE`: HEX"), and every
# file there has such a line; Eros's OBJ gives the PDS table back byte for
# byte by the command its SOURCE.md gives; and the check itself fails on a
# copy with one byte changed.
#   tests/data_checksums.sh SOURCE_DIR
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

grids=("$root"/data/elevation/*/)
[ ${#grids[@]} -ge 3 ] || { echo "data/elevation holds ${#grids[@]} grids, not Earth's, Mars's and the Moon's"; exit 1; }
check "${grids[@]%/}"
echo "ok: ${#grids[@]} grids match their SOURCE.md"

shapes=("$root"/data/shapes/*/)
[ -d "${shapes[0]}" ] || { echo "data/shapes holds no measured shape model"; exit 1; }
check "${shapes[@]%/}"
echo "ok: ${#shapes[@]} shape models match their SOURCE.md"

eros="$root/data/shapes/eros"
tab="$(grep -v '^#' "$eros/eros007790.obj" |
  awk '$1=="v"{printf "%s\r\n", $0; next} {printf "f %14d%14d%14d\r\n", $2-1, $3-1, $4-1}' |
  sha256sum | cut -d' ' -f1)"
grep -q "^sha256 of \`EROS007790.TAB\` (not shipped): $tab\$" "$eros/SOURCE.md" ||
  { echo "eros007790.obj does not give the PDS table back (sha256 $tab)"; exit 1; }
echo "ok: eros007790.obj gives EROS007790.TAB back byte for byte"

work="$(mktemp -d "${TMPDIR:-/tmp}/planet-data.XXXXXX")"
trap 'rm -rf "$work"' EXIT
changed() {  # changed FOLDER FILE SHA256-PREFIX: a byte of FILE changed is found
  local body; body="$(basename "$1")"
  mkdir "$work/$body"
  cp "$1/SOURCE.md" "$1/$2" "$work/$body/"
  printf 'X' | dd of="$work/$body/$2" bs=1 seek=100 conv=notrunc status=none
  if out="$(check "$work/$body")"; then echo "a changed byte of $2 went unnoticed"; exit 1; fi
  grep -q "$2: sha256 .*, SOURCE.md says $3" <<<"$out" || { echo "unexpected: $out"; exit 1; }
}
changed "$root/data/elevation/moon" LDEM_4.LBL b5a197b4
changed "$eros" EROS007790.LBL 9966474b
echo "ok: a changed byte is found"
