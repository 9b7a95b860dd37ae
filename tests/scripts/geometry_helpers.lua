-- Helpers shared by the geometry/strategy Lua tests (loaded with dofile from the tests' own folder). Run on its
-- own it checks itself on a trivial case.
local H = {}

-- Deterministic pseudo-random numbers (a 64-bit LCG), so that the tests do not depend on math.random's seeding.
function H.rng(seed)
  local s = seed
  return function(a, b)
    s = (s * 6364136223846793005 + 1442695040888963407) & 0x7fffffffffffffff
    local u = (s >> 11) / (1 << 52)
    return a + (b - a) * u
  end
end

-- Rail height of a placed rail profile (track frame, y increasing) at y, nil outside.
local function rail_height(ry, rz, y)
  if y < ry[1] or y > ry[#ry] then return nil end
  local lo, hi = 1, #ry
  while hi - lo > 1 do
    local mid = (lo + hi) // 2
    if ry[mid] <= y then lo = mid else hi = mid end
  end
  if ry[hi] == ry[lo] then return math.max(rz[lo], rz[hi]) end
  local a = (y - ry[lo]) / (ry[hi] - ry[lo])
  return rz[lo] + a * (rz[hi] - rz[lo])
end
H.rail_height = rail_height

-- Smallest vertical gap (wheel above rail, m) of one side at lateral position y and roll (yaw ignored): the rigid
-- 2-D section in the plane x = 0, which contains the axle when yaw = 0. Also returns where it is (track y).
function H.vertical_gap(ws, side, y, roll)
  local w, r = ws[side .. "_wheel"], ws[side .. "_rail"]
  local c, s = math.cos(roll), math.sin(roll)
  local best, at = math.huge, nil
  for i = 1, #w.y do
    -- wheelset-frame point (0, yw, zw) -> track frame (0, y + c yw - s zw, s yw + c zw) for A = Rx(roll)
    local ty, tz = y + c * w.y[i] - s * w.z[i], s * w.y[i] + c * w.z[i]
    local h = rail_height(r.y, r.z, ty)
    if h and tz - h < best then best, at = tz - h, ty end
  end
  return best, at
end

-- A random pose as in the issue: |y| <= 10 mm, |yaw| <= 30 mrad, |roll| <= 10 mrad, deepest penetration (yaw ignored)
-- log-uniform in [1 um, 1 mm].
function H.random_pose(ws, rand)
  local p = {y = rand(-0.010, 0.010), yaw = rand(-0.030, 0.030), roll = rand(-0.010, 0.010)}
  local depth = math.exp(rand(math.log(1e-6), math.log(1e-3)))
  local gl = H.vertical_gap(ws, "left", p.y, p.roll)
  local gr = H.vertical_gap(ws, "right", p.y, p.roll)
  p.z = -math.min(gl, gr) - depth
  return p
end

-- nil if two contact results hold the same patches and segments (lines, cones, ends within 1e-9 m), else a message.
function H.difference(a, b)
  for _, side in ipairs{"left", "right"} do
    local pa, pb = a[side].patches, b[side].patches
    if #pa ~= #pb then return ("%s side: %d patches vs %d"):format(side, #pa, #pb) end
    for i = 1, #pa do
      local sa, sb = pa[i].segments, pb[i].segments
      if #sa ~= #sb then return ("%s side, patch %d: %d segments vs %d"):format(side, i, #sa, #sb) end
      for k = 1, #sa do
        local x, y = sa[k], sb[k]
        if x.line ~= y.line or x.cones[1] ~= y.cones[1] or x.cones[2] ~= y.cones[2] or math.abs(x.x_t - y.x_t) > 1e-9
           or math.abs(x.x_l - y.x_l) > 1e-9 then
          return ("%s side, patch %d, segment %d: line %d [%.12g, %.12g] cones %d/%d vs line %d [%.12g, %.12g] cones %d/%d")
                 :format(side, i, k, x.line, x.x_t, x.x_l, x.cones[1], x.cones[2], y.line, y.x_t, y.x_l, y.cones[1], y.cones[2])
        end
      end
    end
  end
  return nil
end

-- Self-check when run as a test.
if arg and arg[0] and arg[0]:find("geometry_helpers%.lua$") then
  local r = H.rng(1)
  for _ = 1, 100 do
    local v = r(2, 3)
    assert(v >= 2 and v < 3, "rng out of range")
  end
  assert(H.rail_height({0, 1}, {0, 2}, 0.25) == 0.5, "rail_height")
  assert(H.rail_height({0, 1}, {0, 2}, 2) == nil, "rail_height outside")
end

return H
