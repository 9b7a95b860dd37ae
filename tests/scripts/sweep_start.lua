-- ws:sweep_start: a sweep on threads of its own while the script goes on (scripts/wear_loop.lua solves the tangent
-- cases so while it places the curving ones). Checked here, S1002 on 60E1 at a 1 mm grid (cheap under the
-- sanitizers):
--   - job:wait() gives what ws:sweep gives for the same keys, every number the same bits (rolling contact with the
--     wear model, grids, contact starts), while the script ran an equilibrium and a second job meanwhile; that
--     equilibrium and the second job's rows equal the same calls made alone;
--   - the result is given once: a second wait is refused; a job never waited for is collected without harm;
--   - bad keys are refused by ws:sweep_start naming the key; an error of the run itself comes with wait;
--   - rows = true (ws:sweep's key: per-row results without the grids) keeps wear_passage bit for bit, and its sum
--     over the rows times their width is the area's wear volume per metre rolled (the Archard integral, both ways).
local check = require "wrc.check"

local ws = wrc.wheelset{wheel = wrc.profile.load(wrc.paths.profiles .. "/s1002.lua"),
                        rail = wrc.profile.load(wrc.paths.profiles .. "/60e1.lua"), grid = 1e-3}
local Q = 200e3
local keys = {y = {-3e-3, -1.5e-3, 0, 1.5e-3, 3e-3, 4.5e-3}, yaw = {0}, Q = Q, V = 30, mu = 0.3, wear = {},
              method = "exact", grids = true, threads = 2, chain = 2, contact_starts = true, progress = false}
local curve = {y = {6e-3, 7e-3}, yaw = {2.5e-3}, Q = Q, V = 30, yaw_rate = 30 / 300, mu = 0.3, wear = {},
               method = "exact", threads = 2, chain = 1, progress = false}
local eq = {y = 2e-3, yaw = 0, Q = Q}

-- Every field of two results the same (numbers to the bit; userdata, e.g. contact_start, by type alone).
local function same(a, b, where)
  check.ok(type(a) == type(b), ("%s: a %s against a %s"):format(where, type(a), type(b)))
  if type(a) == "table" then
    for k, v in pairs(a) do
      if k ~= "seconds" then same(v, b[k], where .. "." .. tostring(k)) end
    end
    for k in pairs(b) do check.ok(a[k] ~= nil, ("%s.%s: only in the second"):format(where, tostring(k))) end
  elseif type(a) ~= "userdata" then
    check.ok(a == b or (a ~= a and b ~= b), ("%s: %s against %s"):format(where, tostring(a), tostring(b)))
  end
end

local job = ws:sweep_start(keys)
local job2 = ws:sweep_start(curve)
local e_meanwhile = ws:equilibrium(eq)
local rows, rows2 = job:wait(), job2:wait()
local alone, alone2, e_alone = ws:sweep(keys), ws:sweep(curve), ws:equilibrium(eq)
check.ok(#rows == 6 and rows.failed == 0, ("6 cases, none failed (%d, %s failed)"):format(#rows, rows.failed))
check.ok(rows[1].left.patches[1].wear_volume > 0, "the rows carry the wear model's results")
check.ok(rows[1].contact_start ~= nil, "contact starts given when asked for")
same(rows, alone, "job")
same(rows2, alone2, "second job")
same(e_meanwhile, e_alone, "equilibrium while the jobs ran")

check.fails(function() job:wait() end, "taken by an earlier wait", "a second wait")
ws:sweep_start{y = {0}, yaw = {0}, Q = Q, progress = false}  -- never waited for: collected below
collectgarbage()
collectgarbage()

check.fails(function() ws:sweep_start{y = {0}, yaw = {0}, Q = Q, chian = 2} end, "chian", "a misspelt key")
check.fails(function() ws:sweep_start{y = {0}, yaw = {0}} end, "Q", "no Q")
local bad = ws:sweep_start{y = {0}, yaw = {0}, Q = -1, progress = false}
check.fails(function() bad:wait() end, "Q = -1 N must be a positive number", "a negative Q, at wait")

-- rows = true (the wear loop's sweeps): the grids dropped, each area's wear per row kept, the same bits as with the
-- grids, and summed over the rows (times their width) the area's wear volume per metre rolled.
local light = {}
for k, v in pairs(keys) do light[k] = v end
light.grids, light.rows, light.contact_starts = nil, true, nil
local lr = ws:sweep(light)
local areas = 0
for i, row in ipairs(lr) do
  for _, side in ipairs{"left", "right"} do
    for k, p in ipairs(row[side].patches) do
      local full = rows[i][side].patches[k]
      check.ok(p.wear_depth == nil and full.wear_depth ~= nil, "rows: no grids (and the full sweep's are there)")
      local sum = 0
      for j, d in ipairs(p.wear_passage) do
        check.ok(d == full.wear_passage[j], "rows: the same bits as with the grids")
        sum = sum + d * p.grid.dy
      end
      check.near(sum, p.wear_volume, 1e-9 * p.wear_volume, "rows: wear_passage dy summed = wear_volume")
      areas = areas + 1
    end
  end
end
check.ok(areas >= 12, ("rows: %d areas checked"):format(areas))
print("sweep_start: ok")
