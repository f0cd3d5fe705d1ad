#!/usr/bin/env bash
# The script `planet cluster slurm` writes, run as a user runs it on a
# login node (bash job.sh) against a stand-in sbatch that records its
# calls: it queues the array, then the merge held on the array
# (afterok:<array id>), both from the submitting side; a task runs its
# share and queues nothing (a compute node may have no sbatch); the script
# given to sbatch itself, or a task list that is not one, is refused in one
# line. The real Slurm: cluster_slurm.sh (long tier).
set -uo pipefail
planet="$1"; work="$2"
rm -rf "$work"; mkdir -p "$work/bin"; cd "$work"
failed=0
fail() { echo "FAIL: $*"; failed=1; }
# The stand-in: each call a line in calls.txt, ids from 101; on a compute
# node (SLURM_JOB_ID set) it fails, as where sbatch is not installed there.
cat > bin/sbatch << 'SH'
#!/bin/bash
if [ -n "${SLURM_JOB_ID:-}" ]; then echo "sbatch: not on a compute node" >&2; exit 1; fi
n=$(($(wc -l < "$CALLS" 2> /dev/null || echo 0) + 101))
echo "$*" >> "$CALLS"
echo "$n;cluster"
SH
chmod +x bin/sbatch
export PATH="$work/bin:$PATH" CALLS="$work/calls.txt"
: > calls.txt
"$planet" cluster slurm --tasks 4 --planet /bin/echo reference --scene earth_noon --spp 64 \
  --out "refs/noon dir/noon.exr" --script job.sh > wrote.txt || fail "planet cluster slurm"
grep -q "submit it with bash" wrote.txt || fail "the command does not say how to submit: $(cat wrote.txt)"

bash job.sh > submit.txt 2>&1 || fail "bash job.sh: $(cat submit.txt)"
[ "$(wc -l < calls.txt 2> /dev/null)" = 2 ] || fail "not two sbatch calls: $(cat calls.txt 2> /dev/null)"
first=$(sed -n 1p calls.txt); second=$(sed -n 2p calls.txt)
[[ "$first" == "--parsable --array=0-3 job.sh --task" ]] || fail "the array call: $first"
[[ "$second" == *"--job-name=planet-reference-earth-noon-merge"* ]] || fail "the merge call: $second"
[[ "$second" == *"--dependency=afterok:101 "* ]] || fail "the merge is not held on array 101: $second"
[[ "$second" == *"--merge"* ]] || fail "the merge call runs no merge: $second"
grep -qx "planet: job array 101 (tasks 0-3) and merge job 102, which waits for it" submit.txt ||
  fail "the submitting side says: $(cat submit.txt)"

# A task on a compute node: its share, and no sbatch.
SLURM_JOB_ID=101 SLURM_ARRAY_JOB_ID=101 SLURM_ARRAY_TASK_ID=2 bash job.sh --task > task.txt 2>&1 ||
  fail "task 2: $(cat task.txt)"
grep -qx "reference --scene earth_noon --spp 64 --out refs/noon dir/noon.exr --shard 2/4" task.txt ||
  fail "task 2 ran: $(cat task.txt)"
[ "$(wc -l < calls.txt)" = 2 ] || fail "a task called sbatch: $(sed -n '3,$p' calls.txt)"

refused() {  # refused FRAGMENT ENV...: exit 2 and one line holding FRAGMENT
  local fragment=$1; shift
  env "$@" bash job.sh ${ARG:-} > out.txt 2>&1
  local rc=$?
  if [ "$rc" -ne 2 ] || [ "$(wc -l < out.txt)" -ne 1 ] || ! grep -q -- "$fragment" out.txt; then
    fail "'$* bash job.sh ${ARG:-}' gave exit $rc, expected 2 and one line with '$fragment': $(cat out.txt)"
  else
    echo "ok: $(cat out.txt)"
  fi
}
refused "run it with bash, not sbatch" SLURM_JOB_ID=7 SLURM_ARRAY_JOB_ID=7 SLURM_ARRAY_TASK_ID=0
ARG=x refused "'x' is not a list of tasks (K, K-L or K,L,...) of 0-3"
[ "$(wc -l < calls.txt)" = 2 ] || fail "a refused run called sbatch"

# Tasks 1 and 3 again, and a merge after them.
bash job.sh 1,3 > again.txt 2>&1 || fail "bash job.sh 1,3: $(cat again.txt)"
[[ "$(sed -n 3p calls.txt)" == "--parsable --array=1,3 job.sh --task" ]] || fail "rerun: $(sed -n 3p calls.txt)"
[[ "$(sed -n 4p calls.txt)" == *"--dependency=afterok:103 "* ]] || fail "rerun's merge: $(sed -n 4p calls.txt)"
[ "$failed" -eq 0 ] && echo "ok: the array, then its merge held on it, queued from the submitting side"
exit $failed
