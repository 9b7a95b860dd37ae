-- wrc.study.run: studies that declare their options and cases, and run in one process or in shards on many
-- machines (README "Studies at scale"). A study's cases are cut into chunks (fixed by the study, never by the
-- number of shards or threads); a shard computes a contiguous range of chunks and streams their rows into part
-- files in DIR/parts, one atomic block file per batch of chunks (the checkpoint); a run again resumes after the last
-- block; the merge concatenates the blocks into exactly the tables a single process writes, then the study makes its
-- figures and summary from those tables, and a manifest lists what the run produced. Each block ends with a line of
-- its line count, size and hash (checked on resume and before a merge); a shard's run and a merge hold a lock in
-- DIR/parts. What an output folder holds is data from whoever made it: it names no script that is run, and no file
-- outside it (or through a link in it) is ever removed (wrc.fs.remove_inside).
--
--   local study = require "wrc.study"
--   local s = study.new{name =, help =, out = "results", options = {{"step_mm", "number", 0.1, "step (mm)"}, ...}}
--   local opt = s.options                      -- checked: an unknown key names the closest declared one
--   s:run{cases =, chunks =, tables =, compute =, finish =, inputs =, key =, key_columns =, batch =}
local out = require "wrc.output"
local fs = wrc.fs
local M = {}

local PARTS, MANIFEST = "parts", "manifest.txt"

local function exit(code, message) error({exit = code, message = message}, 0) end
local function say(fmt, ...) io.stderr:write("wrc: ", string.format(fmt, ...), "\n") end
-- Stops the run with a message (no traceback: the input is wrong, not the program).
local function refuse(code, fmt, ...)
  local text = string.format(fmt, ...)
  say("%s", text)
  exit(code, text)
end
-- Text from a folder or a command line shown on one line: control characters escaped.
local function printable(s)
  return (tostring(s):gsub("%c", function(ch) return ch == "\n" and "\\n" or ("\\%03d"):format(ch:byte()) end))
end
local function shell_quote(s) return "'" .. printable(s):gsub("'", "'\\''") .. "'" end
-- An engine error's message without the "file:line: " of the Lua line that made the call.
local function plain(err) return (tostring(err):gsub("^[^\n]-:%d+: ", "", 1)) end
local function finite(v) return v == v and v ~= math.huge and v ~= -math.huge end
local function command() return wrc.command or {shard = 1, shards = 1, shard_from = "", script = arg and arg[0] or "?"} end

-- Numbers as the shortest text that reads back to the same double.
local function canonical(v)
  if math.type(v) == "integer" then return tostring(v) end
  if type(v) ~= "number" then return tostring(v) end
  for digits = 15, 16 do
    local s = string.format("%." .. digits .. "g", v)
    if tonumber(s) == v then return s end
  end
  return string.format("%.17g", v)
end

----------------------------------------------------------------------------------------------------------------
-- Options

local TYPES = {number = "a number", integer = "a whole number", boolean = "true or false", string = "a string"}

local function convert(d, raw)
  local v
  if d.type == "string" then
    v = tostring(raw)
    -- state.txt and the manifest list options one per line
    if v:find("%c") then return nil, "a control character (a line break?) in the value is refused" end
  elseif d.type == "boolean" then
    local s = tostring(raw)
    if s == "true" or s == "1" or s == "yes" or s == "on" then v = true
    elseif s == "false" or s == "0" or s == "no" or s == "off" then v = false
    else return nil, "expected true or false" end
  else
    v = tonumber(raw)
    if v == nil or not finite(v) then return nil, "expected " .. TYPES[d.type] end
    if d.type == "integer" then
      v = math.tointeger(v)
      if v == nil then return nil, "expected a whole number" end
    end
  end
  if d.min and v < d.min then return nil, "must be >= " .. canonical(d.min) end
  if d.max and v > d.max then return nil, "must be <= " .. canonical(d.max) end
  if d.choices then
    local ok = false
    for _, c in ipairs(d.choices) do ok = ok or c == v end
    if not ok then return nil, "expected one of: " .. table.concat(d.choices, ", ") end
  end
  return v
end

-- The declared options: {name, type, default, help, min =, max =, choices =, hash = false} or the same with keys.
local function declare(spec)
  local list, byname = {}, {}
  local function add(o, where)
    local d = {name = o.name or o[1], type = o.type or o[2], help = o.help or o[4], min = o.min, max = o.max,
               choices = o.choices, hash = o.hash}
    if o.default ~= nil then d.default = o.default else d.default = o[3] end
    if type(d.name) ~= "string" or not d.name:match("^[%a_][%w_]*$") then
      error(where .. ": an option needs a name (letters, digits, _)", 4)
    end
    if not TYPES[d.type] then error(where .. ": option " .. d.name .. ": type must be number, integer, boolean or string", 4) end
    if type(d.help) ~= "string" then error(where .. ": option " .. d.name .. ": one line of help is required", 4) end
    if byname[d.name] then error(where .. ": option " .. d.name .. " is declared twice", 4) end
    if d.default ~= nil then
      local v, why = convert(d, d.default)
      if v == nil then error(where .. ": option " .. d.name .. ": default " .. tostring(d.default) .. ": " .. why, 4) end
      d.default = v
    end
    list[#list + 1], byname[d.name] = d, d
  end
  add({"out", "string", spec.out or "results", "output folder (created if missing)", hash = false}, "wrc.study.new")
  for k, o in ipairs(spec.options or {}) do add(o, "wrc.study.new: options[" .. k .. "]") end
  return list, byname
end

local function usage(study)
  local cmd = command()
  local lines = {("usage: wrc run %s [key=value ...] [--shard K/N] [--merge] [--fresh]\n" ..
                  "       wrc merge %s [out=DIR] [key=value ...]"):format(cmd.script, cmd.script)}
  if study.spec.help then lines[#lines + 1] = "\n" .. study.spec.help:gsub("%s+$", "") end
  lines[#lines + 1] = "\noptions (key=value):"
  local width = 0
  local shown = {}
  for _, d in ipairs(study.declared) do
    shown[d] = d.name .. "=" .. (d.default == nil and "" or canonical(d.default))
    width = math.max(width, #shown[d])
  end
  for _, d in ipairs(study.declared) do
    local extra = {}
    extra[#extra + 1] = d.type
    if d.min then extra[#extra + 1] = ">= " .. canonical(d.min) end
    if d.max then extra[#extra + 1] = "<= " .. canonical(d.max) end
    if d.choices then extra[#extra + 1] = table.concat(d.choices, "|") end
    if d.hash == false then extra[#extra + 1] = "does not change the results" end
    lines[#lines + 1] = ("  %-" .. width .. "s  %s (%s)"):format(shown[d], d.help, table.concat(extra, "; "))
  end
  lines[#lines + 1] = [[

flags:
  --shard K/N  compute part K of N (in a SLURM array job: from SLURM_ARRAY_TASK_ID; --shard wins)
  --merge      assemble the N parts into the outputs, then figures and summary (wrc merge: with the
               options the shards ran with, read from OUT/parts)
  --fresh      discard the parts of an earlier run and start over (a run resumes otherwise)
exit status: 0 done, 1 error, 2 bad options, 3 done with failed cases (OUT/failures.csv)]]
  return table.concat(lines, "\n") .. "\n"
end

-- The values of the declared options from the global `arg` (host key=value pairs); an unknown key or a bad value
-- stops the run naming it.
local function parse_options(study)
  local cmd = command()
  local values, given = {}, {}
  for k, v in pairs(arg or {}) do
    if math.type(k) == "integer" and k >= 1 then
      refuse(2, "%s: unexpected argument '%s' (options are key=value; --help lists them)", cmd.script, printable(v))
    elseif type(k) == "string" then
      local d = study.byname[k]
      if not d then
        local names = {}
        for _, e in ipairs(study.declared) do names[#names + 1] = e.name end
        local best = wrc.closest_name(k, names)
        refuse(2, "%s: unknown option '%s'%s (options: %s; --help describes them)", cmd.script, printable(k),
               best and (" (did you mean '" .. best .. "'?)") or "", table.concat(names, ", "))
      end
      local x, why = convert(d, v)
      if x == nil then refuse(2, "%s: option %s=%s: %s", cmd.script, k, printable(v), why) end
      values[k], given[#given + 1] = x, k
    end
  end
  for _, d in ipairs(study.declared) do
    if values[d.name] == nil then values[d.name] = d.default end
  end
  table.sort(given)
  return setmetatable(values, {__index = function(_, k)
    if study.byname[k] then return nil end
    error("study option '" .. tostring(k) .. "' is not declared (wrc.study.new{options = ...})", 2)
  end}), given
end

local Study = {}
Study.__index = Study
local adopt_recorded_options  -- below, with the parts

-- Declares a study: spec = {name =, help = "what it computes", out = "default folder", options = {...}}. Reads the
-- options from the command line; with --help, prints them and ends the run.
function M.new(spec)
  local cmd = command()
  local s = setmetatable({spec = spec, name = spec.name}, Study)
  s.declared, s.byname = declare(spec)
  if cmd.help then
    io.write(usage(s))
    exit(0)
  end
  if tostring(cmd.script):find("%c") then
    refuse(2, "the study's path %s holds a control character (a line break?): rename it", printable(cmd.script))
  end
  if cmd.from_parts then adopt_recorded_options(s, cmd) end
  s.options, s.given = parse_options(s)
  s.script = fs.absolute(cmd.script)
  -- The output folder is checked before anything is computed (a read-only folder found after the sweep loses it).
  s.dir = s.options.out:gsub("(.)/+$", "%1")
  local ok, err = pcall(function()
    fs.mkdir(s.dir)
    fs.check_writable(s.dir)
  end)
  if not ok then refuse(1, "%s", plain(err)) end
  return s
end

----------------------------------------------------------------------------------------------------------------
-- Fingerprints: what makes two runs the same study

local function fingerprint(v, where)
  local t = type(v)
  if t == "number" or t == "boolean" then return canonical(v) end
  if t == "string" then return #v <= 64 and v or ("hash " .. fs.hash(v)) end
  local mt = getmetatable(v)
  if mt and mt.__name == "wrc.Profile" then
    local y, z = v:points()
    local parts = {v.kind}
    for i = 1, #y do parts[#parts + 1] = string.format("%a %a", y[i], z[i]) end
    return "profile " .. fs.hash(table.concat(parts, "\n"))
  end
  if t == "table" then
    local keys = {}
    for k in pairs(v) do keys[#keys + 1] = k end
    table.sort(keys, function(a, b) return tostring(a) < tostring(b) end)
    local parts = {}
    for _, k in ipairs(keys) do parts[#parts + 1] = tostring(k) .. "=" .. fingerprint(v[k], where .. "." .. tostring(k)) end
    local s = "{" .. table.concat(parts, ",") .. "}"
    return #s <= 64 and s or ("hash " .. fs.hash(s))
  end
  error(where .. ": a " .. t .. " cannot be fingerprinted (give numbers, strings, profiles or tables of them)", 0)
end

-- The lines that define the study (options, inputs, engine, script, cases, chunks, tables) and their hash.
local function identity(study, r, layout)
  local lines = {"engine " .. wrc.version, "script " .. fs.hash_file(study.script)}
  for _, d in ipairs(study.declared) do
    if d.hash ~= false then lines[#lines + 1] = "option " .. d.name .. "=" .. canonical(study.options[d.name]) end
  end
  local keys = {}
  for k in pairs(r.inputs or {}) do keys[#keys + 1] = k end
  table.sort(keys)
  for _, k in ipairs(keys) do lines[#lines + 1] = "input " .. k .. "=" .. fingerprint(r.inputs[k], "inputs." .. k) end
  lines[#lines + 1] = "cases " .. r.cases
  lines[#lines + 1] = "chunks " .. layout
  for _, t in ipairs(r.tables or {}) do lines[#lines + 1] = "table " .. t.file .. " " .. table.concat(t.columns, ",") end
  return fs.hash(table.concat(lines, "\n")), lines
end

-- What differs between two identity listings, for the message that refuses to resume.
local function differences(old, new)
  local function split(lines)
    local m = {}
    for _, l in ipairs(lines) do
      local k, v = l:match("^(%S+ [^=]+)=(.*)$")
      if not k then k, v = l:match("^(%S+) (.*)$") end
      if k then m[k] = v end
    end
    return m
  end
  local a, b, diffs = split(old), split(new), {}
  for k, v in pairs(b) do
    if a[k] ~= v then diffs[#diffs + 1] = ("%s: %s -> %s"):format(k, a[k] or "(none)", v) end
  end
  for k, v in pairs(a) do
    if b[k] == nil then diffs[#diffs + 1] = ("%s: %s -> (none)"):format(k, v) end
  end
  local function rank(d)
    for r, p in ipairs{"option", "input", "script", "engine", "table"} do
      if d:sub(1, #p) == p then return r end
    end
    return 9
  end
  table.sort(diffs, function(x, y) return rank(x) < rank(y) or (rank(x) == rank(y) and x < y) end)
  return #diffs > 0 and table.concat(diffs, "; ") or "their inputs"
end

----------------------------------------------------------------------------------------------------------------
-- Chunks and shards

-- The chunk list: r.chunks (a list of {first =, last =} covering 1..cases in order) or chunks of r.chunk_size cases
-- (default 1), computed on demand so that 10^6 cases need no list.
local function chunk_layout(r)
  if r.chunks then
    local prev = 0
    for k, c in ipairs(r.chunks) do
      if c.first ~= prev + 1 or c.last < c.first then
        error(("study: chunks[%d] = %s..%s does not continue the cases after %d"):format(k, c.first, c.last, prev), 3)
      end
      prev = c.last
    end
    if prev ~= r.cases then error(("study: the chunks cover cases 1..%d of %d"):format(prev, r.cases), 3) end
    local firsts = {}
    for _, c in ipairs(r.chunks) do firsts[#firsts + 1] = c.first end
    return #r.chunks, function(k) return r.chunks[k].first, r.chunks[k].last end,
           "list " .. fs.hash(table.concat(firsts, ","))
  end
  local size = r.chunk_size or 1
  local n = (r.cases + size - 1) // size
  return n, function(k) return (k - 1) * size + 1, math.min(k * size, r.cases) end, "size " .. size
end

-- Shard K of N computes chunks lo..hi: contiguous, the same for every machine.
local function shard_range(k, n, chunks) return (k - 1) * chunks // n + 1, k * chunks // n end

local function shard_name(k, n) return ("shard-%d-of-%d"):format(k, n) end
local function block_name(a, b) return ("chunks-%09d-%09d.txt"):format(a, b) end

-- A word for a command shown to the user: as it is when the shell leaves it alone, else quoted.
local function shell_word(s)
  s = tostring(s)
  return (s:match("^[%w_%./=,:+@%%][%w_%./=,:+@%%%-]*$") and s) or shell_quote(s)
end

-- The blocks a shard folder holds, sorted by their first chunk (the longest first): {a, b, name}.
local function blocks_of(folder)
  local list = {}
  for _, name in ipairs(fs.list(folder)) do
    local a, b = name:match("^chunks%-(%d+)%-(%d+)%.txt$")
    if a then list[#list + 1] = {tonumber(a), tonumber(b), name} end
  end
  table.sort(list, function(x, y) return x[1] < y[1] or (x[1] == y[1] and x[2] > y[2]) end)
  return list
end

-- The blocks that do not overlap, in order, and the others (left by an earlier run with another batch size).
local function disjoint(blocks)
  local kept, extra, last = {}, {}, 0
  for _, b in ipairs(blocks) do
    if b[1] > last and b[2] >= b[1] then
      kept[#kept + 1], last = b, b[2]
    else
      extra[#extra + 1] = b
    end
  end
  return kept, extra
end

-- A block's text: its lines, then an end line with their count, their bytes and their hash, by which a later run
-- or the merge tells a whole block from one cut short or changed.
local function block_text(lines)
  local body = table.concat(lines, "\n") .. "\n"
  return body .. ("# end of block: %d lines, %d bytes, hash %s\n"):format(#lines, #body, fs.hash(body))
end

-- Why the block file at `path` is damaged, or nil when its end line vouches for it.
local function block_damage(path)
  local f = io.open(path, "rb")
  if not f then return "it cannot be read" end
  local size = f:seek("end")
  f:seek("set", math.max(0, size - 128))
  local tail = f:read("a") or ""
  f:close()
  local trailer = ("\n" .. tail):match("\n(# end of block: [^\n]*\n)$")
  local lines, bytes, hash = (trailer or ""):match("^# end of block: (%d+) lines, (%d+) bytes, hash (%x+)\n$")
  if not lines then return "its end line is missing (cut short, or written by a wrc that did not check blocks)" end
  if size ~= tonumber(bytes) + #trailer then return "its size is not the one its end line records" end
  local h, _, n = fs.digest(path, tonumber(bytes))
  if n ~= tonumber(lines) then return ("it holds %d lines where its end line records %s"):format(n, lines) end
  if h ~= hash then return "its content does not match its checksum (a value changed)" end
  return nil
end

-- A line of a block: "<tag> <text>", or "~<tag> <text>" with "\" and line breaks escaped when the text holds a line
-- break (a quoted CSV cell may: a file name from a folder), so that every row stays one line of the block.
local function part_line(tag, text)
  if not text:find("\n", 1, true) then return tag .. " " .. text end
  return "~" .. tag .. " " .. text:gsub("\\", "\\\\"):gsub("\n", "\\n")
end
local function unescape(text) return (text:gsub("\\(.)", function(ch) return ch == "n" and "\n" or ch end)) end

local function read_lines(path)
  local f = io.open(path, "r")
  if not f then return nil end
  local lines = {}
  for l in f:lines() do lines[#lines + 1] = l end
  f:close()
  return lines
end

-- state.txt of a shard folder: hash, script, shard, chunks, the given options (arg) and the identity lines.
local function write_state(folder, c)
  local t = {"wrc study parts", "hash " .. c.hash, "script " .. c.study.script,
             ("shard %d %d"):format(c.shard, c.shards), ("chunks %d %d %d"):format(c.lo, c.hi, c.nchunks)}
  for _, k in ipairs(c.study.given) do
    if k ~= "out" then t[#t + 1] = "arg " .. k .. "=" .. canonical(c.study.options[k]) end
  end
  for _, l in ipairs(c.lines) do t[#t + 1] = "line " .. l end
  fs.write_file(folder .. "/state.txt", table.concat(t, "\n") .. "\n")
end

local function read_state(folder)
  local lines = read_lines(folder .. "/state.txt")
  if not lines or lines[1] ~= "wrc study parts" then return nil end
  local st = {args = {}, lines = {}}
  for _, l in ipairs(lines) do
    local k, v = l:match("^(%S+) (.*)$")
    if k == "hash" or k == "script" then st[k] = v
    elseif k == "shard" then st.shard, st.shards = v:match("^(%d+) (%d+)$")
    elseif k == "chunks" then st.lo, st.hi, st.nchunks = v:match("^(%d+) (%d+) (%d+)$")
    elseif k == "arg" then st.args[#st.args + 1] = v
    elseif k == "line" then st.lines[#st.lines + 1] = v end
  end
  st.lo, st.hi, st.nchunks = tonumber(st.lo), tonumber(st.hi), tonumber(st.nchunks)
  st.shard, st.shards = tonumber(st.shard), tonumber(st.shards)
  return st
end

-- The shard folders of DIR/parts that are real folders: {name =, k =, n =, path =} in the order of their names.
local function shard_folders(dir)
  local root, list = dir .. "/" .. PARTS, {}
  if fs.kind(root) ~= "folder" or fs.is_link(root) then return list end
  for _, name in ipairs(fs.list(root)) do
    local k, n = name:match("^shard%-(%d+)%-of%-(%d+)$")
    local path = root .. "/" .. name
    if k and not fs.is_link(path) and fs.kind(path) == "folder" then
      list[#list + 1] = {name = name, k = tonumber(k), n = tonumber(n), path = path}
    end
  end
  return list
end

----------------------------------------------------------------------------------------------------------------
-- Locks: one run at a time computes a shard, one merges a folder

-- Locks DIR/parts/<name>.lock for the rest of the run (its process's end releases it, kill -9 too), or stops the run
-- naming the process that holds it.
local function take_lock(c, name, what)
  c.locks = c.locks or {}
  if c.locks[name] then return end
  local ok, err = pcall(fs.mkdir_inside, c.dir, PARTS)
  if not ok then refuse(1, "%s", plain(err)) end
  local lock, note
  ok, err = pcall(function() lock, note = fs.lock(c.dir .. "/" .. PARTS .. "/" .. name .. ".lock") end)
  if not ok then refuse(1, "%s", plain(err)) end
  if not lock then
    refuse(1, "%s: %s is being written by another wrc run (%s): wait until it ends, or stop it (its lock ends with " ..
           "its process)", c.dir, what, note)
  end
  if not lock.locked then say("%s: two runs into this folder at once are not kept apart", note) end
  c.locks[name] = lock
end
local function shard_lock(c, k, n) take_lock(c, shard_name(k, n), ("shard %d of %d"):format(k, n)) end
local function merge_lock(c)
  take_lock(c, "merge", "the folder (a merge, or a run of the whole study in one process)")
end

-- Removes the temporary files a killed run left in `rel` ("" for the output folder itself): names of the exact
-- pattern wrc gives them, plain files only. The lock this run holds says that no other run is writing them.
local function remove_temporaries(c, rel)
  local folder = rel == "" and c.dir or (c.dir .. "/" .. rel)
  for _, name in ipairs(fs.list(folder)) do
    if fs.is_temporary(name) then fs.remove_inside(c.dir, rel == "" and name or (rel .. "/" .. name)) end
  end
end

----------------------------------------------------------------------------------------------------------------
-- The output folder: manifest, unknown files, stale files

-- The manifest of DIR: its header fields (status, hash, ...) and known[name] = {size =, hash =} for every file it
-- lists as written or possibly left by a run. Names that do not name a file inside DIR are left out (ignored).
local function read_manifest(dir)
  local lines = read_lines(dir .. "/" .. MANIFEST)
  if not lines then return nil end
  local m = {known = {}, ignored = {}}
  for _, l in ipairs(lines) do
    local k, v = l:match("^(%S+) (.*)$")
    if k == "file" or k == "previous" then
      local name, size, hash = v:match("^(.-) (%d+) (%x+)$")
      name = name or v  -- a "previous" line of an earlier wrc: no size nor hash
      if fs.name_problem(name) then
        m.ignored[#m.ignored + 1] = name
      else
        m.known[name] = {size = tonumber(size), hash = hash}
      end
    elseif k then
      m[k] = v
    end
  end
  return m
end

-- Refuses a folder holding files that no wrc run listed: the run would mix its outputs with them.
local function check_folder(dir, quiet)
  local m = read_manifest(dir)
  local known = {}
  for name in pairs(m and m.known or {}) do known[name:match("^[^/]+")] = true end
  if m and #m.ignored > 0 and not quiet then
    local many = #m.ignored > 1
    say("%s/%s: ignored %d name%s that name%s no file inside the folder: %s", dir, MANIFEST, #m.ignored,
        many and "s" or "", many and "" or "s", printable(table.concat(m.ignored, ", ")))
  end
  local unknown = {}
  for _, name in ipairs(fs.list(dir)) do
    if name ~= MANIFEST and name ~= PARTS and not fs.is_temporary(name) and not known[name] then
      unknown[#unknown + 1] = name
    end
  end
  if #unknown > 0 then
    local shown = {table.unpack(unknown, 1, math.min(#unknown, 6))}
    refuse(1, "output folder '%s' holds %s that no wrc run listed in %s (%s%s): remove %s or choose another folder " ..
           "(out=...); a run never mixes its outputs with unknown files", dir,
           #unknown > 1 and (#unknown .. " files") or "a file", m and MANIFEST or "a manifest",
           printable(table.concat(shown, ", ")), #unknown > #shown and ", ..." or "", #unknown > 1 and "them" or "it")
  end
  return m
end

-- previous = {{name =, rec = {size =, hash =} or nil}, ...}: files that are or may be in the folder.
local function write_manifest(c, status, files, previous, extra)
  local t = {"# wrc study manifest: the files this run wrote into this folder (read by the next run into it)",
             "status " .. status, "study " .. c.study.script, "hash " .. c.hash, "engine wrc " .. wrc.version,
             "cases " .. c.cases}
  for _, l in ipairs(extra or {}) do t[#t + 1] = l end
  for _, k in ipairs(c.study.given) do
    if k ~= "out" then t[#t + 1] = "option " .. k .. "=" .. canonical(c.study.options[k]) end
  end
  for _, name in ipairs(files or {}) do
    local path = c.dir .. "/" .. name
    t[#t + 1] = ("file %s %d %s"):format(name, fs.size(path), fs.hash_file(path))
  end
  for _, p in ipairs(previous or {}) do
    local r = p.rec
    t[#t + 1] = (r and r.hash) and ("previous %s %d %s"):format(p.name, r.size, r.hash) or ("previous " .. p.name)
  end
  fs.write_file(c.dir .. "/" .. MANIFEST, table.concat(t, "\n") .. "\n")
end

-- The files of the previous run listed in m_old and not written by this one (seen): removed when each is still the
-- file that run recorded (its hash), a plain file inside the folder; the others are left in place and named.
local function remove_stale(c, m_old, known, seen)
  local removed, left = {}, {}
  for _, name in ipairs(known) do
    if not seen[name] and name ~= MANIFEST then
      local rec, r, why = m_old.known[name], nil, "no hash of it recorded"
      if rec.hash then r, why = fs.remove_inside(c.dir, name, rec.hash) end
      if r == "removed" then
        removed[#removed + 1] = name
      elseif not r then
        left[#left + 1] = ("%s (%s)"):format(name, plain(why))
      end
    end
  end
  local function some(list)
    local shown = {table.unpack(list, 1, math.min(#list, 8))}
    return printable(table.concat(shown, ", ")) .. (#list > #shown and ", ..." or "")
  end
  if #removed > 0 then
    say("removed %d file%s of the previous run into %s (listed in its manifest, not written by this one): %s", #removed,
        #removed > 1 and "s" or "", c.dir, some(removed))
  end
  if #left > 0 then
    say("left %d file%s of the previous run in %s (listed in its manifest, not written by this one, not removed): " ..
        "%s; remove %s yourself: the next run into the folder refuses files no manifest lists", #left,
        #left > 1 and "s" or "", c.dir, some(left), #left > 1 and "them" or "it")
  end
end

----------------------------------------------------------------------------------------------------------------
-- Computing a shard

-- The first line of an error (a Lua error may carry a traceback), with the folders of script paths left out
-- ("fleet_conicity.lua:80: ..."): a case's error reads the same on every machine, wherever the study was checked out.
local function first_line(e)
  local s = type(e) == "table" and (e.message or tostring(e)) or tostring(e)
  return (s:match("^[^\n]*"):gsub("[^%s:]*/([^/%s:]+%.lua):(%d+):", "%1:%2:"))
end

-- The block lines of one chunk: "@k", then "<t> <csv>" per row of table t, "! <csv>" per failed case.
local function chunk_lines(c, k, first, last, results, stats)
  local lines = {"@" .. k}
  for i = first, last do
    local res = results[i]
    local err = res == nil and "the study's compute returned no result for this case" or res.error
    for t, tab in ipairs(c.tables) do
      local rows = res and res[tab.key]
      if rows and type(rows[1]) ~= "table" then rows = {rows} end
      for _, row in ipairs(rows or {}) do
        local ok, line = pcall(out.csv_line, tab.columns, row, tab.file .. " case " .. i)
        if ok then lines[#lines + 1] = part_line(t, line) else err = err or first_line(line) end
      end
    end
    if err then
      stats.failed = stats.failed + 1
      local row = c.key and c.key(i) or {}
      row.case, row.error = i, first_line(err)
      lines[#lines + 1] = part_line("!", out.csv_line(c.failure_columns, row, "failures.csv case " .. i))
      if stats.failed <= 5 then say("case %d failed: %s", i, printable(first_line(err))) end
    end
  end
  return lines
end

-- compute(batch) for a batch of chunks; if it raises, chunk by chunk, and a chunk that raises fails all its cases.
local function compute_batch(c, batch)
  local ok, results = pcall(c.compute, batch)
  if ok and type(results) == "table" then return results end
  if #batch.chunks == 1 then
    local results1, err = {}, ok and "compute returned no table" or results
    for i = batch.first, batch.last do results1[i] = {error = err} end
    return results1
  end
  local all = {}
  for _, ch in ipairs(batch.chunks) do
    local part = compute_batch(c, {chunks = {ch}, first = ch.first, last = ch.last})
    for i = ch.first, ch.last do all[i] = part[i] end
  end
  return all
end

-- Removes the shard folders that `drop(folder)` selects, all of them locked first (none is being computed; if one
-- is, the run stops before removing any).
local function remove_shards(c, drop)
  local chosen = {}
  for _, s in ipairs(shard_folders(c.dir)) do
    if drop(s) then
      shard_lock(c, s.k, s.n)
      chosen[#chosen + 1] = s
    end
  end
  for _, s in ipairs(chosen) do fs.remove_tree_inside(c.dir, PARTS .. "/" .. s.name) end
end

-- The chunks done in a shard folder: its blocks checked, a damaged one and one overlapping another removed (their
-- chunks are computed again). Returns done[chunk] = true.
local function usable_blocks(c, rel)
  local folder = c.dir .. "/" .. rel
  local kept, extra = disjoint(blocks_of(folder))
  local done, damaged = {}, {}
  for _, b in ipairs(kept) do
    local why = block_damage(folder .. "/" .. b[3])
    if why then
      damaged[#damaged + 1] = ("%s: %s"):format(b[3], why)
      fs.remove_inside(c.dir, rel .. "/" .. b[3])
    else
      for k = b[1], b[2] do done[k] = true end
    end
  end
  for _, b in ipairs(extra) do fs.remove_inside(c.dir, rel .. "/" .. b[3]) end
  if #damaged > 0 then
    say("%d damaged block%s in %s, computed again: %s%s", #damaged, #damaged > 1 and "s" or "", folder,
        table.concat(damaged, "; ", 1, math.min(#damaged, 3)), #damaged > 3 and "; ..." or "")
  end
  if #extra > 0 then
    say("%d block%s in %s overlapped others (an earlier run's batches): removed", #extra, #extra > 1 and "s" or "",
        folder)
  end
  return done
end

local function compute_shard(c)
  local rel = PARTS .. "/" .. shard_name(c.shard, c.shards)
  local folder = c.dir .. "/" .. rel
  local ok, err = pcall(fs.mkdir_inside, c.dir, rel)
  if not ok then refuse(1, "%s", plain(err)) end
  local st = read_state(folder)
  local done_run = c.m_old and c.m_old.status == "complete" and c.m_old.hash or nil  -- parts of a finished run
  if st and st.hash ~= c.hash and not c.fresh then
    if st.hash ~= done_run then
      refuse(1, "%s holds the parts of an unfinished run with other inputs (%s): run with --fresh to discard them " ..
             "and start over, or choose another folder (out=...)", folder, differences(st.lines, c.lines))
    end
    say("the previous run into %s was complete and had other inputs (%s): its parts are replaced", c.dir,
        differences(st.lines, c.lines))
  end
  if c.fresh then
    remove_shards(c, function(s) return c.shards == 1 or s.name == shard_name(c.shard, c.shards) end)
  elseif done_run and done_run ~= c.hash and c.shards == 1 then  -- the one writer: the finished run's parts go
    remove_shards(c, function(s)
      local other = read_state(s.path)
      return other ~= nil and other.hash == done_run
    end)
  elseif st and st.hash ~= c.hash then
    fs.remove_tree_inside(c.dir, rel)
  end
  if c.before_compute then c.before_compute() end
  fs.mkdir_inside(c.dir, rel)
  remove_temporaries(c, rel)
  write_state(folder, c)
  local done = usable_blocks(c, rel)
  local stats = {cases = 0, failed = 0, resumed = 0}
  for k = c.lo, c.hi do
    if done[k] then
      local a, b = c.chunk(k)
      stats.resumed = stats.resumed + (b - a + 1)
    end
  end
  if c.shards > 1 or c.cmd.shard_from ~= "" then
    say("shard %d of %d (%s): chunks %d..%d of %d", c.shard, c.shards, c.cmd.shard_from ~= "" and c.cmd.shard_from or
        "one process", c.lo, c.hi, c.nchunks)
  end
  if stats.resumed > 0 then say("resuming: %d cases already computed in %s", stats.resumed, folder) end
  local t0, clock0, last_say = os.time(), os.clock(), os.time()
  local k = c.lo
  while k <= c.hi do
    if done[k] then
      k = k + 1
    else
      local batch = {chunks = {}}
      while k <= c.hi and not done[k] and #batch.chunks < c.batch do
        local a, b = c.chunk(k)
        batch.chunks[#batch.chunks + 1] = {index = k, first = a, last = b}
        k = k + 1
      end
      batch.first, batch.last = batch.chunks[1].first, batch.chunks[#batch.chunks].last
      local w0, c0 = os.time(), os.clock()
      local results = compute_batch(c, batch)
      local lines = {}
      for _, ch in ipairs(batch.chunks) do
        for _, l in ipairs(chunk_lines(c, ch.index, ch.first, ch.last, results, stats)) do lines[#lines + 1] = l end
        stats.cases = stats.cases + (ch.last - ch.first + 1)
      end
      lines[#lines + 1] = ("# time wall %d s, cpu %.3f s"):format(os.time() - w0, os.clock() - c0)
      results = nil
      fs.write_file(folder .. "/" .. block_name(batch.chunks[1].index, batch.chunks[#batch.chunks].index),
                    block_text(lines))
      if os.time() - last_say >= 10 then
        last_say = os.time()
        say("%d of %d cases of this shard, %d failed, %d s", stats.cases + stats.resumed, c.shard_cases, stats.failed,
            os.time() - t0)
      end
    end
  end
  stats.wall, stats.cpu = os.time() - t0, os.clock() - clock0
  return stats
end

----------------------------------------------------------------------------------------------------------------
-- Merging

-- The command that computes shard K of N of this run again (for messages).
local function shard_command(c, k, n)
  local words, has_out = {"wrc run", shell_word(c.cmd.script)}, false
  for _, name in ipairs(c.study.given) do
    words[#words + 1] = shell_word(name .. "=" .. canonical(c.study.options[name]))
    has_out = has_out or name == "out"
  end
  if not has_out then words[#words + 1] = shell_word("out=" .. c.dir) end
  words[#words + 1] = ("--shard %d/%d"):format(k, n)
  return table.concat(words, " ")
end

-- The complete sets of shard folders of this study: {n = N, shards = {[k] = {folder =, rel =, blocks =}}} with the
-- smallest N, each shard's blocks the chain that covers its chunks, or nil and why not.
local function find_parts(c)
  local sets, others = {}, {}
  for _, s in ipairs(shard_folders(c.dir)) do
    local st = read_state(s.path)
    if st and st.hash == c.hash and s.k >= 1 and s.k <= s.n then
      sets[s.n] = sets[s.n] or {}
      sets[s.n][s.k] = {folder = s.path, rel = PARTS .. "/" .. s.name, state = st}
    else
      others[#others + 1] = s.name
    end
  end
  if next(sets) == nil and #others == 0 then return nil, "there are no parts in " .. c.dir .. "/" .. PARTS end
  local why, best = {}, nil
  local ns = {}
  for n in pairs(sets) do ns[#ns + 1] = n end
  table.sort(ns)
  for _, n in ipairs(ns) do
    local complete = true
    for k = 1, n do
      local p = sets[n][k]
      local lo, hi = shard_range(k, n, c.nchunks)
      if not p then
        complete = false
        why[#why + 1] = ("shard %d of %d has not started"):format(k, n)
      else
        p.blocks = {}
        local next_chunk = lo
        for _, b in ipairs((disjoint(blocks_of(p.folder)))) do
          if b[1] == next_chunk and b[2] <= hi then
            p.blocks[#p.blocks + 1] = b
            next_chunk = b[2] + 1
          end
        end
        if next_chunk <= hi then
          complete = false
          why[#why + 1] = ("shard %d of %d: %d of %d chunks done"):format(k, n, next_chunk - lo, hi - lo + 1)
        end
      end
    end
    if complete and not best then best = {n = n, shards = sets[n]} end
  end
  if best then return best end
  if #others > 0 then why[#why + 1] = "parts of other studies or options: " .. table.concat(others, ", ") end
  return nil, table.concat(why, "; ")
end

-- The complete set of parts to merge, its shards locked (none is computed while it is merged) and every block
-- checked; or the run stops saying what is missing or damaged and how to compute it.
local function parts_to_merge(c)
  for _ = 1, 10 do
    local set, why = find_parts(c)
    if not set then
      refuse(1, "cannot merge into '%s': %s. Run the missing shards (a shard run again resumes), then merge again.",
             c.dir, why)
    end
    local held = true
    for k = 1, set.n do
      held = held and c.locks[shard_name(k, set.n)] ~= nil
      shard_lock(c, k, set.n)
    end
    if held then  -- found while its shards were locked: it stays as found
      local damaged, shards = {}, {}
      for k = 1, set.n do
        for _, b in ipairs(set.shards[k].blocks) do
          local bad = block_damage(set.shards[k].folder .. "/" .. b[3])
          if bad then
            damaged[#damaged + 1] = ("shard %d of %d, %s: %s"):format(k, set.n, b[3], bad)
            if shards[#shards] ~= k then shards[#shards + 1] = k end
          end
        end
      end
      if #damaged > 0 then
        local commands = {}
        for _, k in ipairs(shards) do commands[#commands + 1] = "  " .. shard_command(c, k, set.n) end
        refuse(1, "cannot merge into '%s': %d damaged block%s (%s%s). A shard's run checks its blocks and computes " ..
               "the damaged ones again:\n%s\nthen merge again.", c.dir, #damaged, #damaged > 1 and "s" or "",
               table.concat(damaged, "; ", 1, math.min(#damaged, 4)), #damaged > 4 and "; ..." or "",
               table.concat(commands, "\n"))
      end
      return set
    end
  end
  refuse(1, "cannot merge into '%s': its parts keep changing (shards are being computed); merge once they are done",
         c.dir)
end

-- Streams the blocks of every shard, in chunk order, into the tables and failures.csv.
local function merge_tables(c, set)
  local writers = {}
  for t, tab in ipairs(c.tables) do writers[t] = out.csv_writer(c.dir .. "/" .. tab.file, tab.columns) end
  local failures, failed = nil, 0
  local expect = 1
  local function bad(where, fmt, ...)
    for _, w in ipairs(writers) do w:discard() end
    if failures then failures:discard() end
    refuse(1, "cannot merge into '%s': %s: %s; compute that shard again with --fresh", c.dir, where,
           string.format(fmt, ...))
  end
  c.compute_cpu = 0
  for k = 1, set.n do
    local p = set.shards[k]
    for _, b in ipairs(p.blocks) do
      local where = p.folder .. "/" .. b[3]
      for line in io.lines(where) do
        if line:byte(1) == 126 then line = unescape(line:sub(2)) end  -- "~": a row that holds a line break
        local tag = line:byte(1)
        if tag == 64 then  -- "@k"
          local ch = tonumber(line:sub(2))
          if ch ~= expect then bad(where, "it holds chunk %s where chunk %d was expected", line:sub(2, 20), expect) end
          expect = expect + 1
        elseif tag == 33 then  -- "! failure"
          failures = failures or out.open(c.dir .. "/failures.csv")
          if failed == 0 then failures:write(table.concat(c.failure_columns, ","), "\n") end
          failures:write(line:sub(3), "\n")
          failed = failed + 1
        elseif tag == 35 then  -- "# time wall <s> s, cpu <s> s" of a block, or its end line
          local cpu = line:match("^# time wall %d+ s, cpu ([%d.]+) s")
          c.compute_cpu = c.compute_cpu + (tonumber(cpu) or 0)
        else
          local t, rest = line:match("^(%d+) (.*)$")
          local w = writers[tonumber(t or "")]
          if not w then bad(where, "a line of no table: %s", printable(line:sub(1, 40))) end
          w:append(rest)  -- the row's text as computed, byte for byte
        end
      end
    end
  end
  if expect ~= c.nchunks + 1 then
    bad(c.dir .. "/" .. PARTS, "the parts hold chunks 1..%d of %d", expect - 1, c.nchunks)
  end
  for _, w in ipairs(writers) do w:close() end
  if failures then failures:close() end
  return failed
end

local function merge(c, m_old)
  merge_lock(c)
  local set = parts_to_merge(c)
  remove_temporaries(c, "")  -- a killed merge's (the merge is the one writer of the folder; shards write in parts/)
  local known = {}
  for name in pairs(m_old and m_old.known or {}) do known[#known + 1] = name end
  table.sort(known)
  -- Until the end, the manifest says "incomplete" and lists every file that is or may be in the folder (the
  -- previous run's and each new one as it is written), so that a run killed now is marked and its files known.
  local written, seen, records = {}, {}, {}
  local function mark_incomplete(why)
    local previous = {}
    for _, n in ipairs(known) do previous[#previous + 1] = {name = n, rec = records[n] or m_old.known[n]} end
    for _, n in ipairs(written) do
      if not (m_old and m_old.known[n]) then previous[#previous + 1] = {name = n, rec = records[n]} end
    end
    write_manifest(c, "incomplete (" .. why .. ")", {}, previous)
  end
  mark_incomplete("merging; a run killed now leaves this mark")
  local prefix = c.dir .. "/"
  out.on_write = function(path)
    local name = path:sub(1, #prefix) == prefix and path:sub(#prefix + 1) or nil
    if not name then return end
    local why = fs.name_problem(name)
    if why then error(("%s: cannot list '%s' in %s: %s"):format(c.dir, printable(name), MANIFEST, why), 0) end
    local hash, size = fs.digest(path)
    records[name] = {size = size, hash = hash}
    if not seen[name] then
      seen[name] = true
      written[#written + 1] = name
    end
    mark_incomplete("merging; a run killed now leaves this mark")
  end
  local ok, err = pcall(function()
    local failed = merge_tables(c, set)
    local ctx = {dir = c.dir, options = c.study.options, cases = c.cases, failed = failed, shards = set.n}
    local function inside(name)  -- a file of the folder, named on one line of the manifest
      local why = fs.name_problem(tostring(name))
      if why then error(("%s: cannot name a file '%s' in it: %s"):format(c.dir, printable(name), why), 3) end
      return c.dir .. "/" .. name
    end
    function ctx.path(name) return inside(name) end
    function ctx.read(name) return out.read_csv(inside(name)) end
    function ctx.write(name, text) out.text(inside(name), text) end
    if c.finish then c.finish(ctx) end
    c.failed = failed
  end)
  out.on_write = nil
  if not ok then
    mark_incomplete("failed: " .. first_line(err))
    error(err, 0)
  end
  remove_stale(c, m_old, known, seen)
  table.sort(written)
  write_manifest(c, "complete", written, {},
                 {"shards " .. set.n, "failed " .. c.failed, ("compute_cpu %.2f s"):format(c.compute_cpu)})
end

----------------------------------------------------------------------------------------------------------------
-- Study:run

-- r = {
--   cases = n,                                    -- the study's cases, 1..n
--   chunks = {{first =, last =}, ...} | chunk_size = m,  -- each solved on its own (continuation inside a chunk)
--   tables = {{key = "sweep", file = "sweep.csv", columns = {...}}, ...},
--   compute = function(batch) -> results,         -- batch = {chunks = {{index =, first =, last =}, ...}, first =, last =};
--                                                 -- results[case] = {<key> = row or {rows}, error = "why" (failed)}
--   key = function(case) -> {column = value},     -- the columns that name a case in failures.csv (key_columns)
--   key_columns = {...},
--   inputs = {name = value},                      -- profiles, numbers, strings, tables: part of the study's hash
--   batch = 8,                                    -- chunks per compute call (one checkpoint block per call)
--   finish = function(ctx),                       -- after the merge: figures and summary from the tables (ctx.read)
-- }
function Study:run(r)
  local cmd = command()
  cmd.study = true  -- the host's flags applied (a script that never gets here ignores them; the host says so)
  assert(math.type(r.cases) == "integer" and r.cases >= 1, "study:run: cases must be a positive integer")
  assert(type(r.compute) == "function", "study:run: compute(batch) is required")
  local c = {study = self, cases = r.cases, tables = r.tables or {}, compute = r.compute, finish = r.finish, key = r.key,
             batch = math.max(1, r.batch or 1), cmd = cmd, shard = cmd.shard or 1, shards = cmd.shards or 1,
             fresh = cmd.fresh, locks = {}}
  c.failure_columns = {"case"}
  for _, k in ipairs(r.key_columns or {}) do c.failure_columns[#c.failure_columns + 1] = k end
  c.failure_columns[#c.failure_columns + 1] = "error"
  local layout
  c.nchunks, c.chunk, layout = chunk_layout(r)
  c.hash, c.lines = identity(self, r, layout)
  c.dir = self.dir
  check_folder(c.dir)  -- before anything is created in a folder that is refused
  -- One run at a time writes the folder (a merge, or the study in one process) and one computes each shard: locked
  -- before the folder is read for good.
  if cmd.merge or c.shards == 1 then merge_lock(c) end
  if not cmd.merge then shard_lock(c, c.shard, c.shards) end
  local m_old = check_folder(c.dir, true)
  c.m_old = m_old
  if not cmd.merge then
    c.lo, c.hi = shard_range(c.shard, c.shards, c.nchunks)
    local a = c.lo <= c.hi and c.chunk(c.lo) or 1
    local b = c.lo <= c.hi and select(2, c.chunk(c.hi)) or 0
    c.shard_cases = b - a + 1
    if c.shards == 1 then  -- the one writer of this folder: mark it (shards leave the manifest to the merge)
      c.before_compute = function()
        local previous = {}
        for name, rec in pairs(m_old and m_old.known or {}) do previous[#previous + 1] = {name = name, rec = rec} end
        table.sort(previous, function(x, y) return x.name < y.name end)
        write_manifest(c, "incomplete (computing)", {}, previous)
      end
    end
    local stats = compute_shard(c)
    local msg = ("%d cases computed in %d s (%.1f s cpu), %d failed"):format(stats.cases, stats.wall, stats.cpu, stats.failed)
    if stats.resumed > 0 then msg = msg .. (", %d resumed from earlier parts"):format(stats.resumed) end
    if c.shards > 1 then
      say("shard %d of %d done: %s. Once every shard is done: wrc merge %s out=%s (or this command with --merge)",
          c.shard, c.shards, msg, shell_word(cmd.script), shell_word(c.dir))
      if stats.failed > 0 then cmd.status = 3 end
      return
    end
    say("%s", msg)
  end
  merge(c, m_old)
  if c.failed > 0 then
    say("%d of %d cases failed (listed in %s/failures.csv)", c.failed, c.cases, c.dir)
    cmd.status = 3
  end
  return c.failed
end

----------------------------------------------------------------------------------------------------------------
-- wrc merge STUDY.lua: the options from the parts

-- The runs whose parts DIR holds: runs[hash] = state, and their hashes in the order of the shard folders.
local function runs_in(dir)
  local runs, order = {}, {}
  for _, s in ipairs(shard_folders(dir)) do
    local st = read_state(s.path)
    if st and st.hash and not runs[st.hash] then runs[st.hash], order[#order + 1] = st, st.hash end
  end
  return runs, order
end

-- The hash of the script a run's parts came from (an identity line), "?" if none.
local function script_hash(st)
  for _, l in ipairs(st.lines) do
    local h = l:match("^script (%x+)$")
    if h then return h end
  end
  return "?"
end

local function describe(st)
  local options = #st.args > 0 and (", options " .. printable(table.concat(st.args, " "))) or ""
  return ("%s (script hash %s%s)"):format(printable(st.script or "?"), script_hash(st), options)
end

-- `wrc merge STUDY.lua`: the options the shards ran with, from the parts in the output folder, for those not given
-- on the command line -- when the parts came from this very script (its content's hash); else the run stops, saying
-- where they came from. The script named by the parts is never run.
adopt_recorded_options = function(s, cmd)
  local dir = tostring(arg.out or s.spec.out or "results"):gsub("(.)/+$", "%1")
  local runs, order = runs_in(dir)
  if #order == 0 then
    refuse(1, "'%s' holds no parts to merge (no %s/%s/shard-K-of-N/state.txt)", printable(dir), printable(dir), PARTS)
  end
  local mine, match, others = fs.hash_file(cmd.script), {}, {}
  for _, h in ipairs(order) do
    if script_hash(runs[h]) == mine then match[#match + 1] = runs[h] else others[#others + 1] = describe(runs[h]) end
  end
  if #match == 0 then
    refuse(1, "the parts in '%s' do not come from %s (script hash %s) but from %s: wrc merges parts only with the " ..
           "study they came from", printable(dir), printable(cmd.script), mine, table.concat(others, "; "))
  end
  if #match > 1 then  -- runs with other options: those that agree with the options given
    local agree = {}
    for _, st in ipairs(match) do
      local ok = true
      for _, a in ipairs(st.args) do
        local k, v = a:match("^([^=]+)=(.*)$")
        if k and arg[k] ~= nil and tostring(arg[k]) ~= v then ok = false end
      end
      if ok then agree[#agree + 1] = st end
    end
    if #agree >= 1 then match = agree end
  end
  if #match > 1 then
    local list = {}
    for _, st in ipairs(match) do list[#list + 1] = describe(st) end
    refuse(1, "'%s' holds the parts of %d runs of this study with other options (%s): give the options of the one " ..
           "to merge (wrc merge %s out=DIR key=value ...), or remove the parts you do not want", printable(dir), #match,
           table.concat(list, "; "), shell_word(cmd.script))
  end
  local adopted = {}
  for _, a in ipairs(match[1].args) do
    local k, v = a:match("^([^=]+)=(.*)$")
    if k and k ~= "out" and arg[k] == nil then arg[k], adopted[#adopted + 1] = v, a end
  end
  if #adopted > 0 then
    say("merging '%s' with the options its shards ran with: %s", printable(dir), printable(table.concat(adopted, " ")))
  end
end

-- `wrc merge DIR` (the form before wrc named the study): runs nothing, says where the parts came from and how to
-- merge them.
function M.refuse_folder_merge(folder)
  folder = folder:gsub("(.)/+$", "%1")
  local runs, order = runs_in(folder)
  local lines = {}
  for _, h in ipairs(order) do
    local st = runs[h]
    lines[#lines + 1] = ("  wrc merge %s %s    # parts of %s"):format(shell_word(st.script or "?"),
                                                                     shell_word("out=" .. folder), describe(st))
  end
  refuse(2, "wrc merge takes the study, not the folder: wrc merge STUDY.lua %s. wrc runs no script that a folder " ..
         "names (a folder from someone else could name any). %s", shell_word("out=" .. folder),
         #lines == 0 and ("'" .. printable(folder) .. "' holds no parts of a study either.") or
         ("Its parts come from:\n" .. table.concat(lines, "\n") ..
          "\nIf a script is yours, its command above merges its parts (it checks the script's content against the " ..
          "hash)."))
end

return M
