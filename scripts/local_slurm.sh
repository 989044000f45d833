#!/bin/bash
# SPDX-License-Identifier: BSD-3-Clause
# A one-node Slurm cluster on this machine, for the test of `register --scans` as a job array (docs/cluster.md):
# its own munge key and munged, its own slurm.conf, state, spool and logs, all in one folder; two CPUs; the
# controller's and the node daemon's ports picked free.
#   scripts/local_slurm.sh start [DIR]  configures and starts munged, slurmctld and slurmd in DIR (default: a new
#                                       temporary folder), waits (at most 60 s) until the node is idle, and prints
#                                       DIR; `source DIR/env.sh` points sbatch, squeue, scancel... at the cluster
#   scripts/local_slurm.sh stop DIR     cancels the cluster's jobs and stops the daemons started in DIR (only those:
#                                       by the pids recorded there); DIR and its logs (DIR/log) stay
# With LOCAL_SLURM_WATCH_PID set, start also leaves a watcher that stops the cluster when that process ends, so
# that a test killed from outside (a ctest time-out) does not leave the daemons behind.
# Needs root (slurmd starts the jobs as their user) and the Debian packages slurmctld, slurmd and munge
# (scripts/install-deps.sh installs them). Exits 77 with the reason when Slurm cannot run here for one of those
# reasons, so that a test can report itself skipped; 1 when the daemons do not come up (their logs are printed).
set -uo pipefail

say () { echo "local_slurm: $*" >&2; }

# Waits at most $1 seconds for the command $2... to succeed.
wait_until () {
  local deadline=$((SECONDS + $1))
  shift
  until "$@" > /dev/null 2>&1; do
    [ $SECONDS -lt "$deadline" ] || return 1
    sleep 0.2
  done
}

free_port () {
  python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])'
}

# Starts daemon $1 (a name for its pid and log files) as `$2...` in the foreground of a new session, in the
# background; records its pid in DIR/$1.pid.
start_daemon () {
  local name=$1
  shift
  setsid "$@" < /dev/null >> "$dir/log/$name.out" 2>&1 &
  echo $! > "$dir/$name.pid"
}

# Stops the daemon whose pid DIR/$1.pid records, if that pid still runs the program $2: SIGTERM, then SIGKILL
# after 15 s.
stop_daemon () {
  local pid
  pid=$(cat "$dir/$1.pid" 2> /dev/null) || return 0
  if [ -n "$pid" ] && grep -q "$2" "/proc/$pid/cmdline" 2> /dev/null; then
    kill -TERM "$pid" 2> /dev/null
    wait_until 15 bash -c "! kill -0 $pid" || kill -KILL "$pid" 2> /dev/null
  fi
  rm -f "$dir/$1.pid"
}

write_config () {
  local node controller_port node_port
  node=$(hostname -s)
  controller_port=$(free_port) && node_port=$(free_port) || return 1
  while [ "$node_port" = "$controller_port" ]; do node_port=$(free_port) || return 1; done
  : > "$dir/plugstack.conf"
  cat > "$dir/slurm.conf" << EOF
# A one-node cluster for morphreg's tests (scripts/local_slurm.sh); everything under $dir.
ClusterName=morphreg$(basename "$dir" | tr -dc 'a-z0-9' | tail -c 8)
SlurmctldHost=$node(127.0.0.1)
SlurmctldPort=$controller_port
SlurmdPort=$node_port
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$dir/munge/munge.socket
StateSaveLocation=$dir/state
SlurmdSpoolDir=$dir/spool
SlurmctldPidFile=$dir/state/slurmctld.daemon.pid
SlurmdPidFile=$dir/spool/slurmd.daemon.pid
SlurmctldLogFile=$dir/log/slurmctld.log
SlurmdLogFile=$dir/log/slurmd.log
PlugStackConfig=$dir/plugstack.conf
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
MpiDefault=none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
SchedulerType=sched/backfill
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
SlurmdParameters=config_overrides
ReturnToService=2
KillWait=5
MinJobAge=600
NodeName=$node NodeAddr=127.0.0.1 CPUs=2 RealMemory=2000 State=UNKNOWN
PartitionName=local Nodes=$node Default=YES MaxTime=INFINITE State=UP
EOF
  echo "export SLURM_CONF=$dir/slurm.conf" > "$dir/env.sh"
}

start_munge () {
  mungekey --create --keyfile="$dir/munge/munge.key" > /dev/null || return 1
  chmod 600 "$dir/munge/munge.key"
  start_daemon munged munged --foreground --force --key-file="$dir/munge/munge.key" \
    --socket="$dir/munge/munge.socket" --pid-file="$dir/munge/munged.pid" --log-file="$dir/log/munged.log" \
    --seed-file="$dir/munge/munged.seed"
  wait_until 20 bash -c "munge -n -S '$dir/munge/munge.socket' | unmunge -S '$dir/munge/munge.socket'"
}

node_idle () { [ "$(SLURM_CONF=$dir/slurm.conf sinfo -h -N -o %T 2> /dev/null)" = idle ]; }

start () {
  for program in munged mungekey slurmctld slurmd sbatch; do
    command -v "$program" > /dev/null || {
      say "skipped: $program is not installed (scripts/install-deps.sh installs slurmctld, slurmd and munge)"
      exit 77
    }
  done
  [ "$(id -u)" -eq 0 ] || { say "skipped: starting slurmd needs root"; exit 77; }
  dir=${1:-$(mktemp -d /tmp/morphreg-slurm.XXXXXX)}
  mkdir -p "$dir"/{munge,state,spool,log} && chmod 700 "$dir" "$dir/munge" || exit 1
  dir=$(realpath "$dir")
  write_config || { say "cannot write $dir/slurm.conf"; exit 1; }
  start_munge || { say "munged did not start"; tail -n 20 "$dir"/log/munged.*; stop; exit 1; }
  export SLURM_CONF=$dir/slurm.conf
  start_daemon slurmctld slurmctld -D -f "$SLURM_CONF"
  start_daemon slurmd slurmd -D -f "$SLURM_CONF"
  if ! wait_until 60 node_idle; then
    say "the node did not come up within 60 s; the daemons' logs:"
    tail -n 30 "$dir"/log/slurm*.log "$dir"/log/*.out >&2
    stop
    exit 1
  fi
  [ -z "${LOCAL_SLURM_WATCH_PID:-}" ] || watch "$LOCAL_SLURM_WATCH_PID"
  echo "$dir"
}

# Stops the cluster once process $1 has ended (or the cluster was stopped otherwise); detached, silent.
watch () {
  setsid bash -c "while kill -0 $1 && [ -f '$dir/slurmctld.pid' ]; do sleep 1; done
    [ -f '$dir/slurmctld.pid' ] && bash '$(realpath "$0")' stop '$dir'" < /dev/null > /dev/null 2>&1 &
}

stop () {
  [ -f "$dir/slurm.conf" ] || { say "$dir: not a folder of local_slurm.sh start"; exit 1; }
  export SLURM_CONF=$dir/slurm.conf
  if [ -f "$dir/slurmctld.pid" ]; then
    scancel --quiet --full --user="$(id -un)" 2> /dev/null
    wait_until 30 bash -c '[ -z "$(squeue -h -o %i 2> /dev/null)" ]' || say "jobs still listed after 30 s"
  fi
  stop_daemon slurmd slurmd
  stop_daemon slurmctld slurmctld
  stop_daemon munged munged
}

case ${1:-} in
start) start "${2:-}" ;;
stop)
  [ -n "${2:-}" ] || { say "usage: $0 stop DIR"; exit 2; }
  dir=$(realpath "$2")
  stop
  ;;
*)
  say "usage: $0 start [DIR] | stop DIR"
  exit 2
  ;;
esac
