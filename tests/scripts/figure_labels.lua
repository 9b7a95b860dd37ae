-- The paper study's pressure figures say where they are (issue 28): a pressure map (fig6, fig7) names which side of
-- the rail its vertical axis points to, gauge or field, and fig8 names the frame of its axes (the track frame, whose
-- z is about r0 below 0 on the rail). Checked on both wheels, planar and conformal areas: the side is computed here
-- from each area's grid (its first and last rows placed in the track frame) and the wheel (the field side is +y on
-- the left rail, -y on the right).
local check = require "wrc.check"
local sweep = require "wrc.sweep"

local wheel = wrc.profile.load(wrc.paths.profiles .. "/s1002.lua")
local rail = wrc.profile.load(wrc.paths.profiles .. "/60e1.lua")
local dir = (arg.tmp or "/tmp") .. "/figure_labels"
wrc.fs.mkdir(dir)

local function ylabel(file)
  local gp = assert(io.open(file)):read("a")
  return gp:match("set ylabel '([^\n]*)'\n"), gp
end

for _, surface in ipairs{"planar", "conformal"} do
  local ws = wrc.wheelset{wheel = wheel, rail = rail, grid = 0.5e-3, surface = surface}
  for _, y in ipairs{6.3e-3, -6.3e-3, 0} do
    local e = ws:equilibrium{y = y, Q = 200e3}
    local tag = ("%s_y%.1f"):format(surface, y * 1e3)
    sweep.plot_patches(dir, tag, e)
    for _, side in ipairs{"left", "right"} do
      for k, p in ipairs(e[side].patches) do
        -- Track-frame y of the grid's first and last rows (v = y0 and y0 + (ny - 1) dy along t2; on a conformal area
        -- the rows' own points).
        local first, last
        if p.rows then
          first, last = p.rows.y[1], p.rows.y[#p.rows.y]
        else
          local g, o, t2 = p.grid, p.frame.origin, p.frame.t2
          first, last = o.y + g.y0 * t2.y, o.y + (g.y0 + (g.ny - 1) * g.dy) * t2.y
        end
        local outward = (last - first) * (side == "left" and 1 or -1) > 0
        local label = ylabel(("%s/fig6_pressure_%s_%s%d.gp"):format(dir, tag, side, k))
        local expected = outward and "field side up, gauge side down" or "gauge side up, field side down"
        check.ok(label and label:find(expected, 1, true), ("%s %s wheel area %d: '%s', expected '%s'"):format(
                 tag, side, k, tostring(label), expected))
        check.ok(ylabel(("%s/fig7_h_%s_%s%d.gp"):format(dir, tag, side, k)) == label, "fig7 says the same")
      end
    end
    if y > 0 then
      sweep.plot_rail_pressure(dir, "fig8_" .. tag, "test", e)
      local _, gp = ylabel(("%s/fig8_%s_rail_pressure.gp"):format(dir, tag))
      check.ok(gp:find("track frame: origin at the centred wheelset''s centre, y toward the left rail, z up", 1, true),
               "fig8's caption names the frame")
      check.ok(gp:find("set zlabel 'z, track frame (mm", 1, true), "fig8's z axis says its frame")
      local f = assert(io.open(("%s/fig8_%s_rail_pressure.dat"):format(dir, tag)))
      local z = tonumber(f:read("l"):match("^%S+ %S+ (%S+)"))
      f:close()
      check.near(z, -450, 40, "fig8's z is the track frame's (mm): the rail surface about r0 below the origin")
    end
  end
end
print("figure labels: gauge and field sides of the pressure maps, fig8's frame")
