-- The study runner's modules: wrc.study is the runner (the sweep tables and the paper's figures are wrc.sweep, one
-- user of it, and a study that looks for them in wrc.study is told where they are), and the contracts of the
-- runner's modules that need no run: shard layout, checkpoint blocks, identity differences. Whole runs are tested by
-- tests/cluster/*.sh.
local check = require "wrc.check"
local study = require "wrc.study"
local sweep = require "wrc.sweep"

check.ok(type(study.new) == "function", "wrc.study.new")
check.ok(type(study.refuse_folder_merge) == "function", "wrc.study.refuse_folder_merge (the host's wrc merge DIR)")
for _, name in ipairs{"sweep_columns", "creep_columns", "columns", "sweep_row", "rigid_columns", "rigid_row", "series",
                      "nearest_start", "ranges", "first_crossing", "summary", "plot_sweep", "run_sweep", "plot_patches",
                      "plot_rail_pressure"} do
  check.ok(sweep[name] ~= nil, "wrc.sweep." .. name)
  check.fails(function() return study[name] end, 'local sweep = require "wrc.sweep", then sweep.' .. name,
              "wrc.study." .. name)
end
check.ok(study.no_such_name == nil, "another name of wrc.study reads nil")

-- Shard K of N of n chunks: contiguous, in order, every chunk once, sizes within one of each other (brute force).
local layout = require "wrc.study.layout"
for chunks = 0, 25 do
  for n = 1, 9 do
    local next_chunk, smallest, largest = 1, math.huge, 0
    for k = 1, n do
      local lo, hi = layout.shard_range(k, n, chunks)
      check.ok(lo == next_chunk, ("shard %d of %d of %d chunks starts at %d"):format(k, n, chunks, next_chunk))
      next_chunk = hi + 1
      smallest, largest = math.min(smallest, hi - lo + 1), math.max(largest, hi - lo + 1)
    end
    check.ok(next_chunk == chunks + 1, ("%d shards cover the %d chunks"):format(n, chunks))
    check.ok(largest - smallest <= 1, ("%d shards of %d chunks are even"):format(n, chunks))
  end
end
local n, chunk = layout.chunks{cases = 10, chunk_size = 3}
local a, b = chunk(4)
check.ok(n == 4 and a == 10 and b == 10, "10 cases in chunks of 3: the fourth holds case 10 alone")
check.fails(function() layout.chunks{cases = 3, chunks = {{first = 1, last = 1}, {first = 3, last = 3}}} end,
            "chunks[2] = 3..3 does not continue the cases after 1", "a chunk list with a gap")
check.fails(function() layout.chunks{cases = 3, chunks = {{first = 1, last = 2}}} end,
            "the chunks cover cases 1..2 of 3", "a chunk list short of the cases")

-- A checkpoint block's end line vouches for it: a block cut short, changed or grown is found out.
local parts = require "wrc.study.parts"
local fs = wrc.fs
local dir = (arg.tmp or "/tmp") .. "/study_modules"
fs.mkdir(dir)
local row = 'a,"two\nlines \\ here"'
local line = parts.block_line(1, row)
check.ok(not line:find("\n", 1, true) and line:sub(1, 1) == "~", "a row with a line break is one escaped line")
check.ok(parts.unescape(line:sub(2)) == "1 " .. row, "the escaped line reads back to the row")
local text = parts.block_text({"@1", line, "1 b,c", "# time wall 0 s, cpu 0.000 s"})
local path = dir .. "/chunks-000000001-000000001.txt"
local function damage(content)
  fs.write_file(path, content)
  return parts.block_damage(path)
end
check.ok(damage(text) == nil, "a whole block: no damage")
check.ok(damage(text:gsub("b,c", "b,d")):find("checksum", 1, true), "a changed value")
check.ok(damage(text:sub(1, #text - 10)):find("end line is missing", 1, true), "a block cut short")
check.ok(damage(text:gsub("@1\n", "@1\n1 x,y\n")):find("size", 1, true), "a block with a row added")
fs.remove(path)

-- What changed between two runs: options first, then the rest.
local identity = require "wrc.study.identity"
check.ok(identity.differences({"engine 1", "script ab", "option a=1", "cases 4"},
                              {"engine 2", "script ab", "option a=2", "cases 4"}) == "option a: 1 -> 2; engine: 1 -> 2",
         "differences name the option first")
check.ok(identity.script_hash({"engine 1", "script 0f3a"}) == "0f3a", "the script's hash among identity lines")
