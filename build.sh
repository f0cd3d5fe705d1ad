#!/usr/bin/env bash
# The project's entry point. On a fresh Debian 12 machine:
#   ./build.sh run        install what is missing, build, capture the Earth ascent into out/ascent
#   ./build.sh test       install what is missing, build, run the test suite (CTest) but its
#                         long tier (tests of 12 s and more each)
#   ./build.sh test-long  the same for the long tier alone; CI runs both (.ci/run)
#   ./build.sh build      install what is missing, build only
# Warnings are errors when CI is set (as in CI runs) or PLANET_WERROR=ON.
set -euo pipefail
cd "$(dirname "$0")"

what="${1:-run}"
shift || true
build_dir="${PLANET_BUILD_DIR:-build}"
werror="${PLANET_WERROR:-$([ -n "${CI:-}" ] && echo ON || echo OFF)}"

case "$what" in
  run|test|test-long|build) ;;
  *) echo "usage: ./build.sh [run|test|test-long|build]" >&2; exit 2 ;;
esac

scripts/install-deps.sh
cmake -S . -B "$build_dir" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DPLANET_WERROR="$werror" >/dev/null
cmake --build "$build_dir" -j"$(nproc)"

case "$what" in
  run)        exec "$build_dir/planet" capture --flight data/flights/ascent.json --out out/ascent "$@" ;;
  test)       cd "$build_dir" && exec ctest --output-on-failure -j"$(nproc)" -LE long "$@" ;;
  test-long)  cd "$build_dir" && exec ctest --output-on-failure -j"$(nproc)" -L long "$@" ;;
  build)      ;;
esac
