-- No missed area on a deliberately awkward pair: every strategy against brute force on 2000 random poses.
-- The wheel: a vertical flange back, a flange with a flat top, a hollow (concave) worn tread, an exact cylinder,
-- a vertical step down (flat ring) and a false flange lip at the field side. The rail: two crowns with a flat
-- (exactly level) saddle between them, a vertical-ish gauge face. So: two-point contacts on one wheel, lines with
-- two segments, lines lying level on the wheel's cylinder, crossings on flat rings.
local check = require "wrc.check"
local H = dofile(arg[0]:match("(.*/)") .. "geometry_helpers.lua")

local function sample(pieces, step)
  local y, z = {}, {}
  for _, p in ipairs(pieces) do
    if p.vertical then  -- a vertical run at p.y from p.z0 to p.z1
      y[#y + 1], z[#z + 1] = p.y, p.z0
      y[#y + 1], z[#z + 1] = p.y, p.z1
    else
      local n = math.max(1, math.ceil((p.y1 - p.y0) / (p.step or step)))
      for i = (#y > 0 and y[#y] == p.y0) and 1 or 0, n do
        local s = p.y0 + (p.y1 - p.y0) * i / n
        y[#y + 1], z[#z + 1] = s, p.f(s)
      end
    end
  end
  return y, z
end

-- Wheel (profile frame: z = -radius offset; flange tip at -0.026).
local function groove(s)  -- a V groove (a crack) 1 mm deep, 0.6 mm wide at s = -6 mm: yawed lines cross it twice
  return 0.001 * math.max(0, 1 - math.abs(s + 0.006) / 0.0003)
end
local wy, wz = sample({
  {vertical = true, y = -0.070, z0 = -0.008, z1 = -0.024},                                   -- flange back
  {y0 = -0.070, y1 = -0.062, f = function(s) return -0.024 - 0.002 * (s + 0.070) / 0.008 end},
  {y0 = -0.062, y1 = -0.056, f = function() return -0.026 end},                             -- flat flange top
  {y0 = -0.056, y1 = -0.040, f = function(s) return -0.026 + 0.025 * ((s + 0.056) / 0.016) ^ 2 end},
  {y0 = -0.040, y1 = -0.030, f = function(s) return -0.001 + 0.0002 * (s + 0.040) / 0.01 end},
  {y0 = -0.030, y1 = -0.008, f = function(s) return -0.0008 + 0.0006 * math.sin(math.pi * (s + 0.030) / 0.022) end}, -- hollow
  {y0 = -0.008, y1 = -0.004, f = function(s) return -0.0008 + groove(s) end, step = 0.1e-3}, -- groove
  {y0 = -0.004, y1 = 0.003, f = function() return -0.0008 end},                            -- exact cylinder
  {vertical = true, y = 0.003, z0 = -0.0008, z1 = 0.0002},                                   -- step (flat ring)
  {y0 = 0.003, y1 = 0.040, f = function(s) return 0.0002 + (s - 0.003) / 40 end},
  {y0 = 0.040, y1 = 0.046, f = function(s) return 0.001125 - 0.0008 * math.sin(math.pi * (s - 0.040) / 0.006) end}, -- false flange
  {y0 = 0.046, y1 = 0.060, f = function(s) return 0.001125 + (s - 0.046) / 20 end},
}, 1e-3)
local wheel = wrc.profile.points{kind = "wheel", name = "awkward wheel", y = wy, z = wz}

-- Rail (profile frame, z up): two crowns at -7 and +8 mm joined by an exactly level saddle, steep shoulders.
local ry, rz = sample({
  {y0 = -0.037, y1 = -0.022, f = function(v) return -0.0006 - 0.016 * ((-0.022 - v) / 0.015) ^ 1.5 end},
  {y0 = -0.022, y1 = -0.007, f = function(v) return -((v + 0.007) ^ 2) / 0.375 end},
  {y0 = -0.007, y1 = -0.004, f = function(v) return -((v + 0.007) ^ 2) / 0.05 end},
  {y0 = -0.004, y1 = 0.005, f = function() return -0.00018 end},                            -- level saddle
  {y0 = 0.005, y1 = 0.008, f = function(v) return -((v - 0.008) ^ 2) / 0.05 end},
  {y0 = 0.008, y1 = 0.030, f = function(v) return -((v - 0.008) ^ 2) / 0.6 end},
  {y0 = 0.030, y1 = 0.037, f = function(v) return -0.000807 - 0.008 * ((v - 0.030) / 0.007) ^ 2 end},
}, 1e-3)
local rail = wrc.profile.points{kind = "rail", name = "awkward rail", y = ry, z = rz}

-- The wheel's points as given (1 mm, 0.1 mm across the groove; the groove and the step survive), the rail as
-- given (1 mm).
local specs = {
  walk = {"brute", "topology"},
  coarse = {"brute", "coarse", coarse_every = 3},
  composed = {"brute", "coarse", "topology", coarse_every = 3},
}
local ws = {}
for label, spec in pairs(specs) do ws[label] = wrc.wheelset{wheel = wheel, rail = rail, strategy = spec} end
-- (The constant-slope discretisation of "fast" is compared with brute force in strategy_s1002_60e1.lua and the C++
-- tests; here one brute-force run per pose serves the three strategies, which share a discretisation.)

local cones = {left = ws.walk:cones("left"), right = ws.walk:cones("right")}
local rand = H.rng(40)
local n, two_patch, two_segment_lines, ring_ends, compared = 2000, 0, 0, 0, 0
for k = 1, n do
  local pose = H.random_pose(ws.walk, rand)
  local ref
  for label, w in pairs(ws) do
    ref = ref or w:locate{y = pose.y, z = pose.z, roll = pose.roll, yaw = pose.yaw, search = "brute"}
    local diff = H.difference(w:locate(pose), ref)
    if diff then error(("pose %d (y = %.9g, z = %.9g, roll = %.9g, yaw = %.9g), %s: %s"):format(
                        k, pose.y, pose.z, pose.roll, pose.yaw, label, diff)) end
    compared = compared + 1
  end
  for _, side in ipairs{"left", "right"} do
    local wc = cones[side]
    if #ref[side].patches >= 2 then two_patch = two_patch + 1 end
    local seen = {}
    for _, p in ipairs(ref[side].patches) do
      for _, s in ipairs(p.segments) do
        if seen[s.line] then two_segment_lines = two_segment_lines + 1 end
        seen[s.line] = true
        for _, c in ipairs(s.cones) do
          if wc.y[c] == wc.y[c + 1] then ring_ends = ring_ends + 1 end
        end
      end
    end
  end
end
print(("awkward pair: %d poses, %d results compared, %d sides with two patches, %d lines with two segments, "
       .. "%d segment ends on flat rings"):format(n, compared, two_patch, two_segment_lines, ring_ends))
check.ok(two_patch > 100, "two-point contacts are exercised")
check.ok(ring_ends > 10, "segment ends on flat rings are exercised")
check.ok(two_segment_lines > 10, "lines with two segments are exercised")
