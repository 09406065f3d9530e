# Sourced by tests that need Slurm: `start_slurm_cluster DIR` starts a one-node cluster on
# this machine (munged, slurmctld and slurmd from Debian's slurm-wlm and munge, as this
# shell's own processes, every file under DIR) and exports SLURM_CONF for sbatch, squeue,
# scancel and sacct; `stop_slurm_cluster` stops them by their pids. No systemd, no
# /etc/slurm: the cluster is the test's and goes with it.
# start_slurm_cluster returns non-zero with the reason on stderr if Slurm cannot start.

slurm_pids=()

# A free TCP port from the kernel (bind to port 0), so that two tests or a site's own
# Slurm on the default 6817/6818 do not collide.
free_port() {
  /usr/bin/python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])'
}

start_slurm_cluster() {
  local dir="$1" node cpus memory ctld_port slurmd_port
  for program in munged slurmctld slurmd sbatch squeue scancel sinfo; do
    command -v "$program" >/dev/null || { echo "slurm: $program is not installed (scripts/setup.sh test installs slurm-wlm and munge)" >&2; return 1; }
  done
  mkdir -p "$dir"/{munge,state,spool,log}
  chmod 700 "$dir" "$dir/munge"
  # munge: a key of our own; --force lets it run as root with the key and socket in a
  # scratch folder (it refuses otherwise, since root could read anyone's credentials).
  dd if=/dev/urandom of="$dir/munge/munge.key" bs=1024 count=1 status=none
  chmod 400 "$dir/munge/munge.key"
  munged --force --foreground --key-file="$dir/munge/munge.key" --socket="$dir/munge/socket" \
    --pid-file="$dir/munge/munged.pid" --log-file="$dir/log/munged.log" --seed-file="$dir/munge/seed" \
    2>>"$dir/log/munged.log" &
  slurm_pids+=($!)

  node="$(hostname -s)"
  cpus="$(nproc)"
  memory=$(($(awk '/MemTotal/ {print $2}' /proc/meminfo) / 1024 / 2))
  ctld_port="$(free_port)"
  slurmd_port="$(free_port)"
  cat >"$dir/slurm.conf" <<CONF
# A one-node cluster on localhost for tests: written by tests/cli/slurm_cluster.sh.
ClusterName=curvebench-test
SlurmctldHost=$node(127.0.0.1)
SlurmctldPort=$ctld_port
SlurmdPort=$slurmd_port
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$dir/munge/socket
# No cgroups in a container: track a job's processes by their parent pids, bind no CPUs.
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
MpiDefault=none
SwitchType=switch/none
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
SchedulerType=sched/backfill
# Requeued and resubmitted tasks must start at once, not after the default minute.
MinJobAge=300
ReturnToService=2
SlurmctldTimeout=30
SlurmdTimeout=30
StateSaveLocation=$dir/state
SlurmdSpoolDir=$dir/spool
SlurmctldPidFile=$dir/slurmctld.pid
SlurmdPidFile=$dir/slurmd.pid
SlurmctldLogFile=$dir/log/slurmctld.log
SlurmdLogFile=$dir/log/slurmd.log
NodeName=$node NodeAddr=127.0.0.1 CPUs=$cpus RealMemory=$memory State=UNKNOWN
PartitionName=test Nodes=$node Default=YES MaxTime=INFINITE State=UP
CONF
  export SLURM_CONF="$dir/slurm.conf"
  for _ in $(seq 50); do [[ -S $dir/munge/socket ]] && break; sleep 0.1; done
  [[ -S $dir/munge/socket ]] || { echo "slurm: munged did not start: $(tail -3 "$dir/log/munged.log")" >&2; return 1; }
  slurmctld -D -i -f "$SLURM_CONF" >>"$dir/log/slurmctld.out" 2>&1 &
  slurm_pids+=($!)
  slurmd -D -f "$SLURM_CONF" >>"$dir/log/slurmd.out" 2>&1 &
  slurm_pids+=($!)
  # Up when the node takes jobs.
  local state=""
  for _ in $(seq 100); do
    state="$(sinfo -h -N -o %T 2>/dev/null)"
    [[ $state == idle* ]] && return 0
    sleep 0.2
  done
  echo "slurm: the node did not come up (state '${state:-none}'); last log lines:" >&2
  tail -5 "$dir/log/slurmctld.log" "$dir/log/slurmd.log" >&2 2>/dev/null
  return 1
}

stop_slurm_cluster() {
  local pid
  for pid in "${slurm_pids[@]}"; do kill "$pid" 2>/dev/null; done
  for pid in "${slurm_pids[@]}"; do wait "$pid" 2>/dev/null; done
  slurm_pids=()
}
