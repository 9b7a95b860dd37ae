#!/usr/bin/env bash
# Runs a wrc study in N shards with GNU parallel -- on this machine, or on several over ssh -- then merges them into
# exactly the files a single process writes (docs/guide/studies.md).
#
#   examples/cluster/parallel.sh [-n SHARDS] [-j JOBS] [-S HOSTS] STUDY.lua [key=value ...]
#
#   -n SHARDS  parts of the study (default 4); a shard is `wrc run STUDY.lua ... --shard K/N`
#   -j JOBS    shards running at once on each host (default: all cores; give the study threads=1 then)
#   -S HOSTS   GNU parallel's --sshlogin list, e.g. "8/node1,8/node2,:" (":" is this machine). Every host needs wrc,
#              the study script at the same path, and the output folder on a shared file system; remote jobs run
#              in this working directory.
#
# Environment: WRC, the wrc executable (default: `wrc` on the PATH, else build/wrc of the source tree this script is
# in, as the README builds it). A shard that was stopped is simply run again:
# it resumes after its last finished block. Exit status: that of the merge (0, or 3 when cases failed); 130 (Ctrl-C) or
# 143 (SIGTERM) when interrupted, with no merge.
set -euo pipefail

shards=4 jobs="" hosts=""
while getopts "n:j:S:h" o; do
  case $o in
    n) shards=$OPTARG ;;
    j) jobs=$OPTARG ;;
    S) hosts=$OPTARG ;;
    *) sed -n '2,16p' "$0"; exit 2 ;;
  esac
done
shift $((OPTIND - 1))
[[ $shards =~ ^[1-9][0-9]*$ ]] || { echo "parallel.sh: -n $shards: expected a number >= 1" >&2; exit 2; }
if [ $# -lt 1 ]; then
  sed -n '2,16p' "$0" >&2
  exit 2
fi
study=$1
shift
wrc=${WRC:-}
if [ -z "$wrc" ]; then
  wrc=$(command -v wrc || true)
  [ -n "$wrc" ] || wrc=$(cd "$(dirname "$(readlink -f "$0")")/../.." && pwd)/build/wrc
fi
command -v "$wrc" >/dev/null || { echo "parallel.sh: no wrc: not on the PATH nor at $wrc; set WRC=/path/to/wrc" >&2; exit 2; }
command -v parallel >/dev/null || { echo "parallel.sh: GNU parallel is not installed (Debian: apt install parallel)" >&2; exit 2; }

# The shard command's words reach the jobs in an environment variable (shell-quoted by printf %q), not on GNU
# parallel's command line, where {}, {.}, {= perl =} and the like in the study's arguments would be replaced or run.
printf -v WRC_SHARD_WORDS '%q ' "$wrc" run "$study" "$@"
export WRC_SHARD_WORDS
opts=(--will-cite --halt never --line-buffer --tagstring "shard {}/$shards")
[ -n "$jobs" ] && opts+=(--jobs "$jobs")
[ -n "$hosts" ] && opts+=(--sshlogin "$hosts" --workdir "$PWD" --env WRC_SHARD_WORDS)

# Ctrl-C (or SIGTERM to this script) stops the study without a merge: GNU parallel stops the shards, which remove the
# files they were writing (a shard run again resumes). Bash runs the trap once the command in progress has returned.
stopped() {
  echo "parallel.sh: interrupted by SIG$1: the shards stopped, no merge (run the command again to resume)" >&2
  exit "$2"
}
trap 'stopped INT 130' INT
trap 'stopped TERM 143' TERM

start=$(date +%s%N)
# -q: the words of the command are quoted for the shell (on remote hosts too); its only replacement string is the
# shard's {}. A failed shard does not stop the others.
parallel "${opts[@]}" -q bash -c 'shard=$1; eval "set -- $WRC_SHARD_WORDS"; exec "$@" --shard "$shard"' wrc-shard \
  "{}/$shards" ::: $(seq 1 "$shards") || true
shards_done=$(date +%s%N)
status=0
"$wrc" run "$study" "$@" --merge || status=$?
end=$(date +%s%N)
ms() { echo $((($2 - $1) / 1000000)); }
echo "parallel.sh: $shards shards in $(ms "$start" "$shards_done") ms, merge in $(ms "$shards_done" "$end") ms (exit $status)" >&2
exit $status
