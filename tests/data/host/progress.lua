-- Progress lines and notes are drawn by the front end (tests/host_stderr.cmake reads stderr): a sweep, a geometry
-- table and a strategy check with progress = arg.progress ("true", "false", or not given: stderr is a terminal, which
-- under a test it is not), each asked for more threads than its work has use for (a note on stderr).
local progress = ({["true"] = true, ["false"] = false})[arg.progress]
local wheel = wrc.profile.load(wrc.paths.profiles .. "/s1002.lua", {step = 1e-3})
local rail = wrc.profile.load(wrc.paths.profiles .. "/60e1.lua", {step = 1e-3})
local ws = wrc.wheelset{wheel = wheel, rail = rail, grid = 1e-3}
local s = ws:sweep{y = {0, 1e-3}, Q = 200e3, threads = 8, progress = progress}
assert(#s == 2 and s.threads == 1)
local t = ws:geometry_table{y = {from = 0, to = 1e-3, step = 0.5e-3}, threads = 4, progress = progress}
assert(#t.rows == 3 and t.threads == 1)
assert(ws:check_strategy{poses = 3, threads = 1, progress = progress}.poses == 3)
