-- wrc.study.origin: where the parts in an output folder came from, for `wrc merge`. The parts name a script, its
-- content's hash and the options given; they are data from whoever made the folder, so the script they name is
-- never run: `wrc merge STUDY.lua` runs the study the user names, with the options its parts ran with when they came
-- from that very script, and `wrc merge DIR` runs nothing.
--   adopt_options(dir, script)   fills the global `arg` with the options recorded in DIR's parts that the command
--                                line did not give; stops the run (exit 1) when the parts came from another script
--                                or from several runs that the options given do not tell apart
--   refuse_folder_merge(folder)  `wrc merge DIR`: stops (exit 2) naming the scripts of the parts and their commands
local common = require "wrc.study.common"
local identity = require "wrc.study.identity"
local parts = require "wrc.study.parts"
local fs = wrc.fs
local M = {}

local refuse, printable, shell_word = common.refuse, common.printable, common.shell_word

-- A run's parts in one line: script, its hash, the options given.
local function describe(st)
  local options = #st.args > 0 and (", options " .. printable(table.concat(st.args, " "))) or ""
  return ("%s (script hash %s%s)"):format(printable(st.script or "?"), identity.script_hash(st.lines), options)
end

-- Among runs of this script, those whose recorded options agree with the options given (all when none does).
local function agreeing(match)
  local agree = {}
  for _, st in ipairs(match) do
    local ok = true
    for _, a in ipairs(st.args) do
      local k, v = a:match("^([^=]+)=(.*)$")
      if k and arg[k] ~= nil and tostring(arg[k]) ~= v then ok = false end
    end
    if ok then agree[#agree + 1] = st end
  end
  return #agree >= 1 and agree or match
end

-- Of several runs, those computed by this build (their identity lines name it), if any: a shard of another build
-- is then named by the merge.
local function this_build(runs)
  local mine = {}
  for _, st in ipairs(runs) do
    for _, l in ipairs(st.lines) do
      if l == "build " .. wrc.build_id then mine[#mine + 1] = st end
    end
  end
  return #mine >= 1 and mine or runs
end

-- The one run of `script` whose parts DIR holds, or the run stops saying why there is none.
local function the_run(dir, script)
  local runs, order = parts.runs_in(dir)
  if #order == 0 then
    refuse(1, "'%s' holds no parts to merge (no %s/%s/shard-K-of-N/state.txt)", printable(dir), printable(dir),
           parts.FOLDER)
  end
  local mine, match, others = fs.hash_file(script), {}, {}
  for _, h in ipairs(order) do
    if identity.script_hash(runs[h].lines) == mine then match[#match + 1] = runs[h] else others[#others + 1] = describe(runs[h]) end
  end
  if #match == 0 then
    refuse(1, "the parts in '%s' do not come from %s (script hash %s) but from %s: wrc merges parts only with the " ..
           "study they came from", printable(dir), printable(script), mine, table.concat(others, "; "))
  end
  if #match > 1 then match = agreeing(match) end
  if #match > 1 then match = this_build(match) end
  if #match > 1 then
    local list = {}
    for _, st in ipairs(match) do list[#list + 1] = describe(st) end
    refuse(1, "'%s' holds the parts of %d runs of this study with other options (%s): give the options of the one " ..
           "to merge (wrc merge %s out=DIR key=value ...), or remove the parts you do not want", printable(dir), #match,
           table.concat(list, "; "), shell_word(script))
  end
  return match[1]
end

function M.adopt_options(dir, script)
  local adopted = {}
  for _, a in ipairs(the_run(dir, script).args) do
    local k, v = a:match("^([^=]+)=(.*)$")
    if k and k ~= "out" and arg[k] == nil then arg[k], adopted[#adopted + 1] = v, a end
  end
  if #adopted > 0 then
    common.say("merging '%s' with the options its shards ran with: %s", printable(dir),
               printable(table.concat(adopted, " ")))
  end
end

function M.refuse_folder_merge(folder)
  folder = folder:gsub("(.)/+$", "%1")
  local runs, order = parts.runs_in(folder)
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
