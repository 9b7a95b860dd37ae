-- wrc.check: assertions for study scripts and the Lua-level tests. Each failure raises an error that
-- names what was checked, the value and the expectation, at the caller's line.
local M = {}

local function fail(msg, level) error(msg, (level or 1) + 2) end
-- A value in a message: a number as the engine writes it (NaN as NaN: tostring writes 0/0 "-nan").
local function shown(v) return type(v) == "number" and wrc.number_text(v) or tostring(v) end

-- ok(cond, what): cond must be true.
function M.ok(cond, what)
  if not cond then fail("check failed: " .. tostring(what)) end
end

-- near(actual, expected, tol, what): |actual - expected| <= tol.
function M.near(actual, expected, tol, what)
  if type(actual) ~= "number" or actual ~= actual or math.abs(actual - expected) > tol then
    fail(string.format("check failed: %s = %s, expected %.12g +/- %.3g", tostring(what), shown(actual),
                       expected, tol))
  end
end

-- rel(actual, expected, rtol, what): |actual - expected| <= rtol * |expected|.
function M.rel(actual, expected, rtol, what)
  if type(actual) ~= "number" or actual ~= actual or math.abs(actual - expected) > rtol * math.abs(expected) then
    fail(string.format("check failed: %s = %s, expected %.12g within %.3g relative", tostring(what),
                       shown(actual), expected, rtol))
  end
end

-- fails(fn, pattern, what): fn() must raise an error whose message matches pattern (plain find).
function M.fails(fn, pattern, what)
  local ok, err = pcall(fn)
  if ok then fail("check failed: " .. tostring(what) .. " did not raise an error") end
  if pattern and not tostring(err):find(pattern, 1, true) then
    fail(string.format("check failed: %s raised '%s', expected a message containing '%s'", tostring(what),
                       tostring(err), pattern))
  end
  return err
end

return M
