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
-- A label with a quote, and a palette of its own.
out.map{file = dir .. "/q.png", x = {0, 1}, y = {0, 1}, value = {{0, 1}, {1, 2}}, title = "the rail's profile",
        ylabel = "s along the rail's profile (mm)", palette = "defined (0 'white', 1 '#3060c0', 2 '#d03020')"}
check.ok(assert(io.open(dir .. "/q.png", "rb")):read("a"):sub(2, 4) == "PNG", "a label with a quote, a palette")
-- A figure's script runs again from its own folder (issue 28: it named its data by the path the study was started
-- with): it names the data and the picture by their file names alone. Rerun here from the folder, into a fresh PNG.
for _, name in ipairs{"p", "m"} do
  local gp = assert(io.open(dir .. "/" .. name .. ".gp")):read("a")
  check.ok(not gp:find(dir, 1, true), name .. ".gp does not name the folder it was written from")
  os.remove(dir .. "/" .. name .. ".png")
  local q = "'" .. dir:gsub("'", "'\\''") .. "'"
  check.ok(os.execute("cd " .. q .. " && gnuplot " .. name .. ".gp 2>/dev/null"), "gnuplot " .. name .. ".gp in its folder")
  local again = io.open(dir .. "/" .. name .. ".png", "rb")
  check.ok(again and again:read("a"):sub(2, 4) == "PNG", name .. ".png written again by its script")
end
print("output ok")

-- CSV cells: text with commas, quotes or line breaks quoted and read back; a non-finite number names the file, the
-- row and the column; a failed write leaves the old file whole (atomic) and no temporary file behind.
out.csv(dir .. "/q.csv", {"name", "v"}, {{'wheel "A", worn', 1}, {"line\nbreak", 2}, {"plain", 3}})
local _, q = out.read_csv(dir .. "/q.csv")
check.ok(q[1].name == 'wheel "A", worn' and q[2].name == "line\nbreak" and q[3].v == 3, "quoted cells read back")
out.csv(dir .. "/keep.csv", {"a", "b"}, {{1, 2}})
local before = assert(io.open(dir .. "/keep.csv")):read("a")
local err = check.fails(function() out.csv(dir .. "/keep.csv", {"a", "b"}, {{1, 2}, {3, 4}, {5, 0 / 0}}) end,
                        "keep.csv row 3 column b: value is not finite", "NaN names the row and the column")
check.ok(assert(io.open(dir .. "/keep.csv")):read("a") == before, "the old file is untouched: " .. err)
for _, name in ipairs(wrc.fs.list(dir)) do check.ok(not wrc.fs.is_temporary(name), "no temporary file left: " .. name) end
check.fails(function() out.map{file = dir .. "/bad.png", x = {0, 1}, y = {0}, value = {{1, 1 / 0}}} end,
            "value[1][2] at x = 1, y = 0", "a map names the grid point of a non-finite value")

-- gnuplot text is literal: an underscore in a title, a label or a series name stays an underscore (not a subscript,
-- as gnuplot's enhanced text would make it), and a quote does not end the string. The SVG terminal shows the text.
out.plot{file = dir .. "/names.svg", title = "S1002_worn vs 60E1_new", xlabel = "y_w (mm)", ylabel = "rail's z",
         series = {{x = {1, 2}, y = {1, 2}, title = "wheel_07 'hollow'"}}}
local svg = assert(io.open(dir .. "/names.svg")):read("a")
for _, text in ipairs{"S1002_worn vs 60E1_new", "y_w (mm)", "rail&apos;s z", "wheel_07 &apos;hollow&apos;"} do
  local plain = svg:find(text, 1, true) or svg:find((text:gsub("&apos;", "'")), 1, true)
  check.ok(plain ~= nil, "literal text in the SVG: " .. text)
end
check.ok(not svg:find("baseline%-shift"), "no sub- or superscripts in the SVG")
print("csv cells, atomic writes and literal plot text ok")
