-- The VAMPIRE reader (plugins/vampire) on small files written here from the format's description, one per documented
-- variant, independently of the reader and of wrc's writer: line 1 WHEELPROFILE / RAILPROFILE, line 2 a title, line 3
-- TREADDATUM (EUROPEAN = 70 mm, US1 = 2 27/32 in, US2 = 3 1/16 in, CUSTOM <mm>: the flange back to the tape circle)
-- or GAUGEPOINT (EUROPEAN, US, CUSTOM), line 4 FLANGEBACK <mm> or GAUGE <mm>, then rows `yl zl yr zr` in mm: Y from
-- the track centre (right side +Y), wheel Z the radius offset toward the flange tip, rail Z up. The rows are made from
-- the analytic S1002 and 60E1 by those definitions (a different right profile, to see which columns are read), and the
-- profiles read back must be the analytic ones: wheels with the tape circle at y = 0, rails with the origin at the
-- highest point of the head. Then bad files: each error names the file and line.
local check = require "wrc.check"
local H = dofile(os.getenv("WRC_TEST_DATA") .. "/profile/helpers.lua")
local tmp = H.tmpdir() .. "/profile_vampire_"

local s1002 = wrc.profile.load("profiles/s1002.lua", {step = 0.5e-3})
local e60 = wrc.profile.load("profiles/60e1.lua", {step = 0.5e-3})
local INCH = 25.4

local function write(name, text) return H.write(tmp .. name, text) end

-- Rows from a profile: d(y) = distance from the track centre (mm), Z(z) (mm); the right profile gets dz_right (mm)
-- added to Z. `sep` separates the fields; `comment` is appended to every 10th row.
local function rows(p, d, Z, dz_right, sep, comment)
  local ys, zs = p:points()
  local out = {}
  for i = 1, #ys do
    local dd, zz = d(ys[i] * 1e3), Z(zs[i] * 1e3)
    out[#out + 1] = string.format("%.9f%s%.9f%s%.9f%s%.9f%s", -dd, sep, zz, sep, dd, sep, zz + dz_right, sep,
                                  (comment and i % 10 == 0) and comment or "")
    if i == 5 then out[#out + 1] = "" end  -- a blank line among the rows
  end
  return table.concat(out, "\n") .. "\n"
end

-- Same points as `ref` (z shifted by dz metres) within 1e-9 m (the rows carry 9 decimals of a mm).
local function same(p, ref, dz, what)
  local y1, z1 = p:points()
  local y2, z2 = ref:points()
  check.ok(#y1 == #y2, what .. ": " .. #y1 .. " points, expected " .. #y2)
  local worst = 0
  for i = 1, #y1 do worst = math.max(worst, math.abs(y1[i] - y2[i]), math.abs(z1[i] - (z2[i] + dz))) end
  check.ok(worst < 1e-9, what .. ": largest difference " .. worst .. " m")
  print(string.format("  %-56s %d points, largest difference %.2e m", what, #y1, worst))
end

-- Wheels: every tread datum; the right profile 0.3 mm larger in radius (Z toward the flange tip + 0.3).
local datums = {
  {line = "TREADDATUM EUROPEAN", mm = 70, sep = " ", name = "european"},
  {line = "TREADDATUM US1", mm = (2 + 27 / 32) * INCH, sep = ", ", name = "us1"},
  {line = "TREADDATUM US2", mm = (3 + 1 / 16) * INCH, sep = "\t", name = "us2"},
  {line = "treaddatum custom 72.5", mm = 72.5, sep = ",", name = "custom"},
}
for _, c in ipairs(datums) do
  local FB = 1360
  local body = rows(s1002, function(s) return FB / 2 + c.mm + s end, function(z) return -z end, 0.3, c.sep, "  ! a comment")
  local path = write("wheel_" .. c.name .. ".whe", "WHEELPROFILE\nS1002 new, " .. c.name .. "\n" .. c.line ..
                     "\nFLANGEBACK " .. FB .. "\n" .. body)
  local left = wrc.profile.load(path)
  check.ok(left.kind == "wheel", c.name .. ": WHEELPROFILE gives a wheel")
  check.ok(left.metadata.title == "S1002 new, " .. c.name and left.metadata.flange_back == "1360", c.name .. ": metadata")
  check.ok(H.has(left.transforms, "left side (columns yl zl)"), c.name .. ": the side read is reported")
  same(left, s1002, 0, "wheel " .. c.line .. ", left")
  same(wrc.profile.load(path, {side = "right"}), s1002, -0.3e-3, "wheel " .. c.line .. ", right")
end

-- Comments starting with % and " (on the header lines too), and Windows line ends.
do
  local body = rows(s1002, function(s) return 750 + s end, function(z) return -z end, 0, " ", "% note")
  body = body:gsub("\n", " \" quoted note\r\n", 3)
  local path = write("wheel_comments.whe",
                     "WHEELPROFILE\r\n! a title\r\nTREADDATUM EUROPEAN ! 70 mm\r\nFLANGEBACK 1360 % mm\r\n" .. body)
  check.ok(wrc.profile.load(path).metadata.title == "! a title", "the title line is the title, whatever it holds")
  same(wrc.profile.load(path), s1002, 0, "wheel with % and \" comments, CRLF")
end

-- Rails: every gauge point; Y puts the gauge face near GAUGE/2 (35 mm from the head's centre), Z up from the foot
-- (172 mm below the top); the reader puts the origin at the highest point.
for _, c in ipairs{{line = "GAUGEPOINT EUROPEAN", name = "european", value = "EUROPEAN"},
                   {line = "GAUGEPOINT US", name = "us", value = "US"},
                   {line = "GAUGEPOINT CUSTOM 16", name = "custom", value = "CUSTOM 16"}} do
  local body = rows(e60, function(y) return 717.5 + 35 + y end, function(z) return 172 + z end, -0.2, " ")
  local path = write("rail_" .. c.name .. ".rai", "RAILPROFILE\n60E1\n" .. c.line .. "\nGAUGE 1435\n" .. body)
  local left = wrc.profile.load(path)
  check.ok(left.kind == "rail" and left.metadata.gauge_point == c.value and left.metadata.gauge == "1435",
           c.name .. ": a rail, GAUGEPOINT and GAUGE kept: " .. tostring(left.metadata.gauge_point))
  same(left, e60, 0, "rail " .. c.line .. ", left")
  -- The right rail 0.2 mm lower everywhere: the same shape once its own top is the origin.
  same(wrc.profile.load(path, {side = "right"}), e60, 0, "rail " .. c.line .. ", right")
end

-- Bad files: each error names the file and the line.
local function bad(name, text, pattern, options)
  local path = write(name, text)
  local err = check.fails(function() wrc.profile.load(path, options) end, pattern, name)
  check.ok(err:find(name, 1, true), name .. ": the message names the file: " .. err)
  print("  " .. name .. ": " .. err:gsub("\n.*", ""))
end
local good_rows = "-680 9.5 680 9.5\n-700 0 700 0\n-750 0 750 0\n-800 2 800 2\n"
bad("first_line.whe", "WHEEL PROFILE\nt\nTREADDATUM EUROPEAN\nFLANGEBACK 1360\n" .. good_rows, ":1: a VAMPIRE profile starts with")
bad("kind_ext.whe", "RAILPROFILE\nt\nGAUGEPOINT EUROPEAN\nGAUGE 1435\n" .. good_rows, ":1: the file says RAILPROFILE but its extension .whe")
bad("datum.whe", "WHEELPROFILE\nt\nTREADDATUM METRIC\nFLANGEBACK 1360\n" .. good_rows, ":3: TREADDATUM 'METRIC' is not a known datum")
bad("gauge_point.rai", "RAILPROFILE\nt\nGAUGEPOINT US1\nGAUGE 1435\n" .. good_rows, ":3: GAUGEPOINT 'US1' is not a known datum")
bad("custom.whe", "WHEELPROFILE\nt\nTREADDATUM CUSTOM\nFLANGEBACK 1360\n" .. good_rows, ":3: TREADDATUM CUSTOM takes 1 value")
bad("missing_flangeback.whe", "WHEELPROFILE\nt\nTREADDATUM EUROPEAN\n" .. good_rows, ":4: expected `FLANGEBACK <mm>`")
bad("flangeback.whe", "WHEELPROFILE\nt\nTREADDATUM EUROPEAN\nFLANGEBACK 1,360\n" .. good_rows, ":4: FLANGEBACK must be a number")
bad("negative_gauge.rai", "RAILPROFILE\nt\nGAUGEPOINT EUROPEAN\nGAUGE -1435\n" .. good_rows, ":4: GAUGE must be a length in mm")
bad("three_fields.whe", "WHEELPROFILE\nt\nTREADDATUM EUROPEAN\nFLANGEBACK 1360\n" .. good_rows .. "-810 3 810\n",
    ":9: a row holds `yl zl yr zr` (4 numbers, mm), got 3 fields")
bad("decimal_commas.whe", "WHEELPROFILE\nt\nTREADDATUM EUROPEAN\nFLANGEBACK 1360\n-680,5 9,5 680,5 9,5\n",
    ":5: '-680,5 9,5 680,5 9,5' looks written with decimal commas")
bad("nan.whe", "WHEELPROFILE\nt\nTREADDATUM EUROPEAN\nFLANGEBACK 1360\n" .. good_rows .. "-810 nan 810 3\n",
    ":9: zl must be a finite number")
bad("text.whe", "WHEELPROFILE\nt\nTREADDATUM EUROPEAN\nFLANGEBACK 1360\n-680 9.5 680 9.5\n-700 zero 700 0\n", ":6: zl must be a number")
bad("two_points.whe", "WHEELPROFILE\nt\nTREADDATUM EUROPEAN\nFLANGEBACK 1360\n-680 9.5 680 9.5\n-700 0 700 0\n",
    "2 points read after the header; a profile needs at least 3")
bad("short.rai", "RAILPROFILE\nt\nGAUGEPOINT EUROPEAN\n", "the file ends within the 4 header lines")
bad("empty.whe", "", "the file is empty")
bad("side.whe", "WHEELPROFILE\nt\nTREADDATUM EUROPEAN\nFLANGEBACK 1360\n" .. good_rows, "option side must be \"left\" or \"right\"",
    {side = "both"})
-- A file in metres: the host's extent check (the reader declares no unit: VAMPIRE files are in mm).
bad("metres.whe", "WHEELPROFILE\nt\nTREADDATUM EUROPEAN\nFLANGEBACK 1360\n-0.680 0.0095 0.680 0.0095\n-0.7 0 0.7 0\n-0.75 0 0.75 0\n",
    "units")
print("profile_vampire: all checks passed")
