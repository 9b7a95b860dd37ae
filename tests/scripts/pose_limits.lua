-- Prescribed poses far from any contact a wheelset can have are errors, never numbers (issues 28 and 29):
--  - deeper than max_penetration (default 1 mm; realistic contacts are 0.05-0.3 mm deep) in ws:contact, a
--    trajectory's contact, a sweep: `ws:contact{y = 20e-3, z = 0}` (17.5 mm of inter-penetration) returned 120 MN and
--    68 GPa, z = -0.3 m 1.7e10 N, z = -0.5 m a negative Fz; the error names the depth found, the limit and the option;
--  - |z| or |y| beyond the wheels' radius (z = -1 m, -1e308 m: no contact, returned as if all were well) are refused
--    before any geometry runs;
--  - grid sizes outside [1 um, 10 mm] (grid = 1e-30 overflowed the element count and solved to 1.2e-22 N);
--  - loads beyond 1e10 N (Fz = 1e308 printed "-nan" in its message).
local check = require "wrc.check"

local wheel = wrc.profile.load(wrc.paths.profiles .. "/s1002.lua")
local rail = wrc.profile.load(wrc.paths.profiles .. "/60e1.lua")
local ws = wrc.wheelset{wheel = wheel, rail = rail, grid = 0.5e-3}

-- ws:contact at y = 20 mm, z = 0: the flange sits deep in the rail. The depth reported is the inter-penetration of
-- the undeformed profiles along the wheel's normal. The reference, from the discretised wheel and rail alone: at yaw
-- = roll = 0 a rail line's closest approach to the axle lies in x = 0, where it is inside the wheel by the radius of
-- the cone above it minus its distance to the axle, times the cosine of the cone's slope along the normal.
local function deepest(y)
  local c, l = ws:cones("left"), ws:lines("left")
  local best = 0
  for r = 1, #l.y do
    local Y = l.y[r] - y
    for k = 2, #c.y - 2 do
      local ya, yb = c.y[k], c.y[k + 1]
      if ya ~= yb and Y >= ya and Y <= yb then
        local t = (Y - ya) / (yb - ya)
        local overlap = -(c.z[k] + t * (c.z[k + 1] - c.z[k])) - math.abs(l.z[r])
        local slope = (c.z[k] - c.z[k + 1]) / (yb - ya)
        best = math.max(best, overlap / math.sqrt(1 + slope * slope))
      end
    end
  end
  return best
end
local ref = deepest(20e-3)
check.ok(ref > 15e-3, ("at y = 20 mm, z = 0 the flange is %.3f mm deep"):format(ref * 1e3))
local err = check.fails(function() return ws:contact{y = 20e-3, z = 0} end, "more than max_penetration = 1 mm",
                        "ws:contact 17.5 mm deep")
check.ok(err:find("the left wheel and its rail inter-penetrate", 1, true), err)
check.ok(err:find("raise the option max_penetration", 1, true), err)
local depth = tonumber(err:match("inter%-penetrate ([%d%.]+) mm deep"))
check.ok(depth and math.abs(depth - ref * 1e3) < 0.02 * ref * 1e3,
         ("the depth in the message (%s mm) is the reference's (%.3f mm)"):format(tostring(depth), ref * 1e3))
-- The limit is the option: a pose 0.5 mm deep passes the default and fails a limit of 0.2 mm.
local z_half = -0.5e-3
check.ok(ws:contact{y = 0, z = z_half, grids = false}.force.z > 0, "0.5 mm deep: solved")
check.fails(function() return ws:contact{y = 0, z = z_half, max_penetration = 0.2e-3} end,
            "more than max_penetration = 0.2 mm", "0.5 mm deep against a 0.2 mm limit")
check.fails(function() return ws:contact{y = 0, z = 0, max_penetration = 0} end, "max_penetration = 0 m must be a positive",
            "a zero limit")

-- Deep poses along the axle's height: errors, not numbers.
for _, z in ipairs{-0.3, -0.5, -1, -1e308} do
  local e = check.fails(function() return ws:contact{y = 0, z = z} end, "contact: ", ("z = %g m"):format(z))
  check.ok(e:find("max_penetration", 1, true) or e:find("largest radius", 1, true), e)
  check.ok(not e:lower():find("nan", 1, true), e)
end
check.fails(function() return ws:contact{y = 0, z = -1} end, "the wheelset would have passed through its rails", "z = -1 m")
check.fails(function() return ws:locate{y = 0, z = -1e308} end, "largest radius", "ws:locate at z = -1e308 m")
check.fails(function() return ws:contact{y = 2, z = 0} end, "off the track centre", "y = 2 m")

-- A trajectory's steps: the same limit, an option of the trajectory.
local tr = ws:trajectory{}
check.fails(function() return tr:contact{y = 20e-3, z = 0} end, "more than max_penetration = 1 mm", "trajectory step")
check.ok(ws:trajectory{max_penetration = 20e-3}:contact{y = 0, z = -3e-3}.force.z > 0, "a trajectory's raised limit")
check.fails(function() return tr:contact{y = 0, z = -1} end, "largest radius", "trajectory at z = -1 m")

-- A sweep whose load needs more than its max_penetration: every case fails with the reason, the sweep goes on.
local s = ws:sweep{y = {0, 1e-3}, Q = 200e3, max_penetration = 0.05e-3, progress = false}
check.ok(s.failed == 2, "both cases fail")
for _, r in ipairs(s) do check.ok(not r.converged and r.error:find("max_penetration = 0.05 mm", 1, true), r.error) end

-- Grid sizes and loads.
check.fails(function() return wrc.wheelset{wheel = wheel, rail = rail, grid = 1e-30} end,
            "grid = 1e-30 m must be in [1e-06, 0.01] m", "grid = 1e-30")
check.fails(function() return wrc.wheelset{wheel = wheel, rail = rail, grid = 0.02} end, "must be in", "grid = 20 mm")
check.fails(function() return wrc.wheelset{wheel = wheel, rail = rail, grid = 1e-6} end, "is too fine for max_elements",
            "grid = 1 um with the default cap")
local e = check.fails(function() return ws:wheel{side = "left", y = 0, Fz = 1e308} end, "Fz = 1e+308 N must be",
                      "Fz = 1e308")
check.ok(not e:lower():find("nan", 1, true), e)
check.fails(function() return ws:equilibrium{y = 0, Q = 1e300} end, "Q = 1e+300 N must be", "Q = 1e300")
print("pose limits: ok")
