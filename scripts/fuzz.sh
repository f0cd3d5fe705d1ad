#!/usr/bin/env bash
# Runs every libFuzzer target of a PLANET_FUZZ build for a bounded time.
#   scripts/fuzz.sh BUILD_DIR [SECONDS_PER_TARGET (default 20)] [TARGET...]
# Each target starts from its seed corpus (tests/fuzz/corpus/T) and from
# what earlier runs in BUILD_DIR found (BUILD_DIR/fuzz-corpus/T, kept
# there, not in the repository). A crash, a leak, a sanitizer report, an
# escaped exception or an input that takes over 10 s (and again when run
# alone: a unit slowed by the machine itself is dropped) is written to
# BUILD_DIR/fuzz-findings/T-*; copy it into tests/fuzz/regressions/T/ once
# fixed, and the test suite replays it from then on. Prints executions and
# findings per target; exits 1 if anything was found.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="$(cd "${1:?usage: scripts/fuzz.sh BUILD_DIR [SECONDS] [TARGET...]}" && pwd)"
seconds="${2:-20}"
shift 2 || shift $#
targets=("$@")
if [ ${#targets[@]} -eq 0 ]; then
  for f in "$build"/fuzz/fuzz_*; do targets+=("$(basename "$f" | sed 's/^fuzz_//')"); done
fi
[ -x "$build/fuzz/fuzz_${targets[0]}" ] ||
  { echo "fuzz.sh: no fuzz targets in $build/fuzz (configure with CXX=clang++ -DPLANET_FUZZ=ON)" >&2; exit 2; }

cd "$root"  # the seeds name shipped files relative to the repository
export PLANET_ROOT="$root"
scratch="$(mktemp -d)"
trap 'rm -rf "$scratch"' EXIT
export TMPDIR="$scratch"
# Leaks are findings; a sanitizer report ends the run.
export ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=1}"
export LSAN_OPTIONS="${LSAN_OPTIONS:-suppressions=$root/tests/sanitizers/lsan.supp}"
mkdir -p "$build/fuzz-findings"
status=0
printf '%-16s %12s %10s %8s %s\n' target executions exec/s corpus findings
for t in "${targets[@]}"; do
  corpus="$build/fuzz-corpus/$t"
  mkdir -p "$corpus"
  touch "$scratch/start"
  before=$(find "$build/fuzz-findings" -name "$t-*" | wc -l)
  log="$build/fuzz-findings/$t.log"
  # -close_fd_mask=1: the command line's target prints --help pages.
  # A fixed seed: a shorter run explores a prefix of a longer one, so CI
  # meets only what a longer run here has met first.
  "$build/fuzz/fuzz_$t" "$corpus" "tests/fuzz/corpus/$t" -max_total_time="$seconds" -timeout=10 \
    -seed="${PLANET_FUZZ_SEED:-1}" \
    -rss_limit_mb=3072 -max_len=65536 -print_final_stats=1 -close_fd_mask=1 \
    -artifact_prefix="$build/fuzz-findings/$t-" > "$log" 2>&1 || true
  # A slow unit that runs in time on its own was the machine stalling, not
  # the input: it is dropped, and said so.
  while IFS= read -r unit; do
    if timeout 60 "$build/fuzz/fuzz_$t" -timeout=10 -close_fd_mask=1 "$unit" \
        > "$scratch/rerun.log" 2>&1; then
      echo "    $t: $(basename "$unit") ran in time on its own: a stall, not a finding" >&2
      rm -f "$unit"
    fi
  done < <(find "$build/fuzz-findings" -name "$t-slow-unit-*" -newer "$scratch/start")
  after=$(find "$build/fuzz-findings" -name "$t-*" | wc -l)
  runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
  rate=$(sed -n 's/^stat::average_exec_per_sec: *//p' "$log" | tail -1)
  size=$(find "$corpus" -type f | wc -l)
  found=$((after - before))
  if [ -z "$runs" ]; then
    echo "fuzz.sh: $t stopped without its statistics; the end of its log:" >&2
    tail -30 "$log" >&2
    found=$((found > 0 ? found : 1))
  fi
  printf '%-16s %12s %10s %8s %s\n' "$t" "${runs:-?}" "${rate:-?}" "$size" "$found"
  if [ "$found" -gt 0 ]; then
    status=1
    grep -m3 -E "ERROR|fuzz: |runtime error|deadly" "$log" | sed 's/^/    /' >&2 || true
    find "$build/fuzz-findings" -name "$t-*" -newer "$scratch/start" | sed 's/^/    input: /' >&2
  fi
done
exit $status
