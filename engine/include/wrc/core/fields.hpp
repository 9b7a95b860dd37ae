// Results described field by field, once, for every consumer: the Lua binding builds tables from them, the C API
// a flat map of "left.patches.1.force.z" paths, a CSV writer a row. A result type provides
//   void describe(const Result&, FieldSink&)
// calling the sink's methods in a fixed order; names carry no units, the headers of the result types give them.
#pragma once

#include <Eigen/Core>

#include <cstddef>
#include <string_view>

namespace wrc {

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

  // {x =, y =, z =}
  void vec3(std::string_view key, const Eigen::Vector3d& v) {
    begin(key);
    number("x", v.x());
    number("y", v.y());
    number("z", v.z());
    end();
  }
};

}  // namespace wrc
