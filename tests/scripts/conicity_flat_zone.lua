-- Equivalent conicity of a Δr that is exactly zero over a band around the centre (a worn pair with a flat zone;
-- issue 28): the wheelset moves freely inside the band, with no restoring Δr, so EN 15302 gives tan(gamma_e) = 0 (an
-- infinite wavelength) for amplitudes within it, and the result says why in `note`.
--
-- The case, built analytically: a 1:20 cone pair with a flat zone of half-width w, Δr(y) = 2 gamma sign(y) max(|y| - w,
-- 0). Beyond the band, the kinematic motion d2y/dx2 = -Δr / (2 e r0) of amplitude yhat > w is a half sine of
-- excursion A = yhat - w on each side (distance pi / omega, omega^2 = gamma / (e r0)) joined by straight crossings of
-- the band at the slope omega A (distance 2 w / (omega A) each): lambda = (2 / omega) (pi + 2 w / A). Klingel's
-- lambda = 2 pi sqrt(e r0 / tan) then gives tan(gamma_e) = gamma / (1 + 2 w / (pi A))^2.
local check = require "wrc.check"

local gamma, w = 0.05, 2e-3
local y, dr = {}, {}
for k = -100, 100 do  -- every 0.1 mm over +-10 mm; the band's edges are knots
  local yy = k * 1e-4
  y[#y + 1] = yy
  dr[#dr + 1] = yy > w and 2 * gamma * (yy - w) or yy < -w and 2 * gamma * (yy + w) or 0
end
local yhat = {0.5e-3, 1e-3, 2e-3, 3e-3, 5e-3}
for _, method in ipairs{"integral", "harmonic", "regression", "simple"} do
  local t, d = wrc.conicity({y = y, dr = dr}, {yhat = yhat, method = method})
  check.near(d.centre, 0, 1e-15, method .. ": the motion centres on the middle of the flat zone")
  check.near(d.flat_zone[1], -w, 1e-15, method .. ": the flat zone's start")
  check.near(d.flat_zone[2], w, 1e-15, method .. ": the flat zone's end")
  check.ok(d.note and d.note:find("no restoring Δr", 1, true) and d.note:find("tan γe = 0", 1, true), tostring(d.note))
  for k = 1, 3 do  -- within the band
    check.ok(t[k] == 0 and d.wavelength[k] == math.huge,
             ("%s, yhat = %g mm inside the flat zone: tan = %s, wavelength %s"):format(method, yhat[k] * 1e3, t[k], d.wavelength[k]))
  end
  if method == "integral" then
    for k = 4, 5 do
      local expected = gamma / (1 + 2 * w / (math.pi * (yhat[k] - w))) ^ 2
      check.rel(t[k], expected, 1e-9, ("integral, yhat = %g mm beyond the flat zone (analytic %.6f)"):format(yhat[k] * 1e3, expected))
      check.near(d.y_min[k], -yhat[k], 1e-12, "symmetric turning points")
    end
  else
    for k = 4, 5 do check.ok(t[k] > 0 and t[k] < gamma, method .. ": beyond the flat zone, between 0 and the cone's") end
  end
end

-- A single zero (no flat zone) gives no note, and the cone's conicity.
local yc, dc = {}, {}
for k = -100, 100 do yc[#yc + 1], dc[#dc + 1] = k * 1e-4, 2 * gamma * k * 1e-4 end
local t, d = wrc.conicity({y = yc, dr = dc}, {yhat = {1e-3}})
check.rel(t[1], gamma, 1e-12, "the cone pair without a flat zone")
check.ok(d.note == nil and d.flat_zone == nil, "no note without a flat zone")
print(("conicity: flat zone +-%g mm: tan = 0 within, %.5f at yhat = 3 mm (analytic)"):format(w * 1e3,
      gamma / (1 + 2 * w / (math.pi * 1e-3)) ^ 2))
