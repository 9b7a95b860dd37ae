-- 60E1 (ex UIC 60) rail head, EN 13674-1: R300 crown, R80 and R13 arcs, 1:20 flanks. Tangent points
-- from the standard (|y| = 10.228 and 26.0265 mm, i.e. the chords 20.456 and 52.053 mm of its drawing);
-- the arc centres follow from tangency, so the profile is tangent-continuous. Checked by
-- tests/scripts/profile_analytic.lua (head width 72 mm where the R13 meets the flank).
--
-- Returns a wrc.Profile in the engine's rail frame: y lateral (m, + toward the field side), z up (m),
-- origin at the top of the uncanted head. Options: step = sampling step along the arc in metres
-- (default 0.1e-3); depth = how far the flanks go below the top in metres (default 0.030).
local opt = ... or {}
local step = opt.step or 0.1e-3
local depth = opt.depth or 0.030
assert(type(step) == "number" and step > 0 and step <= 0.01, "60e1: step must be a number in ]0, 0.01] m")
assert(depth > 0.0143 and depth <= 0.036, "60e1: depth must lie in ]0.0143, 0.036] m (the flanks end at the head)")

-- Work in mm with z DOWN (as the standard draws it) for the right half y >= 0, then mirror.
local sqrt, atan, cos, sin = math.sqrt, math.atan, math.cos, math.sin
local R1, R2, R3 = 300.0, 80.0, 13.0
local y12, y23 = 10.228, 26.0265
local c1 = {0.0, R1}                                  -- R300 centre (y, zdown)
local t12 = {y12, R1 - sqrt(R1 * R1 - y12 * y12)}     -- R300/R80 tangent point
local function toward(c, t, r_from, r_to)             -- centre of an inner tangent circle
  local k = (r_from - r_to) / r_from
  return {c[1] + k * (t[1] - c[1]), c[2] + k * (t[2] - c[2])}
end
local c2 = toward(c1, t12, R1, R2)
local t23 = {y23, c2[2] - sqrt(R2 * R2 - (y23 - c2[1]) ^ 2)}
local c3 = toward(c2, t23, R2, R3)
-- R13 ends where its tangent has the flank inclination 1:20 (|y| grows 1 per 20 down).
local flank = atan(1 / 20)
local t34 = {c3[1] + R3 * cos(flank), c3[2] - R3 * sin(flank)}
local zdown_end = depth * 1e3
local y_end = t34[1] + (zdown_end - t34[2]) / 20

-- Angles of the points on each arc, measured from the centre: polar angle phi with (y, zdown) =
-- c + r (sin phi, -cos phi); phi grows along the profile from the crown to the field side.
local function angle(c, p) return atan(p[1] - c[1], c[2] - p[2]) end
local pieces = {
  {arc = true, c = c1, r = R1, a0 = 0, a1 = angle(c1, t12)},
  {arc = true, c = c2, r = R2, a0 = angle(c2, t12), a1 = angle(c2, t23)},
  {arc = true, c = c3, r = R3, a0 = angle(c3, t23), a1 = angle(c3, t34)},
  {arc = false, p0 = t34, p1 = {y_end, zdown_end}},
}
local total = 0
for _, pc in ipairs(pieces) do
  pc.len = pc.arc and pc.r * (pc.a1 - pc.a0) or sqrt((pc.p1[1] - pc.p0[1]) ^ 2 + (pc.p1[2] - pc.p0[2]) ^ 2)
  total = total + pc.len
end
local function point_at(u)  -- arc length u (mm) from the crown
  for _, pc in ipairs(pieces) do
    if u <= pc.len or pc == pieces[#pieces] then
      if pc.arc then
        local a = pc.a0 + math.min(u, pc.len) / pc.r
        return pc.c[1] + pc.r * sin(a), pc.c[2] - pc.r * cos(a)
      end
      local f = math.min(u / pc.len, 1)
      return pc.p0[1] + f * (pc.p1[1] - pc.p0[1]), pc.p0[2] + f * (pc.p1[2] - pc.p0[2])
    end
    u = u - pc.len
  end
end

local n = math.max(1, math.ceil(total / (step * 1e3) - 1e-9))
assert(2 * n + 1 <= wrc.profile.max_points, ("60e1: step = %g m gives %.0f points, more than a profile may have " ..
       "(wrc.profile.max_points = %d)"):format(step, 2 * n + 1, wrc.profile.max_points))
local hy, hz = {}, {}
for i = 0, n do hy[i], hz[i] = point_at(total * i / n) end

local y, z = {}, {}
for i = n, 1, -1 do y[#y + 1], z[#z + 1] = -hy[i] * 1e-3, -hz[i] * 1e-3 end  -- gauge side (y < 0)
for i = 0, n do y[#y + 1], z[#z + 1] = hy[i] * 1e-3, -hz[i] * 1e-3 end       -- crown and field side

return wrc.profile.points{kind = "rail", name = "60E1", y = y, z = z}
