#!/usr/bin/env bash
# planet on a real Slurm, as a user runs it there: a one-node cluster on
# this machine (scripts/slurm-one-node.sh), the job-array scripts that
# `planet cluster slurm --tasks 4` writes for a small reference and a short
# capture, run with bash on the submitting side, which queues each array and
# its merge job; sbatch fails inside a job here (as on compute nodes that
# lack it), so nothing may be queued from a task. Once the merge jobs are
# done, the merged outputs must be byte for byte the runs made at once here.
# Skipped (exit 77, with the reason) where the daemons cannot start.
set -uo pipefail
planet="$1"; source_dir="$2"; flight="$3"; work="$4"
rm -rf "$work"; mkdir -p "$work"
work=$(cd "$work" && pwd)
cluster="$work/slurm"
begin=$(date +%s)

"$source_dir/scripts/slurm-one-node.sh" start "$cluster" > "$work/start.txt" 2> "$work/start_err.txt"
rc=$?
if [ "$rc" -eq 77 ]; then
  echo "SKIP: $(cat "$work/start_err.txt")"
  exit 77
fi
# Whatever happens from here, the daemons go and their state with them.
trap '"$source_dir/scripts/slurm-one-node.sh" stop "$cluster"' EXIT
[ "$rc" -eq 0 ] || { echo "FAIL: the cluster did not start (exit $rc):"; cat "$work/start_err.txt"; exit 1; }
export SLURM_CONF="$cluster/slurm.conf"
# sbatch as a compute node without it has it: refused inside any job.
real_sbatch=$(command -v sbatch)
mkdir -p "$work/bin"
cat > "$work/bin/sbatch" << SH
#!/bin/bash
if [ -n "\${SLURM_JOB_ID:-}" ]; then
  echo "sbatch: not on a compute node (job \$SLURM_JOB_ID)" >&2; exit 1
fi
exec "$real_sbatch" "\$@"
SH
chmod +x "$work/bin/sbatch"
export PATH="$work/bin:$PATH"
export PLANET_CACHE_DIR="$work/cache"
echo "one-node Slurm up in $(($(date +%s) - begin)) s: $(sinfo -h -o '%P %D %T %N')"

# A short capture with a frame for each of the 4 tasks (and one more), at
# a tiny size.
sed -e 's/"frame_rate": *[0-9.]*/"frame_rate": 0.2/' \
    -e 's/"width": *[0-9]*/"width": 32/' -e 's/"height": *[0-9]*/"height": 16/' \
    "$flight" > "$work/flight.json"
reference=(reference --scene earth_noon --width 8 --height 4 --spp 256 --quiet)
capture=(capture --flight "$work/flight.json" --quiet)

cd "$work"
single_begin=$(date +%s.%N)
"$planet" "${reference[@]}" --out single/noon.exr > /dev/null || { echo "FAIL: the single reference"; exit 1; }
"$planet" "${capture[@]}" --out single/capture || { echo "FAIL: the single capture"; exit 1; }
single_end=$(date +%s.%N)

"$planet" cluster slurm --tasks 4 "${reference[@]}" --out cluster/noon.exr --script ref_job.sh ||
  { echo "FAIL: planet cluster slurm reference"; exit 1; }
"$planet" cluster slurm --tasks 4 "${capture[@]}" --out cluster/capture --script capture_job.sh ||
  { echo "FAIL: planet cluster slurm capture"; exit 1; }
grep -q -- '--array=0-3' ref_job.sh || { echo "FAIL: no 4-task array in ref_job.sh"; exit 1; }
mkdir -p cluster
submitted=$(date +%s.%N)
bash ref_job.sh > ref_submit.txt 2>&1 || { echo "FAIL: bash ref_job.sh: $(cat ref_submit.txt)"; exit 1; }
bash capture_job.sh > capture_submit.txt 2>&1 ||
  { echo "FAIL: bash capture_job.sh: $(cat capture_submit.txt)"; exit 1; }
cat ref_submit.txt capture_submit.txt

# The submitting side names each merge job; wait for both to end, at most
# 120 s, saying what is still queued every 5 s.
state() { scontrol show job "$1" 2> /dev/null | grep -o 'JobState=[A-Z_]*' | head -1 | cut -d= -f2; }
merge_job() { grep -o 'merge job [0-9]*' "$1" | awk '{print $3}'; }
ref_merge=$(merge_job ref_submit.txt); capture_merge=$(merge_job capture_submit.txt)
for i in $(seq 1 240); do
  done_count=0
  for job in "$ref_merge" "$capture_merge"; do
    case "$(state "${job:-none}")" in
      COMPLETED|FAILED|CANCELLED|TIMEOUT|NODE_FAIL|OUT_OF_MEMORY) done_count=$((done_count + 1)) ;;
    esac
  done
  [ "$done_count" -eq 2 ] && break
  if [ $((i % 10)) -eq 0 ]; then
    echo "waiting ($((i / 2)) s): $(squeue -h -o '%i %j %T' | tr '\n' ';')"
  fi
  sleep 0.5
done
merged=$(date +%s.%N)

failed=0
fail() { echo "FAIL: $*"; failed=1; }
echo "jobs:"
scontrol show job -o 2> /dev/null | sort -t= -k2 -n | awk '{
  for (i = 1; i <= NF; i++)
    if ($i ~ /^(JobId|ArrayJobId|ArrayTaskId|JobName|JobState|ExitCode)=/) printf "%s ", $i
  print "" }'
[ "$(state "${ref_merge:-none}")" = COMPLETED ] || fail "the reference's merge job '${ref_merge}' did not complete"
[ "$(state "${capture_merge:-none}")" = COMPLETED ] || fail "the capture's merge job '${capture_merge}' did not complete"
if [ "$failed" -ne 0 ]; then
  for f in planet-*.out; do echo "--- $f"; cat "$f"; done
  exit 1
fi

compared=0
same() {  # same FILE_A FILE_B
  if cmp "$1" "$2"; then compared=$((compared + 1)); else fail "$2 differs from $1"; fi
}
same single/noon.exr cluster/noon.exr
same single/noon.png cluster/noon.png
for f in single/capture/frame_*.exr single/capture/frame_*.png; do
  same "$f" "cluster/capture/$(basename "$f")"
done
[ "$(ls single/capture/frame_*.exr | wc -l)" -eq 5 ] || fail "the single capture has not 5 frames"
# capture.json as the run at once wrote it, but for the wall time.
if diff <(grep -v wall_seconds single/capture/capture.json) \
        <(grep -v wall_seconds cluster/capture/capture.json); then
  compared=$((compared + 1))
else
  fail "the merged capture.json differs from the single run's beyond its wall time"
fi
ls cluster/noon.shares/share-{0,1,2,3}-of-4.sums > /dev/null || fail "the reference's 4 shares are not all there"
awk -v a="$single_begin" -v b="$single_end" -v c="$submitted" -v d="$merged" 'BEGIN {
  printf "single runs %.1f s; the 4-task arrays, from sbatch to both merges done, %.1f s\n", b - a, d - c }'
[ "$failed" -eq 0 ] && echo "ok: $compared files of the merged reference and capture equal the single runs byte for byte (cmp; capture.json but for its wall time)"
exit $failed
