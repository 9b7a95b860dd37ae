#!/usr/bin/env bash
# Output folders, parts and data from someone else: each part plants the hostile file or folder, runs wrc as a user
# would, and checks that nothing outside the output folder changed (a listing with contents before and after) and
# that no planted command ran (a marker file). Stale files are removed only inside the folder and never through a
# link; `wrc merge` runs the study the user names, never a script the parts name; names with line breaks stay one row
# (part files) or are refused (manifest); wrc's temporary names do not catch a user's file; folder names that gnuplot
# reads as a command ('<', '|'), a datablock ('$') or an option ('-') are plain paths.
source "$(dirname "$0")/common.sh"
FLEET="$SRC/examples/fleet_conicity.lua"

# snapshot EXCLUDED...: every path under this folder but the excluded ones (and the last command's output), with its
# kind and content (or target).
snapshot() {
  local prune=() d f
  for d in "$@" last.out last.err; do prune+=(-path "./$d" -prune -o); done
  find . "${prune[@]}" -print0 | sort -z | while IFS= read -r -d '' f; do
    if [ -L "$f" ]; then printf 'link %q %q\n' "$f" "$(readlink "$f")"
    elif [ -f "$f" ]; then printf 'file %q %s\n' "$f" "$(md5sum < "$f")"
    else printf 'dir %q\n' "$f"; fi
  done
}
# fnv FILE: the FNV-1a hash wrc records for a file (so that a planted manifest line holds the right one).
echo 'print(wrc.fs.hash_file(arg.f))' > fnv.lua
fnv() { "$WRC" run fnv.lua "f=$1"; }
no_traceback() { ! grep -q "stack traceback" last.err || { cat last.err >&2; fail "$1: a traceback"; }; }

echo "== a manifest that lists files outside its folder, or through a link in it: nothing there is removed"
mkdir -p elsewhere/shard-1-of-2
echo secret > elsewhere/secret.txt
echo victim > victim.txt
expect_status 0 "$WRC" run "$CASES" cases=5 plots=false out=out1
ln -s ../elsewhere out1/data
ln -s ../victim.txt out1/notes.txt
{
  echo "file ../victim.txt 7 $(fnv victim.txt)"
  echo "file data/secret.txt 7 $(fnv elsewhere/secret.txt)"
  echo "file notes.txt 7 $(fnv victim.txt)"
} >> out1/manifest.txt
before=$(snapshot out1)
expect_status 0 "$WRC" run "$CASES" cases=5 plots=false out=out1
[ "$(snapshot out1)" = "$before" ] || fail "a run into out1 changed files outside it"
[ -L out1/data ] && [ -L out1/notes.txt ] || fail "the links in out1 were removed"
expect_err "ignored 1 name that names no file inside the folder: ../victim.txt"
expect_err "data/secret.txt ('out1/data' is a symbolic link"
expect_err "notes.txt (a symbolic link)"
# The links are now files that no manifest lists: the next run refuses the folder (the user decides).
expect_status 1 "$WRC" run "$CASES" cases=5 plots=false out=out1
expect_err "that no wrc run listed"
# An absolute name, in the manifest of an interrupted run.
expect_status 0 "$WRC" run "$CASES" cases=5 plots=false out=out1b
sed -i 's/^status .*/status incomplete (merging; a run killed now leaves this mark)/' out1b/manifest.txt
echo "previous $WORK/victim.txt 7 $(fnv victim.txt)" >> out1b/manifest.txt
before=$(snapshot out1b)
expect_status 0 "$WRC" run "$CASES" cases=4 plots=false out=out1b --fresh
[ "$(snapshot out1b)" = "$before" ] || fail "a run into out1b changed files outside it"
expect_err "ignored 1 name that names no file inside the folder: $WORK/victim.txt"
# A parts folder that is a link: a shard's --fresh neither removes nor writes through it.
echo "wrc study parts" > elsewhere/shard-1-of-2/state.txt
echo precious > elsewhere/shard-1-of-2/precious.txt
mkdir out2
ln -s ../elsewhere out2/parts
before=$(snapshot out2)
expect_status 1 "$WRC" run "$CASES" cases=6 plots=false out=out2 --shard 1/2 --fresh
expect_err "'out2/parts' is a symbolic link"
[ "$(snapshot out2)" = "$before" ] || fail "a shard's run removed or wrote through out2/parts"

echo "== wrc merge runs the study the user names, never a script that the parts name"
for k in 1 2; do expect_status 0 "$WRC" run "$CASES" cases=6 plots=false out=merged --shard $k/2; done
printf 'os.execute("touch %q/ran_evil")\n' "$WORK" > evil.lua
sed -i "s|^script .*|script $WORK/evil.lua|" merged/parts/shard-*/state.txt
before=$(snapshot merged)
expect_status 2 "$WRC" merge merged
[ ! -e ran_evil ] || fail "wrc merge ran the script that the parts named"
[ "$(snapshot merged)" = "$before" ] || fail "wrc merge DIR changed files outside DIR"
expect_err "$WORK/evil.lua (script hash $(fnv "$CASES"), options cases=6 plots=false)"
cp "$CASES" changed.lua
echo "-- changed" >> changed.lua
expect_status 1 "$WRC" merge changed.lua out=merged
expect_err "do not come from changed.lua (script hash $(fnv changed.lua))"
expect_status 0 "$WRC" merge "$CASES" out=merged  # the study of the parts (by content), with their options
[ ! -e ran_evil ] || fail "wrc merge ran the script that the parts named"
[ "$(wc -l < merged/rigid.csv)" -eq 7 ] || fail "the merge of 6 cases: $(cat merged/rigid.csv)"
# Two runs of the study in one folder (other options, other shard counts): the options given choose one.
for k in 1 2 3; do expect_status 0 "$WRC" run "$CASES" cases=8 plots=false out=merged --shard $k/3; done
expect_status 1 "$WRC" merge "$CASES" out=merged
expect_err "holds the parts of 2 runs of this study with other options"
expect_status 0 "$WRC" merge "$CASES" out=merged cases=8
[ "$(wc -l < merged/rigid.csv)" -eq 9 ] || fail "the merge of 8 cases: $(cat merged/rigid.csv)"

echo "== a wheel file named with a line break: one row in every table, the same in shards"
mkdir wheels
cp "$SRC/tests/data/profile/samples/s1002.whl" wheels/
cp "$SRC/tests/data/profile/samples/s1002.whl" wheels/$'a\n1 injected,row.whl'
expect_status 0 "$WRC" run "$FLEET" wheels=wheels plots=false out=nl1
for k in 1 2; do expect_status 0 "$WRC" run "$FLEET" wheels=wheels plots=false out=nl2 --shard $k/2; done
expect_status 0 "$WRC" merge "$FLEET" out=nl2
same_outputs nl1 nl2 fleet.csv delta_r.csv summary.txt
cat > rows.lua <<'LUA'
local out = require "wrc.output"
local _, fleet = out.read_csv(arg.dir .. "/fleet.csv")
local _, dr = out.read_csv(arg.dir .. "/delta_r.csv")
local n = {}
for _, r in ipairs(dr) do n[r.wheel] = (n[r.wheel] or 0) + 1 end
local odd = "a\n1 injected,row.whl"
print(#fleet, fleet[1].wheel == odd, fleet[2].wheel, n[odd] == n["s1002.whl"] and n[odd] > 10, #dr == n[odd] * 2)
LUA
got=$("$WRC" run rows.lua dir=nl1)
[ "$got" = "$(printf '2\ttrue\ts1002.whl\ttrue\ttrue')" ] || fail "fleet.csv and delta_r.csv as read back: $got"

echo "== a file name with a line break is never listed in the manifest (it would make a line of its own)"
cat > names.lua <<'LUA'
local study = require "wrc.study"
local out = require "wrc.output"
local s = study.new{name = "names", help = "writes a file whose name holds a line break", out = "names",
                    options = {{"how", "string", "ctx", "ctx: through ctx.write, else through wrc.output"}}}
s:run{cases = 1, compute = function() return {[1] = {}} end,
      finish = function(ctx)
        ctx.write("ok.txt", "x\n")
        if s.options.how == "ctx" then ctx.write("bad\nprevious injected.txt", "x\n") end
        out.text(ctx.dir .. "/bad\nprevious injected.txt", "x\n")
      end}
LUA
expect_status 1 "$WRC" run names.lua out=names
expect_err "names: cannot name a file 'bad\\nprevious injected.txt' in it: a control character"
[ ! -e names/$'bad\nprevious injected.txt' ] || fail "a file name with a line break was written through ctx.write"
expect_status 1 "$WRC" run names.lua out=names2 how=output  # written by wrc.output: not listed
expect_err "names2: cannot list 'bad\\nprevious injected.txt' in manifest.txt: a control character"
grep -q "^previous injected.txt" names2/manifest.txt && fail "a file name made a line of the manifest"

echo "== a user's file or folder that looks like a temporary one is not taken for one"
expect_status 0 "$WRC" run "$CASES" cases=3 plots=false out=tmpnames
echo "my notes" > tmpnames/.notes.tmp.txt
expect_status 1 "$WRC" run "$CASES" cases=3 plots=false out=tmpnames
expect_err "that no wrc run listed in manifest.txt (.notes.tmp.txt)"
[ "$(cat tmpnames/.notes.tmp.txt)" = "my notes" ] || fail "the user's .notes.tmp.txt was touched"
rm tmpnames/.notes.tmp.txt
mkdir -p tmpnames/.d.tmp.x && echo kept > tmpnames/.d.tmp.x/f
expect_status 1 "$WRC" run "$CASES" cases=3 plots=false out=tmpnames
expect_err "(.d.tmp.x)"
no_traceback "a folder named like an old temporary"
rm -r tmpnames/.d.tmp.x
mkdir -p tmpnames/.d.wrc-tmp-0123456789abcdef-1-2 && echo kept > tmpnames/.d.wrc-tmp-0123456789abcdef-1-2/f
expect_status 0 "$WRC" run "$CASES" cases=3 plots=false out=tmpnames
no_traceback "a folder of the temporary pattern"
[ "$(cat tmpnames/.d.wrc-tmp-0123456789abcdef-1-2/f)" = kept ] || fail "a folder of the temporary pattern was touched"

echo "== output folders gnuplot would read as a command, a datablock or an option: plain paths"
for o in -dash '$dollar' '<touch ran_lt; echo ' '|touch ran_pipe; cat >/dev/null; echo '; do
  expect_status 0 "$WRC" run "$CASES" cases=3 "out=$o"
  no_traceback "out=$o"
  [ -s "./$o/z.png" ] || fail "no figure in out=$o"
done
[ ! -e ran_lt ] && [ ! -e ran_pipe ] || fail "gnuplot ran a command from an output folder's name"
expect_status 2 "$WRC" run "$CASES" cases=3 $'out=nl\nx'
expect_err "option out=nl\\nx: a control character (a line break?) in the value is refused"
[ ! -e nl ] || fail "a refused folder name was created"
echo "hostile folders ok"
cd "$TMPBASE" && rm -rf "$WORK"  # kept when a check failed, for a look
