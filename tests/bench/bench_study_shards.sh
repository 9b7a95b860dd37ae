#!/usr/bin/env bash
# Parallel efficiency of a study on this machine (issue 13): the study in one process on 1 thread and on all cores,
# then in N shards under GNU parallel (examples/cluster/parallel.sh, -j CORES, threads=1) and under a single-node
# SLURM started for the benchmark (examples/cluster/study.sbatch, CORES CPUs, one per task). Every sharded run is
# checked byte-identical to the single-process tables. Prints wall time, the compute CPU time the manifest records
# (all blocks, all threads), the parallel efficiency T(1 thread) / (CORES x wall) and the work efficiency
# CPU(1 thread) / CPU (what sharding costs in extra work: processes, wheelsets built per shard, chunk starts; it
# holds on a loaded machine, where wall times do not).
#
#   WRC=build/wrc tests/bench/bench_study_shards.sh [-n SHARDS] [-c CORES] STUDY.lua [key=value ...]
#   e.g. tests/bench/bench_study_shards.sh examples/fleet_conicity.lua count=1000
set -euo pipefail
shards=4 cores=$(nproc)
while getopts "n:c:" o; do
  case $o in n) shards=$OPTARG ;; c) cores=$OPTARG ;; *) exit 2 ;; esac
done
shift $((OPTIND - 1))
study=$(readlink -f "$1")
shift
here=$(cd "$(dirname "$0")/../.." && pwd)
WRC=$(readlink -f "${WRC:-$here/build/wrc}")
export WRC
work=$(mktemp -d /tmp/wrc_bench_shards.XXXXXX)
cd "$work"
source "$here/tests/cluster/slurm_local.sh"
trap 'slurm_stop $?; rm -rf "$work"' EXIT

now() { date +%s%N; }
secs() { awk -v a="$1" -v b="$2" 'BEGIN { printf "%.1f", (b - a) / 1e9 }'; }
cpu_of() { sed -n 's/^compute_cpu \([0-9.]*\) s/\1/p' "$1/manifest.txt"; }
tables() { ls "$1" | grep '\.csv$'; }
rows=()
record() {  # mode dir wall
  rows+=("$(printf '%-34s %9s %12s' "$1" "$3" "$(cpu_of "$2")")")
}

t0=$(now); "$WRC" run "$study" "$@" threads=1 out=one >/dev/null 2>one.err; t1=$(now)
single=$(secs "$t0" "$t1")
record "1 process, 1 thread" one "$single"
t0=$(now); "$WRC" run "$study" "$@" threads="$cores" out=threads >/dev/null 2>threads.err; t1=$(now)
record "1 process, $cores threads" threads "$(secs "$t0" "$t1")"
for f in $(tables one); do cmp one/$f threads/$f; done

t0=$(now)
"$here/examples/cluster/parallel.sh" -n "$shards" -j "$cores" "$study" "$@" threads=1 out=gnu >/dev/null 2>gnu.err
t1=$(now)
record "$shards shards, GNU parallel -j $cores" gnu "$(secs "$t0" "$t1")"
for f in $(tables one); do cmp one/$f gnu/$f; done

slurm_start "$work/slurm" "$cores" >/dev/null
t0=$(now)
"$here/examples/cluster/study.sbatch" -n "$shards" -c 1 "$study" "$@" threads=1 out="$work/slurm_out" >submit.out
read -r array merge < <(sed -n 's/.*array job \([0-9]*\) .*merge job \([0-9]*\) .*/\1 \2/p' submit.out)
slurm_wait "$array,$merge" 3600
t1=$(now)
[ "$(slurm_state "$merge")" = "JobState=COMPLETED" ] || slurm_fail "the merge job: $(slurm_state "$merge")"
record "$shards shards, SLURM ($cores CPUs)" slurm_out "$(secs "$t0" "$t1")"
for f in $(tables one); do cmp one/$f slurm_out/$f; done

load=$(cut -d' ' -f1 /proc/loadavg)
echo "study: $study $*  (tables byte-identical in every mode; load average $load)"
printf '%-34s %9s %12s %11s %9s\n' "mode" "wall s" "compute cpu s" "efficiency" "work"
cpu1=$(cpu_of one)
for r in "${rows[@]}"; do
  wall=$(echo "$r" | awk '{print $(NF-1)}')
  cpu=$(echo "$r" | awk '{print $NF}')
  printf '%s %11s %9s\n' "$r" "$(awk -v t1="$single" -v w="$wall" -v c="$cores" 'BEGIN { printf "%.2f", t1 / (c * w) }')" \
    "$(awk -v a="$cpu1" -v b="$cpu" 'BEGIN { printf "%.2f", a / b }')"
done
