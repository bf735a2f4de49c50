// SPDX-License-Identifier: BSL-1.0
// A position policy whose equation is dimensionally wrong (p0 + v0 t^2: metres plus
// metre-seconds) compiles on plain numbers but not in the SI particle's step. The error is
// the sum in the policy (line 15, column 15), between a length and a length times a time.
// expected-error: step_equation_dimension_error.cpp:15:15: error: no match for
// expected-error: step_equation_dimension_error.cpp:15:15: error: invalid operands to binary expression
#include <pointmass/units.hpp>

namespace si = boost::units::si;

struct UserWrongPosition {
  template <class P, class V, class A, class T, class F>
  static constexpr P position(const P& p0, const V& v0, const V&, const A&, const T& t,
                              const F&) noexcept {
    return p0 + v0 * t * t;
  }
};

int main() {
  pointmass::Particle<double, pointmass::damping::PerSecond, UserWrongPosition> plain;
  plain.integrate(0.033);  // compiles: plain numbers carry no dimension
  pointmass::units::Particle<double, pointmass::damping::PerSecond, UserWrongPosition> checked;
  checked.integrate(0.033 * si::seconds);  // does not
}
