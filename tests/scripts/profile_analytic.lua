-- The analytic profiles measured on their points: S1002 flange height, thickness and flank angle
-- (EN 13715), 60E1 head width (EN 13674-1). Each dimension is measured here by interpolation on the
-- profile's polyline and compared with the standard's nominal value to 0.01 mm.
local check = require "wrc.check"
local H = dofile(os.getenv("WRC_TEST_DATA") .. "/profile/helpers.lua")

-- S1002 as the paper uses it (0.1 mm step), loaded by path relative to wrc.paths.root.
local w = wrc.profile.load("profiles/s1002.lua")
check.ok(w.kind == "wheel" and w.name == "S1002", "S1002 is a wheel profile named S1002")
local y, z = w:points()
local b = w:bounds()
check.near(b.y_min, -0.070, 1e-12, "S1002 starts at the flange back s = -70 mm")
local z_tape = w:interpolate(0.0)

-- Flange tip: the lowest point, refined by the parabola through it and its two neighbours.
local k = 1
for i = 2, #z do if z[i] < z[k] then k = i end end
local y0, y1, y2, z0, z1, z2 = y[k - 1], y[k], y[k + 1], z[k - 1], z[k], z[k + 1]
local denom = (y0 - y1) * (y0 - y2) * (y1 - y2)
local A = (y2 * (z1 - z0) + y1 * (z0 - z2) + y0 * (z2 - z1)) / denom
local B = (y2 * y2 * (z0 - z1) + y1 * y1 * (z2 - z0) + y0 * y0 * (z1 - z2)) / denom
local C = z1 - A * y1 * y1 - B * y1
local y_tip = -B / (2 * A)
local z_tip = C - B * B / (4 * A)
check.near(z_tape - z_tip, 0.028, 1e-5, "S1002 flange height above the tape circle (m)")
check.near(y_tip, -0.055, 0.05e-3, "S1002 flange tip at s = -55 mm")

-- Flange thickness: from the flange back (s = -70) to the flank point 10 mm above the tape circle,
-- found walking from the tip toward the tread.
local y_face, i_face = H.crossing(y, z, k, 1, z_tape - 0.010)
check.near(y_face, -0.0375, 1e-5, "S1002 flank point at F = 10 mm (s, m)")
check.near(y_face - b.y_min, 0.0325, 1e-5, "S1002 flange thickness (m)")

-- Flank angle: the steepest chord between the tip and the F = 10 mm point (the straight flank E lies there).
local steepest = 0
for i = k, i_face do
  steepest = math.max(steepest, math.abs((z[i + 1] - z[i]) / (y[i + 1] - y[i])))
end
check.near(math.deg(math.atan(steepest)), 70.0, 0.01, "S1002 flank angle (degrees)")

-- The definition takes its options: a coarser step and a shorter range.
local coarse = wrc.profile.load("profiles/s1002.lua", {step = 0.5e-3, from = -0.060, to = 0.050})
check.ok(#coarse == 221, "S1002 at 0.5 mm from -60 to +50 mm has 221 points, got " .. #coarse)
check.near(coarse:interpolate(0.010), w:interpolate(0.010), 2e-7, "coarse and fine S1002 agree on the tread")
check.fails(function() wrc.profile.load("profiles/s1002.lua", {step = -1}) end, "s1002: step must be",
            "a definition's own validation reaches the caller")

-- 60E1: head width 72 mm at 14.3 mm below the top (R13/flank tangent points), and the width at the
-- gauge depth 14 mm, still on the R13 arcs (centres at |y| = 23.016 mm, 14.949 mm below the top):
-- 2 (23.016 + sqrt(13^2 - 0.949^2)) = 71.963 mm.
local r = wrc.profile.load("profiles/60e1.lua")
check.ok(r.kind == "rail", "60E1 is a rail profile")
local ry, rz = r:points()
local top = H.argmax(rz)
check.near(rz[top], 0, 1e-12, "60E1 origin at the top of the head")
local function width(depth)
  local yl = H.crossing(ry, rz, top, -1, rz[top] - depth)
  local yr = H.crossing(ry, rz, top, 1, rz[top] - depth)
  return yr - yl
end
check.near(width(0.0143), 0.072, 1e-5, "60E1 head width 14.3 mm below the top (m)")
check.near(width(0.014), 0.071963, 1e-5, "60E1 head width 14 mm below the top (m)")

-- Resampling keeps the shape: along the arc at 0.25 mm every point lies on the original polyline.
local ra = r:resample{step = 0.25e-3, along = "arc"}
local worst = H.max_distance(ra, r)
check.ok(worst < 1e-9, "arc-resampled 60E1 lies on the original polyline (" .. worst .. " m)")
check.near(ra:arc_length(), r:arc_length(), 1e-5, "arc-resampled 60E1 keeps its length")
local yr_ = w:resample{step = 1e-3, along = "y"}
check.ok(#yr_ == 131, "S1002 resampled along y every mm has 131 points, got " .. #yr_)
check.near(yr_:interpolate(-0.040), w:interpolate(-0.040), 1e-12, "y-resampled S1002 at a sample point")
check.ok(yr_.transforms[#yr_.transforms]:find("resampled along y", 1, true), "resampling is recorded in transforms")
check.fails(function() w:resample{step = 0} end, "step", "resample with step 0")
check.fails(function() w:resample{step = 1e-3, along = "x"} end, "'along' must be", "resample along x")
check.fails(function() w:interpolate(0.2) end, "outside the profile", "interpolate outside the profile")
print(string.format("profile_analytic: S1002 flange height %.4f mm, thickness %.4f mm, flank %.4f deg; "
                    .. "60E1 width %.4f mm at 14.3 mm, %.4f mm at 14 mm",
                    (z_tape - z_tip) * 1e3, (y_face - b.y_min) * 1e3, math.deg(math.atan(steepest)),
                    width(0.0143) * 1e3, width(0.014) * 1e3))
