// SPDX-License-Identifier: BSL-1.0
// Force generators on the batch: a ParticleSystem with features::ForceAccumulator satisfies the Bodies
// concept itself, and its arrays can be wrapped in SoaBodies (named, or passed as a temporary);
// all give a particle's bits.
#include <doctest/doctest.h>

#include <array>

#include <pointmass/forces.hpp>
#include <pointmass/particle.hpp>
#include <pointmass/particle_system.hpp>

namespace {
using pointmass::Vector3;
namespace forces = pointmass::forces;
namespace damping = pointmass::damping;
namespace position = pointmass::position;
}  // namespace

TEST_CASE_TEMPLATE("generators on a ParticleSystem match Particle, through apply and SoaBodies", R,
                   float, double) {
  using System = pointmass::ParticleSystem<R, damping::None, position::SemiImplicit,
                                           pointmass::features::ForceAccumulator>;
  using Body = pointmass::Particle<R, damping::None, position::SemiImplicit>;
  static_assert(forces::Bodies<System>);
  const std::array<Vector3<R>, 3> p{
      {{R(0), R(0.2), R(0)}, {R(1), R(-1), R(0)}, {R(2), R(3), R(1)}}};
  const std::array<Vector3<R>, 3> v{{{R(1), R(0), R(0)}, {R(0), R(-2), R(1)}, {R(0), R(0), R(0)}}};
  const std::array<R, 3> masses{R(2), R(0.5), R(3)};
  const forces::Drag<R> drag(R(0.4), R(0.1));
  const forces::Buoyancy<R> buoyancy(R(0.5), R(0.001), R(0));
  const forces::Gravity<R> gravity({R(0), R(-9.807), R(0)});
  const R dt = R(1) / R(60);

  System direct;
  System wrapped;
  std::array<Body, 3> bodies;
  for (std::size_t i = 0; i < 3; ++i) {
    direct.spawn(p[i], v[i]);
    wrapped.spawn(p[i], v[i]);
    direct.set_mass(i, masses[i]);
    wrapped.set_mass(i, masses[i]);
    bodies[i].set_position(p[i]);
    bodies[i].set_velocity(v[i]);
    bodies[i].set_mass(masses[i]);
  }
  for (int step = 0; step < 10; ++step) {
    forces::apply(drag, direct, dt);
    forces::apply(buoyancy, direct, dt);
    forces::apply(gravity, direct, dt);
    // The adapter over wrapped's columns, made afresh for each use.
    const auto adapter = [&] {
      return forces::SoaBodies<R>{wrapped.template column<pointmass::Column::position_x>(),
                                  wrapped.template column<pointmass::Column::position_y>(),
                                  wrapped.template column<pointmass::Column::position_z>(),
                                  wrapped.template column<pointmass::Column::velocity_x>(),
                                  wrapped.template column<pointmass::Column::velocity_y>(),
                                  wrapped.template column<pointmass::Column::velocity_z>(),
                                  wrapped.template column<pointmass::Column::inverse_mass>(),
                                  wrapped.template column<pointmass::Column::force_x>(),
                                  wrapped.template column<pointmass::Column::force_y>(),
                                  wrapped.template column<pointmass::Column::force_z>()};
    };
    forces::SoaBodies<R> soa = adapter();
    forces::apply(drag, soa, dt);
    forces::apply(buoyancy, soa, dt);
    // A temporary adapter: its forces land in the arrays it refers to.
    forces::apply(gravity, adapter(), dt);
    for (Body& body : bodies) {
      forces::update_force(drag, body, dt);
      forces::update_force(buoyancy, body, dt);
      forces::update_force(gravity, body, dt);
    }
    for (std::size_t i = 0; i < 3; ++i) {
      CHECK(direct.force_accumulator(i) == bodies[i].force_accumulator());
      CHECK(wrapped.force_accumulator(i) == bodies[i].force_accumulator());
    }
    direct.step(dt);
    wrapped.step(dt);
    for (Body& body : bodies) body.integrate(dt);
  }
  for (std::size_t i = 0; i < 3; ++i) {
    CHECK(direct.position(i) == bodies[i].position());
    CHECK(wrapped.velocity(i) == bodies[i].velocity());
  }
}
