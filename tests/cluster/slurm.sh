#!/usr/bin/env bash
# examples/cluster/study.sbatch on a real SLURM: a single-node cluster on localhost (munged, slurmctld and slurmd,
# configured in a temporary folder, on free ports), the paper's study (coarse) submitted as an array job of 4 tasks
# and its dependent merge job, compared byte for byte with the study run in one process. The daemons are stopped
# whatever happens (trap); on a failure their logs are printed.
source "$(dirname "$0")/common.sh"
for c in munged slurmctld slurmd sbatch squeue scontrol scancel sinfo; do
  command -v $c >/dev/null || fail "$c is missing (.ci/deps installs the Debian packages slurm-wlm and munge)"
done

S="$WORK/slurm"
mkdir -p "$S/state" "$S/spool"
chmod 755 "$WORK" "$S"  # munged wants its socket's folder open to all
export SLURM_CONF="$S/slurm.conf"
pids=()
jobs_submitted=""

show_logs() {
  for f in "$S"/*.log "$WORK"/wrc-*.out; do
    [ -f "$f" ] || continue
    echo "----- $f (last 40 lines)" >&2
    tail -n 40 "$f" >&2
  done
}
cleanup() {
  local status=$?
  [ -n "$jobs_submitted" ] && scancel $jobs_submitted 2>/dev/null || true
  for p in "${pids[@]}"; do kill "$p" 2>/dev/null || true; done
  for _ in $(seq 1 50); do
    local alive=0
    for p in "${pids[@]}"; do kill -0 "$p" 2>/dev/null && alive=1; done
    [ $alive = 0 ] && break
    sleep 0.2
  done
  for p in "${pids[@]}"; do kill -9 "$p" 2>/dev/null || true; done
  [ $status = 0 ] || show_logs
  exit $status
}
trap cleanup EXIT
trap 'exit 1' INT TERM

# Two TCP ports nobody listens on.
free_port() {
  local p
  while :; do
    p=$((20000 + RANDOM % 40000))
    local hex
    hex=$(printf ':%04X ' $p)
    grep -q "$hex" /proc/net/tcp /proc/net/tcp6 2>/dev/null || { echo $p; return; }
  done
}
ctld_port=$(free_port)
slurmd_port=$(free_port)
[ "$ctld_port" != "$slurmd_port" ] || slurmd_port=$((ctld_port + 1))

# munge: a fresh key, its own socket.
head -c 1024 /dev/urandom > "$S/munge.key"
chmod 400 "$S/munge.key"
munged -F --key-file="$S/munge.key" --socket="$S/munge.sock" --pid-file="$S/munged.pid" --log-file="$S/munged.log" \
  --seed-file="$S/munged.seed" >"$S/munged.out.log" 2>&1 &
pids+=($!)
for _ in $(seq 1 100); do [ -S "$S/munge.sock" ] && break; sleep 0.1; done
[ -S "$S/munge.sock" ] || fail "munged did not start"

user=$(id -un)
cat > "$SLURM_CONF" <<CONF
ClusterName=wrctest
SlurmctldHost=$(hostname -s)(127.0.0.1)
SlurmctldPort=$ctld_port
SlurmdPort=$slurmd_port
SlurmUser=$user
SlurmdUser=$user
AuthType=auth/munge
AuthInfo=socket=$S/munge.sock
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
NodeName=wrcnode NodeAddr=127.0.0.1 CPUs=2 State=UNKNOWN
PartitionName=wrc Nodes=wrcnode Default=YES MaxTime=INFINITE State=UP
CONF
slurmctld -D -i -f "$SLURM_CONF" >"$S/slurmctld.out.log" 2>&1 &
pids+=($!)
slurmd -D -N wrcnode -f "$SLURM_CONF" >"$S/slurmd.out.log" 2>&1 &
pids+=($!)
for _ in $(seq 1 300); do
  [ "$(sinfo -h -o %T 2>/dev/null)" = "idle" ] && break
  sleep 0.2
done
[ "$(sinfo -h -o %T 2>/dev/null)" = "idle" ] || fail "the SLURM node is not idle after 60 s: $(sinfo 2>&1)"
echo "SLURM is up: slurmctld on port $ctld_port, slurmd on port $slurmd_port"

# The reference: one process.
"$WRC" run "$PAPER" "${COARSE[@]}" threads=1 out=single >/dev/null 2>single.err || fail "the single run failed: $(cat single.err)"

# The array of 4 tasks and the merge job after it.
WRC="$WRC" "$SRC/examples/cluster/study.sbatch" -n 4 -c 1 "$PAPER" "${COARSE[@]}" out="$WORK/sharded" >submit.out 2>&1 ||
  { cat submit.out >&2; fail "study.sbatch could not submit"; }
cat submit.out
read -r array merge < <(sed -n 's/.*array job \([0-9]*\) .*merge job \([0-9]*\) .*/\1 \2/p' submit.out)
[ -n "$array" ] && [ -n "$merge" ] || fail "no job ids in: $(cat submit.out)"
jobs_submitted="$array $merge"
start=$SECONDS
while [ -n "$(squeue -h -j "$array,$merge" 2>/dev/null)" ]; do
  [ $((SECONDS - start)) -lt 900 ] || { squeue >&2; fail "the jobs did not end within 900 s"; }
  sleep 1
done
echo "jobs ended after $((SECONDS - start)) s"
jobs_submitted=""
for k in 1 2 3 4; do
  state=$(scontrol show job "${array}_$k" 2>/dev/null | grep -o 'JobState=[A-Z]*' | head -1)
  [ "$state" = "JobState=COMPLETED" ] || fail "array task $k: $state"
  grep -q "shard $k of 4 (SLURM_ARRAY_TASK_ID=$k of the array 1-4 (4 tasks))" "wrc-study-${array}_$k.out" ||
    fail "array task $k did not take its shard from SLURM"
done
state=$(scontrol show job "$merge" | grep -o 'JobState=[A-Z]*' | head -1)
[ "$state" = "JobState=COMPLETED" ] || fail "the merge job: $state"
same_outputs single sharded sweep.csv rigid.csv summary.txt
grep -q "^shards 4" sharded/manifest.txt || fail "the merged manifest does not say 4 shards"
echo "SLURM ok"
