-- A profile file whose points scatter as measurement noise does is loaded with a warning that names the file, the
-- scatter and the remedy (a smoothing length), and the warning's claim holds: on S1002 against 60E1 the scattered
-- points raise pmax where the same points loaded with smooth = 0.5e-3 give the clean profile's
-- (wrc/profile/scatter.hpp). The reference is the analytic S1002 written with 1 nm resolution.
--   - 1 um of Gaussian scatter added to z (every 0.1 mm): one warning, whose estimate is within 20 % of the 1 um;
--     none with smooth = 0.5e-3, none after p:transform{smooth = 0.5e-3}, none for the clean file, none for it
--     every 2 mm; one for it written with 1 um resolution; the same for the points given as arrays
--     (wrc.profile.points), whose remedy is its key smooth;
--   - one wheel at Fz = 100 kN, y = 0, 3 and 6.5 mm, 0.5 mm grid: the scattered points' pmax more than 5 % above the
--     clean profile's at some pose, the smoothed ones within 3 % at every pose.
local check = require "wrc.check"
local H = dofile(os.getenv("WRC_TEST_DATA") .. "/profile/helpers.lua")
local tmp = H.tmpdir() .. "/profile_scatter_" .. tostring(os.time()) .. "_"

local s1002 = wrc.profile.load(wrc.paths.profiles .. "/s1002.lua")
local rail = wrc.profile.load(wrc.paths.profiles .. "/60e1.lua")
local ys, zs = s1002:points()

math.randomseed(7)
local function gauss() return math.sqrt(-2 * math.log(1 - math.random())) * math.cos(2 * math.pi * math.random()) end
-- Every `every`-th point of S1002 in mm with `decimals`, scatter (m) added to z.
local function write(path, scatter, every, decimals)
  local rows, row = {}, ("%%.%df %%.%df"):format(decimals or 6, decimals or 6)
  for i = 1, #ys, every or 1 do rows[#rows + 1] = row:format(ys[i] * 1e3, (zs[i] + scatter * gauss()) * 1e3) end
  return H.write(path, table.concat(rows, "\n") .. "\n")
end
local clean_file, noisy_file = write(tmp .. "clean.txt", 0), write(tmp .. "noisy.txt", 1e-6)
check.ok(#wrc.profile.load(write(tmp .. "coarse.txt", 0, 20), {kind = "wheel"}).warnings == 0,
         "S1002 every 2 mm: its curvature's change is not taken for scatter")
check.ok(#wrc.profile.load(write(tmp .. "rounded.txt", 0, 1, 3), {kind = "wheel"}).warnings == 1,
         "S1002 written with 1 um resolution (a scatter of 0.29 um): warned of")

local clean = wrc.profile.load(clean_file, {kind = "wheel"})
local noisy = wrc.profile.load(noisy_file, {kind = "wheel"})
local smoothed = wrc.profile.load(noisy_file, {kind = "wheel", smooth = 0.5e-3})
check.ok(#clean.warnings == 0, "the clean file: no warning")
check.ok(#noisy.warnings == 1, "the scattered file: one warning")
local w = noisy.warnings[1]
for _, part in ipairs{noisy_file, "smooth = 0.5e-3", "points every 0.1 mm"} do
  check.ok(w:find(part, 1, true), "the warning names " .. part .. ": " .. w)
end
local um = tonumber(w:match("scatter by about ([%d.]+) um"))
check.rel(um, 1.0, 0.2, "the warning's scatter (um) against the 1 um added")
check.ok(#smoothed.warnings == 0, "smooth = 0.5e-3: no warning")
check.ok(#noisy:transform{smooth = 0.5e-3}.warnings == 0, "smoothed by transform: the warning goes")
check.ok(#noisy:transform{shift = {z = 1e-3}}.warnings == 1, "moved by transform: the warning stays")
local cropped = noisy:transform{crop = {y = {-0.05, 0.05}}}
check.ok(#cropped.warnings == 1 and #cropped:transform{smooth = 0.5e-3}.warnings == 0,
         "cropped, the warning stays; then smoothed, it goes")

-- The same points given as arrays (wrc.profile.points, a polyline through them as given): the same warning, its
-- remedy the key smooth of wrc.profile.points, which takes the warning away; the clean points are not warned of.
local function read_points(path)
  local y, z = {}, {}
  for line in io.lines(path) do
    local a, b = line:match("(%S+) (%S+)")
    y[#y + 1], z[#z + 1] = tonumber(a) * 1e-3, tonumber(b) * 1e-3
  end
  return y, z
end
local ny, nz = read_points(noisy_file)
local given = wrc.profile.points{kind = "wheel", y = ny, z = nz, name = "given"}
check.ok(#given.warnings == 1 and given.warnings[1]:find("Make it with a smoothing length, smooth = 0.5e-3", 1, true),
         "scattered points given as arrays: the warning, its remedy smooth: " .. tostring(given.warnings[1]))
check.rel(tonumber(given.warnings[1]:match("scatter by about ([%d.]+) um")), um, 1e-9, "the file's estimate")
local given_smooth = wrc.profile.points{kind = "wheel", y = ny, z = nz, smooth = 0.5e-3}
check.ok(#given_smooth.warnings == 0 and given_smooth.smooth == 0.5e-3, "smooth = 0.5e-3: a spline, no warning")
local cy, cz = read_points(clean_file)
check.ok(#wrc.profile.points{kind = "wheel", y = cy, z = cz}.warnings == 0, "the clean points: no warning")

local function pmax(wheel, y)
  local ws = wrc.wheelset{wheel = wheel, rail = rail, grid = 0.5e-3}
  local c, m = ws:wheel{side = "left", y = y, Fz = 100e3}, 0
  for _, p in ipairs(c.patches) do m = math.max(m, p.pmax) end
  return m
end
local worst = 0
for _, y in ipairs{0, 3e-3, 6.5e-3} do
  local ref, raw, fixed = pmax(clean, y), pmax(noisy, y), pmax(smoothed, y)
  print(("y = %.1f mm: pmax clean %.1f MPa, scattered %+.1f %%, smoothed %+.1f %%"):format(y * 1e3, ref / 1e6,
        (raw / ref - 1) * 100, (fixed / ref - 1) * 100))
  worst = math.max(worst, raw / ref - 1)
  check.rel(fixed, ref, 0.03, ("y = %g mm: the smoothed points' pmax against the clean profile's"):format(y * 1e3))
end
check.ok(worst > 0.05, ("the scattered points raise pmax by more than 5 %% somewhere (%.1f %%)"):format(worst * 100))
