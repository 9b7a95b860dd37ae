-- Each wheel's Jacobian (ws:contact{sensitivity = true} with rolling keys: w.jacobian) against central finite
-- differences of the same calls: d(Fx, Fy, Fz, Mx, My, Mz)/d(xi, eta, phi, y, z, roll, yaw) of the left wheel,
-- S1002 on 60E1 (grid 0.5 mm), exact theory and FASTSIM, prescribed creepages with spin in partial slip and near
-- saturation, at the tread (y = 0 and 3 mm) and the flange root (y = 6.5 mm) of the frictionless equilibria under
-- 200 kN (the poses are inputs only).
--
-- Tolerance: every entry within 1 % of its column's scale (the largest force, or moment, of the difference column).
-- The differences: step h (below: 0.2 % of the creepages, 1e-6 m / rad for y, roll, yaw, 1e-7 m for z, where the
-- approach changes Fz by ~0.1 %); the solutions change their adhesion / slip split and their contact set at discrete
-- elements, so a difference straddling such a change is no derivative, and FASTSIM's flexibilities curve where an edge
-- element passes through its weight's ramp (ellipse.cpp: within 1e-6 rad of roll, which moves the element's pressure
-- by a third of the ramp): the forward and backward quotients must agree within 0.1 % of the column's scale, else
-- the step is halved (up to 7 times) and the column fails when they never do. (At 0.5 % and 4 halvings the roll
-- column of FASTSIM near saturation at y = 0 took a difference 1.7 % off; at 0.1 % it agrees within 2e-5.) The solvers' tolerances (normal 1e-8,
-- rolling 1e-9 here) keep their noise far below the differences.
--
-- With the wheelset's kinematics (V, vy) instead of creepages, the pose columns (the creepages then change with the
-- pose). And a wrong Jacobian fails: the pose columns of the normal problem's part alone (the frictionless call's
-- jacobian, without the tangential chain) must fail the same check in every case.
local check = require "wrc.check"

local wheel = wrc.profile.load(wrc.paths.profiles .. "/s1002.lua")
local rail = wrc.profile.load(wrc.paths.profiles .. "/60e1.lua")
local ws = wrc.wheelset{wheel = wheel, rail = rail, grid = 0.5e-3}
local columns = {"xi", "eta", "phi", "y", "z", "roll", "yaw"}
local creepage_step = {xi = 2e-6, eta = 2e-6, phi = 2e-4}
local pose_step = {y = 1e-6, z = 1e-7, roll = 1e-6, yaw = 1e-6}
local tol = 0.01

local function wrench(c)
  local w = c.left
  return {w.force.x, w.force.y, w.force.z, w.moment.x, w.moment.y, w.moment.z}
end

local function copy(t)
  local o = {}
  for k, v in pairs(t) do o[k] = v end
  return o
end

-- The call at a pose and creepages; `rolling` false: frictionless.
local function call(pose, creepage, method, sensitivity, rolling)
  local args = copy(pose)
  if rolling ~= false then
    args.mu, args.method, args.rolling_tolerance = 0.3, method, 1e-9
    if creepage.V then args.V, args.vy = creepage.V, creepage.vy else args.creepage = creepage end
  end
  args.sensitivity = sensitivity
  return ws:contact(args)
end

-- The central quotient of the wrenches fp, fm at +-h around f0, the forward and backward ones, and whether those two
-- agree within `share` of tol times each block's (forces, moments) scale.
local function quotients(fp, fm, f0, h, share)
  local d, fwd, bwd = {}, {}, {}
  for i = 1, 6 do
    d[i] = (fp[i] - fm[i]) / (2 * h)
    fwd[i] = (fp[i] - f0[i]) / h
    bwd[i] = (f0[i] - fm[i]) / h
  end
  local ok = true
  for _, rows in ipairs{{1, 2, 3}, {4, 5, 6}} do
    local scale = 0
    for _, i in ipairs(rows) do scale = math.max(scale, math.abs(d[i])) end
    for _, i in ipairs(rows) do ok = ok and math.abs(fwd[i] - bwd[i]) <= share * tol * scale end
  end
  return d, ok, fwd, bwd
end

-- Central difference of a column with its one-sided check; nil and the last forward and backward quotients when they
-- never agree (a kink at the pose itself).
local function difference(pose, creepage, method, col, f0)
  local h = creepage_step[col] or pose_step[col]
  local last
  for _ = 1, 8 do
    local p, m, cp, cm = copy(pose), copy(pose), copy(creepage), copy(creepage)
    if creepage_step[col] and creepage.V then return nil, nil  -- kinematics: no creepage of their own to vary
    elseif creepage_step[col] then cp[col], cm[col] = creepage[col] + h, creepage[col] - h
    else p[col], m[col] = pose[col] + h, pose[col] - h end
    local d, ok, fwd, bwd = quotients(wrench(call(p, cp, method)), wrench(call(m, cm, method)), f0, h, 0.1)
    if ok then return d end
    h = h / 2
    last = {fwd, bwd}
  end
  return nil, last
end

-- Largest error of J's column against d, relative to the column's scale (forces and moments apart).
local function column_error(J, d)
  local worst = 0
  for _, rows in ipairs{{1, 2, 3}, {4, 5, 6}} do
    local scale = 0
    for _, i in ipairs(rows) do scale = math.max(scale, math.abs(d[i])) end
    for _, i in ipairs(rows) do
      if scale > 0 then worst = math.max(worst, math.abs(J[i] - d[i]) / scale) end
    end
  end
  return worst
end

local cases = {
  {name = "partial slip", creepage = {xi = 1e-3, eta = 0.5e-3, phi = 0.2}},
  {name = "near saturation", creepage = {xi = 3e-3, eta = 2e-3, phi = 0.2}},
  -- the wheelset's kinematics (pure rolling at r0, a lateral velocity): the creepages follow the pose
  {name = "kinematics", creepage = {V = 30, vy = 0.03}},
}
for _, y in ipairs{0, 3e-3, 6.5e-3} do
  local e = ws:equilibrium{y = y, Q = 200e3}
  local pose = {y = y, z = e.z, roll = e.roll, yaw = 0}
  for _, method in ipairs{"exact", "fastsim"} do
    for _, case in ipairs(cases) do
      local name = ("y = %.1f mm, %s, %s"):format(y * 1e3, method, case.name)
      local c = call(pose, case.creepage, method, true)
      local J, f0 = c.left.jacobian, wrench(c)
      local normal_only = call(pose, case.creepage, method, true, false).left.jacobian
      local adhesion = c.left.patches[1].adhesion
      local worst, wrong = 0, 0
      for _, col in ipairs(columns) do
        local d, sides = difference(pose, case.creepage, method, col, f0)
        if not d and not sides then goto next_column end
        if not d then
          -- The split or contact set changes at the pose itself: the Jacobian (of the solution's own split) is one
          -- of the one-sided derivatives.
          local ef, eb = column_error(J[col], sides[1]), column_error(J[col], sides[2])
          print(("%s: column %s at a kink, one-sided errors %.3g %% and %.3g %%"):format(name, col, ef * 100, eb * 100))
          d = ef < eb and sides[1] or sides[2]
        end
        do
          local err = column_error(J[col], d)
          worst = math.max(worst, err)
          if not creepage_step[col] then wrong = math.max(wrong, column_error(normal_only[col], d)) end
          check.ok(err <= tol, ("%s: column %s within %g %% of its scale (%.3g %%)"):format(name, col, tol * 100, err * 100))
        end
        ::next_column::
      end
      print(("%s: adhesion %.2f, worst %.3f %%, the normal part alone %.2f %%"):format(name, adhesion, worst * 100,
                                                                                     wrong * 100))
      check.ok(wrong > tol, name .. ": the normal problem's part alone fails the same check")
    end
  end
end

-- ws:wheel (Fz prescribed, z solved): jacobian_fz, the Jacobian with Fz held, against differences of ws:wheel itself
-- (force_tolerance 1e-8: the solved z's own error then changes the forces by far less than the differences); its
-- column z is d(.)/dFz, dFz/dFz = 1. Step 10 N (1e-4 of Fz): at the flange root (here a 60 deg contact, the wheel
-- lighter than in the equilibrium) the forces bend with Fz, and the differences at 30 and 100 N are 3 % apart from
-- the 10 N one, which they approach.
for _, y in ipairs{3e-3, 6.5e-3} do
  local e = ws:equilibrium{y = y, Q = 200e3}
  local creepage = {xi = 1e-3, eta = 0.5e-3, phi = 0.2}
  local base = {side = "left", y = y, roll = e.roll, yaw = 0, Fz = 100e3, creepage = creepage, mu = 0.3,
                rolling_tolerance = 1e-9, force_tolerance = 1e-8}
  local args = copy(base)
  args.sensitivity = true
  local J = ws:wheel(args).jacobian_fz
  local steps = {xi = 2e-6, phi = 2e-4, y = 1e-6, roll = 1e-6, yaw = 1e-6, z = 10}
  for _, col in ipairs{"xi", "phi", "y", "roll", "yaw", "z"} do
    local p, m = copy(base), copy(base)
    local h = steps[col]
    if creepage[col] then
      p.creepage, m.creepage = copy(creepage), copy(creepage)
      p.creepage[col], m.creepage[col] = creepage[col] + h, creepage[col] - h
    else
      local key = col == "z" and "Fz" or col
      p[key], m[key] = base[key] + h, base[key] - h
    end
    -- Halved while the forward and backward quotients disagree, as for ws:contact above (the flange root's split and
    -- contact set change at discrete elements); at a kink at the pose itself, the nearer one-sided quotient.
    local function at(args)
      local w = ws:wheel(args)
      return {w.force.x, w.force.y, w.force.z, w.moment.x, w.moment.y, w.moment.z}
    end
    local f0, d, sides = at(base), nil, nil
    for _ = 1, 5 do
      local ok, fwd, bwd
      d, ok, fwd, bwd = quotients(at(p), at(m), f0, h, 0.5)
      if ok or col == "z" or creepage[col] then sides = nil break end
      sides = {fwd, bwd}
      h = h / 2
      p[col], m[col] = base[col] + h, base[col] - h
    end
    if sides then
      local ef, eb = column_error(J[col], sides[1]), column_error(J[col], sides[2])
      print(("ws:wheel y = %.1f mm: column %s at a kink, one-sided errors %.3g %% and %.3g %%"):format(y * 1e3, col,
                                                                                                   ef * 100, eb * 100))
      d = ef < eb and sides[1] or sides[2]
    end
    local err = column_error(J[col], d)
    check.ok(err <= tol, ("ws:wheel y = %.1f mm: jacobian_fz column %s within 1 %% (%.3g %%)"):format(y * 1e3, col,
                                                                                                  err * 100))
  end
  check.rel(J.z[3], 1, 1e-9, "ws:wheel: dFz/dFz = 1")
end

-- The trajectories give the same Jacobians (their steps at the trajectory's tolerances).
do
  local e = ws:equilibrium{y = 3e-3, Q = 200e3}
  local pose = {y = 3e-3, z = e.z, roll = e.roll, yaw = 0}
  local creepage = {xi = 1e-3, eta = 0.5e-3, phi = 0.2}
  local J = call(pose, creepage, "exact", true).left.jacobian
  local tr = ws:trajectory{}
  local args = copy(pose)
  args.creepage, args.mu, args.sensitivity = creepage, 0.3, true
  local T = tr:contact(args).left.jacobian
  for _, col in ipairs(columns) do
    check.ok(column_error(T[col], J[col]) <= tol, "tr:contact: jacobian column " .. col .. " as ws:contact's")
  end
  local w = tr:wheel{side = "left", y = 3e-3, roll = e.roll, Fz = 100e3, creepage = creepage, mu = 0.3, sensitivity = true}
  check.ok(w.jacobian ~= nil and w.jacobian_fz ~= nil and math.abs(w.jacobian_fz.z[3] - 1) < 1e-9,
           "tr:wheel: jacobian and jacobian_fz")
  check.ok(ws:contact(pose).left.jacobian == nil, "no jacobian without sensitivity")
end

-- Friction falling with the slip velocity is not linearised: an error naming the law, not a wrong Jacobian.
do
  local ok, err = pcall(function()
    return ws:contact{y = 0, z = -0.1e-3, roll = 0, creepage = {xi = 1e-3}, V = 30, friction = {preset = "polach_dry"},
                      sensitivity = true}
  end)
  check.ok(not ok and tostring(err):find("polach friction law falls with the slip velocity", 1, true) ~= nil,
           "a falling friction law with sensitivity: " .. tostring(err))
end
