-- The fast normal solver (CG with FFT products) against the dense reference (active set, Cholesky) through the
-- whole pipeline (issue 5): the same wheelset built with solver = "fast" (default) and solver = "dense", the
-- same poses. Per contact area: the same grid, the same contact set, pressures within 1e-6 of the peak, the
-- same forces and centres of pressure. Grids are coarse (0.7 mm, 0.4 mm) so that the dense solves stay cheap
-- under the sanitizers.
local check = require "wrc.check"

local function compare(fast, dense, what)
  check.ok(#fast.patches == #dense.patches, what .. "same number of areas")
  local worst = 0
  for k, pf in ipairs(fast.patches) do
    local pd = dense.patches[k]
    local w = string.format("%sarea %d: ", what, k)
    check.ok(pf.merged == pd.merged, w .. "same merge")
    local gf, gd = pf.grid, pd.grid
    check.ok(gf.nx == gd.nx and gf.ny == gd.ny and gf.x0 == gd.x0 and gf.y0 == gd.y0, w .. "same grid")
    local pmax, dp, set_differs = pd.pmax, 0, 0
    for j = 1, gd.ny do
      for i = 1, gd.nx do
        local a, b = pf.pressure[j][i], pd.pressure[j][i]
        if (a > 0) ~= (b > 0) then set_differs = set_differs + 1 end
        dp = math.max(dp, math.abs(a - b))
      end
    end
    worst = math.max(worst, dp / pmax)
    check.ok(set_differs == 0, w .. "same contact set (" .. set_differs .. " elements differ)")
    check.ok(dp <= 1e-6 * pmax, string.format("%smax |dp| / pmax = %.3g <= 1e-6", w, dp / pmax))
    check.ok(pf.elements == pd.elements, w .. "same element count")
    check.rel(pf.normal_force, pd.normal_force, 1e-7, w .. "normal force")
    check.rel(pf.pmax, pd.pmax, 1e-6, w .. "peak pressure")
    check.near(pf.point.x, pd.point.x, 1e-9, w .. "centre of pressure x")
    check.near(pf.point.y, pd.point.y, 1e-9, w .. "centre of pressure y")
    check.near(pf.point.z, pd.point.z, 1e-9, w .. "centre of pressure z")
  end
  return worst
end

local function both(opts)
  local f, d = {}, {}
  for k, v in pairs(opts) do f[k], d[k] = v, v end
  d.solver = "dense"
  return wrc.wheelset(f), wrc.wheelset(d)
end

print(string.format("%-28s %6s %8s %8s %8s %10s", "pair", "y_mm", "z_mm", "areas", "elements", "max_dp/pmax"))
-- S1002 on 60E1: tread, tread + flange root (two zones in one area), flange.
local wheel = wrc.profile.load(wrc.paths.profiles .. "/s1002.lua")
local rail = wrc.profile.load(wrc.paths.profiles .. "/60e1.lua")
local fast, dense = both{wheel = wheel, rail = rail, grid = 0.7e-3}
for _, pose in ipairs{{0, -0.03e-3, 0}, {3e-3, 0.05e-3, 0.002}, {5e-3, 0.3e-3, 0}, {6.5e-3, 0.77e-3, 0}} do
  local y, z, yaw = pose[1], pose[2], pose[3]
  local cf, cd = fast:contact{y = y, z = z, yaw = yaw}, dense:contact{y = y, z = z, yaw = yaw}
  local n = 0
  for _, side in ipairs{"left", "right"} do
    for _, p in ipairs(cf[side].patches) do n = n + p.elements end
  end
  check.ok(n > 150, "enough elements in contact")
  local worst = math.max(compare(cf.left, cd.left, "S1002 left: "), compare(cf.right, cd.right, "S1002 right: "))
  print(string.format("%-28s %6.1f %8.3f %8d %8d %10.2e", "S1002/60E1" .. (yaw ~= 0 and " yaw 2 mrad" or ""),
                      y * 1e3, z * 1e3, #cf.left.patches + #cf.right.patches, n, worst))
  check.rel(cf.force.z, cd.force.z, 1e-7, "total vertical force")
  check.near(cf.moment.x, cd.moment.x, 1e-7 * cd.force.z * 0.75, "total roll moment")
end

-- Two crowns 12 mm apart solved as one merged area (contact_merge.lua's pair, coarser).
local Rc, d, step = 0.08, 12e-3, 0.05e-3
local wy, wz, ry, rz = {}, {}, {}, {}
for k = 0, 130 do wy[#wy + 1], wz[#wz + 1] = -0.070 + k * 1e-3, 0.0 end
local n = math.floor((d / 2 + 0.015) / step + 0.5)
local function arc(t) return math.abs(t) < Rc and math.sqrt(Rc * Rc - t * t) - Rc or -Rc end
for k = -n, n do
  local yk = k * step
  ry[#ry + 1], rz[#rz + 1] = yk, math.max(arc(yk + d / 2), arc(yk - d / 2))
end
local yg = d / 2 + math.sqrt(Rc * Rc - (Rc - 0.2e-3) ^ 2)
local f2, d2 = both{wheel = wrc.profile.points{kind = "wheel", y = wy, z = wz},
                    rail = wrc.profile.points{kind = "rail", y = ry, z = rz}, cant = 0, gauge_depth = 0.2e-3,
                    gauge = 2 * (0.75 - yg), grid = 0.4e-3, strategy = {"coarse", "topology"}}
local cf, cd = f2:contact{z = -40e-6}, d2:contact{z = -40e-6}
check.ok(#cf.left.patches == 1 and cf.left.patches[1].merged == 2, "two crowns: one merged area")
local worst = compare(cf.left, cd.left, "two crowns: ")
print(string.format("%-28s %6.1f %8.3f %8d %8d %10.2e", "two crowns (merged)", 0, -0.04, 1, cf.left.patches[1].elements,
                    worst))
