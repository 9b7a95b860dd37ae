-- The station reader (tests/out_of_tree/reader_plugin), built out of tree against an installed wrc and given to
-- the installed wrc through WRC_PLUGIN_PATH: it is listed from that folder, reads a file of known points (a
-- parabola, mm) into the same points in metres, takes its own option and reports a bad line with the file and line.
--   wrc run plugin_check.lua tmp=<folder> plugins=<the folder in WRC_PLUGIN_PATH>
local check = require "wrc.check"

local function write(name, text)
  local path = arg.tmp .. "/" .. name
  local f = assert(io.open(path, "w"))
  f:write(text)
  f:close()
  return path
end

local station
for _, r in ipairs(wrc.profile.readers()) do
  if r.id == "station" then station = r end
end
check.ok(station ~= nil, "the station reader is listed")
check.ok(station.origin:find(arg.plugins, 1, true) == 1,
         "the station reader comes from " .. arg.plugins .. ": " .. station.origin)
check.ok(station.extensions[1] == ".sta" and station.options[1] == "first", "its extension and option")

-- y every millimetre from -20 to 20, z = -y^2/400 (mm).
local lines = {"stations rail", "# a parabola"}
for i = -20, 20 do lines[#lines + 1] = ("P%d %.17g %.17g"):format(i + 21, i, -i * i / 400) end
local path = write("head.sta", table.concat(lines, "\n") .. "\n")
local p = wrc.profile.load(path)
check.ok(p.kind == "rail" and #p == 41, "41 rail points, got " .. #p .. " " .. p.kind)
check.ok(p.transforms[1] == "read by 'station'", "read by the station reader: " .. tostring(p.transforms[1]))
local y, z = p:points()
for i = 1, 41 do
  local ymm = i - 21
  check.near(y[i], ymm * 1e-3, 1e-15, "y of point " .. i)
  check.near(z[i], -ymm * ymm / 400 * 1e-3, 1e-15, "z of point " .. i)
end

local q = wrc.profile.load(path, {first = "P11"})
local qy = q:points()
check.ok(#q == 31, "first = P11 keeps 31 stations, got " .. #q)
check.near(qy[1], -10e-3, 1e-15, "the first station kept")

local bad = write("bad.sta", "stations rail\nP1 -10 -1\nP2 zero 0\nP3 10 -1\n")
check.fails(function() wrc.profile.load(bad) end, bad .. ":3: expected `<label> <y> <z>` (mm)", "a bad line")
print("station reader built out of tree: " .. station.origin)
