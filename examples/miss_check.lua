-- The miss check of a location strategy: random wheelset poses located with the strategy and with brute force
-- (every rail line against every cone of the same discretisation); a difference is an error naming the first pose
-- that differs. The default is the full check of the default strategy on the paper's S1002 / 60E1 track:
--
--   wrc run examples/miss_check.lua [poses=100000] [strategy=accurate] [threads=0] [seed=1]
--                                   [y_mm=10] [yaw_mrad=30] [roll_mrad=10] [progress=true]
--
-- Poses: |y| <= y_mm, |yaw| <= yaw_mrad, |roll| <= roll_mrad, uniform; 1 um .. 1 mm below the height of first
-- touch, log-uniform. Brute force costs ~50 ms per pose at the paper's 0.1 mm: 10^5 poses are ~1.4 h of CPU.
local poses = math.tointeger(tonumber(arg.poses or 100000))
assert(poses and poses >= 1, "miss_check: poses must be a positive integer")
local y, yaw, roll = (arg.y_mm or 10) * 1e-3, (arg.yaw_mrad or 30) * 1e-3, (arg.roll_mrad or 10) * 1e-3

local wheel = wrc.profile.load("profiles/s1002.lua", {step = 0.1e-3})
local rail = wrc.profile.load("profiles/60e1.lua", {step = 0.1e-3})
local ws = wrc.wheelset{wheel = wheel, rail = rail, strategy = arg.strategy or wrc.defaults.wheelset.strategy}

local seed, threads = math.tointeger(tonumber(arg.seed or 1)), math.tointeger(tonumber(arg.threads or 0))
local r = ws:check_strategy{poses = poses, y = {-y, y}, yaw = {-yaw, yaw}, roll = {-roll, roll}, seed = seed,
                            threads = threads, progress = arg.progress and tostring(arg.progress) == "true" or nil}
print(string.format("miss check of strategy '%s' against brute force: %d poses (%d with contact, %d areas), no "
                    .. "difference; %.1f s on %d threads; %.0f closed-form tests per pose (brute force %.0f)",
                    ws.strategy.name, r.poses, r.contact_poses, r.patches, r.seconds, r.threads, r.tests / r.poses,
                    r.brute_tests / r.poses))
return r
