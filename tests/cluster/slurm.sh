#!/usr/bin/env bash
# examples/cluster/study.sbatch on a real SLURM: a single-node cluster on localhost (munged, slurmctld and slurmd,
# configured in a temporary folder, on free ports), the paper's study (coarse) submitted as an array job of 4 tasks
# and its dependent merge job, compared byte for byte with the study run in one process. The daemons are stopped
# whatever happens (trap); on a failure their logs are printed.
source "$(dirname "$0")/common.sh"
source "$(dirname "$0")/slurm_local.sh"
jobs_submitted=""
on_exit() {
  local status=$?
  [ -n "$jobs_submitted" ] && scancel $jobs_submitted 2>/dev/null || true
  slurm_stop $status
  exit $status
}
trap on_exit EXIT
trap 'exit 1' INT TERM
slurm_start "$WORK/slurm" 2

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
slurm_wait "$array,$merge" 900
echo "jobs ended after $((SECONDS - start)) s"
jobs_submitted=""
for k in 1 2 3 4; do
  state=$(slurm_state "${array}_$k")
  [ "$state" = "JobState=COMPLETED" ] || fail "array task $k: $state"
  grep -q "shard $k of 4 (SLURM_ARRAY_TASK_ID=$k of the array 1-4 (4 tasks))" "wrc-study-${array}_$k.out" ||
    fail "array task $k did not take its shard from SLURM"
done
state=$(slurm_state "$merge")
[ "$state" = "JobState=COMPLETED" ] || fail "the merge job: $state"
same_outputs single sharded sweep.csv rigid.csv summary.txt
grep -q "^shards 4" sharded/manifest.txt || fail "the merged manifest does not say 4 shards"
echo "SLURM ok"
