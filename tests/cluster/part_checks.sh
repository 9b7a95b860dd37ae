#!/usr/bin/env bash
# Part files and runs at once. Each checkpoint block ends with a line that records its line count, size and hash: a
# block cut short, a value changed or its chunk markers deleted is found; the merge refuses it, naming the shard, the
# block and the command that computes it again, and that shard's run computes it again (no --fresh). One run at a time
# computes a shard and one merges a folder (a lock, released when the process ends, kill -9 too): a second run of a
# shard with another batch size, or a second and third merge started at once, stop naming the holder's pid, and the
# folder merges into the bytes of a single run.
source "$(dirname "$0")/common.sh"
RUN=(cases=24 plots=false)
no_traceback() { ! grep -q "stack traceback" last.err || { cat last.err >&2; fail "$1: a traceback"; }; }
# first_block_file FOLDER: the path of the first checkpoint block in FOLDER.
first_block() { ls "$1"/chunks-*.txt | head -1; }
# wait_for_block FOLDER: until FOLDER holds a checkpoint block (a run is under way).
wait_for_block() {
  for _ in $(seq 1 600); do
    ls "$1"/chunks-* >/dev/null 2>&1 && return
    sleep 0.05
  done
  fail "no block appeared in $1"
}

expect_status 0 "$WRC" run "$CASES" "${RUN[@]}" out=single

echo "== a block cut short or with a value changed: the merge refuses, the shard's run computes it again"
for k in 1 2; do expect_status 0 "$WRC" run "$CASES" "${RUN[@]}" batch=4 out=cut --shard $k/2; done
blocks=(cut/parts/shard-2-of-2/chunks-*.txt)
sed -i "$(($(wc -l < "${blocks[0]}") - 2))d" "${blocks[0]}"   # its last row deleted (before its time and end lines)
sed -i -E '2s/^(1 [0-9]+,[-0-9.]+),0,/\1,1,/' "${blocks[1]}"  # yaw 0 -> 1 in a row: the same size
truncate -s -40 "${blocks[2]}"                                 # cut short (as a block of an earlier wrc: no end line)
expect_status 1 "$WRC" merge "$CASES" out=cut
no_traceback "a merge of damaged blocks"
expect_err "cannot merge into 'cut': 3 damaged blocks"
expect_err "shard 2 of 2, $(basename "${blocks[0]}"): its size is not the one its end line records"
expect_err "shard 2 of 2, $(basename "${blocks[1]}"): its content does not match its checksum (a value changed)"
expect_err "shard 2 of 2, $(basename "${blocks[2]}"): its end line is missing"
expect_err "cases=24 out=cut plots=false --shard 2/2"
[ ! -e cut/rigid.csv ] || fail "a refused merge wrote rigid.csv"
expect_status 0 "$WRC" run "$CASES" "${RUN[@]}" batch=4 out=cut --shard 2/2
expect_err "3 damaged blocks in cut/parts/shard-2-of-2, computed again"
expect_status 0 "$WRC" merge "$CASES" out=cut
same_outputs single cut rigid.csv summary.txt

echo "== the chunk markers of a shard deleted: its run computes its blocks again, without --fresh"
sed -i '/^@/d' cut/parts/shard-1-of-2/chunks-*.txt
expect_status 1 "$WRC" run "$CASES" "${RUN[@]}" batch=4 out=cut --merge
expect_err "damaged blocks (shard 1 of 2"
expect_status 0 "$WRC" run "$CASES" "${RUN[@]}" batch=4 out=cut --shard 1/2
no_traceback "a rerun over deleted markers"
expect_err "damaged blocks in cut/parts/shard-1-of-2, computed again"
expect_status 0 "$WRC" run "$CASES" "${RUN[@]}" batch=4 out=cut --merge
same_outputs single cut rigid.csv summary.txt

echo "== blocks that overlap (left by two runs of a shard at once, before wrc locked shards): merged once, removed"
for k in 1 2; do expect_status 0 "$WRC" run "$CASES" "${RUN[@]}" batch=4 out=overlap --shard $k/2; done
blocks=(overlap/parts/shard-1-of-2/chunks-*.txt)
cp "${blocks[1]}" overlap/parts/shard-1-of-2/chunks-000000003-000000006.txt  # chunks 5..8, named 3..6
expect_status 0 "$WRC" merge "$CASES" out=overlap
same_outputs single overlap rigid.csv summary.txt
expect_status 0 "$WRC" run "$CASES" "${RUN[@]}" batch=4 out=overlap --shard 1/2
expect_err "1 block in overlap/parts/shard-1-of-2 overlapped others (an earlier run's batches): removed"
[ ! -e overlap/parts/shard-1-of-2/chunks-000000003-000000006.txt ] || fail "the overlapping block is still there"

echo "== one shard run twice at once with other batch sizes: the second stops, naming the first"
"$WRC" run "$CASES" "${RUN[@]}" batch=1 pause=0.2 out=twice --shard 1/2 >/dev/null 2>first.err &
pid=$!
wait_for_block twice/parts/shard-1-of-2
expect_status 1 "$WRC" run "$CASES" "${RUN[@]}" batch=5 out=twice --shard 1/2
expect_err "twice: shard 1 of 2 is being written by another wrc run (pid $pid on host "
# A run of the whole study with --fresh would discard every shard's parts: it stops before removing any.
blocks_before=$(ls twice/parts/shard-1-of-2 | grep -c '^chunks-')
expect_status 1 "$WRC" run "$CASES" "${RUN[@]}" out=twice --fresh
expect_err "twice: shard 1 of 2 is being written by another wrc run (pid $pid on host "
[ "$(ls twice/parts/shard-1-of-2 | grep -c '^chunks-')" -ge "$blocks_before" ] || fail "--fresh removed a running shard"
wait $pid || fail "the first run of shard 1 failed: $(cat first.err)"
expect_status 0 "$WRC" run "$CASES" "${RUN[@]}" out=twice --shard 2/2
expect_status 0 "$WRC" merge "$CASES" out=twice
same_outputs single twice rigid.csv summary.txt

echo "== a shard killed with SIGKILL: its lock goes with it, the shard run again resumes"
"$WRC" run "$CASES" "${RUN[@]}" batch=1 pause=0.2 out=killed --shard 1/2 >/dev/null 2>killed.err &
pid=$!
wait_for_block killed/parts/shard-1-of-2
kill -9 $pid
wait $pid 2>/dev/null || true
expect_status 0 "$WRC" run "$CASES" "${RUN[@]}" out=killed --shard 1/2
expect_err "resuming:"
expect_status 0 "$WRC" run "$CASES" "${RUN[@]}" out=killed --shard 2/2
expect_status 0 "$WRC" merge "$CASES" out=killed
same_outputs single killed rigid.csv summary.txt

echo "== three merges at once: one merges, the two others stop; the folder is whole"
for k in 1 2; do expect_status 0 "$WRC" run "$CASES" "${RUN[@]}" out=three --shard $k/2; done
pids=()
for i in 1 2 3; do  # the third starts while the first is in the middle of its figures (summary.txt written)
  [ $i = 3 ] && sleep 1.5
  "$WRC" merge "$CASES" out=three finish_pause=3 >"merge$i.out" 2>"merge$i.err" &
  pids+=($!)
done
merged=0 stopped=0
for i in 1 2 3; do
  status=0
  wait "${pids[$((i - 1))]}" || status=$?
  if [ $status = 0 ]; then merged=$((merged + 1))
  # a merge that checks the lock before its holder has written its note (two starting at once) is told so instead
  elif [ $status = 1 ] && grep -qE "three: the folder \(a merge, .*\) is being written by another wrc run \((pid |a \
process that has not written its note yet\))" "merge$i.err"; then
    stopped=$((stopped + 1))
  else
    cat "merge$i.err" >&2
  fi
done
[ $merged = 1 ] && [ $stopped = 2 ] || fail "three merges at once: $merged merged, $stopped stopped (expected 1 and 2)"
same_outputs single three rigid.csv summary.txt
grep -q "^status complete" three/manifest.txt || fail "three/manifest.txt is not complete"
ls -A three | grep -q "wrc-tmp" && fail "temporary files left in three/: $(ls -A three)"
echo "part checks ok"
cd "$TMPBASE" && rm -rf "$WORK"  # kept when a check failed, for a look
