-- The study of Baeza, Thompson, Squicciarini & Denia (2018), section 4: a free, frictionless wheelset with
-- S1002 wheels on 60E1 rails (1:40, gauge 1435 mm at 14 mm, flange backs 1360 mm, r0 = 450 mm), E = 210 GPa,
-- nu = 0.3, Q = 200 kN at the centre; y from -8 to +8 mm in 0.1 mm steps for yaw 0 and 1 degree. z and roll
-- solved (Newton), Y, My and Mz reported; the rigid-contact reference for the same sweep.
--
--   wrc run examples/paper_study.lua [out=results] [step_mm=0.1] [threads=N] ... [--shard K/N] [--merge]
--   wrc run examples/paper_study.lua --help            (lists the options)
--
-- surface: the contact areas on one plane each, as the paper ("planar", the default here), or on the curved
-- surface along the rail's profile ("conformal"); examples/surfaces_study.lua runs both side by side.
--
-- Writes into `out`: sweep.csv (elastic), rigid.csv (rigid reference), the figures of the paper as PNG
-- (fig4_z_roll, fig5_YQ_Mz, fig6_pressure_*, fig7_h_*, fig8_rail_*, rigid_vs_elastic) with their data, and
-- summary.txt (the numbers quoted in docs/getting-started.md), all made from the two tables; manifest.txt lists them.
local study = require "wrc.study"
local sweep = require "wrc.sweep"

local s = study.new{
  name = "paper_study",
  help = "Section 4 of Baeza et al. (2018): equilibria of a free wheelset, S1002 on 60E1, Q = 200 kN, yaw 0 and 1 deg.",
  out = "results",
  options = {
    {"step_mm", "number", 0.1, "step of the lateral displacement y (mm)", min = 1e-3},
    {"ymax_mm", "number", 8, "y runs from -ymax_mm to +ymax_mm (mm)", min = 0, max = 30},
    {"grid_mm", "number", 0.2, "element size of the potential contact areas (mm)", min = 1e-3, max = 10},
    {"chain", "integer", 0, "cut the continuation chains into pieces of at most this many cases, each started cold " ..
                            "(0: whole chains, as the paper; more pieces spread over more shards)", min = 0},
    {"surface", "string", "planar", "contact areas on one plane each (as the paper) or along the rail's profile",
     choices = {"planar", "conformal"}},
    {"V_kmh", "number", 0, "rolling speed (km/h): with it the creep forces, T gamma and the damage indices at each " ..
     "equilibrium's pose are columns of sweep.csv (0: the normal problem alone, as the paper)", min = 0, max = 500},
    {"mu", "number", 0.3, "friction coefficient of the rolling contact (with V_kmh)", min = 0.01, max = 2},
    {"method", "string", "exact", "rolling contact solver (with V_kmh)", choices = {"exact", "fastsim"}},
    {"wear", "string", "none", "wear model of the rolling contact (with V_kmh): its volume per metre rolled a column",
     choices = {"none", "archard", "usfd"}},
    {"threads", "integer", 0, "worker threads (0: all cores of this process)", min = 0, max = 256, hash = false},
    {"plots", "boolean", true, "make the figures", hash = false},
  },
}
local opt = s.options
local step, ymax, grid = opt.step_mm * 1e-3, opt.ymax_mm * 1e-3, opt.grid_mm * 1e-3

local wheel = wrc.profile.load("profiles/s1002.lua", {step = 0.1e-3})
local rail = wrc.profile.load("profiles/60e1.lua", {step = 0.1e-3})
local ws = wrc.wheelset{
  wheel = wheel, rail = rail,
  radius = 0.45, back_to_back = 1.360, gauge = 1.435, gauge_depth = 0.014, cant = 1 / 40,
  E = 2.1e11, nu = 0.3, grid = grid, surface = opt.surface,
}
local Q = 200e3

-- The sweep: y in [-ymax, ymax], both yaws, with continuation along y (chunks on the machine's cores or shards).
local ys = {}
local n = math.floor(ymax / step + 0.5)
for i = -n, n do ys[#ys + 1] = i * step end
local yaws = {0, math.rad(1)}

-- After the sweep (and the merge of its shards): the summary and the figures, made from the tables.
local function finish(ctx)
  local _, rows = ctx.read("sweep.csv")
  local _, rigid_rows = ctx.read("rigid.csv")
  local summary = sweep.summary(rows, 0, Q)
  ctx.write("summary.txt", summary)
  io.write(summary)
  if not opt.plots then return end
  sweep.plot_sweep(ctx.dir, rows, rigid_rows, {0, 1})
  -- Single equilibria with their pressure grids, started from the sweep's neighbouring solution.
  local function equilibrium(y, yaw)
    return ws:equilibrium{y = y, yaw = yaw, Q = Q, start = sweep.nearest_start(rows, y, yaw)}
  end
  -- Pressure and h for several lateral positions at yaw 0 (figures 6 and 7).
  for _, y_mm in ipairs{-4, 0, 3, 5, 6, 6.3} do
    sweep.plot_patches(ctx.dir, string.format("y%+.1fmm_yaw0", y_mm), equilibrium(y_mm * 1e-3, 0))
  end
  -- Pressure on the rail surface for the three poses of figure 8.
  for _, c in ipairs{{6.3, 1, "a"}, {0, 0, "b"}, {-6.3, -1, "c"}} do
    sweep.plot_rail_pressure(ctx.dir, "fig8" .. c[3], string.format("y = %.1f mm, yaw = %g deg", c[1], c[2]),
                             equilibrium(c[1] * 1e-3, math.rad(c[2])))
  end
  print("results in " .. ctx.dir)
end

-- Rolling at the equilibria's poses (V_kmh > 0): the creep forces and the damage indices as columns of sweep.csv.
local rolling = nil
if opt.V_kmh > 0 then
  rolling = {V = opt.V_kmh / 3.6, mu = opt.mu, method = opt.method,
             wear = opt.wear ~= "none" and {model = opt.wear} or nil}
elseif opt.wear ~= "none" then
  error("wear=" .. opt.wear .. " needs a rolling speed: give V_kmh (km/h, > 0)", 0)
end

sweep.run_sweep(s, ws, {y = ys, yaw = yaws, Q = Q, rigid = true, threads = opt.threads, chain = opt.chain,
                        inputs = {wheel = wheel, rail = rail}, rolling = rolling, finish = finish})
