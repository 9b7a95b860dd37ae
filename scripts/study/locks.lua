-- wrc.study.locks: one run at a time computes a shard, one writes the folder (a merge, or the study in one process).
-- A run's lock set takes OUT/parts/<name>.lock files (flock: held for the rest of the run, released when its process
-- ends, kill -9 too) and stops the run naming the process that holds one (exit status 1).
--   new(dir) -> locks        locks:shard(k, n), locks:merge(), locks:holds_shard(k, n)
local common = require "wrc.study.common"
local parts = require "wrc.study.parts"
local fs = wrc.fs
local M = {}

local Locks = {}
Locks.__index = Locks

function M.new(dir) return setmetatable({dir = dir, held = {}}, Locks) end

-- Takes DIR/parts/<name>.lock (once per run), or stops the run.
function Locks:take(name, what)
  if self.held[name] then return end
  local ok, err = pcall(fs.mkdir_inside, self.dir, parts.FOLDER)
  if not ok then common.refuse(1, "%s", common.plain(err)) end
  local lock, note
  ok, err = pcall(function() lock, note = fs.lock(self.dir .. "/" .. parts.FOLDER .. "/" .. name .. ".lock") end)
  if not ok then common.refuse(1, "%s", common.plain(err)) end
  if not lock then
    common.refuse(1, "%s: %s is being written by another wrc run (%s): wait until it ends, or stop it (its lock ends " ..
                  "with its process)", self.dir, what, note)
  end
  if not lock.locked then common.say("%s: two runs into this folder at once are not kept apart", note) end
  self.held[name] = lock
end

function Locks:shard(k, n) self:take(parts.shard_name(k, n), ("shard %d of %d"):format(k, n)) end
function Locks:merge() self:take("merge", "the folder (a merge, or a run of the whole study in one process)") end
function Locks:holds_shard(k, n) return self.held[parts.shard_name(k, n)] ~= nil end

return M
