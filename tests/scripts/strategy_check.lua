-- The opt-in cross check of a strategy against brute force (issue 14): a user strategy with an off-by-one error
-- (each coarse window walked without its first and last rail line) misses parts of contact areas silently -- the
-- forces come out low -- and ws:check_strategy / wrc.wheelset{check_strategy = N} name the first pose that differs
-- and the rail line it misses; correct strategies pass; the first pose is the same on 1 and 2 threads. A small
-- sample of the 10^5-pose miss check of the default strategy (examples/miss_check.lua) runs here too.
local check = require "wrc.check"

local wheel = wrc.profile.load(wrc.paths.profiles .. "/s1002.lua", {step = 0.5e-3})
local rail = wrc.profile.load(wrc.paths.profiles .. "/60e1.lua", {step = 0.5e-3})
local tmp = arg.tmp or os.getenv("WRC_TEST_TMP") or "."

local path = tmp .. "/strategy_check_off_by_one.lua"
local f = assert(io.open(path, "w"))
f:write([[
return {
  description = "coarse windows walked without their first and last line (an off-by-one error)",
  defaults = {step = 0.5e-3, coarse_every = 4, coarse_wheel_step = 2e-3},
  discretise = function(d, opt)
    d.wheel = d.wheel:resample{step = opt.step}
    d.rail = d.rail:resample{step = opt.step}
    local D = wrc.geometry.cell_dilation(d.rail, opt.coarse_every)
    d.coarse = {every = opt.coarse_every, wheel = wrc.geometry.offset_outward(d.wheel, D, opt.coarse_wheel_step)}
    return d
  end,
  locate = function(ctx, side)
    ctx:coarse(side)
    for _, w in ipairs(ctx:windows(side)) do
      if w[2] - 1 >= w[1] + 1 then ctx:walk(side, w[1] + 1, w[2] - 1, w[3], w[4]) end
    end
  end,
}
]])
f:close()

local bad = wrc.wheelset{wheel = wheel, rail = rail, strategy = path, grid = 0.5e-3}
local good = wrc.wheelset{wheel = wheel, rail = rail, strategy = {"uniform", "coarse", "topology", step = 0.5e-3},
                          grid = 0.5e-3}

-- Silent today: the wrong strategy gives a result, with less force at the same pose.
local pose = {y = 3e-3, z = -0.1e-3, roll = 0, yaw = 0}
local fb, fg = bad:contact(pose).force.z, good:contact(pose).force.z
check.ok(fb < 0.99 * fg, string.format("the off-by-one strategy loses force silently (%.1f vs %.1f kN)", fb / 1e3, fg / 1e3))

-- The check names it.
local err = check.fails(function() bad:check_strategy{poses = 40, y = {-8e-3, 8e-3}, yaw = {0, 0.0175}} end,
                        "differs from brute force on the same discretisation at pose", "the off-by-one strategy")
check.ok(err:find("misses rail line", 1, true), "the message names the line missed: " .. err)
local first = err:match("at pose (%d+) of 40")
check.ok(first, "the message names the pose number")
local err2 = check.fails(function() bad:check_strategy{poses = 40, y = {-8e-3, 8e-3}, yaw = {0, 0.0175}, threads = 2} end,
                         "differs", "the same check on two threads")
check.ok(err2:match("at pose (%d+) of 40") == first, "the first pose in drawing order on any thread count")
check.fails(function() wrc.wheelset{wheel = wheel, rail = rail, strategy = path, check_strategy = 40} end,
            "differs from brute force", "wrc.wheelset{check_strategy = N}")

-- An inline (non-portable) strategy with the same error is checked in this Lua state.
local inline_bad = wrc.wheelset{wheel = wheel, rail = rail, strategy = {
  locate = function(ctx, side)
    ctx:coarse(side)
    for _, w in ipairs(ctx:windows(side)) do
      if w[2] - 1 >= w[1] + 1 then ctx:walk(side, w[1] + 1, w[2] - 1, w[3], w[4]) end
    end
  end,
  discretise = function(d)
    d.coarse = {every = 4, wheel = wrc.geometry.offset_outward(d.wheel, wrc.geometry.cell_dilation(d.rail, 4), 2e-3)}
    return d
  end}}
err = check.fails(function() inline_bad:check_strategy{poses = 20} end, "differs from brute force", "an inline strategy")
check.ok(err:find("misses rail line", 1, true), "the inline strategy misses a line: " .. err)

-- Correct strategies pass; every pose is in contact (1 um .. 1 mm below first touch).
local r = good:check_strategy{poses = 40, y = {-8e-3, 8e-3}, yaw = {0, 0.0175}}
check.ok(r.poses == 40 and r.contact_poses == 40, "the good strategy: 40 poses, all in contact")
check.ok(r.brute_tests > 100 * r.tests, "brute force runs every pair")
local with = wrc.wheelset{wheel = wheel, rail = rail, strategy = {"uniform", "coarse", "topology", step = 0.5e-3},
                          grid = 0.5e-3, check_strategy = 10}
check.ok(with.strategy_check.poses == 10 and with.params.check_strategy == 10, "wrc.wheelset{check_strategy = 10}")
check.ok(good.strategy_check == nil, "no check unless asked")
check.fails(function() good:check_strategy{poses = 5, y = {1, 2}} end, "'y'", "a range out of bounds")
check.fails(function() good:check_strategy{poses = 5, yaw = {0.01}} end, "two numbers", "a range of one number")
check.fails(function() good:check_strategy{poses = 5, pose = 3} end, "unknown key 'pose'", "a misspelt key")

-- A sample of the full miss check of the default strategy at the paper's 0.1 mm.
arg.poses = 12
local m = dofile(wrc.paths.root .. "/examples/miss_check.lua")
check.ok(m.poses == 12 and m.contact_poses == 12, "the miss check's sample")
