#!/usr/bin/env bash
# A one-node Slurm cluster on this machine, for tests: munged, slurmctld and
# slurmd (Debian's slurm-wlm and munge, run as root without systemd), with
# every file they keep under one folder, their own munge socket and key and
# their own ports, so that they touch nothing of a Slurm the machine may
# already run.
#
#   scripts/slurm-one-node.sh start DIR   start the cluster in DIR (made if
#                                         missing); prints the line to give
#                                         its clients: export SLURM_CONF=...
#   scripts/slurm-one-node.sh stop DIR    stop the daemons started in DIR and
#                                         remove DIR
#
# Exit status 77 where the cluster cannot start here (no slurm-wlm or munge,
# not root, a daemon that does not come up), with the reason on stderr.
set -euo pipefail

what="${1:-}"; dir="${2:-}"
if [ -z "$what" ] || [ -z "$dir" ]; then
  echo "usage: scripts/slurm-one-node.sh start|stop DIR" >&2
  exit 2
fi

cannot() { echo "slurm-one-node: cannot start a cluster here: $*" >&2; exit 77; }

# The daemons this folder's pid files name, each stopped by its own id:
# all asked at once, then any still there after 10 s killed.
stop() {
  local name pids=()
  for name in slurmd slurmctld munged; do
    [ -s "$dir/$name.pid" ] && pids+=("$(cat "$dir/$name.pid")")
  done
  [ ${#pids[@]} -gt 0 ] || return 0
  kill "${pids[@]}" 2> /dev/null || true
  local alive pid
  for _ in $(seq 1 100); do
    alive=0
    for pid in "${pids[@]}"; do kill -0 "$pid" 2> /dev/null && alive=1; done
    [ "$alive" -eq 0 ] && return 0
    sleep 0.1
  done
  kill -KILL "${pids[@]}" 2> /dev/null || true
}

if [ "$what" = stop ]; then
  [ -d "$dir" ] || exit 0
  stop
  rm -rf "$dir"
  exit 0
fi
[ "$what" = start ] || { echo "usage: scripts/slurm-one-node.sh start|stop DIR" >&2; exit 2; }

# The daemons live in sbin, which a non-login shell's PATH may lack.
export PATH="$PATH:/usr/sbin:/sbin"
for tool in munged slurmctld slurmd sbatch sinfo; do
  command -v "$tool" > /dev/null || cannot "no $tool (scripts/install-deps.sh installs slurm-wlm and munge)"
done
[ "$(id -u)" -eq 0 ] || cannot "the daemons run as root here, and this is user $(id -un)"

mkdir -p "$dir"
dir=$(cd "$dir" && pwd)
chmod 700 "$dir"
mkdir -p "$dir/state" "$dir/spool"
host=$(hostname -s)
cpus=$(nproc)

# Two free TCP ports: none listening on them now (/proc/net/tcp lists
# them in hex).
port_free() {
  ! grep -qi ":$(printf '%04X' "$1") " /proc/net/tcp /proc/net/tcp6 2> /dev/null
}
port=$((20000 + ($$ % 2000) * 2))
for _ in $(seq 1 200); do
  port_free "$port" && port_free $((port + 1)) && break
  port=$((port + 2))
done

# munge: its own key and socket.
dd if=/dev/urandom of="$dir/munge.key" bs=1024 count=1 status=none
chmod 400 "$dir/munge.key"
munged --socket="$dir/munge.socket" --key-file="$dir/munge.key" --pid-file="$dir/munged.pid" \
  --log-file="$dir/munged.log" --seed-file="$dir/munge.seed" --force \
  || { stop; cannot "munged did not start: $(tail -n 3 "$dir/munged.log" 2> /dev/null | tr '\n' ' ')"; }

cat > "$dir/slurm.conf" <<EOF
ClusterName=planet-test
SlurmctldHost=$host
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
AuthInfo=socket=$dir/munge.socket
CredType=cred/munge
SlurmctldPort=$port
SlurmdPort=$((port + 1))
StateSaveLocation=$dir/state
SlurmdSpoolDir=$dir/spool
SlurmctldPidFile=$dir/slurmctld.pid
SlurmdPidFile=$dir/slurmd.pid
SlurmctldLogFile=$dir/slurmctld.log
SlurmdLogFile=$dir/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
SchedulerType=sched/backfill
MpiDefault=none
ReturnToService=2
AccountingStorageType=accounting_storage/none
JobAcctGatherType=jobacct_gather/none
JobCompType=jobcomp/none
# Finished jobs stay known to scontrol for ten minutes: a test reads their states.
MinJobAge=600
NodeName=$host CPUs=$cpus State=UNKNOWN
PartitionName=main Nodes=$host Default=YES MaxTime=INFINITE State=UP
EOF
export SLURM_CONF="$dir/slurm.conf"

slurmctld -f "$SLURM_CONF" -i \
  || { stop; cannot "slurmctld did not start: $(tail -n 3 "$dir/slurmctld.log" 2> /dev/null | tr '\n' ' ')"; }
slurmd -f "$SLURM_CONF" \
  || { stop; cannot "slurmd did not start: $(tail -n 3 "$dir/slurmd.log" 2> /dev/null | tr '\n' ' ')"; }

# Up when the node is idle, within 30 s.
state=""
for i in $(seq 1 60); do
  state=$(sinfo -h -n "$host" -o %T 2> /dev/null || true)
  [ "$state" = idle ] && break
  [ $((i % 10)) -eq 0 ] && echo "slurm-one-node: waiting for node $host (${state:-no answer yet})" >&2
  sleep 0.5
done
if [ "$state" != idle ]; then
  log=$(tail -n 3 "$dir/slurmctld.log" "$dir/slurmd.log" 2> /dev/null | tr '\n' ' ')
  stop
  cannot "node $host is '${state:-unknown}' after 30 s: $log"
fi
echo "export SLURM_CONF=$SLURM_CONF"
