-- The paper's study (examples/paper_study.lua: S1002 on 60E1, Q = 200 kN, y from -8 to 8 mm, yaw 0 and 1 deg) with
-- both contact surfaces (issue 15): each contact area on one plane (the paper's, surface = "planar") and on the
-- curved surface along the rail's profile (surface = "conformal", each element's pressure along its own normal).
--
--   wrc run examples/surfaces_study.lua [out=results/surfaces] [step_mm=0.1] [threads=N] [grid_mm=0.2]  (--help)
--
-- Writes into `out`: sweep_planar.csv and sweep_conformal.csv (the columns of the paper study's sweep.csv, plus
-- left_min_row_angle_deg and left_max_row_angle_deg: the range of the directions the left wheel's pressure acts in),
-- YQ_surfaces.png (Y/Q against y, both surfaces and yaws; YQ_surfaces_flange.png from 4.5 to 7 mm), angle_surfaces.png (the left wheel's contact angle: the
-- resultant's, and the range over its loaded rows) with their data, and summary.txt: per surface and yaw, where Y/Q
-- first exceeds 0.8, where the left wheel's contact angle exceeds 60 deg, where the right wheel lifts, and the
-- largest difference of Y/Q between the surfaces.
local out = require "wrc.output"
local study = require "wrc.study"
local paper = require "wrc.sweep"  -- the paper study's rows, series and ranges

local opt = study.new{
  name = "surfaces_study", out = "results/surfaces",
  help = "The paper's study with planar and with conformal contact areas, side by side.",
  options = {
    {"step_mm", "number", 0.1, "step of the lateral displacement y (mm)", min = 1e-3},
    {"grid_mm", "number", 0.2, "element size of the potential contact areas (mm)", min = 1e-3, max = 10},
    {"threads", "integer", 0, "worker threads (0: all cores of this process)", min = 0, max = 256, hash = false},
  },
}.options
local dir, step, grid = opt.out, opt.step_mm * 1e-3, opt.grid_mm * 1e-3
local deg = 180 / math.pi

local wheel = wrc.profile.load("profiles/s1002.lua", {step = 0.1e-3})
local rail = wrc.profile.load("profiles/60e1.lua", {step = 0.1e-3})
local ys = {}
for i = -math.floor(8e-3 / step + 0.5), math.floor(8e-3 / step + 0.5) do ys[#ys + 1] = i * step end
local yaws = {0, math.rad(1)}
local Q = 200e3

-- The range of directions of the left wheel's loaded areas (rad): the rows of a conformal area, the plane's normal.
local function row_angles(r)
  local lo, hi = nil, nil
  for _, p in ipairs(r.left.patches) do
    if p.normal_force > 0 then
      lo = lo and math.min(lo, p.angle_min) or p.angle_min
      hi = hi and math.max(hi, p.angle_max) or p.angle_max
    end
  end
  return lo, hi
end

-- Cases of one yaw, ordered by y.
local function series(sweep, yaw)
  local s = {}
  for _, r in ipairs(sweep) do
    if math.abs(r.yaw - yaw) < 1e-12 then s[#s + 1] = r end
  end
  table.sort(s, function(a, b) return a.y < b.y end)
  return s
end

local sweeps, lines = {}, {}
local columns = {}
for _, c in ipairs(paper.sweep_columns) do columns[#columns + 1] = c end
columns[#columns + 1] = "left_min_row_angle_deg"
columns[#columns + 1] = "left_max_row_angle_deg"
for _, surface in ipairs{"planar", "conformal"} do
  local ws = wrc.wheelset{wheel = wheel, rail = rail, grid = grid, surface = surface}
  local sweep = ws:sweep{y = ys, yaw = yaws, Q = Q, threads = opt.threads}
  sweeps[surface] = sweep
  local rows = {}
  for _, r in ipairs(sweep) do
    local row = paper.sweep_row(r)
    if r.converged then
      local lo, hi = row_angles(r)
      row.left_min_row_angle_deg, row.left_max_row_angle_deg = lo and lo * deg, hi and hi * deg
    end
    rows[#rows + 1] = row
  end
  out.csv(string.format("%s/sweep_%s.csv", dir, surface), columns, rows)
  lines[#lines + 1] = string.format("%s: %d cases, %d failed, %.1f s on %d threads", surface, #sweep, sweep.failed,
                                    sweep.seconds, sweep.threads)
  for _, yaw in ipairs(yaws) do  -- on the table's rows, as the paper study's summary (wrc.sweep)
    local s = paper.series(rows, yaw * deg)
    local y08 = paper.first_crossing(s, 0.8)
    lines[#lines + 1] = string.format("  yaw %g deg: Y/Q first exceeds 0.8 at y = %s mm", yaw * deg,
                                      y08 and string.format("%.2f", y08) or "(never)")
    lines[#lines + 1] = "    left contact angle > 60 deg, the resultant:          y = " ..
                            paper.ranges(s, function(r) return (r.left_angle_deg or 0) > 60 end) .. " mm"  -- nil: lifted
    lines[#lines + 1] = "    left contact angle > 60 deg, the steepest loaded row: y = " ..
                            paper.ranges(s, function(r) return (r.left_max_row_angle_deg or 0) > 60 end) .. " mm"
    lines[#lines + 1] = "    right wheel lifted:                                   y = " ..
                            paper.ranges(s, function(r) return not (r.right_Fz_kN > 0) end) .. " mm"
  end
end

-- Differences between the surfaces, case by case.
local worst, at = 0, nil
for k, r in ipairs(sweeps.planar) do
  local c = sweeps.conformal[k]
  if r.converged and c.converged and math.abs(c.Y_Q - r.Y_Q) > worst then worst, at = math.abs(c.Y_Q - r.Y_Q), c end
end
if at then
  lines[#lines + 1] = string.format("largest |Y/Q conformal - Y/Q planar| = %.3f at y = %.1f mm, yaw %g deg", worst,
                                    at.y * 1e3, at.yaw * deg)
end
local summary = table.concat(lines, "\n") .. "\n"
out.text(dir .. "/summary.txt", summary)
io.write(summary)

-- Figures.
local function curve(surface, yaw, value)
  local x, v = {}, {}
  for _, r in ipairs(series(sweeps[surface], yaw)) do
    x[#x + 1] = r.y * 1e3
    v[#v + 1] = r.converged and value(r) or 0 / 0
  end
  return x, v
end
local series_YQ, series_angle = {}, {}
for _, yaw in ipairs(yaws) do
  for _, surface in ipairs{"planar", "conformal"} do
    local style = surface == "planar" and "lines lw 2 dt 2" or "linespoints pt 7 ps 0.4"
    local x, v = curve(surface, yaw, function(r) return r.Y_Q end)
    series_YQ[#series_YQ + 1] = {x = x, y = v, title = string.format("%s, yaw %g deg", surface, yaw * deg), style = style}
    if yaw == 0 then
      local xa, va = curve(surface, yaw, function(r) return r.left.force.z > 0 and r.left.angle * deg or 0 / 0 end)
      series_angle[#series_angle + 1] = {x = xa, y = va, title = surface .. ": the resultant", style = style}
    end
  end
end
for _, bound in ipairs{{"lowest", 1}, {"steepest", 2}} do
  local x, v = curve("conformal", 0, function(r)
    local a = select(bound[2], row_angles(r))
    return a and a * deg or 0 / 0  -- no loaded area: the left wheel has lifted
  end)
  series_angle[#series_angle + 1] = {x = x, y = v, title = "conformal: the " .. bound[1] .. " loaded row",
                                     style = "lines lw 1"}
end
out.plot{file = dir .. "/YQ_surfaces.png", title = "Y/Q with planar and conformal contact areas (S1002 / 60E1, Q = 200 kN)",
         xlabel = "lateral displacement y (mm)", ylabel = "Y/Q", series = series_YQ}
-- The flange root, where they differ: y from 4.5 to 7 mm.
local zoom = {}
for _, se in ipairs(series_YQ) do
  local x, v = {}, {}
  for i = 1, #se.x do
    if se.x[i] >= 4.5 - 1e-9 and se.x[i] <= 7 + 1e-9 then x[#x + 1], v[#v + 1] = se.x[i], se.y[i] end
  end
  zoom[#zoom + 1] = {x = x, y = v, title = se.title, style = se.style}
end
out.plot{file = dir .. "/YQ_surfaces_flange.png", title = "Y/Q at the flange root: planar and conformal contact areas",
         xlabel = "lateral displacement y (mm)", ylabel = "Y/Q", series = zoom, extra = {"set key top left"}}
out.plot{file = dir .. "/angle_surfaces.png", title = "contact angle of the left wheel, yaw 0",
         xlabel = "lateral displacement y (mm)", ylabel = "contact angle (deg)", series = series_angle,
         extra = {"set key top left"}}
print("results in " .. dir)
