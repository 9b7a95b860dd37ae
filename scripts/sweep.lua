-- wrc.sweep: sweep studies, one user of the study runner (wrc.study). Table rows with units in the column names
-- (sweep.csv from ws:sweep or ws:equilibrium results, rigid.csv from their rigid references), a sweep of equilibria
-- as a study (run_sweep: the cases and chunks of ws:sweep_plan handed to s:run), the summary of contact ranges and
-- the plots of the paper's figures, made from the tables.
--   local study, sweep = require "wrc.study", require "wrc.sweep"
--   local s = study.new{...}
--   sweep.run_sweep(s, ws, {y =, yaw =, Q =, finish = function(ctx) ... sweep.summary(rows, 0, Q) ... end})
local out = require "wrc.output"
local M = {}

local deg = 180 / math.pi

local function patch_count(wheel)
  local n = 0
  for _, p in ipairs(wheel.patches) do
    if p.normal_force > 0 then n = n + 1 end
  end
  return n
end

-- Separate contact regions of a wheel (an inter-penetration area may hold two, e.g. tread and flange root).
local function region_count(wheel)
  local n = 0
  for _, p in ipairs(wheel.patches) do n = n + (p.regions or 0) end
  return n
end

-- Largest contact angle over the loaded areas of a wheel: of the contact plane (`angle`, the direction of the
-- force), or of the wheel normal at the paper's nominal point (`nominal_angle`).
local function max_angle(wheel, field)
  local a = nil
  for _, p in ipairs(wheel.patches) do
    local v = p[field or "angle"]
    if p.normal_force > 0 and (a == nil or v > a) then a = v end
  end
  return a
end

M.sweep_columns = {
  "yaw_deg", "y_mm", "converged", "z_mm", "roll_mrad", "Y_kN", "Y_Q", "My_kNm", "Mz_kNm",
  "left_patches", "left_contact_regions", "left_Fy_kN", "left_Fz_kN", "left_angle_deg", "left_max_patch_angle_deg",
  "left_max_nominal_angle_deg", "left_rolling_radius_mm",
  "right_patches", "right_contact_regions", "right_Fy_kN", "right_Fz_kN", "right_angle_deg", "right_rolling_radius_mm",
  "rolling_radius_difference_mm", "iterations", "residual_force_N", "residual_moment_Nm",
  "flange_climb",
}

-- Columns of a sweep run with kinematics (ws:sweep{..., V =, mu =}): the creep forces of each wheel in the track
-- frame and the frictional power at the equilibrium's pose, and their totals. sweep_row fills them when present.
M.creep_columns = {
  "left_creep_Fx_kN", "left_creep_Fy_kN", "left_creep_Fz_kN", "left_power_W",
  "right_creep_Fx_kN", "right_creep_Fy_kN", "right_creep_Fz_kN", "right_power_W",
  "creep_Fx_kN", "creep_Fy_kN", "creep_Mz_kNm", "power_W",
}

-- With kinematics also the damage indices of each wheel (docs/guide/damage.md): T gamma and T gamma with spin summed
-- over its areas (N = J/m) and the largest of their Burstow RCF damages per passage; with a wear model (wear = {...})
-- the volume its areas wear off per metre rolled (mm^3/m).
M.damage_columns = {
  "left_Tgamma_N", "left_Tgamma_spin_N", "left_rcf_damage_max",
  "right_Tgamma_N", "right_Tgamma_spin_N", "right_rcf_damage_max",
}
M.wear_columns = {"left_wear_mm3_per_m", "right_wear_mm3_per_m"}

local function has_wear(r)
  for _, side in ipairs{"left", "right"} do
    for _, p in ipairs(r[side] and r[side].patches or {}) do
      if p.wear_volume then return true end
    end
  end
  return false
end

-- The columns of a sweep's table: sweep_columns, and creep_columns and damage_columns when the sweep solved the
-- tangential problems (and wear_columns with a wear model).
function M.columns(sweep)
  for _, r in ipairs(sweep) do
    if r.creep_force then
      local c = {table.unpack(M.sweep_columns)}
      for _, name in ipairs(M.creep_columns) do c[#c + 1] = name end
      for _, name in ipairs(M.damage_columns) do c[#c + 1] = name end
      if has_wear(r) then
        for _, name in ipairs(M.wear_columns) do c[#c + 1] = name end
      end
      return c
    end
  end
  return M.sweep_columns
end

-- The damage cells of a wheel: sums over its areas (the largest RCF damage); nil when no area was solved.
local function damage_cells(row, side, w)
  local t, ts, rcf, wear
  for _, p in ipairs(w.patches or {}) do
    if p.Tgamma then
      t, ts = (t or 0) + p.Tgamma, (ts or 0) + p.Tgamma_spin
      rcf = math.max(rcf or 0, p.rcf_damage)
      if p.wear_volume then wear = (wear or 0) + p.wear_volume * 1e9 end
    end
  end
  row[side .. "_Tgamma_N"], row[side .. "_Tgamma_spin_N"], row[side .. "_rcf_damage_max"] = t, ts, rcf
  row[side .. "_wear_mm3_per_m"] = wear
end

local function creep_cells(row, r)
  if not r.creep_force then return end
  for _, side in ipairs{"left", "right"} do
    local w = r[side]
    if w.creep_force then
      row[side .. "_creep_Fx_kN"] = w.creep_force.x / 1e3
      row[side .. "_creep_Fy_kN"] = w.creep_force.y / 1e3
      row[side .. "_creep_Fz_kN"] = w.creep_force.z / 1e3
      row[side .. "_power_W"] = w.power
    end
    damage_cells(row, side, w)
  end
  row.creep_Fx_kN, row.creep_Fy_kN = r.creep_force.x / 1e3, r.creep_force.y / 1e3
  row.creep_Mz_kNm, row.power_W = r.creep_moment.z / 1e3, r.power
end

-- One row of sweep.csv from a sweep (or equilibrium) result.
function M.sweep_row(r)
  local row = {yaw_deg = r.yaw * deg, y_mm = r.y * 1e3, converged = r.converged and 1 or 0}
  if not r.converged then return row end
  row.z_mm, row.roll_mrad = r.z * 1e3, r.roll * 1e3
  row.Y_kN, row.Y_Q, row.My_kNm, row.Mz_kNm = r.Y / 1e3, r.Y_Q, r.My / 1e3, r.Mz / 1e3
  for _, side in ipairs{"left", "right"} do
    local w = r[side]
    row[side .. "_patches"] = patch_count(w)
    row[side .. "_contact_regions"] = region_count(w)
    row[side .. "_Fy_kN"] = w.force.y / 1e3
    row[side .. "_Fz_kN"] = w.force.z / 1e3
    row[side .. "_angle_deg"] = w.angle and w.angle * deg  -- nil (an empty cell): a lifted wheel
    row[side .. "_rolling_radius_mm"] = w.rolling_radius and w.rolling_radius * 1e3
  end
  local a, an = max_angle(r.left), max_angle(r.left, "nominal_angle")
  row.left_max_patch_angle_deg = a and a * deg
  row.left_max_nominal_angle_deg = an and an * deg
  row.rolling_radius_difference_mm = r.rolling_radius_difference and r.rolling_radius_difference * 1e3  -- nil: a wheel lifted
  row.iterations = r.iterations
  row.residual_force_N, row.residual_moment_Nm = r.residual.force, r.residual.moment
  row.flange_climb = r.flange_climb and 1 or 0
  creep_cells(row, r)
  return row
end

M.rigid_columns = {
  "yaw_deg", "y_mm", "converged", "tension", "z_mm", "roll_mrad", "Y_kN", "Y_Q", "Mz_kNm",
  "left_y_mm", "left_angle_deg", "left_N_kN", "right_y_mm", "right_angle_deg", "right_N_kN",
  "rolling_radius_difference_mm",
}

function M.rigid_row(r)
  local g = r.rigid
  local row = {yaw_deg = r.yaw * deg, y_mm = r.y * 1e3, converged = (g and g.converged) and 1 or 0}
  if not (g and g.converged) then return row end
  row.tension = g.tension and 1 or 0
  row.z_mm, row.roll_mrad = g.z * 1e3, g.roll * 1e3
  for _, side in ipairs{"left", "right"} do
    row[side .. "_y_mm"] = g[side].point.y * 1e3
    row[side .. "_angle_deg"] = g[side].angle * deg
  end
  if not g.tension then  -- forces only where both wheels push (else no rigid equilibrium on the rails)
    row.Y_kN, row.Y_Q, row.Mz_kNm = g.Y / 1e3, g.Y_Q, g.Mz / 1e3
    row.left_N_kN, row.right_N_kN = g.left.normal_force / 1e3, g.right.normal_force / 1e3
  end
  row.rolling_radius_difference_mm = (g.left.rolling_radius - g.right.rolling_radius) * 1e3
  return row
end

-- Rows (of sweep.csv or rigid.csv, as wrc.output.read_csv returns them) of one yaw (deg), ordered by y.
function M.series(rows, yaw_deg)
  local s = {}
  for _, r in ipairs(rows) do
    if math.abs(r.yaw_deg - yaw_deg) < 1e-9 then s[#s + 1] = r end
  end
  table.sort(s, function(a, b) return a.y_mm < b.y_mm end)
  return s
end

-- {z =, roll =} (m, rad) of the converged row nearest to (y, yaw) (m, rad; nil if none): a start for
-- ws:equilibrium. A case at yaw -psi is the mirror of one at +psi (y -> -y, roll -> -roll).
function M.nearest_start(rows, y, yaw)
  local best, dist = nil, math.huge
  for _, r in ipairs(rows) do
    if r.converged == 1 then
      for _, m in ipairs{1, -1} do
        if math.abs(m * math.rad(r.yaw_deg) - yaw) < 1e-9 then
          local d = math.abs(m * r.y_mm * 1e-3 - y)
          if d < dist then best, dist = {z = r.z_mm * 1e-3, roll = m * r.roll_mrad * 1e-3}, d end
        end
      end
    end
  end
  return best
end

-- Ranges of y (mm) where pred(row) holds, as text "a .. b, c .. d" (consecutive sweep points).
local function ranges(series, pred)
  local parts, first, last = {}, nil, nil
  for _, r in ipairs(series) do
    if r.converged == 1 and pred(r) then
      first = first or r.y_mm
      last = r.y_mm
    elseif first then
      parts[#parts + 1] = string.format("%.1f .. %.1f", first, last)
      first = nil
    end
  end
  if first then parts[#parts + 1] = string.format("%.1f .. %.1f", first, last) end
  return #parts > 0 and table.concat(parts, ", ") or "none"
end
M.ranges = ranges

-- The y (mm) where Y/Q first exceeds `limit` going from y = 0 toward +y (linear between sweep points).
function M.first_crossing(series, limit)
  local prev = nil
  for _, r in ipairs(series) do
    if r.converged == 1 and r.y_mm >= 0 then
      if prev and prev.Y_Q <= limit and r.Y_Q > limit then
        return prev.y_mm + (limit - prev.Y_Q) * (r.y_mm - prev.y_mm) / (r.Y_Q - prev.Y_Q)
      end
      prev = r
    end
  end
  return nil
end

-- The summary of a sweep table (rows of sweep.csv) at one yaw (deg), Q in N: failed cases, residuals, Y/Q = 0.8
-- and the contact ranges of the left wheel.
function M.summary(rows, yaw_deg, Q)
  local s = M.series(rows, yaw_deg)
  local lines = {}
  local failed, worst_f, worst_m = 0, 0, 0
  for _, r in ipairs(rows) do
    if r.converged == 1 then
      worst_f = math.max(worst_f, math.abs(r.residual_force_N) / Q)
      worst_m = math.max(worst_m, math.abs(r.residual_moment_Nm) / Q)
    else
      failed = failed + 1
    end
  end
  lines[#lines + 1] = string.format("cases: %d, failed: %d", #rows, failed)
  lines[#lines + 1] = string.format("largest residuals: force %.2e Q, moment %.2e Q m", worst_f, worst_m)
  local y08 = M.first_crossing(s, 0.8)
  lines[#lines + 1] = string.format("yaw %g deg: Y/Q first exceeds 0.8 at y = %s mm", yaw_deg,
                                    y08 and string.format("%.2f", y08) or "(never)")
  local function over60(v) return v ~= nil and v > 60 end
  lines[#lines + 1] = "  left wheel, one inter-penetration area:   y = " .. ranges(s, function(r) return r.left_patches == 1 end) .. " mm"
  lines[#lines + 1] = "  left wheel, two inter-penetration areas:  y = " .. ranges(s, function(r) return r.left_patches == 2 end) .. " mm"
  lines[#lines + 1] = "  left wheel, one contact region:  y = " .. ranges(s, function(r) return r.left_contact_regions == 1 end) .. " mm"
  lines[#lines + 1] = "  left wheel, two contact regions: y = " .. ranges(s, function(r) return r.left_contact_regions >= 2 end) .. " mm"
  lines[#lines + 1] = "  left wheel, no contact:          y = " .. ranges(s, function(r) return r.left_patches == 0 end) .. " mm"
  lines[#lines + 1] = "  left contact angle > 60 deg:    y = " ..
                          ranges(s, function(r) return over60(r.left_max_patch_angle_deg) end) ..
                          " mm (contact plane: the force direction)"
  lines[#lines + 1] = "                                  y = " ..
                          ranges(s, function(r) return over60(r.left_max_nominal_angle_deg) end) ..
                          " mm (wheel normal at the paper's nominal point)"
  lines[#lines + 1] = "  right wheel lifted (no load):   y = " .. ranges(s, function(r) return r.right_patches == 0 end) .. " mm"
  return table.concat(lines, "\n") .. "\n"
end

-- Figures 4 and 5 and the rigid/elastic comparison from the tables (rows of sweep.csv and rigid.csv, the same
-- cases in the same order) for the yaws given in degrees.
function M.plot_sweep(dir, rows, rigid_rows, yaws_deg)
  local function series_xy(yaw, column, rigid, forces)
    local xs, vs = {}, {}
    local src_rows = rigid and rigid_rows or rows
    for _, r in ipairs(M.series(src_rows, yaw)) do
      xs[#xs + 1] = r.y_mm
      local ok = r.converged == 1 and not (forces and r.tension == 1) and r[column] ~= nil
      vs[#vs + 1] = ok and r[column] or 0 / 0
    end
    return xs, vs
  end
  local function plot(file, ylabel, column, title, with_rigid, forces)
    local series = {}
    for _, yaw in ipairs(yaws_deg) do
      local x, v = series_xy(yaw, column)
      series[#series + 1] = {x = x, y = v, title = string.format("elastic, yaw %g deg", yaw), style = "linespoints pt 7 ps 0.4"}
      if with_rigid then
        local xr, vr = series_xy(yaw, column, true, forces)
        series[#series + 1] = {x = xr, y = vr, title = string.format("rigid, yaw %g deg", yaw), style = "lines lw 2 dt 2"}
      end
    end
    out.plot{file = dir .. "/" .. file, title = title, xlabel = "lateral displacement y (mm)", ylabel = ylabel, series = series}
  end
  plot("fig4_z.png", "vertical displacement z (mm)", "z_mm", "Fig. 4: height of the centre")
  plot("fig4_roll.png", "roll angle (mrad)", "roll_mrad", "Fig. 4: roll angle")
  plot("fig5_YQ.png", "Y/Q", "Y_Q", "Fig. 5: lateral / vertical force")
  plot("fig5_Mz.png", "Mz (kN m)", "Mz_kNm", "Fig. 5: yaw moment that holds the wheelset")
  plot("rigid_vs_elastic_z.png", "z (mm)", "z_mm", "rigid vs elastic contact: height", true)
  plot("rigid_vs_elastic_roll.png", "roll (mrad)", "roll_mrad", "rigid vs elastic contact: roll", true)
  plot("rigid_vs_elastic_YQ.png", "Y/Q", "Y_Q", "rigid vs elastic contact: Y/Q (rigid: where both wheels push)", true, true)
end

-- A sweep of equilibria as a study (s from wrc.study.new): the cases yaw x y (y ascending), cut into the engine's
-- continuation chunks (ws:sweep_plan), each computed on its own, so that any split into shards, batches or threads
-- gives the same rows. Writes sweep.csv (and rigid.csv with rigid = true) and calls o.finish(ctx) after the merge.
--   o = {y = {...} (ascending), yaw = {...} (rad), Q =, rigid =, threads =, chain =, inputs =, finish =,
--        rolling = {V =, mu =, method =, wear =, ...} (the rolling keys of ws:sweep: the creep forces and the damage
--        indices at each equilibrium's pose, their columns in sweep.csv; nil: the normal problem alone)}
function M.run_sweep(s, ws, o)
  for i = 2, #o.y do assert(o.y[i] > o.y[i - 1], "sweep.run_sweep: y must be ascending") end
  local plan = ws:sweep_plan{y = o.y, yaw = o.yaw, chain = o.chain}
  local chunks = {}
  for k, c in ipairs(plan.chunks) do chunks[k] = {first = c.first, last = c.last} end
  local threads = (o.threads and o.threads > 0) and o.threads or wrc.cores
  local columns = M.sweep_columns
  if o.rolling then
    columns = {table.unpack(M.sweep_columns)}
    for _, list in ipairs{M.creep_columns, M.damage_columns, o.rolling.wear and M.wear_columns or {}} do
      for _, name in ipairs(list) do columns[#columns + 1] = name end
    end
  end
  local tables = {{key = "sweep", file = "sweep.csv", columns = columns}}
  if o.rigid then tables[2] = {key = "rigid", file = "rigid.csv", columns = M.rigid_columns} end
  local ny = #o.y
  return s:run{
    cases = plan.cases, chunks = chunks, tables = tables, inputs = o.inputs, batch = 2 * threads,
    key_columns = {"yaw_deg", "y_mm"},
    key = function(i) return {yaw_deg = o.yaw[(i - 1) // ny + 1] * deg, y_mm = o.y[(i - 1) % ny + 1] * 1e3} end,
    compute = function(batch)
      local ids = {}
      for _, c in ipairs(batch.chunks) do ids[#ids + 1] = c.index end
      local keys = {y = o.y, yaw = o.yaw, Q = o.Q, rigid = o.rigid, threads = o.threads, chain = o.chain,
                    chunks = ids, progress = false}
      for k, v in pairs(o.rolling or {}) do keys[k] = v end
      local sweep = ws:sweep(keys)
      local results = {}
      for _, r in ipairs(sweep) do
        results[r.case] = {sweep = M.sweep_row(r), rigid = o.rigid and M.rigid_row(r) or nil,
                           error = (not r.converged) and (r.error or "did not converge") or nil}
      end
      return results
    end,
    finish = o.finish,
  }
end

-- Grid centres (mm) of a patch in its contact plane.
local function axes(p)
  local xs, ys = {}, {}
  for i = 1, p.grid.nx do xs[i] = (p.grid.x0 + (i - 1) * p.grid.dx) * 1e3 end
  for j = 1, p.grid.ny do ys[j] = (p.grid.y0 + (j - 1) * p.grid.dy) * 1e3 end
  return xs, ys
end

local function scaled(grid, k, floor)
  local v = {}
  for j, row in ipairs(grid) do
    v[j] = {}
    for i, x in ipairs(row) do v[j][i] = floor and math.max(x * k, floor) or x * k end
  end
  return v
end

-- The grid's second axis: across the contact plane, or along the rail's profile (a conformal area), and which way it
-- points across the rail: toward the field side (away from the track centre: +y on the left rail, -y on the right)
-- or the gauge side. A map draws it upward.
local function across(p, side)
  local d = p.frame.t2.y
  if p.rows and #p.rows.y > 1 then d = p.rows.y[#p.rows.y] - p.rows.y[1] end
  local up = d * (side == "left" and 1 or -1) >= 0 and "field" or "gauge"
  local what = p.surface == "conformal" and "arc length along the rail profile" or "lateral, in the contact plane"
  return string.format("%s (mm): %s side up, %s side down", what, up, up == "field" and "gauge" or "field")
end

-- Figures 6 and 7: pressure and undeformed distance of every contact area of an equilibrium.
function M.plot_patches(dir, tag, e)
  for _, side in ipairs{"left", "right"} do
    for k, p in ipairs(e[side].patches) do
      if p.pressure then
        local xs, ys = axes(p)
        local name = string.format("%s_%s%d", tag, side, k)
        out.map{file = string.format("%s/fig6_pressure_%s.png", dir, name), x = xs, y = ys, value = scaled(p.pressure, 1e-6),
                title = string.format("pressure (MPa), %s wheel, %s: N = %.1f kN, angle %.1f deg", side, tag,
                                      p.normal_force / 1e3, p.angle * deg),
                xlabel = "x, rolling direction (mm)", ylabel = across(p, side), cblabel = "MPa"}
        out.map{file = string.format("%s/fig7_h_%s.png", dir, name), x = xs, y = ys, value = scaled(p.h, 1e3, -0.05),
                title = string.format("undeformed distance h (mm, > 0 inter-penetration), %s wheel, %s", side, tag),
                xlabel = "x, rolling direction (mm)", ylabel = across(p, side), cblabel = "mm"}
      end
    end
  end
end

-- The rail surface point under an element of an area: the element's lateral plane coordinate v placed between
-- the two rail lines (from the area's segments) that bracket it; x along the track from the plane.
local function rail_surface_mapper(p)
  local o, t1, t2 = p.frame.origin, p.frame.t1, p.frame.t2
  if p.rows then  -- a conformal area lies on the rail: its grid row j at (rows.y[j], rows.z[j]), x from its origin
    return function(u, v)
      local j = math.floor((v - p.grid.y0) / p.grid.dy + 0.5) + 1
      return o.x + u, p.rows.y[j], p.rows.z[j]
    end
  end
  local lines, seen = {}, {}
  for _, s in ipairs(p.segments or {}) do
    if not seen[s.line] then
      seen[s.line] = true
      lines[#lines + 1] = {v = (s.y - o.y) * t2.y + (s.z - o.z) * t2.z - o.x * t2.x, y = s.y, z = s.z}
    end
  end
  table.sort(lines, function(a, b) return a.v < b.v end)
  return function(u, v)
    local x = o.x + u * t1.x + v * t2.x
    if #lines < 2 then return x, o.y + u * t1.y + v * t2.y, o.z + u * t1.z + v * t2.z end
    local k = 1
    while k < #lines - 1 and lines[k + 1].v < v do k = k + 1 end
    local a, b = lines[k], lines[k + 1]
    local f = (v - a.v) / (b.v - a.v)
    return x, a.y + f * (b.y - a.y), a.z + f * (b.z - a.z)
  end
end

-- Figure 8: the pressure of the left wheel's contact areas on the rail surface, in the track frame (docs/design.md
-- section 2: origin at the centre of the centred wheelset, x along the track, y toward the left rail, z up; the rail
-- surface lies about r0 below the origin), which the caption names.
function M.plot_rail_pressure(dir, name, title, e)
  local points = {}
  for _, p in ipairs(e.left.patches) do
    if p.pressure then
      local on_rail = rail_surface_mapper(p)
      for j = 1, p.grid.ny do
        for i = 1, p.grid.nx do
          local pr = p.pressure[j][i]
          if pr > 0 then
            local x, y, z = on_rail(p.grid.x0 + (i - 1) * p.grid.dx, p.grid.y0 + (j - 1) * p.grid.dy)
            points[#points + 1] = {x * 1e3, y * 1e3, z * 1e3, pr * 1e-6}
          end
        end
      end
    end
  end
  out.scatter3d{file = dir .. "/" .. name .. "_rail_pressure.png", points = points, width = 900, height = 700,
                title = "Fig. 8: pressure on the left rail surface, " .. title ..
                        " (track frame: origin at the centred wheelset's centre, y toward the left rail, z up)",
                xlabel = "x along the track (mm)", ylabel = "y, track frame (mm): + field side, - gauge side",
                zlabel = "z, track frame (mm; the rail top about r0 below the centre)", cblabel = "MPa"}
end

return M
