-- The merge angle's default depends on the surface (ContactOptions::merge_angle, merge_angle_of in
-- wheelset/contact.hpp): 0.26 rad on the plane, where one plane must serve both areas; 1.2 rad on the conformal
-- surface, where the merged area follows the rail's surface. The pose: S1002 on 60E1, left wheel at 30 kN,
-- y = 6.5 mm, yaw 1 deg, where the wheel touches the flange root (28 deg) and the flange flank (70 deg) in two
-- inter-penetration areas whose normals differ by 0.73 rad (the only such pose of a sweep over y = 4-7 mm, yaw 0
-- and 1 deg, 30-200 kN on these profiles). Checked:
-- 1. The defaults as stated (wrc.defaults.wheelset, each surface's wheelset) and the option still honoured.
-- 2. Conformal by default: the two zones are one area (two contact regions), coupled by the half-space; with
--    merge_angle = 0.26 they are two areas, and the planar surface keeps them apart by default.
-- 3. The coupling's direction (a finite-element study of the two bodies, docs/validation.md "Against CONTACT"):
--    each zone's load lowers the other's surface, so at the same total load the lighter zone carries less
--    coupled than apart, and the heavier more.
local check = require "wrc.check"

local wheel = wrc.profile.load(wrc.paths.profiles .. "/s1002.lua")
local rail = wrc.profile.load(wrc.paths.profiles .. "/60e1.lua")
local y, yaw, Fz = 6.5e-3, 0.0175, 30e3

-- 1. Defaults.
check.near(wrc.defaults.wheelset.merge_angle, 1.2, 0, "the default merge angle (conformal surface)")
local function solve(opts)
  opts.wheel, opts.rail, opts.grid = wheel, rail, 0.4e-3
  local ws = wrc.wheelset(opts)
  local w = ws:wheel{side = "left", y = y, yaw = yaw, roll = 0, Fz = Fz}
  return ws:contact{y = y, z = w.z, roll = 0, yaw = yaw}.left, ws, w.z
end
local coupled, ws_c, z_c = solve{}
local apart, ws_a, z_a = solve{merge_angle = 0.26}
local planar, ws_p = solve{surface = "planar"}
check.near(ws_c.params.merge_angle, 1.2, 0, "conformal wheelset: merge_angle 1.2")
check.near(ws_a.params.merge_angle, 0.26, 0, "merge_angle given: honoured")
check.near(ws_p.params.merge_angle, 0.26, 0, "planar wheelset: merge_angle 0.26")

-- 2. Grouping.
check.ok(#apart.patches == 2, ("merge_angle = 0.26: the two zones apart (%d areas)"):format(#apart.patches))
local turn = math.abs(apart.patches[1].angle - apart.patches[2].angle)
print(("apart: areas at %.3f and %.3f rad (%.3f apart), %.2f and %.2f kN"):format(apart.patches[1].angle,
      apart.patches[2].angle, turn, apart.patches[1].normal_force / 1e3, apart.patches[2].normal_force / 1e3))
check.ok(turn > 0.26 and turn < 1.2, "the zones' normals differ by more than the planar and less than the conformal default")
check.ok(#planar.patches == 2, ("planar default: the two zones apart (%d areas)"):format(#planar.patches))
check.ok(#coupled.patches == 1, ("conformal default: the two zones in one area (%d areas)"):format(#coupled.patches))
local area = coupled.patches[1]
check.ok(area.regions == 2, ("the coupled area holds two contact regions (%d)"):format(area.regions))

-- 3. The split: the coupled area's pressure summed over the rows of each zone (the rows split at the unloaded gap
-- between them; each zone's rows turn the pressure along its own normals, so the zones' loads are summed as
-- magnitudes, like the separate areas' normal_force).
local g = area.grid
local zones, current, gap = {}, nil, true
for j = 1, g.ny do
  local row = 0
  for i = 1, g.nx do row = row + area.pressure[j][i] * g.dx * g.dy end
  if row > 0 then
    if gap then current = #zones + 1; zones[current] = {load = 0, angle = 0} end
    zones[current].load = zones[current].load + row
    zones[current].angle = zones[current].angle + row * math.atan(-area.rows.normal_y[j], area.rows.normal_z[j])
    gap = false
  else gap = true end
end
check.ok(#zones == 2, ("the coupled area's rows: two loaded zones (%d)"):format(#zones))
for _, z in ipairs(zones) do z.angle = z.angle / z.load end
local function by_angle(list, angle)
  local best
  for _, z in ipairs(list) do if not best or math.abs(z.angle - angle) < math.abs(best.angle - angle) then best = z end end
  return best
end
local flat_a = apart.patches[1].angle < apart.patches[2].angle and apart.patches[1] or apart.patches[2]
local steep_a = flat_a == apart.patches[1] and apart.patches[2] or apart.patches[1]
local flat_c, steep_c = by_angle(zones, flat_a.angle), by_angle(zones, steep_a.angle)
check.ok(flat_c ~= steep_c, "each zone of the coupled area matches one area apart")
print(("coupled: root %.2f kN (apart %.2f), flank %.2f kN (apart %.2f); Fy %.3f kN (apart %.3f)"):format(
      flat_c.load / 1e3, flat_a.normal_force / 1e3, steep_c.load / 1e3, steep_a.normal_force / 1e3,
      coupled.force.y / 1e3, apart.force.y / 1e3))
-- With friction (xi = 1e-3, mu = 0.3 at the same z), the coupling's effect on the longitudinal creep force (printed).
local function Fx(ws, z) return ws:contact{y = y, z = z, roll = 0, yaw = yaw, creepage = {xi = 1e-3}, mu = 0.3}.left.force.x end
print(("xi = 1e-3, mu = 0.3: Fx %.3f kN coupled (apart %.3f)"):format(Fx(ws_c, z_c) / 1e3, Fx(ws_a, z_a) / 1e3))
local light_c, light_a = flat_c, flat_a
if flat_a.normal_force > steep_a.normal_force then light_c, light_a = steep_c, steep_a end
check.ok(light_c.load < light_a.normal_force, "coupled, the lighter zone carries less than apart")
check.near(coupled.force.z, apart.force.z, 1e-6 * Fz, "the same vertical load")

-- 4. An angle between normals is at most pi: a larger merge_angle is refused, naming the value in radians if it was
-- meant in degrees; a negative one too.
local function with(angle) return function() wrc.wheelset{wheel = wheel, rail = rail, merge_angle = angle} end end
check.fails(with(40), "merge_angle = 40 must be in [0, pi] rad (the angle between two contact normals); 40 degrees would be 0.6981 rad", "merge_angle in degrees")
check.fails(with(-0.1), "merge_angle = -0.1 must be in [0, pi] rad", "a negative merge_angle")
check.ok(pcall(with(math.pi)), "merge_angle = pi: every area merged, accepted")
