-- wrc.study.layout: which cases make each chunk, and which chunks each shard computes. The study fixes its chunks
-- (never the number of shards or threads), so that any split of the work gives the same rows. Arithmetic only.
--   chunks(r) -> n, chunk(k) -> first, last, text   r: Study:run's table (cases, and chunks or chunk_size); text
--                                                   names the layout among the study's identity lines
--   shard_range(k, n, chunks) -> lo, hi             shard K of N computes chunks lo..hi (empty when lo > hi)
local fs = wrc.fs
local M = {}

-- r.chunks, a list of {first =, last =} covering 1..cases in order; an error names the first that does not, at
-- the study's line (level 4: here, chunks, Study:run, the study).
local function check_list(r)
  local prev = 0
  for k, c in ipairs(r.chunks) do
    if c.first ~= prev + 1 or c.last < c.first then
      error(("study: chunks[%d] = %s..%s does not continue the cases after %d"):format(k, c.first, c.last, prev), 4)
    end
    prev = c.last
  end
  if prev ~= r.cases then error(("study: the chunks cover cases 1..%d of %d"):format(prev, r.cases), 4) end
end

-- The chunk list: r.chunks or chunks of r.chunk_size cases (default 1), computed on demand so that 10^6 cases need
-- no list.
function M.chunks(r)
  if r.chunks then
    check_list(r)
    local firsts = {}
    for _, c in ipairs(r.chunks) do firsts[#firsts + 1] = c.first end
    return #r.chunks, function(k) return r.chunks[k].first, r.chunks[k].last end,
           "list " .. fs.hash(table.concat(firsts, ","))
  end
  local size = r.chunk_size or 1
  local n = (r.cases + size - 1) // size
  return n, function(k) return (k - 1) * size + 1, math.min(k * size, r.cases) end, "size " .. size
end

-- Contiguous, and the same on every machine.
function M.shard_range(k, n, chunks) return (k - 1) * chunks // n + 1, k * chunks // n end

return M
