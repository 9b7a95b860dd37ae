-- The Lua side of profile loading: a reader registered from Lua (seen by the host like a plugin), Lua
-- definitions and their errors, p:transform, and option errors.
local check = require "wrc.check"
local H = dofile(os.getenv("WRC_TEST_DATA") .. "/profile/helpers.lua")
local tmp = H.tmpdir() .. "/profile_lua_api_"

-- A reader for "semicolon pairs" files written in Lua: y;z per line, micrometres, kind from the file's
-- first line.
wrc.profile.register_reader{
  id = "upairs", extensions = {".upr"}, options = {"scale"},
  description = "y;z pairs in micrometres",
  read = function(path, options)
    local y, z, lines = {}, {}, {}
    local kind
    local n = 0
    for line in io.lines(path) do
      n = n + 1
      if n == 1 then
        kind = line:match("^kind=(%a+)$") or error(string.format("%s:%d: expected kind=wheel|rail", path, n), 0)
      else
        local a, b = line:match("^(%S+);(%S+)$")
        local function num(v) if v == "nan" then return 0 / 0 end return tonumber(v) end
        if not a or not num(a) or not num(b) then
          error(string.format("%s:%d: expected y;z", path, n), 0)
        end
        local s = tonumber(options.scale or "1")
        y[#y + 1], z[#z + 1], lines[#lines + 1] = num(a) * s, num(b) * s, n
      end
    end
    return {y = y, z = z, lines = lines, kind = kind, units = 1e-6, transforms = {"upairs: as given"}}
  end,
}
local readers = wrc.profile.readers()
local found
for _, r in ipairs(readers) do if r.id == "upairs" then found = r end end
check.ok(found and found.extensions[1] == ".upr" and found.origin:find("Lua", 1, true), "the Lua reader is listed")

local rows = {"kind=rail"}
for i = -20, 20 do rows[#rows + 1] = string.format("%d;%d", i * 1000, -(i * i) * 10) end
local f = H.write(tmp .. "arc.upr", table.concat(rows, "\n") .. "\n")
local p = wrc.profile.load(f)
check.ok(p.kind == "rail" and #p == 41, "the Lua reader's points arrive")
check.near(p:bounds().y_max, 0.020, 1e-12, "units = 1e-6 applied")
check.ok(p.transforms[2] == "upairs: as given", "the Lua reader's transforms are kept")
local q = wrc.profile.load(f, {scale = 2, mirror_z = true})
check.near(q:bounds().y_max, 0.040, 1e-12, "the reader's own option arrives (as a string)")
check.near(q:bounds().z_max, 0.008, 1e-12, "mirror_z applied by the host")
check.fails(function() wrc.profile.load(f, {scael = 2}) end, "unknown option 'scael' for reader 'upairs'", "misspelt option")
local bad = H.write(tmp .. "bad.upr", "kind=rail\n0;0\n1000;x\n")
check.fails(function() wrc.profile.load(bad) end, "profile_lua_api_bad.upr:3: expected y;z", "Lua reader error names file:line")
local nan = H.write(tmp .. "nan.upr", "kind=rail\n0;0\n1000;nan\n2000;0\n")
check.fails(function() wrc.profile.load(nan) end, "profile_lua_api_nan.upr:3: coordinate is not a finite number",
            "NaN from a Lua reader is caught with its line")
check.fails(function() wrc.profile.register_reader{id = "upairs", extensions = {".u2"}, read = print} end,
            "duplicate reader id 'upairs'", "duplicate Lua reader id")
check.fails(function() wrc.profile.register_reader{id = "text", extensions = {".u3"}, read = print} end,
            "duplicate reader id 'text': the plugin", "Lua reader with a plugin's id")
check.fails(function() wrc.profile.register_reader{id = "x", extensions = {".x"}} end, "'read' must be a function",
            "reader without read")

-- Lua definitions: their own errors, a wrong return, and geometric options applied by the host.
local def = H.write(tmp .. "def.lua", "local o = ... \nreturn 42\n")
check.fails(function() wrc.profile.load(def) end, "returned a number, expected a wrc.Profile", "definition returning a number")
local broken = H.write(tmp .. "broken.lua", "local x = \n")
check.fails(function() wrc.profile.load(broken) end, "profile_lua_api_broken.lua:2", "definition with a syntax error")
check.fails(function() wrc.profile.load("profiles/no_such.lua") end, "profiles/no_such.lua: not a shipped profile",
            "missing shipped definition")
check.fails(function() wrc.profile.load("no_such_folder/w.lua") end, "no_such_folder/w.lua: no such file (relative to " ..
            "the working directory", "missing file")
local s = wrc.profile.load("profiles/s1002.lua", {mirror_y = true, shift = {z = 0.001}})
check.near(s:bounds().y_max, 0.070, 1e-12, "mirror_y applied to a definition")
check.near(s:interpolate(0), 0.001, 1e-12, "shift applied to a definition")
check.fails(function() wrc.profile.load("profiles/s1002.lua", {units = "m"}) end, "'units' does not apply to a Lua definition",
            "units on a definition")
check.fails(function() wrc.profile.load("profiles/s1002.lua", {kind = "rail"}) end, "is a wheel profile but the option kind",
            "kind contradicting a definition")

-- A definition's options are checked as a file's are (issue 28): a key that neither the definition reads nor
-- wrc.profile.load takes is an error naming the closest known one; an options table passed on to a nested load counts
-- as read.
local err = check.fails(function() wrc.profile.load("profiles/60e1.lua", {unit = "m"}) end,
                        "unknown option 'unit' for the Lua definition (did you mean 'units'?)", "'unit' on a definition")
check.ok(err:find("it reads: depth, step;", 1, true), "the message lists what 60e1.lua reads: " .. err)
check.fails(function() wrc.profile.load("profiles/s1002.lua", {step = 0.5e-3, form = -0.06}) end,
            "(did you mean 'from'?)", "a misspelt option of s1002.lua")
check.ok(#wrc.profile.load("profiles/s1002.lua", {step = 0.5e-3, from = -0.06, mirror_y = false}) == 241,
         "the options s1002.lua reads and a load option are accepted")
local pass_on = H.write(H.tmpdir() .. "/profile_lua_api_pass_on.lua", [[
local opt = ...
return wrc.profile.load("profiles/60e1.lua", opt)]])
check.ok(#wrc.profile.load(pass_on, {step = 1e-3, depth = 0.02}) < #wrc.profile.load("profiles/60e1.lua"),
         "options passed on to a nested load reach it")
check.fails(function() wrc.profile.load(pass_on, {step = 1e-3, dept = 0.02}) end, "unknown option 'dept'",
            "a misspelt option passed on is refused by the definition that finally reads")

-- p:transform and option type errors.
local r = wrc.profile.load("profiles/60e1.lua")
local t = r:transform{crop = {z = {-0.010, 0.001}}, shift = {y = 0.002}, name = "head"}
check.ok(t.name == "head" and t:bounds().z_min >= -0.010 and #t < #r, "p:transform crops and renames")
check.near(t:bounds().y_min + t:bounds().y_max, 0.004, 1e-9, "p:transform shifts a symmetric head by 2 mm")
check.fails(function() r:transform{mirror = true} end, "unknown key 'mirror'", "unknown transform key")
check.fails(function() r:transform{crop = {z = {0.001, -0.010}}} end, "min < max", "reversed crop window")
check.fails(function() wrc.profile.load(f, {mirror_y = "yes"}) end, "'mirror_y' must be a boolean", "mirror_y as a string")
check.fails(function() wrc.profile.load(f, {units = {}}) end, "'units' must be", "units as a table")
check.fails(function() wrc.profile.load(f, {units = "furlong"}) end, "units must be \"mm\"", "unknown unit")
check.fails(function() wrc.profile.load(f, {shift = {x = 1}}) end, "unknown key 'x'", "shift with x")
print("profile_lua_api: Lua reader, definitions and options checked")
