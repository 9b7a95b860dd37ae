-- A profile file's points are read as the interpolating cubic spline through them unless `smooth = false` asks for the
-- polyline (docs/guide/profiles.md, "Profiles as smooth curves"). Why the default: the analytic S1002 and 60E1 sampled
-- every 0.4 mm (as coarse as exported nominal profiles are) and written to text files, against the same analytic
-- profiles sampled every 0.02 mm (a polyline that fine is the curve) as the reference: one wheel at Fz = 100 kN on the
-- tread (y = 0 and 5 mm). A polyline puts all its curvature in its vertices, so h is piecewise linear and the
-- pressure peaks at the kinks (pmax 5 % high); the spline follows the curve (within 0.5 %).
local check = require "wrc.check"
local H = dofile(os.getenv("WRC_TEST_DATA") .. "/profile/helpers.lua")
local tmp = H.tmpdir() .. "/profile_spline_default_" .. tostring(os.time()) .. "_"

local function coarse_file(def, kind)
  local path = tmp .. kind .. ".txt"
  H.write_text(path, wrc.profile.load(wrc.paths.profiles .. "/" .. def, {step = 0.4e-3}), false)
  return path
end
local wheel_file, rail_file = coarse_file("s1002.lua", "wheel"), coarse_file("60e1.lua", "rail")

local spline_w = wrc.profile.load(wheel_file, {kind = "wheel"})
local spline_r = wrc.profile.load(rail_file, {kind = "rail"})
local poly_w = wrc.profile.load(wheel_file, {kind = "wheel", smooth = false})
local poly_r = wrc.profile.load(rail_file, {kind = "rail", smooth = false})
check.ok(spline_w.smooth == 0 and spline_r.smooth == 0, "a file's points are the interpolating spline by default")
check.ok(poly_w.smooth == nil and poly_r.smooth == nil, "smooth = false keeps the polyline")
check.ok(wrc.profile.load(wheel_file, {kind = "wheel", smooth = 0.5e-3}).smooth == 0.5e-3, "smooth = l still smooths")
check.fails(function() wrc.profile.load(wheel_file, {kind = "wheel", smooth = true}) end, "smooth", "smooth = true is refused")

local ref_w = wrc.profile.load(wrc.paths.profiles .. "/s1002.lua", {step = 0.02e-3})
local ref_r = wrc.profile.load(wrc.paths.profiles .. "/60e1.lua", {step = 0.02e-3})
local function pmax(w, r, y)
  local ws = wrc.wheelset{wheel = w, rail = r, grid = 0.2e-3}
  local res = ws:wheel{side = "left", y = y, yaw = 0, roll = 0, Fz = 100e3}
  local m = 0
  for _, p in ipairs(res.patches) do m = math.max(m, p.pmax) end
  return m
end
for _, y in ipairs({0, 5e-3}) do
  local ref = pmax(ref_w, ref_r, y)
  local e_spline = pmax(spline_w, spline_r, y) / ref - 1
  local e_poly = pmax(poly_w, poly_r, y) / ref - 1
  print(string.format("y = %.0f mm: pmax %.1f MPa (0.02 mm reference); 0.4 mm points as spline %+.2f %%, polyline %+.2f %%",
                      y * 1e3, ref / 1e6, 100 * e_spline, 100 * e_poly))
  check.ok(math.abs(e_spline) < 0.005, "the spline's pmax within 0.5 % of the reference")
  check.ok(e_poly > 0.02, "the polyline's pmax more than 2 % high (the reason for the default)")
end
os.remove(wheel_file)
os.remove(rail_file)
