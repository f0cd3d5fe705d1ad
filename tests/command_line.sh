#!/usr/bin/env bash
# The command line as a newcomer reads it, in parts:
#   help    `--help` is short and says where the techniques are listed;
#           `planet techniques` holds their table; `--version` answers.
#   command_line.sh PLANET PART WORK   (PLANET_ROOT: the source tree)
# Nothing here starts GL: each case is help, a probe, or bad input
# refused before any work.
set -uo pipefail
planet="$1"; part="$2"; work="$3"
rm -rf "$work"; mkdir -p "$work"
source "$(dirname "$0")/expect_refusal.sh"
fail() { echo "FAIL: $*"; failed=1; }

# Runs the command, which must succeed; its standard output in $work/out.txt.
succeed() {
  if ! "$@" > "$work/out.txt" 2> "$work/err.txt"; then
    fail "'$*' failed:"; cat "$work/err.txt"
  fi
}

case "$part" in
help)
  # The table of techniques, 60 lines, under every command's --help
  # drowned its options.
  for command in "" capture fly soak probe "probe sun" "probe ground" lab accuracy; do
    # shellcheck disable=SC2086
    succeed "$planet" $command --help
    lines=$(wc -l < "$work/out.txt")
    if grep -q "Atmosphere techniques:" "$work/out.txt"; then
      fail "planet $command --help holds the table of techniques"
    fi
    echo "planet $command --help: $lines lines"
  done
  succeed "$planet" --help
  [ "$(wc -l < "$work/out.txt")" -le 25 ] || fail "planet --help is over 25 lines"
  grep -q "planet techniques" "$work/out.txt" || fail "planet --help does not point at planet techniques"
  succeed "$planet" probe --help
  [ "$(wc -l < "$work/out.txt")" -le 20 ] || fail "planet probe --help is over 20 lines"
  succeed "$planet" techniques
  grep -q "Atmosphere techniques:" "$work/out.txt" || fail "planet techniques has no table"
  for t in hillaire raymarch bruneton oneil; do
    grep -q "$t" "$work/out.txt" || fail "planet techniques does not list $t"
  done
  version=$(sed -n 's/^project(planet VERSION \([0-9.]*\).*/\1/p' "$PLANET_ROOT/CMakeLists.txt")
  succeed "$planet" --version
  [ "$(cat "$work/out.txt")" = "planet $version" ] ||
    fail "planet --version said '$(cat "$work/out.txt")', not 'planet $version'"
  ;;
*)
  echo "usage: command_line.sh PLANET help WORK" >&2; exit 2 ;;
esac
exit $failed
