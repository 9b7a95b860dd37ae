-- uniform: wheel and rail resampled along their arc at a fixed step (default 0.1 mm, the paper's sampling, or the
-- wheelset's grid element when finer: compose.lua).
-- On its own it tests every line against every cone (compose it with coarse and/or topology to prune).
return {
  description = "profiles resampled along the arc every `step` m; every line against every cone",
  defaults = {step = 0.1e-3},
  discretise = function(d, opt)
    assert(type(opt.step) == "number" and opt.step > 0, "uniform: step must be a positive number of metres")
    d.wheel = d.wheel:resample{step = opt.step}
    d.rail = d.rail:resample{step = opt.step}
    return d
  end,
  scan = "test",
}
