-- examples/paper_study.lua with a rolling speed (V_kmh, mu, method, wear): sweep.csv gains the creep-force, T gamma,
-- RCF and wear columns, and each row's values are those of the rolling contact solved here, one by one, at the pose
-- the row states (ws:contact with the same rolling keys at its y, z, roll and yaw). Without V_kmh there are none.
local check = require "wrc.check"
local out = require "wrc.output"

local dir = (arg.tmp or os.getenv("WRC_TEST_TMP") or "/tmp") .. "/example_paper_rolling"
wrc.fs.remove_tree(dir)  -- this build's numbers: a study resumes the cases an earlier build of the same version wrote
local function run(extra, sub)
  arg = {[0] = arg[0], out = dir .. "/" .. sub, plots = false, step_mm = 2, ymax_mm = 4, grid_mm = 0.5, threads = 1}
  for k, v in pairs(extra) do arg[k] = v end
  dofile(wrc.paths.root .. "/examples/paper_study.lua")
  return out.read_csv(dir .. "/" .. sub .. "/sweep.csv")
end
local cols, rows = run({V_kmh = 100, mu = 0.3, wear = "archard"}, "rolling")
local has = {}
for _, c in ipairs(cols) do has[c] = true end
for _, c in ipairs{"left_creep_Fy_kN", "power_W", "left_Tgamma_N", "right_Tgamma_spin_N", "left_rcf_damage_max",
                   "left_wear_mm3_per_m", "right_wear_mm3_per_m"} do
  check.ok(has[c], "sweep.csv with V_kmh has the column " .. c)
end
-- The example's wheelset (Baeza et al.'s set-up), here again.
local ws = wrc.wheelset{
  wheel = wrc.profile.load("profiles/s1002.lua", {step = 0.1e-3}), rail = wrc.profile.load("profiles/60e1.lua", {step = 0.1e-3}),
  radius = 0.45, back_to_back = 1.360, gauge = 1.435, gauge_depth = 0.014, cant = 1 / 40, E = 2.1e11, nu = 0.3,
  grid = 0.5e-3, surface = "planar"}
check.ok(#rows == 10, "5 lateral shifts x 2 yaws")
for _, r in ipairs(rows) do
  check.ok(r.converged == 1, ("y = %g mm, yaw %g deg converged"):format(r.y_mm, r.yaw_deg))
  local c = ws:contact{y = r.y_mm * 1e-3, z = r.z_mm * 1e-3, roll = r.roll_mrad * 1e-3, yaw = math.rad(r.yaw_deg),
                       V = 100 / 3.6, mu = 0.3, wear = {model = "archard"}}
  for _, side in ipairs{"left", "right"} do
    local t, wear, fy = 0, 0, 0
    for _, p in ipairs(c[side].patches) do
      if p.Tgamma then t, wear = t + p.Tgamma, wear + p.wear_volume * 1e9 end
    end
    local where = ("y = %g mm, yaw %g deg, %s"):format(r.y_mm, r.yaw_deg, side)
    check.ok(t > 0, where .. ": T gamma > 0")
    check.rel(r[side .. "_Tgamma_N"], t, 1e-6, where .. ": T gamma against the contact solved here")
    check.rel(r[side .. "_wear_mm3_per_m"], wear, 1e-6, where .. ": wear volume against the contact solved here")
    check.rel(r[side .. "_creep_Fy_kN"], c[side].creep_force.y / 1e3, 1e-6, where .. ": lateral creep force")
  end
end
local plain = run({}, "plain")
local none = true
for _, c in ipairs(plain) do none = none and not c:match("Tgamma") and not c:match("creep") end
check.ok(none, "without V_kmh: no rolling columns (the paper's study)")
print("paper study with rolling ok")
