-- Creep forces of the paper's wheelset (S1002 on 60E1, 1:40, r0 = 450 mm, E = 210 GPa, nu = 0.3, 0.2 mm elements)
-- rolling at 100 km/h with mu = 0.3. The wheelset stands in its frictionless equilibrium under Q = 200 kN at
-- y = 0, 3 and 6 mm (tread, tread near the flange root, flange root); on the left wheel's contact area:
--   - creep-force curves Fx(xi) and Fy(eta) with the other creepages zero, and Fy(eta) with the spin the wheelset's
--     geometry gives the area at 100 km/h (omega . n / V), by the exact theory and by FASTSIM;
--   - the traction, adhesion/slip map and frictional power density of the left area at y = 3 mm from the full
--     kinematics: pure rolling at r0 (the larger rolling radius there gives the longitudinal creepage, the cone the
--     spin), each element with its own rigid slip;
--   - Fx(xi) on the tread (y = 0) with friction falling with the slip velocity: Polach's law with the parameters of
--     his dry and wet rails (friction = {preset = "polach_dry"}, "polach_wet"), exact and FASTSIM, against mu(V xi) N,
--     the force of full sliding; the maximum of each curve.
--
--   wrc run examples/creep_curves.lua [out=results/creep] [grid_mm=0.2] [points=20] [plots=true]
--
-- Writes into `out`: creep_curves.csv (every point of the curves: y_mm, curve, creepage, F / (mu N) exact and
-- FASTSIM), curves_xi.png, curves_eta.png, curves_spin.png, falling_friction.csv and .png (the curves with Polach's
-- law), traction.csv (the area's grids: x_mm, y_mm are the grid's
-- coordinates, on the default conformal area x along the track and s along the rail's profile), traction_*.png and
-- summary.txt (the numbers of docs/guide/rolling.md "Rolling contact").
local out = require "wrc.output"

local dir = arg.out or "results/creep"
local grid = (arg.grid_mm or 0.2) * 1e-3
local points = tonumber(arg.points) or 20
local plots = arg.plots ~= "false" and arg.plots ~= false
out.mkdir(dir)

local ws = wrc.wheelset{
  wheel = wrc.profile.load("profiles/s1002.lua", {step = 0.1e-3}),
  rail = wrc.profile.load("profiles/60e1.lua", {step = 0.1e-3}),
  radius = 0.45, back_to_back = 1.360, gauge = 1.435, gauge_depth = 0.014, cant = 1 / 40,
  E = 2.1e11, nu = 0.3, grid = grid,
}
local V, mu, Q = 100 / 3.6, 0.3, 200e3
local ys = {0, 3e-3, 6e-3}
local summary = {}
local function note(fmt, ...)
  local line = string.format(fmt, ...)
  summary[#summary + 1] = line
  print(line)
end

-- The creepage at which the linear theory reaches mu N sets each curve's range: 0 .. 2.5 of it.
local rows, curves = {}, {}
local t0 = os.clock()
for _, y in ipairs(ys) do
  local e = ws:equilibrium{y = y, yaw = 0, Q = Q}
  local pose = {y = y, z = e.z, roll = e.roll, yaw = 0, grids = false}
  local function call(extra)
    local t = {}
    for k, v in pairs(pose) do t[k] = v end
    for k, v in pairs(extra) do t[k] = v end
    return ws:contact(t).left.patches
  end
  local kin = call{V = V, mu = mu}
  local area = kin[1]
  for i = 2, #kin do  -- the area carrying most of the load
    if kin[i].normal_force > area.normal_force then area = kin[i] end
  end
  local index = 1
  for i, p in ipairs(kin) do if p == area then index = i end end
  local N, phi0 = area.normal_force, area.creepage.phi
  note("y = %g mm: left area of %.1f kN, contact angle %.1f deg, %d region(s); at 100 km/h xi = %.3e, eta = %.3e, "
       .. "phi = %.3f 1/m, Fx = %.2f kN, Fy = %.2f kN, adhesion %.2f", y * 1e3, N / 1e3, math.deg(area.angle),
       area.regions, area.creepage.xi, area.creepage.eta, phi0, area.Fx / 1e3, area.Fy / 1e3, area.adhesion)
  -- Kalker's linear law on the equivalent ellipse: the slope C11 G c^2 = dFx/dxi at xi -> 0 (measured here).
  local slope = -call{creepage = {xi = 1e-6}, mu = mu}[index].Fx / 1e-6
  local xs = 3 * mu * N / slope  -- the creepage of saturation of the linear law
  for _, curve in ipairs{"xi", "eta", "eta_spin"} do
    local key = y .. curve
    curves[key] = {y = y, curve = curve, c = {}, exact = {}, fastsim = {}}
    for k = 0, points do
      local c = 2.5 * xs * k / points
      local cr = curve == "xi" and {xi = c} or {eta = c, phi = curve == "eta_spin" and phi0 or 0}
      local f = {}
      for _, method in ipairs{"exact", "fastsim"} do
        local p = call{creepage = cr, mu = mu, method = method}[index]
        f[method] = -(curve == "xi" and p.Fx or p.Fy) / (mu * p.normal_force)
      end
      local cv = curves[key]
      cv.c[#cv.c + 1], cv.exact[#cv.exact + 1], cv.fastsim[#cv.fastsim + 1] = c * 1e3, f.exact, f.fastsim
      rows[#rows + 1] = {y_mm = y * 1e3, curve = curve, creepage_permille = c * 1e3, phi_per_m = cr.phi or 0,
                         F_muN_exact = f.exact, F_muN_fastsim = f.fastsim}
    end
    local worst = 0
    for k = 1, #curves[key].c do worst = math.max(worst, math.abs(curves[key].exact[k] - curves[key].fastsim[k])) end
    local half = math.floor(points / 5 + 0.5) + 1  -- the point at 0.5 of the linear law's saturation creepage
    note("  %-8s 0 .. %.2f permille: at %.2f permille exact %.3f, FASTSIM %.3f mu N; largest difference %.3f mu N",
         curve, 2.5 * xs * 1e3, curves[key].c[half], curves[key].exact[half], curves[key].fastsim[half], worst)
  end
end
note("curves: %d points, %.1f s CPU", #rows, os.clock() - t0)
out.csv(dir .. "/creep_curves.csv",
        {"y_mm", "curve", "creepage_permille", "phi_per_m", "F_muN_exact", "F_muN_fastsim"}, rows)

-- Falling friction: Fx(xi) on the tread at y = 0 up to xi = 5 % (slip velocities up to 1.4 m/s at 100 km/h), the
-- points denser at small xi.
local falling = {}
do
  local e = ws:equilibrium{y = 0, yaw = 0, Q = Q}
  local laws = {{"polach_dry", 0.55, 0.40, 0.60}, {"polach_wet", 0.30, 0.40, 0.20}}  -- preset, mu0, A, B (s/m)
  local frows = {}
  for _, law in ipairs(laws) do
    local name, mu0, A, B = law[1], law[2], law[3], law[4]
    local cv = {name = name, c = {}, exact = {}, fastsim = {}, sliding = {}}
    for k = 1, 2 * points do
      local xi = 0.05 * (k / (2 * points)) ^ 2
      local f = {}
      for _, method in ipairs{"exact", "fastsim"} do
        local a = ws:contact{y = 0, z = e.z, roll = e.roll, yaw = 0, grids = false, creepage = {xi = xi}, V = V,
                             friction = {preset = name}, method = method}.left.patches[1]
        f[method] = -a.Fx / a.normal_force
      end
      local sliding = mu0 * ((1 - A) * math.exp(-B * V * xi) + A)  -- mu(V xi): every element sliding at V xi
      cv.c[k], cv.exact[k], cv.fastsim[k], cv.sliding[k] = xi * 1e3, f.exact, f.fastsim, sliding
      frows[#frows + 1] = {law = name, xi_permille = xi * 1e3, F_N_exact = f.exact, F_N_fastsim = f.fastsim,
                           mu_of_V_xi = sliding}
    end
    local top = 1
    for k = 2, #cv.exact do if cv.exact[k] > cv.exact[top] then top = k end end
    cv.top = top
    note("falling friction %s (mu0 %.2f, A %.2f, B %.2f s/m), y = 0, 100 km/h: maximum -Fx / N = %.3f at xi = %.2f "
         .. "permille (w = %.2f m/s), at 50 permille %.3f (exact; FASTSIM %.3f; mu(V xi) %.3f)", name, mu0, A, B,
         cv.exact[top], cv.c[top], V * cv.c[top] * 1e-3, cv.exact[#cv.c], cv.fastsim[#cv.c], cv.sliding[#cv.c])
    falling[#falling + 1] = cv
  end
  out.csv(dir .. "/falling_friction.csv", {"law", "xi_permille", "F_N_exact", "F_N_fastsim", "mu_of_V_xi"}, frows)
end

-- One area in detail: the left wheel at y = 3 mm, full kinematics.
local y = 3e-3
local e = ws:equilibrium{y = y, yaw = 0, Q = Q}
local c = ws:contact{y = y, z = e.z, roll = e.roll, yaw = 0, V = V, mu = mu}
local p = c.left.patches[1]
for _, q in ipairs(c.left.patches) do if q.normal_force > p.normal_force then p = q end end
note("traction picture: y = 3 mm, V = 100 km/h, pure rolling at r0: xi = %.3e, eta = %.3e, phi = %.3f 1/m, "
     .. "Fx = %.2f kN, Fy = %.2f kN, Mz = %.1f N m, |F| / (mu N) = %.3f, adhesion %.2f, power %.0f W",
     p.creepage.xi, p.creepage.eta, p.creepage.phi, p.Fx / 1e3, p.Fy / 1e3, p.Mz,
     math.sqrt(p.Fx ^ 2 + p.Fy ^ 2) / (mu * p.normal_force), p.adhesion, p.power)
-- The area's grid: on a conformal area (the default) x along the track and s, the arc length along the rail's profile,
-- from the reference point; on a plane x along t1, y along t2.
local xlab = p.rows and "x along the track (mm)" or "x along t1 (mm)"
local ylab = p.rows and "s along the rail's profile (mm)" or "y along t2 (mm)"
local gx, gy = {}, {}
for i = 1, p.grid.nx do gx[i] = (p.grid.x0 + (i - 1) * p.grid.dx) * 1e3 end
for j = 1, p.grid.ny do gy[j] = (p.grid.y0 + (j - 1) * p.grid.dy) * 1e3 end
local trows, tmag, ratio = {}, {}, {}
for j = 1, p.grid.ny do
  tmag[j], ratio[j] = {}, {}
  for i = 1, p.grid.nx do
    local pt = math.sqrt(p.px[j][i] ^ 2 + p.py[j][i] ^ 2)
    tmag[j][i] = pt / 1e6
    ratio[j][i] = p.pressure[j][i] > 0 and pt / (mu * p.pressure[j][i]) or 0
    if p.pressure[j][i] > 0 then
      trows[#trows + 1] = {x_mm = gx[i], y_mm = gy[j], p_MPa = p.pressure[j][i] / 1e6, px_MPa = p.px[j][i] / 1e6,
                           py_MPa = p.py[j][i] / 1e6, state = p.adhesion_map[j][i],
                           slip_x_mm_s = p.slip_x[j][i] * 1e3, slip_y_mm_s = p.slip_y[j][i] * 1e3,
                           power_W_mm2 = p.power_density[j][i] * 1e-6}
    end
  end
end
out.csv(dir .. "/traction.csv", {"x_mm", "y_mm", "p_MPa", "px_MPa", "py_MPa", "state", "slip_x_mm_s", "slip_y_mm_s",
                                 "power_W_mm2"}, trows)

local f = assert(io.open(dir .. "/summary.txt", "w"))
f:write(table.concat(summary, "\n"), "\n")
f:close()

if plots then
  -- Colour by position, full lines for the exact theory, dashes for FASTSIM; in the spin figure the curves without
  -- spin are thin dotted lines (exact only).
  local colours = {["0"] = "#1f6fb4", ["3"] = "#d62728", ["6"] = "#2a9a2a"}
  local function plot(name, curve_names, ylabel, title)
    local series = {}
    for _, y in ipairs(ys) do
      local colour = colours[string.format("%g", y * 1e3)]
      for _, cn in ipairs(curve_names) do
        local cv = curves[y .. cn]
        for _, method in ipairs{"exact", "fastsim"} do
          local thin = #curve_names > 1 and cn ~= "eta_spin"
          if not (thin and method == "fastsim") then
            series[#series + 1] = {
              x = cv.c, y = cv[method],
              style = string.format("lines lw %d dt %d lc rgb '%s'", thin and 1 or 2,
                                    thin and 3 or (method == "exact" and 1 or 2), colour),
              title = string.format("y = %g mm%s, %s", y * 1e3,
                                    #curve_names > 1 and (cn == "eta_spin" and ", with spin" or ", no spin") or "",
                                    method == "exact" and "exact" or "FASTSIM")}
          end
        end
      end
    end
    out.plot{file = dir .. "/" .. name .. ".png", series = series, title = title, ylabel = ylabel,
             xlabel = curve_names[1] == "xi" and "longitudinal creepage xi (permille)" or "lateral creepage eta (permille)",
             extra = {"set key right bottom"}}
  end
  plot("curves_xi", {"xi"}, "-Fx / (mu N)", "S1002 / 60E1, 100 km/h, mu = 0.3: longitudinal creep force")
  plot("curves_eta", {"eta"}, "-Fy / (mu N)", "lateral creep force, no spin")
  plot("curves_spin", {"eta", "eta_spin"}, "-Fy / (mu N)", "lateral creep force, with the spin of the area at 100 km/h")
  local series = {}
  for i, cv in ipairs(falling) do
    local colour = i == 1 and "#d62728" or "#1f6fb4"
    local label = cv.name == "polach_dry" and "dry" or "wet"
    series[#series + 1] = {x = cv.c, y = cv.exact, style = "lines lw 2 lc rgb '" .. colour .. "'",
                           title = label .. ", exact"}
    series[#series + 1] = {x = cv.c, y = cv.fastsim, style = "lines lw 2 dt 2 lc rgb '" .. colour .. "'",
                           title = label .. ", FASTSIM"}
    series[#series + 1] = {x = cv.c, y = cv.sliding, style = "lines lw 1 dt 3 lc rgb '" .. colour .. "'",
                           title = label .. ": mu(V xi), full sliding"}
    series[#series + 1] = {x = {cv.c[cv.top]}, y = {cv.exact[cv.top]}, style = "points pt 7 ps 1.5 lc rgb '" .. colour
                           .. "'", title = string.format("%s: maximum %.3f at %.1f permille", label, cv.exact[cv.top],
                                                         cv.c[cv.top])}
  end
  out.plot{file = dir .. "/falling_friction.png", series = series, ylabel = "-Fx / N",
           xlabel = "longitudinal creepage xi (permille)", extra = {"set key right top", "set yrange [0:*]"},
           title = "S1002 / 60E1 tread, 100 km/h: Polach's falling friction (Polach 2005, dry and wet rail)"}
  out.map{file = dir .. "/traction_magnitude.png", x = gx, y = gy, value = tmag, xlabel = xlab,
          ylabel = ylab, cblabel = "|p_t| (MPa)", title = "y = 3 mm, left area: tangential traction"}
  out.map{file = dir .. "/traction_utilisation.png", x = gx, y = gy, value = ratio, xlabel = xlab,
          ylabel = ylab, cblabel = "|p_t| / (mu p)", title = "traction / bound (1 = slip)"}
  out.map{file = dir .. "/adhesion_slip.png", x = gx, y = gy, value = p.adhesion_map, xlabel = xlab,
          ylabel = ylab, cblabel = "0 outside, 1 adhesion, 2 slip",
          title = "y = 3 mm, left area: adhesion (blue) and slip (red); rolling toward +x",
          palette = "defined (0 'white', 1 '#3060c0', 2 '#d03020')", extra = {"set cbrange [0:2]"}}
  local density = {}
  for j = 1, p.grid.ny do
    density[j] = {}
    for i = 1, p.grid.nx do density[j][i] = p.power_density[j][i] * 1e-6 end
  end
  out.map{file = dir .. "/power_density.png", x = gx, y = gy, value = density, xlabel = xlab,
          ylabel = ylab, cblabel = "W/mm^2", title = "frictional power density"}
end
print("written to " .. dir)
