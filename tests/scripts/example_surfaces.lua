-- examples/surfaces_study.lua runs through at a coarse step, lifted wheels included (y = -8 mm lifts the left wheel,
-- whose contact angle is then empty), and its summary states per surface and yaw where Y/Q first exceeds 0.8, as
-- computed here from its own sweep_*.csv.
local check = require "wrc.check"
local out = require "wrc.output"

local dir = (arg.tmp or os.getenv("WRC_TEST_TMP") or "/tmp") .. "/example_surfaces"
wrc.fs.remove_tree(dir)  -- this build's results, none resumed from an earlier build
arg = {[0] = arg[0], out = dir, step_mm = 2, grid_mm = 0.5}  -- the example's declared options (a test's tmp= is not one)
dofile(wrc.paths.root .. "/examples/surfaces_study.lua")
local f = assert(io.open(dir .. "/summary.txt"))
local summary = f:read("a")
f:close()
for _, surface in ipairs{"planar", "conformal"} do
  local _, rows = out.read_csv(dir .. "/sweep_" .. surface .. ".csv")
  check.ok(#rows == 18, surface .. ": 9 positions x 2 yaws")
  local lifted = false
  for _, r in ipairs(rows) do lifted = lifted or (r.left_angle_deg == nil and r.left_Fz_kN == 0) end
  check.ok(lifted, surface .. ": a row where the left wheel lifted, its contact angle empty")
end
check.ok(summary:find("yaw 0 deg: Y/Q first exceeds 0.8 at y = ", 1, true), "summary: the yaw-0 crossing")
check.ok(summary:find("yaw 1 deg: Y/Q first exceeds 0.8 at y = ", 1, true), "summary: the yaw-1 crossing")
check.ok(summary:find("largest |Y/Q conformal - Y/Q planar|", 1, true), "summary: the surfaces' difference")
