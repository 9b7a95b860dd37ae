-- The wear benchmarks' cases (bench_wear_step.lua, bench_wear_start.lua): the example's defaults
-- (examples/wear_evolution.lua): `tangent` cases on tangent track and 5 lateral forces (60 .. 100 kN) in a 300 m curve
-- each way, Q = 200 kN, V = 100 km/h, mu = 0.3; the curving cases placed on a grid of at least 0.5 mm, as the example
-- places them. Returns cases(grid, tangent): the loop's cases function (state, early).
local loop = require "wrc.wear_loop"
local Q = 200e3
return function(grid, tangent)
  return function(state, early)
    local ws = loop.wheelset(state, {grid = math.max(grid, 0.5e-3)})
    return loop.generated_cases{Q = Q, V = 100 / 3.6, mu = 0.3, tangent = tangent, sigma = 1.5e-3,
                                curves = {{radius = 300, yaw = 2.5e-3, share = 0.05}, {radius = -300, yaw = 2.5e-3,
                                share = 0.05}}, forces = {60e3, 70e3, 80e3, 90e3, 100e3},
                                y_for_force = function(sign, Y, yaw, from, hint)
                                  return loop.y_for_force(ws, sign, Y, yaw, Q, from, hint)
                                end,
                                previous = state.previous_cases, early = early}
  end
end
