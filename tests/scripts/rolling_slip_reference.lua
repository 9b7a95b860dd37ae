-- Where the rigid slip is taken (docs/guide/rolling.md "Conventions"; wheelset/tangential.hpp SlipReference):
-- `slip_reference = "undeformed"` (the default; CONTACT's convention) on the wheel's undeformed surface, "deformed" at
-- the element's point midway between the undeformed surfaces, h / 2 nearer the axle (why the first is right: the
-- rolling radius of a compressed disc, tests/python/test_rolling_radius.py).
--   - every element of the wide, curved patch of the centred wheelset at y = 0, planar and conformal: with
--     "undeformed" the longitudinal rigid slip is 1 - D / r0, D = sqrt(R(Y)^2 - x^2) + x^2 n_z^2 / 2R the depth below
--     the axle of the wheel's undeformed surface at the element (R: the placed wheel profile, interpolated here; Y: the
--     lateral position of the wheel's point) plus the normal velocity's share along the contact surface (divided by
--     sqrt(1 + tilt^2), tilt = x n_z / 2R; tests/scripts/rolling_contact.lua), with "deformed" 1 - (D - h n_z / 2) / r0;
--     so the two differ by h n_z / (2 r0) (over the same root);
--   - the area's xi (at its reference point) moves by the same amount, and Fx follows it;
--   - the lateral rigid slip (spin) does not change (a shift along n moves the point within the axle's plane);
--   - bad input: an unknown value, the key with prescribed creepages or without V.
local check = require "wrc.check"
local C = dofile((arg[0]:match("(.*/)") or "./") .. "contact_helpers.lua")

local wheel = wrc.profile.load(wrc.paths.profiles .. "/s1002.lua")
local rail = wrc.profile.load(wrc.paths.profiles .. "/60e1.lua")
local ws = wrc.wheelset{wheel = wheel, rail = rail, grid = 0.5e-3}  -- conformal areas (the default)
local wp = wrc.wheelset{wheel = wheel, rail = rail, grid = 0.5e-3, surface = "planar"}
local r0 = ws.params.radius
local V = 100 / 3.6
local e0 = ws:equilibrium{y = 0, yaw = 0, Q = 200e3}
local function pose(extra)
  local t = {y = e0.y, z = e0.z, roll = e0.roll, yaw = e0.yaw}
  for k, v in pairs(extra) do t[k] = v end
  return t
end

for surface, w in pairs{conformal = ws, planar = wp} do
  local u = w:contact(pose{V = V, mu = 0.3})
  local d = w:contact(pose{V = V, mu = 0.3, slip_reference = "deformed"})
  local explicit = w:contact(pose{V = V, mu = 0.3, slip_reference = "undeformed"})
  local pd, pu = d.left.patches[1], u.left.patches[1]
  check.ok(explicit.left.patches[1].creepage.xi == pu.creepage.xi and explicit.left.patches[1].Fx == pu.Fx,
           surface .. ": \"undeformed\" is the default")
  local o, t1, t2 = pu.frame.origin, pu.frame.t1, pu.frame.t2
  local worst, worst_diff, worst_y, largest, n = 0, 0, 0, 0, 0
  for j = 1, pu.grid.ny do
    for k = 1, pu.grid.nx do
      if pu.pressure[j][k] > 0 then
        local a, b = pu.grid.x0 + (k - 1) * pu.grid.dx, pu.grid.y0 + (j - 1) * pu.grid.dy
        local h = pu.h[j][k]
        local x, Y, nz
        if surface == "planar" then
          nz = pu.normal.z
          x, Y = o.x + a * t1.x + b * t2.x, o.y + a * t1.y + b * t2.y - e0.y
        else  -- the row's point on the rail, h below it along the row's normal: the wheel's undeformed surface
          nz = pu.rows.normal_z[j]
          x, Y = o.x + a, pu.rows.y[j] - h * pu.rows.normal_y[j] - e0.y
        end
        local R = C.wheel_radius(w, Y)
        local D, root = math.sqrt(R * R - x * x) + 0.5 * x * x * nz * nz / R, math.sqrt(1 + (0.5 * x * nz / R) ^ 2)
        worst = math.max(worst, math.abs(pu.rigid_slip_x[j][k] / V - (1 - D / r0) / root))
        local shift = 0.5 * h * nz / r0 / root
        worst_diff = math.max(worst_diff, math.abs((pd.rigid_slip_x[j][k] - pu.rigid_slip_x[j][k]) / V - shift))
        worst_y = math.max(worst_y, math.abs(pd.rigid_slip_y[j][k] - pu.rigid_slip_y[j][k]) / V)
        largest, n = math.max(largest, shift), n + 1
      end
    end
  end
  check.ok(n > 100 and largest > 5e-5, surface .. (": a wide patch whose overlap matters (h n_z / 2 r0 up to %.2e)"):format(largest))
  check.ok(worst < 2e-6, surface .. (": undeformed: rigid slip x = 1 - D / r0 at every element (worst %.2e)"):format(worst))
  check.ok(worst_diff < 1e-8, surface .. (": deformed - undeformed = h n_z / (2 r0) at every element (worst %.2e)"):format(worst_diff))
  check.ok(worst_y < 1e-12, surface .. ": the lateral rigid slip does not depend on the reference")
  -- The reference point: xi moves by the shift of the element there (pure rolling at r0: xi = 1 - rolling radius / r0).
  local g = pu.grid
  local i0, j0 = math.floor(-g.x0 / g.dx + 0.5) + 1, math.floor(-g.y0 / g.dy + 0.5) + 1
  local nz0 = surface == "planar" and pu.normal.z or pu.rows.normal_z[j0]
  check.near(pd.creepage.xi - pu.creepage.xi, 0.5 * pu.h[j0][i0] * nz0 / r0, 1e-12, surface .. ": xi moves by h0 n_z / (2 r0)")
  check.ok(pu.creepage.xi < pd.creepage.xi and pu.Fx > pd.Fx,
           surface .. ": on the undeformed wheel the rolling radius is larger: smaller xi, larger Fx (xi > 0 brakes)")
end

-- Bad input.
do
  local function with(extra) local t = pose(extra); return function() return ws:contact(t) end end
  check.fails(with{V = V, mu = 0.3, slip_reference = "midway"}, "slip_reference", "unknown slip_reference")
  check.fails(with{V = V, mu = 0.3, slip_reference = "midway"}, "deformed", "the message lists the choices")
  check.fails(with{creepage = {xi = 1e-3}, slip_reference = "undeformed", mu = 0.3}, "cannot be given with it",
              "slip_reference with prescribed creepages")
  check.fails(with{slip_reference = "undeformed", mu = 0.3}, "forward speed V", "slip_reference without V")
end
print("slip reference: ok")
