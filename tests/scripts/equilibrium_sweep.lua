-- Equilibrium residuals for every case of a coarse version of the paper's sweep: S1002 on 60E1 (the paper's
-- track), Q = 200 kN, yaw 0 and 1 deg, y from -8 to +8 mm in 1 mm steps, on 2 worker threads, grid 1 mm
-- (coarser than the default 0.2 mm to stay fast under the sanitizers; the full 0.1 mm sweep on the default grid
-- is in tests/bench/bench_equilibrium.cpp). The range covers tread contact, flange contact and, beyond
-- |y| = 6.5 mm, the wheelset balanced on one flange with the other wheel lifted.
--
-- For every case, computed here from the returned tables rather than taken from the solver's own residual:
--   - the forces of the contact areas: pressure integral = integral of the pressure grid (sum p dA), force = N n,
--     wheel force = sum of its areas, total = left + right;
--   - the moment about the wheelset centre (0, y, z) = sum of the elements' moments: each element's p dA along its
--     row's normal at its point on the rail (the default conformal areas; on a plane: (centre of pressure - centre)
--     x area force);
--   - |sum Fz - Q| <= 1e-6 Q and |sum Mx| <= 1e-6 Q x 1 m (the solver's defaults);
--   - the pose re-evaluated by ws:contact (a fresh evaluation of the whole pipeline) is an equilibrium too:
--     same tolerances plus 1e-7 Q for the normal solver's own tolerance (1e-8 of the wheel loads);
--   - the outputs follow docs/design.md, section 2: Y = -sum Fy, My = -sum My, Mz = -sum Mz (what a support at
--     the centre must apply), Y_Q = Y / Q, rolling_radius_difference = left - right; Mz = 0 at yaw 0.
local check = require "wrc.check"

local wheel = wrc.profile.load(wrc.paths.profiles .. "/s1002.lua")
local rail = wrc.profile.load(wrc.paths.profiles .. "/60e1.lua")
local ws = wrc.wheelset{wheel = wheel, rail = rail, grid = 1e-3}
local Q = 200e3
local ftol, mtol = 1e-6 * Q, 1e-6 * Q * 1.0
local noise = 1e-7 * Q

local sweep = ws:sweep{y = {from = -8e-3, to = 8e-3, step = 1e-3}, yaw = {0, math.rad(1)}, Q = Q, threads = 2,
                       grids = true, progress = false}
check.ok(#sweep == 34, "34 cases")
check.ok(sweep.failed == 0, ("no failed case (%d failed)"):format(sweep.failed))

local function sub(a, b) return {x = a.x - b.x, y = a.y - b.y, z = a.z - b.z} end
local function add(a, b) return {x = a.x + b.x, y = a.y + b.y, z = a.z + b.z} end
local function scale(a, s) return {x = a.x * s, y = a.y * s, z = a.z * s} end
local function cross(a, b) return {x = a.y * b.z - a.z * b.y, y = a.z * b.x - a.x * b.z, z = a.x * b.y - a.y * b.x} end
local function norm(a) return math.sqrt(a.x * a.x + a.y * a.y + a.z * a.z) end
local zero = {x = 0, y = 0, z = 0}

-- The moment of an area's pressure about the centre: on a plane, its force at the centre of pressure; on a conformal
-- area, every element's p dA along its row's normal at its point on the rail (x from the frame's origin, at grid
-- x = 0), recomputed from the grid.
local function area_moment(p, centre)
  if p.surface ~= "conformal" then return cross(sub(p.point, centre), p.force) end
  local g, M = p.grid, zero
  for j = 1, g.ny do
    local n = {x = 0, y = p.rows.normal_y[j], z = p.rows.normal_z[j]}
    for i = 1, g.nx do
      local f = p.pressure[j][i] * g.dx * g.dy
      if f > 0 then
        local X = {x = p.frame.origin.x + g.x0 + (i - 1) * g.dx, y = p.rows.y[j], z = p.rows.z[j]}
        M = add(M, scale(cross(sub(X, centre), n), f))
      end
    end
  end
  return M
end

local worst = {force = 0, moment = 0, reeval_force = 0, reeval_moment = 0, pressure = 0}
local lifted = 0
for _, r in ipairs(sweep) do
  local what = ("y = %.1f mm, yaw = %.0f deg"):format(r.y * 1e3, math.deg(r.yaw))
  check.ok(r.converged, what .. ": converged")
  local centre = {x = 0, y = r.y, z = r.z}
  local F, M = zero, zero
  local wheel_force = {}
  for _, side in ipairs{"left", "right"} do
    local w = r[side]
    local Fw, Mw = zero, zero
    for k, p in ipairs(w.patches) do
      local pw = ("%s, %s area %d"):format(what, side, k)
      -- Normal force from the pressure grid.
      local sum = 0
      for _, row in ipairs(p.pressure) do
        for _, v in ipairs(row) do
          check.ok(v >= 0 and v == v, pw .. ": pressure >= 0")
          sum = sum + v
        end
      end
      local N = sum * p.grid.dx * p.grid.dy
      worst.pressure = math.max(worst.pressure, math.abs(N - p.pressure_integral) / Q)
      check.near(N, p.pressure_integral, 1e-9 * Q, pw .. ": integral of the pressure grid")
      check.near(norm(sub(p.force, scale(p.normal, p.normal_force))), 0, 1e-9 * Q, pw .. ": force = N n")
      Fw = add(Fw, p.force)
      Mw = add(Mw, area_moment(p, centre))
    end
    check.near(norm(sub(Fw, w.force)), 0, 1e-9 * Q, what .. ": " .. side .. " wheel force = sum of its areas")
    check.near(norm(sub(Mw, w.moment)), 0, 1e-9 * Q, what .. ": " .. side .. " wheel moment about the centre")
    wheel_force[side] = Fw
    F, M = add(F, Fw), add(M, Mw)
  end
  if #r.right.patches == 0 or #r.left.patches == 0 then lifted = lifted + 1 end
  -- The equilibrium, from the recomputed totals.
  local rf, rm = F.z - Q, M.x
  worst.force = math.max(worst.force, math.abs(rf) / Q)
  worst.moment = math.max(worst.moment, math.abs(rm) / Q)
  check.ok(math.abs(rf) <= ftol, ("%s: |sum Fz - Q| = %.3g N <= %.3g N"):format(what, math.abs(rf), ftol))
  check.ok(math.abs(rm) <= mtol, ("%s: |sum Mx| = %.3g N m <= %.3g N m"):format(what, math.abs(rm), mtol))
  check.near(r.residual.force, rf, 1e-9 * Q, what .. ": reported force residual")
  check.near(r.residual.moment, rm, 1e-9 * Q, what .. ": reported moment residual")
  -- Outputs (docs/design.md, section 2).
  check.near(r.Y, -F.y, 1e-9 * Q, what .. ": Y = -sum Fy")
  check.near(r.My, -M.y, 1e-9 * Q, what .. ": My = -sum My")
  check.near(r.Mz, -M.z, 1e-9 * Q, what .. ": Mz = -sum Mz")
  check.near(r.Y_Q, r.Y / Q, 1e-12, what .. ": Y_Q")
  if r.left.lifted or r.right.lifted then  -- a lifted wheel has no rolling radius: no Δr
    check.ok(r.rolling_radius_difference == nil, what .. ": no rolling radius difference with a wheel lifted")
  else
    check.near(r.rolling_radius_difference, r.left.rolling_radius - r.right.rolling_radius, 1e-12, what .. ": rolling radius difference")
  end
  if r.yaw == 0 then check.near(r.Mz, 0, 1e-6 * Q, what .. ": no yaw moment at yaw 0") end
  -- The pose re-evaluated from scratch.
  local c = ws:contact{y = r.y, z = r.z, roll = r.roll, yaw = r.yaw, grids = false}
  local cf, cm = c.force.z - Q, c.moment.x
  worst.reeval_force = math.max(worst.reeval_force, math.abs(cf) / Q)
  worst.reeval_moment = math.max(worst.reeval_moment, math.abs(cm) / Q)
  check.ok(math.abs(cf) <= ftol + noise, ("%s: re-evaluated |sum Fz - Q| = %.3g N"):format(what, math.abs(cf)))
  check.ok(math.abs(cm) <= mtol + noise, ("%s: re-evaluated |sum Mx| = %.3g N m"):format(what, math.abs(cm)))
  check.near(c.force.y, F.y, noise, what .. ": re-evaluated lateral force")
end
-- Tread and flange contact with both wheels loaded, and one-flange balance, all appear in this sweep.
check.ok(lifted >= 4 and lifted <= 12, ("cases with a lifted wheel: %d (|y| >= 7 mm)"):format(lifted))
print(("%d cases in %.2f s on %d threads; largest residuals: force %.2e Q, moment %.2e Q m; re-evaluated: force %.2e Q, " ..
       "moment %.2e Q m; pressure integral vs normal force %.1e Q; %d cases with a lifted wheel")
          :format(#sweep, sweep.seconds, sweep.threads, worst.force, worst.moment, worst.reeval_force, worst.reeval_moment,
                  worst.pressure, lifted))

-- Per-case starts (the key starts, as a wear loop gives each case its equilibrium on profiles worn a little less):
-- the cases under a 10 % larger load started from the equilibria under Q, in chunks of one case (each would start
-- cold without them). Each case is checked against the sweep under that load without starts (same tolerances), and
-- costs fewer contact evaluations.
do
  local ys = {-3e-3, -1e-3, 0, 2e-3, 4e-3}
  local before = ws:sweep{y = ys, Q = Q, threads = 2, chain = 1, progress = false}
  local z, roll = {}, {}
  for i, e in ipairs(before) do z[i], roll[i] = e.z, e.roll end
  roll[2], z[2] = 0 / 0, 0 / 0  -- none for this case: it starts cold
  local cold = ws:sweep{y = ys, Q = 1.1 * Q, threads = 2, chain = 1, progress = false}
  local warm = ws:sweep{y = ys, Q = 1.1 * Q, threads = 2, chain = 1, progress = false, starts = {z = z, roll = roll}}
  local ev_cold, ev_warm = 0, 0
  for i = 1, #ys do
    local a, b = cold[i], warm[i]
    check.ok(a.converged and b.converged, ("starts: case %d converged"):format(i))
    check.ok(math.abs(b.z - before[i].z) > 2e-6, ("starts: case %d moved (the check is not trivial)"):format(i))
    check.near(b.z, a.z, 1e-8, ("starts: case %d's z as without starts"):format(i))
    check.near(b.Y, a.Y, 2 * ftol, ("starts: case %d's Y as without starts"):format(i))
    if i ~= 2 then ev_cold, ev_warm = ev_cold + a.evaluations, ev_warm + b.evaluations
    else check.ok(b.evaluations == a.evaluations, "starts: a case without one starts cold as before") end
  end
  print(("starts: %d contact evaluations from the starts, %d cold"):format(ev_warm, ev_cold))
  check.ok(ev_warm < ev_cold / 2, "starts: the cases started from their equilibria cost less than half of cold ones")
  for _, bad in ipairs{{z = {0}, roll = {0}}, {z = z}, {z = {0 / 0, 0, 0, 0, 0}, roll = {0, 0, 0, 0, 0}}} do
    local ok, err = pcall(ws.sweep, ws, {y = ys, Q = Q, progress = false, starts = bad})
    check.ok(not ok and tostring(err):match("starts"), "starts: bad starts refused naming the key: " .. tostring(err))
  end
end

-- Contact starts (starts.contact: each case's last pressures and exact tangential tractions, as a wear loop hands them
-- from one step to the next): the rolling cases under a 10 % larger load started from the sweep under Q (chunks of one
-- case: without them each area's first solves start cold). The creep forces equal the cold sweep's within the
-- tangential solver's tolerance, with fewer products of the exact solver.
do
  local ys = {-3e-3, 0, 2e-3, 4e-3}
  local roll_keys = {V = 100 / 3.6, mu = 0.3, method = "exact"}
  local function sweep(load, starts, keep)
    local k = {y = ys, Q = load, threads = 2, chain = 1, progress = false, starts = starts, contact_starts = keep}
    for key, v in pairs(roll_keys) do k[key] = v end
    return ws:sweep(k)
  end
  local before = sweep(Q, nil, true)
  local z, roll, contact = {}, {}, {}
  for i, e in ipairs(before) do
    check.ok(getmetatable(e.contact_start) ~= nil, ("contact starts: case %d has its contact_start"):format(i))
    z[i], roll[i], contact[i] = e.z, e.roll, e.contact_start
  end
  contact[2] = false  -- none for this case: its rolling contact starts as without
  local cold = sweep(1.1 * Q, {z = z, roll = roll})
  local warm = sweep(1.1 * Q, {z = z, roll = roll, contact = contact})
  check.ok(cold[1].contact_start == nil, "contact starts: none unless asked for")
  local function products(e)
    local n = 0
    for _, side in ipairs{"left", "right"} do
      for _, p in ipairs(e[side].patches) do n = n + p.creep_products end
    end
    return n
  end
  local pc, pw = 0, 0
  for i = 1, #ys do
    local a, b = cold[i], warm[i]
    check.ok(a.converged and b.converged, ("contact starts: case %d converged"):format(i))
    local F = math.sqrt(a.creep_force.x ^ 2 + a.creep_force.y ^ 2)
    check.ok(F > 1e3, ("contact starts: case %d has creep forces (%.0f N)"):format(i, F))
    for _, c in ipairs{"x", "y"} do
      check.near(b.creep_force[c], a.creep_force[c], 1e-4 * F, ("contact starts: case %d's creep force %s"):format(i, c))
    end
    check.near(b.z, a.z, 1e-8, ("contact starts: case %d's z as without"):format(i))
    if i ~= 2 then pc, pw = pc + products(a), pw + products(b)
    else check.ok(products(b) == products(a), "contact starts: a case without one solves as before") end
  end
  print(("contact starts: %d products of the exact tangential solver from the starts, %d without"):format(pw, pc))
  check.ok(pw < 0.8 * pc, "contact starts: fewer tangential products")
  for _, bad in ipairs{{false}, {1, 2, 3, 4}} do
    local ok, err = pcall(sweep, Q, {z = z, roll = roll, contact = bad})
    check.ok(not ok and tostring(err):match("starts.contact"), "contact starts: bad ones refused: " .. tostring(err))
  end
end
