-- Symmetries of the equilibrium of a symmetric wheelset on a symmetric track (S1002 on 60E1, Q = 200 kN, grid
-- 1 mm), each case solved on both sides (from scratch, or from mirrored starts):
--   mirror in the x-z plane:   (y, yaw) -> (-y, -yaw): z same, roll, Y, Mz opposite, My same; the left wheel's
--       results become the right wheel's with force (Fx, -Fy, Fz) and moment (-Mx, My, -Mz) (an axial vector
--       under a reflection), the same contact angle, rolling radius and number of contact areas;
--   half turn about z:         (y, yaw) -> (-y, yaw): z same, roll, Y, My opposite, Mz same; left <-> right with
--       force (-Fx, -Fy, Fz) and moment (-Mx, -My, Mz); contact points x -> -x.
-- Cases: tread (y = 3 mm), flange root (6.2 mm) and beyond the lift-off of the right wheel (7 mm), yaw 1 deg, and the
-- flange root at yaw 0 (6.3 mm, where both symmetries coincide and Mz = 0).
--
-- Tolerances: both solutions satisfy the equilibrium to 1e-6 Q = 0.2 N (force) and 0.2 N m (moment). The smallest
-- singular value of the Jacobian d(Fz, Mx)/d(z, roll) at these poses is above 1.5e8 (N/m, N m/rad; the case beyond
-- lift-off is the weakest, measured by central differences), so each pose is within 2e-9 (m, rad) of the exact one
-- and the two within 4e-9: asserted ten times that, z and roll within 4e-8 m and 4e-8 rad. Forces and moments move
-- with the pose by at most about 2e9 N/m, 8 N: asserted 1e-4 Q = 20 N (N m). Contact angles and rolling radii
-- move with the contact point, which runs fastest at the flange root (about 5 m per rad of roll): 2e-5 rad, 1e-6 m.
-- (Measured differences are far smaller, 1e-11 m: the two solves take mirrored paths.)
local check = require "wrc.check"

local wheel = wrc.profile.load(wrc.paths.profiles .. "/s1002.lua")
local rail = wrc.profile.load(wrc.paths.profiles .. "/60e1.lua")
local ws = wrc.wheelset{wheel = wheel, rail = rail, grid = 1e-3}
local Q = 200e3
local tol = {z = 4e-8, roll = 4e-8, force = 1e-4 * Q, moment = 1e-4 * Q, angle = 2e-5, radius = 1e-6}
local worst = {z = 0, roll = 0, force = 0, moment = 0, angle = 0, radius = 0}

local function solve(y, yaw, start) return ws:equilibrium{y = y, yaw = yaw, Q = Q, grids = false, start = start} end

local function near(kind, a, b, what)
  local d = math.abs(a - b)
  worst[kind] = math.max(worst[kind], d)
  check.ok(d <= tol[kind], ("%s: %.10g vs %.10g (difference %.3g > %.3g)"):format(what, a, b, d, tol[kind]))
end

-- s = {x, y, z} signs of the force map and m = signs of the moment map; sy, syaw: the map of y and yaw.
local function compare(e, f, name, s, m)
  near("z", f.z, e.z, name .. ": z")
  near("roll", f.roll, -e.roll, name .. ": roll")
  near("force", f.Y, s[2] * e.Y, name .. ": Y")
  near("moment", f.My, m[2] * e.My, name .. ": My")
  near("moment", f.Mz, m[3] * e.Mz, name .. ": Mz")
  check.ok((f.rolling_radius_difference == nil) == (e.rolling_radius_difference == nil), name .. ": Δr present on both")
  if e.rolling_radius_difference then  -- absent with a wheel lifted
    near("radius", f.rolling_radius_difference, -e.rolling_radius_difference, name .. ": rolling radius difference")
  end
  for _, pair in ipairs{{"left", "right"}, {"right", "left"}} do
    local a, b = e[pair[1]], f[pair[2]]
    local w = ("%s: %s wheel vs %s"):format(name, pair[1], pair[2])
    check.ok(#a.patches == #b.patches, w .. ": number of contact areas")
    for i, c in ipairs{"x", "y", "z"} do
      near("force", b.force[c], s[i] * a.force[c], w .. ": force " .. c)
      near("moment", b.moment[c], m[i] * a.moment[c], w .. ": moment " .. c)
    end
    if #a.patches > 0 then
      near("angle", b.angle, a.angle, w .. ": contact angle")
      near("radius", b.rolling_radius, a.rolling_radius, w .. ": rolling radius")
    end
  end
end

local deg = math.pi / 180
-- {y, yaw, start}: the case beyond lift-off starts near the branch balanced on one flange (from the centre the
-- solver would reach it by continuation, 120 evaluations); its images start from the image of that start.
for _, c in ipairs{{3e-3, deg}, {6.2e-3, deg}, {7e-3, deg, {z = 1.2e-3, roll = -0.5e-3}}, {6.3e-3, 0}} do
  local y, yaw, start = c[1], c[2], c[3]
  local image = start and {z = start.z, roll = -start.roll}
  local e = solve(y, yaw, start)
  local name = ("y = %.1f mm, yaw = %g deg"):format(y * 1e3, yaw / deg)
  local mirror = solve(-y, -yaw, image)
  compare(e, mirror, name .. " mirrored to (-y, -yaw)", {1, -1, 1}, {-1, 1, -1})
  if yaw ~= 0 then
    local turned = solve(-y, yaw, image)
    compare(e, turned, name .. " turned to (-y, yaw)", {-1, -1, 1}, {-1, -1, 1})
  else
    check.near(e.Mz, 0, tol.moment, name .. ": Mz = 0 at yaw 0")
  end
  print(("%s: z = %.4f mm, roll = %.4f mrad, Y/Q = %.4f, Mz = %.1f N m, areas left %d right %d"):format(
      name, e.z * 1e3, e.roll * 1e3, e.Y_Q, e.Mz, #e.left.patches, #e.right.patches))
end
print(("largest differences: z %.2e m, roll %.2e rad, forces %.2e N, moments %.2e N m, angles %.2e rad, radii %.2e m")
          :format(worst.z, worst.roll, worst.force, worst.moment, worst.angle, worst.radius))
