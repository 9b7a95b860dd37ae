-- coarse (paper Fig. 3): per pose, a pre-search on a few points moved outside the solids -- one rail line per
-- cell of `coarse_every` lines, against the wheel offset outward by the cells' size (wrc.geometry.offset_outward,
-- points every `coarse_wheel_step` m) -- then the fine search only in the windows where the coarse one found
-- inter-penetration. That it cannot miss a crossing is proved in engine/src/geometry/search.cpp (coarse) and
-- checked against brute force in tests/geometry/test_location.cpp and tests/scripts/strategy_*.lua.
-- As a strategy of its own: uniform resampling, coarse windows, every pair tested inside them.
return {
  description = "coarse pre-search on outward-offset profiles, fine search only where it found penetration",
  defaults = {coarse_every = 16, coarse_wheel_step = 2e-3},
  uses = {"uniform", "coarse"},
  windows = true,
  discretise = function(d, opt)
    local every = opt.coarse_every
    assert(math.type(every) == "integer" or (type(every) == "number" and every % 1 == 0),
           "coarse: coarse_every must be an integer")
    -- The coarse wheel must contain the fine wheel dilated by the cells' size; the engine checks it.
    local D = wrc.geometry.cell_dilation(d.rail, every)
    d.coarse = {every = math.tointeger(every), wheel = wrc.geometry.offset_outward(d.wheel, D, opt.coarse_wheel_step)}
    return d
  end,
}
