#!/usr/bin/env bash
# A SLURM cluster of one host, from Debian's slurm-wlm and munge, for trying the cluster tools
# (docs/cluster.md) and for their tests: munged, slurmctld and slurmd on sockets and ports of their
# own, every file (key, configuration, state, logs) in one folder, nothing in /etc.
#
#   bash scripts/slurm_cluster.sh start DIR [PORT]   # then: export SLURM_CONF=DIR/slurm.conf
#   bash scripts/slurm_cluster.sh stop DIR
#
# PORT (16817 by default) is slurmctld's; slurmd takes PORT + 1. The partition is `debug`, with
# every core of this machine. Runs as root (slurmd starts jobs as their user).
set -euo pipefail

usage() {
  echo "usage: bash scripts/slurm_cluster.sh start DIR [PORT], or stop DIR" >&2
  exit 2
}

(($# >= 2)) || usage
action=$1
dir=$2
port=${3:-16817}
if [[ ! $port =~ ^[0-9]{4,5}$ ]] || [[ $port -lt 1024 || $port -gt 65534 ]]; then
  echo "slurm_cluster: PORT: expected an integer in [1024, 65534], got '$port'" >&2
  exit 2
fi

stop_pid_file() {
  local pid_file=$1
  [[ -f $pid_file ]] || return 0
  local pid
  pid=$(cat "$pid_file")
  kill "$pid" 2>/dev/null || true
  for _ in $(seq 50); do
    kill -0 "$pid" 2>/dev/null || break
    sleep 0.1
  done
  kill -9 "$pid" 2>/dev/null || true
  rm -f "$pid_file"
}

# A job still running when slurmd stops keeps its slurmstepd waiting for slurmd for good: cancel
# the cluster's jobs first and give them 10 s to end.
cancel_jobs() {
  [[ -f $dir/slurmctld.pid ]] && kill -0 "$(cat "$dir/slurmctld.pid")" 2> /dev/null || return 0
  SLURM_CONF=$dir/slurm.conf scancel --user="$(id -un)" 2> /dev/null || true
  for _ in $(seq 50); do
    [[ -z $(SLURM_CONF=$dir/slurm.conf squeue -h 2> /dev/null) ]] && return 0
    sleep 0.2
  done
}

# The step daemons of this cluster's jobs that outlived them (known by their SLURM_CONF).
stop_step_daemons() {
  local pid
  for pid in $(pgrep -x slurmstepd); do
    if tr '\0' '\n' < "/proc/$pid/environ" 2> /dev/null | grep -qx "SLURM_CONF=$dir/slurm.conf"; then
      kill -9 "$pid" 2> /dev/null || true
    fi
  done
}

stop() {
  cancel_jobs
  stop_pid_file "$dir/slurmd.pid"
  stop_pid_file "$dir/slurmctld.pid"
  stop_pid_file "$dir/munge/munged.pid"
  stop_step_daemons
}

write_config() {
  local host cpus memory
  host=$(hostname -s)
  cpus=$(nproc)
  memory=$(($(awk '/MemTotal/ {print $2}' /proc/meminfo) / 1024 / 2))
  cat > "$dir/slurm.conf" <<CONF
# Written by scripts/slurm_cluster.sh: one host, every file under $dir.
ClusterName=ari_local
SlurmctldHost=$host
SlurmctldPort=$port
SlurmdPort=$((port + 1))
AuthType=auth/munge
AuthInfo=socket=$dir/munge/munge.socket
CredType=cred/munge
SlurmUser=root
SlurmdUser=root
StateSaveLocation=$dir/state
SlurmdSpoolDir=$dir/spool
SlurmctldPidFile=$dir/slurmctld.pid
SlurmdPidFile=$dir/slurmd.pid
SlurmctldLogFile=$dir/slurmctld.log
SlurmdLogFile=$dir/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
MpiDefault=none
ReturnToService=2
SchedulerType=sched/backfill
# Schedule every second, not every minute: a merge job waiting on an array starts as it ends.
SchedulerParameters=sched_interval=1,bf_interval=1
JobRequeue=1
KillWait=5
NodeName=$host CPUs=$cpus RealMemory=$memory State=UNKNOWN
PartitionName=debug Nodes=$host Default=YES MaxTime=INFINITE State=UP
CONF
}

start_munge() {
  mkdir -p "$dir/munge"
  chmod 700 "$dir/munge"
  if [[ ! -f $dir/munge/munge.key ]]; then
    head -c 1024 /dev/urandom > "$dir/munge/munge.key"
    chmod 400 "$dir/munge/munge.key"
  fi
  munged --force --socket="$dir/munge/munge.socket" --key-file="$dir/munge/munge.key" \
    --pid-file="$dir/munge/munged.pid" --log-file="$dir/munge/munged.log" \
    --seed-file="$dir/munge/munged.seed"
}

# Waits until sinfo shows the node idle: slurmd has registered with slurmctld.
wait_for_node() {
  for _ in $(seq 100); do
    if [[ $(SLURM_CONF=$dir/slurm.conf sinfo -h -o %T 2>/dev/null) == idle* ]]; then
      return 0
    fi
    sleep 0.2
  done
  echo "slurm_cluster: the node did not come up in 20 s (look in $dir/slurmctld.log and" \
    "$dir/slurmd.log)" >&2
  return 1
}

case $action in
  start)
    for program in munged slurmctld slurmd sinfo; do
      command -v "$program" > /dev/null || {
        echo "slurm_cluster: $program not found: run scripts/install_deps.sh" >&2
        exit 2
      }
    done
    stop
    mkdir -p "$dir/state" "$dir/spool"
    dir=$(cd "$dir" && pwd)
    write_config
    start_munge
    SLURM_CONF=$dir/slurm.conf slurmctld -c
    SLURM_CONF=$dir/slurm.conf slurmd -c
    wait_for_node
    echo "export SLURM_CONF=$dir/slurm.conf"
    ;;
  stop)
    [[ -d $dir ]] || exit 0
    dir=$(cd "$dir" && pwd)
    stop
    ;;
  *) usage ;;
esac
