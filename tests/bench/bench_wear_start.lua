-- The starts of a Heun step's second rate evaluation (scripts/wear_loop.lua; docs/guide/wear.md "Speed", where a
-- step's CPU goes): the exact tangential solver's products of the second evaluation (at the Euler step's profiles
-- P + D) of the steps after the first, started from the first's tractions T(P) (as the loop starts it), from the
-- tractions half a step away T(P + D/2), and from its own solution (what a perfect start would leave: a product per
-- area). The example's default cases (90 on tangent track, 10 curving) at 0.2 mm, S1002/60E1, exact rolling,
-- Archard/KTH.
--   build/wrc run tests/bench/bench_wear_start.lua [grid_mm=0.2] [steps=4] [threads=2] [tangent=90]
local loop = require "wrc.wear_loop"
local grid = (tonumber(arg.grid_mm) or 0.2) * 1e-3
local steps = tonumber(arg.steps) or 4
local tangent = tonumber(arg.tangent) or 90
local cases = dofile((arg[0]:match("(.*/)") or "./") .. "wear_cases.lua")(grid, tangent)
local o = {step = 0.1e-3, smooth = 1e-3, wear = {}, threads = tonumber(arg.threads) or 2}
local euler = setmetatable({scheme = "euler"}, {__index = o})
local half = setmetatable({scheme = "euler", step = o.step / 2}, {__index = o})  -- the same rates, half the distance
-- The products of the cases solved at `state` (its profiles) from `starts` (the loop's by case).
local function solved_from(state, starts)
  state.starts = starts
  local _, info = loop.step(state, cases, euler)
  return info.products
end
local st = loop.step(loop.initial{wheel = wrc.profile.load("profiles/s1002.lua"),
                                  rail = wrc.profile.load("profiles/60e1.lua"), wheelset = {grid = grid}}, cases, o)
for k = 2, steps do
  local predicted, first = loop.step(st, cases, euler)  -- P + D, its starts T(P)
  local mid = loop.step(st, cases, half)                -- P + D/2 (from T(P))
  local at_mid = loop.step(mid, cases, half)            -- its starts: T(P + D/2)
  local at_end, loops = loop.step(predicted, cases, euler)  -- from T(P), as the loop solves it; its starts T(P + D)
  print(("step %d (from %.3f km): the first evaluation %d products; the second"):format(k, st.km, first.products))
  print(("  from T(P), the loop's start                %6d"):format(loops.products))
  print(("  from T(P + D/2)                            %6d"):format(solved_from(predicted, at_mid.starts)))
  print(("  from T(P + D), its own solution            %6d"):format(solved_from(predicted, at_end.starts)))
  st = loop.step(st, cases, o)
end
