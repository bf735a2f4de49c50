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

template <class Real>
Real Vector3<Real>::magnitude() const {
  return std::sqrt(x * x + y * y + z * z);
}

template <class Real>
void Vector3<Real>::normalise() {
  const Real length = magnitude();
  if (length > 0) *this *= Real(1) / length;
}

template <class Real>
void ParticleDrag<Real>::update_force(Particle<Real>* particle, Real) {
  Vector3<Real> force = particle->velocity();
  Real drag = force.magnitude();
  drag = k1_ * drag + k2_ * drag * drag;
  force.normalise();
  force *= -drag;
  particle->add_force(force);
}

template <class Real>
void ParticleAnchoredSpring<Real>::update_force(Particle<Real>* particle, Real) {
  Vector3<Real> force = particle->position();
  force.add_scaled_vector(*anchor_, Real(-1));
  Real magnitude = force.magnitude();
  magnitude = (rest_length_ - magnitude) * spring_constant_;
  force.normalise();
  force *= magnitude;
  particle->add_force(force);
}

template <class Real>
void ParticleForceRegistry<Real>::update_forces(Real duration) {
  for (const Registration& registration : registrations_) {
    registration.generator->update_force(registration.particle, duration);
  }
}

template class Particle<float>;
template class Particle<double>;
template struct Vector3<float>;
template struct Vector3<double>;
template class ParticleDrag<float>;
template class ParticleDrag<double>;
template class ParticleAnchoredSpring<float>;
template class ParticleAnchoredSpring<double>;
template class ParticleForceRegistry<float>;
template class ParticleForceRegistry<double>;

}  // namespace reference_engine
