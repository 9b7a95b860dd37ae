-- The Lua side of tests/bench/bench_python.py: n wheel solves of S1002 on 60E1 (the README's wheelset), y spread
-- evenly over 0 .. 7 mm, Fz = 100 kN on the left wheel, one after the other; prints the CPU seconds they took
-- (os.clock) and a checksum of the results (the sum of the lateral forces, N) for the Python side to compare.
--
--   wrc run tests/bench/bench_wheel.lua [n=200] [repeat=3]
local n = tonumber(arg.n) or 200
local reps = tonumber(arg["repeat"]) or 3
local root = arg.root or "."
local ws = wrc.wheelset{
  wheel = wrc.profile.load(root .. "/profiles/s1002.lua"),
  rail = wrc.profile.load(root .. "/profiles/60e1.lua"),
}
local best, sum = math.huge, 0
for _ = 1, reps do
  local t0 = os.clock()
  sum = 0
  for i = 0, n - 1 do
    -- numpy.linspace's values, bit for bit: i times the step, the last one the end itself
    local y = n == 1 and 0 or i == n - 1 and 7e-3 or i * (7e-3 / (n - 1))
    local w = ws:wheel{side = "left", y = y, Fz = 100e3}
    sum = sum + w.force.y
  end
  best = math.min(best, os.clock() - t0)
end
print(("lua: %d wheel solves in %.4f s (best of %d), sum of force.y = %.17g N"):format(n, best, reps, sum))
