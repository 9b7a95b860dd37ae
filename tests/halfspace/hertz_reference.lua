-- Analytic Hertz solution for Lua-level tests: the same formulas as hertz_reference.hpp (Johnson, Contact
-- Mechanics, 1985, sections 3.6 and 4.2), for two bodies of the same material with combined modulus
-- Estar = E / (2 (1 - nu^2)). Undeformed inter-penetration h = delta - A x^2 - B y^2 (A = 1/(2 Rx),
-- B = 1/(2 Ry), m^-1). Load it with dofile(path) from a test; it returns a table of functions:
--   H.elliptic_ke(kp)                      -> K, E (complete elliptic integrals, modulus sqrt(1 - kp^2))
--   H.axis_ratio(q)                        -> b/a (minor/major) for the curvature ratio q = max/min >= 1
--   H.from_approach(A, B, Estar, delta)    -> {a =, b =, p0 =, force =, delta =} (a along x, b along y; SI)
--   H.from_force(A, B, Estar, F)           -> the same for a normal force F (N)
local H = {}

-- AGM: K = pi / (2 M(1, kp)), E = K (1 - sum 2^(n-1) c_n^2), c_0 = k.
function H.elliptic_ke(kp)
  assert(kp > 0 and kp <= 1, "elliptic_ke: kp must be in ]0, 1]")
  local a, b, c = 1.0, kp, math.sqrt((1 - kp) * (1 + kp))
  local sum, power = 0.5 * c * c, 0.5
  for _ = 1, 60 do
    if math.abs(c) <= 1e-17 * a then break end
    a, b, c = 0.5 * (a + b), math.sqrt(a * b), 0.5 * (a - b)
    power = power * 2
    sum = sum + power * c * c
  end
  local K = math.pi / (2 * a)
  return K, K * (1 - sum)
end

-- B/A = (E / kp^2 - K) / (K - E) decreases from infinity (kp -> 0) to 1 (kp -> 1): bisection on kp.
function H.axis_ratio(q)
  assert(q >= 1, "axis_ratio: q must be >= 1")
  if q == 1 then return 1.0 end
  local lo, hi = 1e-12, 1 - 1e-15
  for _ = 1, 200 do
    if hi - lo <= 1e-16 then break end
    local mid = 0.5 * (lo + hi)
    local K, E = H.elliptic_ke(mid)
    if (E / (mid * mid) - K) / (K - E) > q then lo = mid else hi = mid end
  end
  return 0.5 * (lo + hi)
end

function H.from_approach(A, B, Estar, delta)
  assert(A > 0 and B > 0 and Estar > 0 and delta > 0, "from_approach: bad input")
  local swap = A > B
  local Amin, Bmax = math.min(A, B), math.max(A, B)
  local kp = H.axis_ratio(Bmax / Amin)
  local major, minor, p0
  if kp == 1 then  -- circle: a^2 = R delta, p0 = 2 a E* / (pi R)
    major = math.sqrt(delta / (2 * Amin))
    minor = major
    p0 = 2 * major * Estar * 2 * Amin / math.pi
  else
    local K, E = H.elliptic_ke(kp)
    local e2 = (1 - kp) * (1 + kp)
    major = math.sqrt(delta * (K - E) / (Amin * K * e2))
    minor = kp * major
    p0 = delta * Estar / (minor * K)
  end
  local h = {delta = delta, p0 = p0}
  if swap then h.a, h.b = minor, major else h.a, h.b = major, minor end
  h.force = 2 / 3 * math.pi * h.a * h.b * p0
  return h
end

function H.from_force(A, B, Estar, F)
  assert(F > 0, "from_force: F must be positive")
  local unit = H.from_approach(A, B, Estar, 1e-6)
  return H.from_approach(A, B, Estar, 1e-6 * (F / unit.force) ^ (2 / 3))
end

return H
