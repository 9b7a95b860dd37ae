-- The damage indices and the subsurface stresses through the user calls (docs/guide/damage.md), against references
-- computed here:
--   1. Archard in full sliding on a Hertzian patch (ws:contact with a prescribed creepage on a cylinder wheel and a
--      crowned rail of the same radius: a circular Hertz contact): the volume worn off per metre rolled,
--      p.wear_volume (m^3/m), equals k Fn |xi| / H (k Archard's coefficient, -; Fn the Hertz force at the pose's
--      approach, N; xi the creepage, -; H the hardness, Pa) within 1 %, with a constant k and with the KTH map
--      (Jendel 2002: the middle of the published ranges, mild 1..10e-4 and severe 30..40e-4);
--   2. T gamma on S1002 / 60E1 (ws:wheel, ws:contact, tr:contact; conformal and planar): p.Tgamma = |Fx xi| + |Fy eta|
--      and p.Tgamma_spin - p.Tgamma = |Mz phi| with Fx, Fy, Mz summed here from the traction grids px, py;
--   3. p:subsurface on the circular Hertz contact: tau_1 max = Tresca / 2 and its depth against Johnson's closed form on
--      the axis (Contact Mechanics eq. 3.45: 0.31 p0 at 0.48 a for nu = 0.3, maximised here by golden section)
--      within 2 %; with a sliding traction (full sliding, mu = 0.3) the largest von Mises stress rises and moves
--      toward the surface (Hamilton 1983; its closed form is compared in tests/capi/test_capi_damage.cpp).
-- Run with n=20 for a finer grid (elements on the contact radius; default 10).
local check = require "wrc.check"
local here = arg[0]:match("(.*/)") or "./"
local H = dofile(here .. "../halfspace/hertz_reference.lua")

local n = tonumber(arg.n or 10)
local E, nu = 2.1e11, 0.3
local Estar = E / (2 * (1 - nu * nu))
local r0, load, gauge_depth = 0.45, 100e3, 0.2e-3

-- A cylinder wheel (radius r0) on a rail crowned with the transverse radius r0: A = B = 1 / (2 r0), a circle.
local function hertz_wheelset(element)
  local wy, wz, ry, rz = {}, {}, {}, {}
  for k = 0, 130 do wy[#wy + 1], wz[#wz + 1] = -0.070 + k * 1e-3, 0.0 end
  for k = -1250, 1250 do
    local y = k * 0.02e-3
    ry[#ry + 1], rz[#rz + 1] = y, math.sqrt(r0 * r0 - y * y) - r0
  end
  local wheel = wrc.profile.points{kind = "wheel", y = wy, z = wz, name = "cylinder"}
  local rail = wrc.profile.points{kind = "rail", y = ry, z = rz, name = "crown R450"}
  local yg = math.sqrt(r0 * r0 - (r0 - gauge_depth) ^ 2)
  return wrc.wheelset{wheel = wheel, rail = rail, radius = r0, cant = 0, gauge_depth = gauge_depth,
                      gauge = 2 * (0.75 - yg), E = E, nu = nu, grid = element, strategy = {"coarse", "topology"}}
end

local ref = H.from_force(1 / (2 * r0), 1 / (2 * r0), Estar, load)
local ws = hertz_wheelset(ref.a / n)

-- 1. Archard in full sliding. xi = 0.05 is ~20 times the creepage at which the creep force saturates here
-- (3 mu Fn / (G pi a^2 C11) ~ 2e-3), so that the whole patch slips: p.adhesion = 0 is checked.
do
  local xi, k, H_ = 0.05, 1e-3, 2.5e9
  local expected = k * ref.force * xi / H_  -- m^3 per metre rolled
  local c = ws:contact{z = -ref.delta, creepage = {xi = xi}, mu = 0.3, wear = {model = "archard", k = k, hardness = H_}}
  local p = c.left.patches[1]
  check.ok(p.adhesion == 0, "full sliding: no element in adhesion")
  check.rel(p.pressure_integral, ref.force, 0.01, "the patch carries Hertz's force")
  check.rel(p.wear_volume, expected, 0.01, "Archard, constant k: wear volume = k Fn |xi| / H")
  print(("Archard in full sliding, %d elements on a: wear volume %.5e m^3/m, k Fn |xi| / H %.5e (%+.3f %%); "
         .. "sum p dA / Fn - 1 = %+.3f %%"):format(n, p.wear_volume, expected, (p.wear_volume / expected - 1) * 100,
                                                   (p.pressure_integral / ref.force - 1) * 100))
  check.ok(p.wear_model == "archard" and p.wear_map == false, "constant k reported")
  -- The grid field: depth per metre rolled per element; its integral is the volume, its row sums the depth per
  -- passage (wear_passage), the central element's k p |xi| / H (the slip there is the rigid slip: du/dx = 0 by symmetry).
  local g, dA = p.grid, p.grid.dx * p.grid.dy
  local sum, jc, ic, pc = 0, 1, 1, 0
  for j = 1, g.ny do
    local row = 0
    for i = 1, g.nx do
      sum, row = sum + p.wear_depth[j][i] * dA, row + p.wear_depth[j][i] * g.dx
      if p.pressure[j][i] > pc then jc, ic, pc = j, i, p.pressure[j][i] end
    end
    check.rel(p.wear_passage[j] + 1e-30, row + 1e-30, 1e-12, "wear_passage: the row's depth per passage")
  end
  check.rel(sum, p.wear_volume, 1e-12, "wear_volume = sum of wear_depth dA")
  check.rel(p.wear_depth[jc][ic], k * pc * xi / H_, 0.02, "central element: k p |xi| / H (m/m)")
  -- The KTH map at the default hardness (245 HB = 2.40 GPa; p0 = 1.08 GPa < 0.8 H): sliding at V |xi| = 0.05 m/s
  -- (V = 1 m/s) is mild (K2: 1 .. 10e-4, its middle 5.5e-4), at 0.5 m/s (V = 10 m/s) severe (K3: 30 .. 40e-4).
  check.ok(ref.p0 < 0.8 * 245 * 9.80665e6, "p0 below the seizure limit 0.8 H")
  for _, case in ipairs{{V = 1, k = 5.5e-4}, {V = 10, k = 35e-4}} do
    local m = ws:contact{z = -ref.delta, creepage = {xi = xi}, V = case.V, mu = 0.3, wear = {model = "archard"}}
    local q = m.left.patches[1]
    check.ok(q.wear_map == true, "the KTH map reported")
    check.rel(q.wear_volume, case.k * ref.force * xi / (245 * 9.80665e6), 0.01,
              ("Archard, KTH map at V = %g m/s: k Fn |xi| / H"):format(case.V))
  end
  -- Without a wear model no wear field; T gamma is there and is |Fx xi| (full sliding: mu Fn xi).
  local f = ws:contact{z = -ref.delta, creepage = {xi = xi}, mu = 0.3}.left.patches[1]
  check.ok(f.wear_volume == nil and f.wear_depth == nil, "no wear fields without a wear model")
  check.rel(f.Tgamma, 0.3 * ref.force * xi, 0.01, "full sliding: Tgamma = mu Fn |xi|")
  check.fails(function() return ws:contact{z = -ref.delta, wear = {model = "archard"}} end,
              "'wear' is given but neither V", "wear without rolling contact")
  check.fails(function()
    return ws:contact{z = -ref.delta, creepage = {xi = xi}, mu = 0.3, wear = {model = "archard", k = 2}}
  end, "k = 2 must be in", "a bad wear coefficient")
end

-- 2. T gamma on S1002 / 60E1: the creep forces and the spin moment summed here from the traction grids.
do
  local function sums(p)
    local g, dA = p.grid, p.grid.dx * p.grid.dy
    local fx, fy, mz = 0, 0, 0
    for j = 1, g.ny do
      local y = g.y0 + (j - 1) * g.dy
      for i = 1, g.nx do
        local x = g.x0 + (i - 1) * g.dx
        fx, fy = fx + p.px[j][i] * dA, fy + p.py[j][i] * dA
        mz = mz + (x * p.py[j][i] - y * p.px[j][i]) * dA
      end
    end
    return fx, fy, mz
  end
  local function check_tgamma(p, what)
    local fx, fy, mz = sums(p)
    local c = p.creepage
    local t = math.abs(fx * c.xi) + math.abs(fy * c.eta)
    check.ok(t > 1, what .. ": a case with creep work")
    check.rel(p.Tgamma, t, 1e-9, what .. ": Tgamma = |Fx xi| + |Fy eta|")
    check.rel(p.Tgamma_spin - p.Tgamma, math.abs(mz * c.phi), 1e-6, what .. ": Tgamma_spin - Tgamma = |Mz phi|")
    check.ok(p.Tgamma_spin > p.Tgamma, what .. ": spin adds work")
  end
  local wheel, rail = wrc.profile.load("profiles/s1002.lua"), wrc.profile.load("profiles/60e1.lua")
  for _, surface in ipairs{"conformal", "planar"} do
    local s = wrc.wheelset{wheel = wheel, rail = rail, grid = 0.5e-3, surface = surface}
    for _, y in ipairs{0, 6e-3} do
      local w = s:wheel{side = "left", y = y, Fz = 100e3, V = 30, vy = 0.05, yaw_rate = 0.01, mu = 0.3}
      for k, p in ipairs(w.patches) do check_tgamma(p, ("%s ws:wheel y = %g mm, area %d"):format(surface, y * 1e3, k)) end
      local c = s:contact{y = y, z = w.z, roll = 0, creepage = {xi = -1e-3, eta = 0.5e-3, phi = 0.2}, mu = 0.3}
      for k, p in ipairs(c.left.patches) do check_tgamma(p, ("%s ws:contact y = %g mm, area %d"):format(surface, y * 1e3, k)) end
      local tr = s:trajectory{grids = true}
      local t = tr:contact{y = y, z = w.z, V = 30, vy = 0.05, yaw_rate = 0.01, mu = 0.3}
      for k, p in ipairs(t.left.patches) do check_tgamma(p, ("%s tr:contact y = %g mm, area %d"):format(surface, y * 1e3, k)) end
    end
  end
end

-- 3. p:subsurface on the circular Hertz contact.
do
  -- Johnson eq. 3.45 on the axis (p0 = 1, z in a): sigma_z = -1 / (1 + z^2),
  -- sigma_r = -(1 + nu) (1 - z atan(1 / z)) + 1 / (2 (1 + z^2)); tau_1 = |sigma_r - sigma_z| / 2.
  local function tau1(z) return math.abs(-(1 + nu) * (1 - z * math.atan(1 / z)) + 1.5 / (1 + z * z)) / 2 end
  local lo, hi, g = 0.1, 1.0, (math.sqrt(5) - 1) / 2
  for _ = 1, 100 do
    local c, d = hi - g * (hi - lo), lo + g * (hi - lo)
    if tau1(c) > tau1(d) then hi = d else lo = c end
  end
  local zj = (lo + hi) / 2
  check.near(zj, 0.48, 0.005, "Johnson: tau_1 max at 0.48 a")
  check.near(tau1(zj), 0.31, 0.001, "Johnson: tau_1 max 0.31 p0")
  local z = {}
  for k = 0, 100 do z[#z + 1] = (0.2 + 0.006 * k) * ref.a end
  local p = ws:contact{z = -ref.delta}.left.patches[1]
  local s = p:subsurface{z = z}
  check.rel(s.tresca_max / 2, tau1(zj) * ref.p0, 0.02, "p:subsurface: tau_1 max against Johnson eq. 3.45")
  check.rel(s.tresca_max_z, zj * ref.a, 0.02, "p:subsurface: its depth")
  check.rel(s.tau1_max, s.tresca_max / 2, 1e-12, "tau1_max is half of Tresca")
  check.ok(#s.depths == #z and s.depths[1].max_shear.nx == p.grid.nx, "every depth with its grids")
  check.ok(s.shakedown.regime == "elastic" or s.shakedown.regime == "elastic shakedown", "a shakedown verdict")
  check.rel(s.shakedown.load_factor, p.pmax / s.shakedown.shear_yield, 1e-12, "load factor p0 / k")
  check.near(s.shakedown.traction_coefficient, 0, 1e-12, "frictionless: mu = 0")
  print(("Hertz circle, %d elements on a: tau_1 max %.4f p0 at %.4f a (Johnson %.4f at %.4f); von Mises max %.4f p0 at %.4f a")
        :format(n, s.tresca_max / 2 / ref.p0, s.tresca_max_z / ref.a, tau1(zj), zj, s.von_mises_max / ref.p0,
                s.von_mises_max_z / ref.a))
  -- Sliding (full sliding at mu = 0.3): the largest von Mises stress rises and moves toward the surface.
  local zs = {}
  for k = 1, 50 do zs[k] = 0.02 * k * ref.a end
  local free = p:subsurface{z = zs, fields = false}
  local sl = ws:contact{z = -ref.delta, creepage = {xi = 0.05}, mu = 0.3}.left.patches[1]
  local ss = sl:subsurface{z = zs, fields = false}
  check.ok(ss.von_mises_max > 1.03 * free.von_mises_max, "sliding raises the largest von Mises stress")
  check.ok(ss.von_mises_max_z < free.von_mises_max_z, "and moves it toward the surface")
  check.rel(ss.shakedown.traction_coefficient, 0.3, 0.01, "sliding: mu_eff = |(Fx, Fy)| / Fz = mu")
  check.ok(ss.depths[1].von_mises == nil, "fields = false: the maxima alone")
  check.fails(function() return ws:contact{z = -ref.delta, grids = false}.left.patches[1]:subsurface{z = {1e-3}} end,
              "no pressure grid", "an area without grids")
  check.fails(function() return p:subsurface{z = {-1e-3}} end, "z", "a negative depth")
  check.fails(function() return p:subsurface{} end, "'z' is required", "no depths")
end
