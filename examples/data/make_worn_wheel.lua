-- Writes examples/data/s1002_hollow_worn.whl: a hollow-worn S1002 wheel in the MiniProf wheel layout, made by wrc from
-- the analytic S1002 (profiles/s1002.lua) -- not a measurement:
--
--   wrc run examples/data/make_worn_wheel.lua [out=examples/data]
--
-- The tread is worn down radially by 1.2 * cos^2(pi (s - 3 mm) / 56 mm) mm over s = -25 .. 31 mm (a hollow 1.2 mm
-- deep at s = 3 mm, 56 mm wide: the field side is left standing as a "false flange"), the profile is sampled every
-- 0.2 mm and +-3 um of deterministic noise is added to the radial coordinate, as a measuring device would. The file
-- has the layout of tests/data/profile/samples/s1002.whl (X from the flange back, Y toward the flange tip, rows from
-- the field side) with Sh, Sd and qR measured on the worn profile. Rerun only to change the wear; commit the output.
local out = require("wrc.study").new{
  name = "make_worn_wheel", out = (arg[0] or ""):match("^(.*)/[^/]*$") or ".",
  help = "Writes s1002_hollow_worn.whl: a hollow-worn S1002 in the MiniProf wheel layout (generated, not measured).",
}.options.out
local s1002 = wrc.profile.load("profiles/s1002.lua", {step = 0.2e-3})
local y, z = s1002:points()
local seed = 20240611
local function noise()  -- uniform in [-1, 1], a 31-bit LCG
  seed = (seed * 1103515245 + 12345) % 2147483648
  return seed / 2147483648 * 2 - 1
end
for i = 1, #y do
  local u = (y[i] - 0.003) / 0.056
  if math.abs(u) < 0.5 then z[i] = z[i] + 1.2e-3 * math.cos(math.pi * u) ^ 2 end  -- z up = radius down
  z[i] = z[i] + 3e-6 * noise()
end
local worn = wrc.profile.points{kind = "wheel", name = "S1002 hollow worn", y = y, z = z}
local m = worn:flange_measures()
local L = {"MINIPROF", "Filename=s1002_hollow_worn.whl", "ProgramName=wrc examples/data/make_worn_wheel.lua",
           "ProgramVer=1", ("XYPoints=%d"):format(#y), ("Sh=%.2f"):format(m.Sh * 1e3), ("Sd=%.2f"):format(m.Sd * 1e3),
           ("qR=%.2f"):format(m.qR * 1e3), "Comment=generated: S1002 with 1.2 mm hollow tread wear and 3 um noise",
           "Chars=Win", "ColumnDef=X,Y", ""}
for i = #y, 1, -1 do L[#L + 1] = (" %.4f\t% .4f"):format((y[i] + 0.070) * 1e3, -z[i] * 1e3) end
local path = out .. "/s1002_hollow_worn.whl"
wrc.fs.write_file(path, table.concat(L, "\r\n") .. "\r\n")
print(("wrote %s: %d points, Sh %.2f mm, Sd %.2f mm, qR %.2f mm"):format(path, #y, m.Sh * 1e3, m.Sd * 1e3, m.qR * 1e3))
