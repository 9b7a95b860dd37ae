-- wrc.study.identity: what makes two runs the same study. Owns the identity lines (engine version and build, the
-- script's hash, the options that change results, the inputs' fingerprints, cases, chunk layout, tables) and their
-- hash, which the parts and the manifest record, and the reading of them back.
--   of(script, declared, values, r, layout) -> hash, lines   script: absolute path; declared, values: the options
--                                                            (wrc.study.options); r: Study:run's table
--   differences(old_lines, new_lines) -> text                what changed, options first ("option ymax_mm: 8 -> 4")
--   script_hash(lines) -> hex or "?"                         the script's hash recorded among the lines
--   this_build() -> text, build_of(state) -> text            the build running, the one that wrote a shard's state
--   other_build(old_lines, new_lines) -> bool                whether the two differ only in the build
local common = require "wrc.study.common"
local fs = wrc.fs
local M = {}

local canonical = common.canonical

-- A short text that changes when the value does: numbers, booleans, strings (long ones by their hash), profiles
-- (by their points) and tables of them.
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

function M.of(script, declared, values, r, layout)
  local lines = {"engine " .. wrc.version, "build " .. wrc.build_id, "script " .. fs.hash_file(script)}
  for _, d in ipairs(declared) do
    if d.hash ~= false then lines[#lines + 1] = "option " .. d.name .. "=" .. canonical(values[d.name]) end
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

-- Identity lines by their key ("option ymax_mm", "script", ...).
local function by_key(lines)
  local m = {}
  for _, l in ipairs(lines) do
    local k, v = l:match("^(%S+ [^=]+)=(.*)$")
    if not k then k, v = l:match("^(%S+) (.*)$") end
    if k then m[k] = v end
  end
  return m
end

-- Options first, then inputs, script, engine, build, tables, the rest.
local function rank(d)
  for r, p in ipairs{"option", "input", "script", "engine", "build", "table"} do
    if d:sub(1, #p) == p then return r end
  end
  return 9
end

function M.differences(old, new)
  local a, b, diffs = by_key(old), by_key(new), {}
  for k, v in pairs(b) do
    if a[k] ~= v then diffs[#diffs + 1] = ("%s: %s -> %s"):format(k, a[k] or "(none)", v) end
  end
  for k, v in pairs(a) do
    if b[k] == nil then diffs[#diffs + 1] = ("%s: %s -> (none)"):format(k, v) end
  end
  table.sort(diffs, function(x, y) return rank(x) < rank(y) or (rank(x) == rank(y) and x < y) end)
  return #diffs > 0 and table.concat(diffs, "; ") or "their inputs"
end

-- For people: "wrc 0.1.0, build 0123456789ab (git 76986d3, modified)".
function M.this_build() return ("wrc %s, build %s (%s)"):format(wrc.version, wrc.build_id, wrc.build_origin) end

-- The build that wrote a shard's state.txt: its own words (its "built" line), else its identity lines' (an earlier
-- wrc recorded no build).
function M.build_of(st)
  if st.built then return st.built end
  local m = by_key(st.lines)
  return ("wrc %s, build not recorded (an earlier wrc)"):format(m.engine or "?")
end

function M.other_build(old, new)
  local a, b, differs = by_key(old), by_key(new), false
  for _, pair in ipairs{{a, b}, {b, a}} do
    for k, v in pairs(pair[1]) do
      if pair[2][k] ~= v then
        if k ~= "engine" and k ~= "build" then return false end
        differs = true
      end
    end
  end
  return differs
end

function M.script_hash(lines)
  for _, l in ipairs(lines) do
    local h = l:match("^script (%x+)$")
    if h then return h end
  end
  return "?"
end

return M
