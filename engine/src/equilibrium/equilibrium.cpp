// The fields of a sweep's entries (wrc/equilibrium/equilibrium.hpp); the solvers: newton.cpp, wheel.cpp, sweep.cpp.
#include "wrc/equilibrium/equilibrium.hpp"

namespace wrc {

void describe_case(const SweepResult& sweep, std::size_t i, FieldSink& out) {
  out.integer("case", sweep.index[i] + 1);
  describe(sweep.elastic[i], out);
  if (sweep.rigid[i]) {
    out.begin("rigid");
    describe(*sweep.rigid[i], out);
    out.end();
  }
}

}  // namespace wrc
