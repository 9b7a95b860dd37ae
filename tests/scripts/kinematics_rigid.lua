-- Rigid contact geometry (issue 11), S1002 / 60E1 at 0.1 mm, 1:40, gauge 1435 mm, against computations written here:
--  1. every contact point (two-point contact included) against an independent 2-D computation of the gap function
--     over the rail lines in the section x = 0 (yaw 0: it holds the axle), with its own search for separate minima;
--  2. roll fixed at 0: each wheel's touching height is the highest of z_r + R(y_r - y) over the rail lines;
--  3. the zero-yaw section path against the 3-D path at a yaw of 1e-9 rad;
--  4. the lateral curvature radii at the contact points against the analytic arcs of both profiles;
--  5. a wheel with no rail under it is reported lifted, with no radius, angle or Δr;
--  6. geometry tables: the jumps (the positions on both sides), 1 and 2 threads alike, CSV and text files read back;
--  7. bad input.
local check = require "wrc.check"
local out = require "wrc.output"

local wheel = wrc.profile.load("profiles/s1002.lua")
local rail = wrc.profile.load("profiles/60e1.lua")
local ws = wrc.wheelset{wheel = wheel, rail = rail}
local TOL = 1e-6  -- the default two_point_tolerance (m)

-- The gap of every rail line of one side at a zero-yaw pose: the line point in the wheelset frame (A = Rx(roll)),
-- its distance below the axle against the wheel radius there (the cone polyline, linear between its points).
local function section_gaps(side, g)
  local cones, lines = ws:cones(side), ws:lines(side)
  local c, s = math.cos(g.roll), math.sin(g.roll)
  local n = #cones.y
  local gaps = {}
  local k = 2
  for r = 1, #lines.y do
    local dy, dz = lines.y[r] - g.y, lines.z[r] - g.z
    local Y, Z = c * dy + s * dz, -s * dy + c * dz
    if Y < cones.y[2] or Y > cones.y[n - 1] then
      gaps[r] = math.abs(Z)
    else
      while k > 2 and cones.y[k] > Y do k = k - 1 end
      while k < n - 2 and cones.y[k + 1] < Y do k = k + 1 end
      local a = cones.y[k + 1] > cones.y[k] and (Y - cones.y[k]) / (cones.y[k + 1] - cones.y[k]) or 0
      local radius = -(cones.z[k] + a * (cones.z[k + 1] - cones.z[k]))
      gaps[r] = math.abs(Z) - radius
    end
  end
  return gaps
end

-- Separate minima of a gap function within tol of zero: local minima, then any two kept ones need a ridge rising
-- more than tol above the shallower between them.
local function separate_minima(gaps, tol)
  local cand = {}
  for r = 1, #gaps do
    local left = r == 1 or gaps[r] <= gaps[r - 1]
    local right = r == #gaps or gaps[r] <= gaps[r + 1]
    if left and right and gaps[r] <= tol then cand[#cand + 1] = r end
  end
  table.sort(cand, function(a, b) return gaps[a] < gaps[b] end)
  local kept = {}
  for _, c in ipairs(cand) do
    local ok = true
    for _, k in ipairs(kept) do
      local ridge = -math.huge
      for r = math.min(c, k), math.max(c, k) do ridge = math.max(ridge, gaps[r]) end
      if ridge <= gaps[c] + tol then ok = false end
    end
    if ok then kept[#kept + 1] = c end
  end
  return kept
end

-- 1. Contact points against the section, at y every 0.25 mm and at the jumps (where two-point contact is exact).
local t = ws:geometry_table{y = {from = -9e-3, to = 9e-3, step = 0.25e-3}, threads = 1, progress = false}
local ys = {}
for _, r in ipairs(t.rows) do ys[#ys + 1] = r.y end
check.ok(#t.jumps >= 4, "jumps found on both wheels (tread to flange root, flange root to flange face), got " .. #t.jumps)
for _, j in ipairs(t.jumps) do ys[#ys + 1] = 0.5 * (j.y_before + j.y_after) end
local two_point_seen, compared = 0, 0
for _, y in ipairs(ys) do
  local g = ws:rigid{y = y}
  check.ok(g.converged, ("rigid contact at y = %.4f mm"):format(y * 1e3))
  for _, side in ipairs{"left", "right"} do
    local gaps = section_gaps(side, g)
    local mins = separate_minima(gaps, TOL)
    local w = g[side]
    check.ok(#w.contacts == #mins, ("y = %.5f mm, %s: %d contact points, the section has %d"):format(y * 1e3, side,
             #w.contacts, #mins))
    check.ok(w.two_point == (#mins > 1), "two_point flag")
    for i, c in ipairs(w.contacts) do
      check.ok(c.line == mins[i], ("y = %.5f mm, %s point %d: line %d, the section's %d"):format(y * 1e3, side, i, c.line, mins[i]))
      check.near(c.gap, math.max(0, gaps[mins[i]]), 1e-11, "gap of the contact point")
      -- Located between the lines: within half a line spacing of its line.
      local lines = ws:lines(side)
      check.ok(math.abs(c.point.y - lines.y[c.line]) <= 0.5 * 0.1e-3 + 1e-12, "the point lies within half a spacing of its line")
      compared = compared + 1
    end
    if #mins > 1 then two_point_seen = two_point_seen + 1 end
  end
end
check.ok(two_point_seen >= #t.jumps, ("two-point contact at every jump (%d wheels, %d jumps)"):format(two_point_seen, #t.jumps))
print(("kinematics_rigid: %d contact points in %d poses as the 2-D section has them, %d two-point wheels")
      :format(compared, #ys, two_point_seen))

-- 2. Roll fixed at 0: each wheel's touching height, and the rolling radius at its deepest line.
for _, y in ipairs{-7e-3, -2.5e-3, 0, 1e-3, 4e-3, 6.5e-3} do
  local g = ws:rigid{y = y, roll = "fixed"}
  check.ok(g.converged and g.roll == 0 and g.roll_mode == "fixed", "roll fixed at 0")
  local zs = {}
  for _, side in ipairs{"left", "right"} do
    local cones, lines = ws:cones(side), ws:lines(side)
    local best, at = -math.huge, nil
    for r = 1, #lines.y do
      local Y = lines.y[r] - y
      for k = 2, #cones.y - 2 do
        if cones.y[k] <= Y and Y <= cones.y[k + 1] and cones.y[k + 1] > cones.y[k] then
          local R = -(cones.z[k] + (Y - cones.y[k]) / (cones.y[k + 1] - cones.y[k]) * (cones.z[k + 1] - cones.z[k]))
          if lines.z[r] + R > best then best, at = lines.z[r] + R, R end
          break
        end
      end
    end
    check.near(g[side].z, best, 1e-12, ("y = %g mm: %s touching height"):format(y * 1e3, side))
    check.near(g[side].rolling_radius, at, 1e-12, ("y = %g mm: %s rolling radius at the deepest line"):format(y * 1e3, side))
    zs[side] = best
  end
  check.near(g.z, math.max(zs.left, zs.right), 1e-15, "the wheelset rests on the higher touching height")
  check.near(g.left.gap + g.right.gap, math.abs(zs.left - zs.right), 1e-15, "the other wheel's clearance")
  check.near(g.rolling_radius_difference, g.left.contacts[1].rolling_radius - g.right.contacts[1].rolling_radius, 1e-15, "Δr")
end

-- 3. The zero-yaw section against the 3-D search (yaw 1e-9 rad): the same contact within rounding.
for _, y in ipairs{-6e-3, 0.5e-3, 3e-3, 6e-3} do
  local a, b = ws:rigid{y = y}, ws:rigid{y = y, yaw = 1e-9}
  check.near(b.z, a.z, 1e-11, "z, 2-D section vs 3-D search")
  check.near(b.roll, a.roll, 1e-9, "roll, 2-D section vs 3-D search")
  check.near(b.rolling_radius_difference, a.rolling_radius_difference, 1e-9, "Δr, 2-D section vs 3-D search")
  check.ok(b.left.line == a.left.line and b.right.line == a.right.line, "the same touching lines")
end
local yawed = ws:rigid{y = 3e-3, yaw = 0.01}
check.ok(yawed.converged and math.abs(yawed.left.contacts[1].point.x) > 1e-4, "with yaw the contact point leaves x = 0")

-- 4. Curvature radii at the contact points against the arcs of the definitions (60E1: R300 crown to |y| = 10.228
--    mm, R80 to 26.03 mm, R13 to 36.0 mm; S1002: R13 flange root s = -38.43 .. -35, R20 flange face -49.66 .. -39.76),
--    0.3 mm away from the tangent points (the interpolating spline rounds the curvature step over a few points). The
--    rigid contact reaches the crown, both R80 and R13 rail arcs and the R20 flange face; it jumps over the R13 flange
--    root (from s = -33.4 to -40.0 mm at y = 6.27 mm).
local function arc_of_rail(yr)
  local a = math.abs(yr) * 1e3
  if a < 9.9 then return 0.300 elseif a > 10.55 and a < 25.7 then return 0.080 elseif a > 26.35 and a < 35.7 then return 0.013 end
end
local function arc_of_wheel(s)
  s = s * 1e3
  if s > -38.1 and s < -35.3 then return -0.013 elseif s > -49.3 and s < -40.1 then return 0.020 end
end
local seen = {}
local fine = ws:geometry_table{y = {from = -8e-3, to = 8e-3, step = 0.05e-3}, progress = false}
for _, r in ipairs(fine.rows) do
  for _, side in ipairs{"left", "right"} do
    local c = r[side].contacts[1]
    local R = arc_of_rail(c.rail_profile.y)
    if R then
      check.rel(c.rail_lateral_radius, R, 5e-3, ("rail radius at y_rail = %.2f mm"):format(c.rail_profile.y * 1e3))
      seen["rail " .. R] = (seen["rail " .. R] or 0) + 1
    end
    local W = arc_of_wheel(c.wheel_profile.y)
    if W then
      check.rel(c.wheel_lateral_radius, W, 5e-3, ("wheel radius at s = %.2f mm"):format(c.wheel_profile.y * 1e3))
      seen["wheel " .. W] = (seen["wheel " .. W] or 0) + 1
    end
  end
end
for _, key in ipairs{"rail 0.3", "rail 0.08", "rail 0.013", "wheel 0.02"} do
  check.ok((seen[key] or 0) > 0, "contact points on the " .. key .. " m arc")
end
local parts = {}
for k, v in pairs(seen) do parts[#parts + 1] = ("%s m: %d"):format(k, v) end
table.sort(parts)
print("kinematics_rigid: curvature radii checked on the arcs (" .. table.concat(parts, ", ") .. ")")

-- 5. A wheel with no rail under it: a narrow wheel (s = -10 .. 40 mm, a 1:40 cone) shifted 60 mm to the left.
local narrow_y, narrow_z = {}, {}
for s = -10, 40, 0.5 do narrow_y[#narrow_y + 1], narrow_z[#narrow_z + 1] = s * 1e-3, s * 1e-3 / 40 end
local narrow = wrc.profile.points{kind = "wheel", name = "narrow cone", y = narrow_y, z = narrow_z}
local wn = wrc.wheelset{wheel = narrow, rail = rail}
local lifted = wn:rigid{y = 0.06, roll = "fixed"}
check.ok(lifted.converged and lifted.left.lifted and not lifted.right.lifted, "the left wheel has no rail under it: lifted")
check.ok(lifted.left.rolling_radius == nil and lifted.left.angle == nil and lifted.left.contacts == nil, "a lifted wheel has no radius, angle or contact")
check.ok(lifted.rolling_radius_difference == nil, "no Δr with a lifted wheel")
local free = wn:rigid{y = 0.06}
check.ok(not free.converged and free.error:find("does not touch", 1, true), "roll free: no pose with both wheels on their rails: " .. tostring(free.error))

-- 6. Tables: jumps, threads, files.
for _, j in ipairs(fine.jumps) do
  check.ok(j.y_after - j.y_before <= 1.1e-8, "a jump is bracketed to 1e-8 m")
  local a, b = ws:rigid{y = j.y_before}, ws:rigid{y = j.y_after}
  local ca, cb = a[j.side].contacts[1], b[j.side].contacts[1]
  check.near(cb.wheel_profile.y - ca.wheel_profile.y, j.wheel_jump, 1e-9, "the jump along the wheel, recomputed")
  check.ok(math.abs(j.wheel_jump) > 0.5e-3, "a jump moves the contact point by more than 0.5 mm")
end
local two = ws:geometry_table{y = {from = -8e-3, to = 8e-3, step = 0.05e-3}, threads = 2, progress = false}
check.ok(#two.rows == #fine.rows and #two.jumps == #fine.jumps, "2 threads: the same rows and jumps")
for i, r in ipairs(two.rows) do
  check.near(r.z, fine.rows[i].z, 1e-12, "z, 1 vs 2 threads")
  check.near(r.rolling_radius_difference, fine.rows[i].rolling_radius_difference, 1e-12, "Δr, 1 vs 2 threads")
end
local dir = (arg.tmp or os.getenv("WRC_TEST_TMP") or "/tmp") .. "/kinematics_rigid"
out.mkdir(dir)
local small = ws:geometry_table{y = {from = -3e-3, to = 3e-3, step = 0.5e-3}, csv = dir .. "/table.csv",
                                file = dir .. "/table.txt", progress = false}
local cols, rows = out.read_csv(dir .. "/table.csv")
check.ok(#rows == #small.rows and cols[1] == "yaw_deg" and cols[6] == "dr_mm", "CSV rows and columns")
for i, row in ipairs(rows) do
  check.near(row.y_mm, small.rows[i].y * 1e3, 1e-9, "CSV y")
  check.near(row.dr_mm, small.rows[i].rolling_radius_difference * 1e3, 1e-9, "CSV Δr")
  check.near(row.left_angle_deg, math.deg(small.rows[i].left.contacts[1].angle), 1e-7, "CSV contact angle")
end
local f = assert(io.open(dir .. "/table.txt"))
local data = {}
for line in f:lines() do
  if line:sub(1, 1) ~= "#" then
    local v = {}
    for x in line:gmatch("%S+") do v[#v + 1] = tonumber(x) end
    data[#data + 1] = v
  end
end
f:close()
check.ok(#data == #small.rows, "text table: one row per y")
for i, v in ipairs(data) do
  check.ok(#v == 34, "text table: 34 columns")
  local r = small.rows[i]
  check.near(v[1], r.y, 1e-15, "text y")
  check.near(v[4], r.rolling_radius_difference, 1e-12, "text Δr")
  check.near(v[5] - v[6], v[4], 1e-12, "text rL - rR = dr")
  check.near(v[9], r.left.contacts[1].wheel_profile.y, 1e-12, "text sL")
end

-- 7. Bad input.
check.fails(function() ws:rigid{y = 0, roll = "tilted"} end, "'roll' must be \"free\"", "roll mode misspelt")
check.fails(function() ws:rigid{y = 0, roll = 0.5} end, "roll = 0.5 rad must be finite and within +-0.1", "roll out of range")
check.fails(function() ws:rigid{y = 0, two_point_tolerance = -1} end, "two_point_tolerance", "negative tolerance")
check.fails(function() ws:geometry_table{y = {3e-3, 1e-3}} end, "y must increase strictly", "unsorted table")
check.fails(function() ws:geometry_table{y = {1e-3}, start = {z = 0}} end, "'start' does not apply", "start in a table")
check.fails(function() ws:geometry_table{y = {from = -1e-3, to = 1e-3, step = 1e-4}, file = "/nonexistent/x.txt"} end,
            "cannot write", "unwritable file")
check.fails(function() wn:geometry_table{y = {0.05, 0.06}, roll = "fixed", file = dir .. "/lifted.txt", progress = false} end,
            "has no contact on both wheels", "a multibody table needs both wheels")
