// The sandbox of profile definitions (sandbox.hpp): a Lua state of its own per definition, with an allocator that
// counts against a memory budget, a count hook that counts against an instruction budget, only the libraries that
// compute, and a wrc.profile of three entries. The C functions a definition can call are wrapped by `sandboxed`,
// which lets them allocate freely while they run (a refused allocation would longjmp past their C++ objects) and
// checks the budgets when they return.
#include "lua/sandbox.hpp"

#include "lua/convert.hpp"
#include "lua/profile_binding.hpp"
#include "wrc/core/error.hpp"
#include "wrc/core/options.hpp"
#include "wrc/core/paths.hpp"
#include "wrc/profile/load.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>

#include <cstdlib>
#include <cstring>
#include <exception>
#include <filesystem>
#include <memory>

namespace wrc::lua {
namespace {

constexpr int kHookEvery = 1000;                 // instructions between two looks at the budget
constexpr int kMaxNesting = 3;                   // a definition loading a definition loading a definition
constexpr std::uint64_t kNestedLoadCost = 100'000;  // instructions charged for each nested load (a new state)

// The budget of one top-level load, shared by the definitions it loads. Once a limit is passed the load is over: the
// flags stay set, every later allocation that grows is refused and the hook raises at every instruction, so that
// pcall inside the definition cannot carry on.
struct Budget {
  SandboxLimits limits;
  std::string path;  // the definition the caller asked for, named in the messages
  std::uint64_t instructions = 0;
  std::size_t bytes = 0;
  double points = 0;
  bool cpu = false, memory = false, too_many_points = false;
  std::string message;  // why the load is over, made when a limit is passed

  bool exceeded() const { return cpu || memory || too_many_points; }
  void exceed(bool& flag, std::string why) {
    if (!exceeded()) message = fmt::format("the profile definition {} {}", path, why);
    flag = true;
  }
};

// One Lua state of the sandbox (the allocator's user data).
struct Sandbox {
  Budget* budget;
  int depth;           // 0: the definition the caller loads; 1: one it loads; ...
  std::string path;
  int in_call = 0;     // > 0 while a C++ function of the sandbox runs (or the state is set up): allocations not refused
};

Sandbox& sandbox_of(lua_State* L) {
  void* ud = nullptr;
  lua_getallocf(L, &ud);
  return *static_cast<Sandbox*>(ud);
}

void* sandbox_alloc(void* ud, void* ptr, std::size_t osize, std::size_t nsize) {
  Sandbox& s = *static_cast<Sandbox*>(ud);
  Budget& b = *s.budget;
  const std::size_t old = ptr ? osize : 0;  // without ptr, osize is the kind of object
  if (nsize == 0) {
    std::free(ptr);
    b.bytes -= old;
    return nullptr;
  }
  if (nsize > old && s.in_call == 0 && (b.exceeded() || b.bytes + (nsize - old) > b.limits.memory)) {
    if (!b.exceeded()) b.exceed(b.memory, fmt::format("exceeded its memory budget ({} MB)", b.limits.memory >> 20));
    return nullptr;  // Lua raises "not enough memory"
  }
  void* p = std::realloc(ptr, nsize);
  if (p) b.bytes = b.bytes - old + nsize;
  return p;
}

void count_hook(lua_State* L, lua_Debug*) {
  Budget& b = *sandbox_of(L).budget;
  b.instructions += kHookEvery;
  if (!b.exceeded() && b.instructions > b.limits.instructions)
    b.exceed(b.cpu, fmt::format("exceeded its CPU budget ({} Lua instructions)", b.limits.instructions));
  if (!b.exceeded()) return;
  lua_sethook(L, count_hook, LUA_MASKCOUNT, 1);
  // longjmp-safe: a hook keeps no C++ object alive; the message lives in the budget
  luaL_error(L, "%s", b.message.c_str());
}

// The message of a failed sandboxed call, kept outside its frame so that the Lua error is raised with no C++ object
// alive (making the Lua string may itself fail for memory, which longjmps).
std::string& error_text() {
  thread_local std::string text;
  return text;
}

int raise_error_text(lua_State* L) {
  luaL_where(L, 1);
  lua_pushstring(L, error_text().c_str());
  lua_concat(L, 2);
  return lua_error(L);  // longjmp-safe: no C++ object alive in this frame
}

// The sandbox's counterpart of guarded<F> (guard.hpp): F's exceptions become Lua errors, F's allocations are not
// refused, and after F the budgets are checked (memory held, profile points made).
template <int (*F)(lua_State*)>
int sandboxed(lua_State* L) {
  Sandbox& s = sandbox_of(L);
  Budget& b = *s.budget;
  bool failed = b.exceeded();
  int results = 0;
  if (!failed) {
    ++s.in_call;
    try {
      results = F(L);
    } catch (const std::exception& e) {
      error_text() = e.what();
      failed = true;
    } catch (...) {
      error_text() = "unknown C++ exception";
      failed = true;
    }
    --s.in_call;
  }
  if (!failed && results > 0) {
    if (const auto* p = static_cast<std::shared_ptr<const Profile>*>(luaL_testudata(L, -1, kProfileType)); p && *p)
      b.points += static_cast<double>((*p)->size());
    if (b.points > b.limits.points)
      b.exceed(b.too_many_points, fmt::format("made more profile points than its budget ({:.0f} in all)", b.limits.points));
    if (b.bytes > b.limits.memory && !b.exceeded())
      b.exceed(b.memory, fmt::format("exceeded its memory budget ({} MB)", b.limits.memory >> 20));
  }
  if (b.exceeded()) error_text() = b.message;
  if (failed || b.exceeded()) return raise_error_text(L);
  return results;
}

// __index of the globals and of `string`: the names a definition may not have say so.
int refuse_name(lua_State* L, const char* const* names, const char* prefix) {
  if (lua_type(L, 2) != LUA_TSTRING) return 0;
  const char* key = lua_tostring(L, 2);
  for (const char* const* n = names; *n; ++n)
    if (std::strcmp(key, *n) == 0)
      // longjmp-safe: no C++ object alive
      return luaL_error(L, "'%s%s' is not available in a profile definition: a definition is data and runs in a "
                           "sandbox (math, string, table and wrc.profile)", prefix, key);
  return 0;
}

int missing_global(lua_State* L) {
  static const char* const names[] = {"os", "io", "package", "require", "dofile", "loadfile", "loadstring", "debug",
                                      "collectgarbage", "print", "coroutine", "warn", nullptr};
  return refuse_name(L, names, "");
}

int missing_string(lua_State* L) {
  static const char* const names[] = {"dump", nullptr};
  return refuse_name(L, names, "string.");
}

// load(chunk [, name [, mode [, env]]]) with mode "t": text chunks only (a binary chunk can crash the VM).
int text_load(lua_State* L) {
  const int n = lua_gettop(L);
  lua_settop(L, 4);
  lua_pushvalue(L, lua_upvalueindex(1));  // the base library's load
  lua_pushvalue(L, 1);
  lua_pushvalue(L, 2);
  lua_pushliteral(L, "t");
  if (n >= 4) lua_pushvalue(L, 4);
  lua_call(L, n >= 4 ? 4 : 3, 2);
  return 2;
}

Profile run(const std::string& path, const OptionTable& options, Budget& budget, int depth);

// A definition's options reach it as a proxy that records the keys it reads (upvalue 1: the options, 2: the keys
// read), so that a key nobody reads is an unknown option (check_options_read), as for a file's reader. It keeps no
// C++ object alive: a memory error here is the definition's Lua error.
int read_option(lua_State* L) {
  lua_pushvalue(L, 2);
  lua_pushboolean(L, 1);
  lua_rawset(L, lua_upvalueindex(2));
  lua_pushvalue(L, 2);
  lua_rawget(L, lua_upvalueindex(1));
  return 1;
}

// pairs(options) reads every key.
int pairs_options(lua_State* L) {
  lua_pushnil(L);
  while (lua_next(L, lua_upvalueindex(1)) != 0) {
    lua_pop(L, 1);
    lua_pushvalue(L, -1);
    lua_pushboolean(L, 1);
    lua_rawset(L, lua_upvalueindex(2));
  }
  lua_getglobal(L, "next");
  lua_pushvalue(L, lua_upvalueindex(1));
  lua_pushnil(L);
  return 3;
}

// Pushes the keys-read table, then the proxy of the options table on the top (which it replaces).
void push_option_proxy(lua_State* L) {
  const int options = lua_gettop(L);
  lua_createtable(L, 0, 4);  // keys read
  lua_createtable(L, 0, 0);  // the proxy
  lua_createtable(L, 0, 3);  // its metatable
  for (auto [name, fn] : {std::pair<const char*, lua_CFunction>{"__index", read_option}, {"__pairs", pairs_options}}) {
    lua_pushvalue(L, options);
    lua_pushvalue(L, options + 1);
    lua_pushcclosure(L, fn, 2);
    lua_setfield(L, -2, name);
  }
  lua_pushvalue(L, options);  // a nested wrc.profile.load given the proxy passes the options themselves on
  lua_setfield(L, -2, "__options");
  lua_setmetatable(L, -2);
  lua_remove(L, options);  // [keys read, proxy]
}

// A proxy passed to a nested wrc.profile.load stands for all of its options (all read).
void unwrap_option_proxy(lua_State* L, int index) {
  if (!lua_getmetatable(L, index)) return;
  if (lua_getfield(L, -1, "__options") == LUA_TTABLE) {
    lua_getfield(L, -2, "__pairs");
    lua_call(L, 0, 3);  // marks every key read
    lua_pop(L, 3);
    lua_replace(L, index);
    lua_pop(L, 1);
    return;
  }
  lua_pop(L, 2);
}

// Every option given is read by the definition or is one of wrc.profile.load's own (load_option_keys), or the
// load fails as an unknown key does for a file's reader. `read` is the index of the keys-read table.
void check_options_read(lua_State* L, int read, const OptionTable& options, const std::string& path) {
  std::vector<std::string> known = load_option_keys(), unknown;
  lua_pushnil(L);
  while (lua_next(L, read) != 0) {
    lua_pop(L, 1);
    if (lua_type(L, -1) == LUA_TSTRING) known.emplace_back(lua_tostring(L, -1));
  }
  for (const auto& [key, value] : options.entries)
    if (std::find(known.begin(), known.end(), key) == known.end()) unknown.push_back(key);
  if (unknown.empty()) return;
  std::sort(known.begin() + static_cast<std::ptrdiff_t>(load_option_keys().size()), known.end());  // not hash order
  const std::string near = closest_name(unknown.front(), known);
  fail("wrc.profile.load: {}: unknown option '{}' for the Lua definition{} (it reads: {}; wrc.profile.load takes: {})",
       path, unknown.front(), near.empty() ? "" : fmt::format(" (did you mean '{}'?)", near),
       fmt::join(known.begin() + static_cast<std::ptrdiff_t>(load_option_keys().size()), known.end(), ", "),
       fmt::join(load_option_keys(), ", "));
}

// The loader of the definitions a definition at `depth` loads: the same budget, one level deeper.
DefinitionLoader nested_definitions(Budget& budget, int depth) {
  return [&budget, depth](const std::string& path, const OptionTable& options) {
    return run(path, options, budget, depth + 1);
  };
}

// wrc.profile.load inside a definition: the shipped profiles only, as the same rule names them.
int nested_load(lua_State* L) {
  if (lua_istable(L, 2)) unwrap_option_proxy(L, 2);  // before any C++ object lives (it calls Lua)
  const char* ctx = "wrc.profile.load";
  Sandbox& s = sandbox_of(L);
  const std::string given = check_string(L, 1, ctx);
  if (!lua_isnoneornil(L, 2) && !lua_istable(L, 2)) fail("{}: options must be a table, got {}", ctx, type_name(L, 2));
  const OptionTable options = to_options(L, 2, ctx);
  // Decided before anything outside the shipped folder is looked at (a definition learns nothing of other files).
  const std::filesystem::path name(given);
  const bool shipped_name = name.is_relative() && !name.empty() && *name.begin() == "profiles";
  const std::string path = shipped_name || is_shipped_profile(given) ? resolve_profile_path(given) : std::string();
  if (path.empty() || !is_shipped_profile(path))
    fail("{}: {}: a profile definition may load only the profiles shipped with wrc (profiles/NAME, in {})", ctx, given,
         paths().profiles);
  if (s.depth + 1 > kMaxNesting) fail("{}: {}: profile definitions nest more than {} levels", ctx, given, kMaxNesting);
  s.budget->instructions += kNestedLoadCost;
  const DefinitionLoader definitions = nested_definitions(*s.budget, s.depth);
  // `given` again, not `path`: load_profile resolves it by the same rule to the same file.
  push_profile(L, std::make_shared<const Profile>(wrc::load_profile(given, options, &definitions)));
  return 1;
}

void open_profile_type(lua_State* L) {
  luaL_newmetatable(L, kProfileType);
  const luaL_Reg meta[] = {{"__gc", gc_shared<const Profile>},
                           {"__len", sandboxed<profile_api::len>},
                           {"__tostring", sandboxed<profile_api::tostring>},
                           {"__index", sandboxed<profile_api::index>},
                           {nullptr, nullptr}};
  luaL_setfuncs(L, meta, 0);
  lua_pushstring(L, kProfileType);  // getmetatable(p) gives the name; the metatable (its __gc) stays out of reach
  lua_setfield(L, -2, "__metatable");
  const luaL_Reg methods[] = {{"points", sandboxed<profile_api::method_points>},
                              {"resample", sandboxed<profile_api::method_resample>},
                              {"interpolate", sandboxed<profile_api::method_interpolate>},
                              {"arc_length", sandboxed<profile_api::method_arc_length>},
                              {"bounds", sandboxed<profile_api::method_bounds>},
                              {"transform", sandboxed<profile_api::method_transform>},
                              {nullptr, nullptr}};
  lua_createtable(L, 0, 6);
  luaL_setfuncs(L, methods, 0);
  lua_setfield(L, -2, "methods");
  lua_pop(L, 1);
}

// The globals of a definition (sandbox.hpp); called through lua_pcall with allocations not refused.
int open_sandbox(lua_State* L) {
  luaL_requiref(L, LUA_GNAME, luaopen_base, 1);
  luaL_requiref(L, LUA_MATHLIBNAME, luaopen_math, 1);
  luaL_requiref(L, LUA_STRLIBNAME, luaopen_string, 1);
  luaL_requiref(L, LUA_TABLIBNAME, luaopen_table, 1);
  lua_settop(L, 0);
  static const char* const keep[] = {"assert", "error", "getmetatable", "ipairs", "next", "pairs", "pcall",
                                     "rawequal", "rawget", "rawlen", "rawset", "select", "setmetatable", "tonumber",
                                     "tostring", "type", "xpcall", "load", "_G", "_VERSION", "math", "string", "table",
                                     nullptr};
  lua_pushglobaltable(L);  // 1
  lua_pushnil(L);
  while (lua_next(L, 1) != 0) {
    lua_pop(L, 1);
    bool kept = false;
    for (const char* const* k = keep; *k && !kept; ++k) kept = lua_type(L, -1) == LUA_TSTRING && std::strcmp(lua_tostring(L, -1), *k) == 0;
    if (kept) continue;
    lua_pushvalue(L, -1);
    lua_pushnil(L);
    lua_rawset(L, 1);  // clearing a field during the traversal is allowed
  }
  lua_getfield(L, 1, "load");
  lua_pushcclosure(L, text_load, 1);
  lua_setfield(L, 1, "load");
  lua_createtable(L, 0, 1);
  lua_pushcfunction(L, missing_global);
  lua_setfield(L, -2, "__index");
  lua_setmetatable(L, 1);
  lua_getfield(L, 1, "string");
  lua_pushnil(L);
  lua_setfield(L, -2, "dump");
  lua_createtable(L, 0, 1);
  lua_pushcfunction(L, missing_string);
  lua_setfield(L, -2, "__index");
  lua_setmetatable(L, -2);
  lua_pop(L, 1);
  open_profile_type(L);
  lua_createtable(L, 0, 1);  // wrc
  lua_createtable(L, 0, 3);  // wrc.profile
  lua_pushcfunction(L, sandboxed<profile_api::points>);
  lua_setfield(L, -2, "points");
  lua_pushcfunction(L, sandboxed<nested_load>);
  lua_setfield(L, -2, "load");
  lua_pushinteger(L, static_cast<lua_Integer>(kMaxProfilePoints));
  lua_setfield(L, -2, "max_points");
  lua_setfield(L, -2, "profile");
  lua_setfield(L, 1, "wrc");
  return 0;
}

std::string error_message(lua_State* L) {
  if (lua_type(L, -1) == LUA_TSTRING) return lua_tostring(L, -1);
  return fmt::format("(error object is a {} value)", type_name(L, -1));
}

// Runs one definition in a new sandbox state and returns its profile as the definition made it.
Profile run(const std::string& path, const OptionTable& options, Budget& budget, int depth) {
  Sandbox s{&budget, depth, path, 1};
  const std::unique_ptr<lua_State, void (*)(lua_State*)> state(lua_newstate(sandbox_alloc, &s), lua_close);
  if (!state) fail("wrc.profile.load: {}: cannot make a Lua state for the definition (out of memory)", path);
  lua_State* L = state.get();
  lua_pushcfunction(L, open_sandbox);
  if (lua_pcall(L, 0, 0, 0) != LUA_OK) fail("wrc.profile.load: {}: cannot set up the sandbox: {}", path, error_message(L));
  push_option(L, OptionValue::of(options));
  push_option_proxy(L);  // [keys read, proxy]
  s.in_call = 0;
  int status = luaL_loadfilex(L, path.c_str(), "t");
  if (status == LUA_OK) {
    lua_insert(L, -2);  // the chunk below its argument
    lua_sethook(L, count_hook, LUA_MASKCOUNT, kHookEvery);  // kept for the finalizers lua_close runs
    status = lua_pcall(L, 1, 1, 0);
  }
  if (budget.exceeded()) fail("wrc.profile.load: {}", budget.message);
  if (status != LUA_OK) fail("wrc.profile.load: the definition {} failed: {}", path, error_message(L));
  const auto* ud = static_cast<std::shared_ptr<const Profile>*>(luaL_testudata(L, -1, kProfileType));
  if (!ud || !*ud)
    fail("wrc.profile.load: the definition {} returned a {}, expected a wrc.Profile (return wrc.profile.points{{...}})",
         path, type_name(L, -1));
  check_options_read(L, lua_gettop(L) - 1, options, path);
  return **ud;
}

}  // namespace

DefinitionLoader definition_loader(const SandboxLimits& limits) {
  return [limits](const std::string& path, const OptionTable& options) {
    Budget budget;
    budget.limits = limits;
    budget.path = path;
    return run(path, options, budget, 0);
  };
}

Profile load_definition(const std::string& path, const OptionTable& options, const SandboxLimits& limits) {
  const DefinitionLoader definitions = definition_loader(limits);
  return wrc::load_profile(path, options, &definitions);
}

}  // namespace wrc::lua
