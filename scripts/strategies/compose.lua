-- wrc.strategies.compose: turns the `strategy = ...` value of wrc.wheelset into a strategy table.
--
-- A strategy has two halves:
--   discretise(d) -> d   at model build, once per side: d = {side = "left"|"right", wheel = <wrc.Profile>,
--                        rail = <wrc.Profile>} in the profiles' own frames; returns the profiles to discretise into
--                        cones and lines, and optionally coarse = {every = n, wheel = <profile> | wheel_step = m}.
--   locate(ctx, side)    per pose and side: decides which index windows of lines x cones to test, by calling the
--                        engine's primitives on ctx (ctx:test, ctx:walk, ctx:coarse, ctx:test_windows,
--                        ctx:walk_windows; see docs/guide/location.md "Strategies"). The inner loops are native.
--
-- Accepted values:
--   "topology"                          a module scripts/strategies/topology.lua (or a path ending in .lua)
--   {"constant_slope", "coarse", "topology", step = 0.1e-3}   a composition of components, with options
--   {name = "uniform", step = 0.2e-3}   one module with options
--   {locate = function(ctx, side) ... end, discretise = function(d) ... end}   inline (runs only in the Lua state
--                                        that built the wheelset; see docs/guide/location.md)
--
-- A component module returns a table with any of:
--   description  one line
--   defaults     the options it understands, with their default values
--   discretise   function(d, opt) -> d
--   windows      true if it produces search windows per pose (ctx:coarse)
--   scan         "test" | "walk": how the windows (or the whole side) are searched
--   uses         a list of component names: what the module's name means as a strategy of its own
--   locate       function(ctx, side, opt): explicit per-pose code, used as is
-- In a composition the discretise functions run in order; the last `scan` wins (default "test").
local M = {}

-- A module is a component if it does something itself; a pure alias (only `uses`) always expands. A component
-- that also has `uses` expands only when it is named alone (coarse alone means uniform + coarse; inside a
-- composition it is just the coarse step).
local function is_component(mod)
  return mod.discretise ~= nil or mod.windows ~= nil or mod.scan ~= nil or mod.locate ~= nil
end

-- The strategies of scripts/strategies/, for a message: its modules that are components or aliases (not this file).
local function strategy_names()
  local names = {}
  for _, file in ipairs(wrc.fs.list(wrc.paths.scripts .. "/strategies")) do
    local name = file:match("^([%w_]+)%.lua$")
    if name then
      local ok, mod = pcall(require, "wrc.strategies." .. name)
      if ok and type(mod) == "table" and (mod.uses or is_component(mod)) then names[#names + 1] = name end
    end
  end
  return table.concat(names, ", ")
end

-- The fields a module gives, of the types this composer uses them as; and at least one that makes it a strategy.
local field_types = {description = "string", defaults = "table", uses = "table", discretise = "function",
                     locate = "function", windows = "boolean", scan = "string"}
local function checked(label, mod)
  for key, want in pairs(field_types) do
    if mod[key] ~= nil and type(mod[key]) ~= want then
      error(("%s: %s must be a %s, got a %s"):format(label, key, want, type(mod[key])), 0)
    end
  end
  if not (mod.uses or is_component(mod)) then
    error(("%s is not a strategy: it gives none of discretise, windows, scan, locate, uses (strategies: %s)"):format(
          label, strategy_names()), 0)
  end
  return mod
end

local function load_module(name)
  if type(name) ~= "string" then error("strategy component names must be strings, got " .. type(name), 0) end
  if name:find("%.lua$") or name:find("/", 1, true) then
    local chunk, err = loadfile(name)
    if not chunk then error(("strategy file '%s': %s"):format(name, err), 0) end
    local ok, mod = pcall(chunk)
    if not ok then error(("strategy file '%s': %s"):format(name, mod), 0) end
    if type(mod) ~= "table" then error(("strategy file '%s' must return a table"):format(name), 0) end
    return checked(("strategy file '%s'"):format(name), mod)
  end
  if not name:match("^[%w_]+$") then
    error(("unknown strategy '%s' (a name of scripts/strategies/: %s; or a .lua path)"):format(name, strategy_names()), 0)
  end
  local ok, mod = pcall(require, "wrc.strategies." .. name)
  if not ok then
    if tostring(mod):find("module 'wrc.strategies." .. name .. "' not found", 1, true) then
      error(("unknown strategy '%s': no file scripts/strategies/%s.lua (strategies: %s)"):format(name, name,
            strategy_names()), 0)
    end
    error(("strategy '%s': %s"):format(name, mod), 0)
  end
  if type(mod) ~= "table" then error(("strategy module '%s' must return a table"):format(name), 0) end
  return checked(("strategy '%s' (scripts/strategies/%s.lua)"):format(name, name), mod)
end

local function expand(names, out, depth, alone)
  for _, name in ipairs(names) do
    local mod = load_module(name)
    if mod.uses and (not is_component(mod) or alone) and depth < 8 then
      expand(mod.uses, out, depth + 1, false)
    else
      out[#out + 1] = {name = name, mod = mod}
    end
  end
  return out
end

local function build(names, user_opt, element)
  local comps = expand(names, {}, 0, #names == 1)
  if #comps == 0 then error("empty strategy composition", 0) end
  -- Options: the components' defaults, then the user's (a key no component knows is an error: typos).
  local opt, known = {}, {}
  for _, c in ipairs(comps) do
    for k, v in pairs(c.mod.defaults or {}) do
      if opt[k] == nil then opt[k] = v end
      known[k] = true
    end
  end
  -- A default `step` no coarser than the wheelset's grid element (m): a finer grid resolves the kinks between cones
  -- and lines, and pmax then grows with the refinement (docs/guide/normal.md); native_strategy does the same.
  if element ~= nil and type(opt.step) == "number" and element < opt.step then opt.step = element end
  for k, v in pairs(user_opt) do
    if not known[k] then
      local list = {}
      for key in pairs(known) do list[#list + 1] = key end
      table.sort(list)
      error(("strategy option '%s' is not used by %s (options: %s)"):format(tostring(k), table.concat(names, "+"),
            #list > 0 and table.concat(list, ", ") or "none"), 0)
    end
    opt[k] = v
  end
  local explicit, windows, scan = nil, false, "test"
  local labels = {}
  for _, c in ipairs(comps) do
    labels[#labels + 1] = c.name
    if c.mod.locate then explicit = c.mod.locate end
    if c.mod.windows then windows = true end
    if c.mod.scan then scan = c.mod.scan end
  end
  if scan ~= "test" and scan ~= "walk" then error(("strategy scan must be \"test\" or \"walk\", got %s"):format(tostring(scan)), 0) end

  local S = {name = table.concat(names, "+"), components = names, options = opt, portable = true,
             description = #comps == 1 and comps[1].mod.description or ("composition: " .. table.concat(labels, " + "))}
  function S.discretise(d)
    for _, c in ipairs(comps) do
      if c.mod.discretise then
        local r = c.mod.discretise(d, opt)
        if r ~= nil then d = r end
      end
    end
    return d
  end
  -- Per-pose code: a closure chosen once, so that each pose costs one Lua call and two primitive calls per side.
  if explicit then
    S.locate = function(ctx, side) return explicit(ctx, side, opt) end
  elseif windows and scan == "walk" then
    S.locate = function(ctx, side) ctx:coarse(side); ctx:walk_windows(side) end
  elseif windows then
    S.locate = function(ctx, side) ctx:coarse(side); ctx:test_windows(side) end
  elseif scan == "walk" then
    S.locate = function(ctx, side) ctx:walk(side) end
  else
    S.locate = function(ctx, side) ctx:test(side) end
  end
  return S
end

-- `element`: the wheelset's grid element (m), or nil (a strategy rebuilt from its options, which hold its step).
function M.resolve(spec, element)
  if spec == nil then spec = wrc.defaults.wheelset.strategy end  -- the engine's one default
  if type(spec) == "string" then return build({spec}, {}, element) end
  if type(spec) ~= "table" then error("strategy must be a name, a list of names or a table, got " .. type(spec), 0) end
  if spec.locate ~= nil then  -- inline strategy
    if type(spec.locate) ~= "function" then error("inline strategy: locate must be a function", 0) end
    if spec.discretise ~= nil and type(spec.discretise) ~= "function" then
      error("inline strategy: discretise must be a function", 0)
    end
    local discretise = spec.discretise or function(d) return d end
    return {name = spec.name or "(inline)", portable = false, options = {}, description = "inline strategy table",
            discretise = discretise, locate = spec.locate}
  end
  local names, opt = {}, {}
  for k, v in pairs(spec) do
    if math.type(k) == "integer" then names[k] = v
    elseif k == "name" then names[1] = v
    else opt[k] = v end
  end
  if spec.name ~= nil and #spec > 0 then error("a strategy table gives either name = ... or a list of names, not both", 0) end
  if #names == 0 then error("strategy table: give a list of names, name = ..., or locate = function", 0) end
  return build(names, opt, element)
end

return M
