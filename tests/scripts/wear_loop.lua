-- The wear loop (scripts/wear_loop.lua, examples/wear_evolution.lua) against independent references, at a reduced
-- size (coarse grid, few cases, few steps):
--   - the wheel volume each step removes, computed here from the profiles as solids of revolution (frustums), equals
--     the Archard volumes of the step's contact areas (p.wear_volume, weighted by share and distance) within 1 %,
--     with the area-preserving smoothing on;
--   - cases started from their equilibria on the profiles before wear the same profiles as cases started cold, with
--     fewer contact evaluations, and with the pressures and tractions they ended with there also with fewer products
--     of the exact tangential solver;
--   - halving the step size changes the worn area at the final km by < 2 % (a constant k over 600 km; the KTH map over
--     its running-in with the step control);
--   - the rails (rail_passes): the area each step removes from a rail, computed here with the shoelace formula, equals
--     the Archard volumes per metre rolled (m^3/m = m^2 per passage) times the step's passages within 1 %;
--   - mirrored cases wear mirrored profiles: the left wheel (rail) of one run is the right wheel (rail) of the other;
--   - on tangent track the rails wear where the contact points are;
--   - tangent-track cases alone wear a groove into the tread (deepest inside the running band, the flange and the
--     field side untouched) and raise tan gamma_e; curving cases with flange contact thin the flange (Sd falls);
--   - bad cases are refused with the key and the value.
local check = require "wrc.check"
local loop = require "wrc.wear_loop"

local wheel = wrc.profile.load("profiles/s1002.lua")
local rail = wrc.profile.load("profiles/60e1.lua")
local grid = 0.5e-3
local Q, V, mu = 200e3, 100 / 3.6, 0.3
local function initial() return loop.initial{wheel = wheel, rail = rail, wheelset = {grid = grid}} end
local m0 = loop.measures(initial(), {threads = 1})

-- The cases on the state's profiles: the curving ones pressed against the flange with 40 and 60 kN (or spec.forces).
local function cases(spec, st)
  local ws = loop.wheelset(st)
  return loop.generated_cases{Q = Q, V = V, mu = mu, tangent = spec.tangent, sigma = 1.5e-3, curves = spec.curves,
                              forces = spec.forces or {40e3, 60e3},
                              y_for_force = function(sign, Y, yaw, from, hint) return loop.y_for_force(ws, sign, Y, yaw, Q, from, hint) end,
                              previous = st.previous_cases}
end
local mixed = {tangent = 5, curves = {{radius = 500, yaw = 2.5e-3, share = 0.1},
                                      {radius = -500, yaw = 2.5e-3, share = 0.1}}}
local options = {step = 0.1e-3, smooth = 1e-3, wear = {}, threads = 2}
local function step(st, spec, o) return loop.step(st, function(state) return cases(spec, state) end, o or options) end

-- The volume between a wheel profile and its axle, as frustums of the polyline's segments turned about the axle
-- (radius r0 - z): pi (Ra^2 + Ra Rb + Rb^2) / 3 (yb - ya), signed along y so that folds cancel.
local function solid(y, z, r0)
  local v = 0
  for i = 1, #y - 1 do
    local a, b = r0 - z[i], r0 - z[i + 1]
    v = v + math.pi * (a * a + a * b + b * b) / 3 * (y[i + 1] - y[i])
  end
  return v
end

-- The area (m^2) between two polylines whose ends coincide (a profile before and after wear): the shoelace
-- formula over the first one and the second one backwards.
local function area_between(y1, z1, y2, z2)
  local py, pz = {}, {}
  for i = 1, #y1 do py[#py + 1], pz[#pz + 1] = y1[i], z1[i] end
  for i = #y2, 1, -1 do py[#py + 1], pz[#pz + 1] = y2[i], z2[i] end
  local a = 0
  for i = 1, #py do
    local j = i % #py + 1
    a = a + py[i] * pz[j] - py[j] * pz[i]
  end
  return math.abs(a) / 2
end
local RAIL_PASSES = 100  -- passages of the wheelset over a rail section per km it runs

do  -- volume per step against the Archard volumes, Euler's and Heun's (wheels), areas per passage (rails)
  local st = initial()
  -- The share-weighted Archard volume per metre rolled of one wheel over the cases' results.
  local function archard(list, results, side)
    local total, v = 0, 0
    for _, c in ipairs(list) do total = total + c.share end
    for i, e in ipairs(results) do
      check.ok(e.converged, "case " .. i .. " converged")
      for _, p in ipairs(e[side].patches) do v = v + list[i].share / total * p.wear_volume end
    end
    return v
  end
  for k = 1, 2 do
    local list = cases(mixed, st)
    -- The curving cases, placed from the roots of the step before in step 2 (the state's previous_cases): each one's
    -- equilibrium, solved here from a cold start, needs its lateral force within 1e-3.
    check.ok((k == 1) == (st.previous_cases == nil), "step 2 places its cases from the step before's")
    local ws = loop.wheelset(st)
    for _, c in ipairs(list) do
      if c.kind == "curve" then
        local e = ws:equilibrium{y = c.y, yaw = c.yaw, Q = Q}
        check.rel(e.Y, c.Y, 1e-3, ("step %d: the curving case placed for %.0f kN"):format(k, c.Y / 1e3))
      end
    end
    local euler_o, heun_o = {}, {}
    for key, v in pairs(options) do euler_o[key], heun_o[key] = v, v end
    euler_o.scheme, heun_o.scheme = "euler", "heun"
    euler_o.rail_passes, heun_o.rail_passes = RAIL_PASSES, RAIL_PASSES
    local res0 = loop.solve(loop.wheelset(st), list, options)
    local euler, info = loop.step(st, list, euler_o)
    local res1 = loop.solve(loop.wheelset(euler), list, options)  -- Heun's second rates: at Euler's profiles
    local heun = loop.step(st, list, heun_o)
    local distance = (euler.km - st.km) * 1000
    local heun_distance = (heun.km - st.km) * 1000  -- Euler's, or shorter where the mean rates reach deeper
    check.ok(heun_distance <= distance * (1 + 1e-12), "Heun's step runs at most Euler's distance")
    for _, side in ipairs{"left", "right"} do
      local a0, a1 = archard(list, res0, side), archard(list, res1, side)
      local before = solid(st.bodies[side .. "_wheel"].y, st.bodies[side .. "_wheel"].z, 0.45)
      for _, run in ipairs{{"Euler", euler, a0, distance}, {"Heun", heun, (a0 + a1) / 2, heun_distance}} do
        local b = run[2].bodies[side .. "_wheel"]
        local removed, expected = before - solid(b.y, b.z, 0.45), run[3] * run[4]
        print(("step %d %s wheel, %s: %.4f km, removed %.6g mm3, Archard %.6g mm3 (%+.3f %%)"):format(k, side, run[1],
              run[4] / 1000, removed * 1e9, expected * 1e9, (removed / expected - 1) * 100))
        check.rel(removed, expected, 0.01, ("step %d, %s wheel, %s: volume removed against Archard's"):format(k, side,
                  run[1]))
      end
      check.ok(info.depth[side .. "_wheel"] <= options.step * (1 + 1e-12), "the step's largest depth")
      -- The rail: per passage the cross-section the areas' Archard volume per metre rolled (m^3/m = m^2) wears off.
      local rail0 = st.bodies[side .. "_rail"]
      for _, run in ipairs{{"Euler", euler, a0, distance}, {"Heun", heun, (a0 + a1) / 2, heun_distance}} do
        local b = run[2].bodies[side .. "_rail"]
        local removed = area_between(rail0.y, rail0.z, b.y, b.z)
        local expected = run[3] * RAIL_PASSES * run[4] / 1000
        print(("step %d %s rail, %s: removed %.6g mm2, Archard %.6g mm2 (%+.3f %%)"):format(k, side, run[1],
              removed * 1e6, expected * 1e6, (removed / expected - 1) * 100))
        check.rel(removed, expected, 0.01, ("step %d, %s rail, %s: area removed against Archard's"):format(k, side,
                  run[1]))
      end
    end
    st = heun
  end
end

do  -- every case started from its equilibrium and the pressures and tractions it ended with on the profiles before
    -- (the default), from its equilibrium alone (warm = "equilibrium") and from the sweeps' own chains alone (warm =
    -- false): two Heun steps wear the same profiles (every point within 1e-3 of the step's depth, the distance within
    -- 1e-6), the equilibrium starts with fewer contact evaluations, the carried tractions with fewer products of the
    -- exact tangential solver. At omega = V / r0 (spin = "nominal"): the free spin's search adds a tolerance of its
    -- own, which depends on where it starts (tests/scripts/rolling_free.lua); these are the starts' own effects.
  local runs = {}
  for _, warm in ipairs{false, "equilibrium", true} do
    local st, evaluations, products = initial(), 0, 0
    local o = {warm = warm}
    for key, v in pairs(options) do o[key] = v end
    o.spin = "nominal"
    for _ = 1, 2 do
      local info
      st, info = step(st, mixed, o)
      evaluations, products = evaluations + info.evaluations, products + info.products
    end
    runs[#runs + 1] = {st = st, evaluations = evaluations, products = products, warm = tostring(warm)}
  end
  local a = runs[1]
  for k = 2, 3 do
    local b = runs[k]
    local worst, deepest = 0, 0
    for _, name in ipairs(loop.BODIES) do
      for i, v in ipairs(a.st.bodies[name].worn) do
        worst, deepest = math.max(worst, math.abs(v - b.st.bodies[name].worn[i])), math.max(deepest, v)
      end
    end
    print(("warm = %s: %d contact evaluations and %d tangential products in two steps, %d and %d without; worn " ..
           "depths differ by %.3g um at most (deepest %.3f mm)"):format(b.warm, b.evaluations, b.products,
           a.evaluations, a.products, worst * 1e6, deepest * 1e3))
    check.ok(deepest > options.step, "warm starts: the two steps wore the wheels")
    check.ok(worst <= 1e-3 * options.step, "warm = " .. b.warm .. ": the same worn profiles as without starts")
    check.rel(b.st.km, a.st.km, 1e-6, "warm = " .. b.warm .. ": the same distance as without starts")
    check.ok(b.evaluations < 0.8 * a.evaluations, "warm = " .. b.warm .. ": fewer contact evaluations")
  end
  check.ok(runs[3].products < 0.92 * runs[2].products, "carried tractions: fewer tangential products")
end

do  -- the exact tangential solver at the loop's tolerance (M.ROLLING_TOLERANCE, 1e-4 of the rigid slip) against 1e-6
    -- (wrc.wheelset's): one Heun step wears the same profiles (every point within 1e-5 of the step's depth, the
    -- distance within 1e-5) with fewer products, at omega = V / r0 (the free spin's search, noise-limited at 1e-4,
    -- would add its own tolerance); a tolerance out of range is refused with its key and value
  local runs = {}
  for _, tol in ipairs{1e-6, false} do
    local o = {rolling_tolerance = tol or nil}
    for key, v in pairs(options) do o[key] = v end
    o.spin = "nominal"
    local st, info = step(initial(), mixed, o)
    runs[#runs + 1] = {st = st, products = info.products}
  end
  local a, b = runs[1], runs[2]
  local worst = 0
  for _, name in ipairs(loop.BODIES) do
    for i, v in ipairs(a.st.bodies[name].worn) do worst = math.max(worst, math.abs(v - b.st.bodies[name].worn[i])) end
  end
  print(("rolling_tolerance %s: %d tangential products, %d at 1e-6; worn depths differ by %.3g nm at most, the " ..
         "distance by %.2g"):format(tostring(loop.ROLLING_TOLERANCE), b.products, a.products, worst * 1e9, b.st.km / a.st.km - 1))
  check.ok(worst <= 1e-5 * options.step, "rolling_tolerance: the same worn profiles as at 1e-6")
  check.rel(b.st.km, a.st.km, 1e-5, "rolling_tolerance: the same distance as at 1e-6")
  check.ok(b.products < 0.8 * a.products, "rolling_tolerance: fewer tangential products than at 1e-6")
  local o = {rolling_tolerance = 0.5}
  for key, v in pairs(options) do if key ~= "rolling_tolerance" then o[key] = v end end
  check.fails(function() step(initial(), mixed, o) end, "rolling_tolerance = 0.5", "a tolerance out of range")
end

do  -- halving the step: the worn area at the same km (Archard with a constant k: the KTH map's jumps of k, 60-fold
    -- where the pressure passes 0.8 H, make the first steps' running-in depend on the step: docs/guide/wear.md)
  local function run(depth, km_end)
    local st = initial()
    local o = {step = depth, smooth = 1e-3, wear = {k = 1e-4}, threads = 2, km_end = km_end}
    while st.km < km_end do st = step(st, mixed, o) end
    return loop.measures(st, {threads = 1}).left_wheel.worn_area, st.step
  end
  local a, na = run(0.1e-3, 600)
  local b, nb = run(0.05e-3, 600)
  print(("worn area at 600 km: %.5f mm2 (%d steps of 0.1 mm), %.5f mm2 (%d steps of 0.05 mm)"):format(a * 1e6, na,
        b * 1e6, nb))
  check.ok(nb > na, "the halved step takes more steps")
  check.rel(a, b, 0.02, "worn area at the final km with the step halved")
end

do  -- halving the step with the KTH map over its running-in (the first 2 km, where the pressure of a spot the last
    -- step made passes 0.8 H and its k jumps up to 60-fold): converged with the step control (tolerance = step / 10:
    -- a step is shortened until its Heun and Euler depths differ by less), not without it (14 % at 2 km)
  local function run(depth, km_end)
    local st = initial()
    local o = {step = depth, smooth = 1e-3, wear = {}, threads = 2, km_end = km_end, tolerance = depth / 10}
    local retries = 0
    while st.km < km_end do
      local info
      st, info = step(st, mixed, o)
      retries = retries + info.retries
    end
    return loop.measures(st, {threads = 1}).left_wheel.worn_area, st.step, retries
  end
  local a, na, ra = run(0.1e-3, 2)
  local b, nb, rb = run(0.05e-3, 2)
  print(("KTH map: worn area at 2 km: %.5f mm2 (%d steps of 0.1 mm, %d shortened), %.5f mm2 (%d steps of 0.05 mm, " ..
         "%d shortened)"):format(a * 1e6, na, ra, b * 1e6, nb, rb))
  check.ok(ra > 0 and rb > 0, "the step control shortened steps in the running-in")
  check.rel(a, b, 0.02, "KTH map: worn area at 2 km with the step halved")
end

-- Body `left` of run a is body `right` of run b and the other way round (the points of their profiles, each in its
-- own frame), within 1e-4 of the deepest wear; `unit` ("mm" or "um") is the one the deepest wear is printed in.
local function mirror_pair(a, b, left, right, deepest, unit)
  local scale = ({mm = 1e3, um = 1e6})[unit]
  for _, pair in ipairs{{left, right}, {right, left}} do
    local p, q = a.bodies[pair[1]], b.bodies[pair[2]]
    local worst = 0
    for i = 1, #p.y do worst = math.max(worst, math.abs(p.y[i] - q.y[i]), math.abs(p.z[i] - q.z[i])) end
    print(("mirror: %s against %s: largest difference %.3g um (deepest %.3g %s)"):format(pair[1], pair[2],
          worst * 1e6, deepest * scale, unit))
    check.ok(worst < 1e-4 * deepest, ("mirror: %s of one run is %s of the other"):format(pair[1], pair[2]))
  end
end

do  -- mirrored cases wear mirrored profiles
  local skew = {}
  for _, c in ipairs(cases(mixed, initial())) do  -- drop the symmetry: cases on one side only, and one curve
    if c.y >= 0 and not (c.radius and c.radius > 0) then skew[#skew + 1] = c end
  end
  local mirror = {}
  for i, c in ipairs(skew) do  -- fixed cases: the two runs see the same (mirrored) poses
    mirror[i] = {y = -c.y, yaw = -c.yaw, Q = c.Q, V = c.V, mu = c.mu, share = c.share,
                 radius = c.radius and -c.radius}
  end
  local a, b = initial(), initial()
  local o = {rail_passes = RAIL_PASSES}
  for key, v in pairs(options) do o[key] = v end
  for _ = 1, 2 do
    a = loop.step(a, skew, o)
    b = loop.step(b, mirror, o)
  end
  check.rel(a.km, b.km, 1e-6, "mirrored runs: the same distance")
  local deepest = 0
  for _, name in ipairs{"left_wheel", "right_wheel"} do
    for _, v in ipairs(a.bodies[name].worn) do deepest = math.max(deepest, v) end
  end
  check.ok(deepest > 0.1e-3, "the mirrored runs wore the wheels")
  mirror_pair(a, b, "left_wheel", "right_wheel", deepest, "mm")
  local la, ra = a.bodies.left_wheel, a.bodies.right_wheel
  local diff = 0
  for i = 1, #la.y do diff = math.max(diff, math.abs(la.z[i] - ra.z[i])) end
  check.ok(diff > 1e-5, "the skewed cases wear the two wheels differently (the check above is not trivial)")
  -- The rails (in their own frames, field side at -y, as the profile is given): the left rail of one run is the right
  -- rail of the other.
  local rail_deepest = 0
  for _, v in ipairs(a.bodies.left_rail.worn) do rail_deepest = math.max(rail_deepest, v) end
  check.ok(rail_deepest > 1e-6, "the mirrored runs wore the rails")
  mirror_pair(a, b, "left_rail", "right_rail", rail_deepest, "um")
  local lr, rr = a.bodies.left_rail, a.bodies.right_rail
  diff = 0
  for i = 1, #lr.y do diff = math.max(diff, math.abs(lr.z[i] - rr.z[i]), math.abs(lr.y[i] - rr.y[i])) end
  check.ok(diff > 0.1 * rail_deepest, "the skewed cases wear the two rails differently (the check above is not trivial)")
end

do  -- tangent track, one Euler step: the rails wear where the areas touch them. The worn area's centroid on the
    -- placed rail (track frame) against the centroid of the areas' grid rows weighted by the depth they wear per
    -- passage (p.wear_passage), and nothing worn farther than 10 mm from the outermost contact point.
  local st = initial()
  local list = loop.generated_cases{Q = Q, V = V, mu = mu, tangent = 7, sigma = 1.5e-3}
  local o = {rail_passes = RAIL_PASSES, scheme = "euler"}
  for key, v in pairs(options) do o[key] = v end
  local worn = loop.step(st, list, o)
  local results = loop.solve(loop.wheelset(st), list, options)
  local placed = loop.wheelset(st)
  for _, side in ipairs{"left", "right"} do
    local sy, sw, lo, hi = 0, 0, math.huge, -math.huge
    for i, e in ipairs(results) do
      for _, p in ipairs(e[side].patches) do
        lo, hi = math.min(lo, p.frame.origin.y), math.max(hi, p.frame.origin.y)
        for j = 1, p.grid.ny do  -- each grid row at its lateral position (track frame), weighted by its wear
          local y = p.rows and p.rows.y[j] or p.frame.origin.y + (p.grid.y0 + (j - 1) * p.grid.dy) * p.frame.t2.y
          local w = list[i].share * p.wear_passage[j] * p.grid.dy
          sy, sw = sy + w * y, sw + w
        end
      end
    end
    local b, pr = worn.bodies[side .. "_rail"], placed[side .. "_rail"]
    local n = #b.y
    local cy, cw, far = 0, 0, 0
    for i = 2, n - 1 do
      local k = pr.reversed and n + 1 - i or i  -- the placed point of body point i (the right rail runs backwards)
      local w = b.worn[i] * math.abs(b.y[i + 1] - b.y[i - 1]) / 2
      cy, cw = cy + w * pr.y[k], cw + w
      if pr.y[k] < lo - 0.01 or pr.y[k] > hi + 0.01 then far = math.max(far, b.worn[i]) end
    end
    local centre, contact = cy / cw, sy / sw
    print(("tangent, %s rail: worn centroid at y = %.2f mm, rows' wear %.2f mm (contact points %.2f .. %.2f), worn beyond +-10 mm " ..
           "of them %.3g um"):format(side, centre * 1e3, contact * 1e3, lo * 1e3, hi * 1e3, far * 1e6))
    check.ok(math.abs(centre - contact) < 0.2e-3, side .. " rail: worn where the areas wear it (within 0.2 mm)")
    check.ok(far == 0, side .. " rail: nothing worn far from the contact points")
  end
end

do  -- tangent track alone (a narrow lateral distribution, sigma 0.5 mm): a groove worn into the tread, conicity up
  local st = initial()
  local function narrow(state)
    return loop.generated_cases{Q = Q, V = V, mu = mu, tangent = 7, sigma = 0.5e-3}
  end
  for _ = 1, 2 do st = loop.step(st, narrow, options) end
  local m = loop.measures(st, {threads = 1})
  local b = st.bodies.left_wheel
  local deepest, at, outside = 0, nil, 0
  for i = 1, #b.y do
    if b.worn[i] > deepest then deepest, at = b.worn[i], b.y0[i] end
    if math.abs(b.y0[i]) > 0.03 then outside = math.max(outside, b.worn[i]) end
  end
  print(("tangent: %.1f km, deepest %.3f mm at s = %.1f mm, beyond +-30 mm %.3g mm, tan gamma_e %.4f -> %.4f"):format(
        st.km, deepest * 1e3, at * 1e3, outside * 1e3, m0.tan_gamma_e, m.tan_gamma_e))
  check.ok(deepest > 0.05e-3 and at > -0.012 and at < 0.012, "tangent track: worn within the running band")
  check.ok(outside == 0, "tangent track: the flange and the field side are not worn")
  check.ok(m.tan_gamma_e > m0.tan_gamma_e + 0.005, "tangent track: tan gamma_e rises")
end

do  -- curves alone: flange contact (80 and 100 kN: up the flange root toward Sd's height) thins the flange
  local st = initial()
  local curves = {tangent = 0, forces = {80e3, 100e3}, curves = {{radius = 500, yaw = 2.5e-3, share = 0.5},
                                                                 {radius = -500, yaw = 2.5e-3, share = 0.5}}}
  for _ = 1, 3 do st = step(st, curves) end
  local m = loop.measures(st, {threads = 1})
  print(("curves: %.3f km, Sd %.3f -> %.3f mm (left), %.3f -> %.3f mm (right)"):format(st.km, m0.left_wheel.Sd * 1e3,
        m.left_wheel.Sd * 1e3, m0.right_wheel.Sd * 1e3, m.right_wheel.Sd * 1e3))
  check.ok(m.left_wheel.Sd < m0.left_wheel.Sd - 0.05e-3, "curves: Sd of the left wheel falls")
  check.ok(m.right_wheel.Sd < m0.right_wheel.Sd - 0.05e-3, "curves: Sd of the right wheel falls")
end

do  -- the tangent cases solved while the curving ones are placed: generated_cases hands them to `early` before the
    -- first placement, and a step given the cases as a function of the state (which M.step calls with its `early`)
    -- wears the same bits as a step given the same cases as a list
  local st = initial()
  local ws = loop.wheelset(st)
  local function placed(state, early, order)
    return loop.generated_cases{Q = Q, V = V, mu = mu, tangent = 3, sigma = 1.5e-3, curves = mixed.curves,
                                forces = {40e3}, early = early, y_for_force = function(sign, Y, yaw, from, hint)
                                  if order then order[#order + 1] = "place" end
                                  return loop.y_for_force(ws, sign, Y, yaw, Q, from, hint)
                                end}
  end
  local order = {}
  local list = placed(st, function(l) order[#order + 1] = "early " .. #l end, order)
  check.ok(order[1] == "early 3" and order[2] == "place" and #list == 5,
           "early: the 3 tangent cases before the first placement (" .. table.concat(order, ", ") .. ")")
  local o = {scheme = "euler"}
  for key, v in pairs(options) do o[key] = v end
  local a = loop.step(st, list, o)
  local b = loop.step(st, placed, o)
  for _, name in ipairs(loop.BODIES) do
    local ba, bb = a.bodies[name], b.bodies[name]
    for i = 1, #ba.y do check.ok(ba.y[i] == bb.y[i] and ba.z[i] == bb.z[i], name .. ": the same bits either way") end
  end
  check.ok(a.km == b.km and a.km > 0, "early: the same distance")
end

-- Bad cases: the key and the value named.
check.fails(function() loop.generated_cases{Q = -1, V = V, mu = mu, tangent = 1, sigma = 1e-3} end,
            "generated case 1: Q = -1 must be a wheelset load", "a negative load")
local csv = os.tmpname()
local f = io.open(csv, "w")
f:write("y_mm,Q_kN,V_kmh,mu,share\n1,200,100,0.3,1\n2,200,100,,1\n")
f:close()
check.fails(function() loop.read_cases(csv) end, ":3: mu is empty (a number is needed)", "an empty mu")
-- An empty y_mm was a NaN ("y = -nan must be a lateral shift"); a cell that is no number is named with its text.
f = io.open(csv, "w")
f:write("y_mm,Q_kN,V_kmh,mu,share\n1,200,100,0.3,1\n,200,100,0.3,1\n")
f:close()
check.fails(function() loop.read_cases(csv) end, ":3: y_mm is empty (a number is needed)", "an empty y_mm")
f = io.open(csv, "w")
f:write("y_mm,Q_kN,V_kmh,mu,share\n1,200,100,0.3,1\n2,200,fast,0.3,1\n")
f:close()
check.fails(function() loop.read_cases(csv) end, ":3: V_kmh = 'fast' must be a number", "a word for a speed")
-- A number out of range in a case table, NaN as NaN.
check.fails(function() loop.generated_cases{Q = 0 / 0, V = V, mu = mu, tangent = 1, sigma = 1e-3} end,
            "generated case 1: Q = NaN must be a wheelset load", "a NaN load")
f = io.open(csv, "w")
f:write("y_mm,Q_kN,V_kmh,share\n1,200,100,1\n")
f:close()
check.fails(function() loop.read_cases(csv) end, "no column 'mu'", "a missing column")
os.remove(csv)
print("wear loop ok")
