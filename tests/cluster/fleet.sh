#!/usr/bin/env bash
# examples/fleet_conicity.lua: a synthetic fleet gives the same bytes on 1 and 2 threads and in 4 shards merged; a
# folder of wheel files is read (any format), a broken file is recorded as a failure while the others complete, and
# the nominal S1002 in it gets the conicity ws:conicity gives the analytic S1002 (EN 15302 at 3 mm: 0.1742).
source "$(dirname "$0")/common.sh"
FLEET="$SRC/examples/fleet_conicity.lua"

echo "== a synthetic fleet: threads and shards give the same bytes"
"$WRC" run "$FLEET" count=24 threads=1 plots=false out=one >/dev/null 2>one.err || fail "the single run: $(cat one.err)"
"$WRC" run "$FLEET" count=24 threads=2 plots=false out=two >/dev/null 2>two.err || fail "2 threads: $(cat two.err)"
for k in 1 2 3 4; do
  "$WRC" run "$FLEET" count=24 threads=1 plots=false out=four --shard $k/4 >/dev/null 2>"shard$k.err" &
done
wait
expect_status 0 "$WRC" merge "$FLEET" out=four
same_outputs one two fleet.csv delta_r.csv summary.txt
same_outputs one four fleet.csv delta_r.csv summary.txt
[ "$(wc -l < one/fleet.csv)" -eq 25 ] || fail "one/fleet.csv should hold 24 wheels"
grep -q "^wheels: 24, failed: 0" one/summary.txt || fail "the summary: $(cat one/summary.txt)"

echo "== a folder of wheel files, one of them broken"
mkdir -p wheels
cp "$SRC/tests/data/profile/samples/s1002.whl" "$SRC/examples/data/s1002_hollow_worn.whl" wheels/
printf 'y z\nnot a profile\n' > wheels/broken.txt
expect_status 3 "$WRC" run "$FLEET" wheels=wheels plots=false out=files
expect_err "1 of 3 cases failed"
grep -q '^1,broken.txt,"fleet_conicity.lua:[0-9]*: wheels/broken.txt:2' files/failures.csv ||
  fail "failures.csv does not name the broken file and why: $(cat files/failures.csv)"
[ "$(wc -l < files/fleet.csv)" -eq 3 ] || fail "files/fleet.csv should hold the 2 good wheels"
cat > reference.lua <<'LUA'
local ws = wrc.wheelset{wheel = wrc.profile.load("profiles/s1002.lua"), rail = wrc.profile.load("profiles/60e1.lua"),
                        radius = 0.46}
print(string.format("%.6f", ws:conicity{yhat = {3e-3}}[1]))
LUA
ref=$("$WRC" run reference.lua)
got=$(awk -F, '$1 == "s1002.whl" { printf "%.6f", $9 }' files/fleet.csv)
awk -v a="$ref" -v b="$got" 'BEGIN { d = a - b; if (d < 0) d = -d; exit !(d < 2e-4 && a > 0.17 && a < 0.18) }' ||
  fail "tan(gamma_e) of s1002.whl at 3 mm is $got, ws:conicity on the analytic S1002 gives $ref"
echo "fleet ok ($got against $ref)"
