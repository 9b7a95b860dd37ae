-- p:write (engine/src/profile/write.cpp) in every format wrc reads, on a shipped profile pair (S1002 / 60E1 from their
-- definitions) and a measured-like pair (the MiniProf S1002 and the canted Simpack 60E1 of tests/data/profile/samples):
--   - the written file, read back by its reader plugin with the default options (kind for text and CSV), holds the
--     same points within the written precision: 1e-6 mm per written number, so 0.5 nm per coordinate; 1 nm allowed
--     (a VAMPIRE rail comes back with its highest point as the origin, shifted by its rounded top: two roundings; the
--     measured-like rail's origin is the canted head's analytic top, 43 um from the highest sample);
--   - the same contact: ws:wheel on the tread and at the flange root gives the same pmax within 5e-4 and Fy within 5e-5
--     relative as the original pair (the points moved by < 1 nm: pmax moves by up to 1e-4 with the nm changes of the
--     gap sampled by the 0.5 mm elements, Fy by 5e-6; an error in a sign, an offset or a unit moves the contact by
--     millimetres and these numbers by percents or more);
--   - each file has the layout of its format's description, checked here on the text (not through the readers): the
--     VAMPIRE wheel's tape circle at Y = FLANGEBACK/2 + 70 and its flange tip at Z = +28, the left columns the mirror of
--     the right ones, the rail's gauge point (14 mm below the top) at Y = GAUGE/2; the MiniProf wheel's flange back at
--     X = 0 and flange tip at Y = +28; Simpack z down; text in mm with a y_mm header;
--   - bad calls: an unknown format (the list in the message), an extension that is not the format's or the kind's, an
--     unknown key, a rail the VAMPIRE writer cannot place; a failed write leaves the old file as it was.
local check = require "wrc.check"
local H = dofile(os.getenv("WRC_TEST_DATA") .. "/profile/helpers.lua")
local samples = os.getenv("WRC_TEST_DATA") .. "/profile/samples/"
local tmp = H.tmpdir() .. "/profile_write_"

local pairs_ = {
  {name = "shipped", wheel = wrc.profile.load("profiles/s1002.lua"), rail = wrc.profile.load("profiles/60e1.lua"),
   cant = 1 / 40},
  {name = "measured-like", wheel = wrc.profile.load(samples .. "s1002.whl"), rail = wrc.profile.load(samples .. "60e1_canted.prr"),
   cant = 0},
}
local formats = {  -- format, wheel extension, rail extension, options to read back
  {"text", "txt", "txt"}, {"csv", "csv", "csv"}, {"simpack", "prw", "prr"}, {"miniprof", "whl", "ban"},
  {"vampire", "whe", "rai"},
}

-- `top`: compare with ref moved so that its highest point is the origin (a VAMPIRE rail comes back so).
local function same_points(p, ref, what, top)
  local y1, z1 = p:points()
  local y2, z2 = ref:points()
  check.ok(p.kind == ref.kind, what .. ": kind " .. p.kind)
  check.ok(#y1 == #y2, what .. ": " .. #y1 .. " points, expected " .. #y2)
  local k = top and H.argmax(z2)
  local oy, oz = top and y2[k] or 0, top and z2[k] or 0
  local worst = 0
  for i = 1, #y1 do worst = math.max(worst, math.abs(y1[i] - (y2[i] - oy)), math.abs(z1[i] - (z2[i] - oz))) end
  check.ok(worst <= 1e-9, what .. ": largest difference " .. worst .. " m")
  return worst
end

-- Read back as the original was made: a polyline stays one (a file's points are otherwise the interpolating spline).
local function read_back(path, kind, f, original)
  local o = {smooth = false}
  if original.smooth ~= nil then o.smooth = original.smooth end
  if f == "text" or f == "csv" then o.kind = kind end
  return wrc.profile.load(path, o)
end

local cases = {{y = 3e-3, roll = 0.16e-3, Fz = 100e3, what = "tread"}, {y = 6.4e-3, roll = 0.69e-3, Fz = 160e3, what = "flange root"}}
local function contacts(wheel, rail, cant)
  local ws = wrc.wheelset{wheel = wheel, rail = rail, grid = 0.5e-3, cant = cant}
  local out = {}
  for i, c in ipairs(cases) do
    local w = ws:wheel{side = "left", y = c.y, roll = c.roll, Fz = c.Fz}
    check.ok(w.converged, c.what .. ": converged")
    local pmax = 0
    for _, a in ipairs(w.patches) do pmax = math.max(pmax, a.pmax) end
    out[i] = {pmax = pmax, Fy = w.force.y}
  end
  return out
end

-- The rail moved so that its highest point is the origin, as a VAMPIRE rail comes back (a shift that is not a multiple of
-- the element size changes the contact at the level of the discretisation: 0.4 % in Fy for 43 um at 0.5 mm elements).
local function top_origin(rail)
  local ys, zs = rail:points()
  local k = H.argmax(zs)
  return rail:transform{shift = {y = -ys[k], z = -zs[k]}}
end

for _, pr in ipairs(pairs_) do
  local ref = contacts(pr.wheel, pr.rail, pr.cant)
  local ref_top = contacts(pr.wheel, top_origin(pr.rail), pr.cant)
  for _, f in ipairs(formats) do
    local id, wext, rext = f[1], f[2], f[3]
    local wpath, rpath = tmp .. pr.name .. "_wheel." .. wext, tmp .. pr.name .. "_rail." .. rext
    check.ok(pr.wheel:write(wpath) == id and pr.rail:write(rpath) == id, id .. ": the format follows the extension")
    local w, r = read_back(wpath, "wheel", id, pr.wheel), read_back(rpath, "rail", id, pr.rail)
    local dw = same_points(w, pr.wheel, pr.name .. " wheel as " .. id)
    local dr = same_points(r, pr.rail, pr.name .. " rail as " .. id, id == "vampire")
    local got = contacts(w, r, pr.cant)
    local ref = id == "vampire" and ref_top or ref
    for i, c in ipairs(cases) do
      check.rel(got[i].pmax, ref[i].pmax, 5e-4, pr.name .. " " .. id .. " " .. c.what .. ": pmax")
      check.rel(got[i].Fy, ref[i].Fy, 5e-5, pr.name .. " " .. id .. " " .. c.what .. ": Fy")
    end
    print(string.format("%-14s %-8s points within %.1e / %.1e m; pmax %.6g / %.6g MPa, Fy %.6g / %.6g kN (original %.6g / %.6g, %.6g / %.6g)",
                        pr.name, id, dw, dr, got[1].pmax / 1e6, got[2].pmax / 1e6, got[1].Fy / 1e3, got[2].Fy / 1e3,
                        ref[1].pmax / 1e6, ref[2].pmax / 1e6, ref[1].Fy / 1e3, ref[2].Fy / 1e3))
  end
end

-- ---- The layout of each format, read from the text written (not through the readers). ----
local function lines_of(path)
  local t = {}
  for l in io.lines(path) do t[#t + 1] = l end
  return t
end
local function numbers(line, sep)
  local t = {}
  for v in line:gmatch(sep == "," and "[^,]+" or "%S+") do t[#t + 1] = tonumber(v) end
  return t
end

local s1002 = pairs_[1].wheel  -- S1002: tape circle at s = 0, flange tip z = -28 mm at s = -32.5 - ... (the highest |z|)
local e60 = pairs_[1].rail
do
  local L = lines_of(tmp .. "shipped_wheel.whe")
  check.ok(L[1] == "WHEELPROFILE" and L[3] == "TREADDATUM EUROPEAN" and L[4] == "FLANGEBACK 1360.000000",
           "VAMPIRE wheel header: " .. L[1] .. " / " .. L[3] .. " / " .. L[4])
  local ys, zs = s1002:points()
  local tip, zmax = nil, -math.huge
  for i = 5, #L do
    local v = numbers(L[i])
    check.ok(#v == 4 and v[1] == -v[3] and v[2] == v[4], "VAMPIRE rows: the left columns mirror the right ones: " .. L[i])
    if v[4] > zmax then zmax, tip = v[4], v[3] end
    local s = ys[i - 4] * 1e3
    if s == 0 then check.near(v[3], 750, 1e-9, "VAMPIRE wheel: the tape circle at Y = 1360/2 + 70 mm") end
  end
  check.near(zmax, 28, 1e-6, "VAMPIRE wheel: the flange tip at Z = +28 mm (Z toward the flange tip)")
  check.ok(tip > 680 and tip < 750, "VAMPIRE wheel: the flange tip between the flange back and the tape circle, Y = " .. tip)
end
do
  local L = lines_of(tmp .. "shipped_rail.rai")
  check.ok(L[1] == "RAILPROFILE" and L[3] == "GAUGEPOINT EUROPEAN" and L[4] == "GAUGE 1435.000000", "VAMPIRE rail header")
  local Y, Z = {}, {}
  for i = 5, #L do
    local v = numbers(L[i])
    Y[#Y + 1], Z[#Z + 1] = v[3], v[4]
  end
  local top = H.argmax(Z)
  local yg = H.crossing(Y, Z, top, -1, Z[top] - 14)
  check.near(yg, 717.5, 1e-6, "VAMPIRE rail: the gauge point 14 mm below the top at Y = GAUGE/2")
end
do
  local L = lines_of(tmp .. "shipped_wheel.whl")
  check.ok(L[1] == "MINIPROF", "MiniProf: the first line")
  local n, first = nil, nil
  for i, l in ipairs(L) do
    if l:match("^XYPoints=") then n = tonumber(l:match("=(.*)")) end
    if l == "" then first = i + 1 break end
  end
  check.ok(n == #s1002 and #L - first + 1 == n, "MiniProf: XYPoints = the rows after the empty line")
  local x0, ymax = numbers(L[first], ",")[1], -math.huge
  for i = first, #L do ymax = math.max(ymax, numbers(L[i], ",")[2]) end
  check.near(x0, 0, 1e-9, "MiniProf wheel: X = 0 at the flange back (the first point, s = -70 mm)")
  check.near(ymax, 28, 1e-6, "MiniProf wheel: the flange tip at Y = +28 mm (standard orientation)")
end
do
  local text = io.open(tmp .. "shipped_wheel.prw"):read("a")
  check.ok(text:find("type = 1", 1, true) and text:find("units.len.f = 1000", 1, true), "Simpack wheel: type 1, mm")
  local zmax = -math.huge
  for z in text:match("point.begin[^\n]*\n(.-)point.end"):gmatch("%S+%s+(%S+)\n") do zmax = math.max(zmax, tonumber(z)) end
  check.near(zmax, 28, 1e-6, "Simpack wheel: z down, the flange tip at z = +28 mm")
  local rail = io.open(tmp .. "shipped_rail.prr"):read("a")
  check.ok(rail:find("type = 0", 1, true), "Simpack rail: type 0")
end
do
  local L = lines_of(tmp .. "shipped_wheel.csv")
  check.ok(L[3] == "y_mm,z_mm", "CSV: the header names the unit")
  local v = numbers(L[4], ",")
  check.near(v[1], -70, 1e-9, "CSV: y in mm")
end

-- ---- Bad calls ----
local w = pairs_[1].wheel
check.fails(function() w:write(tmp .. "x.txt", {format = "vampyre"}) end,
            "unknown format 'vampyre'; the formats are: text (.txt .dat), csv (.csv), simpack (.prw .prr), miniprof (.whl .ban), vampire (.whe .rai)",
            "an unknown format")
check.fails(function() w:write(tmp .. "x.prof") end, "cannot tell the format from the extension", "an unknown extension")
check.fails(function() w:write(tmp .. "x.prr") end, "profile:write '" .. tmp .. "x.prr': a wheel profile is written as .prw, not .prr",
            "a wheel as a rail file (the message names the file)")
check.fails(function() e60:write(tmp .. "x.whe") end, "a rail profile is written as .rai, not .whe", "a rail as a wheel file")
check.fails(function() w:write(tmp .. "x.whl", {format = "simpack"}) end, "the extension .whl is the miniprof format's, not simpack's",
            "an extension of another format")
check.fails(function() w:write(tmp .. "x.whe", {flangeback = 1.36}) end, "unknown key 'flangeback'", "a misspelt key")
check.fails(function() e60:write(tmp .. "x.ban", {tape_offset = 0.07}) end, "unknown key 'tape_offset'", "a wheel key for a rail")
check.fails(function() w:write(tmp .. "x.whe", {tape_offset = 70}) end, "tape_offset must lie in (0, 0.5) m, got 70", "mm for m")
check.fails(function() w:write(tmp .. "no_such_folder/x.whe") end, "no_such_folder", "a missing folder")
-- A failed write leaves the file as it was (the rail is 30 mm deep: it has no point 50 mm below its top).
local keep = tmp .. "keep.rai"
e60:write(keep)
local before = io.open(keep):read("a")
check.fails(function() e60:write(keep, {gauge_depth = 0.05}) end, "does not reach gauge_depth = 0.05 m below its top",
            "a rail the VAMPIRE writer cannot place")
check.ok(io.open(keep):read("a") == before, "the failed write left the old file as it was")
print("profile_write: all checks passed")
