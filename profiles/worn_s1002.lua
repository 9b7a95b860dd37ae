-- A synthetic worn S1002 wheel: the S1002 of profiles/s1002.lua (same frame: y = s from the tape circle, + toward the
-- field side; z = -F, the flange tip at z = -0.028) with two kinds of wear of fixed shape and given depth.
--
--   Hollow tread: the radius is reduced by w(s) = hollow * cos^2(pi (s - 5 mm) / 60 mm) for |s - 5 mm| < 30 mm
--     (0 outside): a running band from s = -25 mm (the flange root) to s = +35 mm worn deepest 5 mm field-side of the
--     tape circle, so that the tread becomes concave (a hollow) with a false flange toward the field side.
--   Flange wear: the flange face is moved toward the back of the wheel by `flange` (m), i.e. the flange is thinned by
--     that much at its measuring height: z_worn(s) = z(s + flange * psi(s)), with psi = 1 on the face from s = -52 mm
--     (3 mm from the flange tip at s = -55 mm) to s = -35 mm (the end of the R13 root, 6.9 mm above the tape
--     circle), rising smoothly from 0 at the tip and falling smoothly to 0 at s = -28 mm, 0 elsewhere. The flange height (Sh) stays and Sd
--     drops by `flange` (EN 15313 measures, on an unworn tread); qR stays while its point (2 mm below the tip) is on
--     the shifted face (flange up to about 3 mm).
--   Both remove material only (the worn radius is never larger), and s is unchanged, so the profile stays valid.
--
-- Options (the table passed to wrc.profile.load): hollow (m, 0 .. 5e-3, default 0), flange (m, 0 .. 10e-3, default 0),
-- step (m, default 0.1e-3), name (default "S1002 worn h<hollow mm> f<flange mm>").
local opt = ... or {}
local hollow, flange = opt.hollow or 0, opt.flange or 0
assert(type(hollow) == "number" and hollow >= 0 and hollow <= 5e-3, "worn_s1002: hollow must be in [0, 5e-3] m")
assert(type(flange) == "number" and flange >= 0 and flange <= 10e-3, "worn_s1002: flange must be in [0, 10e-3] m")
local base = wrc.profile.load("profiles/s1002.lua", {step = opt.step or 0.1e-3})  -- the shipped S1002
local y, z = base:points()

local function smoothstep(a, b, s)  -- 0 at a, 1 at b, C1
  local x = math.min(1, math.max(0, (s - a) / (b - a)))
  return x * x * (3 - 2 * x)
end
local function psi(s)
  if s <= -0.055 or s >= -0.028 then return 0 end
  if s < -0.052 then return smoothstep(-0.055, -0.052, s) end
  if s <= -0.035 then return 1 end
  return 1 - smoothstep(-0.035, -0.028, s)
end
local function hollow_depth(s)
  local u = (s - 0.005) / 0.060
  if math.abs(u) >= 0.5 then return 0 end
  return hollow * math.cos(math.pi * u) ^ 2
end

-- z of the unworn profile at s, linear between its points (0.1 mm apart: within 0.1 um of the analytic arcs).
local k = 1
local function z_at(s)
  while k > 1 and y[k] > s do k = k - 1 end
  while k < #y - 1 and y[k + 1] < s do k = k + 1 end
  local f = (s - y[k]) / (y[k + 1] - y[k])
  return z[k] + f * (z[k + 1] - z[k])
end

local wz = {}
for i, s in ipairs(y) do
  local shift = flange * psi(s)
  wz[i] = (shift > 0 and z_at(s + shift) or z[i]) + hollow_depth(s)
end
local name = opt.name or string.format("S1002 worn h%.2f f%.2f", hollow * 1e3, flange * 1e3)
return wrc.profile.points{kind = "wheel", name = name, y = y, z = wz}
