-- brute: every rail line against every wheel cone, on the profiles as given (their own sampling). The reference
-- of the tests and benchmarks; slow (about two million closed-form tests per pose at 0.1 mm).
return {
  description = "every line against every cone, profiles as given",
  defaults = {},
  discretise = function(d) return d end,
  scan = "test",
}
