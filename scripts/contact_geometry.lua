-- wrc.contact_geometry: helpers for rigid contact geometry studies (examples/conicity.lua): the contact-point chart
-- (where the touching point sits on the wheel and on the rail as the wheelset moves, the classic "jump chart"), Δr
-- curves, and tan(gamma_e) against the amplitude up to flange contact. Works on the tables of ws:geometry_table and
-- ws:conicity; plots through wrc.output (gnuplot PNG with its data).
local out = require "wrc.output"
local M = {}

-- Arrays (mm) of one wheel's touching point along a table: y of the wheelset, s on the wheel profile, y on the rail
-- profile; NaN where the wheel is lifted or the row has no solution (gaps in the plots).
function M.contact_series(t, side)
  local s = {y = {}, wheel = {}, rail = {}, dr = {}}
  for i, r in ipairs(t.rows) do
    local w = r.converged and r[side]
    local c = w and w.contacts and w.contacts[1]
    s.y[i] = r.y * 1e3
    s.wheel[i] = c and c.wheel_profile.y * 1e3 or 0 / 0
    s.rail[i] = c and c.rail_profile.y * 1e3 or 0 / 0
    s.dr[i] = r.rolling_radius_difference and r.rolling_radius_difference * 1e3 or 0 / 0
  end
  return s
end

-- The contact-point chart of one wheel: its touching point on the wheel profile (s from the tape circle) and on the
-- rail profile (y from the rail's axis, field side +) against the wheelset's lateral displacement. A vertical run is a
-- jump of the contact point.
function M.contact_chart(file, t, side, title)
  local s = M.contact_series(t, side)
  out.plot{file = file, title = title, xlabel = "lateral displacement of the wheelset y (mm)",
           ylabel = "contact point, lateral position on the profile (mm)",
           series = {{x = s.y, y = s.wheel, title = side .. " wheel: s on the wheel profile", style = "lines lw 2"},
                     {x = s.y, y = s.rail, title = side .. " rail: y on the rail profile", style = "lines lw 2"}}}
end

-- tan(gamma_e) against the amplitude for the amplitudes `yhat` (m) that stay clear of flange contact (the Δr table
-- of ws:conicity marks it), by wrc.conicity on the wheelset's own Δr table. Returns {yhat_mm = {...}, tan = {...}}.
function M.conicity_curve(ws, yhat, options)
  local o = {yhat = {yhat[1]}}
  for k, v in pairs(options or {}) do o[k] = v end
  local ymax = 0
  for _, a in ipairs(yhat) do ymax = math.max(ymax, a) end
  o.y = o.y or {from = -(1.5 * ymax + 1e-3), to = 1.5 * ymax + 1e-3, step = 0.05e-3}
  local _, details = ws:conicity(o)
  local c = {yhat_mm = {}, tan = {}, dr = details.dr}
  for _, a in ipairs(yhat) do
    local ok, t = pcall(wrc.conicity, details.dr, {yhat = a, method = o.method})
    if not ok then break end  -- flange contact (or the table's end): larger amplitudes are not defined
    c.yhat_mm[#c.yhat_mm + 1], c.tan[#c.tan + 1] = a * 1e3, t[1]
  end
  return c
end

-- tan(gamma_e) at one amplitude (m) from a curve of conicity_curve (linear between its amplitudes), or nil.
function M.at(curve, yhat)
  local x = yhat * 1e3
  for i = 2, #curve.yhat_mm do
    local a, b = curve.yhat_mm[i - 1], curve.yhat_mm[i]
    if x >= a - 1e-12 and x <= b + 1e-12 then return curve.tan[i - 1] + (x - a) / (b - a) * (curve.tan[i] - curve.tan[i - 1]) end
  end
end

return M
