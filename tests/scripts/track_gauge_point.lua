-- The gauge point rule (issue 11): gauge_depth below the rail's highest point as it lies in the track, walking toward
-- the gauge side; gauge_point = "first" (default: the first crossing of that level) or "innermost" (EN 13848-1's
-- band: the innermost gauge-face point down to gauge_depth). A rail whose gauge face crosses the 14 mm level three
-- times (a lip: down to 15 mm at y = -34, back up to 13 mm at -35, down again) separates them; the crossings are
-- computed here from the polyline: first at y = -30 - 4 (4/5) = -33.2 mm, innermost at -35 - 1/7 mm.
local check = require "wrc.check"

local wheel = wrc.profile.load("profiles/s1002.lua")
local mm = 1e-3
local lip = wrc.profile.points{kind = "rail", name = "lipped", y = {-36 * mm, -35 * mm, -34 * mm, -30 * mm, 0, 30 * mm, 36 * mm},
                               z = {-20 * mm, -13 * mm, -15 * mm, -10 * mm, 0, -10 * mm, -20 * mm}}
local function top_y(ws)  -- the placed left rail's highest point
  local r, k = ws.left_rail, 1
  for i = 2, #r.z do if r.z[i] > r.z[k] then k = i end end
  return r.y[k]
end
local a = wrc.wheelset{wheel = wheel, rail = lip, cant = 0}
local b = wrc.wheelset{wheel = wheel, rail = lip, cant = 0, gauge_point = "innermost"}
check.ok(a.params.gauge_point == "first" and b.params.gauge_point == "innermost", "ws.params.gauge_point")
check.near(a.gauge_points.left.y, 0.7175, 1e-15, "the gauge point sits at gauge / 2")
check.near(top_y(a) - 0.7175, 33.2 * mm, 1e-12, "first: the first crossing of the 14 mm level")
check.near(top_y(b) - 0.7175, (35 + 1 / 7) * mm, 1e-12, "innermost: the innermost point of the 0 .. 14 mm band")
-- On a new 60E1 the two rules agree (one crossing).
local rail = wrc.profile.load("profiles/60e1.lua")
local c, d = wrc.wheelset{wheel = wheel, rail = rail}, wrc.wheelset{wheel = wheel, rail = rail, gauge_point = "innermost"}
check.near(top_y(c), top_y(d), 1e-15, "60E1: both rules give the same gauge point")
check.fails(function() wrc.wheelset{wheel = wheel, rail = rail, gauge_point = "lowest"} end, "'gauge_point' must be one of",
            "an unknown rule")

-- At cant 1:20 the 60E1's 1:20 gauge-side flank turns vertical: it is accepted (a rounding lean is no overhang).
local steep = wrc.wheelset{wheel = wheel, rail = rail, cant = 1 / 20}
check.near(steep.gauge_points.left.y, 0.7175, 1e-15, "60E1 at 1:20")
check.ok(steep:rigid{y = 0}.converged, "60E1 at 1:20: a rigid contact")
