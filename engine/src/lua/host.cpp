// The script host: state creation, package paths, protected calls with tracebacks, running a script with the
// command line's flags (host/command_line parses them).
#include "wrc/lua/host.hpp"

#include "lua/bindings.hpp"
#include "lua/convert.hpp"
#include "wrc/core/error.hpp"
#include "wrc/core/paths.hpp"

#include <csignal>
#include <cstdio>
#include <cstring>
#include <initializer_list>
#include <optional>
#include <string>

namespace wrc::lua {

// True when the error object at idx is {exit = code}: a script ending on purpose (e.g. a study's --help).
bool is_exit_request(lua_State* L, int idx) {
  if (!lua_istable(L, idx)) return false;
  const bool integer = lua_getfield(L, idx, "exit") == LUA_TNUMBER && lua_isinteger(L, -1);
  lua_pop(L, 1);
  return integer;
}

int traceback_handler(lua_State* L) {
  if (is_exit_request(L, 1)) return 1;  // passed through untouched
  const char* msg = lua_tostring(L, 1);
  if (msg == nullptr) {  // error object is not a string: use its __tostring or its type
    if (luaL_callmeta(L, 1, "__tostring") && lua_type(L, -1) == LUA_TSTRING) return 1;
    msg = lua_pushfstring(L, "(error object is a %s value)", luaL_typename(L, 1));
  }
  luaL_traceback(L, L, msg, 1);
  return 1;
}

namespace {

// Messages pass as they are: a string raised by `error` or `assert` (the function at level 1 of the stack, the handler
// being level 0), or by an engine function checking its input (a C function whose message starts with its caller's
// "file:line: ", as `guarded` writes it). A runtime error of Lua code, or a C function's error that does not say
// where (a library's "bad argument"), may be a bug: its traceback shows where.
int plain_errors_handler(lua_State* L) {
  lua_Debug ar;
  if (lua_type(L, 1) == LUA_TSTRING && lua_getstack(L, 1, &ar) && lua_getinfo(L, "fS", &ar)) {
    bool message = false;
    for (const char* name : {"error", "assert"}) {
      lua_getglobal(L, name);
      message = message || lua_rawequal(L, -1, -2);
      lua_pop(L, 1);
    }
    lua_pop(L, 1);  // the function
    if (!message && std::strcmp(ar.what, "C") == 0) {
      luaL_where(L, 2);
      const char* where = lua_tostring(L, -1);
      message = *where != '\0' && std::strncmp(lua_tostring(L, 1), where, std::strlen(where)) == 0;
      lua_pop(L, 1);
    }
    if (message) return 1;
  }
  return traceback_handler(L);
}

int pcall_with(lua_State* L, lua_CFunction handler, int nargs, int nresults) {
  const int base = lua_gettop(L) - nargs;  // function index
  lua_pushcfunction(L, handler);
  lua_insert(L, base);
  const int status = lua_pcall(L, nargs, nresults, base);
  lua_remove(L, base);
  return status;
}

}  // namespace

int pcall_traceback(lua_State* L, int nargs, int nresults) { return pcall_with(L, traceback_handler, nargs, nresults); }

int pcall_plain_errors(lua_State* L, int nargs, int nresults) { return pcall_with(L, plain_errors_handler, nargs, nresults); }

namespace {

// require "wrc.x.y" -> <scripts>/x/y.lua (the engine's own Lua library, from any working directory).
// A package searcher is called by Lua, not through `guarded`: it may raise Lua errors itself, so it keeps
// no C++ object with a destructor alive (Lua strings on the stack instead; paths() is a static).
int search_wrc_scripts(lua_State* L) {
  const char* name = luaL_checkstring(L, 1);  // longjmp-safe: no C++ objects alive
  if (std::strncmp(name, "wrc.", 4) != 0) {
    lua_pushliteral(L, "\n\tno 'wrc.' prefix");
    return 1;
  }
  const char* rel = luaL_gsub(L, name + 4, ".", "/");  // "wrc.x.y" -> "x/y"
  const char* scripts = paths().scripts.c_str();
  lua_getglobal(L, "package");
  lua_getfield(L, -1, "searchpath");
  lua_pushstring(L, rel);
  lua_pushfstring(L, "%s/?.lua;%s/?/init.lua", scripts, scripts);
  lua_call(L, 2, 2);
  if (lua_isnil(L, -2)) return 1;  // message from searchpath
  const char* file = lua_tostring(L, -2);
  if (luaL_loadfile(L, file) != LUA_OK) {
    // longjmp-safe: no C++ objects alive
    return luaL_error(L, "error loading module '%s' from file '%s':\n\t%s", name, file, lua_tostring(L, -1));
  }
  lua_pushstring(L, file);
  return 2;
}

void install_searcher(lua_State* L) {
  lua_getglobal(L, "package");
  lua_getfield(L, -1, "searchers");
  const lua_Integer n = luaL_len(L, -1);
  // After the preload searcher (1), so the C module `wrc` itself still comes from package.preload.
  for (lua_Integer i = n; i >= 2; --i) {
    lua_geti(L, -1, i);
    lua_seti(L, -2, i + 1);
  }
  lua_pushcfunction(L, search_wrc_scripts);
  lua_seti(L, -2, 2);
  lua_pop(L, 2);
}

// os.execute as Lua's, except that a command Ctrl-C ended ends this process too. Under os.execute, system() ignores
// SIGINT and SIGQUIT in the caller while the command runs (POSIX), so the terminal's Ctrl-C reached only the command
// (gnuplot for a figure) and the run went on to report the command's failure (exit status 1, not 130). Raised here,
// the signal takes the way of any other: `wrc run`'s handler removes the temporaries and the run ends by it.
int execute_passing_interrupts(lua_State* L) {
  const int args = lua_gettop(L);
  lua_pushvalue(L, lua_upvalueindex(1));
  lua_insert(L, 1);
  lua_call(L, args, LUA_MULTRET);
  const int results = lua_gettop(L);
  if (results == 3 && lua_type(L, 2) == LUA_TSTRING && std::strcmp(lua_tostring(L, 2), "signal") == 0) {
    const auto sig = static_cast<int>(lua_tointeger(L, 3));
    if (sig == SIGINT || sig == SIGQUIT) std::raise(sig);
  }
  return results;
}

void wrap_execute(lua_State* L) {
  lua_getglobal(L, "os");
  lua_getfield(L, -1, "execute");
  lua_pushcclosure(L, execute_passing_interrupts, 1);
  lua_setfield(L, -2, "execute");
  lua_pop(L, 1);
}

int open_state(lua_State* L) {
  luaL_openlibs(L);
  wrap_execute(L);
  luaL_getsubtable(L, LUA_REGISTRYINDEX, LUA_PRELOAD_TABLE);
  lua_pushcfunction(L, luaopen_wrc);
  lua_setfield(L, -2, "wrc");
  lua_pop(L, 1);
  install_searcher(L);
  lua_getglobal(L, "require");
  lua_pushstring(L, "wrc");
  lua_call(L, 1, 1);
  lua_setglobal(L, "wrc");
  return 0;
}

}  // namespace

lua_State* new_state() {
  lua_State* L = luaL_newstate();
  if (L == nullptr) throw Error("cannot create a Lua state (out of memory)");
  lua_pushcfunction(L, open_state);
  if (pcall_traceback(L, 0, 0) != LUA_OK) {
    std::string msg = lua_tostring(L, -1) ? lua_tostring(L, -1) : "unknown error";
    lua_close(L);
    throw Error("cannot initialise the Lua state: " + msg);
  }
  return L;
}

namespace {

void push_args(lua_State* L, const std::string& script, const std::vector<std::string>& args) {
  lua_createtable(L, static_cast<int>(args.size()), 4);
  lua_pushstring(L, script.c_str());
  lua_rawseti(L, -2, 0);
  lua_Integer positional = 0;
  for (const std::string& a : args) {
    const auto eq = a.find('=');
    if (eq == std::string::npos) {  // a key=value word has a key (host/command_line checked it)
      lua_pushstring(L, a.c_str());
      lua_rawseti(L, -2, ++positional);
      continue;
    }
    const std::string key = a.substr(0, eq), value = a.substr(eq + 1);
    if (lua_stringtonumber(L, value.c_str()) == 0) lua_pushstring(L, value.c_str());
    lua_setfield(L, -2, key.c_str());
  }
  lua_setglobal(L, "arg");
}

// wrc.command = {script =, shard =, shards =, shard_from =, merge =, fresh =, help =}.
void push_command(lua_State* L, const std::string& script, const host::RunFlags& flags) {
  lua_getglobal(L, "wrc");
  lua_createtable(L, 0, 8);
  set_string(L, "script", script);
  set_integer(L, "shard", flags.shard);
  set_integer(L, "shards", flags.shards);
  set_string(L, "shard_from", flags.shard_from);
  set_bool(L, "merge", flags.merge);
  set_bool(L, "fresh", flags.fresh);
  set_bool(L, "help", flags.help);
  set_bool(L, "from_parts", flags.from_parts);
  lua_setfield(L, -2, "command");
  lua_pop(L, 1);
}

// The exit code of a finished run: the error's message on stderr (1), {exit = code} quietly, or the
// wrc.command.status a successful script left (0 by default).
int exit_code(lua_State* L, int status) {
  if (status != LUA_OK) {
    if (is_exit_request(L, -1)) {
      lua_getfield(L, -1, "exit");
      return static_cast<int>(lua_tointeger(L, -1));
    }
    const char* msg = lua_tostring(L, -1);
    // luaL_loadfile says "cannot open <file>" for a missing file; syntax errors carry file:line.
    std::fprintf(stderr, "wrc: %s\n", msg ? msg : "error object is not a string");
    return 1;
  }
  lua_getglobal(L, "wrc");
  lua_getfield(L, -1, "command");
  const int code = lua_istable(L, -1) && lua_getfield(L, -1, "status") == LUA_TNUMBER ? static_cast<int>(lua_tointeger(L, -1)) : 0;
  return code;
}

// True when the script ran a study (wrc.study's s:run sets wrc.command.study).
bool declared_study(lua_State* L) {
  lua_getglobal(L, "wrc");
  const bool study = lua_istable(L, -1) && lua_getfield(L, -1, "command") == LUA_TTABLE &&
                     lua_getfield(L, -1, "study") == LUA_TBOOLEAN && lua_toboolean(L, -1);
  lua_settop(L, 0);
  return study;
}

lua_State* open_or_report() {
  try {
    return new_state();
  } catch (const std::exception& e) {
    std::fprintf(stderr, "wrc: %s\n", e.what());
    return nullptr;
  }
}

}  // namespace

int run_file(const std::string& path, const std::vector<std::string>& args, const host::RunFlags& flags) {
  lua_State* L = open_or_report();
  if (L == nullptr) return 1;
  push_args(L, path, args);
  push_command(L, path, flags);
  int status = luaL_loadfile(L, path.c_str());
  if (status == LUA_OK) status = pcall_traceback(L, 0, 0);
  int code = exit_code(L, status);
  if (status == LUA_OK && (flags.shards > 1 || flags.merge || flags.fresh || flags.help) && !declared_study(L)) {
    // A plain script ignores the flags: it ran whole. For a shard or a merge that is an error of the command.
    std::fprintf(stderr, "wrc: %s runs no study through wrc.study (study.new, s:run): the flags --shard, --merge, "
                 "--fresh and --help do not apply to it, and it ran as a whole\n", path.c_str());
    if (flags.shards > 1 || flags.merge) code = 2;
  }
  lua_close(L);
  return code;
}

int refuse_folder_merge(const std::string& folder) {
  lua_State* L = open_or_report();
  if (L == nullptr) return 1;
  push_command(L, "", host::RunFlags{});
  int status = luaL_loadstring(L, "return require('wrc.study').refuse_folder_merge(...)");
  if (status == LUA_OK) {
    lua_pushstring(L, folder.c_str());
    status = pcall_traceback(L, 1, 0);
  }
  const int code = exit_code(L, status);
  lua_close(L);
  return code == 0 ? 2 : code;
}

Session::Session() : state_(new_state()) {}

Session::~Session() { lua_close(static_cast<lua_State*>(state_)); }

std::optional<std::string> Session::run(std::string_view code, const std::string& chunkname) {
  auto* L = static_cast<lua_State*>(state_);
  int status = luaL_loadbuffer(L, code.data(), code.size(), chunkname.c_str());
  if (status == LUA_OK) status = pcall_traceback(L, 0, 0);
  if (status == LUA_OK) return std::nullopt;
  std::string msg = lua_tostring(L, -1) ? lua_tostring(L, -1) : "error object is not a string";
  lua_pop(L, 1);
  return msg;
}

}  // namespace wrc::lua
