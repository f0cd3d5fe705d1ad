#!/usr/bin/env bash
# The long tier's shares under ASan (scripts/hardening.sh asan-long K/N):
# for each N, the shares 0..N-1 hold every long test once, and a share
# that is no share of N is refused in one line with status 2.
#   long_shares.sh SOURCE_DIR BUILD_DIR
set -uo pipefail
source_dir="$1" build_dir="$2"
export PLANET_ASAN_BUILD_DIR="$build_dir" PLANET_ASAN_LONG_LIST=1
all="$(cd "$build_dir" && ctest -N -L long | sed -n 's/^ *Test *#[0-9]*: //p' | LC_ALL=C sort)"
[ -n "$all" ] || { echo "FAIL: no long tests in $build_dir"; exit 1; }
failed=0
for n in 1 2 3 4; do
  union=""
  for ((k = 0; k < n; ++k)); do
    share="$("$source_dir/scripts/hardening.sh" asan-long "$k/$n")" ||
      { echo "FAIL: asan-long $k/$n refused"; failed=1; }
    [ -n "$share" ] || { echo "FAIL: asan-long $k/$n is empty"; failed=1; }
    union+="$share"$'\n'
  done
  if [ "$(LC_ALL=C sort <<< "${union%$'\n'}")" != "$all" ]; then
    echo "FAIL: the $n shares do not hold each of the $(wc -l <<< "$all") long tests once"
    failed=1
  fi
done
for bad in 2/2 x/2 1/0 -1/3; do
  out="$("$source_dir/scripts/hardening.sh" asan-long "$bad" 2>&1)"
  status=$?
  if [ "$status" -ne 2 ] || [ "$(wc -l <<< "$out")" -ne 1 ]; then
    echo "FAIL: asan-long $bad gave status $status and: $out"
    failed=1
  fi
done
[ "$failed" -eq 0 ] && echo "ok: $(wc -l <<< "$all") long tests in shares of 1 to 4"
exit $failed
