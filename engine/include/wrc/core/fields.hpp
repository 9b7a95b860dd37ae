// Results described field by field, once, for every consumer: the front ends record it (core/field_record.hpp) and
// convert it (Lua tables, C paths "left.patches.1.force.z", Python Results; a CSV writer a row). A result type provides
//   void describe(const Result&, FieldSink&)
// calling the sink's methods in a fixed order. Names carry no units: each call gives the field's FieldDoc (unit and
// meaning) beside its value, so that a field reference is made by the same calls that
// fill results and cannot drift from them.
#pragma once

#include <Eigen/Core>

#include <cstddef>
#include <string_view>

namespace wrc {

// What a field is: its unit (SI: "m", "N", "Pa", "rad", "N m"; "-" for a pure number, an index or a count; "" for
// text, flags and lists) and one line of meaning (signs and frames by docs/design.md, section 2). Every field of the
// engine's results has one: DocSink (core/field_reference.hpp) writes them into docs/reference/fields.md, and the
// test that regenerates that page fails on a field without.
struct FieldDoc {
  const char* unit = "";
  const char* meaning = "";
};

class FieldSink {
 public:
  virtual ~FieldSink() = default;
  virtual void number(std::string_view key, double v) = 0;
  virtual void integer(std::string_view key, long long v) = 0;
  virtual void boolean(std::string_view key, bool v) = 0;
  virtual void string(std::string_view key, std::string_view v) = 0;
  // An array of numbers, of integers.
  virtual void numbers(std::string_view key, const double* v, std::size_t n) = 0;
  virtual void integers(std::string_view key, const long long* v, std::size_t n) = 0;
  // A grid of nx x ny values v[i + nx j] (Lua: rows j = 1..ny of nx values).
  virtual void grid(std::string_view key, const double* v, int nx, int ny) = 0;
  // A nested table, until end().
  virtual void begin(std::string_view key) = 0;
  // A list of n tables, each opened by item() and closed by end(); the list itself is closed by end().
  virtual void begin_list(std::string_view key, std::size_t n) = 0;
  virtual void item() = 0;
  virtual void end() = 0;
  // The table being filled is an object of this kind (e.g. "wrc.Patch": a contact area, whose Lua table then has
  // the methods of that type, p:subsurface{...}); sinks without methods ignore it.
  virtual void object_type(std::string_view /*name*/) {}

  // The same with the field's documentation, handed to document() first.
  void number(std::string_view key, double v, FieldDoc doc) {
    document(key, doc);
    number(key, v);
  }
  void integer(std::string_view key, long long v, FieldDoc doc) {
    document(key, doc);
    integer(key, v);
  }
  void boolean(std::string_view key, bool v, FieldDoc doc) {
    document(key, doc);
    boolean(key, v);
  }
  void string(std::string_view key, std::string_view v, FieldDoc doc) {
    document(key, doc);
    string(key, v);
  }
  void numbers(std::string_view key, const double* v, std::size_t n, FieldDoc doc) {
    document(key, doc);
    numbers(key, v, n);
  }
  void integers(std::string_view key, const long long* v, std::size_t n, FieldDoc doc) {
    document(key, doc);
    integers(key, v, n);
  }
  void grid(std::string_view key, const double* v, int nx, int ny, FieldDoc doc) {
    document(key, doc);
    grid(key, v, nx, ny);
  }
  void begin(std::string_view key, FieldDoc doc) {
    document(key, doc);
    begin(key);
  }
  void begin_list(std::string_view key, std::size_t n, FieldDoc doc) {
    document(key, doc);
    begin_list(key, n);
  }

  // {x =, y =, z =}: a vector, each component with the vector's unit.
  void vec3(std::string_view key, const Eigen::Vector3d& v, FieldDoc doc = {}) {
    begin(key, doc);
    number("x", v.x(), {doc.unit, "x component"});
    number("y", v.y(), {doc.unit, "y component"});
    number("z", v.z(), {doc.unit, "z component"});
    end();
  }

 protected:
  // The documentation of the field `key` that the next call fills (a sink that writes a reference records it;
  // the others ignore it).
  virtual void document(std::string_view /*key*/, FieldDoc /*doc*/) {}
};

}  // namespace wrc
