// SPDX-License-Identifier: BSL-1.0
// A stand-in for Cyclone's particle, as /work/shared/SPEC.md describes it, for
// benchmarks/engine_step.cpp (its cost) and tests/reference/test_engine_replay.cpp (its
// trajectories): a vector of x, y, z and one padding component (16 bytes in float, 32 in
// double); a particle storing, in this order, inverse mass, damping, position, velocity,
// force accumulator and acceleration (72 bytes in float, 144 in double); `integrate` an
// ordinary member function defined in its own translation unit (reference_engine.cpp, so not
// inlined into a caller's loop), returning at once for inverse mass <= 0, asserting a
// positive duration, and computing the code listing's form with one pow per call:
//   p += v t;  a = acceleration + force * inverse_mass;  v += a t;  v *= pow(damping, t);
//   force = 0.
// It is written from that description, not from the engine's source. Beside it, the engine's
// force generators (SPEC.md, "The reference engine's force generators"): an interface with
// one virtual update_force, drag and an anchored spring, and a registry of (particle,
// generator) pairs walked in insertion order, each defined in reference_engine.cpp.
#pragma once

#include <vector>

namespace reference_engine {

template <class Real>
struct Vector3 {
  Real x = 0;
  Real y = 0;
  Real z = 0;

 private:
  Real pad = 0;  // the engine's fourth component, for alignment in its own containers

 public:
  Vector3() = default;
  Vector3(Real x_, Real y_, Real z_) : x(x_), y(y_), z(z_) {}
  void add_scaled_vector(const Vector3& v, Real scale) {
    x += v.x * scale;
    y += v.y * scale;
    z += v.z * scale;
  }
  void operator*=(Real scale) {
    x *= scale;
    y *= scale;
    z *= scale;
  }
  void clear() { x = y = z = 0; }
  /// The engine's magnitude and normalise (divides when the magnitude is positive).
  Real magnitude() const;
  void normalise();
};

template <class Real>
class Particle {
 public:
  /// Defined in reference_engine.cpp (instantiated there for float and double).
  void integrate(Real duration);

  void set_mass(Real mass) { inverse_mass_ = Real(1) / mass; }
  void set_inverse_mass(Real inverse_mass) { inverse_mass_ = inverse_mass; }
  void set_damping(Real damping) { damping_ = damping; }
  void set_position(const Vector3<Real>& p) { position_ = p; }
  void set_velocity(const Vector3<Real>& v) { velocity_ = v; }
  void set_acceleration(const Vector3<Real>& a) { acceleration_ = a; }
  void add_force(const Vector3<Real>& f) { force_accumulator_.add_scaled_vector(f, Real(1)); }
  const Vector3<Real>& position() const { return position_; }
  const Vector3<Real>& velocity() const { return velocity_; }

 private:
  Real inverse_mass_ = 1;
  Real damping_ = 1;
  Vector3<Real> position_;
  Vector3<Real> velocity_;
  Vector3<Real> force_accumulator_;
  Vector3<Real> acceleration_;
};

static_assert(sizeof(Vector3<float>) == 16 && sizeof(Vector3<double>) == 32);
static_assert(sizeof(Particle<float>) == 72 && sizeof(Particle<double>) == 144);

/// The engine's force generator: one virtual member that adds to a particle's force.
template <class Real>
class ParticleForceGenerator {
 public:
  ParticleForceGenerator() = default;
  ParticleForceGenerator(const ParticleForceGenerator&) = default;
  ParticleForceGenerator& operator=(const ParticleForceGenerator&) = default;
  virtual ~ParticleForceGenerator() = default;
  virtual void update_force(Particle<Real>* particle, Real duration) = 0;
};

/// -(k1 s + k2 s^2) times the normalised velocity, s the speed.
template <class Real>
class ParticleDrag : public ParticleForceGenerator<Real> {
 public:
  ParticleDrag(Real k1, Real k2) : k1_(k1), k2_(k2) {}
  void update_force(Particle<Real>* particle, Real duration) override;

 private:
  Real k1_;
  Real k2_;
};

/// (rest - |d|) k times the normalised d = position - *anchor.
template <class Real>
class ParticleAnchoredSpring : public ParticleForceGenerator<Real> {
 public:
  ParticleAnchoredSpring(Vector3<Real>* anchor, Real spring_constant, Real rest_length)
      : anchor_(anchor), spring_constant_(spring_constant), rest_length_(rest_length) {}
  void update_force(Particle<Real>* particle, Real duration) override;

 private:
  Vector3<Real>* anchor_;
  Real spring_constant_;
  Real rest_length_;
};

/// (particle, generator) pairs, walked in insertion order: one virtual call each.
template <class Real>
class ParticleForceRegistry {
 public:
  void add(Particle<Real>* particle, ParticleForceGenerator<Real>* generator) {
    registrations_.push_back({particle, generator});
  }
  void update_forces(Real duration);

 private:
  struct Registration {
    Particle<Real>* particle;
    ParticleForceGenerator<Real>* generator;
  };
  std::vector<Registration> registrations_;
};

}  // namespace reference_engine
