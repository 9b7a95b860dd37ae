-- ws:trajectory{...}: a wheelset followed along time steps, each warm-started from the previous one. S1002 on
-- 60E1, grid 0.5 mm. Along a hunting-like motion (y = 4 mm sin, yaw following, 2 ms steps):
--   - every step's contact forces and moments equal those of a cold ws:contact at the same pose (tolerance 1e-8)
--     within what the trajectory's tolerance (1e-6 of the gap) allows: 1e-5 of the wheel's force, from starts
--     extrapolated from the last two steps (the default) and from the last step alone; the extrapolated starts
--     need fewer CG iterations (here 373 against 414: a start that ignored the step before would not);
--   - tr:wheel{Fz =} finds the height ws:wheel finds, within 1e-9 m (Fz within 1e-6 relative, stiffness > 1e9 N/m),
--     and meets the force tolerance at every step of a 1 kHz hunting motion; its approach is measured from the
--     height at which the wheel just touches (ws:rigid, roll fixed);
--   - with the rolling keys, every step's creep forces equal those of the cold call with the same keys;
--   - reset() forgets the previous steps; bad options are errors.
local check = require "wrc.check"

local ws = wrc.wheelset{wheel = wrc.profile.load(wrc.paths.profiles .. "/s1002.lua"),
                        rail = wrc.profile.load(wrc.paths.profiles .. "/60e1.lua"), grid = 0.5e-3}
local e0 = ws:equilibrium{y = 0, Q = 200e3}
local worst, iterations, tr = 0, {}, nil
for _, extrapolate in ipairs{true, false} do
  tr = ws:trajectory{extrapolate = extrapolate}
  iterations[extrapolate] = 0
  for k = 0, 24 do
    local t = k * 2e-3
    local y = 4e-3 * math.sin(2 * math.pi * 1.5 * t)
    local pose = {y = y, z = e0.z - 0.01e-3 + 0.02 * y * y, roll = 0.05 * y, yaw = -1e-3 * math.cos(2 * math.pi * 1.5 * t)}
    local a = tr:contact(pose)
    local b = ws:contact{y = pose.y, z = pose.z, roll = pose.roll, yaw = pose.yaw, grids = false}
    for _, side in ipairs{"left", "right"} do
      local scale = math.max(1, math.abs(b[side].force.z))
      check.ok(#a[side].patches == #b[side].patches, ("step %d, %s: the same contact areas"):format(k, side))
      for _, p in ipairs(a[side].patches) do iterations[extrapolate] = iterations[extrapolate] + p.iterations end
      for _, c in ipairs{"x", "y", "z"} do
        local d = math.abs(a[side].force[c] - b[side].force[c]) / scale
        worst = math.max(worst, d)
        check.ok(d <= 1e-5, ("extrapolate = %s, step %d, %s: force %s %.9g against %.9g"):format(
                 tostring(extrapolate), k, side, c, a[side].force[c], b[side].force[c]))
        check.near(a[side].moment[c], b[side].moment[c], 1e-5 * scale, ("step %d, %s: moment %s"):format(k, side, c))
      end
    end
  end
end
print(("trajectory: CG iterations over 25 steps %d from extrapolated starts, %d from the last step"):format(
      iterations[true], iterations[false]))
check.ok(iterations[true] < 0.95 * iterations[false], "extrapolated starts save CG iterations")
print(("trajectory: largest force difference to cold evaluations %.2g of the wheel's force"):format(worst))

-- One wheel with Fz given along the steps.
tr:reset()
for k = 0, 4 do
  local y = 1e-3 * k
  local a = tr:wheel{side = "left", y = y, Fz = 100e3}
  local b = ws:wheel{side = "left", y = y, Fz = 100e3}
  check.ok(a.converged, "trajectory wheel converged")
  check.near(a.force.z, 100e3, 1e-6 * 100e3, "trajectory wheel: Fz")
  check.near(a.z, b.z, 1e-9, ("trajectory wheel at y = %g mm: z as ws:wheel"):format(y * 1e3))
  -- the approach: below the height at which the undeformed wheel just touches (ws:rigid with the roll fixed)
  local r = ws:rigid{y = y, roll = 0}
  check.near(b.approach, r.left.z - b.z, 1e-10, ("ws:wheel at y = %g mm: approach below the touching height"):format(y * 1e3))
end

-- Both wheels with Fz given along a hunting motion at 1 kHz (y = 5 mm sin 1.5 Hz, yaw following): every step
-- converges to the force tolerance (1e-6). The trajectory's normal solves are only good to ~1e-6 themselves: without
-- solving 10x tighter once a step is within that noise, some steps wandered there until max_iterations (5 of 2000).
tr = ws:trajectory{}
local evaluations, steps = 0, 300
for k = 0, steps - 1 do
  local t = k * 1e-3
  local y = 5e-3 * math.sin(2 * math.pi * 1.5 * t)
  local yaw = -5e-3 * 2 * math.pi * 1.5 / (100 / 3.6) * math.cos(2 * math.pi * 1.5 * t)
  for _, side in ipairs{"left", "right"} do
    local ok, w = pcall(tr.wheel, tr, {side = side, y = y, yaw = yaw, Fz = 100e3})
    check.ok(ok and w.converged, ("hunting step %d, %s wheel converged%s"):format(k, side, ok and "" or ": " .. tostring(w)))
    if ok then
      check.near(w.force.z, 100e3, 1e-6 * 100e3, ("hunting step %d, %s wheel: Fz"):format(k, side))
      evaluations = evaluations + w.iterations
    end
  end
end
print(("trajectory: tr:wheel along the hunting motion, %.2f evaluations per wheel and step"):format(evaluations / (2 * steps)))

-- Rolling along the steps: the rolling keys of ws:contact / ws:wheel at every step (the velocities of a multibody
-- code change from step to step). The creep forces equal those of a cold call with the same keys, within the
-- trajectory's tolerance; tr:wheel's Fz includes the creep forces' vertical part, as ws:wheel's does.
tr = ws:trajectory{}
for k = 0, 4 do
  local y, V = 0.8e-3 * k, 100 / 3.6
  local keys = {V = V, vy = 0.02 * (k - 2), yaw_rate = 0.01, mu = 0.3, method = k % 2 == 0 and "exact" or "fastsim"}
  local pose = {y = y, z = e0.z - 0.01e-3 + 0.02 * y * y, roll = 0.05 * y, yaw = -1e-3}
  local function with(t) for key, v in pairs(keys) do t[key] = v end return t end
  local a = tr:contact(with{y = pose.y, z = pose.z, roll = pose.roll, yaw = pose.yaw})
  local b = ws:contact(with{y = pose.y, z = pose.z, roll = pose.roll, yaw = pose.yaw, grids = false})
  for _, side in ipairs{"left", "right"} do
    local scale = 0.3 * b[side].force.z
    for _, c in ipairs{"x", "y", "z"} do
      check.near(a[side].creep_force[c], b[side].creep_force[c], 1e-4 * scale,
                 ("rolling step %d (%s), %s: creep force %s"):format(k, keys.method, side, c))
    end
  end
  local wa = tr:wheel(with{side = "left", y = y, yaw = -1e-3, Fz = 100e3})
  local wb = ws:wheel(with{side = "left", y = y, yaw = -1e-3, Fz = 100e3})
  check.near(wa.force.z, 100e3, 1e-6 * 100e3, ("rolling step %d: tr:wheel Fz with the creep forces"):format(k))
  check.near(wa.z, wb.z, 1e-8, ("rolling step %d: tr:wheel height as ws:wheel's"):format(k))
  check.near(wa.creep_force.y, wb.creep_force.y, 1e-4 * 30e3, ("rolling step %d: tr:wheel lateral creep force"):format(k))
end
check.fails(function() tr:contact{y = 0, z = e0.z, mu = 0.3} end, "neither V", "friction without V or creepage")
check.fails(function() tr:wheel{side = "left", y = 0, Fz = 100e3, V = 0, mu = 0.3} end, "V", "V = 0")

check.fails(function() ws:trajectory{tolerence = 1e-6} end, "did you mean 'tolerance'", "misspelt option")
check.fails(function() ws:trajectory{extrapolate = 1} end, "extrapolate", "extrapolate must be a boolean")
check.fails(function() ws:trajectory{tolerance = 0.5} end, "tolerance must be in", "tolerance out of range")
check.fails(function() tr:contact{y = 0 / 0} end, "'y' must be finite", "NaN pose")
