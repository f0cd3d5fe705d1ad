#!/usr/bin/env bash
# Replays each fuzz target's seed corpus and findings (tests/fuzz/corpus/T,
# tests/fuzz/regressions/T) through planet_fuzz_replay: every input must be
# answered (accepted, or refused with an InputError) without a crash.
set -euo pipefail
replay="$1"; fuzz_dir="$2"; targets="$3"
scratch="$(mktemp -d)"
trap 'rm -rf "$scratch"' EXIT
export TMPDIR="$scratch"
failed=0
for t in $targets; do
  dirs=("$fuzz_dir/corpus/$t")
  [ -d "$fuzz_dir/regressions/$t" ] && dirs+=("$fuzz_dir/regressions/$t")
  if ! "$replay" "$t" "${dirs[@]}" > "$TMPDIR/replay-$t.out" 2> "$TMPDIR/replay-$t.err"; then
    echo "FAIL: $t: $(grep '^replay ' "$TMPDIR/replay-$t.err" | tail -1)"
    tail -20 "$TMPDIR/replay-$t.err"
    failed=1
  else
    tail -1 "$TMPDIR/replay-$t.out"
  fi
done
exit $failed
