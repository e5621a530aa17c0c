#!/usr/bin/env bash
# A single-node Slurm cluster on this machine, for tests and for trying the sbatch scripts before a real
# cluster: munged, slurmctld and slurmd from Debian's munge and slurm-wlm, run as root, listening on the
# loopback only, with their key, configuration, state and logs in one folder.
#   scripts/slurm/local-cluster.sh start [DIR]   # default DIR: /tmp/villa-slurm; prints the SLURM_CONF line
#   scripts/slurm/local-cluster.sh stop [DIR]
#   scripts/slurm/local-cluster.sh env [DIR]     # the exports that point sbatch/squeue at it
# Then: export SLURM_CONF=DIR/slurm.conf; sbatch ...
# Needs root (slurmd starts jobs as their users) and the packages (scripts/install-deps.sh installs slurm-wlm and munge).
set -euo pipefail
action=${1:-}
dir=${2:-${VILLA_SLURM_DIR:-/tmp/villa-slurm}}
conf=$dir/slurm.conf

stop() {
  for name in slurmd slurmctld munged; do
    if [[ -f $dir/$name.pid ]]; then
      pid=$(cat "$dir/$name.pid" 2>/dev/null || true)
      if [[ -n $pid ]] && kill -0 "$pid" 2>/dev/null; then
        kill "$pid" 2>/dev/null || true
        for _ in $(seq 50); do kill -0 "$pid" 2>/dev/null || break; sleep 0.1; done
        kill -9 "$pid" 2>/dev/null || true
      fi
      rm -f "$dir/$name.pid"
    fi
  done
}

case $action in
  start)
    [[ $(id -u) == 0 ]] || { echo "local-cluster.sh: start needs root (slurmd runs jobs as their users)" >&2; exit 2; }
    for tool in munged slurmctld slurmd sbatch; do
      command -v "$tool" >/dev/null || { echo "local-cluster.sh: $tool missing: run scripts/install-deps.sh" >&2; exit 1; }
    done
    stop
    mkdir -p "$dir/state" "$dir/spool" "$dir/munge"
    chmod 700 "$dir/munge"
    [[ -s $dir/munge/munge.key ]] || { dd if=/dev/urandom of="$dir/munge/munge.key" bs=1024 count=1 status=none; chmod 400 "$dir/munge/munge.key"; }
    munged --force --key-file="$dir/munge/munge.key" --socket="$dir/munge/munge.socket" \
      --pid-file="$dir/munged.pid" --log-file="$dir/munged.log" --seed-file="$dir/munge/munge.seed"
    node=$(hostname -s)
    cpus=$(nproc)
    mem=$(( $(awk '/MemTotal/ {print $2}' /proc/meminfo) / 1024 - 1024 ))
    cat > "$conf" <<CONF
# Written by scripts/slurm/local-cluster.sh: one node, the loopback, root, no cgroups.
ClusterName=villa-local
SlurmctldHost=$node(127.0.0.1)
SlurmctldPort=${VILLA_SLURMCTLD_PORT:-6817}
SlurmdPort=${VILLA_SLURMD_PORT:-6818}
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$dir/munge/munge.socket
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU_Memory
SchedulerType=sched/backfill
MpiDefault=none
ReturnToService=2
StateSaveLocation=$dir/state
SlurmdSpoolDir=$dir/spool
SlurmctldPidFile=$dir/slurmctld.pid
SlurmdPidFile=$dir/slurmd.pid
SlurmctldLogFile=$dir/slurmctld.log
SlurmdLogFile=$dir/slurmd.log
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
JobAcctGatherType=jobacct_gather/none
SlurmctldTimeout=30
SlurmdTimeout=30
InactiveLimit=0
KillWait=5
MinJobAge=300
NodeName=$node NodeAddr=127.0.0.1 CPUs=$cpus RealMemory=$mem State=UNKNOWN
PartitionName=villa Nodes=$node Default=YES MaxTime=INFINITE State=UP
CONF
    export SLURM_CONF=$conf
    slurmctld -f "$conf"
    slurmd -f "$conf" -N "$node"
    for _ in $(seq 100); do
      if sinfo -h -o %t 2>/dev/null | grep -qE '^(idle|mix|alloc)'; then
        echo "export SLURM_CONF=$conf"
        exit 0
      fi
      sleep 0.2
    done
    echo "local-cluster.sh: the node did not come up in 20 s; logs in $dir:" >&2
    tail -n 20 "$dir/slurmctld.log" "$dir/slurmd.log" >&2 || true
    exit 1
    ;;
  stop) stop ;;
  env) echo "export SLURM_CONF=$conf" ;;
  *) echo "usage: $0 start|stop|env [DIR]" >&2; exit 2 ;;
esac
