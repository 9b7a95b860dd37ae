-- The paper's track (S1002 on 60E1, defaults: r0 = 0.45 m, flange backs 1.360 m, gauge 1.435 m at 14 mm,
-- cant 1:40) assembled by wrc.wheelset, checked on the placed profiles with measurements made here:
-- gauge points, tape circles, the cant direction, and z = 0 as the first touch (minimum vertical gap).
local check = require "wrc.check"
local H = dofile(os.getenv("WRC_TEST_DATA") .. "/profile/helpers.lua")

local S1002 = wrc.profile.load("profiles/s1002.lua")
local R60E1 = wrc.profile.load("profiles/60e1.lua")
local ws = wrc.wheelset{wheel = S1002, rail = R60E1}

-- Smallest vertical gap wheel - rail over the lateral overlap of two sorted polylines, taken at every
-- vertex of both (the gap of two piecewise-linear functions is extreme at a vertex of one of them).
local function min_gap(w, r)
  local g = math.huge
  for i = 1, #w.y do
    local zr = H.interp(r.y, r.z, w.y[i])
    if zr then g = math.min(g, w.z[i] - zr) end
  end
  for i = 1, #r.y do
    local zw = H.interp(w.y, w.z, r.y[i])
    if zw then g = math.min(g, zw - r.z[i]) end
  end
  return g
end

local function check_track(ws, what, gauge, depth, tape)
  local sides = {left = 1, right = -1}
  local gaps = {}
  for side, sign in pairs(sides) do
    local rail, wheel = ws[side .. "_rail"], ws[side .. "_wheel"]
    check.ok(rail.frame == "track" and wheel.frame == "wheelset", what .. ": placed profile frames")
    -- Gauge point: from the top of the placed rail toward the track centre, the first point `depth` below it.
    local top = H.argmax(rail.z)
    local toward_centre = sign > 0 and -1 or 1
    local yg = H.crossing(rail.y, rail.z, top, toward_centre, rail.z[top] - depth)
    check.near(yg, sign * gauge / 2, 1e-9, what .. ": " .. side .. " gauge point y (m)")
    check.near(ws.gauge_points[side].y, yg, 1e-9, what .. ": ws.gauge_points." .. side .. ".y")
    check.near(ws.gauge_points[side].z, rail.z[top] - depth, 1e-12, what .. ": ws.gauge_points." .. side .. ".z")
    check.near(ws.rail_top[side], rail.z[top], 1e-12, what .. ": ws.rail_top." .. side)
    -- Tape circle: where the placed tread is at radius r0 (z_w = -r0), found on the tread from the field side.
    local r0 = ws.params.radius
    local field_end = sign > 0 and #wheel.y or 1
    local yt = H.crossing(wheel.y, wheel.z, field_end, sign > 0 and -1 or 1, -r0)
    check.near(yt, sign * tape, 1e-9, what .. ": " .. side .. " tape circle y_w (m)")
    check.near(ws.tape_points[side].y, yt, 1e-9, what .. ": ws.tape_points." .. side .. ".y")
    -- Flange back at |y_w| = back_to_back / 2.
    local back = sign > 0 and wheel.y[1] or wheel.y[#wheel.y]
    check.near(math.abs(back), ws.params.back_to_back / 2, 1e-12, what .. ": " .. side .. " flange back")
    gaps[side] = min_gap(wheel, rail)
  end
  -- First touch at z = 0: the smallest gap over both sides is zero.
  check.near(math.min(gaps.left, gaps.right), 0, 1e-9, what .. ": smallest wheel-rail vertical gap at z = 0 (m)")
  return gaps
end

local gaps = check_track(ws, "paper track", 1.435, 0.014, 0.750)
-- The profiles are symmetric, so both wheels touch at once.
check.near(gaps.left, gaps.right, 1e-12, "left and right first touch together")

-- Cant: 60E1 is symmetric about its axis, so the chord between mirror-image points i and n+1-i of the
-- placed rail has the slope of the cant; the field side is the higher one (head tilted toward the centre).
local n = #R60E1
for side, sign in pairs({left = 1, right = -1}) do
  local r = ws[side .. "_rail"]
  local i, j = 50, n + 1 - 50
  local slope = (r.z[j] - r.z[i]) / (r.y[j] - r.y[i])
  check.near(slope, sign * (1 / 40), 1e-12, side .. " rail chord slope = cant (field side up)")
end

-- 60E1.txt: with this track the canted top point lies 43.03 mm field side of the gauge point, at
-- |Y| = 760.533 mm. The top of the polyline is the vertex nearest to the flat crown, so compare the
-- crown's height profile instead: z at |y| = 0.760533 is the highest to within the R300 sag of a vertex.
local lr = ws.left_rail
local ztop = H.interp(lr.y, lr.z, 0.760533)
check.near(ztop, ws.rail_top.left, 2e-8, "the canted head's top at |y| = 760.533 mm (60E1.txt)")

-- The wheelset lowered by 0.1 mm penetrates, raised by 0.1 mm it clears: the gap shifts one to one.
local lowered = {y = ws.left_wheel.y, z = {}}
for i, z in ipairs(ws.left_wheel.z) do lowered.z[i] = z - 1e-4 end
check.near(min_gap(lowered, ws.left_rail), gaps.left - 1e-4, 1e-12, "lowered wheel: gap -0.1 mm")

-- Other parameters: gauge, depth and tape circle follow.
local ws2 = wrc.wheelset{wheel = S1002, rail = R60E1, gauge = 1.445, gauge_depth = 0.016, back_to_back = 1.356, radius = 0.46}
check_track(ws2, "modified track", 1.445, 0.016, 0.748)

-- An already canted rail (the 60E1 canted 1:40 as a file would hold it) with cant = 0 gives the same
-- placed rails as the analytic rail canted by the assembly.
local pre = H.canted_60e1(0.1e-3, 0.030)
local ws3 = wrc.wheelset{wheel = S1002, rail = pre, cant = 0}
check_track(ws3, "pre-canted rail, cant = 0", 1.435, 0.014, 0.750)
local a = wrc.profile.points{kind = "rail", y = ws3.left_rail.y, z = ws3.left_rail.z}
local b = wrc.profile.points{kind = "rail", y = ws.left_rail.y, z = ws.left_rail.z}
local d = H.max_distance(a, b)
check.ok(d < 1e-7, "pre-canted and assembly-canted rails coincide (" .. d .. " m)")
print(string.format("track_paper: gauge points +/-%.6f m, tape circles +/-%.6f m, first-touch gap %.3g m",
                    ws.gauge_points.left.y, ws.tape_points.left.y, math.min(gaps.left, gaps.right)))
