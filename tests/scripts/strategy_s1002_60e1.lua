-- No missed area on S1002 / 60E1: on 2000 random poses (|y| <= 10 mm, |yaw| <= 30 mrad, |roll| <= 10 mrad,
-- penetration 1 um .. 1 mm), every strategy -- run through its Lua `locate` -- finds the same patches and segments
-- (segment ends within 1e-9 m) as brute force (every line against every cone) on the same discretisation.
-- The profiles are sampled at 2 mm here to keep brute force affordable under the sanitizers; the benchmark
-- tests/bench/bench_contact_location.cpp makes the same check at the paper's 0.1 mm. The strategies whose search
-- is brute force itself (brute, uniform, constant_slope) are compared on the first poses only.
local check = require "wrc.check"
local H = dofile(arg[0]:match("(.*/)") .. "geometry_helpers.lua")

local step = 2e-3
local wheel = wrc.profile.load(wrc.paths.profiles .. "/s1002.lua", {step = step})
local rail = wrc.profile.load(wrc.paths.profiles .. "/60e1.lua", {step = step})

-- Strategies grouped by discretisation: one brute-force run per pose and group.
local groups = {
  {coarse = {name = "coarse", step = step, coarse_every = 4}, topology = {name = "topology", step = step},
   composed = {"uniform", "coarse", "topology", step = step, coarse_every = 4},
   uniform = {name = "uniform", step = step}},
  {fast = {name = "fast", step = step, coarse_every = 4}, constant_slope = {name = "constant_slope", step = step}},
}
local all_pairs = {uniform = true, constant_slope = true}
local ws = {}
for g, group in ipairs(groups) do
  ws[g] = {}
  for label, spec in pairs(group) do ws[g][label] = wrc.wheelset{wheel = wheel, rail = rail, strategy = spec} end
end
-- The brute strategy itself (profiles as given).
local brute = wrc.wheelset{wheel = wheel, rail = rail, strategy = "brute"}

local rand = H.rng(2018)
local n, compared, patches, two_patch, fewer_tests = 2000, 0, 0, 0, 0
for k = 1, n do
  local pose = H.random_pose(brute, rand)
  for g, group in ipairs(ws) do
    local ref
    for label, w in pairs(group) do
      if all_pairs[label] and k > 20 then goto next end
      ref = ref or w:locate{y = pose.y, z = pose.z, roll = pose.roll, yaw = pose.yaw, search = "brute"}
      local c = w:locate(pose)
      local diff = H.difference(c, ref)
      if diff then
        error(("pose %d (y = %.9g, z = %.9g, roll = %.9g, yaw = %.9g), strategy %s: %s"):format(
              k, pose.y, pose.z, pose.roll, pose.yaw, label, diff))
      end
      if not all_pairs[label] and c.tests < ref.tests then fewer_tests = fewer_tests + 1 end
      compared = compared + 1
      ::next::
    end
    for _, side in ipairs{"left", "right"} do
      patches = patches + #ref[side].patches
      if #ref[side].patches >= 2 then two_patch = two_patch + 1 end
    end
  end
  if k <= 20 then
    local c = brute:locate(pose)
    check.ok(H.difference(c, brute:locate{y = pose.y, z = pose.z, roll = pose.roll, yaw = pose.yaw, search = "brute"}) == nil,
             "brute strategy = brute search")
  end
end
print(("%d poses, %d strategy results compared with brute force, %d patches, %d sides with two patches"):format(
      n, compared, patches, two_patch))
check.ok(compared == n * 4 + 20 * 2, "every strategy compared on every pose")
check.ok(patches > n, "most poses have contact")
check.ok(fewer_tests > 3 * n, "the pruned strategies test fewer pairs than brute force")
