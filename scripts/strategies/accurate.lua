-- accurate: the paper's discretisation (wheel and rail resampled every 0.1 mm along the arc) searched with the
-- coarse pre-search and the topology walk. The default strategy of wrc.wheelset: the normal problem needs the
-- fine wheel. On a near-conformal contact (S1002 on 60E1 at y = 0) the lateral gap varies by a few um over
-- 20 mm, and the constant-slope wheel of `fast` (cones up to 1 mm long, chord sagitta ~1 um) leaves visible
-- stripes in the pressure; at 0.1 mm the sagitta is ~5 nm. The search costs ~55 us per pose instead of ~45 us,
-- which is nothing beside the normal solve. Options: step (m), coarse_every (lines per cell), coarse_wheel_step (m).
return {
  description = "wheel and rail every 0.1 mm, coarse pre-search, topology walk",
  uses = {"uniform", "coarse", "topology"},
}
