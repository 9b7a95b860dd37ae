-- Strategies beyond the built-in ones: a strategy file written here (no recompilation), inline tables, the
-- composition syntax with options, and the errors a strategy author meets.
local check = require "wrc.check"
local H = dofile(arg[0]:match("(.*/)") .. "geometry_helpers.lua")

local wheel = wrc.profile.load(wrc.paths.profiles .. "/s1002.lua", {step = 1e-3})
local rail = wrc.profile.load(wrc.paths.profiles .. "/60e1.lua", {step = 1e-3})
local tmp = arg.tmp or os.getenv("WRC_TEST_TMP") or "."

-- A user's strategy file: coarse windows, then its own loop over them calling the walk with explicit 1-based
-- windows -- the same result as brute force.
local path = tmp .. "/strategy_custom_user.lua"
local f = assert(io.open(path, "w"))
f:write([[
return {
  description = "user strategy: coarse windows walked one by one from Lua",
  defaults = {step = 1e-3, coarse_every = 4, coarse_wheel_step = 2e-3},
  discretise = function(d, opt)
    d.wheel = d.wheel:resample{step = opt.step}
    d.rail = d.rail:resample{step = opt.step}
    local D = wrc.geometry.cell_dilation(d.rail, opt.coarse_every)
    d.coarse = {every = opt.coarse_every, wheel = wrc.geometry.offset_outward(d.wheel, D, opt.coarse_wheel_step)}
    return d
  end,
  locate = function(ctx, side)
    ctx:coarse(side)
    for _, w in ipairs(ctx:windows(side)) do ctx:walk(side, w[1], w[2], w[3], w[4]) end
  end,
}
]])
f:close()
local user = wrc.wheelset{wheel = wheel, rail = rail, strategy = path}
check.ok(user.strategy.portable, "a strategy chosen by file is portable to worker threads")
check.ok(user:coarse("left") ~= nil, "the user strategy built a coarse level")
-- Its default step (1 mm) is coarser than the wheelset's grid (0.2 mm, the default): the step follows the grid, as
-- the built-in strategies' does (docs/guide/location.md); a step given is kept.
check.ok(user.strategy.options.step == 0.2e-3, "a default step coarser than the grid follows the grid")
local given = wrc.wheelset{wheel = wheel, rail = rail, strategy = {name = path, step = 1e-3}}
check.ok(given.strategy.options.step == 1e-3, "a step given is kept")
check.ok(given:lines("left").count < user:lines("left").count, "the step given discretises more coarsely")

-- Inline table: runs in this state only.
local calls = 0
local inline = wrc.wheelset{wheel = wheel, rail = rail, strategy = {
  discretise = function(d) return d end,
  locate = function(ctx, side) calls = calls + 1; ctx:walk(side) end,
}}
check.ok(inline.strategy.portable == false, "an inline strategy is not portable")
check.ok(inline.strategy.name == "(inline)", "inline strategy name")

-- Composition with options, by list.
local composed = wrc.wheelset{wheel = wheel, rail = rail,
                              strategy = {"constant_slope", "coarse", "topology", step = 1e-3, slope_step = 0.02,
                                          coarse_every = 6}}
check.ok(composed.strategy.name == "constant_slope+coarse+topology", "composition name")
check.near(composed.strategy.options.slope_step, 0.02, 0, "composition option")
check.near(composed:coarse("left").every, 6, 0, "coarse_every reaches the model")

local rand = H.rng(7)
for k = 1, 60 do
  local pose = H.random_pose(user, rand)
  for label, ws in pairs{user = user, inline = inline, composed = composed} do
    local ref = ws:locate{y = pose.y, z = pose.z, roll = pose.roll, yaw = pose.yaw, search = "brute"}
    local diff = H.difference(ws:locate(pose), ref)
    if diff then error(("pose %d, %s: %s"):format(k, label, diff)) end
  end
end
check.ok(calls == 2 * 60, "the inline locate ran once per side and pose")

-- Errors a strategy author meets.
check.fails(function() wrc.wheelset{wheel = wheel, rail = rail, strategy = "nosuch"} end,
            "unknown strategy 'nosuch'", "unknown strategy name")
check.fails(function() wrc.wheelset{wheel = wheel, rail = rail, strategy = {name = "uniform", stpe = 1e-3}} end,
            "strategy option 'stpe' is not used by uniform", "misspelt option")
check.fails(function() wrc.wheelset{wheel = wheel, rail = rail, strategy = 42} end,
            "strategy must be a name", "strategy of the wrong type")
check.fails(function() wrc.wheelset{wheel = wheel, rail = rail, strategy = {locate = 1}} end,
            "locate must be a function", "inline locate not a function")
check.fails(function()
  wrc.wheelset{wheel = wheel, rail = rail, strategy = {locate = function() end, discretise = function() return 1 end}}
end, "must return a table", "discretise returning a number")
check.fails(function()
  wrc.wheelset{wheel = wheel, rail = rail, strategy = {locate = function() end,
    discretise = function(d) d.coarse = {every = 4, wheel = d.wheel}; return d end}}
end, "does not contain the fine wheel dilated", "a coarse wheel that is not offset outward")
-- A window that cuts segments: with yaw a segment's ends are on different cones; test only up to the first.
local saved, cut
local bad = wrc.wheelset{wheel = wheel, rail = rail, strategy = {locate = function(ctx, side)
  saved = ctx
  if cut then ctx:test(side, 1, ctx:lines(side), 1, cut) else ctx:test(side) end
end}}
local yawed = {y = 0, z = -1e-3, roll = 0, yaw = 0.02}
for _, p in ipairs(bad:locate(yawed).left.patches) do
  for _, s in ipairs(p.segments) do
    if s.cones[1] ~= s.cones[2] then cut = math.min(s.cones[1], s.cones[2]) end
  end
end
check.ok(cut ~= nil, "a yawed segment spans two cones")
check.fails(function() bad:locate(yawed) end, "odd number", "a window that cuts segments")
check.fails(function() saved:walk("left") end, "only valid during the strategy's locate call", "ctx kept after locate")
local bad2 = wrc.wheelset{wheel = wheel, rail = rail, strategy = {locate = function(ctx, side) ctx:test(side, 1, 1e6, 1, 2) end}}
check.fails(function() bad2:locate{y = 0, z = -1e-4} end, "is outside the left side", "window out of range")
local bad3 = wrc.wheelset{wheel = wheel, rail = rail, strategy = {locate = function(ctx, side) ctx:coarse(side) end}}
check.fails(function() bad3:locate{y = 0, z = -1e-4} end, "no coarse level", "coarse without a coarse level")
local bad4 = wrc.wheelset{wheel = wheel, rail = rail, strategy = {locate = function(ctx, side) ctx:walk("middle") end}}
check.fails(function() bad4:locate{y = 0, z = -1e-4} end, "side must be \"left\" or \"right\"", "bad side name")
local bad5 = wrc.wheelset{wheel = wheel, rail = rail, strategy = {locate = function() error("boom") end}}
check.fails(function() bad5:locate{y = 0, z = -1e-4} end, "boom", "an error inside locate reaches the caller")
os.remove(path)
