-- A fleet of wheels against one rail: for each wheel its rolling-radius-difference (Δr) table, its equivalent
-- conicity (EN 15302, integral method, roll fixed) at 3 mm and at the amplitudes asked, and its flange measures
-- (EN 15313); for the fleet a summary, a histogram of tan(gamma_e) and a scatter of tan(gamma_e) against the flange
-- thickness. Out of the box it generates a synthetic fleet of worn S1002 wheels (profiles/worn_s1002.lua: a hollow
-- tread and a thinned flange, each of a random depth, uniform in [0, hollow_max_mm] and [0, flange_max_mm], drawn
-- per wheel from `seed`); given a folder (wheels=DIR) it reads every wheel profile file in it that a reader takes
-- (MiniProf, Simpack, text; Lua definitions only with definitions=true, and then sandboxed).
--
--   wrc run examples/fleet_conicity.lua [count=1000] [out=results/fleet]          (--help lists the options)
--   wrc run examples/fleet_conicity.lua wheels=measured/ rail=measured/rail.ban rail_mirror_y=true
--   examples/cluster/parallel.sh -n 4 examples/fleet_conicity.lua threads=1         (4 shards, then the merge)
--
-- Writes into `out`:
--   fleet.csv       one row per wheel: wheel, source, hollow_mm, flange_wear_mm (synthetic), Sh_mm, Sd_mm, qR_mm,
--                   y0_mm (the centre of the motion), tan_ge_<a>mm per amplitude (empty where EN 15302's conicity is
--                   not defined, e.g. flange contact inside the amplitude; `notes` says why)
--   delta_r.csv     every wheel's Δr table: wheel, y_mm, dr_mm, flange (1: a touching point steeper than 45 deg)
--   failures.csv    wheels that could not be evaluated, with the error (only when some could not)
--   summary.txt, conicity_histogram.png, conicity_vs_flange.png, manifest.txt
local study = require "wrc.study"
local out = require "wrc.output"

local s = study.new{
  name = "fleet_conicity",
  help = "Equivalent conicity (EN 15302) and flange measures (EN 15313) of a fleet of wheels on one rail: a\n" ..
         "synthetic fleet of worn S1002 wheels by default, or every wheel profile in a folder (wheels=DIR).",
  out = "results/fleet",
  options = {
    {"wheels", "string", "", "folder of wheel profiles (the formats of the readers); empty: the synthetic fleet"},
    {"definitions", "boolean", false, "with wheels=DIR, also the Lua profile definitions (.lua) in it (run sandboxed)"},
    {"count", "integer", 1000, "wheels of the synthetic fleet", min = 1},
    {"seed", "integer", 1, "random seed of the synthetic fleet", min = 0},
    {"hollow_max_mm", "number", 2, "largest hollow tread depth of the synthetic fleet (mm)", min = 0, max = 5},
    {"flange_max_mm", "number", 3, "largest flange thinning of the synthetic fleet (mm)", min = 0, max = 10},
    {"smooth_mm", "number", 0, "smoothing length for the wheel files (mm; 0: as measured; see \"smooth =\")", min = 0,
     max = 10},
    {"rail", "string", "profiles/60e1.lua", "rail profile (a definition or a file)"},
    {"rail_mirror_y", "boolean", false, "mirror the rail file (MiniProf rails measured with the track centre on +X)"},
    {"cant", "number", 1 / 40, "rail inclination (1/40 = 0.025)", min = 0, max = 0.1},
    {"gauge_mm", "number", 1435, "track gauge at 14 mm below the rail top (mm)", min = 1000, max = 1700},
    {"back_to_back_mm", "number", 1360, "distance between the flange backs (mm)", min = 1000, max = 1700},
    {"radius_mm", "number", 460, "nominal wheel radius (mm)", min = 200, max = 700},
    {"amplitudes_mm", "string", "3", "amplitudes of tan(gamma_e) (mm), comma-separated; the first is the figures'"},
    {"table_step_mm", "number", 0.05, "step of the Δr tables (mm)", min = 0.001, max = 1},
    {"threads", "integer", 0, "worker threads of each wheel's Δr table (0: all cores)", min = 0, max = 256,
     hash = false},
    {"plots", "boolean", true, "make the figures", hash = false},
  },
}
local opt = s.options

local amplitudes = {}
for a in opt.amplitudes_mm:gmatch("[^,%s]+") do
  local v = tonumber(a)
  if not v or v <= 0 or v > 20 then error("amplitudes_mm: '" .. a .. "' is not an amplitude in ]0, 20] mm", 0) end
  amplitudes[#amplitudes + 1] = v
end
if #amplitudes == 0 then error("amplitudes_mm: give at least one amplitude", 0) end
local amax = math.max(table.unpack(amplitudes))
local function tan_column(a) return ("tan_ge_%smm"):format((("%g"):format(a):gsub("%.", "p"))) end

local rail = wrc.profile.load(opt.rail, opt.rail_mirror_y and {mirror_y = true} or {})

-- The wheels: files of a folder (those a reader takes, and Lua definitions when asked for; sorted by name), or the
-- synthetic fleet. A .lua file in a data folder is not taken unless definitions=true: the folder is data.
local files = {}
if opt.definitions and opt.wheels == "" then error("definitions=true applies to a folder of wheels (wheels=DIR)", 0) end
-- The folder as a path of the file system: a name "profiles/..." alone means the shipped profiles.
local wheel_dir = (opt.wheels == "profiles" or opt.wheels:match("^profiles/")) and "./" .. opt.wheels or opt.wheels
if opt.wheels ~= "" then
  local known = {[".lua"] = opt.definitions or nil}
  for _, r in ipairs(wrc.profile.readers()) do
    for _, e in ipairs(r.extensions) do known[e:lower()] = true end
  end
  for _, name in ipairs(wrc.fs.list(opt.wheels)) do
    local ext = name:match("(%.[^./]+)$")
    if ext and known[ext:lower()] and wrc.fs.kind(opt.wheels .. "/" .. name) == "file" then files[#files + 1] = name end
  end
  if #files == 0 then
    error(("wheels=%s: no wheel profile in it (extensions of the readers%s)"):format(opt.wheels,
          opt.definitions and ", .lua" or "; definitions=true takes .lua definitions too"), 0)
  end
end
local count = opt.wheels ~= "" and #files or opt.count

-- Wheel i: its name, its profile and, for the synthetic fleet, the depths drawn for it (independent of the others,
-- so that any shard draws the same).
local function wheel(i)
  if opt.wheels ~= "" then
    local name = files[i]
    local options = {kind = "wheel", smooth = opt.smooth_mm > 0 and opt.smooth_mm * 1e-3 or nil}
    return {name = name, source = name, profile = wrc.profile.load(wheel_dir .. "/" .. name, options)}
  end
  math.randomseed(opt.seed, i)
  local hollow, flange = opt.hollow_max_mm * math.random() * 1e-3, opt.flange_max_mm * math.random() * 1e-3
  local name = ("W%05d"):format(i)
  return {name = name, source = "synthetic", hollow = hollow, flange = flange,
          profile = wrc.profile.load("profiles/worn_s1002.lua", {hollow = hollow, flange = flange, name = name})}
end

-- One wheel: the Δr table (from ws:conicity at the smallest amplitude, over the range the largest needs), then
-- tan(gamma_e) at every amplitude on that table, and the flange measures.
local y_range = {from = -(1.5 * amax + 1) * 1e-3, to = (1.5 * amax + 1) * 1e-3, step = opt.table_step_mm * 1e-3}
local function evaluate(i)
  local w = wheel(i)
  local ws = wrc.wheelset{wheel = w.profile, rail = rail, cant = opt.cant, gauge = opt.gauge_mm * 1e-3,
                          back_to_back = opt.back_to_back_mm * 1e-3, radius = opt.radius_mm * 1e-3}
  local _, d = ws:conicity{yhat = {math.min(table.unpack(amplitudes)) * 1e-3}, y = y_range, threads = opt.threads}
  local m = w.profile:flange_measures()
  local row = {wheel = w.name, source = w.source, hollow_mm = w.hollow and w.hollow * 1e3,
               flange_wear_mm = w.flange and w.flange * 1e3, Sh_mm = m.Sh * 1e3, Sd_mm = m.Sd * 1e3,
               qR_mm = m.qR * 1e3, y0_mm = d.centre * 1e3}
  local notes = {}
  for _, a in ipairs(amplitudes) do
    local ok, tan = pcall(wrc.conicity, d.dr, {yhat = a * 1e-3})
    if ok then
      row[tan_column(a)] = tan[1]
    else
      notes[#notes + 1] = ("%g mm: %s"):format(a, (tostring(tan):gsub("^.-:%d+: ", ""):match("^[^\n]*")))
    end
  end
  row.notes = #notes > 0 and table.concat(notes, "; ") or nil
  local dr_rows = {}
  for k = 1, #d.dr.y do
    dr_rows[k] = {wheel = w.name, y_mm = d.dr.y[k] * 1e3, dr_mm = d.dr.dr[k] * 1e3, flange = d.dr.flange[k] and 1 or 0}
  end
  return {fleet = row, delta_r = dr_rows}
end

local fleet_columns = {"wheel", "source", "hollow_mm", "flange_wear_mm", "Sh_mm", "Sd_mm", "qR_mm", "y0_mm"}
for _, a in ipairs(amplitudes) do fleet_columns[#fleet_columns + 1] = tan_column(a) end
fleet_columns[#fleet_columns + 1] = "notes"

-- The fleet's identity (the hash of the run's parts): the rail's points, and the wheel files' contents.
local inputs = {rail = rail}
if opt.wheels ~= "" then
  local hashes = {}
  for i, name in ipairs(files) do hashes[i] = name .. " " .. wrc.fs.hash_file(opt.wheels .. "/" .. name) end
  inputs.wheels = table.concat(hashes, "\n")
end

-- After the merge: the summary and the figures, from fleet.csv.
local function quantile(sorted, q) return #sorted > 0 and sorted[math.max(1, math.ceil(q * #sorted))] or nil end
local function finish(ctx)
  local _, rows = ctx.read("fleet.csv")
  local lines = {("wheels: %d, failed: %d (rail %s, 1:%g, gauge %g mm)"):format(ctx.cases, ctx.failed, rail.name,
                                                                              1 / opt.cant, opt.gauge_mm)}
  for _, a in ipairs(amplitudes) do
    local col, v, high = tan_column(a), {}, 0
    for _, r in ipairs(rows) do
      if r[col] then
        v[#v + 1] = r[col]
        if r[col] > 0.3 then high = high + 1 end
      end
    end
    table.sort(v)
    if #v > 0 then
      lines[#lines + 1] = ("tan(gamma_e) at %g mm: %d wheels, min %.4f, median %.4f, 90 %% %.4f, max %.4f; " ..
                           "above 0.3: %d, undefined: %d"):format(a, #v, v[1], quantile(v, 0.5), quantile(v, 0.9), v[#v],
                                                                  high, #rows - #v)
    else
      lines[#lines + 1] = ("tan(gamma_e) at %g mm: undefined for every wheel"):format(a)
    end
  end
  local sd = {}
  for _, r in ipairs(rows) do sd[#sd + 1] = r.Sd_mm end
  table.sort(sd)
  if #sd > 0 then
    lines[#lines + 1] = ("flange thickness Sd: min %.2f, median %.2f, max %.2f mm"):format(sd[1], quantile(sd, 0.5), sd[#sd])
  end
  local text = table.concat(lines, "\n") .. "\n"
  ctx.write("summary.txt", text)
  io.write(text)
  if not opt.plots then return end
  local col = tan_column(amplitudes[1])
  local tans, xs, ys = {}, {}, {}
  for _, r in ipairs(rows) do
    if r[col] then
      tans[#tans + 1] = r[col]
      xs[#xs + 1], ys[#ys + 1] = r.Sd_mm, r[col]
    end
  end
  local label = ("tan(gamma_e) at %g mm"):format(amplitudes[1])
  out.histogram{file = ctx.path("conicity_histogram.png"), values = tans, bins = 40, xlabel = label,
                ylabel = "wheels", title = ("equivalent conicity of %d wheels on %s 1:%g (EN 15302, roll fixed)")
                                              :format(#tans, rail.name, 1 / opt.cant)}
  out.plot{file = ctx.path("conicity_vs_flange.png"), xlabel = "flange thickness Sd (mm)", ylabel = label,
           title = "equivalent conicity against flange thickness",
           series = {{x = xs, y = ys, title = "one wheel", style = "points pt 7 ps 0.5"}}}
  print("results in " .. ctx.dir)
end

s:run{
  cases = count, chunk_size = 1, batch = 25, inputs = inputs,
  tables = {{key = "fleet", file = "fleet.csv", columns = fleet_columns},
            {key = "delta_r", file = "delta_r.csv", columns = {"wheel", "y_mm", "dr_mm", "flange"}}},
  key_columns = {"wheel"},
  key = function(i) return {wheel = opt.wheels ~= "" and files[i] or ("W%05d"):format(i)} end,
  compute = function(batch)
    local results = {}
    for i = batch.first, batch.last do
      local ok, r = pcall(evaluate, i)
      results[i] = ok and r or {error = r}
    end
    return results
  end,
  finish = finish,
}
