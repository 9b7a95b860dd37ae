-- A contact area too narrow for its grid (wheelset/contact.hpp, kMinSpan): S1002 on 60E1, the left wheel at y = 7 mm
-- with 1 kN, a flange contact ~0.6 mm wide. On a 0.5 mm grid it spans 2 elements across and its pmax is ~45 % low
-- against a 0.1 mm grid's, which spans 5; the area says `resolved = false` on each call, and stderr shows it once per
-- wheelset (its trajectories included): the CMake test that runs this script checks stderr.
local check = require "wrc.check"
local wheel = wrc.profile.load(wrc.paths.profiles .. "/s1002.lua")
local rail = wrc.profile.load(wrc.paths.profiles .. "/60e1.lua")
local case = {side = "left", y = 7e-3, Fz = 1e3}

local function solve(grid)
  local ws = wrc.wheelset{wheel = wheel, rail = rail, grid = grid}
  local first, again = ws:wheel(case), ws:wheel(case)
  local tr = ws:trajectory{}
  local step = tr:wheel(case)
  check.ok(#first.patches == 1, "one contact area")
  for _, r in ipairs{again, step} do
    check.ok(r.patches[1].resolved == first.patches[1].resolved, "each call says it")
  end
  return first.patches[1], first.resolution_note
end

local coarse, coarse_note = solve(0.5e-3)
local fine, fine_note = solve(0.1e-3)
check.ok(coarse_note and coarse_note:find("spans only") and fine_note == nil, "the wheel's resolution_note, only then")
print(("0.5 mm: span %d x %d, pmax %.0f MPa; 0.1 mm: span %d x %d, pmax %.0f MPa"):format(
  coarse.span.x, coarse.span.y, coarse.pmax / 1e6, fine.span.x, fine.span.y, fine.pmax / 1e6))
check.ok(not coarse.resolved and coarse.span.y < 4 and coarse.span.x >= 4, "0.5 mm: too few elements across t2")
check.ok(fine.resolved and fine.span.y >= 4, "0.1 mm: resolved")
check.ok(coarse.pmax < 0.8 * fine.pmax, "0.5 mm: pmax far below the resolved one")

-- The spans counted from the pressure grid itself: the most elements in contact in one row and in one column.
local function spans(p)
  local x, y, columns = 0, 0, {}
  for _, row in ipairs(p.pressure) do
    local n = 0
    for i, v in ipairs(row) do
      if v > 0 then n, columns[i] = n + 1, (columns[i] or 0) + 1 end
    end
    x = math.max(x, n)
  end
  for _, n in pairs(columns) do y = math.max(y, n) end
  return x, y
end
for _, p in ipairs{coarse, fine} do
  local x, y = spans(p)
  check.ok(p.span.x == x and p.span.y == y, ("span %d x %d, counted %d x %d"):format(p.span.x, p.span.y, x, y))
end
