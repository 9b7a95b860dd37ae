#!/usr/bin/env bash
# Lua files planted in data folders and working directories do not run (docs/guide/studies.md "What is code and what
# is data").
# Each planted file would leave a marker file in the test's folder (os.execute, io.open, package.loadlib); none may
# exist afterwards:
#   - the fleet study's wheels=DIR takes the readers' formats only: a zz.lua in DIR is neither run nor listed; with
#     definitions=true it is listed and runs sandboxed, a failed case that says why;
#   - "profiles/60e1.lua" is the shipped rail from any working directory, also one holding a planted
#     ./profiles/60e1.lua (the same bytes out of the conicity example as from a clean folder), and a data folder
#     named profiles/ is still read as one; "./profiles/60e1.lua" names the planted file, which runs sandboxed.
source "$SRC/tests/cluster/common.sh"
FLEET="$SRC/examples/fleet_conicity.lua"

# hostile FILE KIND: a definition that tries all three ways out, then returns a plausible-looking profile.
hostile() {
  cat > "$1" <<LUA
os.execute("touch '$WORK/MARK_os'")
io.open("$WORK/MARK_io", "w"):write("x")
package.loadlib("libc.so.6", "system")("touch '$WORK/MARK_lib'")
return wrc.profile.load("profiles/$2.lua")
LUA
}
no_markers() {
  if ls "$WORK"/MARK_* >/dev/null 2>&1; then fail "a planted Lua file ran: $(ls "$WORK"/MARK_*)"; fi
  echo "no marker: $*"
}

echo "== a folder of wheels with a planted zz.lua"
mkdir -p wheels clean
cp "$SRC/tests/data/profile/samples/s1002.whl" wheels/
hostile wheels/zz.lua s1002
expect_status 0 "$WRC" run "$FLEET" wheels=wheels plots=false out=fleet
no_markers "fleet over wheels/"
[ "$(wc -l < fleet/fleet.csv)" -eq 2 ] || fail "fleet/fleet.csv should hold s1002.whl alone: $(cat fleet/fleet.csv)"
! grep -q "zz.lua" fleet/fleet.csv || fail "zz.lua is listed as a wheel"
[ ! -e fleet/failures.csv ] || fail "failures.csv: $(cat fleet/failures.csv)"

echo "== definitions=true: the definition is listed and runs sandboxed"
expect_status 3 "$WRC" run "$FLEET" wheels=wheels definitions=true plots=false out=defs
no_markers "fleet over wheels/ with definitions=true"
grep -q "^2,zz.lua,.*'os' is not available in a profile definition" defs/failures.csv ||
  fail "failures.csv does not say why zz.lua failed: $(cat defs/failures.csv)"

echo "== a planted ./profiles/60e1.lua in the working directory"
mkdir -p profiles
hostile profiles/60e1.lua 60e1
cp "$SRC/tests/data/profile/samples/s1002.whl" profiles/
cat > rail.lua <<'LUA'
local r = wrc.profile.load(arg[1])
print(r.source, #r)
LUA
expect_status 0 "$WRC" run rail.lua profiles/60e1.lua
[ "$(cat last.out)" = "$(cd / && "$WRC" run "$WORK/rail.lua" profiles/60e1.lua)" ] ||
  fail "profiles/60e1.lua is not the shipped rail here: $(cat last.out)"
grep -q "^$SRC/profiles/60e1.lua" last.out || grep -q "/share/wrc/profiles/60e1.lua" last.out ||
  fail "the rail does not come from the shipped profiles: $(cat last.out)"
no_markers "profiles/60e1.lua"
expect_status 1 "$WRC" run rail.lua ./profiles/60e1.lua
expect_err "'os' is not available in a profile definition"
no_markers "./profiles/60e1.lua"

echo "== the same results as from a clean folder; a data folder named profiles/"
expect_status 0 "$WRC" run "$SRC/examples/conicity.lua" plots=false out=conicity
(cd clean && "$WRC" run "$SRC/examples/conicity.lua" plots=false out=conicity >/dev/null 2>&1) || fail "conicity in clean/"
same_outputs conicity clean/conicity conicity.csv table_s1002_60e1_1in40.csv table_worn_60e1_1in40.csv
expect_status 0 "$WRC" run "$FLEET" wheels=profiles plots=false out=fleet_profiles
same_outputs fleet fleet_profiles fleet.csv delta_r.csv
no_markers "conicity and fleet beside ./profiles"
echo "planted files ok"
