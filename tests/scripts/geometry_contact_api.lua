-- ws:locate{...} and the discretisation as seen from Lua (docs/design.md, section 5): fields, symmetry, units, the
-- default strategy, counters and bad input.
local check = require "wrc.check"

local wheel = wrc.profile.load(wrc.paths.profiles .. "/s1002.lua")
local rail = wrc.profile.load(wrc.paths.profiles .. "/60e1.lua")
local ws = wrc.wheelset{wheel = wheel, rail = rail}

-- The default strategy.
check.ok(ws.strategy.name == "accurate", "the default strategy is 'accurate'")
check.ok(ws.strategy.portable, "the default strategy runs in worker threads")
check.ok(ws:coarse("left") ~= nil and ws:coarse("left").dilation > 0, "the default strategy has a coarse level")

-- Discretisation: closed wheel (first/last points on the axle), lines in increasing y, mirror images.
local cl, cr = ws:cones("left"), ws:cones("right")
check.ok(cl.count == #cl.y - 1, "cones = points - 1")
check.near(cl.z[1], 0, 0, "closing point on the axle")
check.near(cl.z[#cl.z], 0, 0, "closing point on the axle")
check.near(cl.y[1], cl.y[2], 0, "the first cone is a flat disc")
check.near(cl.y[2], -cr.y[#cr.y - 1], 1e-15, "the right wheel mirrors the left")
local ll = ws:lines("left")
for i = 2, #ll.y do check.ok(ll.y[i] >= ll.y[i - 1], "lines ordered by y") end

-- A centred pose: one patch per wheel, mirror images of each other, the tread contact near the tape circle.
local c = ws:locate{y = 0, z = -0.1e-3}
check.ok(#c.left.patches == 1 and #c.right.patches == 1, "one patch per wheel when centred")
local pl, pr = c.left.patches[1], c.right.patches[1]
check.near(pl.nominal_point.y, -pr.nominal_point.y, 1e-12, "mirror: nominal points")
check.near(pl.nominal_point.z, pr.nominal_point.z, 1e-12, "mirror: nominal heights")
check.near(pl.nominal_point.x, 0, 1e-12, "zero yaw: nominal point at x = 0")
check.near(pl.nominal_normal.y, -pr.nominal_normal.y, 1e-12, "mirror: normals")
check.near(math.sqrt(pl.nominal_normal.x ^ 2 + pl.nominal_normal.y ^ 2 + pl.nominal_normal.z ^ 2), 1, 1e-12, "unit normal")
check.ok(pl.nominal_normal.z < -0.99, "tread contact: the wheel's outward normal points down")
check.near(pl.depth, 0.1e-3, 2e-6, "depth of the nominal point ~ the 0.1 mm the wheelset is pressed in")
check.ok(math.abs(pl.nominal_point.y - 0.75) < 0.01, "tread contact within 10 mm of the tape circle")
check.ok(pl.side == "left" and pr.side == "right", "patch side")
check.ok(#pl.segments == #pr.segments, "mirror: segment counts")
local longest = pl.segments[pl.longest]
for _, s in ipairs(pl.segments) do
  check.ok(s.x_t <= s.x_l, "x_t <= x_l")
  check.ok(s.x_l - s.x_t <= longest.x_l - longest.x_t, "longest segment")
  check.ok(s.line >= pl.first_line and s.line <= pl.last_line, "line range")
  check.near(s.y, ll.y[s.line], 0, "segment y is its line's")
  check.ok(s.cones[1] >= 1 and s.cones[1] <= cl.count and s.cones[2] >= 1 and s.cones[2] <= cl.count, "cone indices")
end
check.near(pl.nominal_point.x, 0.5 * (longest.x_t + longest.x_l), 1e-15, "nominal point = mid-point of the longest segment")
check.near(pl.nominal_point.y, longest.y, 0, "nominal point on the longest segment's line")
check.near(pl.wheel_radius, 0.45 - 0.0, 2e-3, "wheel radius near r0 on the tread")
check.ok(c.tests > 0 and c.left.tests > 0 and c.right.tests > 0, "test counts")
check.ok(ws.tests.total == c.tests, "ws.tests after ws:locate")
check.near(c.pose.z, -0.1e-3, 0, "pose echoed")

-- Brute force on the same discretisation: every line against every cone.
local b = ws:locate{y = 0, z = -0.1e-3, search = "brute"}
check.ok(b.tests == 2 * cl.count * ll.count, "brute force tests every pair")
check.ok(c.tests * 100 < b.tests, "the default strategy tests two orders of magnitude fewer pairs")

-- No contact above the rails.
local up = ws:locate{y = 0, z = 1e-3}
check.ok(#up.left.patches == 0 and #up.right.patches == 0, "no patch when lifted")

-- Yaw moves the left flange contact ahead (x > 0) when the wheelset is pushed left: the classic lead.
local yawed = ws:locate{y = 8e-3, z = -0.1e-3, yaw = 0.01}
local lead = false
for _, p in ipairs(yawed.left.patches) do if p.nominal_point.x > 1e-3 then lead = true end end
check.ok(lead, "flange contact leads with positive yaw")

-- Bad input.
check.fails(function() ws:locate{y = 0, z = 0, pitch = 1} end, "unknown key 'pitch'", "unknown pose key")
check.fails(function() ws:locate{y = 0 / 0} end, "'y' must be finite", "NaN pose")
check.fails(function() ws:locate{yaw = 1} end, "yaw = 1 rad must be finite and within +-0.3 rad", "too much yaw")
check.fails(function() ws:locate{search = "fastest"} end, "'search' must be one of", "unknown search")
check.fails(function() ws:cones("middle") end, "side must be", "bad side")
