-- The Lua side of tests/matlab/test_lua_reference.m: the same calls as the test makes through the MEX file, printed
-- as "name value" lines with 17 significant digits (a double's exact text), for the test to compare bit for bit.
-- (A creepage of 1e-3 / 3 needs all 17 digits on its way through the option text.)
local function out(name, v) print(("%s %.17g"):format(name, v)) end

local wheel = wrc.profile.load("profiles/s1002.lua")
local rail = wrc.profile.load("profiles/60e1.lua")
local ws = wrc.wheelset{wheel = wheel, rail = rail, gauge = 1.435, cant = 0.025, radius = 0.45}

local e = ws:equilibrium{y = 3e-3, yaw = 0, Q = 200e3}
out("equilibrium.Y_Q", e.Y_Q); out("equilibrium.z", e.z); out("equilibrium.roll", e.roll)
out("equilibrium.left.force.z", e.left.force.z); out("equilibrium.patches", #e.left.patches)
out("equilibrium.left.patches.1.pmax", e.left.patches[1].pmax)

local c = ws:contact{y = 2e-3, z = e.z, roll = e.roll, yaw = 2e-3}
local p = c.left.patches[1]
out("contact.force.y", c.force.y); out("contact.force.z", c.force.z)
out("contact.nx", p.grid.nx); out("contact.ny", p.grid.ny)
-- Three elements of the pressure grid, (j, i) = (row along y, column along x): the centre and two off it.
local j, i = (p.grid.ny + 1) // 2, (p.grid.nx + 1) // 2
out("contact.p_centre", p.pressure[j][i]); out("contact.p_j1", p.pressure[j + 1][i]);
out("contact.p_i3", p.pressure[j][i + 3])

local r = ws:contact{y = 2e-3, z = e.z, roll = e.roll, yaw = 0, V = 30, creepage = {xi = 1e-3 / 3}, mu = 0.3}
out("rolling.force.x", r.force.x); out("rolling.left.patches.1.Fx", r.left.patches[1].Fx)

local w = ws:wheel{side = "right", y = 3e-3, yaw = 0, roll = 0, Fz = 100e3}
out("wheel.force.y", w.force.y); out("wheel.force.z", w.force.z)

local g = ws:rigid{y = 3e-3, yaw = 0}
out("rigid.z", g.z); out("rigid.roll", g.roll); out("rigid.dr", g.rolling_radius_difference)
out("rigid.left.rolling_radius", g.left.rolling_radius)

local t = ws:conicity{yhat = {1e-3, 3e-3}}
out("ws_conicity.1", t[1]); out("ws_conicity.2", t[2])

local y, dr = {}, {}
for k = -100, 100 do y[#y + 1] = k * 1e-4; dr[#dr + 1] = 0.1 * y[#y] + 300 * y[#y] ^ 3 end
local tc = wrc.conicity({y = y, dr = dr}, {yhat = {2e-3, 5e-3}, method = "harmonic"})
out("conicity.1", tc[1]); out("conicity.2", tc[2])

local m = wheel:flange_measures()
out("flange.Sh", m.Sh); out("flange.Sd", m.Sd); out("flange.qR", m.qR)

local gt = ws:geometry_table{y = {from = -5e-3, to = 5e-3, step = 1e-3}, roll = "fixed", threads = 1}
out("table.rows", #gt.rows); out("table.rows.4.dr", gt.rows[4].rolling_radius_difference)

local tr = ws:trajectory{tolerance = 1e-6}
tr:contact{y = 1e-3, z = e.z, roll = e.roll, yaw = 0}
local s2 = tr:contact{y = 1.1e-3, z = e.z, roll = e.roll, yaw = 0}
out("trajectory.force.z", s2.force.z)
