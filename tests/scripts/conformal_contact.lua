-- Conformal contact areas (surface = "conformal", wrc/wheelset/conformal.hpp):
--  1. The flat limit: a nearly flat curved patch (a cylindrical wheel on a crowned rail, transverse radius 90 and
--     450 mm, 100 kN) gives the Hertz solution (elliptic integrals, tests/halfspace/hertz_reference.lua) and the
--     planar solution of the same pose: the surface (midway between the flat wheel and the crown) turns by at most
--     0.05 rad across these patches.
--  2. The results follow from the grids: on S1002/60E1 at the flange root (y = 6.3 mm, where one area turns through
--     tens of degrees), force and moment recomputed here from the pressure grid and the rows' points and normals;
--     the pressure's integral, the resultant's direction and angle, the angle range of the loaded rows; the rows
--     lie on the rail profile (the reference surface), their normals are unit and perpendicular to x (no
--     longitudinal force: a straight rail cannot push along itself); the left and right wheels mirror each other.
--  3. Rotational covariance: the same wheel-rail geometry turned as a whole about x by beta (the rail by its cant,
--     the wheelset by its roll, the centre carried along) gives the same force magnitude and the same pressure grid,
--     with the contact angle turned by beta -- for both surfaces (the planar path's plane is built from the
--     geometry, so it turns with it too; what tells the surfaces apart are the tests of conformal_virtual_work.lua,
--     conformal_persson.lua and equilibrium_jacobian.lua).
local check = require "wrc.check"
local here = arg[0]:match("(.*/)") or "./"
local H = dofile(here .. "../halfspace/hertz_reference.lua")
local P = dofile(here .. "../data/profile/helpers.lua")

local E, nu = 2.1e11, 0.3
local Estar = E / (2 * (1 - nu * nu))
local function norm(a) return math.sqrt(a.x * a.x + a.y * a.y + a.z * a.z) end

-- 1. The flat limit ------------------------------------------------------------------------------------------------
do
  local r0, load, line_step, gauge_depth = 0.45, 100e3, 0.02e-3, 0.2e-3
  local wheel = P.cone_wheel(0)
  print("flat limit: cylinder r0 = 450 mm on a crowned rail, 100 kN; errors against Hertz (%), conformal vs planar")
  for _, q in ipairs{1, 5} do
    local R = r0 / q
    local rail = P.crowned_rail(R, 0.025, line_step)
    local ref = H.from_force(1 / (2 * r0), 1 / (2 * R), Estar, load)
    for _, nb in ipairs{8, 16} do
      local element = math.min(ref.a, ref.b) / nb
      local function solve(surface)
        local ws = P.crown_wheelset(wheel, rail, R, {radius = r0, gauge_depth = gauge_depth, E = E, nu = nu,
                                                     grid = element, surface = surface})
        return ws:contact{z = -ref.delta}.left.patches[1]
      end
      local c, p = solve("conformal"), solve("planar")
      local what = ("B/A = %g, %d elements on the semi-axis: "):format(q, nb)
      check.ok(c.surface == "conformal" and p.surface == "planar", what .. "the surfaces asked for")
      local eF, ep = c.normal_force / ref.force - 1, c.pmax / ref.p0 - 1
      local dF, dp = c.normal_force / p.normal_force - 1, c.pmax / p.pmax - 1
      local turn = c.angle_max - c.angle_min
      print(("  B/A = %g, n_b = %2d: force %+.3f %%, pmax %+.3f %%; conformal - planar: force %+.4f %%, pmax %+.4f %%; " ..
             "the surface turns by %.4f rad"):format(q, nb, 100 * eF, 100 * ep, 100 * dF, 100 * dp, turn))
      check.ok(math.abs(eF) < 0.01, what .. "force within 1 % of Hertz")
      check.ok(math.abs(ep) < 0.02, what .. "peak pressure within 2 % of Hertz")
      check.ok(math.abs(dF) < 1e-3 and math.abs(dp) < 2e-3, what .. "conformal = planar within 0.1 % (force), 0.2 % (pmax)")
      check.near(c.angle, 0, 1e-9, what .. "resultant vertical")
      check.ok(turn > 0 and turn < 0.05, what .. "a nearly flat patch")
      check.ok(c.grid.nx == p.grid.nx and math.abs(c.grid.ny - p.grid.ny) <= 1, what .. "the same potential area")
    end
  end
end

-- 2. The results follow from the grids (S1002 / 60E1, flange root) ------------------------------------------------
local wheel = wrc.profile.load(wrc.paths.profiles .. "/s1002.lua")
local rail = wrc.profile.load(wrc.paths.profiles .. "/60e1.lua")
do
  local ws = wrc.wheelset{wheel = wheel, rail = rail, surface = "conformal", grid = 0.4e-3}
  local w = ws:wheel{side = "left", y = 6.3e-3, yaw = 0, roll = 0, Fz = 100e3}
  local c = ws:contact{y = 6.3e-3, z = w.z, roll = 0}
  local lines = ws:lines("left")
  for _, side in ipairs{"left", "right"} do
    for k, p in ipairs(c[side].patches) do
      local what = ("%s area %d: "):format(side, k)
      local g = p.grid
      local dA = g.dx * g.dy
      local F, M, S, P = {x = 0, y = 0, z = 0}, {x = 0, y = 0, z = 0}, 0, 0
      local centre = {x = 0, y = c.pose.y, z = c.pose.z}
      local amin, amax = math.huge, -math.huge
      for j = 1, g.ny do
        local n = {x = 0, y = p.rows.normal_y[j], z = p.rows.normal_z[j]}
        check.near(norm(n), 1, 1e-12, what .. "unit row normal")
        local row = 0
        for i = 1, g.nx do
          local f = p.pressure[j][i] * dA
          check.ok(p.angles[j][i] == p.rows.angle[j], what .. "the angle grid holds the rows' angles")
          -- the element's point: track x from the frame's origin (at grid x = 0), y and z of its row
          local X = {x = p.frame.origin.x + g.x0 + (i - 1) * g.dx, y = p.rows.y[j], z = p.rows.z[j]}
          local r = {x = X.x - centre.x, y = X.y - centre.y, z = X.z - centre.z}
          F = {x = F.x, y = F.y + f * n.y, z = F.z + f * n.z}
          M = {x = M.x + f * (r.y * n.z - r.z * n.y), y = M.y + f * (r.z * n.x - r.x * n.z), z = M.z + f * (r.x * n.y - r.y * n.x)}
          S, row = S + f, row + f
        end
        if row > 0 then amin, amax = math.min(amin, p.rows.angle[j]), math.max(amax, p.rows.angle[j]) end
        P = P + row
      end
      local N = norm(F)
      check.rel(S, p.pressure_integral, 1e-9, what .. "pressure integral")
      check.ok(N < S, what .. "the resultant is shorter than the pressure's integral (the normals turn)")
      check.near(norm({x = F.x - p.force.x, y = F.y - p.force.y, z = F.z - p.force.z}), 0, 1e-9 * N, what .. "force = sum p dA n")
      check.near(norm({x = M.x - p.moment.x, y = M.y - p.moment.y, z = M.z - p.moment.z}), 0, 1e-9 * N, what .. "moment = sum (X - c) x p dA n")
      check.near(p.force.x, 0, 1e-9 * N, what .. "no longitudinal force")
      check.rel(p.normal_force, N, 1e-12, what .. "normal force = |force|")
      check.near(p.normal.y * N, F.y, 1e-9 * N, what .. "normal = force direction (y)")
      check.near(p.normal.z * N, F.z, 1e-9 * N, what .. "normal = force direction (z)")
      local sign = side == "left" and 1 or -1
      check.near(p.angle, math.atan(-sign * F.y, F.z), 1e-12, what .. "angle of the resultant")
      check.near(p.angle_min, amin, 1e-15, what .. "smallest angle of the loaded rows")
      check.near(p.angle_max, amax, 1e-15, what .. "largest angle of the loaded rows")
      check.ok(p.angle_min <= p.angle and p.angle <= p.angle_max, what .. "the resultant within the range")
      -- Rows: arc length steps of one element; points on the rail profile (between two consecutive rail lines).
      for j = 2, g.ny do check.near(p.rows.s[j] - p.rows.s[j - 1], g.dy, 1e-12, what .. "rows one element apart") end
      local off = 0
      for j = 1, g.ny do
        local best = math.huge
        for r = 1, lines.count - 1 do
          local ay, az, by, bz = lines.y[r], lines.z[r], lines.y[r + 1], lines.z[r + 1]
          local ly, lz = by - ay, bz - az
          local t = math.max(0, math.min(1, ((p.rows.y[j] - ay) * ly + (p.rows.z[j] - az) * lz) / (ly * ly + lz * lz)))
          best = math.min(best, math.sqrt((p.rows.y[j] - ay - t * ly) ^ 2 + (p.rows.z[j] - az - t * lz) ^ 2))
        end
        off = math.max(off, best)
      end
      check.ok(off < 1e-12, what .. ("rows on the rail profile (%.1e m)"):format(off))
      if side == "left" and k == 1 then
        print(("flange root, y = 6.3 mm, left wheel at 100 kN: |F| %.2f kN of %.2f kN of pressure, resultant at %.2f deg, " ..
               "loaded rows from %.2f to %.2f deg"):format(N / 1e3, S / 1e3, math.deg(p.angle), math.deg(amin), math.deg(amax)))
        check.ok(amax - amin > math.rad(10), what .. "the patch turns by more than 10 deg")
      end
    end
  end
  -- Mirror: the centred pose, both wheels alike.
  local m = ws:contact{y = 0, z = -0.1e-3, roll = 0}
  check.ok(#m.left.patches == #m.right.patches, "mirror: as many areas on both wheels")
  check.rel(m.left.force.z, m.right.force.z, 1e-9, "mirror: vertical forces")
  check.near(m.left.force.y, -m.right.force.y, 1e-9 * m.left.force.z, "mirror: lateral forces")
  check.near(m.left.patches[1].angle_max, m.right.patches[1].angle_max, 1e-12, "mirror: angle range")
end

-- 3. Rotational covariance -------------------------------------------------------------------------------------------
do
  -- The rail head only (its gauge and field faces would fold over when turned); the right rail far below, out of
  -- reach of the rolled wheelset.
  local head = rail:transform{crop = {z = {-0.012, 0.001}}}
  local far = head:transform{shift = {z = -0.3}}
  local beta, c0 = 0.1, 1 / 40
  local function wheelset(cant, surface)
    return wrc.wheelset{left_wheel = wheel, right_wheel = wheel, left_rail = head, right_rail = far, cant = cant,
                        gauge_depth = 0.010, surface = surface, grid = 0.4e-3}
  end
  local cb, sb = math.cos(beta), math.sin(beta)
  local function turn(y, z) return cb * y - sb * z, sb * y + cb * z end
  for _, surface in ipairs{"planar", "conformal"} do
    local A = wheelset(c0, surface)
    local B = wheelset(math.tan(math.atan(c0) + beta), surface)
    -- B's left rail is A's turned by beta and moved by t (found from one point, checked on all).
    local ra, rb = A.left_rail, B.left_rail
    local y1, z1 = turn(ra.y[1], ra.z[1])
    local ty, tz = rb.y[1] - y1, rb.z[1] - z1
    for k = 1, #ra.y do
      local y, z = turn(ra.y[k], ra.z[k])
      check.ok(math.abs(y + ty - rb.y[k]) < 1e-12 and math.abs(z + tz - rb.z[k]) < 1e-12, "the rail turned as a whole")
    end
    for _, y in ipairs{3e-3, 5.5e-3, 6.3e-3} do
      local w = A:wheel{side = "left", y = y, yaw = 0, roll = 0, Fz = 100e3}
      local yb, zb = turn(y, w.z)
      local a = A:contact{y = y, z = w.z, roll = 0}.left
      local b = B:contact{y = yb + ty, z = zb + tz, roll = beta}.left
      local what = ("%s, y = %.1f mm, turned by %.2f rad: "):format(surface, y * 1e3, beta)
      check.rel(norm(b.force), norm(a.force), 1e-9, what .. "force magnitude")
      check.near(b.angle, a.angle + beta, 1e-9, what .. "contact angle turned by beta")
      check.ok(#a.patches == #b.patches, what .. "as many areas")
      local dp, pmax = 0, 0
      for k, pa in ipairs(a.patches) do
        local pb = b.patches[k]
        check.ok(pa.grid.nx == pb.grid.nx and pa.grid.ny == pb.grid.ny, what .. "the same grid")
        for j = 1, pa.grid.ny do
          for i = 1, pa.grid.nx do
            dp, pmax = math.max(dp, math.abs(pa.pressure[j][i] - pb.pressure[j][i])), math.max(pmax, pa.pressure[j][i])
          end
        end
      end
      check.ok(dp <= 1e-8 * pmax, what .. ("the same pressure field (%.1e of pmax)"):format(dp / pmax))
      print(("rotation: %s |F| %.4f kN, max |dp| / pmax %.1e"):format(what, norm(a.force) / 1e3, dp / pmax))
    end
  end
end
