-- Profile definitions are data (docs/guide/studies.md "What is code and what is data"): a definition runs in a sandbox,
-- so that a hostile one cannot reach the system (each attempt below would create a marker file; none may exist
-- afterwards, and each is refused with a message naming what is missing), cannot escape its budgets of instructions,
-- memory and profile points (not even by catching the error), and still has what a definition needs. Also the point
-- limit of every profile (kMaxProfilePoints) and the lookup rule of "profiles/NAME" seen from a study.
local check = require "wrc.check"
local H = dofile(os.getenv("WRC_TEST_DATA") .. "/profile/helpers.lua")
local tmp = H.tmpdir() .. "/profile_sandbox_"
local marker = tmp .. "MARKER"
os.remove(marker)

local function marker_exists()
  local f = io.open(marker, "r")
  if f then f:close() end
  return f ~= nil
end

-- Writes a definition and loads it; it must fail with `expected` in the message and leave no marker behind.
local function refused(name, code, expected)
  local path = H.write(tmp .. name .. ".lua", (code:gsub("MARKER", marker)))
  check.fails(function() wrc.profile.load(path) end, expected, name)
  check.ok(not marker_exists(), name .. ": nothing ran outside the sandbox (no marker file)")
end

local unavailable = "is not available in a profile definition: a definition is data and runs in a sandbox"
refused("os_execute", [[os.execute("touch 'MARKER'")]], "'os' " .. unavailable)
refused("io_open", [[local f = io.open("MARKER", "w") f:write("x") f:close()]], "'io' " .. unavailable)
refused("loadlib", [[package.loadlib("libc.so.6", "system")("touch 'MARKER'")]], "'package' " .. unavailable)
refused("require", [[require("os").execute("touch 'MARKER'")]], "'require' " .. unavailable)
refused("dofile", [[dofile("MARKER")]], "'dofile' " .. unavailable)
refused("loadfile", [[loadfile("MARKER")]], "'loadfile' " .. unavailable)
refused("debug", [[debug.getregistry()]], "'debug' " .. unavailable)
refused("collectgarbage", [[collectgarbage("stop")]], "'collectgarbage' " .. unavailable)
refused("print", [[print("hello")]], "'print' " .. unavailable)
refused("string_dump", [[return string.dump(function() end)]], "'string.dump' " .. unavailable)
refused("wrc_fs", [[wrc.fs.write("MARKER", "x")]], "attempt to index a nil value (field 'fs')")
refused("wrc_wheelset", [[return wrc.wheelset{}]], "attempt to call a nil value (field 'wheelset')")
refused("hidden_global", [[local e = _G or _ENV; return e["o" .. "s"].execute("touch 'MARKER'")]], "'os' " .. unavailable)

-- Binary chunks (precompiled Lua can crash the VM): neither as the file nor through load.
local escape = string.dump(function() os.execute("touch '" .. marker .. "'") end)
local binary = H.write(tmp .. "binary.lua", escape)
check.fails(function() wrc.profile.load(binary) end, "attempt to load a binary chunk (mode is 't')", "a binary definition")
refused("load_binary", "return assert(load(" .. ("%q"):format(escape) .. "))()", "attempt to load a binary chunk (mode is 't')")
check.ok(not marker_exists(), "no binary chunk ran")

-- A profile's metatable (its __gc, which would release the profile twice) is out of reach.
local mt_def = H.write(tmp .. "metatable.lua", [[
local p = wrc.profile.points{kind = "rail", y = {-0.01, 0, 0.01}, z = {-1e-3, 0, -1e-3}}
local mt = getmetatable(p)
return wrc.profile.points{kind = "rail", name = type(mt) .. " " .. tostring(mt), y = {-0.01, 0, 0.01}, z = {-1e-3, 0, -1e-3}}
]])
check.ok(wrc.profile.load(mt_def).name == "string wrc.Profile", "getmetatable(profile) gives its name only")

-- Inside a definition wrc.profile.load takes the shipped profiles only.
refused("load_own_file", ("return wrc.profile.load(%q)"):format(tmp .. "os_execute.lua"),
        "a profile definition may load only the profiles shipped with wrc")
refused("load_relative", [[return wrc.profile.load("./profiles/s1002.lua")]],
        "a profile definition may load only the profiles shipped with wrc")

-- Budgets: instructions, memory, profile points; catching the error with pcall does not carry on.
refused("endless_loop", [[while true do end]], "exceeded its CPU budget (1000000000 Lua instructions)")
refused("endless_pcall", [[while true do pcall(function() while true do end end) end io.open("MARKER", "w")]],
        "exceeded its CPU budget")
refused("huge_table", [[local t = {} for i = 1, 1e10 do t[i] = {i} end]], "exceeded its memory budget (256 MB)")
refused("huge_pcall", [[
local keep = {}
for k = 1, 1e6 do pcall(function() local s = "x" for i = 1, 40 do s = s .. s end keep[k] = s end) end
os.execute("touch 'MARKER'")]], "exceeded its memory budget (256 MB)")
refused("many_points", [[
local p = wrc.profile.load("profiles/s1002.lua", {step = 0.16 / 999990})
local t = {}
for i = 1, 1e6 do t[i] = p:resample{step = 0.16 / 999990} end]], "made more profile points than its budget (6000000 in all)")

-- What a definition legitimately uses: its options, math, string, table, load of text, pcall and error, the shipped
-- profiles and wrc.profile.points. Its S1002 is the one a study loads.
local legit = H.write(tmp .. "legit.lua", [[
local opt = ...
local ok, err = pcall(error, "caught")
assert(not ok and err:find("caught"))
local twice = load("local x = ... return 2 * x")
local base = wrc.profile.load("profiles/s1002.lua", {step = opt.step})
local y, z = base:points()
local order = {3, 1, 2}
table.sort(order)
assert(table.concat(order, ",") == "1,2,3" and select("#", 1, 2) == 2 and math.floor(twice(1.5)) == 3)
assert(#y <= wrc.profile.max_points)
return wrc.profile.points{kind = "wheel", name = string.format("copy of %s", base.name), y = y, z = z}
]])
local copy = wrc.profile.load(legit, {step = 0.5e-3})
local direct = wrc.profile.load("profiles/s1002.lua", {step = 0.5e-3})
check.ok(copy.name == "copy of S1002" and #copy == #direct, "a definition built on the shipped S1002")
local cy, cz = copy:points()
local dy, dz = direct:points()
for i = 1, #dy, 37 do check.ok(cy[i] == dy[i] and cz[i] == dz[i], "the same S1002 point " .. i) end

-- One point limit for every profile: the shipped definitions refuse a step that would exceed it (1e-9 m gave 130 M
-- points and an out-of-memory kill), wrc.profile.points and resampling refuse more points.
check.ok(wrc.profile.max_points == 1000000, "wrc.profile.max_points")
check.fails(function() wrc.profile.load("profiles/s1002.lua", {step = 1e-9}) end,
            "s1002: step = 1e-09 m gives 130000002 points, more than a profile may have (wrc.profile.max_points = 1000000)",
            "S1002 at 1 nm")
check.fails(function() wrc.profile.load("profiles/60e1.lua", {step = 1e-9}) end, "more than a profile may have", "60E1 at 1 nm")
check.fails(function() wrc.profile.load("profiles/worn_s1002.lua", {step = 1e-9}) end, "more than a profile may have",
            "worn S1002 at 1 nm")
local many = {}
for i = 1, wrc.profile.max_points + 1 do many[i] = i * 1e-9 end
check.fails(function() wrc.profile.points{kind = "rail", y = many, z = many} end,
            "wrc.profile.points gives 1000001 points, more than a profile may have (at most 1000000", "points")
check.fails(function() direct:resample{step = 1e-9} end, "more than a profile may have", "resampling at 1 nm")

-- The lookup rule: "profiles/NAME" is the shipped profile, whatever the working directory holds.
check.ok(wrc.profile.load("profiles/60e1.lua").source == wrc.paths.profiles .. "/60e1.lua", "profiles/60e1.lua is shipped")
check.fails(function() wrc.profile.load("profiles/../examples/conicity.lua") end, "not a shipped profile",
            "profiles/.. leaves the shipped folder")
check.ok(not marker_exists(), "no marker file at the end")
print("profile sandbox ok")
