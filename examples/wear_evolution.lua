-- Wheel (and rail) profiles worn over mileage: a wear loop (docs/guide/wear.md). Per step every running case is
-- solved -- the wheelset's equilibrium under its load, then rolling contact with the wear model (Archard with the KTH
-- map by default) at that pose, the axle turning at omega = V / r0 (spin=nominal) or at the spin that balances its
-- torque (spin=free); the depth each area wears per passage is mapped onto the profiles, spread over the
-- wheel's circumference, weighted by the cases' shares of distance, smoothed (area-preserving) and scaled so that the
-- step's largest wheel depth is step_mm; the profiles move along their normals, and the next step runs on them.
--
-- The cases: generated (a normal distribution of the lateral shift on tangent track, and curving cases with flange
-- contact on either rail: the wheelset pressed against the outer rail with given lateral forces, with the attack
-- angle and yaw rate of the curve) or a CSV table of a multibody run (cases=FILE, columns in docs/guide/wear.md).
--
--   wrc run examples/wear_evolution.lua [out=results/wear] [steps=20] [step_mm=0.1] [cases=run.csv] ...
--   wrc run examples/wear_evolution.lua --help            (lists the options)
--
-- Each step is one case of the study (one checkpoint block): a run killed and run again resumes after its last
-- finished step, recomputing the steps before it (a step's profiles are the result of all steps before it) and
-- ending with the same files, byte for byte. Shards are allowed but gain nothing: a step needs the ones before.
--
-- Writes into `out`: evolution.csv (per step: km, worn_area_mm2, Sh_mm, Sd_mm, qR_mm, tan_gamma_e_3mm,
-- max_depth_mm of the left wheel, the right wheel's and the rails' alike, the step's distance and volumes),
-- profiles.csv (every point of every profile at every step), the profiles of every step as Simpack files
-- (left_wheel_step05.prw, ...), the figures profiles_left_wheel.png (overlays), Sd_tan_gamma.png (Sd and
-- tan gamma_e against km), depth_left_wheel.png (the depth worn against the lateral position), summary.txt.
local study = require "wrc.study"
local out = require "wrc.output"
local loop = require "wrc.wear_loop"

local s = study.new{
  name = "wear_evolution",
  help = "Wheel profiles worn over mileage (Archard / KTH or USFD wear on exact rolling contact), S1002 on 60E1.",
  out = "results/wear",
  options = {
    {"wheel", "string", "profiles/s1002.lua", "wheel profile (a definition or a file)"},
    {"rail", "string", "profiles/60e1.lua", "rail profile (a definition or a file)"},
    {"cant", "number", 1 / 40, "rail inclination (1/40 = 0.025; 0 for a rail already canted in its file)", min = 0,
     max = 0.1},
    {"gauge_mm", "number", 1435, "track gauge at 14 mm below the rail top (mm)", min = 1000, max = 1700},
    {"back_to_back_mm", "number", 1360, "distance between the flange backs (mm)", min = 900, max = 1700},
    {"radius_mm", "number", 450, "nominal wheel radius (mm)", min = 150, max = 650},
    {"cases", "string", "", "CSV of running cases (y_mm, Q_kN, V_kmh, mu, share, ...); empty: generated"},
    {"steps", "integer", 20, "wear steps", min = 1, max = 10000},
    {"step_mm", "number", 0.1, "largest wheel depth worn per step (mm)", min = 1e-4, max = 2},
    {"km_end", "number", 0, "stop at this distance (km; the last step shortened; 0: after `steps`)", min = 0},
    {"scheme", "string", "heun", "time stepping: the start's rates averaged with those after an Euler step, or the " ..
     "start's alone", choices = {"heun", "euler"}},
    {"tolerance", "number", 0, "Heun's step control: the largest difference between a step's Heun and Euler " ..
     "depths, as a fraction of step_mm (0: none; 0.1 resolves the KTH map's running-in)", min = 0, max = 1},
    {"smooth_mm", "number", 1, "standard deviation of the area-preserving smoothing (mm; 0: none)", min = 0,
     max = 20},
    {"grid_mm", "number", 0.2, "element size of the contact areas (mm)", min = 0.01, max = 5},
    {"method", "string", "exact", "rolling contact solver", choices = {"exact", "fastsim"}},
    {"spin", "string", "nominal", "the wheelset's spin: omega = V / r0, or the one that balances its axle torque " ..
     "(free rolling)", choices = {"nominal", "free"}},
    {"model", "string", "archard", "wear model", choices = {"archard", "usfd"}},
    {"k", "number", 0, "Archard's constant wear coefficient (0: the KTH wear map)", min = 0, max = 1},
    {"tangent", "integer", 90, "generated cases on tangent track", min = 0},
    {"sigma_mm", "number", 1.5, "standard deviation of the lateral shift on tangent track (mm)", min = 0.01, max = 10},
    {"curve_radius_m", "number", 300, "radius of the generated curves (m; one each way)", min = 50},
    {"curve_share", "number", 0.1, "share of the distance in curves (both ways together)", min = 0, max = 1},
    {"curve_forces_kN", "string", "60,70,80,90,100", "lateral forces of the generated curving cases, one case each way " ..
     "per force (kN; comma-separated; empty: none)"},
    {"attack_mrad", "number", 2.5, "attack angle of the wheelset in the curves (mrad)", min = 0, max = 50},
    {"Q_kN", "number", 200, "wheelset load of the generated cases (kN)", min = 1, max = 1000},
    {"V_kmh", "number", 100, "speed of the generated cases (km/h)", min = 1, max = 500},
    {"mu", "number", 0.3, "friction coefficient of the generated cases", min = 0.01, max = 1},
    {"rail_passes", "number", 0, "passages of the wheelset over a rail section per km it runs (0: rails not worn)",
     min = 0},
    {"threads", "integer", 0, "worker threads of each sweep (0: all cores)", min = 0, max = 256, hash = false},
    {"plots", "boolean", true, "make the figures", hash = false},
  },
}
local opt = s.options
if opt.cases == "" and opt.tangent == 0 and (opt.curve_forces_kN:match("^%s*$") or opt.curve_share == 0) then
  error("no running cases: tangent=0 and no curving cases (curve_forces_kN, curve_share), and no cases=FILE", 0)
end
if opt.cases == "" and opt.tangent > 0 and not opt.curve_forces_kN:match("^%s*$") and opt.curve_share >= 1 then
  error("curve_share=1 leaves nothing to the tangent cases: give tangent=0 for curves alone", 0)
end

local wheel, rail = wrc.profile.load(opt.wheel, {kind = "wheel"}), wrc.profile.load(opt.rail, {kind = "rail"})
local wheelset = {grid = opt.grid_mm * 1e-3, cant = opt.cant, gauge = opt.gauge_mm * 1e-3,
                  back_to_back = opt.back_to_back_mm * 1e-3, radius = opt.radius_mm * 1e-3}
-- The set-up checked once, on a coarse grid, before any step: a wheelset that cannot be built (a rail canted in its
-- file given without cant=0, gauge and flange backs of different tracks) stops the study with wrc.wheelset's message,
-- where every step would fail with it.
do
  local probe = {}
  for k, v in pairs(wheelset) do probe[k] = v end
  probe.grid = 2e-3
  loop.wheelset(loop.initial{wheel = wheel, rail = rail, wheelset = probe})
end
local wear = {model = opt.model, k = (opt.model == "archard" and opt.k > 0) and opt.k or nil}
local step_options = {step = opt.step_mm * 1e-3, smooth = opt.smooth_mm * 1e-3, wear = wear, method = opt.method, spin = opt.spin,
                      threads = opt.threads, rail_passes = opt.rail_passes, scheme = opt.scheme,
                      tolerance = opt.tolerance > 0 and opt.tolerance * opt.step_mm * 1e-3 or nil,
                      km_end = opt.km_end > 0 and opt.km_end or nil}
local csv_cases = opt.cases ~= "" and loop.read_cases(opt.cases) or nil

-- The cases on a state's profiles: the CSV's, or generated (the curving ones pressed against the flange with their
-- lateral forces, found on the state's profiles: wear moves the flange away, the force stays; the tangent cases are
-- solved meanwhile: `early`).
local forces = {}
for f in opt.curve_forces_kN:gmatch("[^,%s]+") do
  local v = tonumber(f)
  if not v or v <= 0 or v > 500 then error("curve_forces_kN: '" .. f .. "' is not a force in ]0, 500] kN", 0) end
  forces[#forces + 1] = v * 1e3
end
local function cases_of(st, early)
  if csv_cases then return csv_cases end
  local curve_share = #forces > 0 and opt.curve_share or 0
  local curves = {}
  if curve_share > 0 then
    curves = {{radius = opt.curve_radius_m, yaw = opt.attack_mrad * 1e-3, share = curve_share / 2},
              {radius = -opt.curve_radius_m, yaw = opt.attack_mrad * 1e-3, share = curve_share / 2}}
  end
  -- Placed on a grid of at least 0.5 mm: the lateral force hardly depends on it, the equilibria cost 6 times less.
  local ws = loop.wheelset(st, {grid = math.max(opt.grid_mm, 0.5) * 1e-3})
  local Q = opt.Q_kN * 1e3
  return loop.generated_cases{
    Q = Q, V = opt.V_kmh / 3.6, mu = opt.mu, tangent = opt.tangent, sigma = opt.sigma_mm * 1e-3, curves = curves,
    forces = forces, y_for_force = function(sign, Y, yaw, from, hint) return loop.y_for_force(ws, sign, Y, yaw, Q, from, hint) end,
    previous = st.previous_cases, early = early}
end

-- The states of the loop: state k after k steps, with its measures. Kept from one compute call to the next; a run
-- resumed (or a shard) recomputes the steps before its first, which gives the same bits.
local states = {}
local function state(k)
  if states[k] then return states[k] end
  if k == 0 then
    local st = loop.initial{wheel = wheel, rail = rail, wheelset = wheelset}
    states[0] = {st = st, m = loop.measures(st, {threads = opt.threads})}
    return states[0]
  end
  local prev = state(k - 1)
  if prev.done then return prev end
  local st, info = loop.step(prev.st, cases_of, step_options)
  states[k] = {st = st, m = loop.measures(st, {threads = opt.threads}), info = info, prev = prev.st,
               done = step_options.km_end ~= nil and st.km >= step_options.km_end}
  if k >= 2 then states[k - 2] = nil end  -- the state before is kept for the step's volumes
  return states[k]
end

local columns = {"step", "km", "worn_area_mm2", "Sh_mm", "Sd_mm", "qR_mm", "tan_gamma_e_3mm", "max_depth_mm",
                 "right_worn_area_mm2", "right_Sh_mm", "right_Sd_mm", "right_qR_mm", "right_max_depth_mm",
                 "rail_worn_area_mm2", "rail_max_depth_mm", "right_rail_worn_area_mm2", "right_rail_max_depth_mm",
                 "step_km", "step_depth_mm", "volume_mm3", "archard_volume_mm3", "right_volume_mm3",
                 "right_archard_volume_mm3", "cases", "cases_failed", "points_untangled", "step_shortened"}

local function row(k, r)
  local m, st, info = r.m, r.st, r.info or {}
  local lw, rw, lr, rr = m.left_wheel, m.right_wheel, m.left_rail, m.right_rail
  local e = {step = k, km = st.km, worn_area_mm2 = lw.worn_area * 1e6, Sh_mm = lw.Sh * 1e3, Sd_mm = lw.Sd * 1e3,
             qR_mm = lw.qR * 1e3, tan_gamma_e_3mm = m.tan_gamma_e, max_depth_mm = lw.max_depth * 1e3,
             right_worn_area_mm2 = rw.worn_area * 1e6, right_Sh_mm = rw.Sh * 1e3, right_Sd_mm = rw.Sd * 1e3,
             right_qR_mm = rw.qR * 1e3, right_max_depth_mm = rw.max_depth * 1e3,
             rail_worn_area_mm2 = lr.worn_area * 1e6, rail_max_depth_mm = lr.max_depth * 1e3,
             right_rail_worn_area_mm2 = rr.worn_area * 1e6, right_rail_max_depth_mm = rr.max_depth * 1e3}
  if info.distance then
    e.step_km = info.distance / 1000
    e.step_depth_mm = info.depth.left_wheel * 1e3
    local b0, b1 = r.prev.bodies, st.bodies
    local r0 = wheelset.radius or wrc.defaults.wheelset.radius
    e.volume_mm3 = loop.volume_between(r0, b0.left_wheel.y, b0.left_wheel.z, b1.left_wheel.y, b1.left_wheel.z) * 1e9
    e.right_volume_mm3 = loop.volume_between(r0, b0.right_wheel.y, b0.right_wheel.z, b1.right_wheel.y,
                                             b1.right_wheel.z) * 1e9
    e.archard_volume_mm3, e.right_archard_volume_mm3 = info.archard.left * 1e9, info.archard.right * 1e9
    e.cases, e.cases_failed, e.points_untangled, e.step_shortened = info.cases, info.failed, info.folds, info.retries
  end
  return e
end

local function profile_rows(k, st)
  local rows = {}
  for _, name in ipairs(loop.BODIES) do
    local b = st.bodies[name]
    if name:match("wheel") or opt.rail_passes > 0 then
      for i = 1, #b.y do rows[#rows + 1] = {step = k, body = name, i = i, y_mm = b.y[i] * 1e3, z_mm = b.z[i] * 1e3} end
    end
  end
  return rows
end

-- After the merge: the profile files, the figures and the summary, from the tables.
local function finish(ctx)
  local _, ev = ctx.read("evolution.csv")
  local _, pr = ctx.read("profiles.csv")
  local by = {}
  for _, r in ipairs(pr) do
    local key = r.body .. "|" .. r.step
    by[key] = by[key] or {y = {}, z = {}, body = r.body, step = r.step}
    local t = by[key]
    t.y[#t.y + 1], t.z[#t.z + 1] = r.y_mm * 1e-3, r.z_mm * 1e-3
  end
  local keys = {}
  for key in pairs(by) do keys[#keys + 1] = key end
  table.sort(keys)
  for _, key in ipairs(keys) do
    local t = by[key]
    local kind = t.body:match("wheel") and "wheel" or "rail"
    local p = wrc.profile.points{kind = kind, y = t.y, z = t.z, name = ("%s step %d"):format(t.body, t.step)}
    ctx.write_profile(("%s_step%02d.%s"):format(t.body, t.step, kind == "wheel" and "prw" or "prr"), p)
  end
  local last = ev[#ev]
  if not last then error("no wear step was computed: every case failed (" .. ctx.dir .. "/failures.csv says why)", 0) end
  local lines = {("%d steps to %.3f km (%s cases, %d failed in the last step)"):format(last.step, last.km,
                   csv_cases and #csv_cases or "generated", last.cases_failed or 0),
                 ("left wheel: worn area %.3f mm2, largest depth %.3f mm, Sh %.3f -> %.3f mm, Sd %.3f -> %.3f mm, " ..
                  "qR %.3f -> %.3f mm"):format(last.worn_area_mm2, last.max_depth_mm, ev[1].Sh_mm, last.Sh_mm,
                                                ev[1].Sd_mm, last.Sd_mm, ev[1].qR_mm, last.qR_mm),
                 ("tan gamma_e at 3 mm: %s -> %s"):format(tostring(ev[1].tan_gamma_e_3mm),
                                                          tostring(last.tan_gamma_e_3mm))}
  local text = table.concat(lines, "\n") .. "\n"
  ctx.write("summary.txt", text)
  io.write(text)
  if not opt.plots then return end
  local series = {}
  local every = math.max(1, math.floor(#ev / 5))
  for k = 0, last.step do
    local t = by["left_wheel|" .. k]
    if t and (k % every == 0 or k == last.step) then
      local ys, zs = {}, {}
      for i = 1, #t.y do ys[i], zs[i] = t.y[i] * 1e3, t.z[i] * 1e3 end
      series[#series + 1] = {x = ys, y = zs, title = ("%.1f km"):format(ev[k + 1].km)}
    end
  end
  out.plot{file = ctx.path("profiles_left_wheel.png"), xlabel = "y (mm, from the tape circle)",
           ylabel = "z (mm, radius offset)", title = "left wheel profile worn over mileage", series = series}
  local km, sd, tan = {}, {}, {}
  for i, r in ipairs(ev) do km[i], sd[i], tan[i] = r.km, r.Sd_mm, r.tan_gamma_e_3mm or 0 / 0 end
  out.plot{file = ctx.path("Sd.png"), xlabel = "distance (km)", ylabel = "Sd (mm)",
           title = "flange thickness Sd (EN 15313) of the left wheel", series = {{x = km, y = sd, title = "Sd",
           style = "linespoints"}}}
  out.plot{file = ctx.path("tan_gamma.png"), xlabel = "distance (km)", ylabel = "tan gamma_e at 3 mm",
           title = "equivalent conicity (EN 15302, roll fixed)", series = {{x = km, y = tan, title = "tan gamma_e",
           style = "linespoints"}}}
  local dz = {}
  local t0, t1 = by["left_wheel|0"], by["left_wheel|" .. last.step]
  local xs = {}
  for i = 1, #t0.y do
    xs[i] = t0.y[i] * 1e3
    dz[i] = math.sqrt((t1.y[i] - t0.y[i]) ^ 2 + (t1.z[i] - t0.z[i]) ^ 2) * 1e3
  end
  out.plot{file = ctx.path("depth_left_wheel.png"), xlabel = "y (mm, from the tape circle)", ylabel = "depth (mm)",
           title = ("depth worn off the left wheel in %.1f km"):format(last.km), series = {{x = xs, y = dz,
           title = "normal depth"}}}
  print("results in " .. ctx.dir)
end

s:run{
  cases = opt.steps + 1, chunk_size = 1, batch = 1,
  inputs = {wheel = wheel, rail = rail, cases = opt.cases ~= "" and wrc.fs.hash_file(opt.cases) or ""},
  tables = {{key = "evolution", file = "evolution.csv", columns = columns},
            {key = "profiles", file = "profiles.csv", columns = {"step", "body", "i", "y_mm", "z_mm"}}},
  key_columns = {"step"},
  key = function(i) return {step = i - 1} end,
  compute = function(batch)
    local results = {}
    for i = batch.first, batch.last do
      local k = i - 1
      local r = state(k)
      if r.st.step < k then
        results[i] = {}  -- km_end reached before: no row
      else
        results[i] = {evolution = row(k, r), profiles = profile_rows(k, r.st)}
      end
    end
    return results
  end,
  finish = finish,
}
