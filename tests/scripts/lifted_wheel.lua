-- A lifted wheel (one that carries no load) has no contact angle and no rolling radius: ws:contact's and
-- ws:equilibrium's wheel tables leave them out (nil) and sweep.csv leaves their cells empty, as rigid results do;
-- never 0, which reads as a flat contact on a wheel of no radius (issue 28).
--
-- The case: the paper's wheelset at y = 8 mm, yaw 0, where the right wheel lifts (docs/guide/normal.md). That it has
-- lifted is checked independently of the solver's flag: at the equilibrium's pose the right wheel's deepest rail line
-- (from the discretised cones and lines) is outside the wheel.
local check = require "wrc.check"
local out = require "wrc.output"
local tables = require "wrc.sweep"

local wheel = wrc.profile.load(wrc.paths.profiles .. "/s1002.lua")
local rail = wrc.profile.load(wrc.paths.profiles .. "/60e1.lua")
local ws = wrc.wheelset{wheel = wheel, rail = rail, grid = 0.5e-3}
local tmp = arg.tmp or "."

local e = ws:equilibrium{y = 8e-3, Q = 200e3}
check.ok(e.converged and e.right.lifted and not e.left.lifted, "y = 8 mm: the right wheel lifts")
check.ok(e.right.force.z == 0, "the lifted wheel carries nothing")

-- Roll and height only (yaw 0): a rail line at (y, z) is inside the right wheel when its distance to the axle is
-- below the cone radius at its axial position.
local c, l = ws:cones("right"), ws:lines("right")
local cr, sr = math.cos(e.roll), math.sin(e.roll)
local deepest = -math.huge
for r = 1, #l.y do
  local dy, dz = l.y[r] - e.y, l.z[r] - e.z
  local Y, D = cr * dy + sr * dz, math.abs(-sr * dy + cr * dz)
  for k = 2, #c.y - 2 do
    local ya, yb = c.y[k], c.y[k + 1]
    if ya ~= yb and Y >= math.min(ya, yb) and Y <= math.max(ya, yb) then
      local t = (Y - ya) / (yb - ya)
      deepest = math.max(deepest, -(c.z[k] + t * (c.z[k + 1] - c.z[k])) - D)
    end
  end
end
check.ok(deepest < 0, ("the right wheel is %.3f mm above its rail"):format(-deepest * 1e3))

for what, w in pairs{equilibrium = e.right, contact = ws:contact{y = e.y, z = e.z, roll = e.roll}.right} do
  check.ok(w.lifted, what .. ": lifted")
  check.ok(w.angle == nil, what .. ": no contact angle, got " .. tostring(w.angle))
  check.ok(w.rolling_radius == nil, what .. ": no rolling radius, got " .. tostring(w.rolling_radius))
end
check.ok(e.left.angle > 0 and e.left.rolling_radius > 0.4, "the loaded wheel keeps both")

local row = tables.sweep_row(e)
check.ok(row.right_angle_deg == nil and row.right_rolling_radius_mm == nil, "sweep row: no cells for the lifted wheel")
local path = tmp .. "/lifted_wheel_sweep.csv"
out.csv(path, tables.sweep_columns, {row})
local _, rows = out.read_csv(path)
local cells = rows[1]
for _, col in ipairs{"right_angle_deg", "right_rolling_radius_mm"} do
  check.ok(cells[col] == nil or cells[col] == "", "sweep.csv: " .. col .. " is an empty cell, got " .. tostring(cells[col]))
end
check.ok(tonumber(cells.left_rolling_radius_mm) > 400, "sweep.csv: the loaded wheel's radius is written")
print("lifted wheel: angle and rolling radius absent in Lua, empty in sweep.csv")
