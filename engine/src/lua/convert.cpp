#include "lua/convert.hpp"

#include "wrc/profile/profile.hpp"
#include "wrc/wheelset/contact.hpp"
#include "wrc/wheelset/tangential.hpp"

#include <cmath>
#include <string>

namespace wrc::lua {

void check_table(lua_State* L, int idx, std::string_view context) {
  if (!lua_istable(L, idx)) fail("{}: expected a table, got {}", context, type_name(L, idx));
}

double check_number(lua_State* L, int idx, std::string_view context) {
  int isnum = 0;
  double v = lua_tonumberx(L, idx, &isnum);
  if (!isnum) fail("{}: argument {} must be a number, got {}", context, idx, type_name(L, idx));
  if (!std::isfinite(v)) fail("{}: argument {} must be finite, got {}", context, idx, v);
  return v;
}

std::string check_string(lua_State* L, int idx, std::string_view context) {
  if (lua_type(L, idx) != LUA_TSTRING) fail("{}: argument {} must be a string, got {}", context, idx, type_name(L, idx));
  std::size_t n = 0;
  const char* s = lua_tolstring(L, idx, &n);
  return std::string(s, n);  // all of it: a Lua string may hold NUL bytes, which the callee must see (a path's check)
}

void push_vec3(lua_State* L, const Eigen::Vector3d& v) {
  lua_createtable(L, 0, 3);
  set_number(L, "x", v.x());
  set_number(L, "y", v.y());
  set_number(L, "z", v.z());
}

void push_array(lua_State* L, const double* data, std::size_t n) {
  lua_createtable(L, static_cast<int>(n), 0);
  for (std::size_t i = 0; i < n; ++i) {
    lua_pushnumber(L, data[i]);
    lua_rawseti(L, -2, static_cast<lua_Integer>(i + 1));
  }
}

void set_number(lua_State* L, const char* key, double v) {
  lua_pushnumber(L, v);
  lua_setfield(L, -2, key);
}

void set_integer(lua_State* L, const char* key, long long v) {
  lua_pushinteger(L, static_cast<lua_Integer>(v));
  lua_setfield(L, -2, key);
}

void set_string(lua_State* L, const char* key, std::string_view v) {
  lua_pushlstring(L, v.data(), v.size());
  lua_setfield(L, -2, key);
}

void set_bool(lua_State* L, const char* key, bool v) {
  lua_pushboolean(L, v);
  lua_setfield(L, -2, key);
}

namespace {

OptionValue table_option(lua_State* L, int idx, std::string_view context, int depth) {
  if (depth > kMaxOptionDepth) fail("{}: tables nested more than {} levels deep", context, kMaxOptionDepth);
  std::vector<OptionValue> array;
  OptionTable table;
  table.dialect = OptionDialect::lua;
  // Raw access only: a metamethod that raised would longjmp past the C++ objects being built here.
  const lua_Integer n = static_cast<lua_Integer>(lua_rawlen(L, idx));
  lua_pushnil(L);
  while (lua_next(L, idx) != 0) {
    int isint = 0;
    const lua_Integer k = lua_tointegerx(L, -2, &isint);
    if (lua_type(L, -2) == LUA_TSTRING) {
      const std::string key = lua_tostring(L, -2);
      table.entries.emplace_back(key, to_option_at(L, lua_gettop(L), fmt::format("{}.{}", context, key), depth + 1));
    } else if (!(lua_type(L, -2) == LUA_TNUMBER && isint && k >= 1 && k <= n)) {
      lua_pop(L, 2);
      fail("{}: a table with keys that are neither names nor 1..n", context);
    }
    lua_pop(L, 1);
  }
  if (n > 0 && !table.empty()) fail("{}: a table with both an array part and named keys", context);
  if (n == 0) return OptionValue::of(std::move(table));
  for (lua_Integer i = 1; i <= n; ++i) {
    lua_rawgeti(L, idx, i);
    array.push_back(to_option_at(L, lua_gettop(L), fmt::format("{}[{}]", context, i), depth + 1));
    lua_pop(L, 1);
  }
  return OptionValue::of(std::move(array));
}

}  // namespace

OptionValue to_option_at(lua_State* L, int idx, std::string_view context, int depth) {
  switch (lua_type(L, idx)) {
    case LUA_TNUMBER: return OptionValue::of(static_cast<double>(lua_tonumber(L, idx)));
    case LUA_TBOOLEAN: return OptionValue::of(static_cast<bool>(lua_toboolean(L, idx)));
    case LUA_TSTRING: {
      std::size_t n = 0;
      const char* s = lua_tolstring(L, idx, &n);
      return OptionValue::of(std::string(s, n));
    }
    case LUA_TTABLE: return table_option(L, lua_absindex(L, idx), context, depth);
    case LUA_TUSERDATA:
      if (auto* p = static_cast<std::shared_ptr<const Profile>*>(luaL_testudata(L, idx, "wrc.Profile")))
        return OptionValue::of_object(*p, "wrc.Profile");
      if (auto* c = static_cast<std::shared_ptr<const ContactStart>*>(luaL_testudata(L, idx, ContactStart::kTypeName)))
        if (*c) return OptionValue::of_object(*c, ContactStart::kTypeName);
      [[fallthrough]];
    default: fail("{}: a {} cannot be an option value", context, type_name(L, idx));
  }
}

OptionValue to_option(lua_State* L, int idx, std::string_view context) { return to_option_at(L, idx, context, 0); }

namespace {

// A function of the rail's lateral coordinate as the table {y = {...}, mu = {...}} of its values, sampled where
// wheelset/tangential.hpp says. The function runs protected: its error becomes this call's.
OptionValue sampled_function(lua_State* L, int idx, std::string_view context) {
  const int n = static_cast<int>(std::lround((kFrictionProfileTo - kFrictionProfileFrom) / kFrictionProfileStep)) + 1;
  std::vector<OptionValue> ys, mus;
  for (int i = 0; i < n; ++i) {
    const double y = kFrictionProfileFrom + i * kFrictionProfileStep;
    lua_pushvalue(L, idx);
    lua_pushnumber(L, y);
    if (lua_pcall(L, 1, 1, 0) != LUA_OK) {
      const std::string msg = lua_tostring(L, -1) ? lua_tostring(L, -1) : "(no message)";
      lua_pop(L, 1);
      fail("{}: the function failed at y = {} m: {}", context, y, msg);
    }
    int isnum = 0;
    const double mu = lua_tonumberx(L, -1, &isnum);
    const char* got = type_name(L, -1);
    lua_pop(L, 1);
    if (!isnum) fail("{}: the function returned a {} at y = {} m, expected a number (mu)", context, got, y);
    ys.push_back(OptionValue::of(y));
    mus.push_back(OptionValue::of(mu));
  }
  OptionTable t;
  t.set("y", OptionValue::of(std::move(ys)));
  t.set("mu", OptionValue::of(std::move(mus)));
  return OptionValue::of(std::move(t));
}

// friction_profile: a function, a table {left =, right =} of functions or tables, or a table {y =, mu =}.
OptionValue friction_profile_option(lua_State* L, int idx, std::string_view context) {
  if (lua_type(L, idx) == LUA_TFUNCTION) return sampled_function(L, idx, context);
  if (lua_type(L, idx) != LUA_TTABLE) return to_option_at(L, idx, context, 1);
  OptionTable sides;
  bool functions = false;
  for (const char* side : {"left", "right"}) {
    lua_pushstring(L, side);
    lua_rawget(L, idx);  // raw: a metamethod that raised would longjmp past the C++ objects here
    const int top = lua_gettop(L);
    if (lua_type(L, top) == LUA_TFUNCTION) {
      sides.set(side, sampled_function(L, top, fmt::format("{}.{}", context, side)));
      functions = true;
    } else if (!lua_isnil(L, top)) {
      sides.set(side, to_option_at(L, top, fmt::format("{}.{}", context, side), 2));
    }
    lua_pop(L, 1);
  }
  if (!functions) return to_option_at(L, idx, context, 1);
  lua_pushnil(L);
  while (lua_next(L, idx) != 0) {
    const bool side = lua_type(L, -2) == LUA_TSTRING &&
                      (std::string_view(lua_tostring(L, -2)) == "left" || std::string_view(lua_tostring(L, -2)) == "right");
    lua_pop(L, 1);
    if (!side) {
      lua_pop(L, 1);
      fail("{}: with functions per wheel only the keys 'left' and 'right'", context);
    }
  }
  return OptionValue::of(std::move(sides));
}

}  // namespace

OptionTable to_options(lua_State* L, int idx, std::string_view context, std::initializer_list<std::string_view> skip) {
  if (lua_isnoneornil(L, idx)) return {};
  check_table(L, idx, context);
  idx = lua_absindex(L, idx);
  OptionTable t;
  lua_pushnil(L);
  while (lua_next(L, idx) != 0) {
    if (lua_type(L, -2) != LUA_TSTRING) {
      lua_pop(L, 2);
      fail("{}: option keys must be names", context);
    }
    const std::string key = lua_tostring(L, -2);
    bool skipped = false;
    for (auto k : skip) skipped = skipped || k == key;
    const std::string where = fmt::format("{}: '{}'", context, key);
    if (!skipped)
      t.entries.emplace_back(key, key == "friction_profile" ? friction_profile_option(L, lua_gettop(L), where)
                                                            : to_option_at(L, lua_gettop(L), where, 1));
    lua_pop(L, 1);
  }
  return t;
}

void push_option(lua_State* L, const OptionValue& v) {
  switch (v.type) {
    case OptionValue::Type::number: lua_pushnumber(L, v.number); return;
    case OptionValue::Type::boolean: lua_pushboolean(L, v.boolean); return;
    case OptionValue::Type::string: lua_pushlstring(L, v.string.data(), v.string.size()); return;
    case OptionValue::Type::array:
      lua_createtable(L, static_cast<int>(v.array.size()), 0);
      for (std::size_t i = 0; i < v.array.size(); ++i) {
        push_option(L, v.array[i]);
        lua_rawseti(L, -2, static_cast<lua_Integer>(i + 1));
      }
      return;
    case OptionValue::Type::table:
      lua_createtable(L, 0, static_cast<int>(v.table->entries.size()));
      for (const auto& [k, e] : v.table->entries) {
        push_option(L, e);
        lua_setfield(L, -2, k.c_str());
      }
      return;
    case OptionValue::Type::object:
      if (v.string != kProfileTypeName) fail("an object of type {} has no Lua value", v.string);
      push_shared(L, std::static_pointer_cast<const Profile>(v.object), kProfileTypeName);
      return;
  }
}

OptionTable table_options(lua_State* L, int idx, std::string_view context, std::initializer_list<std::string_view> skip) {
  check_table(L, idx, context);
  return to_options(L, idx, context, skip);
}

}  // namespace wrc::lua
