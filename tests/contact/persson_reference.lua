-- Persson's problem for Lua-level tests: a cylindrical pin of radius R pressed by a force P (per unit length) into a
-- cylindrical hole of radius R + dR in an infinite plate, frictionless, plane strain, both of the same material
-- (Persson 1964; Johnson, Contact Mechanics, 1985, section 5.3). Solved here exactly within linear elasticity (dR << R)
-- by a one-dimensional integral equation over the contact arc, independently of the engine's half-space solver.
--
-- The kernel, from Michell's solution. Let the pressure on the common boundary be p(phi) = sum a_n cos(n phi). For
-- the mode n >= 2 the disc's boundary moves inward and the hole's boundary outward (plane strain, kappa = 3 - 4 nu,
-- shear modulus mu) by
--     disc:  a_n R / (4 mu) (kappa / (n + 1) + 1 / (n - 1)) cos(n theta),
--     hole:  a_n R / (4 mu) (kappa / (n - 1) + 1 / (n + 1)) cos(n theta),
-- together (R / E*) a_n 2 n / (n^2 - 1) cos(n theta) with 1/E* = (kappa + 1) / (4 mu) = 2 (1 - nu^2) / E (the pair's
-- modulus of docs/design.md section 2); the uniform mode n = 0 opens the gap by (R / E*) a_0; the mode n = 1 (the
-- net force) moves the boundaries by multiples of cos(theta) only, like the pin's rigid approach, so it merges into
-- the unknown approach D. Summing the series,
--     w(theta) = (R / E*) a_0 + R / (pi E*) int p(phi) K(theta - phi) dphi,
--     K(x) = sum_{n >= 2} 2 n / (n^2 - 1) cos(n x) = -2 cos(x) log|2 sin(x / 2)| - 1 - cos(x) / 2,
-- whose log |x| singularity is the half-plane's: for small angles the problem is Hertz's line contact with the
-- relative radius R^2 / dR (checked by the test that uses this file).
-- Contact: the gap dR (1 - cos theta) - D cos theta + w(theta) is 0 where p > 0 and >= 0 elsewhere; equilibrium
-- P = R int p cos(phi) dphi. In the units R = E* = dR = 1, the solution depends only on P / (E* dR).
--
-- Numerics: p piecewise constant on `panels` panels over [0, theta_max] (p symmetric), collocation at the panel
-- centres, the log singularity integrated exactly and the smooth rest by 8-point Gauss; the active set iterated
-- (drop negative pressures, add penetrated panels) with D and P as in the force-controlled normal problem. The
-- contact semi-angle comes from the pressure's square-root edge: p^2 linear in theta over the last loaded panels.
--
-- Load it with dofile(path); it returns:
--   P.kernel(x)                       -> K(x)
--   P.solve(load, panels, theta_max)  -> {alpha =, theta = {...}, p = {...}, D =} for load = P / (E* dR): panel
--                                        centres (rad) and pressures p R / (E* dR)
--   P.hertz_alpha(load)               -> the small-angle (Hertz) semi-angle: alpha^2 = 4 P / (pi E* dR)
local M = {}

function M.kernel(x)
  return -2 * math.cos(x) * math.log(math.abs(2 * math.sin(0.5 * x))) - 1 - 0.5 * math.cos(x)
end

-- K(x) + 2 log|x|: smooth.
local function smooth(x)
  if math.abs(x) < 1e-9 then return -1.5 end
  return M.kernel(x) + 2 * math.log(math.abs(x))
end

local gauss = {{-0.9602898564975363, 0.1012285362903763}, {-0.7966664774136267, 0.2223810344533745},
               {-0.5255324099163290, 0.3137066458778873}, {-0.1834346424956498, 0.3626837833783620},
               {0.1834346424956498, 0.3626837833783620}, {0.5255324099163290, 0.3137066458778873},
               {0.7966664774136267, 0.2223810344533745}, {0.9602898564975363, 0.1012285362903763}}

-- int_a^b K(x) dx.
local function kernel_integral(a, b)
  local function xlogx(x) return x == 0 and 0 or x * math.log(math.abs(x)) - x end
  local s = -2 * (xlogx(b) - xlogx(a))
  local m, h = 0.5 * (a + b), 0.5 * (b - a)
  for _, g in ipairs(gauss) do s = s + g[2] * h * smooth(m + h * g[1]) end
  return s
end

-- Solves the dense system M x = r (Gaussian elimination with partial pivoting).
local function linear_solve(Mat, r)
  local n = #r
  for c = 1, n do
    local piv = c
    for k = c + 1, n do if math.abs(Mat[k][c]) > math.abs(Mat[piv][c]) then piv = k end end
    Mat[c], Mat[piv], r[c], r[piv] = Mat[piv], Mat[c], r[piv], r[c]
    local rc = Mat[c]
    for k = c + 1, n do
      local f = Mat[k][c] / rc[c]
      if f ~= 0 then
        local rk = Mat[k]
        for j = c, n do rk[j] = rk[j] - f * rc[j] end
        r[k] = r[k] - f * r[c]
      end
    end
  end
  local x = {}
  for c = n, 1, -1 do
    local s = r[c]
    for j = c + 1, n do s = s - Mat[c][j] * x[j] end
    x[c] = s / Mat[c][c]
  end
  return x
end

function M.solve(load, panels, theta_max)
  assert(load > 0, "persson: the load must be positive")
  local N, d = panels, theta_max / panels
  local theta, A = {}, {}
  for i = 1, N do theta[i] = (i - 0.5) * d end
  for i = 1, N do
    A[i] = {}
    for j = 1, N do  -- the panel at +phi and its mirror at -phi; the a_0 term
      local a, b = (j - 1) * d, j * d
      A[i][j] = (kernel_integral(theta[i] - b, theta[i] - a) + kernel_integral(theta[i] + a, theta[i] + b)) / math.pi +
                2 * d / (2 * math.pi)
    end
  end
  local active = {}
  for i = 1, N do active[i] = theta[i] < math.sqrt(4 * load / math.pi) end  -- start: the Hertz arc
  local p, D = {}, 0
  for _ = 1, 200 do
    local idx = {}
    for i = 1, N do if active[i] then idx[#idx + 1] = i end end
    assert(#idx > 0, "persson: empty contact set")
    -- rows: gap = 0 on the active panels; last row: the force. Unknowns: p on the active panels, then D.
    local n = #idx
    local Mat, r = {}, {}
    for a, i in ipairs(idx) do
      local row = {}
      for b, j in ipairs(idx) do row[b] = A[i][j] end
      row[n + 1] = -math.cos(theta[i])
      Mat[a], r[a] = row, -(1 - math.cos(theta[i]))
    end
    local last = {}
    for b, j in ipairs(idx) do last[b] = 2 * d * math.cos(theta[j]) end
    last[n + 1] = 0
    Mat[n + 1], r[n + 1] = last, load
    local x = linear_solve(Mat, r)
    for i = 1, N do p[i] = 0 end
    for a, i in ipairs(idx) do p[i] = x[a] end
    D = x[n + 1]
    local changed = false
    for i = 1, N do
      if active[i] and p[i] < 0 then active[i], changed = false, true end
    end
    if not changed then
      for i = 1, N do
        if not active[i] then
          local g = (1 - math.cos(theta[i])) - D * math.cos(theta[i])
          for j = 1, N do g = g + A[i][j] * p[j] end
          if g < -1e-12 then active[i], changed = true, true end
        end
      end
    end
    if not changed then break end
  end
  -- The edge: p^2 linear in theta through the last three loaded panels.
  local last = 0
  for i = 1, N do if p[i] > 0 then last = i end end
  assert(last >= 4 and last < N, "persson: the contact must span more than 3 panels and end inside the range")
  local sx, sy, sxx, sxy = 0, 0, 0, 0
  for i = last - 2, last do
    local x, y = theta[i], p[i] ^ 2
    sx, sy, sxx, sxy = sx + x, sy + y, sxx + x * x, sxy + x * y
  end
  local c1 = (3 * sxy - sx * sy) / (3 * sxx - sx * sx)
  local c0 = (sy - c1 * sx) / 3
  return {alpha = -c0 / c1, theta = theta, p = p, D = D}
end

function M.hertz_alpha(load)
  return math.sqrt(4 * load / math.pi)
end

return M
