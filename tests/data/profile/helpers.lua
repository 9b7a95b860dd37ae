-- Helpers of the profile, track and contact tests (loaded with dofile from WRC_TEST_DATA, or relative to the
-- script): geometry measured on polylines, writers of sample files in each reader's format (written here,
-- independently of the readers, from the analytic profiles), and the Hertzian pairs of the contact tests.
local H = {}

-- Distance (m) from (y, z) to the polyline ys, zs (sorted by y): nearest segment, searched outward from
-- the segment that brackets y until the lateral distance alone exceeds the best found.
function H.distance(ys, zs, y, z)
  local n = #ys
  local lo, hi = 1, n
  while hi - lo > 1 do
    local mid = (lo + hi) // 2
    if ys[mid] <= y then lo = mid else hi = mid end
  end
  local best = math.huge
  local function seg(i)
    local ay, az, by, bz = ys[i], zs[i], ys[i + 1], zs[i + 1]
    local dy, dz = by - ay, bz - az
    local L2 = dy * dy + dz * dz
    local t = L2 > 0 and ((y - ay) * dy + (z - az) * dz) / L2 or 0
    t = math.max(0, math.min(1, t))
    local ey, ez = ay + t * dy - y, az + t * dz - z
    return math.sqrt(ey * ey + ez * ez)
  end
  local i = lo
  while i >= 1 and i < n do
    best = math.min(best, seg(i))
    if y - ys[i] > best then break end
    i = i - 1
  end
  i = lo + 1
  while i < n do
    best = math.min(best, seg(i))
    if ys[i] - y > best then break end
    i = i + 1
  end
  return best
end

-- Largest distance (m) of the points of profile a (restricted by keep(y, z) when given) to profile b,
-- with the worst point.
function H.max_distance(a, b, keep)
  local ay, az = a:points()
  local by, bz = b:points()
  local worst, wy, wz, n = 0, nil, nil, 0
  for i = 1, #ay do
    if not keep or keep(ay[i], az[i]) then
      n = n + 1
      local d = H.distance(by, bz, ay[i], az[i])
      if d > worst then worst, wy, wz = d, ay[i], az[i] end
    end
  end
  return worst, wy, wz, n
end

-- Index of the largest z.
function H.argmax(zs)
  local k = 1
  for i = 2, #zs do if zs[i] > zs[k] then k = i end end
  return k
end

-- Walking from index `from` in direction `dir` (+1/-1), the first y where z crosses `level`
-- (linear interpolation between the two points around the crossing), and the index reached.
function H.crossing(ys, zs, from, dir, level)
  local i = from
  while i + dir >= 1 and i + dir <= #ys do
    local j = i + dir
    if (zs[i] - level) * (zs[j] - level) <= 0 and zs[i] ~= zs[j] then
      local t = (level - zs[i]) / (zs[j] - zs[i])
      return ys[i] + t * (ys[j] - ys[i]), i
    end
    i = j
  end
  error(string.format("no crossing of z = %.6f walking from point %d in direction %d", level, from, dir), 2)
end

-- Piecewise-linear z at y of sorted arrays (nil outside).
function H.interp(ys, zs, y)
  if y < ys[1] or y > ys[#ys] then return nil end
  local lo, hi = 1, #ys
  while hi - lo > 1 do
    local mid = (lo + hi) // 2
    if ys[mid] <= y then lo = mid else hi = mid end
  end
  if ys[hi] == ys[lo] then return zs[lo] end
  local t = (y - ys[lo]) / (ys[hi] - ys[lo])
  return zs[lo] + t * (zs[hi] - zs[lo])
end

-- The analytic 60E1 canted 1:40 (field side up, as on the track) with the origin moved to the highest
-- point of the canted head, as files of canted rails define it (tests/data/profile/samples/60e1_canted.prr;
-- the Manchester benchmark's UIC60 .prr does the same). The R300 crown centre sits 300 mm below
-- the uncanted top; after the rotation the circle's top is at (300 sin a, 300 (1 - cos a)).
function H.canted_60e1(step, depth)
  local rail = wrc.profile.load("profiles/60e1.lua", {step = step or 0.02e-3, depth = depth or 0.030})
  local a = math.atan(1 / 40)
  local c, s = math.cos(a), math.sin(a)
  local ty, tz = 0.300 * s, 0.300 * (1 - c)
  local y0, z0 = rail:points()
  local ys, zs = {}, {}
  for i = 1, #y0 do
    ys[i] = c * y0[i] - s * z0[i] - ty
    zs[i] = s * y0[i] + c * z0[i] - tz
  end
  return wrc.profile.points{kind = "rail", name = "60E1 canted 1:40", y = ys, z = zs}
end

-- Hertzian pairs of the contact tests. A wheel of conicity `slope` (radius r0 - slope s, s in [-70, 60] mm every
-- mm); slope 0: a cylinder (z exactly 0).
function H.cone_wheel(slope)
  local y, z = {}, {}
  for k = 0, 130 do
    local s = -0.070 + k * 1e-3
    y[#y + 1], z[#z + 1] = s, slope == 0 and 0.0 or slope * s
  end
  return wrc.profile.points{kind = "wheel", y = y, z = z, name = slope == 0 and "cylinder" or "cone"}
end

-- A rail crowned by a circular arc of lateral radius R (m), top at y = z = 0, points `step` apart out to
-- +-half_width (m): the rail lines themselves under strategy {"coarse", "topology"} (which does not resample).
function H.crowned_rail(R, half_width, step)
  local y, z = {}, {}
  local n = math.floor(half_width / step + 0.5)
  for k = -n, n do
    local yk = k * step
    y[#y + 1], z[#z + 1] = yk, math.sqrt(R * R - yk * yk) - R
  end
  return wrc.profile.points{kind = "rail", y = y, z = z, name = string.format("crown R%.0f", R * 1e3)}
end

-- A wheelset of a wheel on the crowned rail of radius R, cant 0, its crown (rail profile y = 0) under the tape
-- circle (y = 0.75): the gauge point is on the gauge side of the crown, o.gauge_depth below its top. o: radius,
-- gauge_depth, E, nu, grid, surface (nil: the default). A test body on a test rail, whose gauge leaves its flanges
-- more play than any track (check_setup = false).
function H.crown_wheelset(wheel, rail, R, o)
  local yg = math.sqrt(R * R - (R - o.gauge_depth) ^ 2)
  return wrc.wheelset{wheel = wheel, rail = rail, radius = o.radius, cant = 0, gauge_depth = o.gauge_depth,
                      gauge = 2 * (0.75 - yg), E = o.E, nu = o.nu, grid = o.grid, surface = o.surface,
                      strategy = {"coarse", "topology"}, check_setup = false}
end

local function write(path, text)
  local f = assert(io.open(path, "w"))
  f:write(text)
  f:close()
  return path
end
H.write = write

-- Simpack file: points given in the engine frame (m) are written as the file's raw data, so that the
-- file's own processing keys (`keys`: y_sign, inversion, shift_y, shift_z, units) bring them back.
-- Raw point = (y_sign * y * u - shift_y, -z * u - shift_z) with u = units (file units per metre).
function H.write_simpack(path, p, o)
  o = o or {}
  local u = o.units or 1000
  local ys, zs = p:points()
  local ysign = o.mirror_y and -1 or 1
  local sy, sz = o.shift_y or 0, o.shift_z or 0
  local out = {
    "! written by the wrc tests\n",
    "  header.begin\n    version = 1\n",
    string.format("    type = %d  ! 0=rail, 1=wheel\n", p.kind == "wheel" and 1 or 0),
    "  header.end\n  spline.begin\n",
    "    comment = 'wrc test sample ! not a comment'\n",
    "    point.dist.min = 0\n",
    string.format("    shift.y = %.17g\n    shift.z = %.17g\n", sy, sz),
    "    rotate = 0\n    bound.y.min = 1\n    bound.y.max = 0\n    bound.z.min = 1\n    bound.z.max = 0\n",
    string.format("    mirror.y = %d\n    mirror.z = 0\n    inversion = %d\n", o.mirror_y and 1 or 0, o.inversion and 1 or 0),
    string.format("    units.len.f = %+.15e\n    units.ang.f = 1\n", u),
    "    point.begin\n    ! y z\n",
  }
  local first, last, step = 1, #ys, 1
  if o.inversion then first, last, step = #ys, 1, -1 end
  for i = first, last, step do
    -- Undo, in reverse order, what the reader will apply: units, inversion (order above), mirror, shift.
    local y, z = ysign * ys[i] * u - sy, -zs[i] * u - sz
    out[#out + 1] = string.format("%.9E\t%.9E\n", y, z)
  end
  out[#out + 1] = "    point.end\n  spline.end\n"
  return write(path, table.concat(out))
end

-- MiniProf file. Rails: X = x_sign * y, Y = y_sign * z (mm); wheels: X = s + 70, Y = -z (toward the flange tip).
function H.write_miniprof(path, p, o)
  o = o or {}
  local ys, zs = p:points()
  local rows = {}
  for i = 1, #ys do
    local X, Y
    if p.kind == "wheel" then
      X, Y = ys[i] * 1e3 + 70, -zs[i] * 1e3
    else
      X, Y = (o.x_sign or 1) * ys[i] * 1e3, (o.y_sign or 1) * zs[i] * 1e3
    end
    rows[#rows + 1] = string.format("%s%.7E\t%.7E", (i % 7 == 0) and '"' or ' ', X, Y)
  end
  local head = string.format("Filename=%s\nMPTypeNo=299\nXYPoints=%d\nChars=Win\nRefPoint1=0.0000, 0.0000\nColumnDef=X,Y\n\n",
                             path:match("[^/]+$"), o.xypoints or #rows)
  return write(path, head .. table.concat(rows, "\n") .. "\n")
end

-- Plain text: y z in mm (engine frame), with a `y_mm,z_mm` header when `csv`.
function H.write_text(path, p, csv)
  local ys, zs = p:points()
  local out = {csv and "y_mm,z_mm\n" or "# y z (mm)\n"}
  for i = 1, #ys do
    out[#out + 1] = string.format(csv and "%.9f,%.9f\n" or "%.9f %.9f\n", ys[i] * 1e3, zs[i] * 1e3)
  end
  return write(path, table.concat(out))
end

-- The steepest part of a left wheel profile's flange face, from its points: the steepest slope on the gauge side
-- (rad) and the tip-side end of the part within 1 deg of it (profile y, m).
function H.steepest_flange(wheel)
  local wy, wz = wheel:points()
  local steepest, steep_y = 0, nil
  for i = 1, #wy - 1 do
    if wy[i + 1] <= 0 then steepest = math.max(steepest, math.atan(wz[i + 1] - wz[i], wy[i + 1] - wy[i])) end
  end
  for i = 1, #wy - 1 do
    if wy[i + 1] <= 0 and wy[i] > -0.05 and math.atan(wz[i + 1] - wz[i], wy[i + 1] - wy[i]) >= steepest - math.rad(1) then
      steep_y = steep_y or wy[i]
    end
  end
  return steepest, steep_y
end

-- Whether a string of `list` holds `pattern` (plain text).
function H.has(list, pattern)
  for _, t in ipairs(list) do if t:find(pattern, 1, true) then return true end end
  return false
end

function H.tmpdir()
  local d = (arg and arg.tmp) or os.getenv("WRC_TEST_TMP") or "/tmp"
  return d
end

return H
