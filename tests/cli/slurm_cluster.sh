#!/usr/bin/env bash
# A real single-node Slurm for the tests (Debian slurm-wlm + munge), in a temporary folder: munged
# with a generated key, slurmctld and slurmd with a generated slurm.conf (one node, localhost,
# ports of its own), all as root. Source it, then `slurm_up DIR` and `slurm_down` (also on EXIT).
# Sets SLURM_CONF for sbatch/squeue/sinfo. Needs root (slurmd runs the jobs as their user).

slurm_pids=()

slurm_down() {
  local p
  for p in "${slurm_pids[@]}"; do kill "$p" 2>/dev/null; done
  for p in "${slurm_pids[@]}"; do
    for _ in $(seq 50); do kill -0 "$p" 2>/dev/null || break; sleep 0.1; done
    kill -9 "$p" 2>/dev/null
  done
  slurm_pids=()
}

# slurm_up DIR: starts the cluster with its state in DIR; returns 1 (with the logs) if it does not come up.
slurm_up() {
  local d=$1
  [[ $(id -u) -eq 0 ]] || { echo "slurm test: needs root (slurmd, munged)"; return 1; }
  local b
  for b in munged slurmctld slurmd sbatch squeue sinfo scancel; do
    command -v "$b" >/dev/null || { echo "slurm test: $b missing (scripts/install_deps.sh installs slurm-wlm, munge)"; return 1; }
  done
  mkdir -p "$d/state" "$d/spool" "$d/munge"
  chmod 700 "$d/munge"
  head -c 1024 /dev/urandom > "$d/munge/munge.key"
  chmod 400 "$d/munge/munge.key"
  munged --force --key-file="$d/munge/munge.key" --socket="$d/munge/munge.sock" \
    --pid-file="$d/munge/munged.pid" --log-file="$d/munge/munged.log" --seed-file="$d/munge/munged.seed" || return 1
  slurm_pids+=("$(cat "$d/munge/munged.pid")")
  # ports of our own, so that a Slurm on the machine is not disturbed
  local port=$((17000 + RANDOM % 2000))
  local cpus; cpus=$(nproc)
  cat > "$d/slurm.conf" <<CONF
ClusterName=drydemtest
SlurmctldHost=localhost
SlurmUser=root
SlurmdUser=root
SlurmctldPort=$port
SlurmdPort=$((port + 1))
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$d/munge/munge.sock
StateSaveLocation=$d/state
SlurmdSpoolDir=$d/spool
SlurmctldPidFile=$d/slurmctld.pid
SlurmdPidFile=$d/slurmd.pid
SlurmctldLogFile=$d/slurmctld.log
SlurmdLogFile=$d/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
MpiDefault=pmix
SchedulerType=sched/backfill
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
ReturnToService=2
SlurmdTimeout=60
InactiveLimit=0
KillWait=10
MinJobAge=60
NodeName=localhost CPUs=$cpus State=UNKNOWN
PartitionName=test Nodes=localhost Default=YES MaxTime=INFINITE State=UP
CONF
  export SLURM_CONF=$d/slurm.conf
  slurmctld -c -f "$d/slurm.conf" || { cat "$d/slurmctld.log"; return 1; }
  for _ in $(seq 50); do [[ -s $d/slurmctld.pid ]] && break; sleep 0.1; done
  slurm_pids+=("$(cat "$d/slurmctld.pid")")
  slurmd -f "$d/slurm.conf" -N localhost || { cat "$d/slurmd.log"; return 1; }
  for _ in $(seq 50); do [[ -s $d/slurmd.pid ]] && break; sleep 0.1; done
  slurm_pids+=("$(cat "$d/slurmd.pid")")
  for _ in $(seq 60); do
    if sinfo -h -o '%T' 2>/dev/null | grep -q idle; then echo "slurm up: $(sinfo -h -o '%P %D %T %C')"; return 0; fi
    sleep 0.5
  done
  echo "slurm did not come up:"; sinfo; tail -20 "$d/slurmctld.log" "$d/slurmd.log"
  return 1
}
