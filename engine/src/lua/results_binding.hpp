// Engine results as Lua tables: the engine describes each result field by field (core/fields.hpp); LuaSink turns
// the description into nested tables, so the binding holds no list of result fields of its own.
#pragma once

#include "lua/lua.hpp"
#include "wrc/core/fields.hpp"

#include <string>
#include <vector>

namespace wrc::lua {

// Pushes one new table on construction; describe(result, sink) then fills it. Values are set with raw access.
class LuaSink final : public FieldSink {
 public:
  explicit LuaSink(lua_State* L);
  void number(std::string_view key, double v) override;
  void integer(std::string_view key, long long v) override;
  void boolean(std::string_view key, bool v) override;
  void string(std::string_view key, std::string_view v) override;
  void numbers(std::string_view key, const double* v, std::size_t n) override;
  void integers(std::string_view key, const long long* v, std::size_t n) override;
  void grid(std::string_view key, const double* v, int nx, int ny) override;
  void begin(std::string_view key) override;
  void begin_list(std::string_view key, std::size_t n) override;
  void item() override;
  void end() override;
  // Sets the metatable registered under `name` (e.g. wrc.Patch) on the table being filled, when there is one.
  void object_type(std::string_view name) override;

 private:
  void set(std::string_view key);  // t[key] = value on top, t below it
  struct Frame {
    std::string key;
    bool item = false;  // an item of a list (set by index on end())
    int count = 0;      // items so far, for a list
  };
  lua_State* L_;
  std::vector<Frame> frames_;
};

// The values of a result's grid (a wrc.Grid userdata at idx, values[i + nx j]) and its size; nullptr when the value
// there is not a grid.
const std::vector<double>* grid_values(lua_State* L, int idx, int& nx, int& ny);

// The result as a table on the top of the stack.
template <class Result, class... Extra>
void push_result(lua_State* L, const Result& r, Extra&&... extra) {
  LuaSink sink(L);
  describe(r, sink, std::forward<Extra>(extra)...);
}

}  // namespace wrc::lua
