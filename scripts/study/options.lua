-- wrc.study.options: a study's declared options. Owns their declaration ({name, type, default, help, min =, max =,
-- choices =, hash = false}, or the same with keys; `out`, the output folder, is always declared first), reading the
-- key=value pairs of the command line (the global `arg`) against it, and the --help text.
--   declare(spec) -> list, byname        a bad declaration is an error at the line that called wrc.study.new
--   read(list, byname) -> values, given  values of every declared option (reading an undeclared one is an error),
--                                        given: the names set on the command line, sorted; a bad key or value
--                                        stops the run with exit status 2, naming it
--   usage(spec, list) -> text            the --help text: usage lines, the study's help, options and flags
local common = require "wrc.study.common"
local M = {}

local TYPES = {number = "a number", integer = "a whole number", boolean = "true or false", string = "a string"}
local canonical = common.canonical

local function finite(v) return v == v and v ~= math.huge and v ~= -math.huge end

local function convert_boolean(raw)
  local s = tostring(raw)
  if s == "true" or s == "1" or s == "yes" or s == "on" then return true end
  if s == "false" or s == "0" or s == "no" or s == "off" then return false end
  return nil, "expected true or false"
end

local function convert_number(d, raw)
  local v = tonumber(raw)
  if v == nil or not finite(v) then return nil, "expected " .. TYPES[d.type] end
  if d.type == "integer" then
    v = math.tointeger(v)
    if v == nil then return nil, "expected a whole number" end
  end
  return v
end

-- The value of option d from its text (or a default), or nil and why not.
local function convert(d, raw)
  local v, why
  if d.type == "string" then
    v = tostring(raw)
    -- state.txt and the manifest list options one per line
    if v:find("%c") then return nil, "a control character (a line break?) in the value is refused" end
  elseif d.type == "boolean" then
    v, why = convert_boolean(raw)
  else
    v, why = convert_number(d, raw)
  end
  if v == nil then return nil, why end
  if d.min and v < d.min then return nil, "must be >= " .. canonical(d.min) end
  if d.max and v > d.max then return nil, "must be <= " .. canonical(d.max) end
  if d.choices then
    local ok = false
    for _, c in ipairs(d.choices) do ok = ok or c == v end
    if not ok then return nil, "expected one of: " .. table.concat(d.choices, ", ") end
  end
  return v
end

-- One declared option from {name, type, default, help, ...}; errors name `where` at the study's line (level 5:
-- here, add, declare, wrc.study.new, the study).
local function declared(o, where, byname)
  local d = {name = o.name or o[1], type = o.type or o[2], help = o.help or o[4], min = o.min, max = o.max,
             choices = o.choices, hash = o.hash}
  if o.default ~= nil then d.default = o.default else d.default = o[3] end
  if type(d.name) ~= "string" or not d.name:match("^[%a_][%w_]*$") then
    error(where .. ": an option needs a name (letters, digits, _)", 5)
  end
  if not TYPES[d.type] then error(where .. ": option " .. d.name .. ": type must be number, integer, boolean or string", 5) end
  if type(d.help) ~= "string" then error(where .. ": option " .. d.name .. ": one line of help is required", 5) end
  if byname[d.name] then error(where .. ": option " .. d.name .. " is declared twice", 5) end
  if d.default ~= nil then
    local v, why = convert(d, d.default)
    if v == nil then error(where .. ": option " .. d.name .. ": default " .. tostring(d.default) .. ": " .. why, 5) end
    d.default = v
  end
  return d
end

-- The declared options of spec = {out = "default folder", options = {...}}, in order, and by name.
function M.declare(spec)
  local list, byname = {}, {}
  local function add(o, where)
    local d = declared(o, where, byname)
    list[#list + 1], byname[d.name] = d, d
  end
  add({"out", "string", spec.out or "results", "output folder (created if missing)", hash = false}, "wrc.study.new")
  for k, o in ipairs(spec.options or {}) do add(o, "wrc.study.new: options[" .. k .. "]") end
  return list, byname
end

-- One line of --help: "name=default  help (type; range; ...)", the first column `width` wide.
local function usage_line(d, shown, width)
  local extra = {d.type}
  if d.min then extra[#extra + 1] = ">= " .. canonical(d.min) end
  if d.max then extra[#extra + 1] = "<= " .. canonical(d.max) end
  if d.choices then extra[#extra + 1] = table.concat(d.choices, "|") end
  if d.hash == false then extra[#extra + 1] = "does not change the results" end
  return ("  %-" .. width .. "s  %s (%s)"):format(shown, d.help, table.concat(extra, "; "))
end

function M.usage(spec, list)
  local script = common.command().script
  local lines = {("usage: wrc run %s [key=value ...] [--shard K/N] [--merge] [--fresh]\n" ..
                  "       wrc merge %s [out=DIR] [key=value ...]"):format(script, script)}
  if spec.help then lines[#lines + 1] = "\n" .. spec.help:gsub("%s+$", "") end
  lines[#lines + 1] = "\noptions (key=value):"
  local width, shown = 0, {}
  for _, d in ipairs(list) do
    shown[d] = d.name .. "=" .. (d.default == nil and "" or canonical(d.default))
    width = math.max(width, #shown[d])
  end
  for _, d in ipairs(list) do lines[#lines + 1] = usage_line(d, shown[d], width) end
  lines[#lines + 1] = [[

flags:
  --shard K/N  compute part K of N (in a SLURM array job: from SLURM_ARRAY_TASK_ID; --shard wins)
  --merge      assemble the N parts into the outputs, then figures and summary (wrc merge: with the
               options the shards ran with, read from OUT/parts)
  --fresh      discard the parts of an earlier run and start over (a run resumes otherwise)
exit status: 0 done, 1 error, 2 bad options, 3 done with failed cases (OUT/failures.csv)]]
  return table.concat(lines, "\n") .. "\n"
end

-- Stops the run: `k` is no declared option (the closest declared one named).
local function refuse_unknown(script, k, list)
  local names = {}
  for _, e in ipairs(list) do names[#names + 1] = e.name end
  local best = wrc.closest_name(k, names)
  common.refuse(2, "%s: unknown option '%s'%s (options: %s; --help describes them)", script, common.printable(k),
                best and (" (did you mean '" .. best .. "'?)") or "", table.concat(names, ", "))
end

function M.read(list, byname)
  local script = common.command().script
  local values, given = {}, {}
  for k, v in pairs(arg or {}) do
    if math.type(k) == "integer" and k >= 1 then
      common.refuse(2, "%s: unexpected argument '%s' (options are key=value; --help lists them)", script,
                    common.printable(v))
    elseif type(k) == "string" then
      local d = byname[k]
      if not d then refuse_unknown(script, k, list) end
      local x, why = convert(d, v)
      if x == nil then common.refuse(2, "%s: option %s=%s: %s", script, k, common.printable(v), why) end
      values[k], given[#given + 1] = x, k
    end
  end
  for _, d in ipairs(list) do
    if values[d.name] == nil then values[d.name] = d.default end
  end
  table.sort(given)
  return setmetatable(values, {__index = function(_, k)
    if byname[k] then return nil end
    error("study option '" .. tostring(k) .. "' is not declared (wrc.study.new{options = ...})", 2)
  end}), given
end

return M
