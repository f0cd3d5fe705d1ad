#!/usr/bin/env bash
# The hardening builds and runs (docs/testing.md#hardening). Steps:
#   asan-quick   every target under AddressSanitizer + UndefinedBehaviorSanitizer
#                (clang, -O1; build-asan/) and the quick tier under them, whole,
#                GL tests included (Mesa's llvmpipe): the tests `./build.sh test`
#                runs
#   asan-long [K/N]  share K of N (K from 0) of the long tier under the same
#                build: the long tier's tests sorted by name, every N-th from
#                the K-th. Without K/N, share K of PLANET_ASAN_LONG_SHARES (3),
#                K the commit's number (git rev-list --count HEAD) modulo N,
#                so that N commits in a row run every share; a share that failed runs
#                again by hand with the K/N it printed;
#                PLANET_ASAN_LONG_LIST=1 lists the share's tests, runs none
#   asan         the whole suite under the same build (by hand: it does not
#                fit in CI's time)
#   fuzz         each libFuzzer target of that build for PLANET_FUZZ_SECONDS (20)
#   tsan         the CPU tests that run threads (the path tracer's pool, the
#                shares, the tile cache's workers) under ThreadSanitizer (-O1)
#   tsan-ci      the same build, the threaded tests less the three that check
#                the path tracer's accuracy (minutes each under TSan, and
#                threaded as SameBitsAtOneAndTwoThreads is, which stays)
# The ASan build is made once a run, however many steps use it. Any
# sanitizer report fails the run; tests/sanitizers/*.supp hold the
# suppressions, each with its reason.
#   scripts/hardening.sh [STEP [K/N]]...   (default: asan fuzz tsan)
# CI (.ci/run) runs asan-quick asan-long fuzz tsan-ci: the long tier's share
# that the commit picks.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
cd "$root"
[ $# -eq 0 ] && set -- asan fuzz tsan
asan_dir="${PLANET_ASAN_BUILD_DIR:-build-asan}"
tsan_dir="${PLANET_TSAN_BUILD_DIR:-build-tsan}"
seconds="${PLANET_FUZZ_SECONDS:-20}"
shares="${PLANET_ASAN_LONG_SHARES:-3}"
jobs="$(nproc)"
supp="$root/tests/sanitizers"

# The steps, each asan-long with its share, checked before any work.
steps=()
while [ $# -gt 0 ]; do
  step="$1"
  shift
  case "$step" in
    asan|asan-quick|fuzz|tsan|tsan-ci) steps+=("$step") ;;
    asan-long)
      if [[ "${1:-}" == */* ]]; then
        share="$1"
        shift
      else
        # The commit's number in its history: N commits in a row run every
        # share.
        count="$(git rev-list --count HEAD 2> /dev/null)" ||
          { echo "hardening.sh: asan-long without K/N needs a git checkout (its commit picks K)" >&2; exit 2; }
        share="$(( count % shares ))/$shares"
      fi
      if ! [[ "$share" =~ ^([0-9]+)/([0-9]+)$ ]] || [ "${BASH_REMATCH[1]}" -ge "${BASH_REMATCH[2]}" ]; then
        echo "hardening.sh: asan-long takes K/N with 0 <= K < N, not '$share'" >&2
        exit 2
      fi
      steps+=("asan-long $share")
      ;;
    *) echo "hardening.sh: unknown step '$step' (asan-quick, asan-long [K/N], asan, fuzz, tsan, tsan-ci)" >&2; exit 2 ;;
  esac
done

[ "${PLANET_ASAN_LONG_LIST:-}" = 1 ] || scripts/install-deps.sh

configure() {  # DIR SANITIZERS OPTIMISATION [extra cmake arguments]
  local dir="$1" sanitize="$2" opt="$3"
  shift 3
  CC=clang CXX=clang++ cmake -S . -B "$dir" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=$opt -gline-tables-only" -DPLANET_SANITIZE="$sanitize" \
    -DCMAKE_UNITY_BUILD=ON -DCMAKE_UNITY_BUILD_BATCH_SIZE=16 \
    -DPLANET_WERROR=ON "$@" > /dev/null
}

# -O1: the quick tier's CPU tests run several times faster than at -O0
# (glm's vector code inlined), which more than pays for the slower build.
asan_built=0
build_asan() {  # [TARGET...]: those alone, where no step before built them all
  [ "$asan_built" = 1 ] && return
  configure "$asan_dir" address,undefined -O1 -DPLANET_FUZZ=ON
  if [ $# -gt 0 ]; then
    cmake --build "$asan_dir" -j"$jobs" --target "$@"
  else
    cmake --build "$asan_dir" -j"$jobs"
    asan_built=1
  fi
}

# The long tier's share K of N: its tests sorted by name, every N-th from
# the K-th, one a line.
long_share() {  # K N
  (cd "$asan_dir" && ctest -N -L long) | sed -n 's/^ *Test *#[0-9]*: //p' | LC_ALL=C sort |
    awk -v k="$1" -v n="$2" '(NR - 1) % n == k'
}
# Names, one a line, as one anchored regular expression for ctest -R.
names_pattern() {
  awk '{ gsub(/[.*+?()|\[\]{}^$]/, "\\\\&"); names = names sep $0; sep = "|" } END { print "^(" names ")$" }'
}

# intercept_tls_get_addr=0: up to LLVM 16 (Debian 12 has clang 14) the
# runtime's __tls_get_addr hook takes a dynamic TLS block that starts 16
# bytes into a page for a glibc 2.19 block with a header, reads a bogus
# address and length from the two words before it, and LeakSanitizer's
# tracer dies reading them at exit ("Tracer caught signal 11"). Mesa's
# driver, loaded with dlopen, has such blocks; where one lands depends on
# the run's allocations, so a test failed that way on every run of a share
# and passed alone. Without the hook LeakSanitizer reads the threads' static
# TLS still; no test reports a leak that lives in dynamic TLS alone.
export ASAN_OPTIONS="detect_leaks=1:check_initialization_order=1:detect_stack_use_after_return=1:abort_on_error=0:intercept_tls_get_addr=0"
# Read from a copy outside the source tree: a test puts the tree out of
# reach (installed_program_runs_outside_the_source_tree), and ASan stops a
# program whose suppressions it cannot read.
lsan_supp="$(mktemp)"
trap 'rm -f "$lsan_supp"' EXIT
cp "$supp/lsan.supp" "$lsan_supp"
export LSAN_OPTIONS="suppressions=$lsan_supp:print_suppressions=0"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"

# The window's tests (fly under Xvfb) run with leak checking off, their
# memory errors still checked: what leaks there is 2 x 56 bytes that a
# library X loads and unloads keeps, which a suppression cannot name
# (tests/sanitizers/README.md). Each test may run twice (a window test
# under load can miss its window's first frame); a report that a test
# makes twice fails it.
window_tests='^fly_'
asan_ctest() {  # ctest arguments
  (cd "$asan_dir" && ctest --output-on-failure -j"$jobs" --repeat until-pass:2 -E "$window_tests" "$@")
  (cd "$asan_dir" && ASAN_OPTIONS="$ASAN_OPTIONS:detect_leaks=0" \
    ctest --output-on-failure -j"$jobs" --repeat until-pass:2 -R "$window_tests" "$@")
}
# The same for a list of tests, one name a line: the window's among them
# apart from the rest (ctest takes one -R, so each part is named in full).
asan_ctest_names() {  # names
  local rest window
  rest="$(grep -Ev "$window_tests" <<< "$1" || true)"
  window="$(grep -E "$window_tests" <<< "$1" || true)"
  if [ -n "$rest" ]; then
    (cd "$asan_dir" && ctest --output-on-failure -j"$jobs" --repeat until-pass:2 \
      -R "$(names_pattern <<< "$rest")")
  fi
  if [ -n "$window" ]; then
    (cd "$asan_dir" && ASAN_OPTIONS="$ASAN_OPTIONS:detect_leaks=0" \
      ctest --output-on-failure -j"$jobs" --repeat until-pass:2 -R "$(names_pattern <<< "$window")")
  fi
}

for step in "${steps[@]}"; do
  start=$(date +%s)
  case "$step" in
    asan)
      build_asan
      asan_ctest
      ;;
    asan-quick)
      build_asan
      asan_ctest -LE long
      ;;
    asan-long*)
      share="${step#asan-long }"
      if [ "${PLANET_ASAN_LONG_LIST:-}" = 1 ]; then  # the share's names alone, from any build
        long_share "${share%/*}" "${share#*/}"
        continue
      fi
      build_asan
      echo "hardening: $step (again by hand: scripts/hardening.sh asan-long $share)"
      names="$(long_share "${share%/*}" "${share#*/}")"
      [ -n "$names" ] || { echo "hardening: asan-long $share holds no test" >&2; exit 1; }
      asan_ctest_names "$names"
      ;;
    fuzz)
      targets=()
      for f in tests/fuzz/*_fuzz.cpp; do targets+=("fuzz_$(basename "$f" _fuzz.cpp)"); done
      build_asan "${targets[@]}"
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
  esac
  echo "hardening: $step passed in $(( $(date +%s) - start )) s"
done
