#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# A one-node Slurm cluster on this machine, for running studies as job arrays and for the
# tests that drive a real sbatch:
#   scripts/slurm_local.sh start    munged, slurmctld and slurmd with a minimal slurm.conf
#                                   sized to this machine's cores; prints the SLURM_CONF line
#   scripts/slurm_local.sh stop     cancels this cluster's jobs, stops the three daemons
#   scripts/slurm_local.sh status   sinfo and squeue of this cluster
#   scripts/slurm_local.sh env      prints: export SLURM_CONF=...
# Everything lives in $LOOKAHEAD_SLURM_DIR (default /tmp/lookahead-slurm): slurm.conf, logs,
# state, munge socket, pid files; the system's Slurm and munge setup is left alone. Ports:
# $LOOKAHEAD_SLURM_PORT (slurmctld, default 16817) and the next one (slurmd). Run as root
# (the daemons run as root here); needs the Debian packages slurm-wlm and munge
# (scripts/install_deps.sh).
set -euo pipefail

dir=${LOOKAHEAD_SLURM_DIR:-/tmp/lookahead-slurm}
port=${LOOKAHEAD_SLURM_PORT:-16817}
conf=$dir/slurm.conf
export SLURM_CONF=$conf

die() { echo "slurm_local: $*" >&2; exit 1; }

pid_alive() { [ -f "$1" ] && kill -0 "$(cat "$1")" 2>/dev/null; }

# Stops the process in pid file $1 (TERM, then KILL after 10 s).
stop_pid() {
  local file=$1 pid
  [ -f "$file" ] || return 0
  pid=$(cat "$file")
  if kill -0 "$pid" 2>/dev/null; then
    kill -TERM "$pid" 2>/dev/null || true
    for _ in $(seq 100); do kill -0 "$pid" 2>/dev/null || break; sleep 0.1; done
    kill -0 "$pid" 2>/dev/null && kill -KILL "$pid" 2>/dev/null || true
  fi
  rm -f "$file"
}

write_conf() {
  local host node
  host=$(hostname -s)
  # This machine as slurmd sees it, without the memory (a drained node is worse than none).
  node=$(slurmd -C | head -n1 | sed -e 's/ RealMemory=[0-9]*//')
  cat > "$conf" <<CONF
# Written by scripts/slurm_local.sh: a one-node cluster on $host.
ClusterName=lookahead
SlurmctldHost=$host(127.0.0.1)
SlurmctldPort=$port
SlurmdPort=$((port + 1))
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$dir/munge/munge.socket
StateSaveLocation=$dir/state
SlurmdSpoolDir=$dir/spool
SlurmctldPidFile=$dir/slurmctld.pid
SlurmdPidFile=$dir/slurmd.pid
SlurmctldLogFile=$dir/slurmctld.log
SlurmdLogFile=$dir/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SwitchType=switch/none
MpiDefault=none
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
SchedulerType=sched/backfill
AccountingStorageType=accounting_storage/none
JobAcctGatherType=jobacct_gather/none
JobCompType=jobcomp/none
ReturnToService=2
MaxArraySize=1001
MinJobAge=600
KillWait=5
InactiveLimit=0
SlurmctldTimeout=30
SlurmdTimeout=30
$node NodeAddr=127.0.0.1 State=UNKNOWN
PartitionName=local Nodes=$host Default=YES MaxTime=INFINITE State=UP
CONF
}

start_munge() {
  mkdir -p "$dir/munge"
  chmod 0700 "$dir/munge"
  if [ ! -s /etc/munge/munge.key ]; then
    mkdir -p /etc/munge
    if command -v mungekey >/dev/null; then mungekey --create --keyfile=/etc/munge/munge.key
    else dd if=/dev/urandom of=/etc/munge/munge.key bs=1024 count=1 status=none; fi
    chmod 0400 /etc/munge/munge.key
  fi
  pid_alive "$dir/munged.pid" && return 0
  munged --force --socket="$dir/munge/munge.socket" --key-file=/etc/munge/munge.key \
    --pid-file="$dir/munged.pid" --log-file="$dir/munged.log" --seed-file="$dir/munge/seed" \
    || die "munged did not start (see $dir/munged.log)"
  for _ in $(seq 50); do [ -S "$dir/munge/munge.socket" ] && return 0; sleep 0.1; done
  die "munged made no socket (see $dir/munged.log)"
}

wait_for_node() {
  local host state
  host=$(hostname -s)
  for _ in $(seq 150); do
    state=$(sinfo -h -n "$host" -o %T 2>/dev/null | head -n1 || true)
    case "$state" in
      idle*|mixed*|allocated*) return 0 ;;
      drain*|down*) scontrol update nodename="$host" state=resume >/dev/null 2>&1 || true ;;
    esac
    sleep 0.2
  done
  die "node $host not ready (state '$state'; see $dir/slurmctld.log and $dir/slurmd.log)"
}

start() {
  [ "$(id -u)" -eq 0 ] || die "run as root (the daemons of this one-node cluster run as root)"
  for b in munged slurmctld slurmd sbatch sinfo; do
    command -v "$b" >/dev/null || die "$b not found: run scripts/install_deps.sh (slurm-wlm, munge)"
  done
  mkdir -p "$dir/state" "$dir/spool"
  chmod 0755 "$dir"
  start_munge
  if ! pid_alive "$dir/slurmctld.pid"; then
    write_conf
    slurmctld -c -f "$conf" || die "slurmctld did not start (see $dir/slurmctld.log)"
  fi
  pid_alive "$dir/slurmd.pid" || slurmd -f "$conf" || die "slurmd did not start (see $dir/slurmd.log)"
  wait_for_node
  echo "export SLURM_CONF=$conf"
}

stop() {
  if pid_alive "$dir/slurmctld.pid"; then
    scancel --full --quiet --user="$(id -un)" 2>/dev/null || true
    # Jobs end within KillWait (5 s); their steps belong to slurmd, so wait before stopping it.
    for _ in $(seq 100); do
      [ -z "$(squeue -h -o %i 2>/dev/null)" ] && break
      sleep 0.2
    done
  fi
  stop_pid "$dir/slurmd.pid"
  stop_pid "$dir/slurmctld.pid"
  stop_pid "$dir/munged.pid"
}

case "${1:-}" in
  start) start ;;
  stop) stop ;;
  status) sinfo; squeue ;;
  env) echo "export SLURM_CONF=$conf" ;;
  *) echo "usage: $0 start|stop|status|env" >&2; exit 2 ;;
esac
