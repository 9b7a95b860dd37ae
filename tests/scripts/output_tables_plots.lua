-- wrc.output: CSV tables (units in the headers, read back exactly, NaN refused) and gnuplot PNG plots.
local check = require "wrc.check"
local out = require "wrc.output"

local dir = (arg.tmp or "/tmp") .. "/output_test"
out.mkdir(dir .. "/nested/again")
local f = io.open(dir .. "/nested/again/probe", "w")
check.ok(f ~= nil, "mkdir -p made the nested folder")
f:close()

-- A table round trip: numbers written with 10 significant digits, rows as arrays or keyed by column.
local rows = {{1.25, -3e-7, 42}, {y_mm = 2.5, z_mm = 1 / 3, n = 7}}
out.csv(dir .. "/t.csv", {"y_mm", "z_mm", "n"}, rows)
local cols, back = out.read_csv(dir .. "/t.csv")
check.ok(cols[1] == "y_mm" and cols[2] == "z_mm" and cols[3] == "n", "header with units")
check.near(back[1].y_mm, 1.25, 0, "row 1 by position")
check.near(back[1].z_mm, -3e-7, 1e-17, "small number")
check.near(back[2].z_mm, 1 / 3, 1e-10, "10 significant digits")
check.near(back[2].n, 7, 0, "row 2 by name")
check.fails(function() out.csv(dir .. "/bad.csv", {"a"}, {{0 / 0}}) end, "not finite", "NaN is refused")

-- A plot: gnuplot writes a PNG (magic bytes), NaN points become gaps instead of errors.
out.plot{file = dir .. "/p.png", title = "a_b", xlabel = "x (mm)", ylabel = "y",
         series = {{x = {1, 2, 3, 4}, y = {1, 4, 0 / 0, 16}, title = "squares"}}}
local png = assert(io.open(dir .. "/p.png", "rb")):read("a")
check.ok(#png > 1000 and png:sub(2, 4) == "PNG", "a PNG was written")
out.map{file = dir .. "/m.png", x = {0, 1}, y = {0, 1, 2}, value = {{0, 1}, {1, 2}, {2, 3}}}
check.ok(assert(io.open(dir .. "/m.png", "rb")):read("a"):sub(2, 4) == "PNG", "a map PNG was written")
-- Labels with quotes (gnuplot doubles a quote inside '...', the shell's escape is not its own).
out.map{file = dir .. "/q.png", x = {0, 1}, y = {0, 1}, value = {{0, 1}, {1, 2}}, title = "the rail's profile",
        xlabel = "it's x", ylabel = "s along the rail's profile (mm)", cblabel = "'quoted'"}
check.ok(assert(io.open(dir .. "/q.png", "rb")):read("a"):sub(2, 4) == "PNG", "labels with quotes")
print("output ok")
