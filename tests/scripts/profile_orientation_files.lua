-- Profile files turned round on the way in, and the messages that say how to turn them back. Every file is written
-- here from the analytic 60E1 (EN 13674-1) and S1002 (EN 13715); each message must name the file, the line or key at
-- fault and what to set. Files that are right load without a warning and with the standard's geometry:
--  - 60E1: the R300 crown, z = -(300 - sqrt(300^2 - y^2)) mm about the top, which a canted head keeps about its new
--    highest point (the circle turns about its centre), over the crown's part that lies there;
--  - S1002: z = 0 at the tape circle (y = 0), the flange tip Sh = 28 mm below it.
-- Cases: Simpack's rotate = 180 (a turn by 180 degrees, about x: y and z both reversed), MiniProf columns swapped,
-- a mirrored canted MiniProf rail (refused) against a worn high rail (warned), files cut exactly at a row's end.
local check = require "wrc.check"
local H = dofile(os.getenv("WRC_TEST_DATA") .. "/profile/helpers.lua")
local tmp = H.tmpdir() .. "/profile_orientation_files_"

local flat = wrc.profile.load("profiles/60e1.lua", {step = 0.1e-3, depth = 0.030})
local canted = H.canted_60e1(0.1e-3, 0.030)
local s1002 = wrc.profile.load("profiles/s1002.lua", {step = 0.2e-3})

local function crown_z(y_mm) return -(300 - math.sqrt(300 ^ 2 - y_mm ^ 2)) * 1e-3 end

-- The loaded rail on the R300 crown at the given y (mm): within 0.1 um (the files hold 8 digits).
local function check_crown(p, ys_mm, what)
  local y, z = p:points()
  for _, y_mm in ipairs(ys_mm) do
    check.near(H.interp(y, z, y_mm * 1e-3), crown_z(y_mm), 1e-7, string.format("%s: the R300 crown at y = %g mm", what, y_mm))
  end
end
local canted_crown = {-15, -10, -5, 0, 2}  -- the crown (|y| <= 10.228 mm uncanted) turned 1:40: -17.7 .. 2.7 mm

local function check_s1002(p, what)
  local y, z = p:points()
  check.near(H.interp(y, z, 0), 0, 1e-7, what .. ": z = 0 at the tape circle")
  check.near(p:bounds().z_min, -0.028, 1e-6, what .. ": the flange tip 28 mm below the tape circle")
end

-- The message names the file (path:line: when a line is given) and holds every pattern.
local function check_message(msg, path, line, patterns, what)
  local prefix = line and string.format("%s:%d: ", path, line) or path .. ": "
  check.ok(msg:find(prefix, 1, true) ~= nil, what .. ": the message names " .. prefix .. " in: " .. msg)
  for _, pattern in ipairs(patterns) do
    check.ok(msg:find(pattern, 1, true) ~= nil, string.format("%s: '%s' in: %s", what, pattern, msg))
  end
end

-- A Simpack file of raw points (pts.y, pts.z in m; the file holds them in mm, z down) and the spline keys `keys`
-- ({key, value} pairs in order); returns the path and the line of each key.
local function simpack(name, kind, pts, keys)
  local ys, zs = pts.y, pts.z
  local lines = {"header.begin", "  version = 1", "  type = " .. (kind == "wheel" and 1 or 0), "header.end",
                 "spline.begin", "  units.len.f = 1000"}
  local at = {}
  for _, kv in ipairs(keys) do
    lines[#lines + 1] = string.format("  %s = %s", kv[1], kv[2])
    at[kv[1]] = #lines
  end
  lines[#lines + 1] = "  point.begin"
  for i = 1, #ys do lines[#lines + 1] = string.format("%.9E\t%.9E", ys[i] * 1e3, zs[i] * 1e3) end
  lines[#lines + 1] = "  point.end"
  lines[#lines + 1] = "spline.end"
  return H.write(tmp .. name, table.concat(lines, "\n") .. "\n"), at
end

-- The points of p as (sy * y, sz * z).
local function signed(p, sy, sz)
  local y, z = p:points()
  local ys, zs = {}, {}
  for i = 1, #y do ys[i], zs[i] = sy * y[i], sz * z[i] end
  return {y = ys, z = zs}
end

local degrees = {{"rotate", "180"}, {"units.ang.f", "57.29577951308232"}}  -- degrees per radian

-- 1. Simpack rotate = 180. As Simpack reads a file, z points down: the points (y, -z). Points given as (-y, z) with
-- rotate = 180 are the same profile turned by 180 degrees, which the rotation turns back: a legitimate flip.
do
  local path = simpack("turned.prr", "rail", signed(canted, -1, 1), degrees)
  local p = wrc.profile.load(path)
  check.ok(#p.warnings == 0, "rotate = 180 (degrees) turning the points back: no warning: " .. table.concat(p.warnings, "; "))
  check.ok(H.has(p.transforms, "rotated by 3.14159265 rad"), "the turn is reported: " .. table.concat(p.transforms, "; "))
  check_crown(p, canted_crown, "canted 60E1 .prr turned by rotate = 180")
  local radians = simpack("turned_rad.prr", "rail", signed(canted, -1, 1), {{"rotate", "3.141592653589793"}})
  local q = wrc.profile.load(radians)
  check.ok(#q.warnings == 0, "rotate = pi (radians): no warning")
  check_crown(q, canted_crown, "canted 60E1 .prr turned by rotate = pi")
  local wheel = simpack("turned.prw", "wheel", signed(s1002, -1, 1), degrees)
  local w = wrc.profile.load(wheel)
  check.ok(#w.warnings == 0, "S1002 .prw turned by rotate = 180: no warning: " .. table.concat(w.warnings, "; "))
  check_s1002(w, "S1002 .prw turned by rotate = 180")
end

-- rotate = 180 on points already as Simpack reads them turns the profile upside down: the warning names rotate, its
-- line and how to set it, not the option mirror_z.
do
  local path, at = simpack("upside.prr", "rail", signed(canted, 1, -1), degrees)
  local p = wrc.profile.load(path)
  check.ok(#p.warnings == 1, "an upside-down rail by rotate = 180: one warning")
  check_message(p.warnings[1], path, nil, {"upside down", string.format("rotate = 180 (line %d)", at.rotate),
                                           "set rotate = 0"}, "rail upside down by rotate")
  check.ok(not p.warnings[1]:find("mirror_z", 1, true), "the warning does not send to mirror_z: " .. p.warnings[1])
  local wheel, wat = simpack("upside.prw", "wheel", signed(s1002, 1, -1), degrees)
  local w = wrc.profile.load(wheel)
  check_message(w.warnings[1] or "", wheel, nil, {"upside down", string.format("rotate = 180 (line %d)", wat.rotate),
                                                  "set rotate = 0"}, "wheel upside down by rotate")
  check.ok(not w.warnings[1]:find("mirror_z", 1, true), "the wheel's warning does not send to mirror_z")
  -- The same by mirror.z = 1, and by the option mirror_z: each named as the step to undo.
  local mz, mat = simpack("mirror_z.prr", "rail", signed(canted, 1, -1), {{"mirror.z", "1"}})
  check_message(wrc.profile.load(mz).warnings[1] or "", mz, nil,
                {"upside down", string.format("mirror.z = 1 (line %d)", mat["mirror.z"]), "set mirror.z = 0"}, "mirror.z = 1")
  local right = simpack("right.prr", "rail", signed(canted, 1, -1), {})
  check.ok(#wrc.profile.load(right).warnings == 0, "the file as Simpack reads it: no warning")
  check_message(wrc.profile.load(right, {mirror_z = true}).warnings[1] or "", right, nil,
                {"upside down", "the option mirror_z = true: drop it"}, "the option mirror_z")
end

-- Points with z up (not as Simpack reads them) and rotate = 180: the turn sets z down, but mirrors y with it; the
-- canted head then leans outward, tilted 1:40 as a rigid body: refused, naming rotate and what turns over alone.
do
  local path, at = simpack("zup.prr", "rail", signed(canted, 1, 1), degrees)
  local err = check.fails(function() wrc.profile.load(path) end, "mirrored", "z up turned by rotate = 180")
  check_message(err, path, nil, {"leans outward", "1:40", string.format("rotate = 180 (line %d)", at.rotate),
                                 "set rotate = 0 and mirror.z = 1"}, "y mirrored by rotate")
  local fixed = simpack("zup_fixed.prr", "rail", signed(canted, 1, 1), {{"mirror.z", "1"}})
  local p = wrc.profile.load(fixed)
  check.ok(#p.warnings == 0, "the same points with mirror.z = 1: no warning")
  check_crown(p, canted_crown, "canted 60E1 .prr with mirror.z = 1")
end

-- 2. MiniProf columns swapped: the vertical in the X column. A rail (ColumnDef given: its line named) and a wheel
-- (no ColumnDef: the first row named).
local function swap_columns(text)
  local head, rows = text:match("^(.-\n\n)(.*)$")
  return head .. rows:gsub("([ \"])([^\t\n]+)\t([^\t\n]+)", "%1%3\t%2")
end
do
  local ban = H.write_miniprof(tmp .. "canted.ban", canted, {x_sign = -1, y_sign = 1})
  local p = wrc.profile.load(ban, {mirror_y = true})
  check.ok(#p.warnings == 0, "the canted .ban with mirror_y: no warning")
  check_crown(p, canted_crown, "canted 60E1 .ban")
  local f = assert(io.open(ban))
  local text = f:read("a")
  f:close()
  local swapped = H.write(tmp .. "swapped.ban", swap_columns(text))
  local column_def = select(2, text:match("^(.-)ColumnDef"):gsub("\n", "")) + 1
  local err = check.fails(function() wrc.profile.load(swapped, {mirror_y = true}) end, "columns look swapped",
                          "a .ban with X and Y swapped")
  check_message(err, swapped, column_def, {"ColumnDef=X,Y takes column 1 as X", "swap the two columns",
                                           "ColumnDef=Y,X"}, "swapped .ban")
  check.ok(not err:find("which way Y", 1, true), "not the Y-orientation message")

  local whl = H.write_miniprof(tmp .. "s1002.whl", s1002)
  check_s1002(wrc.profile.load(whl), "S1002 .whl")
  f = assert(io.open(whl))
  text = f:read("a"):gsub("ColumnDef=X,Y\n", "")
  f:close()
  local bare = swap_columns(text)
  local first_row = select(2, bare:match("^(.-\n\n)"):gsub("\n", "")) + 1
  local wheel = H.write(tmp .. "swapped.whl", bare)
  err = check.fails(function() wrc.profile.load(wheel) end, "columns look swapped", "a .whl with X and Y swapped")
  check_message(err, wheel, first_row, {"without a ColumnDef line", "ColumnDef=Y,X"}, "swapped .whl")
end

-- 3. A canted MiniProf rail measured with the track centre on +X read without mirror_y: its head leans outward, and
-- is the symmetric 60E1 head tilted 1:40 outward: refused. A worn high rail read right can lean outward too (its
-- worn gauge face moves the middle of the head toward the field side) but is no tilted symmetric head: warned.
do
  local ban = H.write_miniprof(tmp .. "centre_on_x.ban", canted, {x_sign = -1, y_sign = -1})
  local err = check.fails(function() wrc.profile.load(ban) end, "the rail profile is mirrored",
                          "a canted .ban read without mirror_y")
  check_message(err, ban, nil, {"leans outward", "tilted outward by 1:40", "Pass mirror_y = true"}, "mirrored .ban")
  check_crown(wrc.profile.load(ban, {mirror_y = true}), canted_crown, "the same .ban with mirror_y")

  -- Side wear: the gauge side cut by a face at 60 degrees through the point 14 mm below the top, 12 mm inside the
  -- head's gauge side there (a worn high rail on a track without cant).
  local y, z = flat:points()
  local k = H.argmax(z)
  local face = H.crossing(y, z, k, -1, z[k] - 0.014) + 0.012
  local wy, wz = {}, {}
  for i = 1, #y do wy[i], wz[i] = y[i], math.min(z[i], z[k] - 0.014 + math.tan(math.rad(60)) * (y[i] - face)) end
  local worn = H.write_miniprof(tmp .. "worn.ban", wrc.profile.points{kind = "rail", y = wy, z = wz},
                                {x_sign = -1, y_sign = 1})
  local p = wrc.profile.load(worn, {mirror_y = true})
  check.ok(#p.warnings == 1, "a worn high rail: loaded, with one warning")
  check_message(p.warnings[1], worn, nil, {"leans outward", "unless it is a worn high rail",
                                           "the option mirror_y = true: drop it"}, "worn high rail")
  check_crown(p, {-5, 0, 5, 10}, "the worn rail's crown, unworn")
end

-- 4. Files cut exactly at the end of a row (no line break after it): MiniProf's XYPoints and Simpack's point.end
-- tell them from complete ones.
do
  local ban = H.write_miniprof(tmp .. "full.ban", canted, {x_sign = -1, y_sign = 1})
  local f = assert(io.open(ban))
  local text = f:read("a")
  f:close()
  local lines = {}
  for l in text:gmatch("[^\n]*\n") do lines[#lines + 1] = l end
  local keep = #lines - 10
  local cut = H.write(tmp .. "cut.ban", table.concat(lines, "", 1, keep):sub(1, -2))
  local xy_line = select(2, text:match("^(.-)XYPoints"):gsub("\n", "")) + 1
  local err = check.fails(function() wrc.profile.load(cut, {mirror_y = true}) end, "cut short", "a .ban cut at a row's end")
  check_message(err, cut, xy_line, {string.format("XYPoints = %d but the file holds %d points", #canted, #canted - 10),
                                    string.format("truncated) after line %d", keep)}, "cut .ban")

  local prr = simpack("full.prr", "rail", signed(canted, 1, -1), {})
  f = assert(io.open(prr))
  text = f:read("a")
  f:close()
  lines = {}
  for l in text:gmatch("[^\n]*\n") do lines[#lines + 1] = l end
  keep = #lines - 12
  local cut_prr = H.write(tmp .. "cut.prr", table.concat(lines, "", 1, keep):sub(1, -2))
  err = check.fails(function() wrc.profile.load(cut_prr) end, "cut short", "a .prr cut at a row's end")
  check_message(err, cut_prr, keep, {"the file ends inside point.begin (line 7): no point.end"}, "cut .prr")
end
