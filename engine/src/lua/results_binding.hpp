// Engine results as Lua tables: the engine describes each result field by field (core/fields.hpp) into the one
// recorder (core/field_record.hpp), whose tree becomes nested tables, so the binding holds no list of result fields
// of its own.
#pragma once

#include "lua/lua.hpp"
#include "wrc/core/field_record.hpp"

#include <utility>
#include <vector>

namespace wrc::lua {

// The recorded result as a new table on the top of the stack: tables and lists as nested tables (lists 1-based),
// arrays as sequences, grids as wrc.Grid userdata (their values taken from the record), a table's object_type as its
// metatable (registered under that name, e.g. wrc.Patch, when there is one). Values are set with raw access, in the
// tree's order (a repeated key: the last value).
void push_fields(lua_State* L, FieldRecord& record);

// The values of a result's grid (a wrc.Grid userdata at idx, values[i + nx j]) and its size; nullptr when the value
// there is not a grid.
const std::vector<double>* grid_values(lua_State* L, int idx, int& nx, int& ny);

// The result as a table on the top of the stack.
template <class Result, class... Extra>
void push_result(lua_State* L, const Result& r, Extra&&... extra) {
  record_and_convert([L](FieldRecord& record) { push_fields(L, record); }, r, std::forward<Extra>(extra)...);
}

}  // namespace wrc::lua
