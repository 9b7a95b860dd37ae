-- The dense reference solver through the pipeline (docs/guide/normal.md "Cost of the dense solver"): S1002 on 60E1
-- at `grid` (default 0.5 mm), Q = 200 kN, solver = "dense": one equilibrium on the tread (y = 0) and one on the
-- flange (y = 7.8 mm), then ws:sweep of 27 equilibria from y = -7.8 to 7.8 mm on one thread. Each Newton step's
-- evaluations start from the last one's pressures, so their active sets gain and lose elements. Prints the CPU
-- seconds (os.clock) and the evaluations of each.
--
--   wrc run tests/bench/bench_dense_pipeline.lua [grid_mm=0.5]
local grid = (tonumber(arg.grid_mm) or 0.5) * 1e-3
local ws = wrc.wheelset{wheel = wrc.profile.load(wrc.paths.profiles .. "/s1002.lua"),
                        rail = wrc.profile.load(wrc.paths.profiles .. "/60e1.lua"), grid = grid, solver = "dense"}
print(("S1002 / 60E1, grid %.2f mm, Q = 200 kN, solver = dense; CPU s"):format(grid * 1e3))
for _, y in ipairs{0, 7.8e-3} do
  local t0 = os.clock()
  local e = ws:equilibrium{y = y, yaw = 0, Q = 200e3, grids = false}
  print(("equilibrium y = %.1f mm: %.2f s, %d evaluations, converged %s"):format(y * 1e3, os.clock() - t0,
                                                                               e.evaluations, tostring(e.converged)))
end
local t0 = os.clock()
local s = ws:sweep{y = {from = -7.8e-3, to = 7.8e-3, step = 0.6e-3}, yaw = {0}, Q = 200e3, threads = 1}
local evaluations = 0
for i = 1, #s do evaluations = evaluations + s[i].evaluations end
print(("sweep of %d equilibria (one thread): %.2f s, %d evaluations, %d failed"):format(#s, os.clock() - t0,
                                                                                    evaluations, s.failed))
