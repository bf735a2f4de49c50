// SPDX-License-Identifier: BSL-1.0
// What fuzz_pointmass.cpp (checks on) shares with other_settings.cpp (checks off): the user
// column whose construction can throw, the systems both units drive, and the operations the
// other unit runs on the fuzz target's systems (the checks setting changes no type).
#pragma once

#include <pointmass/particle_system.hpp>

#include <cstddef>

namespace fuzz {

// The user column of the systems with the game features (tag and value).
struct FuzzOwner {};
// A value the column is built from; its conversion throws when `refuse` is set.
struct FuzzSeed {
  int value;
  bool refuse;
};
struct FuseBlown {};
// While set, Fuse's default constructor (the T{} of a spawn without a value) throws.
inline bool fuse_refuses = false;
// Trivially copyable (as a column must be), with constructors that can throw: without
// exceptions they never do.
struct Fuse {
  int value;
  Fuse() : value(0) {
#if POINTMASS_HAS_EXCEPTIONS
    if (fuse_refuses) throw FuseBlown{};
#endif
  }
  Fuse(int v) : value(v) {}  // NOLINT(google-explicit-constructor): the int column's spelling
  Fuse(FuzzSeed seed) : value(seed.value) {  // NOLINT(google-explicit-constructor)
#if POINTMASS_HAS_EXCEPTIONS
    if (seed.refuse) throw FuseBlown{};
#endif
  }
  friend bool operator==(const Fuse&, const Fuse&) = default;
};

namespace pm = pointmass;
// The systems of the extended operations (first bytes 0xFA to 0xFF).
using FuseFloat = pm::ParticleSystem<float, pm::damping::PerSecond, pm::position::Euler,
                                     pm::features::Lifetime, pm::features::Interpolation,
                                     pm::features::Handles, pm::features::Column<FuzzOwner, Fuse>>;
using FuseDouble = pm::ParticleSystem<double, pm::damping::PerSecond, pm::position::Euler,
                                      pm::features::Lifetime, pm::features::Interpolation,
                                      pm::features::Handles, pm::features::Column<FuzzOwner, Fuse>>;
using FuseExact =
    pm::ParticleSystem<double, pm::damping::Exact, pm::position::Exact,
                       pm::features::PerParticleDamping, pm::features::PerParticleAcceleration,
                       pm::features::ForceAccumulator, pm::features::Lifetime,
                       pm::features::Handles, pm::features::Column<FuzzOwner, Fuse>>;
using FuseCompensated =
    pm::ParticleSystem<pm::Precision<float, pm::Compensated<float>>,
                       pm::damping::AccelerateThenDamp, pm::position::SemiImplicit,
                       pm::features::ForceAccumulator, pm::features::Handles,
                       pm::features::Column<FuzzOwner, Fuse>>;

// A particle's state as the other unit reads it.
template <class System>
struct Read {
  pm::Vector3<typename System::position_value> position;
  pm::Vector3<typename System::real> velocity;
  int owner;
  typename System::Handle handle;
};

// Operations compiled in other_settings.cpp, with the checks off (explicitly instantiated
// there for the systems above). Only hot-path preconditions differ between the settings: the
// target gives these a valid duration and index; setters and spawns validate either way.
template <class System>
struct OtherSettings {
  using R = typename System::real;
  using W = typename System::position_value;
  static std::size_t spawn(System& system, const pm::Vector3<W>& p, const pm::Vector3<R>& v);
  static std::size_t spawn(System& system, const pm::Vector3<W>& p, const pm::Vector3<R>& v,
                           int owner);
  static void kill(System& system, std::size_t i);
  static void set_velocity(System& system, std::size_t i, const pm::Vector3<R>& v);
  static void set_column(System& system, std::size_t i, int owner);
  static void step(System& system, R duration);
  static void step_particles(System& system, R duration);  // begin_step, step_particle, finish
  static Read<System> read(const System& system, std::size_t i);  // i < size()
  static std::size_t size(const System& system);
};

}  // namespace fuzz
