-- Inputs that once crashed the engine or broke a profile's invariants, each synthesised here (a small file in the
-- test's temporary folder), with the reason checked independently of the engine's own check.
--
-- 1. A wheel with a 0.5 mm step in its tread (a measured wheel with a flat, or a file spliced from two). Its points
--    are monotone in y, but the interpolating cubic spline through them (the default reading of a file) overshoots
--    the step and turns back in y. The wheel's cones then went back in y, the searches that bisect them ran past
--    its cones and ws:equilibrium died of SIGSEGV (y = -10 mm, yaw = 10 mrad, Q = 10 kN). The fold is found here on
--    the spline's own points (p:resample along the arc); the wheelset is refused naming the spline, and the
--    polyline through the same points (smooth = false) solves that equilibrium.
-- 2. p:resample with a step as long as the arc returned 2 points, a profile no later step accepts.
-- 3. Points at +-1.7e308 m were a profile, whose arc length (their distance, computed here) overflows to inf; a
--    shift of 1e300 m made every point's z the same number. Points are bounded (1 km), however they are given; a
--    shift beyond the bound is named as such.
-- 4. ws:conicity{yhat = 1} (an amplitude in mm given as metres) built its table first and failed there, naming a
--    table row y[1] = -1.501 m the user never gave; the amplitude is checked as it is read.
-- 5. A wheel with a 2 mm hollow (a parabola over 50 mm of tread) at 10 kN, y = 3 mm, on 60E1 at 0.1 mm: continuation
--    from y = 0 left a wheel lifted, where both residuals come from one wheel and Newton turned the wheelset about
--    that contact the wrong way, 1-2 % down a step, until the 400 evaluations were spent before the rigid start was
--    tried (no equilibrium). Checked by a contact evaluation at the pose found and by Newton from the rigid start.
--    With a budget that ends on continuation's path, the result was the pose z = 0, roll = 0, evaluated at y and
--    reported as the last iterate; it is now the rigid position there, and the error says that no attempt reached y.
local check = require "wrc.check"
local write = dofile((arg[0]:match("(.*/)") or "./") .. "../data/profile/helpers.lua").write
local tmp = (arg.tmp or ".") .. "/robust_inputs_"
wrc.fs.mkdir(arg.tmp or ".")

local s1002 = wrc.profile.load(wrc.paths.profiles .. "/s1002.lua", {step = 0.5e-3})
local rail = wrc.profile.load(wrc.paths.profiles .. "/60e1.lua", {step = 0.5e-3})

-- ---- 1. a stepped tread: the spline folds, the wheelset is refused, the polyline is solved ----
local step_y, step_h = 0.010, 0.5e-3
local wy, wz = s1002:points()
local rows = {}
for i = 1, #wy do
  local lifted = wy[i] > step_y
  if lifted and wy[i - 1] <= step_y then  -- the step: 0.1 um wide, 0.5 mm high
    rows[#rows + 1] = string.format("%.6f %.6f", (step_y + 1e-7) * 1e3, (wz[i - 1] + step_h) * 1e3)
  end
  rows[#rows + 1] = string.format("%.6f %.6f", wy[i] * 1e3, (wz[i] + (lifted and step_h or 0)) * 1e3)
end
local file = write(tmp .. "stepped_wheel.txt", table.concat(rows, "\n") .. "\n")

local spline = wrc.profile.load(file, {kind = "wheel"})
check.ok(spline.smooth == 0, "a file's points are read as their interpolating spline")
local fy = spline:resample{step = 0.1e-3, along = "arc"}:points()
local back = 0
for i = 2, #fy do back = math.max(back, fy[i - 1] - fy[i]) end
check.ok(back > 1e-6, ("the spline through the step turns back in y (by %.4f mm)"):format(back * 1e3))
local err = check.fails(function() return wrc.wheelset{wheel = spline, rail = rail, grid = 0.5e-3} end,
                        "not monotone in y", "a wheel whose spline folds back is refused")
check.ok(err:find("smooth = false", 1, true) and err:find("stepped_wheel.txt", 1, true),
         "the message names the file and the way out: " .. err)

local poly = wrc.profile.load(file, {kind = "wheel", smooth = false})
local ws = wrc.wheelset{wheel = poly, rail = rail, grid = 0.5e-3}
local e = ws:equilibrium{y = -10e-3, yaw = 0.01, Q = 10e3}
check.ok(e.converged and math.abs(e.left.force.z + e.right.force.z - 10e3) < 10,
         ("the polyline's equilibrium carries the load (Fz = %.1f N)"):format(e.left.force.z + e.right.force.z))

-- ---- 2. a resampling has at least 3 points ----
local arc = s1002:arc_length()
local width = s1002:bounds().y_max - s1002:bounds().y_min
check.fails(function() return s1002:resample{step = 1.01 * arc} end, "a profile needs at least 3", "a step beyond the arc")
check.fails(function() return s1002:resample{step = 1.01 * width, along = "y"} end, "a profile needs at least 3",
            "a step beyond the width")
check.ok(#s1002:resample{step = 0.99 * arc} == 3, "a step just shorter than the arc gives 3 points")
check.ok(#s1002:resample{step = 0.99 * width, along = "y"} == 3, "a step just shorter than the width gives 3 points")

-- ---- 3. coordinates bounded ----
local far = 1.7e308
check.ok(far - (-far) == math.huge, "the distance between the points overflows")
check.fails(function() return wrc.profile.points{kind = "wheel", y = {-far, 0, far}, z = {0, 0, 0}} end,
            "are the coordinates in metres", "points at +-1.7e308 m")
check.fails(function() return wrc.profile.points{kind = "wheel", y = {-0.01, 0, 1001}, z = {0, 0, 0}} end,
            "more than 1000 m", "a point 1001 m out")
check.ok(#wrc.profile.points{kind = "wheel", y = {-0.01, 0, 999}, z = {0, 0, 0}} == 3, "999 m is accepted")
local cone = write(tmp .. "cone.txt", "-70 1.75\n0 0\n60 -1.5\n")
check.fails(function() return wrc.profile.load(cone, {kind = "wheel", shift = {z = 1e300}}) end,
            "shift.z = 1e+300 m is out of range", "a shift of 1e300 m (named, not taken for a unit)")
check.fails(function() return wrc.profile.load(cone, {kind = "wheel", units = 1e300}) end,
            "are the coordinates in metres", "units of 1e300 m")

-- ---- 4. an amplitude checked before the table is built ----
err = check.fails(function() return ws:conicity{yhat = 1} end, "the amplitude yhat = 1 m", "yhat = 1 m")
check.ok(not err:find("y[1]", 1, true), "the message names the amplitude, not a table row: " .. err)

-- ---- 5. an equilibrium reached past a lifted wheel ----
local hy, hz = s1002:points()
for i = 1, #hy do
  local d = (hy[i] + 0.005) / 0.025
  if math.abs(d) < 1 then hz[i] = hz[i] + 2e-3 * (1 - d * d) end
end
local hw = wrc.wheelset{wheel = wrc.profile.points{kind = "wheel", y = hy, z = hz},
                        rail = wrc.profile.load(wrc.paths.profiles .. "/60e1.lua", {step = 0.1e-3}), grid = 0.5e-3}
local Q, yh = 10e3, 3e-3
e = hw:equilibrium{y = yh, yaw = 0, Q = Q, on_failure = "return"}
check.ok(e.converged, "the hollow wheel's equilibrium is found (" .. tostring(e.message) .. ")")
local c = hw:contact{y = yh, z = e.z, roll = e.roll}
check.ok(math.abs(c.force.z - Q) < 1e-5 * Q and math.abs(c.moment.x) < 1e-5 * Q,
         ("the pose carries Q with no roll moment (Fz = %.6f N, Mx = %.3g N m)"):format(c.force.z, c.moment.x))
check.ok(c.left.force.z > 0.3 * Q and c.right.force.z > 0.3 * Q, "both wheels carry load")
local g = hw:rigid{y = yh, Q = Q}
local r = hw:equilibrium{y = yh, yaw = 0, Q = Q, start = {z = g.z - 1e-6, roll = g.roll}}
check.ok(math.abs(r.z - e.z) < 1e-8 and math.abs(r.roll - e.roll) < 1e-8,
         ("the same pose as Newton from the rigid start (dz = %.3g m, droll = %.3g rad)"):format(r.z - e.z, r.roll - e.roll))
local cut = hw:equilibrium{y = yh, yaw = 0, Q = Q, max_evaluations = 30, on_failure = "return"}
check.ok(not cut.converged and cut.error:find("no attempt reached y", 1, true), "the error says so: " .. cut.error)
check.ok(cut.z == g.z and cut.roll == g.roll, "the result holds the rigid position at y")
print("robust_inputs: ok")
