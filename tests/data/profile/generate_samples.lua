-- Writes the sample profile files of tests/data/profile/samples/ (see the README there):
--
--   wrc run tests/data/profile/generate_samples.lua [out=<folder>]
--
-- Each file holds the analytic S1002 wheel (profiles/s1002.lua, EN 13715) or 60E1 rail head
-- (profiles/60e1.lua, EN 13674-1), sampled every 0.5 mm, in the orientation, units and header layout
-- that the format has in files met in practice, so that the reader plugins are tested on realistic
-- files: Simpack processing keys with their numbered comments, MiniProf `Key=Value` headers, points
-- marked with `"`, an extra column. Numbers are written with 8 significant digits, as those files do.
-- The files are committed; rerun this script only when a definition or a file's layout changes.
local here = (arg[0] or ""):match("^(.*)/[^/]*$") or "."
local H = dofile(here .. "/helpers.lua")
local out = arg.out or (here .. "/samples")
wrc.fs.mkdir(out)

local STEP = 0.5e-3
local wheel = wrc.profile.load("profiles/s1002.lua", {step = STEP})  -- s = -70 .. +60 mm
local rail = wrc.profile.load("profiles/60e1.lua", {step = STEP})    -- 30 mm deep, uncanted
local CANT = math.atan(1 / 40)

local function write(name, lines)
  local path = out .. "/" .. name
  local f = assert(io.open(path, "w"))
  f:write(table.concat(lines, "\n"), "\n")
  f:close()
  print("wrote " .. path)
end

local function e8(v) return string.format("%.7E", v) end  -- 8 significant digits

-- The 60E1 canted 1:40 toward the track centre, as files of a canted rail hold it: rotated about the
-- rail's longitudinal axis (field side up, engine frame), the origin moved to the highest point of the
-- canted head. That point is the canted R300 crown centre (0, -300 mm rotated) plus 300 mm up.
local function canted_points()
  local y0, z0 = rail:points()
  local c, s = math.cos(CANT), math.sin(CANT)
  local top_y, top_z = 0.300 * s, 0.300 - 0.300 * c  -- canted frame, before the shift
  local ys, zs = {}, {}
  for i = 1, #y0 do
    ys[i] = c * y0[i] - s * z0[i] - top_y
    zs[i] = s * y0[i] + c * z0[i] - top_z
  end
  return ys, zs
end

---------------------------------------------------------------------------------------------------------
-- Simpack. z is positive DOWN in the file; the spline section lists the processing steps 1..7 that the
-- reader applies in their numbered order.
local function simpack(o)
  local L = {
    "! Simpack wheel-rail profile, written by wrc's tests/data/profile/generate_samples.lua",
    "! " .. o.title,
    "",
    "  header.begin",
    "    version       =  1                       ! version of the file layout",
    string.format("    type          =  %d                       ! 0 = rail profile, 1 = wheel profile", o.type),
    "  header.end",
    "",
    "  spline.begin",
    "    approx.smooth  = +0.000000000000000e+00   ! approximation smoothing (0: the points as given)",
    string.format("    file           = '%s'   ! where the points came from", o.source),
    "    file.mtime     =  0                       ! time stamp of that file",
    string.format("    comment        = '%s'   ! free text", o.comment),
    "    type           =  0                       ! type of the original file",
    "    point.dist.min = +0.000000000000000e+00   ! 1: minimum distance between points (length unit)",
    string.format("    shift.y        = %+.15e   ! 2: y shift (length unit)", o.shift_y or 0),
    string.format("    shift.z        = %+.15e   ! 2: z shift (length unit)", o.shift_z or 0),
    string.format("    rotate         = %+.15e   ! 3: rotation about x (angle unit)", o.rotate or 0),
    "    bound.y.min    = +1.000000000000000e+00   ! 4: y bounds, off while min > max (length unit)",
    "    bound.y.max    = +0.000000000000000e+00   ! 4",
    "    bound.z.min    = +1.000000000000000e+00   ! 4: z bounds, off while min > max (length unit)",
    "    bound.z.max    = +0.000000000000000e+00   ! 4",
    string.format("    mirror.y       =  %d                       ! 5: y -> -y (0 no, 1 yes)", o.mirror_y and 1 or 0),
    "    mirror.z       =  0                       ! 5: z -> -z (0 no, 1 yes)",
    string.format("    inversion      =  %d                       ! 6: reverse the point order (0 no, 1 yes)", o.inversion and 1 or 0),
    "!   units.len      = 'mm'                     ! 7: name of the length unit",
    string.format("!   units.ang      = '%s'                    ! 7: name of the angle unit", o.angle_unit or "rad"),
    "    units.len.f    = +1.000000000000000e+03   ! 7: length unit per metre",
    string.format("    units.ang.f    = %+.15e   ! 7: angle unit per radian", o.angle_factor or 1),
    "    point.begin",
    "    ! y (length unit)        z (length unit, down)",
    "    ! ---------------------  ---------------------",
  }
  for i = 1, #o.y do L[#L + 1] = e8(o.y[i]) .. "\t" .. e8(o.z[i]) end
  L[#L + 1] = "    point.end"
  L[#L + 1] = "  spline.end"
  write(o.name, L)
end

-- S1002 as wheel files commonly hold it: raw y = -s (the flange back at +70 mm), z = F(s) down, from the
-- flange back to the field side; mirror.y turns y into s and inversion reverses the order.
do
  local s, z = wheel:points()
  local ry, rz = {}, {}
  for i = 1, #s do ry[i], rz[i] = -s[i] * 1e3, -z[i] * 1e3 end
  simpack{name = "s1002.prw", type = 1, title = "S1002 wheel (EN 13715), analytic, every 0.5 mm",
          source = "profiles/s1002.lua", comment = "S1002 h28 e32.5 6.7% ! sampled every 0.5 mm",
          mirror_y = true, inversion = true, y = ry, z = rz}
end

-- 60E1 canted 1:40, already canted in the file (use it with cant = 0): origin at the highest point of
-- the canted head, gauge side at -y, z down, from the gauge side to the field side.
local cy, cz = canted_points()
do
  local ry, rz = {}, {}
  for i = 1, #cy do ry[i], rz[i] = cy[i] * 1e3, -cz[i] * 1e3 end
  simpack{name = "60e1_canted.prr", type = 0, title = "60E1 rail head (EN 13674-1) canted 1:40, every 0.5 mm",
          source = "profiles/60e1.lua", comment = "60E1 canted 1:40, origin at the top of the canted head",
          y = ry, z = rz}
end

-- The same canted rail as the uncanted 60E1 points with the processing keys that cant it: shift (step 2)
-- moves the future top point to the origin, rotate (step 3, in degrees: units.ang.f = 180/pi) turns the
-- head about x. In the file's frame (z down) the field side rises for a negative angle.
do
  local y0, z0 = rail:points()
  local ry, rz = {}, {}
  for i = 1, #y0 do ry[i], rz[i] = y0[i] * 1e3, -z0[i] * 1e3 end
  -- The top of the canted head, in the uncanted file frame (mm, z down): the crown point at polar angle
  -- -CANT from the crown centre (0, +300).
  local ty, tz = 300 * math.sin(CANT), 300 * (1 - math.cos(CANT))
  simpack{name = "60e1_rotated.prr", type = 0, title = "60E1 rail head (EN 13674-1) uncanted, canted 1:40 by rotate",
          source = "profiles/60e1.lua", comment = "60E1 uncanted; shift and rotate cant it 1:40",
          shift_y = -ty, shift_z = -tz, rotate = -math.deg(CANT), angle_unit = "deg", angle_factor = 180 / math.pi,
          y = ry, z = rz}
end

---------------------------------------------------------------------------------------------------------
-- MiniProf: `Key=Value` header lines, an empty line, then one row per point (columns of ColumnDef).
local function refpoints()
  local L = {}
  for k = 0, 2 do
    L[#L + 1] = string.format("RefPoint%d=0.0000, 0.0000", 3 * k + 1)
    L[#L + 1] = string.format("RefPoint%d=10.0000, 0.0000", 3 * k + 2)
    L[#L + 1] = string.format("RefPoint%d=0.0000, 5.0000", 3 * k + 3)
  end
  return L
end

-- Rail as measured on the track: the track centre on the +X side (X = -y of the left rail, so it is read
-- with mirror_y = true) and Y increasing downward (Y = -z), as some instruments export it. Points after
-- the first marked with `"`.
do
  local L = {"Filename=60e1_canted.ban", "ProgramName=wrc generate_samples.lua", "ProgramVer=1", "ProgramDate=",
             "MPTypeNo=299", "MPSerNo=0", string.format("XYPoints=%d", #cy), "XOffset=0.0000", "YOffset=0.0000",
             "Tilt=", "AreaRef=", "AreaGain=", "AreaLoss=", "BaseTilt=", "BaseOffset=", "SectionNo=", "Line=",
             "Position=", "Rail=left, 60E1 canted 1:40 (analytic, every 0.5 mm)", "Chars=Win"}
  for _, r in ipairs(refpoints()) do L[#L + 1] = r end
  L[#L + 1] = "ColumnDef=X,Y"
  L[#L + 1] = ""
  -- From the field side (X < 0) to the gauge side, as the .prr read backwards.
  for i = #cy, 1, -1 do
    local mark = (i == #cy or i == 1) and " " or '"'
    L[#L + 1] = string.format("%s% .7E\t% .7E", mark, -cy[i] * 1e3, -cz[i] * 1e3)
  end
  write("60e1_canted.ban", L)
end

-- Wheel: X from the flange back (X = s + 70 mm), Y = F(s), the radius offset toward the flange tip
-- (standard), from the field side to the flange back; the older `MINIPROF` first line, the wheel's
-- measures in the header (measured here on the analytic profile) and a third column A, the slope angle
-- of the profile at the point (degrees, central difference).
do
  local s, z = wheel:points()
  local fine = wrc.profile.load("profiles/s1002.lua", {step = 0.01e-3})
  local fy, fz = fine:points()
  local z_tape = fine:interpolate(0)
  local tip = 1
  for i = 2, #fz do if fz[i] < fz[tip] then tip = i end end
  -- Walking from the tip toward the tread: Sd at 10 mm above the tape circle, qR from there to the point
  -- 2 mm below the tip (EN 15313 measures).
  local y_sd = H.crossing(fy, fz, tip, 1, z_tape - 0.010)
  local y_qr = H.crossing(fy, fz, tip, 1, fz[tip] + 0.002)
  local n = #s
  local L = {"MINIPROF", "Filename=s1002.whl", "ProgramName=wrc generate_samples.lua", "ProgramVer=1",
             string.format("XYPoints=%d", n),
             string.format("Sh=%.2f", (z_tape - fz[tip]) * 1e3),
             string.format("Sd=%.2f", (y_sd + 0.070) * 1e3),
             string.format("qR=%.2f", (y_sd - y_qr) * 1e3),
             "DiameterTaperline=900.00", string.format("DiameterFlange=%.2f", 900 + 2 * (z_tape - fz[tip]) * 1e3),
             "Chars=Win"}
  for _, r in ipairs(refpoints()) do L[#L + 1] = r end
  L[#L + 1] = "ColumnDef=X,Y,A"
  L[#L + 1] = ""
  for i = n, 1, -1 do
    local a, b = math.max(i - 1, 1), math.min(i + 1, n)
    local slope = -(z[b] - z[a]) / (s[b] - s[a])  -- dF/ds
    L[#L + 1] = string.format(" %.7E\t% .7E\t% .4f", (s[i] + 0.070) * 1e3, -z[i] * 1e3, math.deg(math.atan(slope)))
  end
  write("s1002.whl", L)
end
