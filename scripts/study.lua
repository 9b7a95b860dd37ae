-- wrc.study: the study runner. A study declares its options and its cases, and runs in one process or in shards on
-- many machines (docs/guide/studies.md). Its cases are cut into
-- chunks (fixed by the study, never by the number of shards or threads); a shard computes a contiguous range of
-- chunks and streams their rows into checkpoint blocks in OUT/parts; a run again resumes after the last whole block;
-- the merge concatenates the blocks into exactly the tables one process writes, then the study makes its figures and
-- summary from those tables, and OUT/manifest.txt lists what the run produced. What an output folder holds is data
-- from whoever made it: it names no script that is run, and no file outside it (or through a link in it) is removed.
--
--   local study = require "wrc.study"
--   local s = study.new{name =, help =, out = "results", options = {{"step_mm", "number", 0.1, "step (mm)"}, ...}}
--   local opt = s.options                      -- checked: an unknown key names the closest declared one
--   s:run{cases =, chunks =, tables =, compute =, finish =, inputs =, key =, key_columns =, batch =}
--
-- This module is the runner's entry and its orchestration: new, Study:run, and refuse_folder_merge (the host's
-- `wrc merge DIR`). Each concern is a module of its own in scripts/study/:
--   options   declared options, key=value, --help        identity  what makes two runs the same study (hash)
--   layout    chunks and shards (arithmetic)               parts     OUT/parts: blocks, state.txt, shard folders
--   locks     one run per shard, one per folder            manifest  OUT/manifest.txt; unknown and stale files
--   shard     computing a shard, resuming                  merge     the tables and finish(ctx) from the parts
--   origin    where a folder's parts came from (merge)     common    messages, the command, text forms
-- The sweep tables and the paper's figures (wrc.sweep) are one user of the runner.
local common = require "wrc.study.common"
local identity = require "wrc.study.identity"
local layout = require "wrc.study.layout"
local locks = require "wrc.study.locks"
local manifest = require "wrc.study.manifest"
local merge = require "wrc.study.merge"
local options = require "wrc.study.options"
local origin = require "wrc.study.origin"
local parts = require "wrc.study.parts"
local shard = require "wrc.study.shard"
local fs = wrc.fs
local M = {}

local say = common.say

local Study = {}
Study.__index = Study

-- An output folder's name without trailing slashes.
local function folder_name(out) return (tostring(out):gsub("(.)/+$", "%1")) end

-- Declares a study: spec = {name =, help = "what it computes", out = "default folder", options = {...}} (the
-- options: wrc.study.options). Reads the options from the command line (with `wrc merge STUDY.lua`, those its
-- parts ran with for the others); with --help, prints them and ends the run. The output folder is made and checked
-- writable before anything is computed (a read-only folder found after the sweep loses it).
-- The study: s.options (the values), s.given (names given), s.dir, s.script (absolute), s.spec, s.name.
function M.new(spec)
  local cmd = common.command()
  local s = setmetatable({spec = spec, name = spec.name}, Study)
  s.declared, s.byname = options.declare(spec)
  if cmd.help then
    io.write(options.usage(spec, s.declared))
    common.exit(0)
  end
  if tostring(cmd.script):find("%c") then
    common.refuse(2, "the study's path %s holds a control character (a line break?): rename it",
                  common.printable(cmd.script))
  end
  if cmd.from_parts then origin.adopt_options(folder_name(arg.out or spec.out or "results"), cmd.script) end
  s.options, s.given = options.read(s.declared, s.byname)
  s.script = fs.absolute(cmd.script)
  s.dir = folder_name(s.options.out)
  local ok, err = pcall(function()
    fs.mkdir(s.dir)
    fs.check_writable(s.dir)
  end)
  if not ok then common.refuse(1, "%s", common.plain(err)) end
  return s
end

-- The options given as "key=value" (sorted by key): all of them, and those that are not `out`.
local function given_args(s)
  local all, args = {}, {}
  for _, k in ipairs(s.given) do
    local a = k .. "=" .. common.canonical(s.options[k])
    all[#all + 1] = a
    if k ~= "out" then args[#args + 1] = a end
  end
  return all, args
end

-- The run that Study:run hands to the modules (shard, merge, manifest); they read it, and only Study:run and
-- compute_shard below set its fields:
--   dir, script (absolute), command_script (as given), options, args ({"key=value"} given, out aside), command_args
--   (all given), hash, lines (identity), cases, nchunks, chunk(k) -> first, last, tables, compute, key,
--   failure_columns ({"case", key columns..., "error"}), finish, batch, shard, shards, shard_from, fresh, locks;
--   m_old (the manifest found); lo, hi, shard_cases (the shard's chunks and cases, when it computes).
local function new_run(s, r, cmd, nchunks, chunk)
  local run = {dir = s.dir, script = s.script, command_script = cmd.script, options = s.options, cases = r.cases,
               nchunks = nchunks, chunk = chunk, tables = r.tables or {}, compute = r.compute, key = r.key,
               finish = r.finish, batch = math.max(1, r.batch or 1), shard = cmd.shard or 1, shards = cmd.shards or 1,
               shard_from = cmd.shard_from, fresh = cmd.fresh, locks = locks.new(s.dir)}
  run.command_args, run.args = given_args(s)
  run.failure_columns = {"case"}
  for _, k in ipairs(r.key_columns or {}) do run.failure_columns[#run.failure_columns + 1] = k end
  run.failure_columns[#run.failure_columns + 1] = "error"
  return run
end

-- Computes this run's shard. False when it is one of several: they are merged later, by a run of their own.
local function compute_shard(run, cmd)
  run.lo, run.hi = layout.shard_range(run.shard, run.shards, run.nchunks)
  local a = run.lo <= run.hi and run.chunk(run.lo) or 1
  local b = run.lo <= run.hi and select(2, run.chunk(run.hi)) or 0
  run.shard_cases = b - a + 1
  local before = nil
  if run.shards == 1 then  -- the one writer of this folder: mark it (shards leave the manifest to the merge)
    before = function() manifest.recorder(run, run.m_old):incomplete("computing") end
  end
  local stats = shard.compute(run, before)
  local msg = ("%d cases computed in %d s (%.1f s cpu), %d failed"):format(stats.cases, stats.wall, stats.cpu,
                                                                           stats.failed)
  if stats.resumed > 0 then msg = msg .. (", %d resumed from earlier parts"):format(stats.resumed) end
  if run.shards > 1 then
    say("shard %d of %d done: %s. Once every shard is done: wrc merge %s out=%s (or this command with --merge)",
        run.shard, run.shards, msg, common.shell_word(cmd.script), common.shell_word(run.dir))
    if stats.failed > 0 then cmd.status = 3 end
    return false
  end
  say("%s", msg)
  return true
end

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
-- Returns the number of failed cases (nothing for one shard of several); wrc.command.status is 3 when some failed.
function Study:run(r)
  local cmd = common.command()
  cmd.study = true  -- the host's flags applied (a script that never gets here ignores them; the host says so)
  assert(math.type(r.cases) == "integer" and r.cases >= 1, "study:run: cases must be a positive integer")
  assert(type(r.compute) == "function", "study:run: compute(batch) is required")
  local nchunks, chunk, chunks_text = layout.chunks(r)  -- (its errors name the study's line)
  local run = new_run(self, r, cmd, nchunks, chunk)
  run.hash, run.lines = identity.of(self.script, self.declared, self.options, r, chunks_text)
  -- A folder without parts is checked before anything is created in it (a refused folder stays as it was); one with
  -- parts only once its locks are held, so that a file that another run is writing there is not taken as unknown.
  local has_parts = fs.kind(run.dir .. "/" .. parts.FOLDER) == "folder"
  if not has_parts then manifest.check_folder(run.dir) end
  -- One run at a time writes the folder (a merge, or the study in one process) and one computes each shard: locked
  -- before the folder is read for good.
  if cmd.merge or run.shards == 1 then run.locks:merge() end
  if not cmd.merge then run.locks:shard(run.shard, run.shards) end
  run.m_old = manifest.check_folder(run.dir, not has_parts)
  if not cmd.merge and not compute_shard(run, cmd) then return end
  local failed = merge.merge(run)
  if failed > 0 then
    say("%d of %d cases failed (listed in %s/failures.csv)", failed, run.cases, run.dir)
    cmd.status = 3
  end
  return failed
end

-- `wrc merge DIR` (the form before wrc named the study): runs nothing, says where the parts came from and how to
-- merge them. The host calls it.
M.refuse_folder_merge = origin.refuse_folder_merge

-- The sweep tables and the paper's figures were in wrc.study until it became the runner alone: a study that still
-- looks for them here is told where they are.
local MOVED = {}
for _, name in ipairs{"sweep_columns", "creep_columns", "columns", "sweep_row", "rigid_columns", "rigid_row", "series",
                      "nearest_start", "ranges", "first_crossing", "summary", "plot_sweep", "run_sweep", "plot_patches",
                      "plot_rail_pressure"} do
  MOVED[name] = true
end
setmetatable(M, {__index = function(_, name)
  if MOVED[name] then
    error(("wrc.study.%s is in wrc.sweep now: local sweep = require \"wrc.sweep\", then sweep.%s"):format(name, name), 2)
  end
end})

return M
