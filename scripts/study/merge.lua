-- wrc.study.merge: assembling a run's outputs from its parts. Owns finding a complete set of shards of this run (the
-- smallest N whose every shard is done; its shards locked so that it stays as found, every block checked), streaming
-- the blocks in chunk order into exactly the tables one process writes (and failures.csv), then calling the study's
-- finish(ctx) on them, with the manifest kept by a recorder (wrc.study.manifest) from start to end.
--   merge(run) -> failed             the number of failed cases; a missing or damaged part stops the run (exit 1)
--                                    naming what is missing or damaged and the command that computes it
-- run: the fields wrc.study's Study:run documents.
local common = require "wrc.study.common"
local identity = require "wrc.study.identity"
local layout = require "wrc.study.layout"
local manifest = require "wrc.study.manifest"
local parts = require "wrc.study.parts"
local out = require "wrc.output"
local fs = wrc.fs
local M = {}

local refuse, printable, shell_word = common.refuse, common.printable, common.shell_word

-- The command that computes shard K of N of this run again (for messages).
local function shard_command(run, k, n)
  local words, has_out = {"wrc run", shell_word(run.command_script)}, false
  for _, a in ipairs(run.command_args) do
    words[#words + 1] = shell_word(a)
    has_out = has_out or a:match("^[^=]*") == "out"
  end
  if not has_out then words[#words + 1] = shell_word("out=" .. run.dir) end
  words[#words + 1] = ("--shard %d/%d"):format(k, n)
  return table.concat(words, " ")
end

----------------------------------------------------------------------------------------------------------------
-- The parts to merge

-- The shard folders of this run by N and K: sets[n][k] = {folder =, state =}; the names of the others; and those
-- of this study computed by another build, builds[name] = that build.
local function sets_of(run)
  local sets, others, builds = {}, {}, {}
  for _, s in ipairs(parts.shard_folders(run.dir)) do
    local st = parts.read_state(s.path)
    if st and st.hash == run.hash and s.k >= 1 and s.k <= s.n then
      sets[s.n] = sets[s.n] or {}
      sets[s.n][s.k] = {folder = s.path, state = st}
    elseif st and identity.other_build(st.lines, run.lines) then
      builds[#builds + 1] = {name = s.name, k = s.k, n = s.n, build = common.printable(identity.build_of(st))}
    else
      others[#others + 1] = s.name
    end
  end
  return sets, others, builds
end

-- Why the shards computed by another build are not merged, and the commands that compute them with this one.
local function other_builds(run, builds)
  local names, commands = {}, {}
  for _, b in ipairs(builds) do
    names[#names + 1] = ("%s (%s)"):format(b.name, b.build)
    commands[#commands + 1] = shard_command(run, b.k, b.n) .. " --fresh"
  end
  return ("shards computed by another build of wrc, which this one (%s) does not mix with its own: %s; compute " ..
          "them again with this build (%s), or merge with the wrc that computed them"):format(identity.this_build(),
          table.concat(names, ", "), table.concat(commands, "; "))
end

-- Whether shard p (K of N) is done: p.blocks set to the chain of blocks that covers its chunks; or why not.
local function chain_blocks(run, p, k, n)
  local lo, hi = layout.shard_range(k, n, run.nchunks)
  p.blocks = {}
  local next_chunk = lo
  for _, b in ipairs((parts.disjoint(parts.blocks_of(p.folder)))) do
    if b[1] == next_chunk and b[2] <= hi then
      p.blocks[#p.blocks + 1] = b
      next_chunk = b[2] + 1
    end
  end
  if next_chunk <= hi then return false, ("shard %d of %d: %d of %d chunks done"):format(k, n, next_chunk - lo, hi - lo + 1) end
  return true
end

-- The complete set of shard folders with the smallest N: {n = N, shards = {[k] = {folder =, blocks =}}}, or nil
-- and why not.
local function find_parts(run)
  local sets, others, builds = sets_of(run)
  if next(sets) == nil and #others == 0 and #builds == 0 then
    return nil, "there are no parts in " .. run.dir .. "/" .. parts.FOLDER
  end
  local why, ns, stale = {}, {}, {}
  for _, b in ipairs(builds) do stale[b.name] = true end
  for n in pairs(sets) do ns[#ns + 1] = n end
  table.sort(ns)
  local best = nil
  for _, n in ipairs(ns) do
    local complete = true
    for k = 1, n do
      local p, ok, because = sets[n][k], false, ("shard %d of %d has not started"):format(k, n)
      if stale[parts.shard_name(k, n)] then because = ("shard %d of %d was computed by another build"):format(k, n) end
      if p then ok, because = chain_blocks(run, p, k, n) end
      if not ok then complete, why[#why + 1] = false, because end
    end
    if complete and not best then best = {n = n, shards = sets[n]} end
  end
  if best then return best end
  if #builds > 0 then why[#why + 1] = other_builds(run, builds) end
  if #others > 0 then why[#why + 1] = "parts of other studies or options: " .. table.concat(others, ", ") end
  return nil, table.concat(why, "; ")
end

-- Stops the run when a block of the set is damaged, naming each and the commands that compute them again.
local function refuse_damaged(run, set)
  local damaged, shards = {}, {}
  for k = 1, set.n do
    for _, b in ipairs(set.shards[k].blocks) do
      local bad = parts.block_damage(set.shards[k].folder .. "/" .. b[3])
      if bad then
        damaged[#damaged + 1] = ("shard %d of %d, %s: %s"):format(k, set.n, b[3], bad)
        if shards[#shards] ~= k then shards[#shards + 1] = k end
      end
    end
  end
  if #damaged == 0 then return end
  local commands = {}
  for _, k in ipairs(shards) do commands[#commands + 1] = "  " .. shard_command(run, k, set.n) end
  refuse(1, "cannot merge into '%s': %d damaged block%s (%s%s). A shard's run checks its blocks and computes the " ..
         "damaged ones again:\n%s\nthen merge again.", run.dir, #damaged, #damaged > 1 and "s" or "",
         table.concat(damaged, "; ", 1, math.min(#damaged, 4)), #damaged > 4 and "; ..." or "",
         table.concat(commands, "\n"))
end

-- The complete set of parts to merge, its shards locked (none is computed while it is merged) and every block
-- checked; or the run stops saying what is missing or damaged and how to compute it.
local function parts_to_merge(run)
  for _ = 1, 10 do
    local set, why = find_parts(run)
    if not set then
      refuse(1, "cannot merge into '%s': %s. Run the missing shards (a shard run again resumes), then merge again.",
             run.dir, why)
    end
    local held = true
    for k = 1, set.n do
      held = held and run.locks:holds_shard(k, set.n)
      run.locks:shard(k, set.n)
    end
    if held then  -- found while its shards were locked: it stays as found
      refuse_damaged(run, set)
      return set
    end
  end
  refuse(1, "cannot merge into '%s': its parts keep changing (shards are being computed); merge once they are done",
         run.dir)
end

----------------------------------------------------------------------------------------------------------------
-- The tables

-- The files a merge streams into: a writer per table, failures.csv opened at the first failure.
local function open_outputs(run)
  local o = {writers = {}, failed = 0, cpu = 0, expect = 1}
  for t, tab in ipairs(run.tables) do o.writers[t] = out.csv_writer(run.dir .. "/" .. tab.file, tab.columns) end
  function o.discard()
    for _, w in ipairs(o.writers) do w:discard() end
    if o.failures then o.failures:discard() end
  end
  return o
end

-- Stops the merge: the files begun are discarded (the folder keeps the tables it had).
local function bad(run, o, where, fmt, ...)
  o.discard()
  refuse(1, "cannot merge into '%s': %s: %s; compute that shard again with --fresh", run.dir, where,
         string.format(fmt, ...))
end

-- One line of a block: a chunk's start, a failure, a time, or a row whose text goes to its table byte for byte.
local function merge_line(run, o, where, line)
  if line:byte(1) == 126 then line = parts.unescape(line:sub(2)) end  -- "~": a row that holds a line break
  local tag = line:byte(1)
  if tag == 64 then  -- "@k"
    local ch = tonumber(line:sub(2))
    if ch ~= o.expect then bad(run, o, where, "it holds chunk %s where chunk %d was expected", line:sub(2, 20), o.expect) end
    o.expect = o.expect + 1
  elseif tag == 33 then  -- "! failure"
    o.failures = o.failures or out.open(run.dir .. "/failures.csv")
    if o.failed == 0 then o.failures:write(table.concat(run.failure_columns, ","), "\n") end
    o.failures:write(line:sub(3), "\n")
    o.failed = o.failed + 1
  elseif tag == 35 then  -- "# time wall <s> s, cpu <s> s" of a block, or its end line
    local cpu = line:match("^# time wall %d+ s, cpu ([%d.]+) s")
    o.cpu = o.cpu + (tonumber(cpu) or 0)
  else
    local t, rest = line:match("^(%d+) (.*)$")
    local w = o.writers[tonumber(t or "")]
    if not w then bad(run, o, where, "a line of no table: %s", printable(line:sub(1, 40))) end
    w:append(rest)
  end
end

-- Streams the blocks of every shard, in chunk order, into the tables and failures.csv. Returns the number of failed
-- cases and the compute CPU time the blocks record (s).
local function merge_tables(run, set)
  local o = open_outputs(run)
  for k = 1, set.n do
    local p = set.shards[k]
    for _, b in ipairs(p.blocks) do
      local where = p.folder .. "/" .. b[3]
      for line in io.lines(where) do merge_line(run, o, where, line) end
    end
  end
  if o.expect ~= run.nchunks + 1 then
    bad(run, o, run.dir .. "/" .. parts.FOLDER, "the parts hold chunks 1..%d of %d", o.expect - 1, run.nchunks)
  end
  for _, w in ipairs(o.writers) do w:close() end
  if o.failures then o.failures:close() end
  return o.failed, o.cpu
end

----------------------------------------------------------------------------------------------------------------
-- The merge

-- What the study's finish(ctx) gets: the folder, options and counts, and its files by name (one line each in the
-- manifest: a name that cannot be is an error at the study's line).
local function finish_context(run, failed, shards)
  local ctx = {dir = run.dir, options = run.options, cases = run.cases, failed = failed, shards = shards}
  local function inside(name)
    local why = fs.name_problem(tostring(name))
    if why then error(("%s: cannot name a file '%s' in it: %s"):format(run.dir, printable(name), why), 3) end
    return run.dir .. "/" .. name
  end
  function ctx.path(name) return inside(name) end
  function ctx.read(name) return out.read_csv(inside(name)) end
  function ctx.write(name, text) out.text(inside(name), text) end
  -- A profile written by p:write (its format from the extension, or options.format), listed as the tables are.
  function ctx.write_profile(name, profile, options)
    local path = inside(name)
    profile:write(path, options or {})
    if out.on_write then out.on_write(path) end
  end
  return ctx
end

function M.merge(run)
  run.locks:merge()
  local set = parts_to_merge(run)
  parts.remove_temporaries(run.dir, "")  -- a killed merge's (the merge is the one writer of the folder)
  local rec = manifest.recorder(run, run.m_old)
  rec:incomplete("merging; a run killed now leaves this mark")
  out.on_write = function(path) rec:wrote(path) end
  local failed, cpu
  local ok, err = pcall(function()
    failed, cpu = merge_tables(run, set)
    if run.finish then run.finish(finish_context(run, failed, set.n)) end
  end)
  out.on_write = nil
  if not ok then
    rec:incomplete("failed: " .. common.first_line(err))
    error(err, 0)
  end
  rec:complete({"shards " .. set.n, "failed " .. failed, ("compute_cpu %.2f s"):format(cpu)})
  return failed
end

return M
