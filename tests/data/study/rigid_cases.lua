-- A study of cheap cases for the tests and the memory benchmark of the study runner (wrc.study): case i is the
-- rigid-contact reference (ws:rigid) of the paper's wheelset at y = ((i - 1) mod 161 - 80) x 0.1 mm, yaw 0 (or
-- work=none: the row without the engine, to time the runner alone). Options make it fail on purpose (fail=3,7),
-- pause (a run to kill) and checkpoint often.
--
--   wrc run tests/data/study/rigid_cases.lua cases=100000 out=/tmp/rc
local study = require "wrc.study"
local out = require "wrc.output"

local s = study.new{
  name = "rigid_cases",
  help = "Rigid-contact references of the paper's wheelset, one per case (tests and benchmarks of wrc.study).",
  out = "rigid_cases",
  options = {
    {"cases", "integer", 100, "number of cases", min = 1},
    {"chunk", "integer", 1, "cases per chunk", min = 1},
    {"batch", "integer", 16, "chunks per compute call (one checkpoint block each)", min = 1, hash = false},
    {"work", "string", "rigid", "what a case computes", choices = {"rigid", "none"}},
    {"fail", "string", "", "cases whose computation raises an error, e.g. 3,7 (tests)"},
    {"pause", "number", 0, "seconds to wait after each block (tests: a run to kill)", min = 0, hash = false},
    {"finish_pause", "number", 0, "seconds to wait in the middle of the figures (tests)", min = 0, hash = false},
    {"plots", "boolean", true, "make the histogram of z", hash = false},
  },
}
local opt = s.options
local failing = {}
for c in opt.fail:gmatch("%d+") do failing[tonumber(c)] = true end

local ws = wrc.wheelset{wheel = wrc.profile.load("profiles/s1002.lua"), rail = wrc.profile.load("profiles/60e1.lua")}
local function pose(i) return ((i - 1) % 161 - 80) * 0.1e-3, 0 end

local columns = {"case", "y_mm", "yaw_deg", "z_mm", "roll_mrad", "tension", "Y_Q"}
s:run{
  cases = opt.cases, chunk_size = opt.chunk, batch = opt.batch,
  tables = {{key = "rigid", file = "rigid.csv", columns = columns}},
  key_columns = {"y_mm", "yaw_deg"},
  key = function(i)
    local y, yaw = pose(i)
    return {y_mm = y * 1e3, yaw_deg = math.deg(yaw)}
  end,
  compute = function(batch)
    local results = {}
    for i = batch.first, batch.last do
      if failing[i] then error(("case %d fails on purpose"):format(i)) end
      local y, yaw = pose(i)
      local r = opt.work == "rigid" and ws:rigid{y = y, yaw = yaw, Q = 200e3} or
                {z = -y * y, roll = y, tension = false, Y_Q = y}
      results[i] = {rigid = {case = i, y_mm = y * 1e3, yaw_deg = math.deg(yaw), z_mm = r.z * 1e3,
                             roll_mrad = r.roll * 1e3, tension = r.tension and 1 or 0,
                             Y_Q = (not r.tension) and r.Y_Q or nil}}
    end
    if opt.pause > 0 then os.execute(("sleep %g"):format(opt.pause)) end
    return results
  end,
  -- Streams the table (no row kept): the range of z, then a summary and a histogram of z.
  finish = function(ctx)
    local zmin, zmax, zs, n = math.huge, -math.huge, {}, 0
    local f = assert(io.open(ctx.path("rigid.csv")))
    f:read("l")
    for line in f:lines() do
      local z = tonumber(out.split_csv(line)[4])
      n = n + 1
      zmin, zmax = math.min(zmin, z), math.max(zmax, z)
      if #zs < 1000 then zs[#zs + 1] = z end
    end
    f:close()
    ctx.write("summary.txt", ("cases: %d, failed: %d, rows: %d, z from %.4f to %.4f mm\n"):format(ctx.cases, ctx.failed,
                                                                                                 n, zmin, zmax))
    if opt.finish_pause > 0 then os.execute(("sleep %g"):format(opt.finish_pause)) end
    if not opt.plots then return end
    out.histogram{file = ctx.path("z.png"), values = zs, title = "z of the first 1000 cases", xlabel = "z (mm)"}
  end,
}
