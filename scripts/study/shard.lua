-- wrc.study.shard: computing shard K of N of a run (the whole study is shard 1 of 1). Owns the shard folder's life:
-- the parts of a changed study refused (an unfinished run's) or replaced (a finished run's, or --fresh, every shard
-- folder concerned locked before any is removed), the blocks already done checked and kept (resume), the other
-- chunks computed in batches of run.batch chunks, each batch written as one checkpoint block. A compute that raises
-- is retried chunk by chunk; a chunk that still raises, and a case without a result, are recorded as failed cases.
--   compute(run, before) -> stats    stats = {cases =, failed =, resumed =, wall =, cpu =}; before() is called once
--                                    the parts of another run are gone, before the shard writes (may be nil)
-- run: the fields wrc.study's Study:run documents.
local common = require "wrc.study.common"
local identity = require "wrc.study.identity"
local parts = require "wrc.study.parts"
local out = require "wrc.output"
local fs = wrc.fs
local M = {}

local say, first_line = common.say, common.first_line

-- The block lines of the results of one case: "<t> <csv>" per row of table t, "! <csv>" if it failed.
local function case_lines(run, i, res, lines, stats)
  local err = res == nil and "the study's compute returned no result for this case" or res.error
  for t, tab in ipairs(run.tables) do
    local rows = res and res[tab.key]
    if rows and type(rows[1]) ~= "table" then rows = {rows} end
    for _, row in ipairs(rows or {}) do
      local ok, line = pcall(out.csv_line, tab.columns, row, tab.file .. " case " .. i)
      if ok then lines[#lines + 1] = parts.block_line(t, line) else err = err or first_line(line) end
    end
  end
  if err then
    stats.failed = stats.failed + 1
    local row = run.key and run.key(i) or {}
    row.case, row.error = i, first_line(err)
    lines[#lines + 1] = parts.block_line("!", out.csv_line(run.failure_columns, row, "failures.csv case " .. i))
    if stats.failed <= 5 then say("case %d failed: %s", i, common.printable(first_line(err))) end
  end
end

-- compute(batch) for a batch of chunks; if it raises, chunk by chunk, and a chunk that raises fails all its cases.
local function compute_batch(run, batch)
  local ok, results = pcall(run.compute, batch)
  if ok and type(results) == "table" then return results end
  if #batch.chunks == 1 then
    local results1, err = {}, ok and "compute returned no table" or results
    for i = batch.first, batch.last do results1[i] = {error = err} end
    return results1
  end
  local all = {}
  for _, ch in ipairs(batch.chunks) do
    local part = compute_batch(run, {chunks = {ch}, first = ch.first, last = ch.last})
    for i = ch.first, ch.last do all[i] = part[i] end
  end
  return all
end

-- Computes a batch and writes its block: "@k" and the lines of its cases per chunk, then its times.
local function compute_block(run, folder, batch, stats)
  local w0, c0 = os.time(), os.clock()
  local results = compute_batch(run, batch)
  local lines = {}
  for _, ch in ipairs(batch.chunks) do
    lines[#lines + 1] = "@" .. ch.index
    for i = ch.first, ch.last do case_lines(run, i, results[i], lines, stats) end
    stats.cases = stats.cases + (ch.last - ch.first + 1)
  end
  lines[#lines + 1] = ("# time wall %d s, cpu %.3f s"):format(os.time() - w0, os.clock() - c0)
  results = nil  -- collectable while the block is written
  fs.write_file(folder .. "/" .. parts.block_name(batch.chunks[1].index, batch.chunks[#batch.chunks].index),
                parts.block_text(lines))
end

-- Removes the shard folders that `drop(folder)` selects, all of them locked first (none is being computed; if one
-- is, the run stops before removing any).
local function remove_shards(run, drop)
  local chosen = {}
  for _, s in ipairs(parts.shard_folders(run.dir)) do
    if drop(s) then
      run.locks:shard(s.k, s.n)
      chosen[#chosen + 1] = s
    end
  end
  for _, s in ipairs(chosen) do fs.remove_tree_inside(run.dir, parts.FOLDER .. "/" .. s.name) end
end

-- The parts of another run of the study: refused when unfinished (unless --fresh), removed when replaced.
local function clear_other_runs(run, rel, folder)
  local st = parts.read_state(folder)
  local m_old = run.m_old
  local done_run = m_old and m_old.status == "complete" and m_old.hash or nil  -- parts of a finished run
  if st and st.hash ~= run.hash and not run.fresh then
    if st.hash ~= done_run and identity.other_build(st.lines, run.lines) then
      common.refuse(1, "%s holds the parts of an unfinished run computed by another build of wrc (%s; this is %s): " ..
                    "resuming would mix the two builds' results. Finish that run with the wrc that began it, or run " ..
                    "with --fresh to discard its parts and compute them again with this build, or choose another " ..
                    "folder (out=...)", folder, common.printable(identity.build_of(st)), identity.this_build())
    end
    if st.hash ~= done_run then
      common.refuse(1, "%s holds the parts of an unfinished run with other inputs (%s): run with --fresh to discard " ..
                    "them and start over, or choose another folder (out=...)", folder,
                    identity.differences(st.lines, run.lines))
    end
    say("the previous run into %s was complete and had other inputs (%s): its parts are replaced", run.dir,
        identity.differences(st.lines, run.lines))
  end
  if run.fresh then
    local mine = parts.shard_name(run.shard, run.shards)
    remove_shards(run, function(s) return run.shards == 1 or s.name == mine end)
  elseif done_run and done_run ~= run.hash and run.shards == 1 then  -- the one writer: the finished run's parts go
    remove_shards(run, function(s)
      local other = parts.read_state(s.path)
      return other ~= nil and other.hash == done_run
    end)
  elseif st and st.hash ~= run.hash then
    fs.remove_tree_inside(run.dir, rel)
  end
end

-- The chunks done in a shard folder: its blocks checked, a damaged one and one overlapping another removed (their
-- chunks are computed again). Returns done[chunk] = true.
local function usable_blocks(run, rel)
  local folder = run.dir .. "/" .. rel
  local kept, extra = parts.disjoint(parts.blocks_of(folder))
  local done, damaged = {}, {}
  for _, b in ipairs(kept) do
    local why = parts.block_damage(folder .. "/" .. b[3])
    if why then
      damaged[#damaged + 1] = ("%s: %s"):format(b[3], why)
      fs.remove_inside(run.dir, rel .. "/" .. b[3])
    else
      for k = b[1], b[2] do done[k] = true end
    end
  end
  for _, b in ipairs(extra) do fs.remove_inside(run.dir, rel .. "/" .. b[3]) end
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

-- The shard folder ready to be written: other runs' parts gone, a killed run's temporaries removed, state.txt
-- written. Returns the chunks already done.
local function prepare(run, rel, folder, before)
  local ok, err = pcall(fs.mkdir_inside, run.dir, rel)
  if not ok then common.refuse(1, "%s", common.plain(err)) end
  clear_other_runs(run, rel, folder)
  if before then before() end
  fs.mkdir_inside(run.dir, rel)
  parts.remove_temporaries(run.dir, rel)
  parts.write_state(folder, {hash = run.hash, script = run.script, shard = run.shard, shards = run.shards,
                             lo = run.lo, hi = run.hi, nchunks = run.nchunks, args = run.args,
                             built = identity.this_build(), lines = run.lines})
  return usable_blocks(run, rel)
end

-- The next batch from chunk k on: up to run.batch chunks not done. Returns it and the chunk after it.
local function next_batch(run, k, done)
  local batch = {chunks = {}}
  while k <= run.hi and not done[k] and #batch.chunks < run.batch do
    local a, b = run.chunk(k)
    batch.chunks[#batch.chunks + 1] = {index = k, first = a, last = b}
    k = k + 1
  end
  batch.first, batch.last = batch.chunks[1].first, batch.chunks[#batch.chunks].last
  return batch, k
end

local function announce(run, folder, resumed)
  local from = run.shard_from
  if run.shards > 1 or from ~= "" then
    say("shard %d of %d (%s): chunks %d..%d of %d", run.shard, run.shards, from ~= "" and from or "one process",
        run.lo, run.hi, run.nchunks)
  end
  if resumed > 0 then say("resuming: %d cases already computed in %s", resumed, folder) end
end

function M.compute(run, before)
  local rel = parts.FOLDER .. "/" .. parts.shard_name(run.shard, run.shards)
  local folder = run.dir .. "/" .. rel
  local done = prepare(run, rel, folder, before)
  local stats = {cases = 0, failed = 0, resumed = 0}
  for k = run.lo, run.hi do
    if done[k] then
      local a, b = run.chunk(k)
      stats.resumed = stats.resumed + (b - a + 1)
    end
  end
  announce(run, folder, stats.resumed)
  local t0, clock0, last_say = os.time(), os.clock(), os.time()
  local k = run.lo
  while k <= run.hi do
    if done[k] then
      k = k + 1
    else
      local batch
      batch, k = next_batch(run, k, done)
      compute_block(run, folder, batch, stats)
      if os.time() - last_say >= 10 then
        last_say = os.time()
        say("%d of %d cases of this shard, %d failed, %d s", stats.cases + stats.resumed, run.shard_cases,
            stats.failed, os.time() - t0)
      end
    end
  end
  stats.wall, stats.cpu = os.time() - t0, os.clock() - clock0
  return stats
end

return M
