-- wrc.wear_loop: the policy of a wear loop (docs/guide/wear.md): running cases, one wear step, the measures of a worn
-- wheelset. The numeric kernels are the engine's (wrc.wear, damage/profile_wear.hpp); examples/wear_evolution.lua
-- makes a study of it.
--
--   local loop = require "wrc.wear_loop"
--   local cases = loop.generated_cases{...} or loop.read_cases("cases.csv")
--   local state = loop.initial{wheel = p, rail = r, wheelset = {...}}     -- or left_wheel =, right_wheel =
--   state = loop.step(state, cases, {step = 1e-4, smooth = 1e-3, wear = {}, threads = 0})
--   local m = loop.measures(state)                                       -- worn area, Sh, Sd, qR, tan gamma_e
--
-- One step: every case solved (an equilibrium under its load, then rolling contact with the wear model at that pose:
-- cases sharing load, speed, friction, yaw and kinematics in one ws:sweep on all cores); each area's wear per passage
-- (p.wear_passage, per grid row: the depth summed along the rolling direction over the patch length) mapped onto
-- the profiles -- the wheel's spread over its circumference (divided by 2 pi R at the row's radius), the rail's per
-- passage -- as strips of the rows' width at the arc where the rows touch each profile; weighted by the cases'
-- shares of distance; smoothed (area-preserving); scaled so that the step's largest wheel depth is `step`; every
-- point moved along its normal by its depth.
local M = {}

local two_pi = 2 * math.pi

----------------------------------------------------------------------------------------------------------------
-- Cases

-- A case: y (m), yaw (rad), Q (N, the wheelset's load), V (m/s), mu, share (of the distance, > 0), and the
-- kinematics: radius (m; > 0 a curve toward +y, whose outer rail is the right one; < 0 toward -y; nil on tangent
-- track: yaw_rate = V / radius) or creepage = {xi, eta, phi} (prescribed at every area).
local function check_case(c, where)
  local function need(key, ok, what)
    if type(c[key]) ~= "number" or c[key] ~= c[key] or not ok(c[key]) then
      local v = c[key]
      error(("%s: %s = %s must be %s"):format(where, key, type(v) == "number" and wrc.number_text(v) or tostring(v), what), 0)
    end
  end
  need("y", function(v) return math.abs(v) <= 0.03 end, "a lateral shift within +-30 mm (m)")
  need("yaw", function(v) return math.abs(v) <= 0.1 end, "a yaw angle within +-0.1 rad")
  need("Q", function(v) return v > 0 and v < 2e6 end, "a wheelset load in ]0, 2e6[ N")
  need("V", function(v) return v ~= 0 and math.abs(v) < 200 end, "a speed in ]0, 200[ m/s")
  need("mu", function(v) return v > 0 and v <= 2 end, "a friction coefficient in ]0, 2]")
  need("share", function(v) return v > 0 end, "a share of the distance > 0")
  if c.radius ~= nil then need("radius", function(v) return math.abs(v) >= 10 end, "a curve radius >= 10 m (m)") end
end

-- Cases from a CSV table of a multibody run, one row per case, units in the column names: y_mm, Q_kN (the wheelset's
-- vertical load), V_kmh, mu, share (of the distance; normalised), and optionally yaw_mrad (0), radius_m (the curve:
-- > 0 a curve toward +y, < 0 toward -y, empty or 0 tangent track) or the creepages xi, eta, phi_1pm (all three).
function M.read_cases(path)
  local out = require "wrc.output"
  local columns, rows = out.read_csv(path)
  local known = {}
  for _, c in ipairs(columns) do known[c] = true end
  for _, c in ipairs{"y_mm", "Q_kN", "V_kmh", "mu", "share"} do
    if not known[c] then error(("%s: no column '%s' (needs y_mm, Q_kN, V_kmh, mu, share)"):format(path, c), 0) end
  end
  local cases = {}
  for i, r in ipairs(rows) do
    local where = ("%s:%d"):format(path, i + 1)
    for _, col in ipairs{"y_mm", "Q_kN", "V_kmh", "mu", "share"} do  -- an empty cell was a NaN, "y = -nan must be ..."
      if r[col] == nil then error(("%s: %s is empty (a number is needed)"):format(where, col), 0) end
      if type(r[col]) ~= "number" then
        error(("%s: %s = '%s' must be a number"):format(where, col, tostring(r[col])), 0)
      end
    end
    local c = {y = r.y_mm * 1e-3, yaw = (r.yaw_mrad or 0) * 1e-3, Q = r.Q_kN * 1e3, V = r.V_kmh / 3.6, mu = r.mu,
               share = r.share,
               radius = (r.radius_m and r.radius_m ~= 0) and r.radius_m or nil}
    if r.xi or r.eta or r.phi_1pm then
      if not (r.xi and r.eta and r.phi_1pm) then error(where .. ": give all of xi, eta, phi_1pm or none", 0) end
      if c.radius then error(where .. ": radius_m with prescribed creepages (one or the other)", 0) end
      c.creepage = {xi = r.xi, eta = r.eta, phi = r.phi_1pm}
    end
    check_case(c, where)
    cases[#cases + 1] = c
  end
  if #cases == 0 then error(path .. ": no cases", 0) end
  return cases
end

-- The equilibrium a curving case of `previous` (cases generated on profiles worn a little less) was placed at.
local function previous_hint(previous, radius, Y)
  for _, c in ipairs(previous or {}) do
    if c.hint and c.radius == radius and c.Y == Y then return c.hint end
  end
end

-- Generated cases (o: Q, V, mu, tangent = n, sigma (m), curves = {{radius =, yaw =, share =}, ...}, forces = {N, ...},
-- y_for_force = function(sign, Y, yaw, from, hint) -> y, root (M.y_for_force), previous = the cases generated on the
-- profiles before (their equilibria start the search; a state's `previous_cases`, set by M.step),
-- early = function(list) (optional: given the tangent cases before the curving ones are placed, e.g. the `early` M.step
-- hands a cases function, which starts their solves meanwhile)): n cases on tangent track at lateral shifts over
-- +-3 sigma weighted by a normal distribution (together the share 1 - the curves'), and per curve one case for each
-- lateral force in `forces`, the wheelset pressed with it against the curve's outer rail (y_for_force: the shift at
-- which the frictionless equilibrium needs that lateral force, M.y_for_force), with the curve's attack angle and yaw
-- rate.
function M.generated_cases(o)
  local cases, curve_share = {}, 0
  for _, cv in ipairs(o.curves or {}) do curve_share = curve_share + cv.share end
  assert(curve_share < 1 or (o.tangent or 0) == 0, "generated_cases: the curves' shares leave nothing to the tangent")
  local n = o.tangent or 0
  local weights, total = {}, 0
  for i = 1, n do
    local y = n == 1 and 0 or o.sigma * (-3 + 6 * (i - 1) / (n - 1))
    weights[i] = {y = y, w = math.exp(-0.5 * (y / o.sigma) ^ 2)}
    total = total + weights[i].w
  end
  for _, w in ipairs(weights) do
    cases[#cases + 1] = {y = w.y, yaw = 0, Q = o.Q, V = o.V, mu = o.mu, share = (1 - curve_share) * w.w / total,
                         kind = "tangent"}
  end
  if o.early and #cases > 0 then o.early({table.unpack(cases)}) end
  for _, cv in ipairs(o.curves or {}) do
    local sign = cv.radius > 0 and -1 or 1  -- a curve toward +y has its outer rail at -y: flange on the right
    local forces = {table.unpack(o.forces)}
    table.sort(forces)
    local from, last = nil, nil  -- |y| of the last force: the next one's lower bound; its equilibrium
    for _, force in ipairs(forces) do
      local yaw = sign * math.abs(cv.yaw)
      local y, root = o.y_for_force(sign, sign * force, yaw, from, previous_hint(o.previous, cv.radius, sign * force) or last)
      from, last = math.abs(y), root
      cases[#cases + 1] = {y = y, yaw = yaw, Q = o.Q, V = o.V, mu = o.mu, radius = cv.radius,
                           share = cv.share / #forces, kind = "curve", Y = sign * force, hint = root}
    end
  end
  for i, c in ipairs(cases) do check_case(c, "generated case " .. i) end
  return cases
end

-- The lateral shift y (m) at which the frictionless equilibrium of the wheelset under Q (N) at yaw (rad) needs the
-- lateral force Y (N; > 0 toward the left rail: the left flange, sign 1; < 0 the right, sign -1), to |Y error| <=
-- 1e-3 |Y| or 1e-8 m of y: regula falsi (Illinois) on |y| between `from` (m, default 0) and where the wheel's flange
-- touches its rail rigidly (M.flange_contact) plus 0.5 mm, grown by 0.5 mm up to 2.5 mm while Y is not reached (a worn
-- flange). `hint` (optional, {y = |y|, z =, roll =}: the equilibrium this returned for the same force on profiles worn
-- a little less) starts the search: the bracket is grown from it in steps of 2 um x 4^k. Every equilibrium starts
-- from the nearest one evaluated before (a cold one costs 20 times more).
-- Returns y and the hint of the root ({y = |y|, z =, roll =}).
local HINT_STEP = 2e-6
function M.y_for_force(ws, sign, Y, yaw, Q, from, hint)
  local seen = {hint}
  local function excess(y)
    local near
    for _, p in ipairs(seen) do
      if not near or math.abs(p.y - y) < math.abs(near.y - y) then near = p end
    end
    local e = ws:equilibrium{y = sign * y, yaw = yaw, Q = Q, on_failure = "return",
                             start = near and {z = near.z, roll = near.roll} or nil}
    if not e.converged then error(("no equilibrium at y = %.4f mm: %s"):format(sign * y * 1e3, tostring(e.error)), 0) end
    seen[#seen + 1] = {y = y, z = e.z, roll = e.roll}
    return sign * (e.Y - Y)
  end
  local function done(y, fy) return math.abs(fy) <= 1e-3 * math.abs(Y), sign * y, seen[#seen] end
  local flange = M.flange_contact(ws, sign)
  if not flange then error("y_for_force: no flange contact within 15 mm", 0) end
  local lo, hi = from or 0, flange + 0.5e-3
  local a, b, fa, fb
  if hint and hint.y >= lo and hint.y < hi then  -- grow a bracket from the hint
    local y, fy = hint.y, excess(hint.y)
    local ok, ys, root = done(y, fy)
    if ok then return ys, root end
    local dir, h = fy < 0 and 1 or -1, HINT_STEP
    while true do
      local y2 = dir > 0 and math.min(hi, y + h) or math.max(lo, y - h)
      local f2 = excess(y2)
      ok, ys, root = done(y2, f2)
      if ok then return ys, root end
      if (f2 < 0) ~= (fy < 0) then
        if dir > 0 then a, fa, b, fb = y, fy, y2, f2 else a, fa, b, fb = y2, f2, y, fy end
        break
      end
      if y2 == lo or y2 == hi then a, b = nil, nil break end  -- no sign change up to the end: the whole range
      y, fy, h = y2, f2, 4 * h
    end
  end
  if not a then
    a, b = lo, hi
    fa, fb = excess(a), excess(b)
  end
  for _ = 1, 4 do  -- a worn flange may carry Y only deeper than 0.5 mm past its rigid touch: look up to 2.5 mm past
    if fa > 0 or fb >= 0 then break end
    a, fa, b = b, fb, b + 0.5e-3
    fb = excess(b)
  end
  if fa > 0 or fb < 0 then
    error(("no lateral shift between %.3f and %.3f mm needs Y = %.1f kN (it runs from %.1f to %.1f kN)"):format(
          sign * a * 1e3, sign * b * 1e3, Y / 1e3, (sign * fa + Y) / 1e3, (sign * fb + Y) / 1e3), 0)
  end
  local side = 0
  for _ = 1, 100 do
    local y = (a * fb - b * fa) / (fb - fa)
    local fy = excess(y)
    local ok, ys, root = done(y, fy)
    if ok or b - a < 1e-8 then return ys, root end
    if fy < 0 then
      a, fa = y, fy
      if side == -1 then fb = fb / 2 end
      side = -1
    else
      b, fb = y, fy
      if side == 1 then fa = fa / 2 end
      side = 1
    end
  end
  error(("no convergence to Y = %.1f kN"):format(Y / 1e3), 0)
end

-- Cases that share everything but y are one sweep; the same y twice adds the shares.
local function case_key(c)
  local k = ("%.17g|%.17g|%.17g|%.17g|%.17g|%s"):format(c.yaw, c.Q, c.V, c.mu, c.radius or 0, c.creepage and
            ("%.17g,%.17g,%.17g"):format(c.creepage.xi, c.creepage.eta, c.creepage.phi) or "-")
  return k
end

local function groups_of(cases)
  local groups, order = {}, {}
  for i, c in ipairs(cases) do
    local k = case_key(c)
    if not groups[k] then
      groups[k] = {case = c, ys = {}, members = {}}
      order[#order + 1] = k
    end
    local g = groups[k]
    local y = ("%.17g"):format(c.y)
    if not g.members[y] then
      g.ys[#g.ys + 1] = c.y
      g.members[y] = {}
    end
    table.insert(g.members[y], i)
  end
  local list = {}
  for _, k in ipairs(order) do list[#list + 1] = groups[k] end
  return list
end

----------------------------------------------------------------------------------------------------------------
-- The state: profiles as point arrays (their own frames), what stays fixed, and the distance run

local function profile_of(kind, y, z, name) return wrc.profile.points{kind = kind, y = y, z = z, name = name} end

local function body(kind, p)
  local y, z = p:points()
  return {kind = kind, y = y, z = z, y0 = y, z0 = z, worn = {}, name = p.name}
end

-- s = {wheel = or left_wheel =, right_wheel =, rail = or left_rail =, right_rail =, wheelset = {other keys of
-- wrc.wheelset}}
function M.initial(s)
  local st = {km = 0, step = 0, params = s.wheelset or {}, bodies = {}}
  st.bodies.left_wheel = body("wheel", s.left_wheel or s.wheel)
  st.bodies.right_wheel = body("wheel", s.right_wheel or s.wheel)
  st.bodies.left_rail = body("rail", s.left_rail or s.rail)
  st.bodies.right_rail = body("rail", s.right_rail or s.rail)
  for _, b in pairs(st.bodies) do
    for i = 1, #b.y do b.worn[i] = 0 end
  end
  return st
end

M.BODIES = {"left_wheel", "right_wheel", "left_rail", "right_rail"}

-- The wheelset of the state's profiles (`overrides`: other keys of wrc.wheelset, e.g. a coarser grid).
function M.wheelset(st, overrides)
  local o = {}
  for k, v in pairs(st.params) do o[k] = v end
  for k, v in pairs(overrides or {}) do o[k] = v end
  for _, name in ipairs(M.BODIES) do
    local b = st.bodies[name]
    o[name] = profile_of(b.kind, b.y, b.z, ("%s step %d"):format(b.name or name, st.step))
  end
  return wrc.wheelset(o)
end

----------------------------------------------------------------------------------------------------------------
-- Solving the cases

-- The exact tangential solver's tolerance in the loop (rolling_tolerance; wrc.wheelset's default is 1e-6): it stops
-- when every element's slip (in the adhesion zone) and its traction's distance to the bound (in the slip zone, as a
-- slip) are within it times the rigid slip, so the slips that wear is made of are within 1e-4 of it. The example's
-- evolution.csv moves by at most 7e-6 relative over 20 steps (docs/guide/wear.md, Speed); the solves need 25-55 %
-- fewer products.
M.ROLLING_TOLERANCE = 1e-4

local function sweep_keys(ws, g, o, warm)
  if o.spin ~= nil and o.spin ~= "free" and o.spin ~= "nominal" then
    error("wear step: spin = " .. tostring(o.spin) .. " must be \"free\" (the torque-free spin) or \"nominal\" "
          .. "(omega = V / r0)", 0)
  end
  local c = g.case
  local k = {y = g.ys, yaw = {c.yaw}, Q = c.Q, V = c.V, mu = c.mu, wear = o.wear or {}, method = o.method,
             rolling_tolerance = o.rolling_tolerance or M.ROLLING_TOLERANCE,
             rows = true, chain = o.chain or ((warm and #g.ys <= 8) and 2 or 8), progress = false}
  if c.creepage then k.creepage = c.creepage
  else
    if c.radius then k.yaw_rate = c.V / c.radius end
    k.free_rolling = o.spin == "free" or nil  -- the balanced spin; "nominal" (default): omega = V / r0
  end
  -- Chains of 8 (a chunk's first case starts from its equilibrium on the profiles before, or cold); a small group
  -- (the curving cases: 5 on one side of y = 0, one chain of 4 after the centre) with those starts (`warm`) in
  -- pieces of 2, so that two threads share it (cold, each piece would cost 10 times more). No more threads than
  -- chunks (a small group would say that it used fewer).
  local chunks = #ws:sweep_plan{y = k.y, yaw = k.yaw, chain = k.chain}.chunks
  k.threads = math.max(1, math.min((o.threads or 0) > 0 and o.threads or wrc.cores, chunks))
  return k
end

-- Which case of the profiles before a case continues: its kinematics and its lateral force (a curving case, whose y
-- moves as the flange wears) or its y.
local function start_key(c) return case_key(c) .. "|" .. (c.Y and ("Y%.17g"):format(c.Y) or ("%.17g"):format(c.y)) end

-- The sweeps of a state's cases, each started on threads of its own (ws:sweep_start) as soon as its group's cases are
-- known, so that the script goes on meanwhile (placing the curving cases while the tangent ones are solved). `starts`
-- as M.solve's. start(cases) starts the groups not started yet (a group is its sweep key and its y values);
-- finish(cases, each) starts the rest, calls each(i, result), if given, for the cases in the list's order as soon as
-- a case and the ones before it are solved, and returns M.solve's results. Every case's result is the same whichever
-- sweeps ran together: no case depends on the thread that solves it.
local function solver(ws, o, starts)
  local jobs = {}
  local function id(g)
    local ys = {}
    for k, y in ipairs(g.ys) do ys[k] = ("%.17g"):format(y) end
    return case_key(g.case) .. "|" .. table.concat(ys, ",")
  end
  local function start(cases)
    for _, g in ipairs(groups_of(cases)) do
      local key = id(g)
      if not jobs[key] then
        local keys = sweep_keys(ws, g, o, starts ~= nil)
        keys.contact_starts = o.warm ~= false and o.warm ~= "equilibrium"
        if starts then
          local z, roll, contact = {}, {}, {}
          for k, y in ipairs(g.ys) do
            local s = starts[start_key(cases[g.members[("%.17g"):format(y)][1]])]
            z[k], roll[k] = s and s.z or 0 / 0, s and s.roll or 0 / 0
            contact[k] = keys.contact_starts and s and s.contact or false
          end
          keys.starts = {z = z, roll = roll, contact = contact}
        end
        jobs[key] = ws:sweep_start(keys)
      end
    end
  end
  local function finish(cases, each)
    start(cases)
    local results, next_starts, done = {}, {}, 0
    for _, g in ipairs(groups_of(cases)) do
      local s = jobs[id(g)]:wait()
      for k, y in ipairs(g.ys) do
        for _, i in ipairs(g.members[("%.17g"):format(y)]) do
          results[i] = s[k]
          if s[k].converged then
            next_starts[start_key(cases[i])] = {z = s[k].z, roll = s[k].roll, contact = s[k].contact_start}
          end
        end
      end
      while each and results[done + 1] do
        done = done + 1
        each(done, results[done])
      end
    end
    return results, next_starts
  end
  return {start = start, finish = finish}
end

-- Every case solved: results[i] = the equilibrium with its rolling contact (e.converged false: failed). `starts`
-- (optional): by start_key, the equilibria {z =, roll =} and the pressures and tractions they ended with (contact:
-- ws:sweep's contact_start) of the cases solved on profiles worn a little less, which start each case's (ws:sweep's
-- starts). Returns the results and the starts they give the next profiles.
function M.solve(ws, cases, o, starts)
  return solver(ws, o, starts).finish(cases)
end

----------------------------------------------------------------------------------------------------------------
-- Rows onto the profiles

-- The track-frame points of an area's grid rows (conformal: on the rail's surface; planar: on the contact plane).
local function row_points(p)
  local X, Y, Z = {}, {}, {}
  local o, t2 = p.frame.origin, p.frame.t2
  for j = 1, p.grid.ny do
    if p.rows then
      X[j], Y[j], Z[j] = o.x, p.rows.y[j], p.rows.z[j]
    else
      local v = p.grid.y0 + (j - 1) * p.grid.dy
      X[j], Y[j], Z[j] = o.x + v * t2.x, o.y + v * t2.y, o.z + v * t2.z
    end
  end
  return X, Y, Z
end

-- A track-frame point in the wheelset frame of the pose e (docs/design.md, section 2: p = (0, y, z) + Rz Rx p_w).
local function to_wheelset(e, X, Y, Z)
  local qx, qy, qz = X, Y - e.y, Z - e.z
  local cy, sy, cr, sr = math.cos(e.yaw), math.sin(e.yaw), math.cos(e.roll), math.sin(e.roll)
  local ux, uy = cy * qx + sy * qy, -sy * qx + cy * qy
  return ux, cr * uy + sr * qz, -sr * uy + cr * qz
end

-- Strips of one wheel's areas on its profile and on its rail's: arc centre (m), width (m), area (m^2) per metre
-- rolled (wheel) and per passage (rail), and the areas' Archard volume per metre rolled (m^3/m).
local function wheel_strips(st, e, side, strips)
  local sign = side == "left" and 1 or -1
  local y_tape = st.y_tape
  local r0 = st.r0
  local wheel, rail = st.bodies[side .. "_wheel"], st.placed[side .. "_rail"]
  local ws_, wz_, ws_w, ry, rz, ra = {}, {}, {}, {}, {}, {}
  local volume = 0
  for _, p in ipairs(e[side].patches) do
    if p.wear_passage and p.normal_force > 0 then
      volume = volume + p.wear_volume
      local X, Y, Z = row_points(p)
      for j = 1, p.grid.ny do
        local d = p.wear_passage[j]
        if d > 0 then
          local px, py, pz = to_wheelset(e, X[j], Y[j], Z[j])
          local R = math.sqrt(px * px + pz * pz)
          ws_[#ws_ + 1], wz_[#wz_ + 1] = sign * py - y_tape, r0 - R
          ws_w[#ws_w + 1] = d * p.grid.dy / (two_pi * R)  -- spread over the circumference: per metre rolled
          ry[#ry + 1], rz[#rz + 1], ra[#ra + 1] = Y[j], Z[j], d * p.grid.dy
          strips.dy[#strips.dy + 1] = p.grid.dy
        end
      end
    end
  end
  if #ws_ == 0 then return volume end
  local arc_w = wrc.wear.project{y = wheel.y, z = wheel.z, points_y = ws_, points_z = wz_}
  local arc_r = wrc.wear.project{y = rail.y, z = rail.z, points_y = ry, points_z = rz}
  local n0 = #strips.dy - #ws_
  for k = 1, #ws_ do
    local w = strips.weight
    local t = strips[side .. "_wheel"]
    t.centre[#t.centre + 1], t.width[#t.width + 1], t.area[#t.area + 1] = arc_w[k], strips.dy[n0 + k], w * ws_w[k]
    local r = strips[side .. "_rail"]
    -- The placed right rail runs the other way round: its arc from the profile's first point is the total minus.
    local a = rail.reversed and (rail.length - arc_r[k]) or arc_r[k]
    r.centre[#r.centre + 1], r.width[#r.width + 1], r.area[#r.area + 1] = a, strips.dy[n0 + k], w * ra[k]
  end
  return volume
end

-- Where the state's rails are placed (track frame), for the rows found on their surfaces.
local function placed_rails(st, ws)
  local placed = {}
  for _, side in ipairs{"left", "right"} do
    local pr = ws[side .. "_rail"]
    local arc = wrc.wear.arc_length{y = pr.y, z = pr.z}
    placed[side .. "_rail"] = {y = pr.y, z = pr.z, reversed = pr.reversed, length = arc[#arc]}
  end
  return placed
end

----------------------------------------------------------------------------------------------------------------
-- One step

-- The wear rates of a state: per body the depth per point (m) per metre rolled (wheels) or per passage (rails),
-- smoothed; the Archard volume per metre rolled of each wheel (m^3/m, share-weighted); the failed cases. `cases`: a
-- list, or M.step's function of the state (called with the state and `early`, which starts the solves of the cases
-- it is given while the function places the others). Returns the rates and the list of cases.
local function rates(st, cases, o)
  local ws = M.wheelset(st)
  local geo = {bodies = st.bodies, y_tape = ws.params.back_to_back / 2 + ws.params.tape_offset,
               r0 = ws.params.radius, placed = placed_rails(st, ws)}
  local solve = solver(ws, o, o.warm ~= false and st.starts or nil)
  if type(cases) == "function" then cases = cases(st, solve.start) end
  local strips = {dy = {}}
  for _, name in ipairs(M.BODIES) do strips[name] = {centre = {}, width = {}, area = {}} end
  local total_share = 0
  for _, c in ipairs(cases) do total_share = total_share + c.share end
  local r = {cases = #cases, failed = 0, archard = {left = 0, right = 0}, errors = {}, rate = {},
             evaluations = 0, products = 0}
  -- Each case mapped in the list's order (the sums' order) as soon as it and the ones before it are solved: the
  -- tangent cases while the curving ones still are.
  local function map(i, e)
    r.evaluations = r.evaluations + (e.evaluations or 0)
    for _, side in ipairs{"left", "right"} do
      for _, p in ipairs(e[side] and e[side].patches or {}) do r.products = r.products + (p.creep_products or 0) end
    end
    if e.converged then
      strips.weight = cases[i].share / total_share
      for _, side in ipairs{"left", "right"} do
        r.archard[side] = r.archard[side] + strips.weight * wheel_strips(geo, e, side, strips)
      end
    else
      r.failed = r.failed + 1
      r.errors[#r.errors + 1] = ("case %d: %s"):format(i, tostring(e.error))
    end
  end
  local _, starts = solve.finish(cases, map)
  r.starts = starts
  for _, name in ipairs(M.BODIES) do
    local b = st.bodies[name]
    local arc = wrc.wear.arc_length{y = b.y, z = b.z}
    local sp = strips[name]
    local d = #sp.centre > 0 and wrc.wear.deposit{arc = arc, centre = sp.centre, width = sp.width, area = sp.area}
    if d and o.smooth > 0 then d = wrc.wear.smooth{arc = arc, depth = d, length = o.smooth} end
    r.rate[name] = d or nil
  end
  return r, cases
end

-- A profile must be monotone in y (wrc.profile.points). On a flange face steeper than 80 degrees, points 0.1 mm apart
-- in y moved along their normals by depths that differ can pass each other; such a point is put 1 um past its
-- neighbour (the area it moves is of the order of the difference, far below the step's). Returns how many were.
local UNTANGLE = 1e-6
local function untangle(y)
  local dir = y[#y] > y[1] and 1 or -1
  local n = 0
  for i = 2, #y do
    if dir * (y[i] - y[i - 1]) < UNTANGLE then
      y[i] = y[i - 1] + dir * UNTANGLE
      n = n + 1
    end
  end
  return n
end

-- The state after running `distance` (m) at the rates (rail passages: rail_passes per km).
local function advance(st, rate, distance, o, km)
  local new = {km = km, step = st.step + 1, params = st.params, bodies = {}}
  local passes = (o.rail_passes or 0) * distance / 1000
  local depth_max = {}
  for _, name in ipairs(M.BODIES) do
    local b = st.bodies[name]
    local factor = b.kind == "wheel" and distance or passes
    local d = rate[name]
    depth_max[name] = 0
    if d and factor > 0 then
      local depth, worn = {}, {}
      for i = 1, #d do
        depth[i] = factor * d[i]
        worn[i] = b.worn[i] + depth[i]
        depth_max[name] = math.max(depth_max[name], depth[i])
      end
      local y, z = wrc.wear.move{y = b.y, z = b.z, depth = depth, kind = b.kind}
      new.folds = (new.folds or 0) + untangle(y)
      new.bodies[name] = {kind = b.kind, y = y, z = z, y0 = b.y0, z0 = b.z0, worn = worn, name = b.name}
    else
      new.bodies[name] = b
    end
  end
  return new, depth_max
end

-- The largest difference between two wheel rates (m/m) over the points of both wheels.
local function largest_difference(a, b)
  local big = 0
  for _, name in ipairs{"left_wheel", "right_wheel"} do
    local x, y = a[name], b[name]
    for i = 1, x and #x or y and #y or 0 do big = math.max(big, math.abs((x and x[i] or 0) - (y and y[i] or 0))) end
  end
  return big
end
local MAX_RETRIES = 8

local function mean_rate(a, b)
  local m = {}
  for _, name in ipairs(M.BODIES) do
    if a[name] or b[name] then
      local x, y, v = a[name], b[name], {}
      for i = 1, #(x or y) do v[i] = ((x and x[i] or 0) + (y and y[i] or 0)) / 2 end
      m[name] = v
    end
  end
  return m
end

-- `cases`: a list, or a function(state, early) -> list (cases placed on the state's profiles, e.g. from its flanges;
-- the state's `previous_cases` are the list placed on the profiles before, to start from; early(list), optional,
-- starts the solves of the cases in `list`, those of the final list that need no placing, while it places the others:
-- M.generated_cases' key `early`).
-- o = {step = m (the largest wheel depth of the step), smooth = m (the smoothing's standard deviation), wear = {...}
-- (the wear model's keys), method =, rolling_tolerance = (the exact solver's; default M.ROLLING_TOLERANCE), spin =
-- "nominal" (default: omega = V / r0) | "free" (each case with kinematics rolls at the omega that balances its axle
-- torque, free_rolling: docs/guide/wear.md), cases with prescribed
-- creepages keep them either way,
-- threads =, chain =, rail_passes = (passages of the wheelset over a rail
-- section per km it runs; 0: the rails are not worn), km_end = km (a step ends there at the latest), scheme =
-- "heun" (default: the rates at the start and at the profiles an Euler step gives, averaged -- second order in the
-- step, the cases solved twice) | "euler" (the rates at the start), tolerance = m (Heun: the largest difference
-- between the Heun and the Euler depth of a wheel point allowed in a step; a step over it is shortened by
-- 0.9 sqrt(tolerance / difference), at most 8 times, its second rates computed again: it resolves the KTH map's jumps
-- of k; nil: no control), warm = false (every case's equilibrium and rolling contact from the sweep's own chains
-- alone; default true: each case starts from its equilibrium and the pressures and exact tangential tractions it
-- ended with on the profiles before, the state's `starts`, which the step hands on; "equilibrium": from its
-- equilibrium alone)}. The
-- distance of the step is the one at which the start's rates wear `step` off the wheel's deepest point, shorter when
-- Heun's mean rates reach deeper or the control shortens it. Returns the new state
-- and what the step did: the distance (m), the largest depth per body (m), the wheels' Archard volumes over the step
-- (m^3), the cases and failed cases, the times the control shortened it (retries), the contact evaluations of the
-- cases' equilibria (evaluations) and the exact tangential solver's products on the areas' grids (products).
function M.step(st, cases, o)
  if o.tolerance ~= nil and not (type(o.tolerance) == "number" and o.tolerance > 0) then
    local t = o.tolerance
    error("wear step: tolerance = " .. (type(t) == "number" and wrc.number_text(t) or tostring(t))
          .. " must be a depth > 0 (m) or nil", 0)
  end
  local r0, cases0 = rates(st, cases, o)
  local largest = 0
  for _, name in ipairs{"left_wheel", "right_wheel"} do
    for _, v in ipairs(r0.rate[name] or {}) do largest = math.max(largest, v) end
  end
  if largest <= 0 then error("wear step: no case wore the wheels (every case failed or had no slip)", 0) end
  local distance, km = o.step / largest, nil
  if o.km_end and st.km + distance / 1000 >= o.km_end then  -- the last step: ends there
    distance, km = (o.km_end - st.km) * 1000, o.km_end
  end
  km = km or st.km + distance / 1000
  local rate, archard = r0.rate, {left = r0.archard.left, right = r0.archard.right}
  local cases1, r1 = nil, nil
  local failed, errors, evaluations, products = r0.failed, r0.errors, r0.evaluations, r0.products
  local retries = 0
  if (o.scheme or "heun") == "heun" then
    while true do
      local predicted = advance(st, r0.rate, distance, o, km)
      predicted.previous_cases, predicted.starts = cases0, r0.starts
      r1, cases1 = rates(predicted, cases, o)
      evaluations, products = evaluations + r1.evaluations, products + r1.products
      -- Heun's depth minus Euler's: the local error of the Euler step, an upper bound of Heun's.
      local err = distance * largest_difference(r0.rate, r1.rate) / 2
      if not o.tolerance or err <= o.tolerance or retries >= MAX_RETRIES then break end
      distance = distance * math.max(0.1, 0.9 * math.sqrt(o.tolerance / err))
      km = st.km + distance / 1000
      retries = retries + 1
    end
    rate = mean_rate(r0.rate, r1.rate)
    archard.left, archard.right = (r0.archard.left + r1.archard.left) / 2, (r0.archard.right + r1.archard.right) / 2
    failed = failed + r1.failed
    for _, e in ipairs(r1.errors) do errors[#errors + 1] = e end
  elseif o.scheme ~= "euler" then
    error("wear step: scheme = " .. tostring(o.scheme) .. " must be \"heun\" or \"euler\"", 0)
  end
  -- Heun's mean can be steeper than the start's rates where the Euler step made a new spot of high pressure (the KTH
  -- map's seizure): the distance then shrinks so that the step's largest wheel depth stays `step`.
  local mean_largest = 0
  for _, name in ipairs{"left_wheel", "right_wheel"} do
    for _, v in ipairs(rate[name] or {}) do mean_largest = math.max(mean_largest, v) end
  end
  if mean_largest * distance > o.step then
    distance = o.step / mean_largest
    km = st.km + distance / 1000
  end
  local new, depth = advance(st, rate, distance, o, km)
  new.previous_cases, new.starts = cases1 or cases0, r1 and r1.starts or r0.starts
  return new, {folds = new.folds or 0, distance = distance, depth = depth, archard = {left = archard.left * distance,
               right = archard.right * distance}, cases = r0.cases, failed = failed, errors = errors, retries = retries,
               evaluations = evaluations, products = products}
end

----------------------------------------------------------------------------------------------------------------
-- Measures

-- The volume of revolution (m^3) between a wheel's profile before and after (points moved one to one): each
-- quadrilateral of the two polylines turned about the axle at its centroid's radius (Pappus), r0 - z the radius.
function M.volume_between(r0, y1, z1, y2, z2)
  local v = 0
  for i = 1, #y1 - 1 do
    local qy = {y1[i], y1[i + 1], y2[i + 1], y2[i]}
    local qz = {z1[i], z1[i + 1], z2[i + 1], z2[i]}
    local a, cy = 0, 0
    -- Signed area and z-moment of the quadrilateral, relative to its first corner.
    for k = 1, 4 do
      local l = k % 4 + 1
      local ay, az, by, bz = qy[k] - qy[1], qz[k] - qz[1], qy[l] - qy[1], qz[l] - qz[1]
      local cross = ay * bz - by * az
      a = a + cross / 2
      cy = cy + (az + bz) * cross / 6
    end
    if a ~= 0 then v = v + two_pi * (r0 - (qz[1] + cy / a)) * a end
  end
  return math.abs(v)
end

-- The lateral shift (m, > 0) at which the wheel on one side (sign 1: left, -1: right) first touches its rail with its
-- flange: where its rigid contact point (yaw 0, roll held) becomes steeper than 45 degrees, found by bisection to
-- 1e-8 m within 15 mm (nil when it stays below). Curving cases are placed from it, so that wear, which moves the flange
-- away, does not relieve a prescribed flange contact by itself.
function M.flange_contact(ws, sign)
  local side = sign > 0 and "left" or "right"
  local function steep(y) return ws:rigid{y = sign * y, yaw = 0, roll = "fixed"}[side].angle > math.rad(45) end
  local lo, hi = 0, 15e-3
  if not steep(hi) then return nil end
  while hi - lo > 1e-8 do
    local mid = (lo + hi) / 2
    if steep(mid) then hi = mid else lo = mid end
  end
  return hi
end

-- The measures of the state: per wheel the worn area (m^2, between its first and its present profile), the largest
-- depth worn since the start (m), Sh, Sd, qR (EN 15313); for the wheelset tan gamma_e at 3 mm (EN 15302, roll fixed;
-- nil where undefined) and the lateral shifts of the first flange contact either side (m); per rail the worn area
-- and the largest depth.
function M.measures(st, o)
  local ws = M.wheelset(st)
  local m = {}
  for _, name in ipairs(M.BODIES) do
    local b = st.bodies[name]
    local big = 0
    for _, v in ipairs(b.worn) do big = math.max(big, v) end
    m[name] = {worn_area = wrc.wear.area_between{y = b.y0, z = b.z0, y2 = b.y, z2 = b.z}, max_depth = big}
    if b.kind == "wheel" then
      local f = profile_of("wheel", b.y, b.z, name):flange_measures()
      m[name].Sh, m[name].Sd, m[name].qR = f.Sh, f.Sd, f.qR
    end
  end
  local ok, tan = pcall(ws.conicity, ws, {yhat = {3e-3}, threads = o and o.threads or 0})
  if ok then m.tan_gamma_e = tan[1] else m.conicity_note = tostring(tan) end
  m.flange_left, m.flange_right = M.flange_contact(ws, 1), M.flange_contact(ws, -1)
  return m
end

return M
