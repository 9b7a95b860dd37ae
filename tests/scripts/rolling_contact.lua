-- Rolling contact with friction through the Lua API (docs/guide/rolling.md): S1002 on 60E1, 0.5 mm elements.
--   - the kinematic creepages against the kinematics written out here, on planar and on conformal areas (the
--     default): spin = omega . n / V (n = t1 x t2, the reference point's normal), the lateral creepage's response
--     to vy, the longitudinal one's to omega (the lever is the rolling radius);
--   - the rigid slip of every element of the wide, curved patch at y = 0: 1 - R / r0 along the track (R varying
--     across the patch), the spin of the element's own normal across it on a conformal area;
--   - the fields of an area recomputed from its grids: creep force = Fx t1 + Fy t2 (planar) or the rows' sums along
--     their own t2 (conformal), power = sum of the density, adhesion fraction from the map, |traction| <= mu p;
--   - braking gives Fx < 0 on both wheels; the mirror symmetry of the centred wheelset; full sliding |F| = mu N;
--   - ws:wheel with friction carries Fz including the creep forces' vertical part; a sweep with kinematics gives
--     the creep forces of ws:contact at its poses;
--   - bad input: clear errors (mu <= 0 or NaN, V = 0, creepage NaN, conflicting or unknown keys).
local check = require "wrc.check"
local C = dofile((arg[0]:match("(.*/)") or "./") .. "contact_helpers.lua")

local wheel = wrc.profile.load(wrc.paths.profiles .. "/s1002.lua")
local rail = wrc.profile.load(wrc.paths.profiles .. "/60e1.lua")
local ws = wrc.wheelset{wheel = wheel, rail = rail, grid = 0.5e-3}  -- conformal areas (the default)
local wp = wrc.wheelset{wheel = wheel, rail = rail, grid = 0.5e-3, surface = "planar"}
local r0 = ws.params.radius
local V = 100 / 3.6

local e0 = ws:equilibrium{y = 0, yaw = 0, Q = 200e3}
local e3 = ws:equilibrium{y = 3e-3, yaw = 0, Q = 200e3}
local function pose(e, extra)
  local t = {y = e.y, z = e.z, roll = e.roll, yaw = e.yaw}
  for k, v in pairs(extra) do t[k] = v end
  return t
end
local function cross(a, b)
  return {x = a.y * b.z - a.z * b.y, y = a.z * b.x - a.x * b.z, z = a.x * b.y - a.y * b.x}
end

-- Kinematic creepages, on both surfaces.
for surface, w in pairs{conformal = ws, planar = wp} do
  local c = w:contact(pose(e3, {V = V, mu = 0.3, yaw_rate = 0.02}))
  for _, side in ipairs{"left", "right"} do
    for i, p in ipairs(c[side].patches) do
      local name = surface .. " " .. side .. " area " .. i
      check.ok((p.rows ~= nil) == (surface == "conformal"), name .. ": the surface")
      -- Omega = (V / r0) a + yaw_rate z with a the axle (roll 0.16 mrad: a = (0, cos roll, sin roll))
      local a = {x = 0, y = math.cos(e3.roll), z = math.sin(e3.roll)}
      local om = {x = V / r0 * a.x, y = V / r0 * a.y, z = V / r0 * a.z + 0.02}
      local n = cross(p.frame.t1, p.frame.t2)
      check.near(p.creepage.phi, (om.x * n.x + om.y * n.y + om.z * n.z) / V, 1e-12, name .. ": spin = Omega . n / V")
      if surface == "planar" then
        check.near(n.x * p.normal.x + n.y * p.normal.y + n.z * p.normal.z, 1, 1e-12, name .. ": t1 x t2 = n")
      end
      local c2 = w:contact(pose(e3, {V = V, mu = 0.3, yaw_rate = 0.02, vy = 0.1}))[side].patches[i]
      local t2 = p.frame.t2
      check.near(c2.creepage.eta - p.creepage.eta, 0.1 * t2.y / V, 1e-12, name .. ": d eta / d vy = t2 . y / V")
      local c3 = w:contact(pose(e3, {V = V, mu = 0.3, yaw_rate = 0.02, omega = V / r0 * 1.001}))[side].patches[i]
      local lever = -(c3.creepage.xi - p.creepage.xi) * V / (V / r0 * 0.001)
      check.near(lever, p.rolling_radius, 0.2e-3, name .. ": d xi / d omega = -(rolling radius) / V")
      -- pure rolling at r0, and the yaw rate moving the wheel's contact point at (y_ref - y) by -yaw_rate (y_ref - y)
      check.near(p.creepage.xi, 1 - lever / r0 - 0.02 * (p.frame.origin.y - e3.y) / V, 1e-7,
                 name .. ": xi = 1 - R / r0 - yaw_rate y_ref / V")
    end
  end
end

-- The rigid slip of every element of the conformal areas at y = 3 mm with all the kinematics (vy, yaw rate, omega off
-- pure rolling), written out here: v = (V, vy, 0) + Omega x (X - c) at the element's point X on the wheel's undeformed
-- surface (the row's point on the rail, h below it along the row's normal n), c = (0, y, z) the wheelset centre;
-- along the track v . e_x tilted toward n by half the slope of the wheel's circumference a x (X - c) (a the axle),
-- across it v . t2 with t2 = (0, n_z, -n_y).
do
  local c = ws:contact(pose(e3, {V = V, mu = 0.3, yaw_rate = 0.02, vy = 0.1, omega = V / r0 * 1.001}))
  local a = {x = 0, y = math.cos(e3.roll), z = math.sin(e3.roll)}
  local om = {x = V / r0 * 1.001 * a.x, y = V / r0 * 1.001 * a.y, z = V / r0 * 1.001 * a.z + 0.02}
  local worst, count = 0, 0
  for _, side in ipairs{"left", "right"} do
    for _, p in ipairs(c[side].patches) do
      for j = 1, p.grid.ny do
        local n = {x = 0, y = p.rows.normal_y[j], z = p.rows.normal_z[j]}
        for k = 1, p.grid.nx do
          if p.pressure[j][k] > 0 then
            local h = p.h[j][k]
            local d = {x = p.frame.origin.x + p.grid.x0 + (k - 1) * p.grid.dx,
                       y = p.rows.y[j] - h * n.y - e3.y, z = p.rows.z[j] - h * n.z - e3.z}
            local w = cross(om, d)
            local v = {x = V + w.x, y = 0.1 + w.y, z = w.z}
            local tw = cross(a, d)
            if tw.x < 0 then tw = {x = -tw.x, y = -tw.y, z = -tw.z} end
            local tilt = 0.5 * (tw.y * n.y + tw.z * n.z) / math.sqrt(tw.x ^ 2 + tw.y ^ 2 + tw.z ^ 2)
            local sx = (v.x + tilt * (v.y * n.y + v.z * n.z)) / math.sqrt(1 + tilt * tilt)
            local sy = v.y * n.z - v.z * n.y
            worst = math.max(worst, math.abs(p.rigid_slip_x[j][k] - sx), math.abs(p.rigid_slip_y[j][k] - sy))
            count = count + 1
          end
        end
      end
    end
  end
  check.ok(count > 100, "conformal kinematics: elements in contact (" .. count .. ")")
  check.ok(worst < 1e-12 * V, "conformal kinematics: the rigid slip of every element (worst " .. worst .. " m/s)")
end

-- The rigid slip of every element of the wide, curved patch of the centred wheelset (zero yaw, roll ~ 0): the wheel's
-- point at lateral position Y and track x moves at V - omega d along the track, d its height below the axle:
-- sqrt(R(Y)^2 - x^2) with R the wheel radius there (the placed profile, interpolated here): the wheel's undeformed
-- surface (the default slip reference; tests/scripts/rolling_slip_reference.lua checks the other). The slip is taken
-- along the contact surface, t1 tilted toward n by half the slope x n_z / R of the wheel's circumference (the rail is
-- straight): the normal velocity -omega x n_z adds -omega x^2 n_z^2 / 2R, which on the tread takes back the wheel's
-- curvature term x^2 / 2R of V - omega d (a slip the rolling wheel does not have). Across the track the spin
-- gives V phi x, with phi = omega (n . axle) / V of the element's own normal: the plane's n, or the row's on a
-- conformal area, where it varies across the patch. Not the linear field of the creepages: R varies quadratically
-- over the 20 mm wide patch.
for surface, w in pairs{conformal = ws, planar = wp} do
  local c = w:contact(pose(e0, {V = V, mu = 0.3}))
  local p = c.left.patches[1]
  local o, t1, t2 = p.frame.origin, p.frame.t1, p.frame.t2
  local axle = {y = math.cos(e0.roll), z = math.sin(e0.roll)}
  local worst, worst_y, spread, lo, hi, spin_lo, spin_hi = 0, 0, 0, math.huge, -math.huge, math.huge, -math.huge
  for j = 1, p.grid.ny do
    for k = 1, p.grid.nx do
      if p.pressure[j][k] > 0 then
        local u, v = p.grid.x0 + (k - 1) * p.grid.dx, p.grid.y0 + (j - 1) * p.grid.dy
        local x, Y, n  -- track x, lateral position on the wheel (from the wheelset centre), normal
        if surface == "planar" then
          n = p.normal
          x, Y = o.x + u * t1.x + v * t2.x, o.y + u * t1.y + v * t2.y - e0.y
        else
          n = {x = 0, y = p.rows.normal_y[j], z = p.rows.normal_z[j]}
          x, Y = o.x + u, p.rows.y[j] - p.h[j][k] * n.y - e0.y
        end
        local R = C.wheel_radius(w, Y)
        local tilt = 0.5 * x * n.z / R
        local expected = (1 - (math.sqrt(R * R - x * x) + 0.5 * x * x * n.z * n.z / R) / r0) / math.sqrt(1 + tilt * tilt)
        worst = math.max(worst, math.abs(p.rigid_slip_x[j][k] / V - expected))
        lo, hi = math.min(lo, expected), math.max(hi, expected)
        local phi = (n.y * axle.y + n.z * axle.z) / r0
        spin_lo, spin_hi = math.min(spin_lo, phi), math.max(spin_hi, phi)
        worst_y = math.max(worst_y, math.abs(p.rigid_slip_y[j][k] / V - phi * x))
      end
    end
  end
  check.ok(hi - lo > 2e-4, surface .. ": the longitudinal rigid slip varies across the patch (by " .. (hi - lo) .. ")")
  check.ok(worst < 2e-6, surface .. ": rigid slip x = 1 - R / r0 at every element (worst " .. worst .. ")")
  check.ok(worst_y < 1e-9, surface .. ": rigid slip y = phi x at every element (worst " .. worst_y .. ")")
  if surface == "conformal" then
    check.ok(spin_hi - spin_lo > 0.05, "conformal: the spin varies across the patch (" .. spin_lo .. " .. " .. spin_hi .. " 1/m)")
  end
end

-- The fields of an area against its grids.
do
  local c = ws:contact(pose(e3, {V = V, mu = 0.3}))
  for _, side in ipairs{"left", "right"} do
    local total = {x = 0, y = 0, z = 0}
    for i, p in ipairs(c[side].patches) do
      local name = side .. " area " .. i
      -- the creep force: each row's traction along e_x and its own t2 = n x e_x = (0, n_z, -n_y)
      local dA = p.grid.dx * p.grid.dy
      -- at its point (x, y_j, z_j) on the rail's surface, for the moment about the wheelset centre
      local F, M = {x = 0, y = 0, z = 0}, {x = 0, y = 0, z = 0}
      for j = 1, p.grid.ny do
        local t2 = {x = 0, y = p.rows.normal_z[j], z = -p.rows.normal_y[j]}
        for k = 1, p.grid.nx do
          local f = {x = p.px[j][k] * dA, y = p.py[j][k] * dA * t2.y, z = p.py[j][k] * dA * t2.z}
          local m = cross({x = p.frame.origin.x + p.grid.x0 + (k - 1) * p.grid.dx, y = p.rows.y[j] - e3.y,
                           z = p.rows.z[j] - e3.z}, f)
          for _, q in ipairs{"x", "y", "z"} do F[q], M[q] = F[q] + f[q], M[q] + m[q] end
        end
      end
      for _, k in ipairs{"x", "y", "z"} do
        check.near(p.creep_force[k], F[k], 1e-9 * math.abs(p.Fx) + 1e-9, name .. ": creep force " .. k)
        check.near(p.creep_moment[k], M[k], 1e-9 * math.abs(p.Fx) + 1e-9, name .. ": creep moment " .. k)
        total[k] = total[k] + p.creep_force[k]
      end
      local power, fx, inside, adhere = 0, 0, 0, 0
      for j = 1, p.grid.ny do
        for k = 1, p.grid.nx do
          local q = p.pressure[j][k]
          power = power + p.power_density[j][k] * dA
          fx = fx + p.px[j][k] * dA
          if q > 0 then
            inside = inside + 1
            if p.adhesion_map[j][k] == 1 then adhere = adhere + 1 end
            check.ok(math.sqrt(p.px[j][k] ^ 2 + p.py[j][k] ^ 2) <= 0.3 * q * (1 + 1e-9), name .. ": |p_t| <= mu p")
            check.ok(p.power_density[j][k] >= 0, name .. ": power density >= 0")
          else
            check.ok(p.adhesion_map[j][k] == 0 and p.px[j][k] == 0, name .. ": no traction outside the contact")
          end
        end
      end
      check.rel(power, p.power, 1e-9, name .. ": power = sum of the density")
      check.rel(fx, p.Fx, 1e-9, name .. ": Fx = sum of px")
      check.near(p.adhesion, adhere / inside, 1e-12, name .. ": adhesion fraction")
      check.ok(p.method == "exact" and p.mu.static == 0.3 and p.mu.kinetic == 0.3 and p.V == V, name .. ": the request")
    end
    for _, k in ipairs{"x", "y", "z"} do
      check.near(c[side].creep_force[k], total[k], 1e-6, side .. ": wheel creep force " .. k)
    end
  end
  -- Frictionless calls are unchanged: the wheel force is the normal one plus the creep force.
  local n = ws:contact(pose(e3, {}))
  check.ok(n.left.creep_force == nil and n.left.patches[1].Fx == nil, "frictionless: no creep fields")
  for _, k in ipairs{"x", "y", "z"} do
    check.near(c.left.force[k] - c.left.creep_force[k], n.left.force[k], 1e-6 * n.left.force.z, "normal force unchanged " .. k)
  end
end

-- On a plane, the creep force is Fx t1 + Fy t2 and its moment about the wheelset centre that of the force at the
-- plane's origin plus Mz n.
do
  local c = wp:contact(pose(e3, {V = V, mu = 0.3}))
  for _, side in ipairs{"left", "right"} do
    for i, p in ipairs(c[side].patches) do
      local t1, t2, n, o = p.frame.t1, p.frame.t2, p.normal, p.frame.origin
      local F = {}
      for _, k in ipairs{"x", "y", "z"} do F[k] = p.Fx * t1[k] + p.Fy * t2[k] end
      local r = {x = o.x, y = o.y - e3.y, z = o.z - e3.z}
      local M = cross(r, F)
      for _, k in ipairs{"x", "y", "z"} do
        check.near(p.creep_force[k], F[k], 1e-9 * math.abs(p.Fx) + 1e-9, "planar " .. side .. " area " .. i .. ": creep force " .. k)
        check.near(p.creep_moment[k], M[k] + p.Mz * n[k], 1e-9 * math.abs(p.Fx) + 1e-9,
                   "planar " .. side .. " area " .. i .. ": creep moment " .. k)
      end
    end
  end
end

-- Braking: both wheels pulled back; the centred wheelset is mirror symmetric; full sliding.
do
  local c = ws:contact(pose(e0, {V = V, mu = 0.3, omega = 0.999 * V / r0}))
  local l, r = c.left.patches[1], c.right.patches[1]
  check.ok(l.creepage.xi > 0 and l.Fx < 0 and r.Fx < 0, "braking: xi > 0, Fx < 0 on both wheels")
  check.rel(r.Fx, l.Fx, 1e-5, "mirror: Fx")
  check.rel(r.Fy, -l.Fy, 1e-5, "mirror: Fy")
  check.rel(r.Mz, -l.Mz, 1e-5, "mirror: Mz")
  check.rel(r.creepage.phi, -l.creepage.phi, 1e-9, "mirror: spin")
  for _, method in ipairs{"exact", "fastsim"} do
    local s = ws:contact(pose(e0, {creepage = {xi = 0.05, eta = 0.03}, mu = 0.25, method = method}))
    for _, side in ipairs{"left", "right"} do
      local p = s[side].patches[1]
      check.rel(math.sqrt(p.Fx ^ 2 + p.Fy ^ 2), 0.25 * p.normal_force, 0.02, method .. " " .. side .. ": full sliding |F| = mu N")
      check.near((p.Fx * 0.05 + p.Fy * 0.03) / math.sqrt(p.Fx ^ 2 + p.Fy ^ 2) / math.sqrt(0.05 ^ 2 + 0.03 ^ 2), -1, 1e-3,
                 method .. " " .. side .. ": opposite to the creepage")
    end
  end
end

-- Rolling backward (V < 0, pure rolling at r0 backward) is the mirror x -> -x of rolling forward: the creepages
-- xi and phi flip (per |V|), and so do Fx and Mz, while Fy stays.
do
  local f = ws:contact(pose(e3, {V = V, mu = 0.3}))
  local b = ws:contact(pose(e3, {V = -V, mu = 0.3}))
  for _, side in ipairs{"left", "right"} do
    local pf, pb = f[side].patches[1], b[side].patches[1]
    check.rel(pb.creepage.xi, -pf.creepage.xi, 1e-9, side .. ": backward xi")
    check.rel(pb.creepage.phi, -pf.creepage.phi, 1e-9, side .. ": backward phi")
    check.rel(pb.Fx, -pf.Fx, 1e-4, side .. ": backward Fx")
    check.rel(pb.Fy, pf.Fy, 1e-4, side .. ": backward Fy")
    check.rel(pb.Mz, -pf.Mz, 1e-3, side .. ": backward Mz")
  end
end

-- ws:wheel with friction: Fz includes the creep forces' vertical part.
do
  local w = ws:wheel{side = "left", y = 6.4e-3, roll = 0.69e-3, Fz = 120e3, V = V, mu = 0.3, yaw_rate = 0.05}
  check.ok(w.converged, "wheel with friction converged")
  check.near(w.force.z, 120e3, 1e-6 * 120e3, "wheel: total vertical force")
  check.ok(math.abs(w.creep_force.z) > 100, "wheel: the creep forces have a vertical part on the flange root")
  local n = 0
  for _, p in ipairs(w.patches) do n = n + p.force.z - p.creep_force.z end
  check.ok(math.abs(n - 120e3) > 50, "wheel: the normal forces alone do not carry Fz")
end

-- A sweep with kinematics: the creep forces of ws:contact at each equilibrium's pose.
do
  local s = ws:sweep{y = {0, 3e-3}, Q = 200e3, V = V, mu = 0.3, threads = 1, progress = false}
  for _, r in ipairs(s) do
    check.ok(r.converged and r.creep_force ~= nil, "sweep case solved with creep forces")
    local c = ws:contact{y = r.y, z = r.z, roll = r.roll, yaw = r.yaw, V = V, mu = 0.3, grids = false}
    for _, side in ipairs{"left", "right"} do
      check.rel(r[side].creep_force.x, c[side].creep_force.x, 1e-4, "sweep creep force x, " .. side)
      check.rel(r[side].creep_force.y, c[side].creep_force.y, 1e-4, "sweep creep force y, " .. side)
    end
  end
  -- The sweep table's creep columns (wrc.sweep).
  local tables = require "wrc.sweep"
  local cols = tables.columns(s)
  check.ok(cols[#cols] == "right_rcf_damage_max" and
           #cols == #tables.sweep_columns + #tables.creep_columns + #tables.damage_columns, "creep and damage columns")
  local row = tables.sweep_row(s[2])
  check.rel(row.left_creep_Fx_kN, s[2].left.creep_force.x / 1e3, 1e-12, "creep column left_creep_Fx_kN")
  check.rel(row.power_W, s[2].power, 1e-12, "creep column power_W")
  -- The damage columns: each wheel's T gamma summed over its areas, |Fx xi| + |Fy eta| of each (docs/guide/damage.md).
  for _, side in ipairs{"left", "right"} do
    local t = 0
    for _, p in ipairs(s[2][side].patches) do t = t + math.abs(p.Fx * p.creepage.xi) + math.abs(p.Fy * p.creepage.eta) end
    check.ok(t > 0, "a sweep case with creep work, " .. side)
    check.rel(row[side .. "_Tgamma_N"], t, 1e-9, "damage column " .. side .. "_Tgamma_N")
    check.ok(row[side .. "_wear_mm3_per_m"] == nil, "no wear column without a wear model, " .. side)
  end
  -- With a wear model: the volume worn off per metre rolled, each wheel's areas summed (mm^3/m), in the sweep's table
  -- and in sweep.csv's cells.
  local sw = ws:sweep{y = {3e-3}, Q = 200e3, V = V, mu = 0.3, threads = 1, progress = false,
                      wear = {model = "archard", k = 1e-3}}
  local wcols = tables.columns(sw)
  check.ok(wcols[#wcols] == "right_wear_mm3_per_m", "wear columns with a wear model")
  local wrow = tables.sweep_row(sw[1])
  for _, side in ipairs{"left", "right"} do
    local v = 0
    for _, p in ipairs(sw[1][side].patches) do v = v + p.wear_volume end
    check.ok(v > 0, "a sweep case that wears, " .. side)
    check.rel(wrow[side .. "_wear_mm3_per_m"], v * 1e9, 1e-12, "wear column " .. side)
  end
  check.ok(#tables.columns(ws:sweep{y = {0}, Q = 200e3, threads = 1, progress = false}) == #tables.sweep_columns,
           "no creep columns without kinematics")
  local ok = pcall(function() return ws:equilibrium{y = 0, Q = 200e3, V = V, mu = 0.3} end)
  check.ok(not ok, "the equilibrium is frictionless: kinematics keys are refused")
end

-- Bad input.
do
  local p = pose(e0, {})
  local function with(extra) local t = pose(e0, extra); return function() return ws:contact(t) end end
  check.fails(with{V = V, mu = 0}, "mu = 0 must be in [0.0001, 1e+12]", "mu = 0")
  check.fails(with{V = V, mu = -0.1}, "must be in [0.0001, 1e+12]", "mu < 0")
  -- A coefficient far below any friction underflowed the traction bound: "internal error; inputs were finite".
  check.fails(with{V = V, mu = 1e-300}, "mu = 1e-300 must be in [0.0001, 1e+12]", "mu = 1e-300")
  check.fails(with{V = V, mu_static = 1e300, mu_kinetic = 0.3}, "mu_static = 1e+300 must be in", "mu_static = 1e300")
  check.fails(with{V = V, mu = 0 / 0}, "'mu' must be finite", "mu NaN")
  -- A percentage, or a coefficient no steel pair has, solved as given would be near the no-slip limit: refused
  -- unless the wheelset's check_setup is off (the no-slip limit asked for on purpose).
  check.fails(with{V = V, mu = 30}, "mu = 30 is implausible for a wheel-rail friction coefficient (0.01 .. 1)", "mu = 30")
  check.fails(with{V = V, friction = {law = "polach", mu0 = 40, A = 0.4, B = 0.6}}, "mu(0) = 40 is implausible",
              "Polach's mu0 = 40")
  check.fails(with{V = V, mu = 0.3, friction_profile = {y = {-0.02, 0.02}, mu = {0.3, 15}}},
              "friction_profile's mu = 15 is implausible", "friction profile in per cent")
  local free = wrc.wheelset{wheel = wheel, rail = rail, grid = 0.5e-3, check_setup = false}
  local t = pose(e0, {V = V, mu = 1e9})
  check.ok(pcall(function() return free:contact(t) end), "check_setup = false: mu = 1e9 (the no-slip limit) accepted")
  check.fails(with{V = 0, mu = 0.3}, "V = 0", "V = 0 with kinematics")
  check.fails(with{V = V}, "'mu'", "no mu")
  check.fails(with{mu = 0.3}, "neither V", "mu without kinematics")
  check.fails(with{omega = 60, mu = 0.3}, "forward speed V", "omega without V")
  check.fails(with{creepage = {xi = 0 / 0}, mu = 0.3}, "'xi' must be finite", "creepage NaN")
  check.fails(with{creepage = {xi = 1e-3, zeta = 1}, mu = 0.3}, "unknown key 'zeta'", "creepage: unknown key")
  check.fails(with{creepage = {xi = 1e-3}, vy = 0.1, mu = 0.3}, "cannot be given with it", "creepage with kinematics")
  check.fails(with{V = V, mu_static = 0.2, mu_kinetic = 0.3}, "exceeds mu_static", "kinetic above static")
  check.fails(with{V = V, mu = 0.3, method = "polach"}, "method", "unknown method")
  check.fails(with{V = V, mu = 0.3, rolling_tolerance = 0}, "rolling_tolerance", "tolerance")
  check.ok(p ~= nil, "bad input refused")
end

-- Messages speak the same from every front end: a position is an ordinal (Lua counts from 1, Python and C from 0, so
-- "y[2]" would name different elements), a type is named in Lua's words when Lua built the options.
do
  for _, bad in ipairs{2, 3} do
    local y = {0, 1e-3, 2e-3, 3e-3}
    y[bad] = 0 / 0
    local err = check.fails(function() return ws:sweep{y = y, Q = 200e3} end, "must be finite, got", "NaN in y")
    local nth = ({"1st", "2nd", "3rd"})[bad]  -- Lua's y[bad] is the bad-th value
    check.ok(tostring(err):find("the " .. nth .. " value of 'y'", 1, true), "the NaN named by its ordinal: " .. tostring(err))
  end
  check.fails(function() return ws:contact{y = 0, z = -1e-4, creepage = {1e-3}, mu = 0.3} end,
              "'creepage' must be a table, got array", "creepage as an array")
end
print("rolling contact: ok")
