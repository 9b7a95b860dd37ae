-- topology (paper Section 2, item 3): the walk. Lines in increasing order; each line is first tested on the cones
-- the previous line crossed (the topology of the profiles makes the next crossings nearby), and every other range
-- of cones is ruled out by a certified bound or split until it is -- so nothing brute force finds is lost, which
-- the literal rule of item 3 cannot promise once yaw makes a line run under several cones. Combine it with the
-- others: {"uniform", "topology"} (this strategy), {"constant_slope", "coarse", "topology"} ("fast").
return {
  description = "topology walk: tests start at the previous line's cones, the rest ruled out by bounds",
  defaults = {},
  uses = {"uniform", "topology"},
  scan = "walk",
}
