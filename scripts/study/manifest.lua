-- wrc.study.manifest: OUT/manifest.txt, the output folder's record of what a run wrote there: status, study, hash,
-- options, counts, "file NAME SIZE HASH" per file written, "previous NAME SIZE HASH" per file a killed or unfinished
-- run may have left. Owns reading it (names that leave the folder are ignored), refusing a folder that holds files no
-- run listed, writing it, and -- through a recorder, while a run writes the folder -- keeping it "incomplete" with
-- every file known, then removing the previous run's stale files (only plain files inside the folder, still of the
-- hash recorded) and marking it "complete".
--   NAME; read(dir) -> m or nil      m = {status =, hash =, ..., known = {[name] = {size =, hash =}}, ignored = {}}
--   check_folder(dir, quiet) -> m    stops the run (exit 1) when DIR holds files no manifest lists
--   write(run, status, files, previous, extra)
--   recorder(run, m_old) -> rec      rec:incomplete(why), rec:wrote(path) (wrc.output's on_write), rec:complete(extra)
-- run = {dir =, script =, hash =, cases =, args = {"key=value", ...}} (the options given, `out` aside).
local common = require "wrc.study.common"
local identity = require "wrc.study.identity"
local parts = require "wrc.study.parts"
local fs = wrc.fs
local M = {}

M.NAME = "manifest.txt"
local printable = common.printable

function M.read(dir)
  local lines = common.read_lines(dir .. "/" .. M.NAME)
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

-- The first `most` names of a list, ", ..." when there are more.
local function some(list, most)
  local shown = {table.unpack(list, 1, math.min(#list, most))}
  return printable(table.concat(shown, ", ")) .. (#list > #shown and ", ..." or "")
end

local function note_ignored(dir, m)
  local many = #m.ignored > 1
  common.say("%s/%s: ignored %d name%s that name%s no file inside the folder: %s", dir, M.NAME, #m.ignored,
             many and "s" or "", many and "" or "s", printable(table.concat(m.ignored, ", ")))
end

-- A run never mixes its outputs with files no wrc run listed.
function M.check_folder(dir, quiet)
  local m = M.read(dir)
  local known = {}
  for name in pairs(m and m.known or {}) do known[name:match("^[^/]+")] = true end
  if m and #m.ignored > 0 and not quiet then note_ignored(dir, m) end
  local unknown = {}
  for _, name in ipairs(fs.list(dir)) do
    if name ~= M.NAME and name ~= parts.FOLDER and not fs.is_temporary(name) and not known[name] then
      unknown[#unknown + 1] = name
    end
  end
  if #unknown > 0 then
    common.refuse(1, "output folder '%s' holds %s that no wrc run listed in %s (%s): remove %s or choose another " ..
                  "folder (out=...); a run never mixes its outputs with unknown files", dir,
                  #unknown > 1 and (#unknown .. " files") or "a file", m and M.NAME or "a manifest", some(unknown, 6),
                  #unknown > 1 and "them" or "it")
  end
  return m
end

-- previous = {{name =, rec = {size =, hash =} or nil}, ...}: files that are or may be in the folder.
function M.write(run, status, files, previous, extra)
  local t = {"# wrc study manifest: the files this run wrote into this folder (read by the next run into it)",
             "status " .. status, "study " .. run.script, "hash " .. run.hash, "engine " .. identity.this_build(),
             "cases " .. run.cases}
  for _, l in ipairs(extra or {}) do t[#t + 1] = l end
  for _, a in ipairs(run.args) do t[#t + 1] = "option " .. a end
  for _, name in ipairs(files or {}) do
    local path = run.dir .. "/" .. name
    t[#t + 1] = ("file %s %d %s"):format(name, fs.size(path), fs.hash_file(path))
  end
  for _, p in ipairs(previous or {}) do
    local r = p.rec
    t[#t + 1] = (r and r.hash) and ("previous %s %d %s"):format(p.name, r.size, r.hash) or ("previous " .. p.name)
  end
  fs.write_file(run.dir .. "/" .. M.NAME, table.concat(t, "\n") .. "\n")
end

----------------------------------------------------------------------------------------------------------------
-- The recorder of a run that writes the folder

local Recorder = {}
Recorder.__index = Recorder

-- known: the previous run's files (sorted); written: this run's, in the order written; records: their digests.
function M.recorder(run, m_old)
  local rec = setmetatable({run = run, old = m_old and m_old.known or {}, known = {}, written = {}, seen = {},
                            records = {}}, Recorder)
  for name in pairs(rec.old) do rec.known[#rec.known + 1] = name end
  table.sort(rec.known)
  return rec
end

-- Until the end, the manifest says "incomplete" and lists every file that is or may be in the folder (the previous
-- run's and each new one as it is written), so that a run killed now is marked and its files known.
function Recorder:incomplete(why)
  local previous = {}
  for _, n in ipairs(self.known) do previous[#previous + 1] = {name = n, rec = self.records[n] or self.old[n]} end
  for _, n in ipairs(self.written) do
    if not self.old[n] then previous[#previous + 1] = {name = n, rec = self.records[n]} end
  end
  M.write(self.run, "incomplete (" .. why .. ")", {}, previous)
end

-- A file written (any path: those outside the folder are not the run's to list).
function Recorder:wrote(path)
  local prefix = self.run.dir .. "/"
  local name = path:sub(1, #prefix) == prefix and path:sub(#prefix + 1) or nil
  if not name then return end
  local why = fs.name_problem(name)
  if why then error(("%s: cannot list '%s' in %s: %s"):format(self.run.dir, printable(name), M.NAME, why), 0) end
  local hash, size = fs.digest(path)
  self.records[name] = {size = size, hash = hash}
  if not self.seen[name] then
    self.seen[name] = true
    self.written[#self.written + 1] = name
  end
  self:incomplete("merging; a run killed now leaves this mark")
end

-- The previous run's files not written by this one: removed when each is still the file that run recorded (its
-- hash), a plain file inside the folder; the others are left in place and named.
function Recorder:remove_stale()
  local removed, left = {}, {}
  for _, name in ipairs(self.known) do
    if not self.seen[name] and name ~= M.NAME then
      local rec, r, why = self.old[name], nil, "no hash of it recorded"
      if rec.hash then r, why = fs.remove_inside(self.run.dir, name, rec.hash) end
      if r == "removed" then
        removed[#removed + 1] = name
      elseif not r then
        left[#left + 1] = ("%s (%s)"):format(name, common.plain(why))
      end
    end
  end
  local dir = self.run.dir
  if #removed > 0 then
    common.say("removed %d file%s of the previous run into %s (listed in its manifest, not written by this one): %s",
               #removed, #removed > 1 and "s" or "", dir, some(removed, 8))
  end
  if #left > 0 then
    common.say("left %d file%s of the previous run in %s (listed in its manifest, not written by this one, not " ..
               "removed): %s; remove %s yourself: the next run into the folder refuses files no manifest lists",
               #left, #left > 1 and "s" or "", dir, some(left, 8), #left > 1 and "them" or "it")
  end
end

-- The stale files removed, the manifest lists this run's files (sorted) with the extra lines (counts).
function Recorder:complete(extra)
  self:remove_stale()
  table.sort(self.written)
  M.write(self.run, "complete", self.written, {}, extra)
end

return M
