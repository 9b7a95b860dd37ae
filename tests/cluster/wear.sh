#!/usr/bin/env bash
# examples/wear_evolution.lua at a reduced size (coarse grid, few cases, 3 steps): 1 and 2 threads give the same bytes;
# a run killed with kill -9 after its first steps and run again resumes and ends with the files of an uninterrupted
# run; the profiles it writes are read back by wrc's readers as the points of profiles.csv and listed in the manifest.
source "$(dirname "$0")/common.sh"
WEAR="$SRC/examples/wear_evolution.lua"
CASES=(steps=3 tangent=5 curve_forces_kN=40 grid_mm=0.5)
SMALL=("${CASES[@]}" plots=false)

echo "== 1 and 2 threads give the same bytes"
expect_status 0 "$WRC" run "$WEAR" "${SMALL[@]}" threads=1 out=one
expect_status 0 "$WRC" run "$WEAR" "${SMALL[@]}" threads=2 out=two
same_outputs one two evolution.csv profiles.csv summary.txt left_wheel_step03.prw right_wheel_step03.prw
[ "$(wc -l < one/evolution.csv)" -eq 5 ] || fail "one/evolution.csv should hold 4 steps (0 to 3)"

echo "== a run killed with kill -9 resumes and ends with the same files"
"$WRC" run "$WEAR" "${SMALL[@]}" threads=1 out=killed >/dev/null 2>killed.err &
pid=$!
for _ in $(seq 1 3000); do
  n=$(ls killed/parts/shard-1-of-1 2>/dev/null | grep -c '^chunks-' || true)
  [ "$n" -ge 2 ] && break
  sleep 0.05
done
kill -9 $pid 2>/dev/null || fail "the run ended before it could be killed"
wait $pid 2>/dev/null || true
[ ! -e killed/evolution.csv ] || fail "a killed run left killed/evolution.csv"
expect_status 0 "$WRC" run "$WEAR" "${SMALL[@]}" threads=1 out=killed
expect_err "resuming:"
same_outputs one killed evolution.csv profiles.csv summary.txt left_wheel_step02.prw left_wheel_step03.prw

echo "== the written profiles are read back"
cat > readback.lua <<'LUA'
local out = require "wrc.output"
local _, rows = out.read_csv(arg.dir .. "/profiles.csv")
for _, body in ipairs{"left_wheel", "right_wheel"} do
  local p = wrc.profile.load(("%s/%s_step03.prw"):format(arg.dir, body))
  local y, z = p:points()
  local k, worst = 0, 0
  for _, r in ipairs(rows) do
    if r.step == 3 and r.body == body then
      k = k + 1
      worst = math.max(worst, math.abs(y[k] - r.y_mm * 1e-3), math.abs(z[k] - r.z_mm * 1e-3))
    end
  end
  assert(p.kind == "wheel" and k == #y and k > 1000, body .. ": the points of profiles.csv")
  assert(worst < 2e-9, ("%s: read back %.3g m off"):format(body, worst))
end
print("read back")
LUA
"$WRC" run readback.lua dir=one | grep -q "read back" || fail "the written profiles are not read back"
# The profile files are the run's (listed in its manifest, ctx.write_profile): a run again into the folder accepts them.
grep -q "^file left_wheel_step03.prw " one/manifest.txt || fail "the manifest does not list left_wheel_step03.prw"
expect_status 0 "$WRC" run "$WEAR" "${CASES[@]}" threads=1 out=one
grep -q "^file Sd.png " one/manifest.txt || fail "the figures are not listed in the manifest"
echo "wear ok"
