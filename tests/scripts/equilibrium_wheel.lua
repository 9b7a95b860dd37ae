-- ws:wheel{side=, y=, yaw=, roll=, Fz=}: one wheel-rail pair with its vertical force prescribed (the penetration
-- solved, as CONTACT and multibody codes use it). S1002 on 60E1, grid 0.5 mm. For tread and flange-root contact,
-- both sides, yaw 0 and 1 deg:
--   - the wheel's vertical force equals Fz within the solver's tolerance (1e-6 Fz);
--   - its height z agrees with a bisection written here on ws:contact (the vertical force of that wheel decreases
--     as the wheelset rises): the bracket z +- 20 um is checked to change sign, then halved 25 times (to 1.2e-12 m).
--     The wheel's own tolerance (1e-6 Fz) and its vertical stiffness (above 1e9 N/m) place its z within 1e-10 m of
--     the root; asserted within 1e-9 m;
--   - the returned forces and contact areas are those ws:contact finds at (y, z, roll, yaw).
local check = require "wrc.check"

local wheel = wrc.profile.load(wrc.paths.profiles .. "/s1002.lua")
local rail = wrc.profile.load(wrc.paths.profiles .. "/60e1.lua")
local ws = wrc.wheelset{wheel = wheel, rail = rail, grid = 0.5e-3}

local deg = math.pi / 180
local cases = {
  {side = "left", y = 3e-3, yaw = 0, roll = 0.16e-3, Fz = 100e3, what = "tread"},
  {side = "right", y = -3e-3, yaw = deg, roll = -0.16e-3, Fz = 80e3, what = "tread"},
  {side = "left", y = 6.4e-3, yaw = 0, roll = 0.69e-3, Fz = 160e3, what = "flange root"},
  {side = "right", y = 3e-3, yaw = deg, roll = 0.16e-3, Fz = 120e3, what = "tread, the other wheel"},
}

local worst = 0
for _, c in ipairs(cases) do
  local name = ("%s wheel, %s, y = %.1f mm, yaw = %g deg, Fz = %g kN"):format(c.side, c.what, c.y * 1e3, c.yaw / deg, c.Fz / 1e3)
  local w = ws:wheel{side = c.side, y = c.y, yaw = c.yaw, roll = c.roll, Fz = c.Fz}
  check.ok(w.converged, name .. ": converged")
  check.near(w.force.z, c.Fz, 1e-6 * c.Fz, name .. ": vertical force")
  check.ok(#w.patches >= 1, name .. ": in contact")
  -- Independent root of Fz(z) = c.Fz by bisection on the full pipeline.
  local function excess(z)
    return ws:contact{y = c.y, z = z, roll = c.roll, yaw = c.yaw, grids = false}[c.side].force.z - c.Fz
  end
  local lo, hi = w.z - 20e-6, w.z + 20e-6
  check.ok(excess(lo) > 0 and excess(hi) < 0, name .. ": the bracket z +- 20 um changes sign")
  for _ = 1, 25 do
    local m = 0.5 * (lo + hi)
    if excess(m) > 0 then lo = m else hi = m end
  end
  local z = 0.5 * (lo + hi)
  worst = math.max(worst, math.abs(w.z - z))
  check.near(w.z, z, 1e-9, name .. ": z against the bisection")
  -- The reported contact is the pipeline's at that pose.
  local ref = ws:contact{y = c.y, z = w.z, roll = c.roll, yaw = c.yaw, grids = false}[c.side]
  check.ok(#ref.patches == #w.patches, name .. ": same contact areas as ws:contact")
  for _, k in ipairs{"x", "y", "z"} do
    check.near(w.force[k], ref.force[k], 1e-7 * c.Fz, name .. ": force " .. k .. " as ws:contact")
    check.near(w.moment[k], ref.moment[k], 1e-7 * c.Fz, name .. ": moment " .. k .. " as ws:contact")
  end
  print(("%s: z = %.6f mm (bisection %.6f mm), %d iterations, contact angle %.1f deg"):format(
      name, w.z * 1e3, z * 1e3, w.iterations, math.deg(w.angle)))
end
print(("largest |z - z_bisection| = %.2e m"):format(worst))
