-- Helpers shared by the normal-contact Lua tests (contact_*.lua; loaded with dofile from the tests' own folder):
-- measures of a solved contact area (a patch of ws:contact / ws:wheel) computed from its pressure and h grids,
-- the inter-penetration area of its segments projected onto its contact plane, and the placed wheel's radius. Run on its own it checks
-- itself on a synthetic area.
local M = {}

local function dot(a, b) return a.x * b.x + a.y * b.y + a.z * b.z end
local function sub(a, b) return {x = a.x - b.x, y = a.y - b.y, z = a.z - b.z} end

-- Plane coordinates (u along t1, v along t2) of a track-frame point.
function M.plane_uv(p, X)
  local d = sub(X, p.frame.origin)
  return dot(d, p.frame.t1), dot(d, p.frame.t2)
end

-- Element centre (u, v) of grid indices (i, j), 1-based as in p.pressure[j][i].
function M.element_uv(g, i, j) return g.x0 + (i - 1) * g.dx, g.y0 + (j - 1) * g.dy end

-- Sum of p dA over the grid (N).
function M.grid_force(p)
  local s = 0
  for j = 1, p.grid.ny do for i = 1, p.grid.nx do s = s + p.pressure[j][i] end end
  return s * p.grid.dx * p.grid.dy
end

-- Shape of the contact set (elements with p > 0), all from the grids:
--   length, width   extents along u and v (m), from element edges
--   area            loaded elements times dA (m^2)
--   ellipse_ratio   area / (pi/4 length width): 1 for an ellipse (to the discretisation), 4/pi for a rectangle
--   components      4-connected groups of loaded elements
--   cop_u, cop_v    centre of pressure (m, plane coordinates)
--   lateral_extent_ratio  (v_max - cop_v) / (cop_v - v_min) with element edges: 1 for Hertz
--   lateral_skewness      third standardised moment of the pressure along v: 0 for Hertz
function M.shape(p)
  local g = p.grid
  local umin, umax, vmin, vmax = math.huge, -math.huge, math.huge, -math.huge
  local n, F, Fu, Fv = 0, 0, 0, 0
  for j = 1, g.ny do
    for i = 1, g.nx do
      local pr = p.pressure[j][i]
      if pr > 0 then
        local u, v = M.element_uv(g, i, j)
        n, F, Fu, Fv = n + 1, F + pr, Fu + pr * u, Fv + pr * v
        umin, umax, vmin, vmax = math.min(umin, u), math.max(umax, u), math.min(vmin, v), math.max(vmax, v)
      end
    end
  end
  assert(n > 0, "shape: no element in contact")
  local s = {area = n * g.dx * g.dy, length = umax - umin + g.dx, width = vmax - vmin + g.dy,
             cop_u = Fu / F, cop_v = Fv / F, elements = n}
  s.ellipse_ratio = s.area / (math.pi / 4 * s.length * s.width)
  s.lateral_extent_ratio = (vmax + 0.5 * g.dy - s.cop_v) / (s.cop_v - vmin + 0.5 * g.dy)
  local m2, m3 = 0, 0
  for j = 1, g.ny do
    for i = 1, g.nx do
      local pr = p.pressure[j][i]
      if pr > 0 then
        local _, v = M.element_uv(g, i, j)
        m2, m3 = m2 + pr * (v - s.cop_v) ^ 2, m3 + pr * (v - s.cop_v) ^ 3
      end
    end
  end
  m2, m3 = m2 / F, m3 / F
  s.lateral_skewness = m3 / m2 ^ 1.5
  -- Components by flood fill.
  local seen, comps = {}, 0
  for j = 1, g.ny do
    for i = 1, g.nx do
      if p.pressure[j][i] > 0 and not seen[(j - 1) * g.nx + i] then
        comps = comps + 1
        local stack = {{i, j}}
        seen[(j - 1) * g.nx + i] = true
        while #stack > 0 do
          local e = table.remove(stack)
          for _, d in ipairs{{1, 0}, {-1, 0}, {0, 1}, {0, -1}} do
            local a, b = e[1] + d[1], e[2] + d[2]
            if a >= 1 and a <= g.nx and b >= 1 and b <= g.ny and p.pressure[b][a] > 0 and not seen[(b - 1) * g.nx + a] then
              seen[(b - 1) * g.nx + a] = true
              stack[#stack + 1] = {a, b}
            end
          end
        end
      end
    end
  end
  s.components = comps
  return s
end

-- Separate contact regions as ws:contact counts them (patch.regions): groups of loaded elements, 8-connected,
-- each carrying at least `min_share` of the force (default 0.001). Returns the count and the groups' forces (N).
function M.regions(p, min_share)
  min_share = min_share or 0.001
  local g = p.grid
  local seen, forces, total = {}, {}, 0
  for j = 1, g.ny do
    for i = 1, g.nx do
      if p.pressure[j][i] > 0 and not seen[(j - 1) * g.nx + i] then
        local f, stack = 0, {{i, j}}
        seen[(j - 1) * g.nx + i] = true
        while #stack > 0 do
          local e = table.remove(stack)
          f = f + p.pressure[e[2]][e[1]]
          for di = -1, 1 do
            for dj = -1, 1 do
              local a, b = e[1] + di, e[2] + dj
              if a >= 1 and a <= g.nx and b >= 1 and b <= g.ny and p.pressure[b][a] > 0 and not seen[(b - 1) * g.nx + a] then
                seen[(b - 1) * g.nx + a] = true
                stack[#stack + 1] = {a, b}
              end
            end
          end
        end
        forces[#forces + 1] = f * g.dx * g.dy
        total = total + f * g.dx * g.dy
      end
    end
  end
  local n, kept = 0, {}
  for _, f in ipairs(forces) do
    if f >= min_share * total then n, kept[#kept + 1] = n + 1, f end
  end
  return n, kept
end

-- The inter-penetration area of a patch projected onto its contact plane, from its segments and the side's rail
-- lines (ws:lines(side)): each rail line is a line of constant v (the plane's t2 has no x component at zero
-- yaw; checked); its segments are u-intervals. Between two consecutive rail lines that both have segments the
-- area is the linear interpolation of their intervals; between a line with segments and one without, the area
-- ends somewhere in between: the line's own intervals are taken (a band a line spacing wide, the generous side).
-- Returns a function inside(u, v) -> true/false and the sorted line list.
function M.interpenetration(p, lines)
  assert(math.abs(p.frame.t2.x) < 1e-9, "interpenetration: the plane's t2 must be across the track (zero yaw)")
  local O = p.frame.origin
  local byline = {}
  for _, s in ipairs(p.segments) do
    local ut = M.plane_uv(p, {x = s.x_t, y = s.y, z = s.z})
    local ul = M.plane_uv(p, {x = s.x_l, y = s.y, z = s.z})
    local list = byline[s.line] or {}
    list[#list + 1] = {math.min(ut, ul), math.max(ut, ul)}
    byline[s.line] = list
  end
  local vs = {}
  for k = 1, lines.count do
    local _, v = M.plane_uv(p, {x = O.x, y = lines.y[k], z = lines.z[k]})
    vs[#vs + 1] = {v = v, line = k}
  end
  table.sort(vs, function(a, b) return a.v < b.v end)
  local function within(list, u)
    for _, r in ipairs(list or {}) do if u >= r[1] and u <= r[2] then return true end end
    return false
  end
  local function inside(u, v)
    if v < vs[1].v or v > vs[#vs].v then return false end
    local lo, hi = 1, #vs
    while hi - lo > 1 do
      local mid = (lo + hi) // 2
      if vs[mid].v <= v then lo = mid else hi = mid end
    end
    local a, b = byline[vs[lo].line], byline[vs[hi].line]
    if a and b then
      local t = vs[hi].v > vs[lo].v and (v - vs[lo].v) / (vs[hi].v - vs[lo].v) or 0
      for _, ra in ipairs(a) do
        for _, rb in ipairs(b) do
          if u >= (1 - t) * ra[1] + t * rb[1] and u <= (1 - t) * ra[2] + t * rb[2] then return true end
        end
      end
      return false
    end
    return within(a, u) or within(b, u)
  end
  return inside, vs
end

-- The contact-inside-inter-penetration property of a solved area: every element with p > 0 has h > 0 and lies
-- inside the projected segments. Returns the number of loaded elements and of violations of each kind.
function M.contact_inside(p, lines)
  local inside = M.interpenetration(p, lines)
  local g = p.grid
  local loaded, bad_h, outside = 0, 0, 0
  for j = 1, g.ny do
    for i = 1, g.nx do
      if p.pressure[j][i] > 0 then
        loaded = loaded + 1
        if not (p.h[j][i] > 0) then bad_h = bad_h + 1 end
        if not inside(M.element_uv(g, i, j)) then outside = outside + 1 end
      end
    end
  end
  return loaded, bad_h, outside
end

-- The placed left wheel's radius (m) at lateral position Y (from the wheelset centre) of wheelset w, interpolated
-- between its points.
function M.wheel_radius(w, Y)
  local wy, wz = w.left_wheel.y, w.left_wheel.z
  for k = 1, #wy - 1 do
    if wy[k] <= Y and Y <= wy[k + 1] then
      return -(wz[k] + (wz[k + 1] - wz[k]) * (Y - wy[k]) / (wy[k + 1] - wy[k]))
    end
  end
  error("Y outside the wheel")
end

-- Self-check on a synthetic area: a 3 x 3 block and a separate element on a 5 x 5 grid.
if arg and arg[0] and arg[0]:find("contact_helpers%.lua$") then
  local check = require "wrc.check"
  local P = {}
  for j = 1, 5 do
    P[j] = {}
    for i = 1, 5 do P[j][i] = (i <= 3 and j <= 3) and 1 or 0 end
  end
  P[5][5] = 1
  local patch = {grid = {nx = 5, ny = 5, dx = 1, dy = 1, x0 = 0, y0 = 0}, pressure = P}
  local s = M.shape(patch)
  check.ok(s.components == 2, "two components")
  check.near(s.area, 10, 0, "area")
  check.near(s.length, 5, 0, "length")
  check.near(s.width, 5, 0, "width")
  check.near(s.cop_u, (3 * (0 + 1 + 2) + 4) / 10, 1e-15, "centre of pressure")
  check.near(M.grid_force(patch), 10, 0, "force")
  P[4][4] = 1  -- joins the single element diagonally
  check.ok(M.regions(patch) == 1 and M.shape(patch).components == 3, "8-connected regions, 4-connected components")
  P[4][4] = 0
  check.ok(M.regions(patch) == 2 and M.regions(patch, 0.2) == 1, "regions below the force share are not counted")
  -- A patch of two lines (v = 0 and v = 1) with intervals [0, 2] and [1, 3], plane = track frame.
  local flat = {frame = {origin = {x = 0, y = 0, z = 0}, t1 = {x = 1, y = 0, z = 0}, t2 = {x = 0, y = 1, z = 0}},
                segments = {{line = 2, x_t = 0, x_l = 2, y = 0, z = 0}, {line = 3, x_t = 1, x_l = 3, y = 1, z = 0}}}
  local inside = M.interpenetration(flat, {count = 4, y = {-1, 0, 1, 2}, z = {0, 0, 0, 0}})
  check.ok(inside(1, 0.5) and inside(2.4, 0.5) and not inside(0.4, 0.5) and not inside(2.6, 0.5), "interpolated")
  check.ok(inside(0.5, -0.5) and not inside(2.5, -0.5), "band beyond the last line with a segment")
  check.ok(not inside(1, -1.5) and not inside(1, 2.5), "beyond the lines")
  print("contact_helpers: ok")
end

return M
