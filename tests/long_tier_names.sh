#!/usr/bin/env bash
# Every GoogleTest case tests/CMakeLists.txt puts in the long tier names a
# test of its program: a renamed test would otherwise leave the long tier
# unnoticed and run in `./build.sh test`.
#   long_tier_names.sh PROGRAM NAME...   (NAME as a --gtest_filter pattern)
set -uo pipefail
program="$1"
shift
# "Suite.Case" per line, as the filter matches them.
tests="$("$program" --gtest_list_tests | awk '/^[^ ]/ { suite = $1; next } { print suite $1 }')"
failed=0
for name in "$@"; do
  found=0
  while IFS= read -r test; do
    # shellcheck disable=SC2053  # the name is a pattern: * and ? as GoogleTest reads them
    if [[ "$test" == $name ]]; then found=1; break; fi
  done <<< "$tests"
  if [ "$found" -eq 0 ]; then
    echo "FAIL: the long tier names $name, which $(basename "$program") does not have"
    failed=1
  fi
done
[ "$failed" -eq 0 ] && echo "ok: $# names"
exit $failed
