-- wrc.output: tables (CSV with units in the headers) and plots (PNG or SVG through gnuplot) for study scripts.
-- Every file is written atomically (a temporary file renamed over the target once complete, wrc.fs.open_atomic):
-- a run killed at any moment leaves the old file or the new one, never a part of one.
--
--   local out = require "wrc.output"
--   out.mkdir("results")
--   out.csv("results/sweep.csv", {"y_mm", "z_mm"}, rows)        -- rows: arrays or tables keyed by column
--   local w = out.csv_writer("results/big.csv", {"y_mm"})       -- streamed: w:row(row) ... w:close()
--   out.text("results/summary.txt", text)
--   out.plot{file = "results/z.png", xlabel = "y (mm)", ylabel = "z (mm)",
--            series = {{x = ys, y = zs, title = "yaw 0"}}}
--   out.map{file = "results/p.png", x = xs, y = ys, value = grid, ...}   -- grid[j][i] at (x[i], y[j])
local M = {}

-- Called with the path of every file this module commits (the study runner lists them in its manifest).
M.on_write = nil

local function shell_quote(s) return "'" .. tostring(s):gsub("'", "'\\''") .. "'" end

-- A gnuplot string literal: single quotes (nothing inside is interpreted but '' for a quote); a line break would
-- end the command, so it becomes a blank.
local function gp_string(s) return "'" .. tostring(s):gsub("[\r\n]", " "):gsub("'", "''") .. "'" end
M.gnuplot_string = gp_string

-- A file's path as gnuplot (and its command line) must get it: a relative path that starts with something else
-- than a letter, a digit, '_', '.' or '/' gets "./" in front, since gnuplot reads a file name that starts with '<'
-- or '|' as a shell command, with '$' as a datablock, and a first '-' on its command line as an option. A control
-- character cannot be written in a gnuplot string (a line break ends the command): an error.
local function plain_path(path)
  path = tostring(path)
  if path:find("%c") then
    local shown = path:gsub("%c", "?")
    error(("cannot make the figure '%s': a control character (a line break?) in its path"):format(shown), 0)
  end
  return path:match("^[%w_./]") and path or ("./" .. path)
end
local function gp_path(path) return gp_string(plain_path(path)) end
-- A figure's script names its data and picture by their file names alone and runs in their folder, so that it can be
-- run again from there (`gnuplot fig.gp` in the output folder), wherever the study was started.
local function leaf(path) return (tostring(path):match("[^/]*$")) end
local function folder(path)
  local d = tostring(path):match("^(.*)/[^/]*$")
  return d == nil and "." or (d == "" and "/" or d)
end

-- mkdir -p
function M.mkdir(path) return wrc.fs.mkdir(path) end

-- Opens `path` for an atomic write: returns a writer with :write(...) and :close() (commits the file; any error
-- before that leaves the old file in place).
function M.open(path)
  local f = wrc.fs.open_atomic(path)
  return {
    write = function(_, ...) f:write(...) end,
    close = function()
      f:commit()
      if M.on_write then M.on_write(path) end
    end,
    discard = function() f:discard() end,
  }
end

-- Writes a whole text file atomically.
function M.text(path, text)
  wrc.fs.write_file(path, text)
  if M.on_write then M.on_write(path) end
end

local function finite(v) return v == v and v ~= math.huge and v ~= -math.huge end

-- A cell: numbers with 10 significant digits (integers exactly), strings quoted when they hold a comma, a quote
-- or a line break (RFC 4180), nil empty. `where` names the row and column for the error on a non-finite number.
local function cell(v, where)
  if v == nil then return "" end
  if type(v) == "number" then
    if not finite(v) then error(where() .. ": value is not finite (" .. wrc.number_text(v) .. ")", 0) end
    if math.type(v) == "integer" then return tostring(v) end
    return string.format("%.10g", v)
  end
  if type(v) == "boolean" then return v and "1" or "0" end
  local s = tostring(v)
  if s:find('[,"\r\n]') then return '"' .. s:gsub('"', '""') .. '"' end
  return s
end
M.cell = function(v) return cell(v, function() return "output.cell" end) end

-- One CSV line (without the line break) of `row` (an array in column order or a table keyed by column name).
-- `where` (a string) names the table and row in the error for a non-finite value: "<where> column <name>".
function M.csv_line(columns, row, where)
  local cells = {}
  for c, name in ipairs(columns) do
    local v = row[name]
    if v == nil then v = row[c] end
    cells[c] = cell(v, function() return string.format("%s column %s", where or "csv", name) end)
  end
  return table.concat(cells, ",")
end

-- A streamed CSV table: w:row(row) appends a row, w:close() commits the file. Memory does not grow with the rows.
function M.csv_writer(path, columns)
  local f = M.open(path)
  f:write(table.concat(columns, ","), "\n")
  local n = 0
  local w = {}
  function w.row(_, row)
    n = n + 1
    local ok, line = pcall(M.csv_line, columns, row, string.format("%s row %d", path, n))
    if not ok then
      f:discard()
      error(line, 2)
    end
    f:write(line, "\n")
  end
  -- A row already formatted by M.csv_line (a study's part files hold them so).
  function w.append(_, line)
    n = n + 1
    f:write(line, "\n")
  end
  function w.close() f:close() end
  function w.discard() f:discard() end
  return w
end

-- Writes a CSV file. columns: header names (units in the names, e.g. "y_mm"); rows: array of rows, each
-- an array in column order or a table keyed by column name. Missing values are written empty; a non-finite
-- number is an error naming the file, the row and the column.
function M.csv(path, columns, rows)
  local w = M.csv_writer(path, columns)
  for _, row in ipairs(rows) do
    local ok, err = pcall(w.row, w, row)
    if not ok then error(err, 2) end
  end
  w:close()
end

-- Splits one CSV line into cells (quoted cells as M.csv writes them).
function M.split_csv(line)
  local cells, i, n = {}, 1, #line
  while i <= n + 1 do
    if line:sub(i, i) == '"' then
      local buf, j = {}, i + 1
      while true do
        local q = line:find('"', j, true)
        if not q then error("unterminated quoted cell: " .. line, 2) end
        buf[#buf + 1] = line:sub(j, q - 1)
        if line:sub(q + 1, q + 1) == '"' then
          buf[#buf + 1] = '"'
          j = q + 2
        else
          i = q + 1
          break
        end
      end
      cells[#cells + 1] = table.concat(buf)
      i = i + 1  -- the comma
    else
      local c = line:find(",", i, true) or (n + 1)
      cells[#cells + 1] = line:sub(i, c - 1)
      i = c + 1
    end
  end
  return cells
end

-- Reads a CSV file written by M.csv: returns columns, rows (tables keyed by column name; numbers converted).
function M.read_csv(path)
  local f, err = io.open(path, "r")
  if not f then error("cannot read " .. path .. ": " .. tostring(err), 2) end
  local columns = M.split_csv(f:read("l") or "")
  local rows = {}
  local pending = nil
  for text in f:lines() do
    local line = pending and (pending .. "\n" .. text) or text
    local _, quotes = line:gsub('"', "")
    pending = (quotes % 2 == 1) and line or nil  -- a quoted cell goes on on the next line
    if pending then goto continue end
    local row = {}
    for c, v in ipairs(M.split_csv(line)) do row[columns[c]] = tonumber(v) or (v ~= "" and v or nil) end
    rows[#rows + 1] = row
    ::continue::
  end
  f:close()
  if pending then error("cannot read " .. path .. ": a quoted cell is not closed", 2) end
  return columns, rows
end

-- Runs gnuplot on `script` (its `set output` given by the placeholder @OUTPUT@) so that the picture appears
-- atomically: the script is kept as <base>.gp with the final name, and run from a temporary copy that writes a
-- temporary picture, renamed once gnuplot succeeded.
local function gnuplot(file, script)
  local base = file:gsub("%.[^./]+$", "")
  M.text(base .. ".gp", (script:gsub("@OUTPUT@", function() return gp_path(leaf(file)) end)))
  -- Temporary names of wrc's own pattern (wrc.fs.is_temporary): a killed run's are recognised and removed, an
  -- interrupted run removes them itself until they are forgotten (once removed or renamed, or on an error).
  local tmp_png, tmp_gp, tmp_log = wrc.fs.temporary_name(file), wrc.fs.temporary_name(base .. ".gp"),
                                   wrc.fs.temporary_name(base .. ".log")
  local _ <close> = setmetatable({}, {__close = function()
    for _, name in ipairs{tmp_png, tmp_gp, tmp_log} do wrc.fs.forget_temporary(name) end
  end})
  local f = assert(io.open(tmp_gp, "w"))
  f:write((script:gsub("@OUTPUT@", function() return gp_path(leaf(tmp_png)) end)))
  f:close()
  local ok = os.execute("(cd " .. shell_quote(plain_path(folder(tmp_gp))) .. " && gnuplot " ..
                        shell_quote(plain_path(leaf(tmp_gp))) .. ") 2>" .. shell_quote(tmp_log))
  local lf = io.open(tmp_log)
  local log = lf and lf:read("a") or ""
  if lf then lf:close() end
  os.remove(tmp_gp)
  os.remove(tmp_log)
  if not ok then
    os.remove(tmp_png)
    error("gnuplot failed on " .. base .. ".gp: " .. log, 3)
  end
  local renamed, why = os.rename(tmp_png, file)
  if not renamed then
    os.remove(tmp_png)
    error("cannot write " .. file .. ": " .. tostring(why), 3)
  end
  if M.on_write then M.on_write(file) end
end

-- The terminal by the file's extension (.png or .svg). Text is not "enhanced" (an underscore in a profile name stays
-- an underscore) unless o.enhanced = true.
local function header(o)
  plain_path(o.file)  -- a path gnuplot cannot take fails before any file is written
  local s = {}
  local enh = o.enhanced and "enhanced" or "noenhanced"
  if o.file:match("%.svg$") then
    s[#s + 1] = string.format("set terminal svg size %d,%d %s font 'Sans,10'", o.width or 900, o.height or 600, enh)
  else
    s[#s + 1] = string.format("set terminal pngcairo size %d,%d %s font 'Sans,10'", o.width or 900, o.height or 600, enh)
  end
  s[#s + 1] = "set output @OUTPUT@"
  if o.title then s[#s + 1] = "set title " .. gp_string(o.title) end
  if o.xlabel then s[#s + 1] = "set xlabel " .. gp_string(o.xlabel) end
  if o.ylabel then s[#s + 1] = "set ylabel " .. gp_string(o.ylabel) end
  if o.zlabel then s[#s + 1] = "set zlabel " .. gp_string(o.zlabel) .. " rotate parallel" end
  if o.cblabel then s[#s + 1] = "set cblabel " .. gp_string(o.cblabel) end
  s[#s + 1] = "set grid"
  for _, line in ipairs(o.extra or {}) do s[#s + 1] = line end
  return s
end

local function data_name(o) return (o.file:gsub("%.[^./]+$", "")) .. ".dat" end

-- Line plot. o.file (PNG or SVG), o.series = {{x=, y=, title=, style= "lines"|"points"|"linespoints"}, ...},
-- optional title, xlabel, ylabel, width, height, enhanced, extra (gnuplot lines). NaN points become gaps.
function M.plot(o)
  local s = header(o)
  local data = data_name(o)
  local f = M.open(data)
  local parts = {}
  for k, se in ipairs(o.series) do
    assert(#se.x == #se.y, "output.plot: series " .. k .. " has x and y of different lengths")
    f:write("# ", (tostring(se.title or ("series " .. k)):gsub("[\r\n]", " ")), "\n")
    for i = 1, #se.x do
      if finite(se.x[i]) and finite(se.y[i]) then
        f:write(cell(se.x[i]), " ", cell(se.y[i]), "\n")
      else
        f:write("\n")  -- a gap (a failed case)
      end
    end
    f:write("\n\n")
    parts[#parts + 1] = string.format("%s index %d using 1:2 with %s title %s", gp_path(leaf(data)), k - 1,
                                      se.style or "lines", gp_string(se.title or ""))
  end
  f:close()
  s[#s + 1] = "plot " .. table.concat(parts, ", \\\n     ")
  gnuplot(o.file, table.concat(s, "\n") .. "\n")
end

-- Colour map of a grid: o.x (nx), o.y (ny), o.value[j][i] at (x[i], y[j]); o.view3d = true for a
-- surface seen in 3-D; o.palette = a gnuplot palette definition (e.g. "defined (0 'white', 1 'blue', 2 'red')")
-- instead of the default colours. A non-finite value is an error naming the grid point.
function M.map(o)
  local s = header(o)
  local data = data_name(o)
  local f = M.open(data)
  for j = 1, #o.y do
    for i = 1, #o.x do
      local where = function() return string.format("%s: value[%d][%d] at x = %s, y = %s", data, j, i, o.x[i], o.y[j]) end
      local ok, v = pcall(cell, o.value[j][i], where)
      if not ok then
        f:discard()
        error(v, 2)
      end
      f:write(cell(o.x[i]), " ", cell(o.y[j]), " ", v, "\n")
    end
    f:write("\n")
  end
  f:close()
  s[#s + 1] = "set palette " .. (o.palette or "rgbformulae 33,13,10")
  if o.view3d then
    s[#s + 1] = "set pm3d depthorder"
    s[#s + 1] = "set view " .. (o.view or "55,30")
  else
    s[#s + 1] = "set view map"
    s[#s + 1] = "set size ratio -1"
  end
  s[#s + 1] = "splot " .. gp_path(leaf(data)) .. " using 1:2:3 with pm3d notitle"
  gnuplot(o.file, table.concat(s, "\n") .. "\n")
end

-- Points in 3-D coloured by a value: o.points = {{x, y, z, value}, ...}; o.view = "65,35".
function M.scatter3d(o)
  local s = header(o)
  local data = data_name(o)
  local f = M.open(data)
  for k, p in ipairs(o.points) do
    local cells = {}
    for c = 1, 4 do
      local ok, v = pcall(cell, p[c], function() return string.format("%s: point %d, column %d", data, k, c) end)
      if not ok then
        f:discard()
        error(v, 2)
      end
      cells[c] = v
    end
    f:write(table.concat(cells, " "), "\n")
  end
  f:close()
  s[#s + 1] = "set palette rgbformulae 33,13,10"
  s[#s + 1] = "set view " .. (o.view or "65,35")
  s[#s + 1] = "set ticslevel 0"
  s[#s + 1] = "splot " .. gp_path(leaf(data)) .. " using 1:2:3:4 with points pt 7 ps 0.3 palette notitle"
  gnuplot(o.file, table.concat(s, "\n") .. "\n")
end

-- Histogram of values: o.values, o.bins (count, default 30) or o.bin_width; o.title, xlabel, ylabel, width, height.
function M.histogram(o)
  local lo, hi = math.huge, -math.huge
  for _, v in ipairs(o.values) do
    if finite(v) then lo, hi = math.min(lo, v), math.max(hi, v) end
  end
  local xs, counts = {}, {}
  if lo <= hi then
    local width = o.bin_width or ((hi > lo) and (hi - lo) / (o.bins or 30) or 1)
    local n = math.max(1, math.floor((hi - lo) / width + 1e-9) + 1)
    for b = 1, n do xs[b], counts[b] = lo + (b - 0.5) * width, 0 end
    for _, v in ipairs(o.values) do
      if finite(v) then
        local b = math.min(n, math.floor((v - lo) / width + 1e-9) + 1)
        counts[b] = counts[b] + 1
      end
    end
    o.extra = o.extra or {}
    table.insert(o.extra, string.format("set boxwidth %.10g absolute", width * 0.9))
    table.insert(o.extra, "set style fill solid 0.6")
  end
  M.plot{file = o.file, title = o.title, xlabel = o.xlabel, ylabel = o.ylabel or "count", width = o.width,
         height = o.height, extra = o.extra, enhanced = o.enhanced,
         series = {{x = xs, y = counts, title = o.series_title or "", style = "boxes"}}}
end

return M
