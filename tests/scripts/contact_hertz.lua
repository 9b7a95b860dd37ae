-- Hertz through the whole pipeline (issue 5): real profile pairs built with wrc.profile.points, located, turned
-- into a contact plane and h by the engine, solved, and compared with the analytic Hertz solution computed here
-- (tests/halfspace/hertz_reference.lua: elliptic integrals by the AGM, the axis ratio by bisection).
--
-- The pair: a cylindrical wheel (flat profile, radius r0) on a crowned rail (a circular arc of transverse radius
-- R, cant 0). Relative curvatures: A = 1/(2 r0) along the track, B = 1/(2 R) across; R = r0 / q gives B/A = q.
-- The centred wheelset touches at z = 0 (the track assembly guarantees it) at the crown, where a rail line
-- lies, so the penetration at the pose z = -delta is delta: computed from the pose, not read from the result.
-- The rail lines are the profile's own points (strategy {"coarse", "topology"} does not resample), 0.02 mm
-- apart: the linear interpolation of h across lines then costs < 1e-5 of the force.
--
-- Run with levels=6 (wrc run tests/scripts/contact_hertz.lua levels=6) for the convergence table down to 128
-- elements on the minor semi-axis (the default 4 levels, 4..32 elements, keep the test fast under ASan), with
-- line_step=5e-6 for rail lines finer than those elements, q=5 for one curvature ratio.
local check = require "wrc.check"
local here = arg[0]:match("(.*/)") or "./"
local H = dofile(here .. "../halfspace/hertz_reference.lua")
local C = dofile(here .. "contact_helpers.lua")
local P = dofile(here .. "../data/profile/helpers.lua")

local levels = math.tointeger(tonumber(arg.levels or 4))
assert(levels and levels >= 1 and levels <= 6, "levels must be 1..6")
local E, nu = 2.1e11, 0.3
local Estar = E / (2 * (1 - nu * nu))
local r0 = 0.45
local load = 100e3        -- N: the Hertz force whose approach is imposed
local line_step = tonumber(arg.line_step or 0.02e-3)  -- m between rail lines
local half_width = 0.025   -- m: the rail extends to +-25 mm (the widest inter-penetration is +-9.4 mm)
local gauge_depth = 0.2e-3 -- m: the gauge point on the crown (the pair has no flange)

local function wheelset(wheel, rail, R, element)
  return P.crown_wheelset(wheel, rail, R, {radius = r0, gauge_depth = gauge_depth, E = E, nu = nu, grid = element})
end

-- Semi-axes measured on the pressure grid, on the row and the column through the element nearest the centre
-- of pressure: (1) the extent of the loaded elements, half their count times the element size (what "within
-- one element" is about); (2) a least-squares fit of the semi-ellipse p^2 = c0 + c1 x^2 over the loaded
-- elements, a = sqrt(-c0 / c1), which resolves the edge below the element size.
local function fit_semi_axis(xs, ps)
  local n, sx, sy, sxx, sxy = 0, 0, 0, 0, 0
  for k = 1, #xs do
    local x, y = xs[k] ^ 2, ps[k] ^ 2
    n, sx, sy, sxx, sxy = n + 1, sx + x, sy + y, sxx + x * x, sxy + x * y
  end
  local c1 = (n * sxy - sx * sy) / (n * sxx - sx * sx)
  local c0 = (sy - c1 * sx) / n
  return math.sqrt(-c0 / c1)
end

local function measured_semi_axes(p)
  local g = p.grid
  local u = p.point.x - p.frame.origin.x  -- t1 = x and t2 = y here (checked by the caller)
  local v = p.point.y - p.frame.origin.y
  local ic = math.floor((u - g.x0) / g.dx + 0.5) + 1
  local jc = math.floor((v - g.y0) / g.dy + 0.5) + 1
  local xs, px, ys, py = {}, {}, {}, {}
  for i = 1, g.nx do
    local pr = p.pressure[jc][i]
    if pr > 0 then xs[#xs + 1], px[#px + 1] = g.x0 + (i - 1) * g.dx - u, pr end
  end
  for j = 1, g.ny do
    local pr = p.pressure[j][ic]
    if pr > 0 then ys[#ys + 1], py[#py + 1] = g.y0 + (j - 1) * g.dy - v, pr end
  end
  return {a = 0.5 * #xs * g.dx, b = 0.5 * #ys * g.dy, a_fit = fit_semi_axis(xs, px), b_fit = fit_semi_axis(ys, py),
          ic = ic, jc = jc}
end

print("Hertz through the pipeline: cylinder wheel r0 = 450 mm on a crowned rail, 100 kN, E = 210 GPa, nu = 0.3")
print(string.format("%5s %9s %5s %7s %9s %9s %9s %7s %7s %9s %9s %8s %7s", "B/A", "R_rail_mm", "n_b", "el_mm",
                    "elements", "dF_%", "dpmax_%", "da_el", "db_el", "da_fit_%", "db_fit_%", "time_s", "ell_r"))
local worst = {F = 0, p = 0, ax = 0}
for _, q in ipairs(arg.q and {tonumber(arg.q)} or {1, 2, 5, 10}) do
  local R = r0 / q
  local A, B = 1 / (2 * r0), 1 / (2 * R)
  local ref = H.from_force(A, B, Estar, load)
  local wheel, rail = P.cone_wheel(0), P.crowned_rail(R, half_width, line_step)
  local errors = {}
  for level = 1, levels do
    local n = 2 ^ (level + 1)  -- elements on the minor semi-axis: 4, 8, 16, ...
    local element = math.min(ref.a, ref.b) / n
    local ws = wheelset(wheel, rail, R, element)
    local t0 = os.clock()
    local c = ws:contact{z = -ref.delta}
    local seconds = os.clock() - t0
    check.ok(#c.left.patches == 1 and #c.right.patches == 1, "one contact area per wheel")
    local p = c.left.patches[1]
    local what = string.format("B/A = %g, %d elements on the semi-axis: ", q, n)
    -- The geometry the normal problem saw.
    check.rel(p.penetration, ref.delta, 1e-9, what .. "max h = the pose's penetration")
    check.near(p.normal.z, 1, 1e-12, what .. "contact normal vertical")
    check.near(p.frame.t1.x, 1, 1e-12, what .. "grid x along the track")
    check.near(p.frame.t2.y, 1, 1e-12, what .. "grid y across the track (toward the field side)")
    check.near(p.angle, 0, 1e-10, what .. "contact angle")
    -- The crown: the highest rail line, under the tape circle (to the gauge point's interpolation error) and
    -- touching the wheel at z = 0.
    local lines = ws:lines("left")
    local crown = 1
    for k = 2, lines.count do if lines.z[k] > lines.z[crown] then crown = k end end
    check.near(lines.y[crown], 0.75, 1e-6, what .. "the crown under the tape circle")
    check.near(lines.z[crown], -r0, 1e-12, what .. "the crown touches the wheel at z = 0")
    check.near(p.point.x, 0, 1e-9, what .. "centre of pressure at the crown (x)")
    check.near(p.point.y, lines.y[crown], 1e-9, what .. "centre of pressure at the crown (y)")
    check.ok(p.point.z <= -r0 and p.point.z >= -r0 - ref.delta, what .. "centre of pressure within the overlap")
    check.rel(C.grid_force(p), p.pressure_integral, 1e-9, what .. "pressure integral = sum of the pressure grid")
    check.rel(c.right.patches[1].normal_force, p.normal_force, 1e-9, what .. "right wheel mirrors the left")
    check.ok(p.complementarity < 1e-6, what .. "complementarity")
    -- Against Hertz.
    local m = measured_semi_axes(p)
    check.near(p.h[m.jc][m.ic], ref.delta, 1e-9 * ref.delta, what .. "the centre element sits on the crown")
    local e = {F = p.normal_force / ref.force - 1, p = p.pmax / ref.p0 - 1,
               a = (m.a - ref.a) / p.grid.dx, b = (m.b - ref.b) / p.grid.dy,
               a_fit = m.a_fit / ref.a - 1, b_fit = m.b_fit / ref.b - 1}
    errors[level] = e
    print(string.format("%5g %9.1f %5d %7.4f %9d %9.4f %9.4f %7.2f %7.2f %9.3f %9.3f %8.3f %7.3f", q, R * 1e3, n,
                        element * 1e3, p.grid.nx * p.grid.ny, 100 * e.F, 100 * e.p, e.a, e.b, 100 * e.a_fit,
                        100 * e.b_fit, seconds, C.shape(p).ellipse_ratio))
    check.ok(math.abs(e.F) < 0.01, what .. "normal force within 1 % of Hertz")
    check.ok(math.abs(e.p) < 0.02, what .. "peak pressure within 2 % of Hertz")
    check.ok(math.abs(e.a) <= 1 and math.abs(e.b) <= 1, what .. "semi-axes within one element")
    worst.F, worst.p = math.max(worst.F, math.abs(e.F)), math.max(worst.p, math.abs(e.p))
    worst.ax = math.max(worst.ax, math.abs(e.a), math.abs(e.b))
    -- The shape measures of contact_s1002_flange.lua give an ellipse here: one zone, the area of the ellipse
    -- of the same length and width, symmetric about the centre of pressure.
    local shape = C.shape(p)
    if n >= 8 then
      check.ok(shape.components == 1 and p.regions == 1, what .. "one zone")
      check.near(shape.ellipse_ratio, 1, 0.08, what .. "area / ellipse of the same length and width")
      check.near(shape.lateral_extent_ratio, 1, 1e-6, what .. "lateral extents about the centre of pressure")
      check.near(shape.lateral_skewness, 0, 1e-5, what .. "lateral skewness of the pressure")
    end
    -- Force against penetration at a second, shallower pose (F ~ delta^1.5 comes from the reference).
    if n == 8 then
      local shallow = H.from_approach(A, B, Estar, 0.4 * ref.delta)
      local p2 = ws:contact{z = -shallow.delta}.left.patches[1]
      check.rel(p2.normal_force, shallow.force, 0.01, what .. "force at 0.4 delta within 1 %")
      check.rel(p2.pmax, shallow.p0, 0.02, what .. "peak pressure at 0.4 delta within 2 %")
    end
  end
  -- Refining the grid reduces the error: the finest level beats the coarsest clearly.
  if levels >= 2 then
    local first, last = errors[1], errors[levels]
    check.ok(math.abs(last.p) < 0.5 * math.abs(first.p), string.format("B/A = %g: the peak pressure error shrinks", q))
    check.ok(math.abs(last.F) < math.abs(first.F) + 1e-4, string.format("B/A = %g: the force error does not grow", q))
  end
end
print(string.format("worst: force %.3f %%, peak pressure %.3f %%, semi-axes %.2f elements", 100 * worst.F,
                    100 * worst.p, worst.ax))

-- Yaw: the cylinder's axle turned by psi about z. Its surface is still a horizontal cylinder touching the crown at
-- z = 0, so the penetration is still delta = -z, and h = delta - (x cos psi + y sin psi)^2 / (2 r0) - y^2 / (2 R):
-- Hertz with the eigenvalues of that quadratic form (the ellipse turns). The engine's arc along each rail line
-- has the paper's radius r0 / cos(conicity) divided by cos^2 psi (the wheel's section along x); with the paper's
-- radius alone h was deeper by 1 / cos^2 psi (force +1 % at 0.1 rad, +4 % at 0.2 rad).
do
  local q, n = 5, 8
  local R = r0 / q
  local wheel, rail = P.cone_wheel(0), P.crowned_rail(R, half_width, line_step)
  local delta = H.from_force(1 / (2 * r0), q / (2 * r0), Estar, load).delta
  print("yawed cylinder on the crown, B/A = 5 at zero yaw, 100 kN at zero yaw")
  print(string.format("%8s %10s %10s %9s %9s", "yaw_rad", "max_h_um", "delta_um", "dF_%", "dpmax_%"))
  for _, psi in ipairs{0.01, 0.03, 0.1, 0.2} do
    local c, s = math.cos(psi), math.sin(psi)
    local a11, a12, a22 = c * c / (2 * r0), c * s / (2 * r0), s * s / (2 * r0) + 1 / (2 * R)
    local m, d = 0.5 * (a11 + a22), math.sqrt(0.25 * (a11 - a22) ^ 2 + a12 * a12)
    local ref = H.from_approach(m - d, m + d, Estar, delta)
    local ws = wheelset(wheel, rail, R, math.min(ref.a, ref.b) / n)
    local res = ws:contact{z = -delta, yaw = psi}
    check.ok(#res.left.patches == 1 and #res.right.patches == 1, "yaw: one area per wheel")
    local p = res.left.patches[1]
    local eF, ep = p.normal_force / ref.force - 1, p.pmax / ref.p0 - 1
    print(string.format("%8.3f %10.4f %10.4f %9.4f %9.4f", psi, p.penetration * 1e6, delta * 1e6, 100 * eF, 100 * ep))
    local what = string.format("yaw %g rad: ", psi)
    check.near(p.normal.z, 1, 1e-12, what .. "contact normal vertical")
    -- The axle's lowest line passes over the crown (track y = yc) at x = -yc tan(psi). The deepest element is the
    -- crown's nearest to it (the elements lie on the rail's fixed lattice, one row on the crown): there
    -- h = delta - a11 (x - x_apex)^2. The section's radius counts: with the unyawed one, h would be deeper by 1 / cos^2 psi (1e-4 at 0.01 rad).
    local yc = p.point.y
    local apex, g = -yc * math.tan(psi), p.grid
    local offset = math.huge
    for i = 0, g.nx - 1 do offset = math.min(offset, math.abs(p.frame.origin.x + g.x0 + i * g.dx - apex)) end
    check.ok(offset <= 0.5 * g.dx + 1e-12, what .. "an element within half an element of the apex along x")
    check.rel(p.penetration, delta - a11 * offset ^ 2, 1e-5, what .. "max h = the penetration at the deepest element to 1e-5 (the yawed section's radius)")
    check.near(yc, 0.75, 1e-6, what .. "centre of pressure on the crown")
    check.near(p.point.x, -yc * math.tan(psi), 1e-6, what .. "centre of pressure under the axle")
    check.ok(math.abs(eF) < 0.01, what .. "normal force within 1 % of Hertz")
    check.ok(math.abs(ep) < 0.02, what .. "peak pressure within 2 % of Hertz")
    check.rel(res.right.patches[1].normal_force, p.normal_force, 1e-7, what .. "right wheel = left wheel")
  end
end
