#!/usr/bin/env bash
# examples/cluster/parallel.sh: the paper's study (coarse) in 4 shards under GNU parallel on this machine, merged,
# byte-identical to the study run in one process; arguments that hold GNU parallel's replacement strings pass as given.
source "$(dirname "$0")/common.sh"
command -v parallel >/dev/null || fail "GNU parallel is not installed (.ci/deps installs the Debian package 'parallel')"

"$WRC" run "$PAPER" "${COARSE[@]}" threads=1 out=single >/dev/null 2>single.err || fail "the single run failed: $(cat single.err)"
WRC="$WRC" timeout 600 "$SRC/examples/cluster/parallel.sh" -n 4 -j 2 "$PAPER" "${COARSE[@]}" threads=1 out=sharded \
  >parallel.out 2>parallel.err || { cat parallel.err >&2; fail "parallel.sh failed"; }
grep -q "parallel.sh: 4 shards in" parallel.err || { cat parallel.err >&2; fail "parallel.sh did not report its shards"; }
for k in 1 2 3 4; do
  grep -q "shard $k/4.*shard $k of 4 done" parallel.err || { cat parallel.err >&2; fail "shard $k/4 did not report its end"; }
done
same_outputs single sharded sweep.csv rigid.csv summary.txt
grep -q "^shards 4" sharded/manifest.txt || fail "the merged manifest does not say 4 shards"

echo "== the study's arguments reach wrc as given: GNU parallel's replacement strings in them are neither replaced nor run"
for out in 'pr_{}' 'pe{= system("touch ran_perl") =}'; do
  WRC="$WRC" timeout 600 "$SRC/examples/cluster/parallel.sh" -n 2 -j 2 "$CASES" cases=6 plots=false "out=$out" \
    >parallel.out 2>parallel.err || { cat parallel.err >&2; fail "parallel.sh failed with out=$out"; }
  [ "$(wc -l < "$out/rigid.csv")" -eq 7 ] || fail "out=$out: $(ls)"
done
[ ! -e ran_perl ] || fail "GNU parallel ran Perl code from an argument"
ls -d pr_1 pr_2 2>/dev/null && fail "out=pr_{} was split by shard"
expect_status 2 "$SRC/examples/cluster/parallel.sh" -n 0 "$CASES"

echo "== without WRC and without wrc on the PATH, parallel.sh runs the build tree's build/wrc (the README's build)"
mkdir -p tree/examples/cluster tree/build
cp "$SRC/examples/cluster/parallel.sh" tree/examples/cluster/
ln -s "$WRC" tree/build/wrc
system=/usr/bin:/bin  # the Debian packages' folders: no wrc there unless installed system-wide
! PATH=$system command -v wrc >/dev/null || fail "a wrc in $system: this check needs a machine without one"
env -u WRC PATH="$system" timeout 600 tree/examples/cluster/parallel.sh -n 2 -j 2 "$CASES" cases=6 plots=false out=tree_out \
  >parallel.out 2>parallel.err || { cat parallel.err >&2; fail "parallel.sh without WRC failed"; }
[ "$(wc -l < tree_out/rigid.csv)" -eq 7 ] || fail "the build tree's wrc did not write the study"
rm tree/build/wrc
env -u WRC PATH="$system" tree/examples/cluster/parallel.sh -n 2 "$CASES" >last.out 2>last.err && fail "no wrc: ran anyway"
expect_err "parallel.sh: no wrc: not on the PATH nor at $PWD/tree/build/wrc; set WRC=/path/to/wrc"
echo "GNU parallel ok"
