-- wrc.output: tables (CSV with units in the headers) and plots (PNG through gnuplot) for study scripts.
--
--   local out = require "wrc.output"
--   out.mkdir("results")
--   out.csv("results/sweep.csv", {"y_mm", "z_mm"}, rows)        -- rows: arrays or tables keyed by column
--   out.plot{file = "results/z.png", xlabel = "y (mm)", ylabel = "z (mm)",
--            series = {{x = ys, y = zs, title = "yaw 0"}}}
--   out.map{file = "results/p.png", x = xs, y = ys, value = grid, ...}   -- grid[j][i] at (x[i], y[j])
local M = {}

local function quote(s) return "'" .. tostring(s):gsub("'", "'\\''") .. "'" end  -- for the shell
-- for gnuplot: '...' takes any text but a quote; with one, "..." with \\ and \" escaped
local function gp(s)
  s = tostring(s)
  if not s:find("'", 1, true) then return "'" .. s .. "'" end
  return '"' .. s:gsub('\\', '\\\\'):gsub('"', '\\"') .. '"'
end

-- mkdir -p
function M.mkdir(path)
  if wrc.fs and wrc.fs.mkdir then return wrc.fs.mkdir(path) end
  local ok = os.execute("mkdir -p " .. quote(path))
  if not ok then error("cannot create folder " .. path, 2) end
end

local function fmtnum(v, where)
  if type(v) ~= "number" then
    if v == nil then return "" end
    return tostring(v)
  end
  if v ~= v or v == math.huge or v == -math.huge then error(where .. ": value is not finite (" .. tostring(v) .. ")", 3) end
  if math.type(v) == "integer" then return tostring(v) end
  return string.format("%.10g", v)
end

-- Writes a CSV file. columns: header names (units in the names, e.g. "y_mm"); rows: array of rows, each
-- an array in column order or a table keyed by column name. Missing values are written empty.
function M.csv(path, columns, rows)
  local f, err = io.open(path, "w")
  if not f then error("cannot write " .. path .. ": " .. tostring(err), 2) end
  f:write(table.concat(columns, ","), "\n")
  for r, row in ipairs(rows) do
    local cells = {}
    for c, name in ipairs(columns) do
      local v = row[name]
      if v == nil then v = row[c] end
      cells[c] = fmtnum(v, string.format("%s row %d column %s", path, r, name))
    end
    f:write(table.concat(cells, ","), "\n")
  end
  f:close()
end

-- Reads a CSV file written by M.csv: returns columns, rows (tables keyed by column name).
function M.read_csv(path)
  local f, err = io.open(path, "r")
  if not f then error("cannot read " .. path .. ": " .. tostring(err), 2) end
  local header = f:read("l")
  local columns = {}
  for name in (header .. ","):gmatch("([^,]*),") do columns[#columns + 1] = name end
  local rows = {}
  for line in f:lines() do
    local row, c = {}, 0
    for cell in (line .. ","):gmatch("([^,]*),") do
      c = c + 1
      row[columns[c]] = tonumber(cell) or (cell ~= "" and cell or nil)
    end
    rows[#rows + 1] = row
  end
  f:close()
  return columns, rows
end

local function gnuplot(script_path, script)
  local f = assert(io.open(script_path, "w"))
  f:write(script)
  f:close()
  local ok = os.execute("gnuplot " .. quote(script_path) .. " 2>" .. quote(script_path .. ".log"))
  if not ok then
    local lf = io.open(script_path .. ".log")
    local log = lf and lf:read("a") or ""
    if lf then lf:close() end
    error("gnuplot failed on " .. script_path .. ": " .. log, 3)
  end
  os.remove(script_path .. ".log")
end

local function header(o)
  local s = {}
  s[#s + 1] = string.format("set terminal pngcairo size %d,%d enhanced font 'Sans,10'", o.width or 900, o.height or 600)
  s[#s + 1] = "set output " .. gp(o.file)
  if o.title then s[#s + 1] = "set title " .. gp(o.title) .. " noenhanced" end
  if o.xlabel then s[#s + 1] = "set xlabel " .. gp(o.xlabel) end
  if o.ylabel then s[#s + 1] = "set ylabel " .. gp(o.ylabel) end
  if o.zlabel then s[#s + 1] = "set zlabel " .. gp(o.zlabel) end
  if o.cblabel then s[#s + 1] = "set cblabel " .. gp(o.cblabel) end
  s[#s + 1] = "set grid"
  for _, line in ipairs(o.extra or {}) do s[#s + 1] = line end
  return s
end

-- Line plot. o.file (PNG), o.series = {{x=, y=, title=, style= "lines"|"points"|"linespoints"}, ...},
-- optional title, xlabel, ylabel, width, height, extra (gnuplot lines).
function M.plot(o)
  local s = header(o)
  local data = o.file:gsub("%.png$", "") .. ".dat"
  local f = assert(io.open(data, "w"))
  local parts = {}
  for k, se in ipairs(o.series) do
    assert(#se.x == #se.y, "output.plot: series " .. k .. " has x and y of different lengths")
    f:write("# ", se.title or ("series " .. k), "\n")
    for i = 1, #se.x do
      if se.y[i] == se.y[i] and se.x[i] == se.x[i] then  -- skip NaN (failed cases) as gaps
        f:write(fmtnum(se.x[i], data), " ", fmtnum(se.y[i], data), "\n")
      else
        f:write("\n")
      end
    end
    f:write("\n\n")
    parts[#parts + 1] = string.format("%s index %d using 1:2 with %s title %s", gp(data), k - 1,
                                      se.style or "lines", gp(se.title or ""))
  end
  f:close()
  s[#s + 1] = "plot " .. table.concat(parts, ", \\\n     ")
  gnuplot(o.file:gsub("%.png$", "") .. ".gp", table.concat(s, "\n") .. "\n")
end

-- Colour map of a grid: o.x (nx), o.y (ny), o.value[j][i] at (x[i], y[j]); o.view3d = true for a
-- surface seen in 3-D; o.contour = level list for contour lines; o.palette = a gnuplot palette definition (e.g.
-- "defined (0 'white', 1 'blue', 2 'red')") instead of the default colours.
function M.map(o)
  local s = header(o)
  local data = o.file:gsub("%.png$", "") .. ".dat"
  local f = assert(io.open(data, "w"))
  for j = 1, #o.y do
    for i = 1, #o.x do
      f:write(fmtnum(o.x[i], data), " ", fmtnum(o.y[j], data), " ", fmtnum(o.value[j][i], data), "\n")
    end
    f:write("\n")
  end
  f:close()
  s[#s + 1] = "set palette " .. (o.palette or "rgbformulae 33,13,10")
  if o.view3d then
    s[#s + 1] = "set pm3d depthorder"
    s[#s + 1] = "set view " .. (o.view or "55,30")
    s[#s + 1] = "splot " .. gp(data) .. " using 1:2:3 with pm3d notitle"
  else
    s[#s + 1] = "set view map"
    s[#s + 1] = "set size ratio -1"
    s[#s + 1] = "splot " .. gp(data) .. " using 1:2:3 with pm3d notitle"
  end
  gnuplot(o.file:gsub("%.png$", "") .. ".gp", table.concat(s, "\n") .. "\n")
end

return M
