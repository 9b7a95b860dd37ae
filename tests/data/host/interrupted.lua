-- Writes part of an output through an atomic file, and part of a temporary of its own (wrc.fs.temporary_name), then
-- computes without end, writing nothing: tests/host/interrupt.sh stops it with a signal. Keys: out (the output's
-- path), mode = "write" (the above), "loop" (the loop alone) or "plot" (a figure, its gnuplot the test's stand-in,
-- which says "computing" and waits for the signal).
if arg.mode == "plot" then
  require("wrc.output").plot{file = arg.out .. ".png", series = {{x = {0, 1}, y = {0, 1}, title = "a line"}}}
  error("the figure's gnuplot was expected to be interrupted")
end
if arg.mode == "write" then
  local f = wrc.fs.open_atomic(arg.out)
  f:write(string.rep("partial line of the new content\n", 1000))
  local own = assert(io.open(wrc.fs.temporary_name(arg.out .. ".own"), "w"))
  own:write("a temporary the script writes itself\n")
  own:flush()
end
io.stdout:write("computing\n")  -- the test signals the run once it reads this line
io.stdout:flush()
local n = 0
while true do n = n + 1 end
