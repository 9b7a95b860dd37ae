-- Profile measures and smooth profiles (issue 11), against the analytic definitions:
--  - EN 15313 flange measures of the nominal S1002: Sh = 28 mm, Sd = 32.5 mm (the standard's nominal values) and qR
--    from the R20 flange face of the definition (section F: F = 8.834924 + sqrt(20^2 - (s + 58.558326)^2) mm at
--    F = 26 mm), computed here;
--  - p:curvature on the arcs of 60E1 (R300, R80, R13) and S1002 (R13 flange root concave, R20 face, R12 top convex);
--  - smooth = ...: the option on a Lua definition, on a file and through p:transform; resampling on the spline lies
--    closer to the analytic S1002 than resampling the polyline; on a noisy file the smoothed curvature is right;
--  - orientation warnings: a mirrored or upside-down wheel; a canted MiniProf rail read without mirror_y refused.
local check = require "wrc.check"
local out = require "wrc.output"

local wheel = wrc.profile.load("profiles/s1002.lua")
local rail = wrc.profile.load("profiles/60e1.lua")

-- Flange measures.
local m = wheel:flange_measures()
check.near(m.Sh, 0.028, 1e-7, "S1002 Sh")
check.near(m.Sd, 0.0325, 1e-7, "S1002 Sd")
local s_qr = -58.558326413 + math.sqrt(20 ^ 2 - (26 - 8.834924130) ^ 2)  -- mm, the face side of the R20 circle
check.near(m.qR, m.sd_point.y - m.qr_point.y, 1e-15, "qR from the two face points")
check.near(m.qr_point.y, s_qr * 1e-3, 1e-6, "the qR point on the R20 flange face")
check.near(m.qR, (-37.5 - s_qr) * 1e-3, 1e-6, "S1002 qR against the R20 flange face of the definition")
check.near(m.tip.y, -0.055, 0.05e-3, "flange tip at s = -55 mm")
print(("kinematics_profiles: S1002 Sh = %.4f mm, Sd = %.4f mm, qR = %.4f mm (face point at s = %.4f mm)")
      :format(m.Sh * 1e3, m.Sd * 1e3, m.qR * 1e3, s_qr))
check.near(wheel:flange_measures{tape_offset = 0.069}.Sd, 0.0315, 1e-7, "Sd follows the inner face position")
check.fails(function() rail:flange_measures() end, "not a wheel", "flange measures of a rail")
local flat = wrc.profile.points{kind = "wheel", y = {-0.05, 0, 0.05}, z = {0.001, 0, -0.001}}
check.fails(function() flat:flange_measures() end, "no flange", "a wheel without flange")

-- Curvature on the arcs.
local function radius(p, y) local _, r = p:curvature(y) return r end
for _, c in ipairs{{rail, 0, 0.300}, {rail, -0.006, 0.300}, {rail, 0.018, 0.080}, {rail, -0.015, 0.080},
                   {rail, 0.031, 0.013}, {rail, -0.033, 0.013},
                   {wheel, -0.0367, -0.013}, {wheel, -0.045, 0.020}, {wheel, -0.056, 0.012}, {wheel, -0.066, 0.0205}} do
  check.rel(radius(c[1], c[2]), c[3], 1e-3, ("%s radius at y = %g mm"):format(c[1].name, c[2] * 1e3))
end
local k, r = rail:curvature(0.0)
check.near(k * r, 1, 1e-12, "curvature and radius")
local mirrored = rail:transform{mirror_y = true}
check.near(mirrored:curvature(-0.018), rail:curvature(0.018), 1e-6, "a mirrored rail keeps its convex R80")
check.fails(function() rail:curvature(0.1) end, "outside the profile", "curvature outside")

-- smooth: on a definition, the spline kept and used to resample.
local sw = wrc.profile.load("profiles/s1002.lua", {smooth = 0})
check.ok(sw.smooth == 0 and wheel.smooth == nil, "p.smooth: the spline's smoothing length, nil for a polyline")
local rs = rail:transform{smooth = 0.2e-3}
check.ok(rs.smooth == 0.2e-3 and #rs == #rail, "p:transform{smooth = ...} fits a smoothing spline")
check.rel(radius(rs, 0.018), 0.080, 1e-3, "a lightly smoothed 60E1 keeps its R80")
check.ok(sw.transforms[#sw.transforms]:find("interpolating cubic spline", 1, true), "smoothing is recorded in transforms")
local fine = wrc.profile.load("profiles/s1002.lua", {step = 0.01e-3})  -- the analytic S1002, close to exact
local fy, fz = fine:points()
local function deviation(p)  -- largest and rms distance of p's points from the fine profile, on the flange
  local y, z = p:points()
  local worst, sum, n = 0, 0, 0
  for i = 1, #y do
    if y[i] > -0.062 and y[i] < -0.036 then
      local best = math.huge
      local j0 = math.floor((y[i] + 0.070) / 0.01e-3)
      for j = math.max(1, j0 - 200), math.min(#fy - 1, j0 + 200) do
        local dy, dz = fy[j + 1] - fy[j], fz[j + 1] - fz[j]
        local t = math.max(0, math.min(1, ((y[i] - fy[j]) * dy + (z[i] - fz[j]) * dz) / (dy * dy + dz * dz)))
        best = math.min(best, math.sqrt((fy[j] + t * dy - y[i]) ^ 2 + (fz[j] + t * dz - z[i]) ^ 2))
      end
      worst = math.max(worst, best)
      sum, n = sum + best * best, n + 1
    end
  end
  return worst, math.sqrt(sum / n)
end
local lin, lin_rms = deviation(wheel:resample{step = 0.07e-3})
local spl, spl_rms = deviation(sw:resample{step = 0.07e-3})
print(("kinematics_profiles: S1002 resampled every 0.07 mm from its 0.1 mm points, distance from the curve on the "
       .. "flange: polyline %.3f um max, %.4f um rms; spline %.3f um max (at the R13/flank tangent point), %.4f um rms")
      :format(lin * 1e6, lin_rms * 1e6, spl * 1e6, spl_rms * 1e6))
check.ok(spl < lin and spl_rms < 0.2 * lin_rms, "resampling the spline follows the curve more closely than the polyline")

-- smooth on a noisy file: the R13 flange root's curvature.
local dir = (arg.tmp or os.getenv("WRC_TEST_TMP") or "/tmp") .. "/kinematics_profiles"
out.mkdir(dir)
local wy, wz = wrc.profile.load("profiles/s1002.lua", {step = 0.1e-3}):points()
local f = assert(io.open(dir .. "/noisy.txt", "w"))
local seed = 7
for i = 1, #wy do
  seed = (seed * 1103515245 + 12345) % 2147483648
  f:write(("%.6f %.6f\n"):format(wy[i] * 1e3, wz[i] * 1e3 + (seed / 2147483648 - 0.5) * 0.004))  -- +-2 um
end
f:close()
local noisy = wrc.profile.load(dir .. "/noisy.txt", {kind = "wheel"})
local smoothed = wrc.profile.load(dir .. "/noisy.txt", {kind = "wheel", smooth = 0.5e-3})
check.ok(math.abs(radius(noisy, -0.045) / 0.020 - 1) > 0.2, "the noisy polyline's curvature is noise")
check.rel(radius(smoothed, -0.045), 0.020, 0.05, "smooth = 0.5 mm: the R20 flange face of a noisy file")
check.rel(radius(smoothed, -0.056), 0.012, 0.05, "smooth = 0.5 mm: the R12 flange top of a noisy file")
check.fails(function() wrc.profile.load(dir .. "/noisy.txt", {kind = "wheel", smooth = -1}) end, "smooth = -1",
            "a negative smoothing length")

-- Orientation.
check.ok(#wheel.warnings == 0 and #rail.warnings == 0, "the analytic profiles look right")
local back = wrc.profile.load("profiles/s1002.lua", {mirror_y = true})
check.ok(back.warnings[1] and back.warnings[1]:find("looks mirrored", 1, true), "a mirrored wheel is reported")
local flipped = wrc.profile.load("profiles/s1002.lua", {mirror_z = true})
check.ok(flipped.warnings[1] and flipped.warnings[1]:find("upside down", 1, true), "an upside-down wheel is reported")
local samples = os.getenv("WRC_TEST_DATA") .. "/profile/samples/"
check.fails(function() wrc.profile.load(samples .. "60e1_canted.ban") end, "Pass mirror_y = true",
            "a canted MiniProf rail without mirror_y is refused")
check.ok(#wrc.profile.load(samples .. "60e1_canted.ban", {mirror_y = true}).warnings == 0, "with mirror_y it is not")
check.ok(#wrc.profile.load(samples .. "s1002.whl").warnings == 0, "the MiniProf wheel looks right")
local down = wrc.profile.load("profiles/60e1.lua", {mirror_z = true})
check.ok(down.warnings[1] and down.warnings[1]:find("upside down", 1, true), "an upside-down rail is reported")
