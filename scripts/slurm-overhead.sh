#!/usr/bin/env bash
# What running on Slurm costs: the wall time of a small reference and a
# short capture made at once, and of the same as 4-task job arrays with
# their merge job (from `planet cluster slurm`) on a one-node cluster
# (scripts/slurm-one-node.sh), with each job's times from scontrol. The
# merged outputs are checked equal to the runs at once (cmp).
#   scripts/slurm-overhead.sh PLANET WORK   (as root; WORK is emptied)
set -euo pipefail
[ $# -eq 2 ] && [ -n "$2" ] || { echo "usage: scripts/slurm-overhead.sh PLANET WORK" >&2; exit 2; }
src=$(cd "$(dirname "$0")/.." && pwd); planet=$(realpath "$1"); work=$(realpath -m "$2")
rm -rf "$work"; mkdir -p "$work"; cd "$work"
export PLANET_ROOT=$src PLANET_CACHE_DIR=$work/cache
$src/scripts/slurm-one-node.sh start $work/slurm > /dev/null
trap "$src/scripts/slurm-one-node.sh stop $work/slurm" EXIT
export SLURM_CONF=$work/slurm/slurm.conf
sed -e 's/"frame_rate": *[0-9.]*/"frame_rate": 0.2/' -e 's/"width": *[0-9]*/"width": 32/' \
    -e 's/"height": *[0-9]*/"height": 16/' $src/tests/data/flights/tiny_ascent.json > flight.json
ref=(reference --scene earth_noon --width 8 --height 4 --spp 256 --quiet)
cap=(capture --flight flight.json --quiet)
now() { date +%s.%N; }
t0=$(now); $planet "${ref[@]}" --out single/noon.exr > /dev/null; t1=$(now)
$planet "${cap[@]}" --out single/capture; t2=$(now)
$planet cluster slurm --tasks 4 "${ref[@]}" --out c/noon.exr --script ref.sh > /dev/null
$planet cluster slurm --tasks 4 "${cap[@]}" --out c/capture --script cap.sh > /dev/null
wait_merge() {  # wait_merge JOB: until the merge job JOB ends
  local job=$1
  for _ in $(seq 1 600); do
    if scontrol show job "$job" | grep -q 'JobState=COMPLETED'; then echo "$job"; return; fi
    sleep 0.2
  done
  echo "timeout" >&2; exit 1
}
# The scripts queue their array and its merge job themselves, and say their ids.
submit() {
  local said; said=$(bash "$1")
  echo "$(grep -o 'job array [0-9]*' <<< "$said" | cut -d' ' -f3) $(grep -o 'merge job [0-9]*' <<< "$said" | cut -d' ' -f3)"
}
t3=$(now); read -r a m < <(submit ref.sh); wait_merge "$m" > /dev/null; t4=$(now)
cmp single/noon.exr c/noon.exr
t5=$(now); read -r b n < <(submit cap.sh); wait_merge "$n" > /dev/null; t6=$(now)
for f in single/capture/frame_*.exr; do cmp $f c/capture/$(basename $f); done
awk -v a=$t0 -v b=$t1 -v c=$t2 -v d=$t3 -v e=$t4 -v f=$t5 -v g=$t6 'BEGIN {
  printf "reference 8x4 256 spp: at once %.1f s, 4-task array + merge %.1f s\n", b - a, e - d
  printf "capture 5 frames 32x16: at once %.1f s, 4-task array + merge %.1f s\n", c - b, g - f }'
for j in $a $m $b $n; do
  scontrol show job -o $j | awk '{for (i = 1; i <= NF; i++) if ($i ~ /^(JobId|ArrayTaskId|JobName|JobState|SubmitTime|StartTime|EndTime|RunTime)=/) printf "%s ", $i; print ""}'
done
