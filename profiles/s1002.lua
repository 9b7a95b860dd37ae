-- S1002 wheel profile (ORE S1002 / UIC 510-2 / EN 13715 "S1002 / h28 / e32,5 / 6,7 %"), analytic
-- definition. Coefficients and breakpoints: the Netter/DLR coefficient set of the EN 13715 S1002
-- sections A-H. F(s) in mm is the radius offset from the tape circle (flange tip F = +28); s in mm is
-- lateral from the tape circle, + toward the field side, flange back at s = -70. Checked by
-- tests/scripts/profile_analytic.lua against the standard's nominal dimensions (flange height 28 mm,
-- thickness 32.5 mm at F = 10 mm, flank 70 deg).
--
-- Returns a wrc.Profile in the engine's left-side frame: y = s (m), z = -F(s) (m, flange tip at -0.028).
-- Options (the table passed to wrc.profile.load): step = sampling step along s in metres (default
-- 0.1e-3 as in the paper); from, to = range of s in metres (default -0.070 .. +0.060).
local opt = ... or {}
local step = opt.step or 0.1e-3
local s_from, s_to = opt.from or -0.070, opt.to or 0.060
assert(type(step) == "number" and step > 0 and step <= 0.01, "s1002: step must be a number in ]0, 0.01] m")
assert(s_from >= -0.070 and s_to <= 0.060 and s_from < s_to, "s1002: from/to must lie in [-0.070, 0.060] m")

-- Section coefficients (mm).
local AA, BA = 1.364323640, 0.066666667
local AB, BB, CB, DB, EB = 0.0, 3.358537058e-02, 1.565681624e-03, 2.810427944e-05, 5.844240864e-08
local FB, GB, HB, IB = 1.562379023e-08, 5.309217349e-15, 5.957839843e-12, 2.646656573e-13
local AC, BC, CC, DC = 4.320221063e+03, 1.038384026e+03, 1.065501873e+02, 6.051367875
local EC, FC, GC, HC = 2.054332446e-01, 4.169739389e-03, 4.687195829e-05, 2.252755540e-07
local AD, BD, CD = 16.446, 13.0, 26.210665
local AE, BE = 93.576667419, 2.747477419
local AF, BF, CF = 8.834924130, 20.0, 58.558326413
local AG, BG, CG = 16.0, 12.0, 55.0
local AH, BH, CH = 9.519259302, 20.5, 49.5

local sqrt = math.sqrt
local function circle(a, b, c, s) return sqrt(math.max(b * b - (s + c) ^ 2, 0)) end

-- F(s), s and F in mm.
local function F(s)
  if s >= 32.15796 then return AA - BA * s end                                     -- A: 1:15 outer slope
  if s >= -26.0 then                                                                -- B: tread
    return AB - BB * s + CB * s ^ 2 - DB * s ^ 3 + EB * s ^ 4 - FB * s ^ 5 + GB * s ^ 6 - HB * s ^ 7 + IB * s ^ 8
  end
  if s >= -35.0 then                                                                -- C: tread to flange root
    return -AC - BC * s - CC * s ^ 2 - DC * s ^ 3 - EC * s ^ 4 - FC * s ^ 5 - GC * s ^ 6 - HC * s ^ 7
  end
  if s >= -38.426669071 then return AD - circle(AD, BD, CD, s) end                 -- D: R13 flange root
  if s >= -39.764473993 then return -AE - BE * s end                               -- E: 70 degree flank
  if s >= -49.662510381 then return AF + circle(AF, BF, CF, s) end                 -- F: R20 flange face
  if s >= -62.764705882 then return AG + circle(AG, BG, CG, s) end                 -- G: R12 flange top
  return AH + circle(AH, BH, CH, s)                                                 -- H: R20.5 flange back
end

local n = math.floor((s_to - s_from) / step + 0.5)
assert(n + 2 <= wrc.profile.max_points, ("s1002: step = %g m gives %.0f points, more than a profile may have " ..
       "(wrc.profile.max_points = %d)"):format(step, n + 2, wrc.profile.max_points))
local y, z = {}, {}
for i = 0, n do
  local s = math.min(s_from + i * step, s_to)
  y[#y + 1] = s
  z[#z + 1] = -F(s * 1e3) * 1e-3
end
if y[#y] < s_to - 1e-12 then y[#y + 1], z[#z + 1] = s_to, -F(s_to * 1e3) * 1e-3 end

return wrc.profile.points{kind = "wheel", name = "S1002", y = y, z = z}
