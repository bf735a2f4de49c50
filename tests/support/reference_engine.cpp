// SPDX-License-Identifier: BSL-1.0
// Cyclone's integrate, out of line (see reference_engine.hpp): what a loop over
// the engine's particles pays is this call, and one pow in it.
#include "reference_engine.hpp"

#include <cassert>
#include <cmath>

namespace reference_engine {

namespace {
float real_pow(float base, float exponent) { return ::powf(base, exponent); }
double real_pow(double base, double exponent) { return ::pow(base, exponent); }
}  // namespace

template <class Real>
void Particle<Real>::integrate(Real duration) {
  if (inverse_mass_ <= 0) return;
  assert(duration > 0);
  position_.add_scaled_vector(velocity_, duration);
  Vector3<Real> resulting_acceleration = acceleration_;
  resulting_acceleration.add_scaled_vector(force_accumulator_, inverse_mass_);
  velocity_.add_scaled_vector(resulting_acceleration, duration);
  velocity_ *= real_pow(damping_, duration);
  force_accumulator_.clear();
}

template class Particle<float>;
template class Particle<double>;

}  // namespace reference_engine
