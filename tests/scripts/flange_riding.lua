-- A wheel riding on its flange (issue 28): at y = 20 mm the left wheel of the paper's wheelset touches its rail with
-- its flange about 20.4 mm above the centred height, beyond the +-20 mm that the searches used to cover, so that
-- ws:rigid{roll = "fixed"} reported it lifted and converged and ws:wheel failed. The searches now reach as far as the
-- profiles do, and rigid results carry flange_climb as the elastic ones do (the same definition).
--
-- References, independent of the solver: at yaw = roll = 0 a rail line (y_l, z_l) (ws:lines, wheelset-centre frame at
-- z = 0) touches the wheel above it when the centre is at z = z_l + R(y_l - y), R the radius of the discretised wheel
-- (ws:cones) there, so the wheel's touching height is the largest of these over the lines (brute force). The flange's
-- steepest part is found from the profile's points.
local check = require "wrc.check"
local H = dofile(os.getenv("WRC_TEST_DATA") .. "/profile/helpers.lua")

local wheel = wrc.profile.load(wrc.paths.profiles .. "/s1002.lua")
local rail = wrc.profile.load(wrc.paths.profiles .. "/60e1.lua")
local ws = wrc.wheelset{wheel = wheel, rail = rail, grid = 0.5e-3}

local function touch_height(side, y)
  local c, l = ws:cones(side), ws:lines(side)
  local best = -math.huge
  for r = 1, #l.y do
    local Y = l.y[r] - y
    for k = 2, #c.y - 2 do
      local ya, yb = c.y[k], c.y[k + 1]
      if ya ~= yb and Y >= math.min(ya, yb) and Y <= math.max(ya, yb) then
        local R = -(c.z[k] + (Y - ya) / (yb - ya) * (c.z[k + 1] - c.z[k]))
        best = math.max(best, l.z[r] + R)
      end
    end
  end
  return best
end

-- The steepest part of the S1002 flange face: its tip-side end (slopes within 1 deg of the steepest).
local steepest, steep_y = H.steepest_flange(wheel)

local y = 20e-3
local zl, zr = touch_height("left", y), touch_height("right", y)
check.ok(zl > 20e-3, ("at y = 20 mm the left wheel touches at z = %.3f mm, beyond the old +-20 mm"):format(zl * 1e3))

-- Roll fixed: each wheel lowered onto its rail; the wheelset rests on the higher, the left flange.
local g = ws:rigid{y = y, roll = "fixed"}
check.ok(g.converged and not g.left.lifted and not g.right.lifted, "roll fixed: both wheels found")
check.near(g.left.z, zl, 1e-9, "roll fixed: the left wheel's touching height (brute force)")
check.near(g.right.z, zr, 1e-9, "roll fixed: the right wheel's touching height (brute force)")
check.near(g.z, zl, 1e-9, "roll fixed: the wheelset rests on its left flange")
check.near(g.right.gap, zl - zr, 1e-9, "roll fixed: the right wheel's clearance")
local yp = g.left.contacts[1].wheel_profile.y
check.ok(yp < steep_y, ("the contact at %.2f mm lies beyond the steepest part (from %.2f mm)"):format(yp * 1e3, steep_y * 1e3))
check.ok(g.flange_climb == true and g.left.flange_climb == true and g.right.flange_climb == false, "roll fixed: flagged")
check.ok(g.flange_climb_reason:find("left wheel: contact at", 1, true) and
         g.flange_climb_reason:find("beyond the steepest part", 1, true), g.flange_climb_reason)

-- Roll free: both wheels touch, the left on its flange (the case that converged unflagged with Y/Q 0.17).
local f = ws:rigid{y = y}
check.ok(f.converged and f.left.contacts[1].wheel_profile.y < steep_y, "roll free: the left contact is on the flange tip")
check.ok(f.flange_climb == true and f.left.flange_climb == true, "roll free: flagged, " .. tostring(f.flange_climb_reason))

-- The paper's range on the tread is not flagged: the contact stays off the flange's upper part there.
for _, yy in ipairs{0, 2e-3, 4e-3, -4e-3} do
  local r = ws:rigid{y = yy}
  check.ok(r.converged and r.flange_climb == false, ("y = %.0f mm: not flagged"):format(yy * 1e3))
  check.ok(r.left.contacts[1].wheel_profile.y >= steep_y and r.right.contacts[1].wheel_profile.y >= steep_y,
           "and its contacts are off the flange's upper part")
end

-- ws:wheel at y = 20 mm: the left wheel pressed onto its flange from the height at which it touches.
local w = ws:wheel{side = "left", y = y, Fz = 100e3}
check.ok(w.converged, "ws:wheel at y = 20 mm converges: " .. tostring(w.error))
check.near(w.z + w.approach, zl, 1e-9, "ws:wheel: touching height + approach (brute force)")
check.near(w.force.z, 100e3, 1e-4 * 100e3, "ws:wheel: the vertical force")
check.ok(w.flange_climb == true, "ws:wheel: flagged, " .. tostring(w.flange_climb_reason))

-- Farther out, the flange tip lands on the rail's field side (90 mm: 25 mm up), as the brute force finds.
local far = ws:rigid{y = 0.09, roll = "fixed"}
check.ok(far.converged and not far.left.lifted, "y = 90 mm: the left wheel touches")
check.near(far.left.z, touch_height("left", 0.09), 1e-9, "y = 90 mm: the touching height (brute force)")
print(("flange riding: touching height %.3f mm at y = 20 mm found and flagged"):format(zl * 1e3))
