-- The size of the coupling of a merged conformal area (tests/scripts/contact_merge_angle.lua checks its defaults,
-- grouping and direction): zones whose normals turn less than the merge angle are one area on the rail's surface
-- developed into the plane (x along the track, s the arc length across the profile), elastically coupled through
-- the half-space on that plane (docs/design.md section 3, "Conformal contact"). Here wrc's solution of such an area
-- is checked against a dense solve of the same discrete problem written independently of the engine:
--   - the elements are wrc's: their centres on the developed surface (x from the grid, s from the rows' arc lengths),
--     their size and their undeformed distance h;
--   - the influence coefficients are written here from Love's closed form for a uniform pressure on a rectangle of
--     a Boussinesq half-space (Love 1929; Johnson, Contact Mechanics, 1985, section 3.3), the double integral of
--     1 / r over the rectangle from the primitive u ln(v + r) + v ln(u + r) (the engine's influence.cpp writes it
--     with asinh), with the wheelset's E and nu for two bodies of one material, 2 (1 - nu^2) / (pi E) per unit of
--     the integral; the form is checked first against the square's centre value and the point load far away;
--   - the normal problem (2 D p - h >= 0, p >= 0, p (2 D p - h) = 0) is solved by an active-set iteration with a
--     Cholesky factorisation of the dense matrix on the contact set, which stops only when p > 0 on the set and the
--     gap >= 0 off it (the complementarity conditions, whose solution is unique).
-- The pose is that of contact_merge_angle.lua (S1002 on 60E1, 30 kN on the left wheel at y = 6.5 mm, yaw 1 deg:
-- the flange root and the flange flank, normals 0.73 rad apart), solved by ws:contact at the pose, i.e. with the
-- penetration prescribed, and again with wrc's vertical force prescribed (the approach then free: 0 at the pose).
-- Checked: each zone's load, the area's vertical force and the approach against the dense solve; and that the same
-- dense solve with the two zones' coupling dropped (the coefficients between them zero, each zone on its own half-
-- space as two areas apart are) lies far outside those bounds.
local check = require "wrc.check"

local wheel = wrc.profile.load(wrc.paths.profiles .. "/s1002.lua")
local rail = wrc.profile.load(wrc.paths.profiles .. "/60e1.lua")
local y, yaw, Fz = 6.5e-3, 0.0175, 30e3
local ws = wrc.wheelset{wheel = wheel, rail = rail, grid = 0.4e-3}
local w = ws:wheel{side = "left", y = y, yaw = yaw, roll = 0, Fz = Fz}
local contact = ws:contact{y = y, z = w.z, roll = 0, yaw = yaw}.left
check.ok(#contact.patches == 1 and contact.patches[1].regions == 2, "the two zones are one area (two regions)")
local area = contact.patches[1]
local g = area.grid
local E, nu = ws.params.E, ws.params.nu

-- Love: integral of 1 / r over the rectangle |xi| <= a, |eta| <= b seen from (x, y), from the primitive
-- F(u, v) = u ln(v + r) + v ln(u + r) at the corners; u and v are never 0 here (offsets of element centres by
-- whole elements, corners half an element away), and ln(u + r) for u < 0 is written ln(v^2 / (r - u)) so that it
-- keeps its digits.
local function ln_plus(u, v, r) return u > 0 and math.log(u + r) or math.log(v * v / (r - u)) end
local function primitive(u, v)
  local r = math.sqrt(u * u + v * v)
  return u * ln_plus(v, u, r) + v * ln_plus(u, v, r)
end
local function love(x, y, a, b)
  return primitive(x + a, y + b) - primitive(x + a, y - b) - primitive(x - a, y + b) + primitive(x - a, y - b)
end
local compliance = 2 * (1 - nu * nu) / (math.pi * E)  -- the pair's displacement difference per Pa, per m of integral
do  -- the closed form against the square's centre (8 a ln(1 + sqrt 2)) and Boussinesq's point load far away
  local a = 0.2e-3
  check.rel(love(0, 0, a, a), 8 * a * math.log(1 + math.sqrt(2)), 1e-12, "Love: the square's centre")
  local x, yy = 30 * a, 40 * a
  local r = math.sqrt(x * x + yy * yy)  -- the point load 4 a^2 / r and the square's next term, a^2 / (6 r^2) of it
  check.rel(love(x, yy, a, a), 4 * a * a / r * (1 + a * a / (6 * r * r)), 1e-6, "Love: the point load far away")
end

-- The elements: wrc's candidates are those with h > 0 (a loaded element has 2 D p = h, and 2 D p > 0 everywhere);
-- under a prescribed force also those within an approach of it (h > -band). Each has its centre on the developed
-- surface (x from the grid, s the row's arc length), its zone (the rows with inter-penetration, split at the rows
-- without) and wrc's pressure.
for j = 2, g.ny do
  check.near(area.rows.s[j] - area.rows.s[1], (j - 1) * g.dy, 1e-9 * g.dy, "the rows' arc lengths one element apart")
end
local band = 0.2 * area.penetration
local el, zone_of_row, zones, in_zone = {}, {}, 0, false
for j = 1, g.ny do
  local any = false
  for i = 1, g.nx do any = any or area.h[j][i] > 0 end
  if any and not in_zone then zones = zones + 1 end
  in_zone = any
  zone_of_row[j] = any and zones or false
end
check.ok(zones == 2, ("the rows with inter-penetration: two zones (%d)"):format(zones))
for j = 1, g.ny do
  for i = 1, g.nx do
    if area.h[j][i] > -band then
      el[#el + 1] = {i = i, j = j, h = area.h[j][i], nz = area.rows.normal_z[j], zone = zone_of_row[j],
                     p = area.pressure[j][i]}
      check.ok(el[#el].p == 0 or el[#el].zone, "every loaded element lies in a zone")
    end
  end
end
local n, dA = #el, g.dx * g.dy
local loaded = 0
for j = 1, g.ny do for i = 1, g.nx do loaded = loaded + (area.pressure[j][i] > 0 and 1 or 0) end end
for _, e in ipairs(el) do loaded = loaded - (e.p > 0 and 1 or 0) end
check.ok(loaded == 0, "every element wrc loads is a candidate")

-- 2 D_kl from the elements' offsets on the developed surface (whole elements: tabulated once per offset), and the
-- same with the coefficients between the two zones dropped.
local T = {}
for dj = 0, g.ny - 1 do
  T[dj] = {}
  for di = 0, g.nx - 1 do T[dj][di] = compliance * love(di * g.dx, dj * g.dy, 0.5 * g.dx, 0.5 * g.dy) end
end
local function coupled_matrix(k, l) return T[math.abs(el[k].j - el[l].j)][math.abs(el[k].i - el[l].i)] end
local function apart_matrix(k, l) return el[k].zone == el[l].zone and coupled_matrix(k, l) or 0 end

-- Cholesky solve of M_SS z = rhs_S (M symmetric positive definite) for the element indices in S, several right-hand
-- sides.
local function solve_spd(M, S, rhs_list)
  local m, L = #S, {}
  for a = 1, m do
    local La = {}
    for b = 1, a do
      local Lb, sum = L[b] or La, M(S[a], S[b])
      for c = 1, b - 1 do sum = sum - La[c] * Lb[c] end
      if a == b then
        assert(sum > 0, "dense reference: the matrix is not positive definite")
        La[a] = math.sqrt(sum)
      else La[b] = sum / Lb[b] end
    end
    L[a] = La
  end
  local out = {}
  for r, rhs in ipairs(rhs_list) do
    local z = {}
    for a = 1, m do
      local La, sum = L[a], rhs[S[a]]
      for c = 1, a - 1 do sum = sum - La[c] * z[c] end
      z[a] = sum / La[a]
    end
    for a = m, 1, -1 do
      local sum = z[a]
      for c = a + 1, m do sum = sum - L[c][a] * z[c] end
      z[a] = sum / L[a][a]
    end
    out[r] = z
  end
  return out
end

-- The normal problem on the elements: g = 2 D p - (h + approach nz) >= 0, p >= 0, p g = 0. With `force`, the
-- vertical force sum p nz dA is prescribed and the vertical approach (m) is the unknown that makes it; without, the
-- approach is 0 (the pose's penetration). Active set from `start` (the elements with h > 0 by default): solve with
-- g = 0 on the set, drop the elements with p <= 0, else add those with g < 0, until neither is left; the solution of
-- this strictly convex problem is unique, whatever the start.
local function dense(M, force, start)
  local H, Wz = {}, {}
  for k = 1, n do H[k], Wz[k] = el[k].h, el[k].nz end
  local S = {}
  for k = 1, n do if (start and start[k] > 0) or (not start and el[k].h > 0) then S[#S + 1] = k end end
  for iteration = 1, 50 do
    local z = solve_spd(M, S, force and {H, Wz} or {H})
    local approach, p = 0, {}
    if force then  -- p = z1 + approach z2 with sum nz p dA = force
      local a1, a2 = 0, 0
      for a, k in ipairs(S) do a1, a2 = a1 + Wz[k] * z[1][a], a2 + Wz[k] * z[2][a] end
      approach = (force / dA - a1) / a2
    end
    for k = 1, n do p[k] = 0 end
    local keep = {}
    for a, k in ipairs(S) do
      local v = z[1][a] + (force and approach * z[2][a] or 0)
      if v > 0 then keep[#keep + 1], p[k] = k, v end
    end
    local changed = #keep < #S
    S = keep
    if not changed then
      for k = 1, n do
        if p[k] == 0 then
          local gap = -(H[k] + approach * Wz[k])
          for l = 1, n do if p[l] > 0 then gap = gap + M(k, l) * p[l] end end
          if gap < -1e-12 * area.penetration then S[#S + 1], changed = k, true end
        end
      end
      table.sort(S)
    end
    if not changed then return {p = p, approach = approach, iterations = iteration} end
  end
  error("dense reference: the active set did not converge in 50 iterations")
end

-- Each zone's load (sum p dA) and the vertical force (sum p nz dA).
local function loads(p)
  local z, v = {0, 0}, 0
  for k = 1, n do
    check.ok(p[k] == 0 or el[k].zone, "only the zones' elements are loaded")
    if el[k].zone then z[el[k].zone] = z[el[k].zone] + p[k] * dA end
    v = v + p[k] * el[k].nz * dA
  end
  return z, v
end
local wrc_p = {}
for k = 1, n do wrc_p[k] = el[k].p end
local wrc_zone, wrc_vertical = loads(wrc_p)
check.rel(wrc_vertical, area.force.z, 1e-9, "wrc's vertical force is the sum of p nz dA over the candidates")

local zone_angle = {0, 0}  -- for the print: each zone's contact angle, its rows' weighted by wrc's pressure
for k = 1, n do
  local e = el[k]
  if e.zone then zone_angle[e.zone] = zone_angle[e.zone] + e.p * dA * area.rows.angle[e.j] / wrc_zone[e.zone] end
end
print(("the zones at contact angles %.3f and %.3f rad, %d candidate elements"):format(zone_angle[1], zone_angle[2], n))

local function compare(name, ref)
  check.ok(ref.approach < band, name .. ": no deeper than the candidates reach")
  local z, v = loads(ref.p)
  local dp, pmax = 0, 0
  for k = 1, n do dp, pmax = math.max(dp, math.abs(ref.p[k] - wrc_p[k])), math.max(pmax, ref.p[k]) end
  print(("%s: zones %.4f and %.4f kN (wrc %.4f, %.4f: %+.2e, %+.2e), vertical %.4f kN (wrc %.4f), approach %.3g um, " ..
         "max |dp| %.2e pmax, %d iterations"):format(name, z[1] / 1e3, z[2] / 1e3, wrc_zone[1] / 1e3,
         wrc_zone[2] / 1e3, wrc_zone[1] / z[1] - 1, wrc_zone[2] / z[2] - 1, v / 1e3, wrc_vertical / 1e3,
         ref.approach * 1e6, dp / pmax, ref.iterations))
  return z, v, dp / pmax
end

-- wrc against the dense solve, penetration prescribed (the pose) and vertical force prescribed (wrc's): wrc's fast
-- solver stops at a gap of 1e-8 of the penetration (NormalOptions::tolerance); measured 3.5e-8 pmax on the pressure,
-- 2.5e-9 on the zones' loads, 3e-14 m of approach (5e-10 of the penetration): bounds of 1e-6.
local bound = 1e-6
local by_penetration = dense(coupled_matrix)
local zp, vp, dpp = compare("dense, penetration prescribed", by_penetration)
local by_force = dense(coupled_matrix, wrc_vertical, by_penetration.p)
local zf, _, dpf = compare("dense, vertical force prescribed", by_force)
for _, r in ipairs{{"penetration", zp, dpp}, {"vertical force", zf, dpf}} do
  for z = 1, 2 do
    check.rel(wrc_zone[z], r[2][z], bound, ("zone %d's load against the dense solve (%s prescribed)"):format(z, r[1]))
  end
  check.ok(r[3] < bound, ("the pressure against the dense solve (%s prescribed): max |dp| %.2e pmax"):format(r[1], r[3]))
end
check.rel(wrc_vertical, vp, bound, "the vertical force at the pose against the dense solve")
check.ok(math.abs(by_force.approach) < bound * area.penetration, "at wrc's vertical force the dense approach is the pose's")

-- Without the coupling (the coefficients between the zones dropped), at the same vertical force: each zone's load
-- and the approach lie far outside those bounds (measured: the lighter zone 13.5 % heavier, the heavier 2.8 %
-- lighter, 3.2 um less approach), so the checks above see the coupling's size. (The zones' loads apart, 15.41 and
-- 28.05 kN, are close to those of the two areas wrc solves apart at merge_angle = 0.26 in contact_merge_angle.lua,
-- 15.40 and 27.99 kN, each on its own plane.)
local apart = dense(apart_matrix, wrc_vertical, by_penetration.p)
local za = compare("dense, zones apart, vertical force prescribed", apart)
for z = 1, 2 do
  check.ok(math.abs(wrc_zone[z] / za[z] - 1) > 1e4 * bound, ("apart, zone %d's load is not wrc's"):format(z))
end
check.ok(math.abs(apart.approach) > 1e4 * bound * area.penetration, "apart, the approach is not the pose's")
