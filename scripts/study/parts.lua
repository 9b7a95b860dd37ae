-- wrc.study.parts: the files of OUT/parts, where shards leave their work, and the names they have there.
-- Each shard folder parts/shard-K-of-N/ holds state.txt (which run: hash, script, shard, chunks, options, the build
-- that computed it, identity lines) and checkpoint blocks chunks-A-B.txt, one per compute call: lines "@k" (chunk k begins), "<t> <csv>" (a row
-- of table t), "! <csv>" (a failed case), "# ..." (times), then an end line with the block's line count, size and
-- hash, by which a later run or a merge tells a whole block from one cut short or changed. What a folder holds is
-- data from whoever made it: read and checked here, never run.
--   FOLDER, shard_name(k, n), block_name(a, b)     names
--   block_text(lines), block_damage(path)           a block's text; why a block file is damaged (nil: whole)
--   block_line(tag, text), unescape(text)           one line of a block ("~" marks an escaped line break)
--   blocks_of(folder), disjoint(blocks)             the blocks of a shard folder {a, b, name}; those that overlap
--   write_state(folder, st), read_state(folder)     state.txt (st: hash, script, shard, shards, lo, hi, nchunks,
--                                                   args = {"key=value"}, built = the build, for people (may be
--                                                   nil), lines = identity lines)
--   shard_folders(dir), runs_in(dir)                the shard folders of OUT/parts; the runs their states name
--   remove_temporaries(dir, rel)                    a killed run's temporary files in DIR/rel ("" for DIR)
local common = require "wrc.study.common"
local fs = wrc.fs
local M = {}

M.FOLDER = "parts"

function M.shard_name(k, n) return ("shard-%d-of-%d"):format(k, n) end
function M.block_name(a, b) return ("chunks-%09d-%09d.txt"):format(a, b) end

function M.block_text(lines)
  local body = table.concat(lines, "\n") .. "\n"
  return body .. ("# end of block: %d lines, %d bytes, hash %s\n"):format(#lines, #body, fs.hash(body))
end

function M.block_damage(path)
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

-- "<tag> <text>", or "~<tag> <text>" with "\" and line breaks escaped when the text holds a line break (a quoted
-- CSV cell may: a file name from a folder), so that every row stays one line of the block.
function M.block_line(tag, text)
  if not text:find("\n", 1, true) then return tag .. " " .. text end
  return "~" .. tag .. " " .. text:gsub("\\", "\\\\"):gsub("\n", "\\n")
end
function M.unescape(text) return (text:gsub("\\(.)", function(ch) return ch == "n" and "\n" or ch end)) end

-- Sorted by their first chunk (the longest first).
function M.blocks_of(folder)
  local list = {}
  for _, name in ipairs(fs.list(folder)) do
    local a, b = name:match("^chunks%-(%d+)%-(%d+)%.txt$")
    if a then list[#list + 1] = {tonumber(a), tonumber(b), name} end
  end
  table.sort(list, function(x, y) return x[1] < y[1] or (x[1] == y[1] and x[2] > y[2]) end)
  return list
end

-- The blocks that do not overlap, in order, and the others (left by an earlier run with another batch size).
function M.disjoint(blocks)
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

function M.write_state(folder, st)
  local t = {"wrc study parts", "hash " .. st.hash, "script " .. st.script,
             ("shard %d %d"):format(st.shard, st.shards), ("chunks %d %d %d"):format(st.lo, st.hi, st.nchunks)}
  for _, a in ipairs(st.args) do t[#t + 1] = "arg " .. a end
  if st.built then t[#t + 1] = "built " .. st.built end
  for _, l in ipairs(st.lines) do t[#t + 1] = "line " .. l end
  fs.write_file(folder .. "/state.txt", table.concat(t, "\n") .. "\n")
end

-- nil when the folder holds no state.txt of wrc's.
function M.read_state(folder)
  local lines = common.read_lines(folder .. "/state.txt")
  if not lines or lines[1] ~= "wrc study parts" then return nil end
  local st = {args = {}, lines = {}}
  for _, l in ipairs(lines) do
    local k, v = l:match("^(%S+) (.*)$")
    if k == "hash" or k == "script" or k == "built" then st[k] = v
    elseif k == "shard" then st.shard, st.shards = v:match("^(%d+) (%d+)$")
    elseif k == "chunks" then st.lo, st.hi, st.nchunks = v:match("^(%d+) (%d+) (%d+)$")
    elseif k == "arg" then st.args[#st.args + 1] = v
    elseif k == "line" then st.lines[#st.lines + 1] = v end
  end
  st.lo, st.hi, st.nchunks = tonumber(st.lo), tonumber(st.hi), tonumber(st.nchunks)
  st.shard, st.shards = tonumber(st.shard), tonumber(st.shards)
  return st
end

-- The shard folders of DIR/parts that are real folders (no link): {name =, k =, n =, path =} in name order.
function M.shard_folders(dir)
  local root, list = dir .. "/" .. M.FOLDER, {}
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

-- The runs whose parts DIR holds: runs[hash] = state, and their hashes in the order of the shard folders.
function M.runs_in(dir)
  local runs, order = {}, {}
  for _, s in ipairs(M.shard_folders(dir)) do
    local st = M.read_state(s.path)
    if st and st.hash and not runs[st.hash] then runs[st.hash], order[#order + 1] = st, st.hash end
  end
  return runs, order
end

-- Names of the exact pattern wrc gives temporaries, plain files only; the caller's lock says that no other run is
-- writing them.
function M.remove_temporaries(dir, rel)
  local folder = rel == "" and dir or (dir .. "/" .. rel)
  for _, name in ipairs(fs.list(folder)) do
    if fs.is_temporary(name) then fs.remove_inside(dir, rel == "" and name or (rel .. "/" .. name)) end
  end
end

return M
