-- wrc.study.common: what the study runner's modules share. The run's command (wrc.command, which the host fills
-- from the command line); the messages of a run (say: a line on stderr; refuse: that line, then the run stops with
-- an exit status and no traceback, since the input is wrong, not the program); and the text forms of values shown
-- on one line, in a command to copy, or written to a file (canonical numbers, printable, shell words, an error's
-- first line). Nothing here touches a folder.
local M = {}

-- Ends the run with an exit status; the host prints nothing more (a study's --help, a refused input).
function M.exit(code, message) error({exit = code, message = message}, 0) end

-- One write per line, so that lines of shards run at once (GNU parallel's --line-buffer) never mix.
function M.say(fmt, ...) io.stderr:write("wrc: " .. string.format(fmt, ...) .. "\n") end

-- Stops the run with a message (no traceback: the input is wrong, not the program).
function M.refuse(code, fmt, ...)
  local text = string.format(fmt, ...)
  M.say("%s", text)
  M.exit(code, text)
end

-- The host's flags (wrc.command): shard, shards, shard_from, script, merge, fresh, help, from_parts; a script run
-- outside the host (no wrc.command) is one whole run.
function M.command() return wrc.command or {shard = 1, shards = 1, shard_from = "", script = arg and arg[0] or "?"} end

-- Text from a folder or a command line shown on one line: control characters escaped.
function M.printable(s)
  return (tostring(s):gsub("%c", function(ch) return ch == "\n" and "\\n" or ("\\%03d"):format(ch:byte()) end))
end

-- A word for a command shown to the user: as it is when the shell leaves it alone, else quoted.
function M.shell_word(s)
  s = tostring(s)
  if s:match("^[%w_%./=,:+@%%][%w_%./=,:+@%%%-]*$") then return s end
  return "'" .. M.printable(s):gsub("'", "'\\''") .. "'"
end

-- An engine error's message without the "file:line: " of the Lua line that made the call.
function M.plain(err) return (tostring(err):gsub("^[^\n]-:%d+: ", "", 1)) end

-- The first line of an error (a Lua error may carry a traceback), with the folders of script paths left out
-- ("fleet_conicity.lua:80: ..."): a case's error reads the same on every machine, wherever the study was checked out.
function M.first_line(e)
  local s = type(e) == "table" and (e.message or tostring(e)) or tostring(e)
  return (s:match("^[^\n]*"):gsub("[^%s:]*/([^/%s:]+%.lua):(%d+):", "%1:%2:"))
end

-- Numbers as the shortest text that reads back to the same double (other values as tostring).
function M.canonical(v)
  if math.type(v) == "integer" then return tostring(v) end
  if type(v) ~= "number" then return tostring(v) end
  for digits = 15, 16 do
    local s = string.format("%." .. digits .. "g", v)
    if tonumber(s) == v then return s end
  end
  return string.format("%.17g", v)
end

-- The lines of a text file, or nil when it cannot be read.
function M.read_lines(path)
  local f = io.open(path, "r")
  if not f then return nil end
  local lines = {}
  for l in f:lines() do lines[#lines + 1] = l end
  f:close()
  return lines
end

return M
