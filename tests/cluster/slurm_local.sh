# A single-node SLURM on localhost for the tests and benchmarks (sourced): slurm_start FOLDER CPUS starts munged,
# slurmctld and slurmd configured in FOLDER on free ports and exports SLURM_CONF; slurm_stop STATUS stops them (by
# their process ids) and, when STATUS is not 0, prints their logs. The caller traps EXIT to call slurm_stop.
slurm_pids=()
slurm_dir=""
slurm_sock_dir=""

slurm_fail() {
  echo "FAILED: $*" >&2
  exit 1
}

slurm_logs() {
  for f in "$slurm_dir"/*.log "$PWD"/wrc-*.out; do
    [ -f "$f" ] || continue
    echo "----- $f (last 40 lines)" >&2
    tail -n 40 "$f" >&2
  done
}

slurm_stop() {
  local status=${1:-0} p alive
  for p in "${slurm_pids[@]}"; do kill "$p" 2>/dev/null || true; done
  for _ in $(seq 1 50); do
    alive=0
    for p in "${slurm_pids[@]}"; do kill -0 "$p" 2>/dev/null && alive=1; done
    [ $alive = 0 ] && break
    sleep 0.2
  done
  for p in "${slurm_pids[@]}"; do kill -9 "$p" 2>/dev/null || true; done
  slurm_pids=()
  [ "$status" = 0 ] || slurm_logs
  [ -n "$slurm_sock_dir" ] && rm -rf "$slurm_sock_dir"
  slurm_sock_dir=""
}

# A TCP port nobody listens on.
slurm_free_port() {
  local p
  while :; do
    p=$((20000 + RANDOM % 40000))
    grep -q "$(printf ':%04X ' $p)" /proc/net/tcp /proc/net/tcp6 2>/dev/null || { echo $p; return; }
  done
}

slurm_start() {
  local S=$1 cpus=$2 c
  for c in munged slurmctld slurmd sbatch squeue scontrol scancel sinfo; do
    command -v $c >/dev/null || slurm_fail "$c is missing (.ci/deps installs the Debian packages slurm-wlm and munge)"
  done
  slurm_dir=$S
  mkdir -p "$S/state" "$S/spool"
  # munged wants execute permission for all on every folder above its socket, which a checkout in a private folder
  # (mktemp -d: 0700) does not give: the socket lives in a folder of its own under /tmp.
  slurm_sock_dir=$(mktemp -d /tmp/wrc-munge.XXXXXX)
  chmod 755 "$slurm_sock_dir"
  local sock="$slurm_sock_dir/munge.sock"
  export SLURM_CONF="$S/slurm.conf"
  local ctld_port slurmd_port
  ctld_port=$(slurm_free_port)
  slurmd_port=$(slurm_free_port)
  [ "$ctld_port" != "$slurmd_port" ] || slurmd_port=$((ctld_port + 1))

  # munge: a fresh key, its own socket.
  head -c 1024 /dev/urandom > "$S/munge.key"
  chmod 400 "$S/munge.key"
  munged -F --key-file="$S/munge.key" --socket="$sock" --pid-file="$S/munged.pid" --log-file="$S/munged.log" \
    --seed-file="$S/munged.seed" >"$S/munged.out.log" 2>&1 &
  slurm_pids+=($!)
  for _ in $(seq 1 100); do [ -S "$sock" ] && break; sleep 0.1; done
  [ -S "$sock" ] || slurm_fail "munged did not start"

  local user
  user=$(id -un)
  cat > "$SLURM_CONF" <<CONF
ClusterName=wrctest
SlurmctldHost=$(hostname -s)(127.0.0.1)
SlurmctldPort=$ctld_port
SlurmdPort=$slurmd_port
SlurmUser=$user
SlurmdUser=$user
AuthType=auth/munge
AuthInfo=socket=$sock
CredType=cred/munge
StateSaveLocation=$S/state
SlurmdSpoolDir=$S/spool
SlurmctldPidFile=$S/slurmctld.pid
SlurmdPidFile=$S/slurmd.pid
SlurmctldLogFile=$S/slurmctld.log
SlurmdLogFile=$S/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
SchedulerType=sched/builtin
SchedulerParameters=sched_interval=1
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
MpiDefault=none
ReturnToService=2
MinJobAge=600
NodeName=wrcnode NodeAddr=127.0.0.1 CPUs=$cpus State=UNKNOWN
PartitionName=wrc Nodes=wrcnode Default=YES MaxTime=INFINITE State=UP
CONF
  slurmctld -D -i -f "$SLURM_CONF" >"$S/slurmctld.out.log" 2>&1 &
  slurm_pids+=($!)
  slurmd -D -N wrcnode -f "$SLURM_CONF" >"$S/slurmd.out.log" 2>&1 &
  slurm_pids+=($!)
  for _ in $(seq 1 300); do
    [ "$(sinfo -h -o %T 2>/dev/null)" = "idle" ] && break
    sleep 0.2
  done
  [ "$(sinfo -h -o %T 2>/dev/null)" = "idle" ] || slurm_fail "the SLURM node is not idle after 60 s: $(sinfo 2>&1)"
  echo "SLURM is up in $S: slurmctld on port $ctld_port, slurmd on port $slurmd_port"
}

# slurm_wait JOBS TIMEOUT: waits until the jobs (comma-separated ids) have left the queue.
slurm_wait() {
  local start=$SECONDS
  while [ -n "$(squeue -h -j "$1" 2>/dev/null)" ]; do
    [ $((SECONDS - start)) -lt "$2" ] || { squeue >&2; slurm_fail "the jobs $1 did not end within $2 s"; }
    sleep 0.5
  done
}

# slurm_state JOB: JobState=... of a job the controller still remembers.
slurm_state() { scontrol show job "$1" 2>/dev/null | grep -o 'JobState=[A-Z_]*' | head -1; }
