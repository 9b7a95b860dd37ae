-- Rigid contact geometry and equivalent conicity (EN 15302) of three wheel/rail pairs on standard gauge (1435 mm at
-- 14 mm, flange backs 1360 mm, r0 = 450 mm):
--   S1002 / 60E1 at 1:40, S1002 / 60E1 at 1:20, and a hollow-worn S1002 read from a MiniProf file
--   (examples/data/s1002_hollow_worn.whl, made by examples/data/make_worn_wheel.lua) on 60E1 at 1:40.
--
--   wrc run examples/conicity.lua [out=results/conicity] [plots=true]      (--help lists the options)
--
-- For each pair: the rigid contact geometry table y = -10 .. 10 mm every 0.05 mm with the roll free (CSV and the
-- multibody text table), its contact-point jumps, the contact-point chart (PNG), and tan(gamma_e) against the
-- amplitude up to flange contact with the roll fixed (EN 15302's usual way) and free. Writes into `out`:
--   table_<pair>.csv, table_<pair>.txt     the geometry tables (docs/guide/geometry.md lists the columns)
--   conicity.csv                           pair, roll, yhat_mm, tan_gamma (integral method)
--   conicity.png, dr.png                   tan(gamma_e) against the amplitude; Δr against y
--   contact_<pair>.png                     the contact-point chart of the left wheel
--   summary.txt                            the jumps and tan(gamma_e) at 3 mm with and without roll
local out = require "wrc.output"
local geo = require "wrc.contact_geometry"
local study = require "wrc.study"

local opt = study.new{
  name = "conicity", out = "results/conicity",
  help = "Rigid contact geometry and EN 15302 conicity of S1002/60E1 at 1:40 and 1:20 and a hollow-worn S1002.",
  options = {{"plots", "boolean", true, "make the figures", hash = false}},
}.options
local dir, plots = opt.out, opt.plots

local s1002 = wrc.profile.load("profiles/s1002.lua")
local e60 = wrc.profile.load("profiles/60e1.lua")
-- The worn wheel is a measurement-like file (0.2 mm points, +-3 um noise): smoothed on load (smooth = 0.5 mm halves
-- waviness of 3 mm wavelength and removes the noise; docs/guide/profiles.md "Profiles as smooth curves").
-- Its file ships with the examples (wrc.paths.root/examples), found so from any working directory.
local worn = wrc.profile.load(wrc.paths.root .. "/examples/data/s1002_hollow_worn.whl", {smooth = 0.5e-3})
local pairs_ = {
  {key = "s1002_60e1_1in40", name = "S1002 / 60E1 1:40", wheel = s1002, cant = 1 / 40, colour = "#1f77b4"},
  {key = "s1002_60e1_1in20", name = "S1002 / 60E1 1:20", wheel = s1002, cant = 1 / 20, colour = "#2ca02c"},
  {key = "worn_60e1_1in40", name = "hollow-worn S1002 / 60E1 1:40", wheel = worn, cant = 1 / 40, colour = "#d62728"},
}
local yhat = {}
for a = 0.5, 8.0001, 0.25 do yhat[#yhat + 1] = a * 1e-3 end

local rows, summary = {}, {}
local tan_series, dr_series = {}, {}
for _, p in ipairs(pairs_) do
  p.ws = wrc.wheelset{wheel = p.wheel, rail = e60, cant = p.cant}
  local t = p.ws:geometry_table{y = {from = -10e-3, to = 10e-3, step = 0.05e-3}, roll = "free",
                                csv = dir .. "/table_" .. p.key .. ".csv", file = dir .. "/table_" .. p.key .. ".txt"}
  summary[#summary + 1] = ("%s: table of %d rows in %.3f s"):format(p.name, #t.rows, t.seconds)
  for _, j in ipairs(t.jumps) do
    if j.side == "left" then
      summary[#summary + 1] = ("  left contact point jumps at y = %.3f mm: %+.2f mm on the wheel (s %.2f -> %.2f mm), "
                               .. "%+.2f mm on the rail, contact angle %.1f -> %.1f deg"):format(
          0.5 * (j.y_before + j.y_after) * 1e3, j.wheel_jump * 1e3, j.before.wheel_profile.y * 1e3,
          j.after.wheel_profile.y * 1e3, j.rail_jump * 1e3, math.deg(j.before.angle), math.deg(j.after.angle))
    end
  end
  local s = geo.contact_series(t, "left")
  dr_series[#dr_series + 1] = {x = s.y, y = s.dr, title = p.name, style = ("lines lw 2 lc rgb '%s'"):format(p.colour)}
  if plots then
    geo.contact_chart(dir .. "/contact_" .. p.key .. ".png", t, "left", "contact points, " .. p.name .. " (roll free)")
  end
  for _, roll in ipairs{"fixed", "free"} do
    local c = geo.conicity_curve(p.ws, yhat, {roll = roll})
    for i = 1, #c.yhat_mm do rows[#rows + 1] = {pair = p.key, roll = roll, yhat_mm = c.yhat_mm[i], tan_gamma = c.tan[i]} end
    tan_series[#tan_series + 1] = {x = c.yhat_mm, y = c.tan, title = ("%s, roll %s"):format(p.name, roll),
                                   style = (roll == "fixed" and "linespoints lw 2 pt 7 ps 0.6" or "lines lw 2 dt 2")
                                           .. (" lc rgb '%s'"):format(p.colour)}
    local at3 = p.ws:conicity{yhat = {3e-3}, roll = roll}
    summary[#summary + 1] = ("  tan(gamma_e) at 3 mm, roll %-5s: %.4f (up to %.2f mm before flange contact)")
        :format(roll, at3[1], c.yhat_mm[#c.yhat_mm])
  end
end
out.csv(dir .. "/conicity.csv", {"pair", "roll", "yhat_mm", "tan_gamma"}, rows)
if plots then
  out.plot{file = dir .. "/conicity.png", title = "equivalent conicity (EN 15302, integral method)",
           xlabel = "amplitude of the lateral motion of the wheelset yhat (mm)", ylabel = "tan(gamma_e)", series = tan_series,
           extra = {"set key top right", "set yrange [0:*]"}}
  out.plot{file = dir .. "/dr.png", title = "rolling radius difference (roll free)", xlabel = "lateral displacement y (mm)",
           ylabel = "r_{left} - r_{right} (mm)", series = dr_series, extra = {"set key top left", "set yrange [-12:12]"},
           enhanced = true}
end
local text = table.concat(summary, "\n") .. "\n"
out.text(dir .. "/summary.txt", text)
io.write(text)
print("results in " .. dir)
