-- Writes the analytic S1002 wheel and 60E1 rail (profiles/*.lua, 0.1 mm along the arc) as text profiles in metres
-- with 17 significant digits, which read back bit for bit: the paper's profiles for tests that build a wheelset
-- without a Lua state (tests/wheelset). Run by CTest as a fixture:
--   wrc run tests/data/profile/write_text_profiles.lua out=<folder>
local out = assert(arg.out, "out=<folder> is required")
wrc.fs.mkdir(out)
for name, file in pairs{s1002 = "profiles/s1002.lua", ["60e1"] = "profiles/60e1.lua"} do
  local p = wrc.profile.load(file)
  local y, z = p:points()
  local f = assert(io.open(out .. "/" .. name .. ".csv", "w"))
  f:write("y_m,z_m\n")
  for i = 1, #y do f:write(string.format("%.17g,%.17g\n", y[i], z[i])) end
  f:close()
end
