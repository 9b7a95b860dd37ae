#!/usr/bin/env bash
# The study runner (wrc.study) on real runs of `wrc`: results that do not depend on threads or shards, a run killed
# with SIGKILL and resumed, failed cases recorded while the others complete, declared options, the output folder's
# checks (writable, unknown files refused, stale files of an earlier run removed, an interrupted run marked), and
# the parts of another build of wrc neither resumed nor merged.
source "$(dirname "$0")/common.sh"
# Coarser still than the other tests (it runs the study ten times): y every 2 mm, 18 cases from tread to flange.
COARSE=(step_mm=2 grid_mm=0.4 plots=false)

echo "== 1, 2 and 8 threads, and 4 shards merged: the same bytes"
# Continuation chains cut into pieces of 2 cases (10 chunks), so that 2 and 8 threads share the work.
"$WRC" run "$PAPER" "${COARSE[@]}" chain=2 threads=1 out=t1 2>/dev/null >/dev/null
"$WRC" run "$PAPER" "${COARSE[@]}" chain=2 threads=2 out=t2 2>/dev/null >/dev/null
"$WRC" run "$PAPER" "${COARSE[@]}" chain=2 threads=8 out=t8 2>/dev/null >/dev/null
same_outputs t1 t2 sweep.csv rigid.csv summary.txt
same_outputs t1 t8 sweep.csv rigid.csv summary.txt
[ "$(wc -l < t1/sweep.csv)" -eq 19 ] || fail "t1/sweep.csv has $(wc -l < t1/sweep.csv) lines, expected 19"
# The whole chains of the paper (4 chunks), one shard each, run at once, merged by `wrc merge`.
"$WRC" run "$PAPER" "${COARSE[@]}" threads=1 out=one 2>/dev/null >/dev/null
for k in 1 2 3 4; do "$WRC" run "$PAPER" "${COARSE[@]}" threads=1 out=four --shard $k/4 2>"shard$k.err" >/dev/null & done
wait
expect_status 2 "$WRC" merge four  # the folder alone: wrc says which study the parts came from, runs none
expect_err "wrc runs no script that a folder names"
expect_err "paper_study.lua"
expect_status 1 "$WRC" merge "$PAPER" out=four/parts  # not an output folder
expect_status 0 "$WRC" merge "$PAPER" out=four  # the options from the parts
expect_err "with the options its shards ran with: grid_mm=0.4 plots=false step_mm=2 threads=1"
same_outputs one four sweep.csv rigid.csv summary.txt
grep -q "^status complete" four/manifest.txt || fail "four/manifest.txt is not complete"
grep -q "^shards 4" four/manifest.txt || fail "four/manifest.txt does not say 4 shards"

echo "== killed with SIGKILL in the middle, run again: it resumes and gives the same bytes"
"$WRC" run "$PAPER" "${COARSE[@]}" chain=2 threads=1 out=killed >/dev/null 2>killed.err &
pid=$!
for _ in $(seq 1 600); do
  n=$(ls killed/parts/shard-1-of-1 2>/dev/null | grep -c '^chunks-' || true)
  [ "$n" -ge 2 ] && break
  sleep 0.1
done
kill -9 $pid 2>/dev/null || fail "the run ended before it could be killed (make the study longer)"
wait $pid 2>/dev/null || true
[ ! -e killed/sweep.csv ] || fail "a killed run left killed/sweep.csv"
grep -q "^status incomplete" killed/manifest.txt || fail "the killed run is not marked incomplete"
# A changed study does not resume into the parts of an unfinished run.
expect_status 1 "$WRC" run "$PAPER" "${COARSE[@]}" chain=2 threads=1 out=killed ymax_mm=4
expect_err "parts of an unfinished run with other inputs (option ymax_mm: 8 -> 4"
expect_status 0 "$WRC" run "$PAPER" "${COARSE[@]}" chain=2 threads=1 out=killed
expect_err "resuming:"
same_outputs t1 killed sweep.csv rigid.csv summary.txt

echo "== a changed study replaces the parts of a finished run, and --fresh starts over"
expect_status 0 "$WRC" run "$PAPER" "${COARSE[@]}" chain=2 threads=1 out=killed ymax_mm=4
expect_err "was complete and had other inputs (option ymax_mm: 8 -> 4"
[ "$(wc -l < killed/sweep.csv)" -eq 11 ] || fail "the changed run has $(wc -l < killed/sweep.csv) lines"
expect_status 0 "$WRC" run "$PAPER" "${COARSE[@]}" chain=2 threads=1 out=killed ymax_mm=4 --fresh
grep -q "resuming" last.err && fail "--fresh resumed"
[ "$(wc -l < killed/sweep.csv)" -eq 11 ] || fail "the fresh run has $(wc -l < killed/sweep.csv) lines"

echo "== failed cases are recorded, the others complete, the exit status says so; shards agree"
expect_status 3 "$WRC" run "$CASES" cases=40 fail=3,17 out=failing
expect_err "2 of 40 cases failed"
[ "$(wc -l < failing/rigid.csv)" -eq 39 ] || fail "failing/rigid.csv should hold 38 rows"
[ "$(wc -l < failing/failures.csv)" -eq 3 ] || fail "failing/failures.csv should hold 2 failures"
grep -q '^3,-7.8,0,.*case 3 fails on purpose' failing/failures.csv || fail "failures.csv lacks case 3 with its error"
grep -q "failed: 2" failing/summary.txt || fail "the summary does not count the failures"
grep -q "^failed 2" failing/manifest.txt || fail "the manifest does not count the failures"
# shard 1 holds cases 1..13 (3 fails), shard 2 cases 14..26 (17 fails), shard 3 cases 27..40: exit 3, 3, 0
for k in 1 2 3; do expect_status "$([ $k = 3 ] && echo 0 || echo 3)" "$WRC" run "$CASES" cases=40 fail=3,17 out=failing3 --shard $k/3; done
expect_status 3 "$WRC" run "$CASES" cases=40 fail=3,17 out=failing3 --merge
same_outputs failing failing3 rigid.csv failures.csv summary.txt

echo "== parts computed by another build of wrc (the same version): neither resumed nor merged, both builds named"
# Shard 1 of 2 computed here, then its state.txt made what another build would have written: another build id (its
# identity lines' hash recomputed as wrc.study.identity computes it) and another description.
cat > other_build.lua <<'LUA'
local lines, out = {}, {}
for l in io.lines(arg.state) do
  if l:match("^line build ") then l = "line build 0123456789ab" end
  if l:match("^built ") then l = "built wrc " .. wrc.version .. ", build 0123456789ab (git 0000000)" end
  if l:match("^line ") then lines[#lines + 1] = l:sub(6) end
  out[#out + 1] = l
end
for i, l in ipairs(out) do
  if l:match("^hash ") then out[i] = "hash " .. wrc.fs.hash(table.concat(lines, "\n")) end
end
local f = assert(io.open(arg.state, "w"))
f:write(table.concat(out, "\n"), "\n")
f:close()
LUA
this=$("$WRC" --version | sed -n 's/^wrc \([^ ]*\) (build \([0-9a-f]*\), \(.*\))$/wrc \1, build \2 (\3)/p')
[ -n "$this" ] || fail "wrc --version does not name its build: $("$WRC" --version)"
"$WRC" run "$CASES" cases=6 plots=false out=builds >/dev/null 2>&1
"$WRC" run "$CASES" cases=6 plots=false out=rebuilt --shard 1/2 >/dev/null 2>&1
grep -qxF "built $this" rebuilt/parts/shard-1-of-2/state.txt || fail "state.txt does not record the build ($this)"
grep -qxF "engine $this" builds/manifest.txt || fail "the manifest does not record the build ($this)"
"$WRC" run other_build.lua state=rebuilt/parts/shard-1-of-2/state.txt
expect_status 1 "$WRC" run "$CASES" cases=6 plots=false out=rebuilt --shard 1/2
expect_err "holds the parts of an unfinished run computed by another build of wrc (wrc"
expect_err ", build 0123456789ab (git 0000000); this is $this): resuming would mix the two builds' results"
expect_err "run with --fresh"
expect_status 0 "$WRC" run "$CASES" cases=6 plots=false out=rebuilt --shard 2/2
expect_status 1 "$WRC" merge "$CASES" out=rebuilt
expect_err "shard 1 of 2 was computed by another build"
expect_err "shard-1-of-2 (wrc"
expect_err "--shard 1/2 --fresh"
expect_status 0 "$WRC" run "$CASES" cases=6 plots=false out=rebuilt --shard 1/2 --fresh
expect_status 0 "$WRC" merge "$CASES" out=rebuilt
same_outputs builds rebuilt rigid.csv summary.txt

echo "== declared options: a misspelt key names the declared one, --help lists them"
expect_status 2 "$WRC" run "$PAPER" stepmm=0.5
expect_err "unknown option 'stepmm' (did you mean 'step_mm'?)"
expect_status 2 "$WRC" run "$PAPER" step_mm=fast
expect_err "option step_mm=fast: expected a number"
expect_status 2 "$WRC" run "$PAPER" threads=1.5
expect_err "expected a whole number"
expect_status 0 "$WRC" run "$PAPER" --help
for o in step_mm=0.1 ymax_mm=8 grid_mm=0.2 chain=0 threads=0 plots=true out=results; do
  grep -qF -- "$o" last.out || fail "--help does not list $o"
done
echo 'print("a plain script")' > plain.lua  # no study: a shard of it would silently be the whole
expect_status 2 "$WRC" run plain.lua --shard 1/2
expect_err "runs no study through wrc.study"
expect_status 2 "$WRC" run "$PAPER" --shard 1/2 --merge
expect_err "takes no --shard"
# Given twice: refused, never the last one silently.
expect_status 2 "$WRC" run "$CASES" cases=10 cases=20
expect_err "option cases is given twice (cases=10 and cases=20)"
expect_status 2 "$WRC" run "$PAPER" --shard 1/2 --shard 2/2
expect_err "--shard is given twice"
expect_status 2 "$WRC" run "$PAPER" --fresh --merge
expect_err "give one of the two"
expect_status 2 "$WRC" merge "$PAPER" --fresh
expect_err "--fresh does not apply"

echo "== the output folder: writable before computing, unknown files refused, stale files removed, a kill marked"
expect_status 1 "$WRC" run "$CASES" cases=5 out=/proc/self
expect_err "output folder '/proc/self' is not writable"
grep -q "computed" last.err && fail "a run into a read-only folder computed before failing"
mkdir -p mine && echo "my notes" > mine/notes.txt
expect_status 1 "$WRC" run "$CASES" cases=5 out=mine
expect_err "no wrc run listed in a manifest (notes.txt)"
[ "$(cat mine/notes.txt)" = "my notes" ] || fail "the user's file was touched"
expect_status 0 "$WRC" run "$CASES" cases=5 out=stale
[ -e stale/z.png ] || fail "no histogram"
expect_status 0 "$WRC" run "$CASES" cases=6 plots=false out=stale
expect_err "removed 3 files of the previous run"
[ ! -e stale/z.png ] && [ ! -e stale/z.dat ] && [ ! -e stale/z.gp ] || fail "stale figures left in stale/"
grep -q "z.png" stale/manifest.txt && fail "the manifest lists a removed file"
# Killed in its finish (after summary.txt, before the figure): marked incomplete; the next run completes and cleans.
"$WRC" run "$CASES" cases=7 finish_pause=60 out=stale >/dev/null 2>stale.err &
pid=$!
for _ in $(seq 1 1200); do
  grep -q "^cases: 7," stale/summary.txt 2>/dev/null && break
  sleep 0.1
done
grep -q "^cases: 7," stale/summary.txt || fail "the run did not reach its finish: $(cat stale.err)"
kill -9 $pid 2>/dev/null || fail "the run ended before it could be killed"
wait $pid 2>/dev/null || true
grep -q "^status incomplete (merging" stale/manifest.txt || fail "a run killed while making its figures is not marked incomplete"
expect_status 0 "$WRC" run "$CASES" cases=7 out=stale
grep -q "^status complete" stale/manifest.txt || fail "the run after the kill is not complete"
for f in $(ls -A stale); do
  case $f in manifest.txt|parts) ;; *) grep -q "^file $f " stale/manifest.txt || fail "stale/$f is not in the manifest";; esac
done
echo "study runs ok"
