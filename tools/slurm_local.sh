#!/usr/bin/env bash
# A one-node Slurm cluster on this machine, for `fabform study --on slurm` and its test:
#   tools/slurm_local.sh start    install Debian's slurm-wlm and munge if missing, write a munge
#                                 key and a one-node slurm.conf, start munged, slurmctld and
#                                 slurmd, wait until the node is idle
#   tools/slurm_local.sh stop     stop the daemons this script started (by their recorded ids)
#   tools/slurm_local.sh status   sinfo's view; exit 0 when the node takes jobs
# As root (or through sudo), without systemd: the daemons run in the background, their ids in
# /run/fabform-slurm. The node has this machine's CPUs; process tracking by Linux's process
# tree and no task binding (no cgroups needed). No accounting database: jobs are followed with
# squeue and scontrol, which keep a finished job for MinJobAge seconds.
set -euo pipefail

state=/run/fabform-slurm
conf=/etc/slurm/slurm.conf
sudo_cmd=""
[[ $(id -u) -ne 0 ]] && sudo_cmd="sudo"

node_state() { sinfo -h -N -o '%t' 2>/dev/null | head -n1; }

install_missing() {
  local missing=()
  for p in slurm-wlm munge; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
  done
  if ((${#missing[@]})); then
    echo "slurm_local: installing ${missing[*]}" >&2
    $sudo_cmd apt-get update -qq
    DEBIAN_FRONTEND=noninteractive $sudo_cmd apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
  fi
}

write_config() {
  local host cpus memory
  host=$(hostname -s)
  cpus=$(nproc)
  memory=$(( $(awk '/MemTotal/ {print $2}' /proc/meminfo) / 1024 * 9 / 10 ))
  $sudo_cmd mkdir -p /etc/slurm /var/spool/slurmctld /var/spool/slurmd /var/log/slurm "$state"
  $sudo_cmd tee "$conf" >/dev/null <<CONF
# Written by fabform's tools/slurm_local.sh: one node, this machine.
ClusterName=fabform-local
SlurmctldHost=${host}(127.0.0.1)
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
StateSaveLocation=/var/spool/slurmctld
SlurmdSpoolDir=/var/spool/slurmd
SlurmctldPidFile=${state}/slurmctld-daemon.pid
SlurmdPidFile=${state}/slurmd-daemon.pid
SlurmctldLogFile=/var/log/slurm/slurmctld.log
SlurmdLogFile=/var/log/slurm/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
MpiDefault=none
SchedulerType=sched/backfill
# Start the next case as soon as one ends: Slurm otherwise waits up to 3 s (batch_sched_delay)
# between scheduling passes for batch jobs, which would dominate short cases.
SchedulerParameters=batch_sched_delay=0
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
ReturnToService=2
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
# A cancelled task gets SIGTERM, then SIGKILL this many seconds later: fabform writes its
# state on SIGTERM within an iteration.
KillWait=10
MinJobAge=600
NodeName=${host} NodeAddr=127.0.0.1 CPUs=${cpus} RealMemory=${memory} State=UNKNOWN
PartitionName=local Nodes=${host} Default=YES MaxTime=INFINITE State=UP
CONF
}

start_munge() {
  if [[ ! -s /etc/munge/munge.key ]]; then
    $sudo_cmd sh -c 'dd if=/dev/urandom bs=1 count=1024 of=/etc/munge/munge.key 2>/dev/null'
  fi
  $sudo_cmd chown munge:munge /etc/munge/munge.key
  $sudo_cmd chmod 0400 /etc/munge/munge.key
  $sudo_cmd mkdir -p /run/munge /var/log/munge /var/lib/munge
  $sudo_cmd chown munge:munge /run/munge /var/log/munge /var/lib/munge
  if ! munge -n 2>/dev/null | unmunge >/dev/null 2>&1; then
    $sudo_cmd runuser -u munge -- /usr/sbin/munged
    cp /run/munge/munged.pid "$state/munged.pid" 2>/dev/null || true
  fi
  munge -n | unmunge >/dev/null
}

start_daemon() {  # name: slurmctld or slurmd, in the foreground mode (-D), in the background
  local name=$1
  if [[ -f "$state/$name.pid" ]] && kill -0 "$(cat "$state/$name.pid")" 2>/dev/null; then return; fi
  $sudo_cmd sh -c "nohup /usr/sbin/$name -D >>/var/log/slurm/$name.out 2>&1 & echo \$! >$state/$name.pid"
}

start() {
  install_missing
  write_config
  start_munge
  start_daemon slurmctld
  for _ in $(seq 50); do scontrol ping >/dev/null 2>&1 && break; sleep 0.2; done
  start_daemon slurmd
  local s=""
  for _ in $(seq 150); do
    s=$(node_state)
    case "$s" in
      idle|mix|alloc) echo "slurm_local: node $(hostname -s) is $s" >&2; return 0 ;;
      down*|drain*) $sudo_cmd scontrol update nodename="$(hostname -s)" state=resume >/dev/null 2>&1 || true ;;
    esac
    sleep 0.2
  done
  echo "slurm_local: the node did not come up (state '${s}'); see /var/log/slurm/" >&2
  return 1
}

stop() {
  for name in slurmd slurmctld munged; do
    local file="$state/$name.pid"
    [[ -f "$file" ]] || continue
    local pid
    pid=$(cat "$file")
    if kill -0 "$pid" 2>/dev/null; then
      $sudo_cmd kill "$pid"
      for _ in $(seq 50); do kill -0 "$pid" 2>/dev/null || break; sleep 0.1; done
    fi
    $sudo_cmd rm -f "$file"
  done
}

case "${1:-}" in
  start) start ;;
  stop) stop ;;
  status) sinfo; s=$(node_state); [[ "$s" == idle || "$s" == mix || "$s" == alloc ]] ;;
  *) echo "usage: tools/slurm_local.sh start|stop|status" >&2; exit 2 ;;
esac
