-- fast: constant_slope + coarse + topology, the fastest location strategy (in
-- tests/bench/bench_contact_location.cpp). Options: step (rail, m), slope_step (rad), max_step (m),
-- coarse_every (lines per cell), coarse_wheel_step (m).
return {
  description = "constant-slope wheel, coarse pre-search, topology walk",
  uses = {"constant_slope", "coarse", "topology"},
}
