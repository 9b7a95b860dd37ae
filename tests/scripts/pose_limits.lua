-- The limits of the wheelset's lateral displacement (|y| <= 0.1 m), yaw (|yaw| <= 0.3 rad) and roll (|roll| <= 0.1
-- rad) are one definition (kMaxLateral, kMaxYaw, kMaxRoll in geometry/pose.hpp), held by every call that takes a pose:
-- each refuses a value just beyond the limit the guide gives (docs/guide/equilibrium.md) with the same words and its
-- own name in front, and none refuses the limit itself. A call whose copy of the limit drifted would break one of these.
local check = require "wrc.check"

local wheel = wrc.profile.load(wrc.paths.profiles .. "/s1002.lua")
local rail = wrc.profile.load(wrc.paths.profiles .. "/60e1.lua")
local ws = wrc.wheelset{wheel = wheel, rail = rail, grid = 1e-3}

local tr = ws:trajectory{}
local limit = {y = 0.1, yaw = 0.3, roll = 0.1}
local words = {y = "must be finite and within +-0.1 m", yaw = "must be finite and within +-0.3 rad",
               roll = "must be finite and within +-0.1 rad"}

-- Each call with y (or yaw) at `v`; `context` is the name its message starts with.
local calls = {
  {context = "equilibrium: ", y = function(v) return ws:equilibrium{y = v, Q = 200e3} end,
   yaw = function(v) return ws:equilibrium{y = 0, yaw = v, Q = 200e3} end},
  {context = "wheel: ", y = function(v) return ws:wheel{side = "left", y = v, Fz = 100e3} end,
   yaw = function(v) return ws:wheel{side = "left", y = 0, yaw = v, Fz = 100e3} end,
   roll = function(v) return ws:wheel{side = "left", y = 0, roll = v, Fz = 100e3} end},
  {context = "wheel: ", y = function(v) return tr:wheel{side = "left", y = v, Fz = 100e3} end,
   yaw = function(v) return tr:wheel{side = "left", y = 0, yaw = v, Fz = 100e3} end,
   roll = function(v) return tr:wheel{side = "left", y = 0, roll = v, Fz = 100e3} end},
  {context = "rigid contact: ", y = function(v) return ws:rigid{y = v} end,
   yaw = function(v) return ws:rigid{y = 0, yaw = v} end, roll = function(v) return ws:rigid{y = 0, roll = v} end},
  {context = "wheelset:contact: ", y = function(v) return ws:contact{y = v, z = -1e-4} end,
   yaw = function(v) return ws:contact{y = 0, z = -1e-4, yaw = v} end,
   roll = function(v) return ws:contact{y = 0, z = -1e-4, roll = v} end},
  {context = "wheelset:locate: ", y = function(v) return ws:locate{y = v, z = -1e-4} end,
   yaw = function(v) return ws:locate{y = 0, z = -1e-4, yaw = v} end,
   roll = function(v) return ws:locate{y = 0, z = -1e-4, roll = v} end},
  {context = "trajectory:contact: ", y = function(v) return tr:contact{y = v, z = -1e-4} end,
   yaw = function(v) return tr:contact{y = 0, z = -1e-4, yaw = v} end,
   roll = function(v) return tr:contact{y = 0, z = -1e-4, roll = v} end},
  {context = "geometry table: the 2nd value of y: ",
   y = function(v) return ws:geometry_table{y = {0, v}, progress = false} end},
  {context = "sweep: the 2nd value of y: ", y = function(v) return ws:sweep{y = {0, v}, Q = 200e3, progress = false} end,
   yaw = function(v) return ws:sweep{y = {0}, yaw = {0, v}, Q = 200e3, progress = false} end,
   yaw_context = "sweep: the 2nd value of yaw: "},
  {context = "wrc.conicity: Δr table: the 1st value of y: ",
   y = function(v) return wrc.conicity({y = {-v, 0, v}, dr = {-1e-3, 0, 1e-3}}, {yhat = 3e-3}) end},
}

for _, c in ipairs(calls) do
  for _, key in ipairs{"y", "yaw", "roll"} do
    local f = c[key]
    if f then
      local context = c[key .. "_context"] or c.context
      for _, sign in ipairs{1, -1} do
        local err = check.fails(function() f(sign * limit[key] * (1 + 1e-9)) end, words[key],
                                context .. key .. " beyond its limit")
        check.ok(err:find(context .. key .. " = ", 1, true), "the message names the call: " .. err)
      end
      -- At the limit itself: no refusal of the value (a pose there may fail for want of contact, not for its range).
      local ok, err = pcall(f, limit[key])
      check.ok(ok or not tostring(err):find("must be finite and within", 1, true),
               context .. key .. " at its limit is not refused: " .. tostring(err))
    end
  end
end

-- The strategy check draws its poses within the same limits.
check.fails(function() ws:check_strategy{poses = 1, roll = {0, limit.roll * (1 + 1e-9)}} end,
            "within [-0.1, 0.1]", "check_strategy: roll beyond its limit")
