-- The starts of a Heun step's second rate evaluation (scripts/wear_loop.lua, docs/guide/wear.md "Where a step's CPU
-- goes"): the exact tangential solver's products of each rate evaluation of the steps after the first, the second
-- started from the first's tractions (the step before's extrapolation off: its `first_starts` dropped) and from their
-- linear extrapolation with the first evaluation's of the step before (the loop's), and what a perfect start would
-- leave: the second evaluation's cases (an Euler step's profiles) solved again from their own solution. The
-- example's default cases (90 on tangent track, 10 curving) at 0.2 mm, S1002/60E1, exact rolling, Archard/KTH.
--   build/wrc run tests/bench/bench_wear_start.lua [grid_mm=0.2] [steps=4] [threads=2] [tangent=90]
local loop = require "wrc.wear_loop"
local grid = (tonumber(arg.grid_mm) or 0.2) * 1e-3
local steps = tonumber(arg.steps) or 4
local tangent = tonumber(arg.tangent) or 90
local Q = 200e3
local function cases(state, early)
  local ws = loop.wheelset(state, {grid = math.max(grid, 0.5e-3)})  -- as the example places them
  return loop.generated_cases{Q = Q, V = 100 / 3.6, mu = 0.3, tangent = tangent, sigma = 1.5e-3,
                              curves = {{radius = 300, yaw = 2.5e-3, share = 0.05}, {radius = -300, yaw = 2.5e-3,
                              share = 0.05}}, forces = {60e3, 70e3, 80e3, 90e3, 100e3},
                              y_for_force = function(sign, Y, yaw, from, hint) return loop.y_for_force(ws, sign, Y, yaw, Q, from, hint) end,
                              previous = state.previous_cases, early = early}
end
local o = {step = 0.1e-3, smooth = 1e-3, wear = {}, threads = tonumber(arg.threads) or 2}
local euler = setmetatable({scheme = "euler"}, {__index = o})
local function line(what, first, second, c)
  print(("%-44s first %6d   second %6d   cpu %6.2f s"):format(what, first, second, os.clock() - c))
end
local st = loop.step(loop.initial{wheel = wrc.profile.load("profiles/s1002.lua"),
                                  rail = wrc.profile.load("profiles/60e1.lua"), wheelset = {grid = grid}}, cases, o)
for k = 2, steps do
  print(("step %d (from %.3f km)"):format(k, st.km))
  local earlier, c = st.first_starts, os.clock()
  st.first_starts = nil
  local _, a = loop.step(st, cases, o)
  line("  second from the first's tractions", a.products - a.second_products, a.second_products, c)
  st.first_starts, c = earlier, os.clock()
  local predicted, b = loop.step(st, cases, euler)  -- the second evaluation's profiles, the first's starts
  local solved, s = loop.step(predicted, cases, euler)
  line("  the second alone (an Euler step at them)", b.products, s.products, c)
  predicted.starts, predicted.previous_cases, c = solved.starts, solved.previous_cases, os.clock()
  local _, own = loop.step(predicted, cases, euler)
  line("  the second from its own solution", b.products, own.products, c)
  c = os.clock()
  local nxt, h = loop.step(st, cases, o)
  line("  second extrapolated (the loop's)", h.products - h.second_products, h.second_products, c)
  st = nxt
end
