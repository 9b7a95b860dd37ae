// The length units of profile files: the names the `units` option of wrc.profile.load takes and a text file's header
// may give (`y_mm`, `z [cm]`, `y (in)`). One list for both, so that a header naming a unit the option takes is read in
// it rather than taken for the default millimetres. Header-only: the reader plugins use it too.
#pragma once

#include <string>
#include <string_view>

namespace wrc {

struct LengthUnit {
  std::string_view name;
  double metres;  // metres per unit
};
inline constexpr LengthUnit kLengthUnits[] = {{"mm", 1e-3}, {"cm", 1e-2}, {"m", 1.0}, {"in", 0.0254}};

// Metres per unit of `name` (exact, case-sensitive), 0 when it names none of kLengthUnits.
constexpr double length_unit(std::string_view name) {
  for (const LengthUnit& u : kLengthUnits)
    if (u.name == name) return u.metres;
  return 0;
}

// "\"mm\", \"cm\", \"m\", \"in\"": the names, for messages.
inline std::string length_unit_names() {
  std::string s;
  for (const LengthUnit& u : kLengthUnits) s += (s.empty() ? "\"" : ", \"") + std::string(u.name) + "\"";
  return s;
}

}  // namespace wrc
