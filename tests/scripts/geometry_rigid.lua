-- Rigid contact points of the paper's track (S1002 / 60E1 at 0.1 mm, cant 1/40, gauge 1435 mm): pressed 0.5 um
-- past first touch, each wheel's inter-penetration area must sit where an independent 2-D minimum-distance
-- computation (written here, on the placed profiles, not the engine's search) puts the rigid contact point:
-- the nominal contact point within 0.2 mm of it. Zero yaw, so the plane x = 0 holds the axle and the section
-- is exact; rolls of 0 and +-5 mrad, lateral shifts of -10 .. +10 mm. (Much smaller penetrations can fall between
-- two rail lines on a steep flange face: the method sees the rail at its lines, 0.1 mm apart along the arc.)
local check = require "wrc.check"
local H = dofile(arg[0]:match("(.*/)") .. "geometry_helpers.lua")

local wheel = wrc.profile.load(wrc.paths.profiles .. "/s1002.lua")
local rail = wrc.profile.load(wrc.paths.profiles .. "/60e1.lua")

-- Smallest vertical gap and where: at the vertices of both polylines (the gap of two piecewise-linear graphs is
-- smallest at a vertex of one of them). Returns the gap and the rail point (y, z) there.
-- The profiles are the wheelset's own discretisation (ws:cones without the two closing points on the axle, and
-- ws:lines), so that both sides see the same polylines.
local function rigid_point(ws, side, y, roll)
  local cones, r = ws:cones(side), ws:lines(side)
  local w = {y = {}, z = {}}
  for i = 2, #cones.y - 1 do w.y[#w.y + 1], w.z[#w.z + 1] = cones.y[i], cones.z[i] end
  local c, s = math.cos(roll), math.sin(roll)
  local ty, tz = {}, {}
  for i = 1, #w.y do ty[i], tz[i] = y + c * w.y[i] - s * w.z[i], s * w.y[i] + c * w.z[i] end
  local best, by, bz = math.huge, nil, nil
  for i = 1, #ty do  -- wheel vertices over the rail
    local h = H.rail_height(r.y, r.z, ty[i])
    if h and tz[i] - h < best then best, by, bz = tz[i] - h, ty[i], h end
  end
  for i = 1, #r.y do  -- rail vertices under the wheel
    local h = H.rail_height(ty, tz, r.y[i])
    if h and h - r.z[i] < best then best, by, bz = h - r.z[i], r.y[i], r.z[i] end
  end
  return best, by, bz
end

local depth = tonumber(arg.depth) or 0.5e-6
local worst, cases = 0, 0
for _, strategy in ipairs{"fast", "topology"} do
  local ws = wrc.wheelset{wheel = wheel, rail = rail, strategy = strategy}
  for _, roll in ipairs{0, 5e-3, -5e-3} do
    for k = -10, 10 do
      local y = k * 1e-3
      for _, side in ipairs{"left", "right"} do
        local gap, ry, rz = rigid_point(ws, side, y, roll)
        local c = ws:locate{y = y, z = -gap - depth, roll = roll, yaw = 0}
        local patches = c[side].patches
        check.ok(#patches >= 1, ("%s side in contact at y = %g mm, roll = %g"):format(side, y * 1e3, roll))
        -- The deepest patch (largest depth at its nominal point).
        local deepest = patches[1]
        for _, p in ipairs(patches) do if p.depth > deepest.depth then deepest = p end end
        local d = math.sqrt((deepest.nominal_point.y - ry) ^ 2 + (deepest.nominal_point.z - rz) ^ 2)
        if d > worst then worst = d end
        cases = cases + 1
        if d > 0.2e-3 then
          error(("%s, %s side, y = %g mm, roll = %g: nominal point (%.6f, %.6f) is %.3f mm from the rigid contact point "
                 .. "(%.6f, %.6f)"):format(strategy, side, y * 1e3, roll, deepest.nominal_point.y, deepest.nominal_point.z, d * 1e3, ry, rz))
        end
        check.near(deepest.nominal_point.x, 0, 1e-9, "zero yaw: the nominal point is at x = 0")
      end
    end
  end
end
print(("%d rigid contact points: nominal points within %.4f mm of the 2-D minimum-distance points"):format(cases, worst * 1e3))
