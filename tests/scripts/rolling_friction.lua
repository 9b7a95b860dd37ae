-- Friction as engineers specify it, through the Lua API (docs/guide/rolling.md): S1002 on 60E1, 0.5 mm elements.
--   - a falling law (friction = {law = ...} or a preset): at small creepage the forces of constant friction mu0; in
--     full sliding (large creepage, no spin: every element slides at w = V xi up to the elastic slip) |Fx| = mu(w) N
--     with mu(w) written out here, by the exact solver and FASTSIM, on the tread and on the flange root;
--   - friction across the rail's profile (friction_profile, per wheel): a lubricated gauge face gives the flange
--     contact the lubricated friction and leaves the tread's (each checked against a run with that friction
--     throughout), a profile given for the left rail leaves the right wheel's; a function of y works as its table;
--   - a sweep with a falling law; bad input: clear errors naming the key.
local check = require "wrc.check"

local wheel = wrc.profile.load(wrc.paths.profiles .. "/s1002.lua")
local rail = wrc.profile.load(wrc.paths.profiles .. "/60e1.lua")
local ws = wrc.wheelset{wheel = wheel, rail = rail, grid = 0.5e-3}

local e0 = ws:equilibrium{y = 0, yaw = 0, Q = 200e3}
local e6 = ws:equilibrium{y = 6.5e-3, yaw = 0, Q = 200e3}  -- the left flange only
local function at(e, extra)
  local t = {y = e.y, z = e.z, roll = e.roll, yaw = e.yaw}
  for k, v in pairs(extra) do t[k] = v end
  return t
end
local function polach(mu0, A, B, w) return mu0 * ((1 - A) * math.exp(-B * w) + A) end
local function sum_p(p)  -- sum p dA of an area's pressure grid
  local s = 0
  for _, row in ipairs(p.pressure) do for _, v in ipairs(row) do s = s + v end end
  return s * p.grid.dx * p.grid.dy
end

-- Small creepage: the falling law's forces are constant mu0's; full sliding: mu(V xi) sum p dA.
for _, method in ipairs{"exact", "fastsim"} do
  for _, e in ipairs{e0, e6} do
    local name = method .. " at y = " .. e.y * 1e3 .. " mm"
    local law = {law = "polach", mu0 = 0.4, A = 0.4, B = 0.6}
    local small = ws:contact(at(e, {creepage = {xi = 2e-5}, V = 30, friction = law, method = method})).left.patches[1]
    local const = ws:contact(at(e, {creepage = {xi = 2e-5}, V = 30, mu = 0.4, method = method})).left.patches[1]
    check.rel(small.Fx, const.Fx, 1e-4, name .. ": small creepage as constant mu0")
    check.ok(small.friction_law == "polach" and small.mu.static == 0.4, name .. ": the law reported")
    for _, V in ipairs{10, 30} do
      local xi = 0.05
      local p = ws:contact(at(e, {creepage = {xi = xi}, V = V, friction = law, method = method})).left.patches[1]
      -- (FASTSIM on the flange root: 1.1 % above at 30 m/s where the exact theory is within 0.07 %: its simplified
      -- elasticity, not the law)
      local tol = (method == "fastsim" and e == e6) and 0.015 or 0.01
      check.rel(-p.Fx, polach(0.4, 0.4, 0.6, V * xi) * sum_p(p), tol, name .. ", V = " .. V .. ": full sliding")
    end
    -- CONTACT's rational law, two terms: mu(w) = 0.15 + 0.1 / (1 + w / 0.3) + 0.1 / (1 + (w / 0.4)^2) at w = 2 m/s
    -- (at 1 m/s, where it falls 8 %/(m/s), FASTSIM's layer slip on the flange root lowers w enough for 1.4 %)
    local p = ws:contact(at(e, {creepage = {xi = 0.05}, V = 40, method = method,
                                friction = {law = "rational", mu_inf = 0.15, m1 = 0.1, s1 = 0.3, m2 = 0.1, s2 = 0.4}}))
    p = p.left.patches[1]
    check.rel(-p.Fx, (0.15 + 0.1 / (1 + 2 / 0.3) + 0.1 / (1 + (2 / 0.4) ^ 2)) * sum_p(p), 0.01,
              name .. ": rational law in full sliding")
  end
end

-- A preset is Polach's law with its parameters.
do
  local a = ws:contact(at(e0, {creepage = {xi = 3e-3}, V = 30, friction = {preset = "polach_dry"}})).left.patches[1]
  local b = ws:contact(at(e0, {creepage = {xi = 3e-3}, V = 30,
                               friction = {law = "polach", mu0 = 0.55, A = 0.4, B = 0.6}})).left.patches[1]
  check.near(a.Fx, b.Fx, 1e-9 * math.abs(b.Fx), "preset polach_dry = mu0 0.55, A 0.4, B 0.6")
end

-- Friction across the rail's profile: a lubricated gauge face (mu 0.1 below y = -25 mm of the rail's profile,
-- 0.4 from -15 mm on), given for the left rail.
local gauge = {left = {y = {-0.025, -0.015}, mu = {0.1, 0.4}}}
for _, method in ipairs{"exact", "fastsim"} do
  for _, case in ipairs{{e6, 0.1, "flange"}, {e0, 0.4, "tread"}} do
    local e, mu, name = case[1], case[2], method .. " " .. case[3]
    for _, xi in ipairs{1e-3, 0.05} do
      local c = ws:contact(at(e, {creepage = {xi = xi}, V = 20, mu = 0.3, friction_profile = gauge, method = method}))
      local ref = ws:contact(at(e, {creepage = {xi = xi}, V = 20, mu = mu, method = method}))
      check.rel(c.left.patches[1].Fx, ref.left.patches[1].Fx, 1e-6, name .. ": the zone's friction, xi = " .. xi)
      for i, p in ipairs(c.right.patches) do  -- no profile for the right rail: mu = 0.3
        check.rel(p.Fx, ws:contact(at(e, {creepage = {xi = xi}, V = 20, mu = 0.3, method = method})).right.patches[i].Fx,
                  1e-9, name .. ": the right wheel keeps mu")
      end
    end
  end
  -- a function of the rail's y, sampled, is the table's piecewise-linear profile
  local f = function(y) return y < -0.02 and 0.1 or 0.4 end
  local a = ws:contact(at(e6, {creepage = {xi = 0.05}, V = 20, mu = 0.3, friction_profile = f, method = method}))
  check.rel(a.left.patches[1].Fx, ws:contact(at(e6, {creepage = {xi = 0.05}, V = 20, mu = 0.1, method = method}))
            .left.patches[1].Fx, 1e-6, method .. ": a function as the profile")
end

-- A sweep with a falling law gives its creep forces.
do
  local s = ws:sweep{y = {0, 3e-3}, Q = 200e3, V = 30, friction = {preset = "polach_wet"}, threads = 1,
                     progress = false}
  check.ok(#s == 2, "sweep with a falling law: two cases")
  for _, r in ipairs(s) do
    local c = ws:contact{y = r.y, z = r.z, roll = r.roll, yaw = r.yaw, V = 30, friction = {preset = "polach_wet"},
                         grids = false}
    check.ok(r.converged and r.creep_force ~= nil, "sweep case solved with creep forces")
    check.near(r.creep_force.y, c.creep_force.y, 1e-6 * math.abs(c.creep_force.y) + 1e-3, "sweep = ws:contact")
  end
end

-- Bad input.
do
  local function with(extra) local t = at(e0, extra); return function() return ws:contact(t) end end
  local law = {law = "polach", mu0 = 0.4, A = 0.4, B = 0.6}
  check.fails(with{V = 30, mu = 0.3, friction = law}, "'mu', 'mu_static', 'mu_kinetic' cannot be given", "mu and law")
  check.fails(with{V = 30, friction = {law = "polach", mu0 = 0.4, A = 0.4}}, "needs 'B'", "polach without B")
  check.fails(with{V = 30, friction = {law = "polach", mu0 = 0.4, A = 1.5, B = 1}}, "A = 1.5 must be in", "A > 1")
  check.fails(with{V = 30, friction = {law = "polach", mu0 = 0.4, A = 0.4, B = 0}}, "B = 0 s/m must be > 0", "B = 0")
  check.fails(with{V = 30, friction = {law = "linear", mu_inf = 0.2, m1 = 0.1}}, "needs its velocity s1", "no s1")
  check.fails(with{V = 30, friction = {law = "linear", mu_inf = 0.2, m1 = -0.1, s1 = 1}}, "m1 = -0.1 must be >= 0",
              "m1 < 0")
  check.fails(with{V = 30, friction = {law = "linear", mu_inf = 0.2, A = 0.4}}, "'A' is a coefficient of the polach",
              "a polach key on another law")
  check.fails(with{V = 30, friction = {law = "coulomb"}}, "law", "unknown law")
  check.fails(with{V = 30, friction = {preset = "icy"}}, "preset", "unknown preset")
  check.fails(with{V = 30, friction = {preset = "polach_dry", B = 1}}, "'preset' gives the whole law", "preset + B")
  check.fails(with{creepage = {xi = 1e-3}, friction = law}, "give V (m/s) with the creepages", "falling law, no V")
  check.fails(with{V = 30, mu = 0.3, friction_profile = {y = {0, -0.01}, mu = {0.3, 0.2}}}, "does not increase",
              "profile y decreasing")
  check.fails(with{V = 30, mu = 0.3, friction_profile = {y = {0, 0.01}, mu = {0.3}}}, "'y' has 2 values and 'mu' 1",
              "profile sizes")
  check.fails(with{V = 30, mu = 0.3, friction_profile = {y = {0, 0.01}, mu = {0.3, 0}}}, "the 2nd value of mu (= 0) must be in",
              "profile mu = 0")
  check.fails(with{V = 30, mu = 0.3, friction_profile = function(y) return -1 end}, "friction_profile", "function < 0")
end
print("rolling friction: ok")
