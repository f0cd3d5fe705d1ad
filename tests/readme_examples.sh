#!/usr/bin/env bash
# The examples of the README and of the book run as written: every
# `build/planet ...` line of the code blocks of README.md and docs/**/*.md
# that names no word to fill in (FILE, DIR, [options]), but the window (fly),
# the long benchmarks and the lab's whole sweeps, runs from a scratch
# folder with the shipped data, exits 0 within two minutes (under the
# sanitizers, PLANET_EXAMPLE_SECONDS: ten) and prints something. A line that more than one page gives runs once, in the order
# of README.md and then the book's pages by name, all in the one folder
# (so that a page's shares can be merged by its next line). And the README
# names the test command CI runs (.ci/run), as its front door promises.
set -uo pipefail
planet="$1"; source="$2"
seconds="${PLANET_EXAMPLE_SECONDS:-120}"
work="$(mktemp -d /tmp/planet-readme.XXXXXX)"
trap 'rm -rf "$work"' EXIT
export XDG_CACHE_HOME="$work/cache"  # a reference rendered here stays here
ln -s "$source/data" "$work/data"     # the shipped data where the examples name it, as in a clone
failed=0; ran=0
while IFS= read -r line; do
  case "$line" in *" fly"*|*" bench"*) continue ;; esac
  # The lab's whole sweep takes some 25 minutes; a sweep of named scenes runs.
  case "$line" in *" lab run"*) [[ "$line" == *"--scenes"* ]] || continue ;; esac
  # The stability map's whole sweep (or a shard of it) takes an hour or more; named cells run.
  case "$line" in *" lab stability"*) [[ "$line" == *"--cells"* ]] || continue ;; esac
  # The measured day in full takes some 25 minutes; a few directions of one capture run.
  case "$line" in *" lab measured"*) [[ "$line" == *"--directions"* ]] || continue ;; esac
  if echo "$line" | grep -qE '\[|\b(FILE|DIR|NAME|DEG|UTC|MIB|PX|M)\b'; then continue; fi
  command="${line//build\/planet/$planet}"
  command="${command//PLANET_CACHE_DIR=data/PLANET_CACHE_DIR=$source/data}"
  ( cd "$work" && timeout "$seconds" bash -c "$command" ) > "$work/out.txt" 2> "$work/err.txt"
  rc=$?
  ran=$((ran + 1))
  if [ "$rc" -ne 0 ] || [ ! -s "$work/out.txt" ]; then
    echo "FAIL (exit $rc): $line"; cat "$work/err.txt"; failed=1
  else
    echo "ok: $line"
  fi
done < <(cd "$source" && awk 'FNR == 1 { block = 0 }
              /^```/ { block = !block; next }
              block && /^(PLANET_CACHE_DIR=data )?build\/planet / {
                line = $0
                while (line ~ /\\$/) { sub(/\\$/, "", line); getline more; line = line more }
                if (!seen[line]++) print line }' README.md $(find docs -name '*.md' | LC_ALL=C sort))
grep -q '^\./build\.sh test ' "$source/README.md" ||
  { echo "FAIL: README.md does not give CI's test command, ./build.sh test"; failed=1; }
[ "$ran" -ge 6 ] || { echo "FAIL: only $ran examples found"; failed=1; }
exit $failed
