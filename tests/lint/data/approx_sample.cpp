// Sample for the self-test of approx.cmake (not compiled): lines 5 and 8 break the rule, the others keep it.
// A comment line may name doctest::Approx(x) freely.
#include <doctest/doctest.h>
void sample(double radius, double angle, double force) {
  CHECK(radius == doctest::Approx(0.45));
  CHECK(radius == doctest::Approx(0.45).epsilon(1e-9).scale(0));
  CHECK(force == doctest::Approx(1.0).epsilon(1e-9));  // approx: unit scale (force / load)
  CHECK(angle == doctest::Approx(0.01).epsilon(1e-6));
  CHECK(angle == doctest::Approx(0.01).scale(1e-3));
}
