-- constant_slope (paper Section 2, item 2): wheel points placed so that the tangent turns by `slope_step` rad
-- between consecutive points -- few points on the conical parts, many where the curvature is high -- at most
-- `max_step` m apart; the rail resampled along its arc every `step` m. On its own: every line against every cone.
return {
  description = "wheel points at constant slope increments (bounded step), rail every `step` m",
  defaults = {step = 0.1e-3, slope_step = 0.01, max_step = 1e-3},
  discretise = function(d, opt)
    d.wheel = wrc.geometry.constant_slope(d.wheel, {slope_step = opt.slope_step, max_step = opt.max_step})
    d.rail = d.rail:resample{step = opt.step}
    return d
  end,
  scan = "test",
}
