-- Wrong inputs whose error once named the wrong thing, each synthesised here (a small file in the test's temporary
-- folder), the message checked for what it must name, against what the test itself knows of the file it wrote.
--
-- 1. A Simpack file (comment lines `! ...`, then header.begin) read as plain text (renamed .txt, or reader = "text"):
--    the text reader took the first `!` line as a header of 2 columns and failed on the next line's field count. `!`
--    and `%` lines are comments to it now, and a file that begins another format's file is refused naming the reader
--    that reads it (the same file read as Simpack gives the same points as its .prw).
-- 2. shift.y = 1e308 in a Simpack file was blamed on the file's unit ("are the coordinates in metres?", at a point's
--    line); the shift's key and line are named as out of range.
-- 3. 1e-400 in a profile file was "must be a number" (from_chars' underflow); it reads as 0 (the file with 0 there
--    gives the same profile), while 1e400 is "out of range", not "not a number".
-- 4. An unknown strategy gave its message followed by a Lua traceback inside the message, even under pcall; the
--    message has no traceback and lists the strategies of scripts/strategies (each listed one builds a wheelset, and
--    the one module not listed, the composer, is refused as not a strategy). A runtime error inside a strategy file
--    keeps its traceback: that is a bug in the file, and the traceback says where.
-- 5. Lua's 0/0 has its sign bit set, and messages wrote it "-nan" (a negative that is not one), -(0/0) "nan": an
--    option, a point of a profile, a reader's option passed on as text, a pose, a check or a table cell of the scripts;
--    each message says NaN now, whatever the sign, and infinities inf / -inf.
-- 6. A path holding a NUL byte ("w.txt\0.csv", a Lua string may hold one) was cut at the NUL on its way to the
--    system: wrc.profile.load read and p:write wrote another file than the one named, silently. Such a path is refused,
--    naming the NUL, and no file is written at the cut name (the test looks in the folder itself).
-- 7. An empty Lua table where an array is expected ({} for y, yhat, a sweep's y) was "must be an array of numbers, got
--    table": Lua's {} is an empty array as much as a table, and the message now says what is wrong, that it is empty.
-- 8. wrc.wheelset{wheel = a, left_wheel = b, right_wheel = c} built with b and c, 'wheel' silently unused (no error
--    named the key that had no effect); it is refused, naming the keys. 'wheel' with one side's own stays the two
--    profiles it says (checked against the wheelset built with both sides given).
local check = require "wrc.check"
local H = dofile((arg[0]:match("(.*/)") or "./") .. "../data/profile/helpers.lua")
local tmp = (arg.tmp or ".") .. "/input_messages_"
wrc.fs.mkdir(arg.tmp or ".")

local s1002 = wrc.profile.load(wrc.paths.profiles .. "/s1002.lua", {step = 1e-3})
local rail = wrc.profile.load(wrc.paths.profiles .. "/60e1.lua", {step = 1e-3})

-- The line of a file that holds `text` (plain), counted here.
local function line_of(path, text)
  local n = 0
  for line in io.lines(path) do
    n = n + 1
    if line:find(text, 1, true) then return n end
  end
end

-- ---- 1. a Simpack file given to the text reader ----
local prw = H.write_simpack(tmp .. "wheel.prw", s1002)
local txt = H.write(tmp .. "wheel.txt", io.open(prw):read("a"))
local begin = line_of(txt, "header.begin")
check.ok(begin > 1, "the file starts with comment lines before header.begin (line " .. begin .. ")")
for _, try in ipairs{{txt, {kind = "wheel"}}, {prw, {reader = "text", kind = "wheel"}}} do
  local err = check.fails(function() return wrc.profile.load(try[1], try[2]) end, "Simpack", "a Simpack file read as text")
  check.ok(err:find(try[1] .. ":" .. begin .. ":", 1, true) and err:find('reader = "simpack"', 1, true)
           and err:find(".prw", 1, true) and not err:find("fields", 1, true),
           "the message names header.begin's line and the reader to use: " .. err)
end
local as_simpack = wrc.profile.load(txt, {reader = "simpack"})
local py, pz = wrc.profile.load(prw):points()
local ty, tz = as_simpack:points()
check.ok(#ty == #py and ty[1] == py[1] and tz[#tz] == pz[#pz], "read as Simpack, the .txt gives the .prw's points")
-- `!` and `%` lines are comments to the text reader: the same points as the file without them.
local plain = H.write_text(tmp .. "plain.txt", s1002)
local commented = H.write(tmp .. "commented.txt", "! ****\n! exported by a program that writes ! comments\n% and %\n"
                          .. io.open(plain):read("a"))
local ay, az = wrc.profile.load(plain, {kind = "wheel"}):points()
local by, bz = wrc.profile.load(commented, {kind = "wheel"}):points()
local same = #ay == #by
for i = 1, #ay do same = same and ay[i] == by[i] and az[i] == bz[i] end
check.ok(same, "comment lines change no point")
check.fails(function() return wrc.profile.load(H.write(tmp .. "comments.txt", "! a\n% b\n# c\n\n"), {kind = "wheel"}) end,
            "only comments and blank lines", "a file of only comments")
-- The other formats given to the text reader, and a text file given to the Simpack reader.
check.fails(function() return wrc.profile.load(H.write_miniprof(tmp .. "wheel.whl", s1002), {reader = "text"}) end,
            'reader = "miniprof"', "a MiniProf file read as text")
check.fails(function() return wrc.profile.load(plain, {reader = "simpack"}) end, 'reader = "text"',
            "a text file read as Simpack")

-- ---- 2. a shift out of range ----
local far = H.write_simpack(tmp .. "far.prw", s1002, {shift_y = 1e308})
local shift_line = line_of(far, "shift.y")
local err = check.fails(function() return wrc.profile.load(far) end, "shift.y", "shift.y = 1e308")
check.ok(err:find(far .. ":" .. shift_line .. ":", 1, true) and err:find("out of range", 1, true)
         and not err:find("metres?", 1, true), "the shift's line, out of range, not the unit: " .. err)
-- 2 km in the file's mm: refused the same way.
err = check.fails(function() return wrc.profile.load(H.write_simpack(tmp .. "km.prw", s1002, {shift_z = -2e6})) end,
                  "shift.z", "shift.z = 2 km")
check.ok(err:find("out of range", 1, true), err)
-- The same for the loader's own shift option (2000 given as metres, meant as mm), and a Simpack point.dist.min that
-- leaves fewer than 3 points is named, not the count of points read.
err = check.fails(function() return wrc.profile.load(prw, {shift = {z = 2000}}) end, "shift.z = 2000 m is out of range",
                  "shift = {z = 2000}")
check.ok(not err:find("are the coordinates", 1, true), "the shift, not the points' unit: " .. err)
local sparse = H.write(tmp .. "sparse.prw", (io.open(prw):read("a"):gsub("point.dist.min = 0", "point.dist.min = 1e300")))
err = check.fails(function() return wrc.profile.load(sparse) end, "point.dist.min = '1e300' leaves 1 of the",
                  "point.dist.min = 1e300")
check.ok(err:find(sparse .. ":" .. line_of(sparse, "point.dist.min") .. ":", 1, true), "its line: " .. err)

-- ---- 3. underflow and overflow ----
local function cone_with(z)
  return H.write(tmp .. "cone.txt", ("-70 1.75\n0 %s\n60 -1.5\n"):format(z))
end
local zy, zz = wrc.profile.load(cone_with("0"), {kind = "wheel"}):points()
for _, tiny in ipairs{"1e-400", "-1e-400", "2.4e-324"} do
  local uy, uz = wrc.profile.load(cone_with(tiny), {kind = "wheel"}):points()
  check.ok(uy[2] == zy[2] and uz[2] == zz[2] and uz[2] == 0, tiny .. " reads as 0")
end
err = check.fails(function() return wrc.profile.load(cone_with("1e400"), {kind = "wheel"}) end, "out of range", "1e400")
check.ok(err:find(":2:", 1, true) and not err:find("must be a number", 1, true), "the line, not 'not a number': " .. err)

-- ---- 4. strategy messages ----
err = check.fails(function() return wrc.wheelset{wheel = s1002, rail = rail, strategy = "nonexistent"} end,
                  "unknown strategy 'nonexistent'", "an unknown strategy")
check.ok(not err:find("traceback", 1, true), "no traceback in the message: " .. err)
local listed = err:match("%(strategies: ([%w_, ]+)%)")
check.ok(listed ~= nil, "the message lists the strategies: " .. err)
local names = {}
for name in listed:gmatch("[%w_]+") do
  names[name] = true
  local ws = wrc.wheelset{wheel = s1002, rail = rail, strategy = name}
  check.ok(ws.strategy.name == name, "listed strategy '" .. name .. "' builds a wheelset")
end
for _, file in ipairs(wrc.fs.list(wrc.paths.scripts .. "/strategies")) do
  local name = file:match("^(.+)%.lua$")
  if name and not names[name] then
    check.fails(function() return wrc.wheelset{wheel = s1002, rail = rail, strategy = name} end, "is not a strategy",
                "the unlisted module '" .. name .. "'")
  end
end
-- A misspelt option, a misspelt name inside a composition, options out of range (checked by the strategy's assert,
-- and by the engine function it calls): messages without traceback.
for _, case in ipairs{{{"fast", stpe = 1e-4}, "strategy option 'stpe' is not used by fast"},
                      {{"constant_slope", "coarse", "topolgy"}, "unknown strategy 'topolgy'"},
                      {{"uniform", step = -1}, "uniform: step must be a positive number"},
                      {{"fast", slope_step = -1}, "slope_step must be a positive angle"}} do
  err = check.fails(function() return wrc.wheelset{wheel = s1002, rail = rail, strategy = case[1]} end, case[2], case[2])
  check.ok(not err:find("traceback", 1, true), "no traceback: " .. err)
end
-- A strategy file with a bug that runs while the strategy is resolved (its defaults' __pairs indexes nil): the
-- traceback stays, and it names the file's line.
local buggy = H.write(tmp .. "buggy_strategy.lua", [[
return {
  defaults = setmetatable({}, {__pairs = function(t)
    local missing
    return missing.next
  end}),
  scan = "test",
}
]])
err = check.fails(function() return wrc.wheelset{wheel = s1002, rail = rail, strategy = buggy} end,
                  "attempt to index", "a bug in a strategy file")
check.ok(err:find("stack traceback", 1, true) and err:find("buggy_strategy.lua:4:", 1, true),
         "the bug keeps its traceback, with the file's line: " .. err)

-- ---- 5. NaN and infinities in messages ----
local whl = H.write_miniprof(tmp .. "wheel5.whl", s1002)
local ws = wrc.wheelset{wheel = s1002, rail = rail}
for _, nan in ipairs{0 / 0, -(0 / 0)} do
  local calls = {
    {function() return wrc.profile.load(whl, {shift = {y = nan}}) end, "'y' must be finite, got NaN"},
    {function() return wrc.profile.load(whl, {tape_x = nan}) end, "option tape_x must be a finite number, got 'NaN'"},
    {function() return wrc.profile.points{kind = "rail", y = {0, nan, 2e-3}, z = {0, 0, 0}} end,
     "the 2nd value of 'y' must be finite, got NaN"},
    {function() return ws:contact{y = nan, z = 0} end, "'y' must be finite, got NaN"},
    {function() return s1002:interpolate(nan) end, "must be finite, got NaN"},
  }
  for i, c in ipairs(calls) do
    err = check.fails(c[1], c[2], ("NaN (%s) in call %d"):format(tostring(nan), i))
    check.ok(not err:find("nan", 1, true) and not err:find("-NaN", 1, true), "no nan nor -NaN: " .. err)
  end
end
-- The scripts' messages (wrc.check, wrc.output, the wear loop) write numbers with wrc.number_text, the same convention.
for _, c in ipairs{{0 / 0, "NaN"}, {-(0 / 0), "NaN"}, {1 / 0, "inf"}, {-1 / 0, "-inf"}, {0.1, "0.1"}, {-2.5e-7, "-2.5e-07"},
                   {3, "3"}, {2^53 + 0.0, "9007199254740992"}} do
  check.ok(wrc.number_text(c[1]) == c[2], ("wrc.number_text: %s, expected %s"):format(wrc.number_text(c[1]), c[2]))
end
err = check.fails(function() check.near(0 / 0, 1, 0.1, "a NaN result") end, "a NaN result = NaN, expected 1", "check.near")
err = check.fails(function() require("wrc.output").csv_line({"x"}, {x = 0 / 0}, "t row 2") end,
                  "t row 2 column x: value is not finite (NaN)", "a NaN cell")
check.fails(function() return ws:contact{y = -1 / 0, z = 0} end, "'y' must be finite, got -inf", "-inf")
check.fails(function() return ws:contact{y = 1 / 0, z = 0} end, "'y' must be finite, got inf", "inf")

-- ---- 6. a NUL byte in a path ----
local cut = tmp .. "nul_cut.txt"
wrc.fs.remove(cut)  -- a run before this one left it
check.ok(wrc.fs.kind(cut) == nil, "no file at the cut name before the calls")
local whole = H.write(cut .. ".real.txt", "-30 -9\n0 0\n30 -9\n")  -- a file exists beyond the NUL's cut too
check.fails(function() return s1002:write(cut .. "\0.csv") end, "holds a NUL character", "p:write to 'x.txt\\0.csv'")
check.fails(function() return wrc.fs.write_file(cut .. "\0x", "text") end, "holds a NUL character", "wrc.fs.write_file")
check.ok(wrc.fs.kind(cut) == nil, "nothing was written at the cut name 'nul_cut.txt'")
H.write(cut, "-30 -9\n0 0\n30 -9\n")  -- now the cut name is a readable profile: loading it would be wrong
err = check.fails(function() return wrc.profile.load(cut .. "\0.real.txt", {kind = "rail"}) end,
                  "holds a NUL character", "wrc.profile.load of 'x.txt\\0.real.txt'")
check.ok(err:find("nul_cut.txt\\0.real.txt", 1, true), "the message shows the NUL: " .. err)
check.ok(#wrc.profile.load(whole, {kind = "rail"}) == 3, "the path without the NUL loads")

-- ---- 7. an empty table for an array ----
for _, c in ipairs{
    {function() return wrc.profile.points{kind = "rail", y = {}, z = {}} end, "needs at least 3 distinct points, got 0"},
    {function() return ws:conicity{yhat = {}} end, "'yhat' needs at least one amplitude"},
    {function() return ws:sweep{y = {}, Q = 2e5} end, "'y' is empty"},
    {function() return ws:geometry_table{y = {}} end, "'y' is empty"},
    {function() return wrc.wear.arc_length{y = {}, z = {}} end, "needs at least 2 points, got 0"}} do
  err = check.fails(c[1], c[2], c[2])
  check.ok(not err:find("got table", 1, true), "not 'got table': " .. err)
end

-- ---- 8. 'wheel' or 'rail' with both sides' own ----
err = check.fails(function() return wrc.wheelset{wheel = s1002, left_wheel = s1002, right_wheel = s1002, rail = rail} end,
                  "'wheel' is given, and so are 'left_wheel' and 'right_wheel'", "wheel shadowed on both sides")
check.fails(function() return wrc.wheelset{wheel = s1002, rail = rail, left_rail = rail, right_rail = rail} end,
            "'rail' is given, and so are 'left_rail' and 'right_rail'", "rail shadowed on both sides")
local worn = wrc.profile.load(wrc.paths.profiles .. "/worn_s1002.lua")
local one = wrc.wheelset{wheel = s1002, left_wheel = worn, rail = rail}
local four = wrc.wheelset{left_wheel = worn, right_wheel = s1002, left_rail = rail, right_rail = rail}
local same = wrc.wheelset{wheel = s1002, rail = rail}
check.ok(one:rigid{y = 1e-3}.z == four:rigid{y = 1e-3}.z and one:rigid{y = 1e-3}.z ~= same:rigid{y = 1e-3}.z,
         "'wheel' with 'left_wheel' is the right wheel's profile, the left one's its own")
print("input_messages: ok")
