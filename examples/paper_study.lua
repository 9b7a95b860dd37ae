-- The study of Baeza, Thompson, Squicciarini & Denia (2018), section 4: a free, frictionless wheelset with
-- S1002 wheels on 60E1 rails (1:40, gauge 1435 mm at 14 mm, flange backs 1360 mm, r0 = 450 mm), E = 210 GPa,
-- nu = 0.3, Q = 200 kN at the centre; y from -8 to +8 mm in 0.1 mm steps for yaw 0 and 1 degree. z and roll
-- solved (Newton), Y, My and Mz reported; the rigid-contact reference for the same sweep.
--
--   wrc run examples/paper_study.lua [out=results] [step_mm=0.1] [threads=N] [grid_mm=0.2] [plots=true]
--                                    [surface=planar]
--
-- surface: the contact areas on one plane each, as the paper ("planar", the default here), or on the curved
-- surface along the rail's profile ("conformal"); examples/surfaces_study.lua runs both side by side.
--
-- Writes into `out`: sweep.csv (elastic), rigid.csv (rigid reference), the figures of the paper as PNG
-- (fig4_z_roll, fig5_YQ_Mz, fig6_pressure_*, fig7_h_*, fig8_rail_*, rigid_vs_elastic) with their data, and
-- summary.txt (the numbers quoted in the README).
local out = require "wrc.output"
local study = require "wrc.study"

local dir = arg.out or "results"
local step = (arg.step_mm or 0.1) * 1e-3
local ymax = (arg.ymax_mm or 8) * 1e-3
local grid = (arg.grid_mm or 0.2) * 1e-3
local plots = arg.plots ~= "false" and arg.plots ~= false
out.mkdir(dir)

local wheel = wrc.profile.load("profiles/s1002.lua", {step = 0.1e-3})
local rail = wrc.profile.load("profiles/60e1.lua", {step = 0.1e-3})
local ws = wrc.wheelset{
  wheel = wheel, rail = rail,
  radius = 0.45, back_to_back = 1.360, gauge = 1.435, gauge_depth = 0.014, cant = 1 / 40,
  E = 2.1e11, nu = 0.3, grid = grid, surface = arg.surface or "planar",
}
local Q = 200e3

-- The sweep: y in [-ymax, ymax], both yaws, run on the machine's cores with continuation along y.
local ys = {}
local n = math.floor(ymax / step + 0.5)
for i = -n, n do ys[#ys + 1] = i * step end
local yaws = {0, math.rad(1)}
local sweep = ws:sweep{y = ys, yaw = yaws, Q = Q, rigid = true, threads = arg.threads}
print(string.format("sweep: %d cases in %.1f s on %d threads, %d failed", #sweep, sweep.seconds, sweep.threads,
                    sweep.failed))

-- Tables (units in the headers).
local rows, rigid_rows = {}, {}
for _, r in ipairs(sweep) do
  rows[#rows + 1] = study.sweep_row(r)
  rigid_rows[#rigid_rows + 1] = study.rigid_row(r)
end
out.csv(dir .. "/sweep.csv", study.sweep_columns, rows)
out.csv(dir .. "/rigid.csv", study.rigid_columns, rigid_rows)

-- Summary: derailment quotient and contact ranges of the left wheel at yaw 0.
local summary = study.summary(sweep, 0)
local f = assert(io.open(dir .. "/summary.txt", "w"))
f:write(summary)
f:close()
io.write(summary)

if plots then
  study.plot_sweep(dir, sweep, yaws)
  -- Single equilibria with their pressure grids, started from the sweep's neighbouring solution.
  local function equilibrium(y, yaw)
    return ws:equilibrium{y = y, yaw = yaw, Q = Q, start = study.nearest_start(sweep, y, yaw)}
  end
  -- Pressure and h for several lateral positions at yaw 0 (figures 6 and 7).
  for _, y_mm in ipairs{-4, 0, 3, 5, 6, 6.3} do
    study.plot_patches(dir, string.format("y%+.1fmm_yaw0", y_mm), equilibrium(y_mm * 1e-3, 0))
  end
  -- Pressure on the rail surface for the three poses of figure 8.
  for _, c in ipairs{{6.3, 1, "a"}, {0, 0, "b"}, {-6.3, -1, "c"}} do
    study.plot_rail_pressure(dir, "fig8" .. c[3], string.format("y = %.1f mm, yaw = %g deg", c[1], c[2]),
                             equilibrium(c[1] * 1e-3, math.rad(c[2])))
  end
end
print("results in " .. dir)
