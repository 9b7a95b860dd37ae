-- examples/conicity.lua runs (without its plots) and writes what it promises: the geometry tables, conicity.csv and
-- summary.txt, with tan(gamma_e) equal to ws:conicity's on the same pairs.
local check = require "wrc.check"
local out = require "wrc.output"

local dir = (arg.tmp or os.getenv("WRC_TEST_TMP") or "/tmp") .. "/example_conicity"
wrc.fs.remove_tree(dir)  -- this build's results, none resumed from an earlier build
arg = {[0] = arg[0], out = dir, plots = false}  -- the example's declared options (a test's tmp= is not one)
dofile(wrc.paths.root .. "/examples/conicity.lua")
for _, key in ipairs{"s1002_60e1_1in40", "s1002_60e1_1in20", "worn_60e1_1in40"} do
  local cols, rows = out.read_csv(dir .. "/table_" .. key .. ".csv")
  check.ok(#rows == 401 and cols[6] == "dr_mm", key .. ": a 401-row table")
  check.ok(io.open(dir .. "/table_" .. key .. ".txt") ~= nil, key .. ": the multibody table")
end
local _, rows = out.read_csv(dir .. "/conicity.csv")
local ws = wrc.wheelset{wheel = wrc.profile.load("profiles/s1002.lua"), rail = wrc.profile.load("profiles/60e1.lua")}
local tan3 = ws:conicity{yhat = {3e-3}}[1]
local found = false
for _, r in ipairs(rows) do
  if r.pair == "s1002_60e1_1in40" and r.roll == "fixed" and math.abs(r.yhat_mm - 3) < 1e-9 then
    check.near(r.tan_gamma, tan3, 1e-9, "conicity.csv at 3 mm")
    found = true
  end
end
check.ok(found, "conicity.csv holds S1002/60E1 1:40 at 3 mm")
local f = assert(io.open(dir .. "/summary.txt"))
local summary = f:read("a")
f:close()
check.ok(summary:find(("roll fixed: %.4f"):format(tan3), 1, true), "summary.txt states tan(gamma_e) at 3 mm")
