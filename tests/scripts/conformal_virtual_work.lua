-- Virtual work: for a frictionless contact the lateral force on the wheel is the derivative of the potential energy
-- with respect to a rigid lateral shift of the wheel at fixed vertical force (issue 15). The left wheel of S1002 on
-- 60E1 (the paper's track) is held at Fz = 100 kN, roll 0, yaw 0 (ws:wheel solves its height z) at y = 5.5, 6.3 and
-- 6.6 mm, where its contact wraps the flange root. With the elastic energy of its contact areas
--     U = 1/2 sum p h dA   (on the contact set h is the elastic approach, 2 D p = h)
-- and the load's potential Fz z, Pi(y) = U + Fz z is stationary in z at the solved height, and
--     Fy = -dPi/dy   (central differences, +-0.5 um; checked against +-0.25 um),
-- the lateral force the rail exerts on the wheel. Likewise at fixed y: Fz = -dU/dz. Both hold for a model whose force
-- directions are those along which its h changes when the wheel moves. The engine's h along a rail line is the
-- line's depth inside the wheel along the wheel's normal, so an element's h changes by -n . dX: the conformal
-- surface, whose elements push along their own normals, satisfies virtual work to the order of its approximations
-- (asserted: within 0.4 % of Fy, 0.2 % of Fz); a plane pushes all of its pressure along one normal, and the planar
-- errors are printed, not asserted: they are what the conformal surface is for (measured at this 0.4 mm grid:
-- planar -15.7, +5.3, +18.8 % of Fy, conformal -0.17, -0.08, +0.11 %, Fz within 0.1 %). With the wheel's normal taken
-- at the radial foot of a line's deepest point instead of at its normal foot, the direction its depth is measured
-- along, the conformal rows leaned at the flange root's concave throat: +0.02, +0.37, +0.72 % of Fy, Fz -0.33 %.
local check = require "wrc.check"

local wheel = wrc.profile.load(wrc.paths.profiles .. "/s1002.lua")
local rail = wrc.profile.load(wrc.paths.profiles .. "/60e1.lua")
local Fz = 100e3

local function energy(w)
  local U = 0
  for _, p in ipairs(w.patches) do
    local dA = p.grid.dx * p.grid.dy
    for j = 1, p.grid.ny do
      for i = 1, p.grid.nx do
        local pr = p.pressure[j][i]
        if pr > 0 then U = U + 0.5 * pr * p.h[j][i] * dA end
      end
    end
  end
  return U
end

print("virtual work, left wheel at Fz = 100 kN: Fy reported vs -dPi/dy, Fz vs -dU/dz (kN; errors relative to Fy, Fz)")
local worst = {}
for _, surface in ipairs{"planar", "conformal"} do
  local ws = wrc.wheelset{wheel = wheel, rail = rail, surface = surface, grid = 0.4e-3, tolerance = 1e-12}
  local function potential(y)
    local w = ws:wheel{side = "left", y = y, yaw = 0, roll = 0, Fz = Fz}
    return energy(w) + Fz * w.z
  end
  worst[surface] = 0
  for _, y in ipairs{5.5e-3, 6.3e-3, 6.6e-3} do
    local w = ws:wheel{side = "left", y = y, yaw = 0, roll = 0, Fz = Fz}
    local what = ("%s, y = %.1f mm: "):format(surface, y * 1e3)
    check.ok(w.converged and math.abs(w.force.z - Fz) < 1e-6 * Fz, what .. "the wheel carries Fz")
    local d = 0.5e-6
    local fy = -(potential(y + d) - potential(y - d)) / (2 * d)
    local fy2 = -(potential(y + d / 2) - potential(y - d / 2)) / d
    -- The plane moves with y, which makes the planar energy rough on this scale (0.25 % at 5.5 mm): checked on the
    -- conformal surface only.
    if surface == "conformal" then
      check.rel(fy2, fy, 2e-3, what .. "the difference quotient converged (+-0.5 um vs +-0.25 um)")
    end
    local dz = 0.1e-6
    local up = energy(ws:contact{y = y, z = w.z + dz, roll = 0}.left)
    local down = energy(ws:contact{y = y, z = w.z - dz, roll = 0}.left)
    local fz = -(up - down) / (2 * dz)
    local ey, ez = w.force.y / fy - 1, w.force.z / fz - 1
    worst[surface] = math.max(worst[surface], math.abs(ey))
    print(("  %-9s y = %.1f mm: Fy %8.3f vs %8.3f (%+6.2f %%), Fz %8.3f vs %8.3f (%+5.2f %%); angle %.1f deg"):format(
        surface, y * 1e3, w.force.y / 1e3, fy / 1e3, 100 * ey, w.force.z / 1e3, fz / 1e3, 100 * ez, math.deg(w.angle)))
    if surface == "conformal" then
      check.ok(math.abs(ey) < 0.004, what .. ("lateral force = -dPi/dy within 0.4 %% (%.2f %%)"):format(100 * ey))
      check.ok(math.abs(ez) < 0.002, what .. ("vertical force = -dU/dz within 0.2 %% (%.2f %%)"):format(100 * ez))
    end
  end
end
print(("largest |error| of Fy: planar %.1f %%, conformal %.1f %%"):format(100 * worst.planar, 100 * worst.conformal))
check.ok(worst.conformal < worst.planar, "the conformal surface satisfies virtual work better than the plane")
