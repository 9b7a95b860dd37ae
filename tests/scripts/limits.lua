-- Limits that used to fail late or wrongly (issue 14):
--  - max_elements is a wheelset option whose default (2^22) lets the paper's poses be solved down to grid = 0.02 mm:
--    the potential contact areas of a coarse paper sweep, scaled to 0.02 mm, fit it (2^20, the old cap, did not fit
--    the y = 0 wheel at 100 kN); a grid too fine for the cap is refused when the wheelset is built, with the elements
--    the centred wheelset needs -- the same count a solve at that pose grids -- and at a solve, the message says
--    whether the grid is too fine for the cap or the pose far too deep;
--  - hopeless loads (Q = 1e9 N, Fz = 1e9 N) stop after a few evaluations with "out of reach", heavy but real ones
--    converge;
--  - a sweep asked for more threads than it can use says so (s.threads_note).
local check = require "wrc.check"

local wheel = wrc.profile.load(wrc.paths.profiles .. "/s1002.lua")
local rail = wrc.profile.load(wrc.paths.profiles .. "/60e1.lua")

-- ---- max_elements ----
check.ok(wrc.defaults.wheelset.max_elements == 4194304, "max_elements defaults to 2^22")
local ws = wrc.wheelset{wheel = wheel, rail = rail, grid = 0.5e-3}
local margin = ws.params.margin
local c = ws:contact{y = 0, z = -0.1e-3}
local n = 0
for _, side in ipairs{"left", "right"} do
  for _, p in ipairs(c[side].patches) do n = math.max(n, p.grid.nx * p.grid.ny) end
end
check.ok(n > 0, "contact at the reference pose")
local err = check.fails(function() wrc.wheelset{wheel = wheel, rail = rail, grid = 0.5e-3, max_elements = n - 1} end,
                        "is too fine for max_elements = " .. (n - 1), "a cap below the centred wheelset's area")
check.ok(err:find("needs " .. n .. " elements", 1, true), "the estimate is the grid a solve makes there: " .. err)
check.ok(err:find("MB", 1, true), "the message gives the memory")
local capped = wrc.wheelset{wheel = wheel, rail = rail, grid = 0.5e-3, max_elements = n}
err = check.fails(function() capped:contact{y = 0, z = -0.2e-3} end, "is too fine for the cap", "a deeper pose, too fine")
check.ok(err:find("more than max_elements = " .. n, 1, true), err)
-- A pose 3 mm deep is refused by max_penetration (1 mm) before it is gridded; allowed deeper, the cap names the depth.
check.fails(function() capped:contact{y = 0, z = -3e-3} end, "more than max_penetration = 1 mm", "a pose 3 mm deep")
err = check.fails(function() capped:contact{y = 0, z = -3e-3, max_penetration = 5e-3} end, "the pose is far too deep",
                  "a pose 3 mm deep, max_penetration = 5 mm")
check.fails(function() wrc.wheelset{wheel = wheel, rail = rail, grid = 0.01e-3} end, "is too fine for max_elements",
            "grid = 0.01 mm with the default cap")
check.ok(wrc.wheelset{wheel = wheel, rail = rail, grid = 0.02e-3}, "grid = 0.02 mm builds with the default cap")

-- The paper's poses at grid = 0.02 mm: each potential area's extent from a 0.5 mm sweep (without its margin), in
-- 0.02 mm elements plus the margin; the largest must fit the default cap, and did not fit the old 2^20 at y = 0.
local s = ws:sweep{y = {from = -8e-3, to = 8e-3, step = 1e-3}, yaw = {0, math.rad(1)}, Q = 200e3, progress = false}
local worst, at_centre = 0, 0
local e = 0.02e-3
for _, r in ipairs(s) do
  check.ok(r.converged, "sweep row")
  for _, side in ipairs{"left", "right"} do
    for _, p in ipairs(r[side].patches) do
      local lx, ly = (p.grid.nx - 2 * margin) * p.grid.dx, (p.grid.ny - 2 * margin) * p.grid.dy
      local fine = (math.ceil(lx / e) + 2 * margin + 1) * (math.ceil(ly / e) + 2 * margin + 1)
      worst = math.max(worst, fine)
      if r.y == 0 and r.yaw == 0 then at_centre = math.max(at_centre, fine) end
    end
  end
end
check.ok(worst < 4194304, ("the paper's largest area at 0.02 mm: %d elements, within 2^22"):format(worst))
print(("largest potential area of the paper's poses at 0.02 mm: %d elements (y = 0: %d)"):format(worst, at_centre))
check.ok(at_centre > 1048576 * 0.9, ("y = 0 at 0.02 mm: ~%d elements, about the old cap 2^20"):format(at_centre))

-- ---- hopeless loads ----
-- (check_setup = false: with it, loads beyond 2 MN per wheelset are refused at the call as implausible, before the
-- solve; the solvers' own stop is tested here.)
local coarse = wrc.wheelset{wheel = wheel, rail = rail, grid = 1e-3, check_setup = false}
local q = coarse:equilibrium{y = 0, Q = 1e9, on_failure = "return"}
check.ok(not q.converged and q.error:find("the load is out of reach: Q = 1e+09 N", 1, true), tostring(q.error))
check.ok(q.error:find("(max_penetration = 1 mm) and still carry only", 1, true), q.error)
check.ok(q.evaluations <= 12, ("Q = 1e9 N stops after %d evaluations"):format(q.evaluations))
local w = coarse:wheel{side = "left", y = 0, Fz = 1e9, on_failure = "return"}
check.ok(not w.converged and w.error:find("the load is out of reach: Fz = 1e+09 N", 1, true), tostring(w.error))
check.ok(w.iterations <= 4, ("Fz = 1e9 N stops after %d iterations"):format(w.iterations))
check.fails(function() coarse:wheel{side = "left", y = 0, Fz = 1e9} end, "out of reach", "an error by default")
local q7 = coarse:equilibrium{y = 7e-3, Q = 1e8, on_failure = "return"}
check.ok(not q7.converged and q7.error:find("out of reach", 1, true) and q7.evaluations <= 12, "Q = 1e8 N at y = 7 mm")
-- Heavy but reachable: 1 MN per wheel converges (residuals within the tolerance), less than 1 mm deep.
local heavy = coarse:equilibrium{y = 3e-3, Q = 2e6}
check.ok(math.abs(heavy.residual.force) <= 1e-6 * 2e6, "Q = 2 MN converges")
for _, p in ipairs(heavy.left.patches) do check.ok(p.penetration < 1e-3, "and stays within 1 mm") end
-- The limit is an option: 0.05 mm is less than the 0.075 mm the paper's wheels need at 100 kN each.
local low = coarse:equilibrium{y = 0, Q = 200e3, max_penetration = 0.05e-3, on_failure = "return"}
check.ok(not low.converged and low.error:find("max_penetration = 0.05 mm", 1, true), tostring(low.error))
check.ok(coarse:equilibrium{y = 0, Q = 200e3, max_penetration = 0.1e-3}.converged, "0.1 mm is enough for 200 kN")
check.fails(function() coarse:equilibrium{y = 0, Q = 200e3, max_penetration = 0} end, "max_penetration", "zero limit")

-- ---- thread counts ----
local r = coarse:sweep{y = {0, 1e-3, 2e-3}, Q = 200e3, threads = 8, progress = false}
check.ok(r.threads == 1 and r.threads_note and r.threads_note:find("threads = 8 asked for, 1 used", 1, true),
         "one chain: " .. tostring(r.threads_note))
r = coarse:sweep{y = {-1e-3, 0, 1e-3}, yaw = {0, 0.01}, Q = 200e3, threads = 8, progress = false}
check.ok(r.threads == 4 and r.threads_note:find("the sweep has 4 chunks", 1, true), tostring(r.threads_note))
r = coarse:sweep{y = {-1e-3, 0, 1e-3}, Q = 200e3, threads = 2, progress = false}
check.ok(r.threads == 2 and r.threads_note == nil, "as asked: no note")
local inline = wrc.wheelset{wheel = wheel, rail = rail, grid = 1e-3, strategy = {locate = function(ctx, side) ctx:walk(side) end}}
r = inline:sweep{y = {0, 1e-3}, Q = 200e3, threads = 2, progress = false}
check.ok(r.threads == 1 and r.threads_note:find("inline Lua table", 1, true), tostring(r.threads_note))
local t = coarse:geometry_table{y = {from = 0, to = 1e-3, step = 0.1e-3}, threads = 4, progress = false}
check.ok(t.threads == 1 and t.threads_note and t.threads_note:find("threads = 4 asked for, 1 used: 11 rows", 1, true),
         "geometry table: " .. tostring(t.threads_note))
check.ok(coarse:geometry_table{y = {0, 1e-3}, threads = 1, progress = false}.threads_note == nil, "as asked: no note")
