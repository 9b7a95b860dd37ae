-- Equivalent conicity through Lua (issue 11): wrc.conicity on tables, ws:conicity on wheelsets.
--  - a coned wheel (1:20) on 60E1 without cant, roll fixed: the contact stays on the rail where its slope is 1:20, so
--    Δr = 2 gamma y exactly and tan(gamma_e) = 0.05 at every amplitude. With the roll free the wheelset rolls by
--    phi = Δr / (2 e) (2 e: the distance of the contact points); the rolled cone touches the rail where its slope is
--    gamma -+ phi, R phi farther along the rail's R = 80 mm arc, and the contact point sits r0 phi farther along the
--    wheel in the wheelset frame: Δr = 2 gamma (y + (r0 + R) phi), i.e. tan(gamma_e) = gamma / (1 - 2 gamma (r0 + R) /
--    (2 e)) to first order in phi;
--  - ws:conicity gives what wrc.conicity gives on the wheelset's own Δr table (returned with the result);
--  - S1002 / 60E1: flange contact inside the amplitude is an error; the default roll is "fixed";
--  - bad tables reach Lua as errors naming what is wrong.
local check = require "wrc.check"

local rail = wrc.profile.load("profiles/60e1.lua")
local cy, cz = {}, {}
for s = -30, 40, 0.1 do cy[#cy + 1], cz[#cz + 1] = s * 1e-3, s * 1e-3 / 20 end
local cone = wrc.profile.points{kind = "wheel", name = "cone 1:20", y = cy, z = cz}
local wc = wrc.wheelset{wheel = cone, rail = rail, cant = 0}
local yhat = {0.5e-3, 1e-3, 2e-3, 3e-3, 5e-3}
for _, method in ipairs{"integral", "harmonic", "regression", "simple"} do
  local t, d = wc:conicity{yhat = yhat, method = method}
  check.ok(d.roll_mode == "fixed" and d.method == method, "ws:conicity defaults to roll = \"fixed\"")
  for k = 1, #yhat do check.near(t[k], 0.05, 2e-5, ("cone 1:20, %s, yhat = %g mm"):format(method, yhat[k] * 1e3)) end
end
local tf = wc:conicity{yhat = yhat, roll = "free"}
local centred = wc:rigid{y = 0}
local two_e = centred.left.contacts[1].point.y - centred.right.contacts[1].point.y
check.rel(centred.left.contacts[1].rail_lateral_radius, 0.080, 1e-3, "the cone touches the rail on its R80 arc")
local expected = 0.05 / (1 - 2 * 0.05 * (0.45 + 0.080) / two_e)
for k = 1, #yhat do check.rel(tf[k], expected, 1e-3, ("cone 1:20 with the roll free, yhat = %g mm"):format(yhat[k] * 1e3)) end
-- The same cone on 60E1 at the default cant 1:40 touches where the head's slope is 1:40, on its R300 crown (within
-- 10 mm of the top): the same estimate with R = 300 mm, a larger rise (5.2 % against 3.7 %).
local wc40 = wrc.wheelset{wheel = cone, rail = rail}
local c40 = wc40:rigid{y = 0}
local two_e40 = c40.left.contacts[1].point.y - c40.right.contacts[1].point.y
check.rel(c40.left.contacts[1].rail_lateral_radius, 0.300, 1e-3, "at 1:40 the cone touches the rail on its R300 crown")
check.near(wc40:conicity{yhat = {2e-3}}[1], 0.05, 2e-5, "cone 1:20 at cant 1:40, roll fixed: its slope")
local expected40 = 0.05 / (1 - 2 * 0.05 * (0.45 + 0.300) / two_e40)
check.rel(wc40:conicity{yhat = {2e-3}, roll = "free"}[1], expected40, 2e-3, "cone 1:20 at cant 1:40 with the roll free")

local wheel = wrc.profile.load("profiles/s1002.lua")
local ws = wrc.wheelset{wheel = wheel, rail = rail}
local t, d = ws:conicity{yhat = {1e-3, 2e-3, 3e-3, 4e-3}}
local again = wrc.conicity(d.dr, {yhat = {1e-3, 2e-3, 3e-3, 4e-3}})
for k = 1, 4 do check.near(t[k], again[k], 1e-15, "ws:conicity = wrc.conicity on its Δr table") end
check.near(d.wavelength[3], 2 * math.pi * math.sqrt(0.5 * 1.5 * 0.45 / t[3]), 0.05, "wavelength with r0 and the contact distance")
local free = ws:conicity{yhat = {3e-3}, roll = "free"}
print(("kinematics_conicity: S1002/60E1 1:40 tan(gamma_e) at 1, 2, 3, 4 mm: %.4f %.4f %.4f %.4f (roll fixed), %.4f at 3 mm with roll")
      :format(t[1], t[2], t[3], t[4], free[1]))
check.fails(function() ws:conicity{yhat = {7e-3}} end, "flange contact inside the motion", "yhat reaching the flange")
check.fails(function() ws:conicity{yhat = {3e-3}, y = {from = -2e-3, to = 2e-3, step = 0.1e-3}} end, "leaves the Δr table",
            "a table too short for the amplitude")
check.fails(function() ws:conicity{yhat = {3e-3}, methd = "simple"} end, "did you mean 'method'", "misspelt option")

-- wrc.conicity's own checks, through Lua.
local y, dr = {}, {}
for i = -50, 50 do y[#y + 1], dr[#dr + 1] = i * 0.1e-3, 0.2 * i * 0.1e-3 end
check.near(wrc.conicity({y = y, dr = dr}, {yhat = 2e-3})[1], 0.1, 1e-12, "a single amplitude")
dr[10] = 0 / 0
check.fails(function() wrc.conicity({y = y, dr = dr}, {yhat = 2e-3}) end, "the 10th point is not a finite number", "NaN")
dr[10] = 0.2 * -41 * 0.1e-3
y[5], y[6] = y[6], y[5]
check.fails(function() wrc.conicity({y = y, dr = dr}, {yhat = 2e-3}) end, "y must increase strictly", "unsorted y")
y[5], y[6] = y[6], y[5]
check.fails(function() wrc.conicity({y = y, dr = dr}, {yhat = 6e-3}) end, "leaves the Δr table", "amplitude outside")
check.fails(function() wrc.conicity({y = y, dr = dr}, {yhat = 2e-3, method = "klingel"}) end, "'method' must be one of",
            "unknown method")
local fl = {}
for i = 1, #y do fl[i] = math.abs(y[i]) > 3.9e-3 end
check.fails(function() wrc.conicity({y = y, dr = dr, flange = fl}, {yhat = 4e-3}) end, "flange contact inside the motion",
            "flange contact marked in the table")
