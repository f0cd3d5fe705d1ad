#!/usr/bin/env bash
# The hardening builds, run by CI after the README's test command:
#   1. every target under AddressSanitizer + UndefinedBehaviorSanitizer
#      (clang, -O0: a third of the compile time of -O1) and the whole test
#      suite under them, GL tests included (Mesa's llvmpipe);
#   2. each libFuzzer target of that build for PLANET_FUZZ_SECONDS (20);
#   3. the CPU tests that run threads (the path tracer's pool, the shares,
#      the tile cache's workers) under ThreadSanitizer (-O1);
#   4. tsan-ci: the same build, the threaded tests less the three that
#      check the path tracer's accuracy (minutes each under TSan, and
#      threaded as SameBitsAtOneAndTwoThreads is, which stays).
# Any sanitizer report fails the run; tests/sanitizers/*.supp hold the
# suppressions, each with its reason.
#   scripts/hardening.sh [asan|fuzz|tsan|tsan-ci]...   (default: asan fuzz tsan)
# CI runs `fuzz` and `tsan-ci`: the whole suite under ASan does not fit
# in its time (docs/testing.md#sanitizers).
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
cd "$root"
steps=("$@")
[ ${#steps[@]} -eq 0 ] && steps=(asan fuzz tsan)
asan_dir="${PLANET_ASAN_BUILD_DIR:-build-asan}"
tsan_dir="${PLANET_TSAN_BUILD_DIR:-build-tsan}"
seconds="${PLANET_FUZZ_SECONDS:-20}"
jobs="$(nproc)"
supp="$root/tests/sanitizers"

scripts/install-deps.sh

configure() {  # DIR SANITIZERS OPTIMISATION [extra cmake arguments]
  local dir="$1" sanitize="$2" opt="$3"
  shift 3
  CC=clang CXX=clang++ cmake -S . -B "$dir" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=$opt -gline-tables-only" -DPLANET_SANITIZE="$sanitize" \
    -DCMAKE_UNITY_BUILD=ON -DCMAKE_UNITY_BUILD_BATCH_SIZE=16 \
    -DPLANET_WERROR=ON "$@" > /dev/null
}

export ASAN_OPTIONS="detect_leaks=1:check_initialization_order=1:detect_stack_use_after_return=1:abort_on_error=0"
export LSAN_OPTIONS="suppressions=$supp/lsan.supp:print_suppressions=0"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"

for step in "${steps[@]}"; do
  start=$(date +%s)
  case "$step" in
    asan)
      configure "$asan_dir" address,undefined -O0 -DPLANET_FUZZ=ON
      cmake --build "$asan_dir" -j"$jobs"
      (cd "$asan_dir" && ctest --output-on-failure -j"$jobs")
      ;;
    fuzz)
      configure "$asan_dir" address,undefined -O0 -DPLANET_FUZZ=ON
      targets=()
      for f in tests/fuzz/*_fuzz.cpp; do targets+=("fuzz_$(basename "$f" _fuzz.cpp)"); done
      cmake --build "$asan_dir" -j"$jobs" --target "${targets[@]}"
      scripts/fuzz.sh "$asan_dir" "$seconds"
      ;;
    tsan|tsan-ci)
      # -O1: at -O0 SameBitsAtOneAndTwoThreads alone took 292 s under TSan.
      configure "$tsan_dir" thread -O1
      cmake --build "$tsan_dir" -j"$jobs" --target planet_tests
      # CraterMarksTest is not threaded: it checks that Clang's build places
      # the craters where GCC's does.
      filter='PathTracerTest.*:RenderSharesTest.*:TileCacheTest.*:LodTest.*:ProgressTest.*:CraterMarksTest.*'
      [ "$step" = tsan-ci ] && filter="$filter-PathTracerTest.WhiteFurnaceLosesNoEnergy"\
":PathTracerTest.SingleScatteringAgreesWithQuadrature:PathTracerTest.ColumnTableMatchesDirectIntegration"
      TSAN_OPTIONS="halt_on_error=1:second_deadlock_stack=1:suppressions=$supp/tsan.supp" \
        PLANET_ROOT="$root" "$tsan_dir/tests/planet_tests" --gtest_filter="$filter"
      ;;
    *) echo "hardening.sh: unknown step '$step' (asan, fuzz, tsan, tsan-ci)" >&2; exit 2 ;;
  esac
  echo "hardening: $step passed in $(( $(date +%s) - start )) s"
done
