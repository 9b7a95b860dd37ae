-- What multibody tables carry (issue 27): per contact the equivalent ellipse FASTSIM uses (p.ellipse), Hertz's
-- ellipse from the curvatures at the contact point (p.hertz; a along the track) and Kalker's coefficients for it
-- (p.kalker), on elastic patches, rigid contact points and the geometry tables' columns.
--
-- Hertzian pairs: a cylindrical wheel, and a coned one, on a crowned rail (a circular arc of lateral radius R, cant 0).
-- Relative curvatures: along the track cos(gamma) / r (gamma the contact angle = the cone's, r the wheel's radius
-- there), across 1 / R. The reference is the tests' own Hertz solution (tests/halfspace/hertz_reference.lua: elliptic
-- integrals by the AGM, the axis ratio by bisection); Kalker's coefficients are checked against his table (Kalker
-- 1990, Table E.3 = Johnson, Contact Mechanics, Table 8.1; nu = 0.25, g = a/b = 1: C11 4.12, C22 3.67, C23 1.47,
-- C33 1.19) within its rounding.
local check = require "wrc.check"
local out = require "wrc.output"
local here = arg[0]:match("(.*/)") or "./"
local H = dofile(here .. "../halfspace/hertz_reference.lua")
local P = dofile(here .. "../data/profile/helpers.lua")

local E, nu = 2.1e11, 0.25
local Estar = E / (2 * (1 - nu * nu))
local r0 = 0.45
local line_step = 0.02e-3
local half_width = 0.025
local gauge_depth = 0.2e-3

local function wheelset(w, R, element)
  return P.crown_wheelset(w, P.crowned_rail(R, half_width, line_step), R,
                          {radius = r0, gauge_depth = gauge_depth, E = E, nu = nu, grid = element})
end

-- Kalker's table (3 significant digits): within half a unit of the last digit.
local function within_table(v, t) return math.abs(v - t) <= 0.5 * 10 ^ (math.floor(math.log(t, 10)) - 2) + 1e-9 end
local table_g1 = {C11 = 4.12, C22 = 3.67, C23 = 1.47, C33 = 1.19}

-- The Hertz fields of a contact (rigid point or elastic patch) against the reference for its radius, angle and load.
local function check_hertz(c, R, load, what)
  check.ok(c.hertz ~= nil and c.kalker ~= nil, what .. "has hertz and kalker")
  local A, B = math.cos(c.angle) / (2 * c.rolling_radius), 1 / (2 * R)
  local ref = H.from_force(A, B, Estar, load)
  check.rel(c.hertz.load, load, 1e-12, what .. "the load assumed")
  check.rel(c.hertz.a, ref.a, 1e-3, what .. "hertz.a (along the track)")
  check.rel(c.hertz.b, ref.b, 1e-3, what .. "hertz.b (across)")
  check.rel(c.hertz.p0, ref.p0, 2e-3, what .. "hertz.p0")
  return ref
end

print("contact ellipses: cylinder and cone wheels r0 = 450 mm on crowned rails, E = 210 GPa, nu = 0.25")
print(string.format("%6s %7s %9s %9s %9s %9s %9s %9s", "slope", "R_mm", "a_mm", "b_mm", "ell_a_%", "ell_b_%",
                    "hz_a_%", "hz_b_%"))
for _, case in ipairs{{slope = 0, R = r0}, {slope = 0, R = r0 / 4}, {slope = 0.2, R = 0.08}} do
  local w = P.cone_wheel(case.slope)
  local what = string.format("slope %g, R %g mm: ", case.slope, case.R * 1e3)
  -- Rigid: the touching point's Hertz ellipse for the default load and for a given one.
  local coarse = wheelset(w, case.R, 0.2e-3)
  local rigid = coarse:rigid{y = 0}
  local c = rigid.left.contacts[1]
  check.near(c.angle, math.atan(case.slope), 2e-4, what .. "rigid contact angle = the cone's")
  check.rel(c.rail_lateral_radius, case.R, 1e-3, what .. "rail radius at the touching point")
  check_hertz(c, case.R, 100e3, what .. "rigid, default load: ")
  check_hertz(coarse:rigid{y = 0, hertz_load = 60e3}.left.contacts[1], case.R, 60e3, what .. "rigid, 60 kN: ")
  -- Elastic: a fine grid (the reference's minor semi-axis over 40 elements) at the pose carrying about 100 kN.
  local ref = H.from_force(math.cos(c.angle) / (2 * c.rolling_radius), 1 / (2 * case.R), Estar, 100e3)
  local ws = wheelset(w, case.R, math.min(ref.a, ref.b) / 40)
  local res = ws:contact{z = rigid.z - ref.delta * math.cos(c.angle), grids = false}
  check.ok(#res.left.patches == 1, what .. "one area")
  local p = res.left.patches[1]
  check.near(p.angle, math.atan(case.slope), 1e-3, what .. "elastic contact angle")
  local hz = check_hertz(p, case.R, p.normal_force, what .. "elastic: ")
  check.rel(p.ellipse.a, p.hertz.a, 0.01, what .. "FASTSIM's ellipse a = Hertz's within 1 %")
  check.rel(p.ellipse.b, p.hertz.b, 0.01, what .. "FASTSIM's ellipse b = Hertz's within 1 %")
  if case.slope == 0 and case.R == r0 then  -- a circle: Kalker's table at g = 1 exactly
    for k, v in pairs(table_g1) do
      check.ok(within_table(p.kalker[k], v), what .. "elastic kalker." .. k .. " = Kalker's " .. v)
      check.ok(within_table(c.kalker[k], v), what .. "rigid kalker." .. k .. " = Kalker's " .. v)
    end
  end
  print(string.format("%6g %7.1f %9.4f %9.4f %9.3f %9.3f %9.4f %9.4f", case.slope, case.R * 1e3, p.hertz.a * 1e3,
                      p.hertz.b * 1e3, 100 * (p.ellipse.a / p.hertz.a - 1), 100 * (p.ellipse.b / p.hertz.b - 1),
                      100 * (p.hertz.a / hz.a - 1), 100 * (p.hertz.b / hz.b - 1)))
end

-- A concave pair has no Hertz ellipse: a wheel hollow across (lateral radius 0.3 m) on a rail crown of 0.5 m.
do
  local y, z = {}, {}
  for k = 0, 130 do
    local s = -0.070 + k * 1e-3
    y[#y + 1], z[#z + 1] = s, -(0.3 - math.sqrt(0.3 ^ 2 - (s + 0.005) ^ 2))
  end
  local hollow = wrc.profile.points{kind = "wheel", y = y, z = z, name = "hollow"}
  local c = wheelset(hollow, 0.5, 0.2e-3):rigid{y = 0}.left.contacts[1]
  check.ok(c.wheel_curvature < 0 and c.wheel_curvature + c.rail_curvature < 0, "the hollow pair is concave across")
  check.ok(c.hertz == nil and c.kalker == nil, "a concave pair: no hertz, no kalker")
end

-- Geometry tables: the CSV and the multibody table carry the rows' Hertz ellipses and coefficients.
local dir = (arg.tmp or os.getenv("WRC_TEST_TMP") or "/tmp") .. "/contact_ellipses"
out.mkdir(dir)
local ws = wheelset(P.cone_wheel(0.2), 0.08, 0.2e-3)
local t = ws:geometry_table{y = {from = -1e-3, to = 1e-3, step = 0.5e-3}, hertz_load = 75e3, csv = dir .. "/t.csv",
                            file = dir .. "/t.txt", progress = false}
local _, rows = out.read_csv(dir .. "/t.csv")
local f = assert(io.open(dir .. "/t.txt"))
local data, header = {}, ""
for line in f:lines() do
  if line:sub(1, 1) == "#" then header = header .. line .. "\n"
  else
    local v = {}
    for x in line:gmatch("%S+") do v[#v + 1] = tonumber(x) end
    data[#data + 1] = v
  end
end
f:close()
check.ok(header:find("normal load of 75000 N", 1, true) ~= nil, "the table's header states the load")
check.ok(header:find("aL     Hertz semi-axis along the track", 1, true) ~= nil, "the table's header documents aL")
for i, r in ipairs(t.rows) do
  local L, R = r.left.contacts[1], r.right.contacts[1]
  check.rel(L.hertz.load, 75e3, 1e-12, "table rows: the load given")
  check_hertz(L, 0.08, 75e3, "table row " .. i .. ": ")
  check.rel(rows[i].left_hertz_a_mm, L.hertz.a * 1e3, 1e-9, "CSV hertz a")
  check.rel(rows[i].right_hertz_b_mm, R.hertz.b * 1e3, 1e-9, "CSV hertz b")
  check.rel(rows[i].left_hertz_p0_MPa, L.hertz.p0 * 1e-6, 1e-9, "CSV hertz p0")
  check.rel(rows[i].left_C23, L.kalker.C23, 1e-9, "CSV C23")
  local v = data[i]
  check.ok(#v == 34, "text table: 34 columns")
  check.rel(v[23], L.hertz.a, 1e-12, "text aL")
  check.rel(v[24], R.hertz.a, 1e-12, "text aR")
  check.rel(v[25], L.hertz.b, 1e-12, "text bL")
  check.rel(v[27], L.kalker.C11, 1e-12, "text C11L")
  check.rel(v[34], R.kalker.C33, 1e-12, "text C33R")
end

-- Bad input.
check.fails(function() ws:rigid{y = 0, hertz_load = -1} end, "hertz_load = -1 N must be a positive number",
            "a negative load")
check.fails(function() ws:geometry_table{y = {0}, hertz_load = 0 / 0} end, "hertz_load", "a NaN load")
