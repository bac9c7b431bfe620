#!/usr/bin/env bash
# A one-node Slurm cluster of its own in a folder, for the farm test and bench/farm_bench.sh:
# munged with its own key and socket, slurmctld and slurmd with a generated slurm.conf on
# loopback ports (proctrack/linuxproc and task/none: no cgroups needed).
#   slurm_cluster.sh start DIR [CPUS]   starts it; prints the lines to source (SLURM_CONF)
#   slurm_cluster.sh stop DIR           cancels every job and stops the daemons it started, by pid
# Run it inside a network namespace of its own (unshare -n, see run_in_netns) for loopback only.
set -euo pipefail

cmd="$1"; dir="$(cd "$2" && pwd)"; cpus="${3:-2}"

pid_alive() { [ -n "$1" ] && kill -0 "$1" 2>/dev/null; }
stop_pid() {  # stops the daemon whose pid file is $1, waiting up to 10 s, then KILL
  local f="$1" pid
  [ -f "$f" ] || return 0
  pid="$(cat "$f")"
  if pid_alive "$pid"; then
    kill -TERM "$pid" 2>/dev/null || true
    for _ in $(seq 100); do pid_alive "$pid" || break; sleep 0.1; done
    pid_alive "$pid" && kill -KILL "$pid" 2>/dev/null || true
  fi
  rm -f "$f"
}

free_port() {
  python3 -c 'import socket; s=socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1]); s.close()'
}

case "$cmd" in
start)
  mkdir -p "$dir/ctld" "$dir/slurmd" "$dir/log"
  host="$(hostname -s)"
  ctld_port="$(free_port)"; slurmd_port="$(free_port)"
  while [ "$slurmd_port" = "$ctld_port" ]; do slurmd_port="$(free_port)"; done
  mungekey --create --keyfile="$dir/munge.key" --force >/dev/null 2>&1 ||
    { dd if=/dev/urandom of="$dir/munge.key" bs=1024 count=1 status=none; }
  chmod 0400 "$dir/munge.key"
  munged --force --socket="$dir/munge.sock" --key-file="$dir/munge.key" --pid-file="$dir/munged.pid" \
         --log-file="$dir/log/munged.log" --seed-file="$dir/munge.seed"
  for _ in $(seq 50); do [ -S "$dir/munge.sock" ] && break; sleep 0.1; done
  [ -S "$dir/munge.sock" ] || { echo "slurm_cluster: munged did not start (see $dir/log/munged.log)" >&2; exit 1; }
  cat >"$dir/slurm.conf" <<CONF
ClusterName=sptfarm
SlurmctldHost=$host(127.0.0.1)
SlurmctldPort=$ctld_port
SlurmdPort=$slurmd_port
AuthType=auth/munge
AuthInfo=socket=$dir/munge.sock
CredType=cred/munge
SlurmUser=root
SlurmdUser=root
StateSaveLocation=$dir/ctld
SlurmdSpoolDir=$dir/slurmd
SlurmctldPidFile=$dir/slurmctld.pid
SlurmdPidFile=$dir/slurmd.pid
SlurmctldLogFile=$dir/log/slurmctld.log
SlurmdLogFile=$dir/log/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
SchedulerType=sched/backfill
SchedulerParameters=sched_min_interval=100000,bf_interval=1
ReturnToService=2
JobRequeue=1
MpiDefault=none
SwitchType=switch/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
JobAcctGatherType=jobacct_gather/none
MinJobAge=600
KillWait=5
SlurmdTimeout=30
InactiveLimit=0
NodeName=$host NodeAddr=127.0.0.1 CPUs=$cpus RealMemory=1000 State=UNKNOWN
PartitionName=spt Nodes=$host Default=YES MaxTime=INFINITE State=UP
CONF
  export SLURM_CONF="$dir/slurm.conf"
  slurmctld -f "$dir/slurm.conf" -i
  for _ in $(seq 100); do [ -f "$dir/slurmctld.pid" ] && scontrol ping >/dev/null 2>&1 && break; sleep 0.1; done
  slurmd -f "$dir/slurm.conf" -N "$host"
  for _ in $(seq 200); do
    state="$(sinfo -h -N -o %t 2>/dev/null | head -1)"
    case "$state" in idle*|mix*|alloc*) break ;; esac
    sleep 0.1
  done
  case "$state" in idle*|mix*|alloc*) ;; *)
    echo "slurm_cluster: the node did not come up (state '$state'; logs in $dir/log)" >&2; exit 1 ;; esac
  echo "export SLURM_CONF=$dir/slurm.conf"
  ;;
stop)
  export SLURM_CONF="$dir/slurm.conf"
  if [ -f "$dir/slurmctld.pid" ] && pid_alive "$(cat "$dir/slurmctld.pid")"; then
    scancel --full --quiet --user="$(id -un)" 2>/dev/null || true
    for _ in $(seq 100); do [ -z "$(squeue -h 2>/dev/null)" ] && break; sleep 0.1; done
  fi
  stop_pid "$dir/slurmd.pid"
  stop_pid "$dir/slurmctld.pid"
  stop_pid "$dir/munged.pid"
  ;;
*) echo "usage: slurm_cluster.sh start|stop DIR [CPUS]" >&2; exit 2 ;;
esac
