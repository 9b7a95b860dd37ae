-- profiles/worn_s1002.lua against its documented shape, measured here on the points: wear only removes material;
-- the hollow is `hollow` deep at s = 5 mm, cos^2-shaped, and 0 outside the band -25 .. 35 mm; the flange face moves
-- toward the back by `flange` (the lateral distance between the worn and the new face at heights from 2 mm below
-- the tip (4 mm with 4 mm of wear) to 8 mm above the tape circle), the flange tip and the back face stay, the tread beyond s = -28 mm is
-- untouched by flange wear.
local check = require "wrc.check"

local base = wrc.profile.load(wrc.paths.profiles .. "/s1002.lua")
local by, bz = base:points()

-- s where the flange face (from the tip toward the tread) crosses the height z.
local function face_at(p, zlev)
  local y, z = p:points()
  for i = 1, #y - 1 do
    if y[i] > -0.055 and y[i] < -0.026 and z[i] <= zlev and z[i + 1] > zlev then
      return y[i] + (zlev - z[i]) * (y[i + 1] - y[i]) / (z[i + 1] - z[i])
    end
  end
  error("no flange face at z = " .. zlev)
end

for _, c in ipairs{{0, 0}, {1.5e-3, 0}, {0, 3e-3}, {2e-3, 4e-3}} do
  local hollow, flange = c[1], c[2]
  local p = wrc.profile.load(wrc.paths.profiles .. "/worn_s1002.lua", {hollow = hollow, flange = flange})
  local what = ("hollow %.1f mm, flange %.1f mm"):format(hollow * 1e3, flange * 1e3)
  local y, z = p:points()
  check.ok(#y == #by and p.kind == "wheel", what .. ": the points of S1002")
  for i = 1, #y do
    check.ok(y[i] == by[i], what .. ": s unchanged")
    check.ok(z[i] >= bz[i] - 1e-12, what .. (": no material added at s = %.1f mm"):format(y[i] * 1e3))
    local s = y[i]
    local hollow_here = math.abs(s - 0.005) < 0.030 and hollow * math.cos(math.pi * (s - 0.005) / 0.060) ^ 2 or 0
    if s >= -0.028 then  -- the tread: the hollow alone
      check.near(z[i] - bz[i], hollow_here, 1e-12, what .. (": tread wear at s = %.1f mm"):format(s * 1e3))
    elseif s <= -0.055 then  -- the tip and the back face
      check.near(z[i], bz[i], 1e-12, what .. (": flange back unchanged at s = %.1f mm"):format(s * 1e3))
    end
  end
  -- The face moved by `flange` wherever the shift is complete (from 2.5 mm off the tip to the end of the root).
  -- (2 mm below the tip, the qR level, the face is shifted completely while it stays 3 mm off the tip: flange <= 3 mm)
  for _, zlev in ipairs(flange <= 3e-3 and {-0.026, -0.020, -0.015, -0.010, -0.008} or {-0.024, -0.020, -0.015, -0.010, -0.008}) do
    local moved = face_at(base, zlev) - face_at(p, zlev)
    check.near(moved, flange, 2e-7, what .. (": face moved at z = %.0f mm"):format(zlev * 1e3))
  end
end
check.fails(function() wrc.profile.load(wrc.paths.profiles .. "/worn_s1002.lua", {hollow = -1e-3}) end, "hollow must be",
            "a negative depth is refused")
print("worn S1002 ok")
