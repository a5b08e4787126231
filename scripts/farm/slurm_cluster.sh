#!/usr/bin/env bash
# slurm_cluster.sh: a single-node Slurm cluster on this machine, in a folder of its own
# (issue 25): for the farm test (tests/farm/farm_test.sh) and to try scripts/farm/farm.sh.
#
#   scripts/farm/slurm_cluster.sh start DIR   munge key, slurm.conf, munged, slurmctld, slurmd
#   scripts/farm/slurm_cluster.sh stop DIR    cancels its jobs, stops the three daemons by the
#                                        process ids they wrote, checks nothing is left
#   scripts/farm/slurm_cluster.sh env DIR     prints the export line clients need (SLURM_CONF)
#
# Everything lives in DIR: etc/slurm.conf, munge/ (key, socket, pid, log), spool/, log/,
# run/ (pid files). The node is this machine (NodeName=$(hostname), CPUs=$(nproc)),
# ProctrackType=proctrack/linuxproc, TaskPlugin=task/none, SlurmdUser=root. munged runs
# as user munge with its own key and socket (nothing of /etc/munge is used);
# slurmctld and slurmd run as root. Needs root and the Debian packages slurm-wlm and
# munge (scripts/setup.sh installs them).
set -euo pipefail

die() { echo "slurm_cluster.sh: error: $*" >&2; exit 2; }

usage() { sed -n '2,15p' "$0" | sed 's/^# \{0,1\}//'; }

(($# == 2)) || { usage >&2; exit 2; }
command=$1
dir=$2

check_packages() {
  local missing=()
  for tool in /usr/sbin/munged /usr/sbin/slurmctld /usr/sbin/slurmd /usr/bin/sbatch /usr/bin/sinfo; do
    [[ -x $tool ]] || missing+=("$tool")
  done
  ((${#missing[@]} == 0)) || die "missing ${missing[*]}: install the Debian packages slurm-wlm and munge (scripts/setup.sh does)"
  id munge >/dev/null 2>&1 || die "no user 'munge': install the Debian package munge (scripts/setup.sh does)"
  ((EUID == 0)) || die "slurmd runs as root (SlurmdUser=root): run this as root"
}

free_port() {  # the first port from $1 on that nobody listens to
  local port=$1
  while ss -ltn 2>/dev/null | awk '{print $4}' | grep -q ":$port\$"; do port=$((port + 1)); done
  echo "$port"
}

wait_for_file() {  # wait_for_file FILE SECONDS WHAT
  local i
  for ((i = 0; i < $2 * 10; i++)); do [[ -s $1 ]] && return 0; sleep 0.1; done
  die "$3 did not start (no $1); see $dir/log and $dir/munge"
}

start() {
  check_packages
  [[ ! -e $dir/run/slurmctld.pid ]] || die "'$dir' holds a running cluster (stop it first)"
  mkdir -p "$dir"/{etc,munge,spool/ctld,spool/d,log,run}
  dir=$(cd "$dir" && pwd)
  chmod 755 "$dir"
  su -s /bin/sh munge -c "test -x '$dir/munge'" ||
    die "user munge cannot reach '$dir' (a parent folder is not searchable: chmod o+x it, or choose another DIR)"
  # munge: a key of our own, readable by user munge only; the folder is munge's.
  dd if=/dev/urandom of="$dir/munge/munge.key" bs=1024 count=1 status=none
  chown -R munge: "$dir/munge"
  chmod 755 "$dir/munge"  # munged wants its socket folder searchable by all
  chmod 400 "$dir/munge/munge.key"
  su -s /bin/sh munge -c "/usr/sbin/munged --key-file='$dir/munge/munge.key' \
    --socket='$dir/munge/munge.socket' --pid-file='$dir/munge/munged.pid' \
    --log-file='$dir/munge/munged.log' --seed-file='$dir/munge/munged.seed'"
  wait_for_file "$dir/munge/munged.pid" 10 munged
  cp "$dir/munge/munged.pid" "$dir/run/munged.pid"

  local host ctld_port d_port
  host=$(hostname)
  ctld_port=$(free_port 6817)
  d_port=$(free_port $((ctld_port + 1)))
  # SchedulerParameters: the main scheduling loop every second instead of 60 and no batch
  # delay, so that an array task or a merge job waits about a second for its turn instead
  # of 2-3 (a farm of short tasks on one node; tests/farm/farm_test.sh with Slurm: 251 s
  # before, 181 s after, the same loaded machine).
  cat >"$dir/etc/slurm.conf" <<EOF
# Written by scripts/farm/slurm_cluster.sh: a single-node cluster in $dir.
ClusterName=specular-farm
SlurmctldHost=$host
SlurmctldPort=$ctld_port
SlurmdPort=$d_port
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
AuthInfo=socket=$dir/munge/munge.socket
CredType=cred/munge
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SchedulerType=sched/backfill
SchedulerParameters=sched_interval=1,bf_interval=1,batch_sched_delay=0
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
MpiDefault=none
ReturnToService=2
StateSaveLocation=$dir/spool/ctld
SlurmdSpoolDir=$dir/spool/d
SlurmctldPidFile=$dir/run/slurmctld.pid
SlurmdPidFile=$dir/run/slurmd.pid
SlurmctldLogFile=$dir/log/slurmctld.log
SlurmdLogFile=$dir/log/slurmd.log
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
MinJobAge=3600
NodeName=$host CPUs=$(nproc) State=UNKNOWN
PartitionName=farm Nodes=ALL Default=YES MaxTime=INFINITE State=UP
EOF
  export SLURM_CONF="$dir/etc/slurm.conf"
  /usr/sbin/slurmctld -f "$SLURM_CONF" -i
  wait_for_file "$dir/run/slurmctld.pid" 20 slurmctld
  /usr/sbin/slurmd -f "$SLURM_CONF"
  wait_for_file "$dir/run/slurmd.pid" 20 slurmd
  local i state=""
  for ((i = 0; i < 300; i++)); do
    state=$(sinfo -h -o %T 2>/dev/null | head -n1 || true)
    [[ $state == idle ]] && break
    sleep 0.1
  done
  [[ $state == idle ]] || die "the node is '${state:-unknown}', not idle, after 30 s; see $dir/log"
  echo "slurm_cluster.sh: node $host idle ($(nproc) CPUs), partition farm; export SLURM_CONF=$SLURM_CONF" >&2
}

stop_pid() {  # stop_pid PIDFILE NAME: TERM, wait up to 10 s, then KILL
  local file=$1 name=$2 pid i
  [[ -s $file ]] || return 0
  pid=$(cat "$file")
  if kill -0 "$pid" 2>/dev/null; then
    kill -TERM "$pid" 2>/dev/null || true
    for ((i = 0; i < 100; i++)); do kill -0 "$pid" 2>/dev/null || break; sleep 0.1; done
    if kill -0 "$pid" 2>/dev/null; then
      echo "slurm_cluster.sh: $name ($pid) ignored TERM; KILL" >&2
      kill -KILL "$pid" 2>/dev/null || true
    fi
  fi
  rm -f "$file"
}

stop() {
  [[ -d $dir ]] || die "no folder '$dir'"
  dir=$(cd "$dir" && pwd)
  export SLURM_CONF="$dir/etc/slurm.conf"
  if [[ -s $dir/run/slurmctld.pid ]] && command -v scancel >/dev/null; then
    scancel --full "--partition=farm" 2>/dev/null || true  # this cluster's jobs only
    local i
    for ((i = 0; i < 100; i++)); do
      [[ -z $(squeue -h 2>/dev/null) ]] && break
      sleep 0.1
    done
  fi
  stop_pid "$dir/run/slurmd.pid" slurmd
  stop_pid "$dir/run/slurmctld.pid" slurmctld
  stop_pid "$dir/run/munged.pid" munged
  local left=()
  for file in "$dir"/run/*.pid "$dir"/munge/munged.pid; do
    [[ -s $file ]] && kill -0 "$(cat "$file")" 2>/dev/null && left+=("$file")
  done
  ((${#left[@]} == 0)) || die "still running: ${left[*]}"
  echo "slurm_cluster.sh: stopped (munged, slurmctld, slurmd)" >&2
}

case "$command" in
  start) start ;;
  stop) stop ;;
  env) echo "export SLURM_CONF='$(cd "$dir" && pwd)/etc/slurm.conf'" ;;
  *) usage >&2; exit 2 ;;
esac
