// The fields of a sweep's entries (wrc/equilibrium/equilibrium.hpp); the solvers: newton.cpp, wheel.cpp, sweep.cpp.
#include "wrc/equilibrium/equilibrium.hpp"

namespace wrc {

void describe_case(const SweepResult& sweep, std::size_t i, FieldSink& out) {
  out.integer("case", sweep.index[i] + 1, {"-", "the case's number in the sweep's plan (1-based)"});
  describe(sweep.elastic[i], out);
  if (sweep.rigid[i]) {
    out.begin("rigid", {"", "the rigid reference of the case (with rigid = true): a rigid contact result"});
    describe(*sweep.rigid[i], out);
    out.end();
  }
}

}  // namespace wrc
