-- One step of the wear loop (scripts/wear_loop.lua) with the example's default cases (examples/wear_evolution.lua: 90
-- on tangent track, 5 lateral forces (60 .. 100 kN) in a 300 m curve each way: 100 cases), S1002/60E1 at 0.2 mm, exact rolling with
-- Archard/KTH: the time to place the curving cases, of one rate evaluation (the cases solved and mapped: an Euler
-- step), of a Heun step (two), and of the next Heun step with and without each case started from its equilibrium and
-- its exact tangential solution of the step before, CPU (all threads) and wall.
--   build/wrc run tests/bench/bench_wear_step.lua [grid_mm=0.2] [method=exact] [threads=2] [tangent=90] [spin=free]
local loop = require "wrc.wear_loop"
local grid = (tonumber(arg.grid_mm) or 0.2) * 1e-3
local threads = tonumber(arg.threads) or 2
local tangent = tonumber(arg.tangent) or 90
local function wall()
  local p = io.popen("date +%s.%N")
  local t = tonumber(p:read("l"))
  p:close()
  return t
end
local st = loop.initial{wheel = wrc.profile.load("profiles/s1002.lua"), rail = wrc.profile.load("profiles/60e1.lua"),
                        wheelset = {grid = grid}}
local cases = dofile((arg[0]:match("(.*/)") or "./") .. "wear_cases.lua")(grid, tangent)
local function timed(what, f)
  local c, w = os.clock(), wall()
  local r = f()
  print(("%-44s cpu %7.2f s   wall %7.2f s"):format(what, os.clock() - c, wall() - w))
  return r
end
local list = timed("placing the 10 curving cases (y for Y)", function() return cases(st) end)
print(("%d cases, grid %.2f mm, method %s, %d threads"):format(#list, grid * 1e3, arg.method or "exact", threads))
local o = {step = 0.1e-3, smooth = 1e-3, wear = {}, threads = threads, method = arg.method, spin = arg.spin}
timed("one Euler step (the cases placed before)", function() o.scheme = "euler"; return loop.step(st, list, o) end)
local st1 = timed("one Heun step (placing the cases twice)", function() o.scheme = "heun"; return loop.step(st, cases, o) end)
-- The steps after the first: every case from its equilibrium and its exact tangential solution on the profiles before
-- (the default), from its equilibrium alone (warm = "equilibrium"), from neither (warm = false).
timed("the next Heun step (cases from the step before)", function() return loop.step(st1, cases, o) end)
o.warm = "equilibrium"
timed("the same from the equilibria alone", function() return loop.step(st1, cases, o) end)
o.warm = false
timed("the same without those starts (warm = false)", function() return loop.step(st1, cases, o) end)
