// SPDX-License-Identifier: BSL-1.0
// The registry: add, remove and clear work (Cyclone declares remove and clear
// but never defines them), and compile-time known and type-erased generators give the same
// forces.
#include <doctest/doctest.h>

#include <pointmass/forces.hpp>
#include <pointmass/particle.hpp>

#include "tolerance.hpp"

namespace {

using pointmass::Particle;
using pointmass::Vector3;
namespace forces = pointmass::forces;

/// A user's own generator, unknown to the registry's type list: a constant push.
template <class R>
struct Push {
  Vector3<R> force;
  int calls = 0;
  void update_force(Particle<R>& particle, R) {
    ++calls;
    particle.add_force(force);
  }
};

template <class R>
Particle<R> at(Vector3<R> p) {
  Particle<R> particle;
  particle.set_position(p);
  return particle;
}

}  // namespace

TEST_CASE_TEMPLATE("registry: add, update, remove, clear", R, float, double) {
  using Registry =
      forces::ForceRegistry<Particle<R>, forces::Gravity<R>, forces::AnchoredSpring<R>>;
  Registry registry;
  Particle<R> a = at<R>({R(2), R(0), R(0)});
  Particle<R> b = at<R>({R(0), R(0), R(0)});
  forces::Gravity<R> gravity({R(0), R(-10), R(0)});
  forces::AnchoredSpring<R> spring({}, R(3), R(1));
  Push<R> push{{R(0), R(0), R(1)}};

  registry.add(a, gravity);
  registry.add(a, spring);
  registry.add(b, gravity);
  registry.add(a, push);  // type-erased
  CHECK(registry.size() == 4);

  registry.update_forces(R(0.1));
  CHECK(a.force_accumulator() == Vector3<R>{R(-3), R(-10), R(1)});
  CHECK(b.force_accumulator() == Vector3<R>{R(0), R(-10), R(0)});
  CHECK(push.calls == 1);
  a.clear_accumulator();
  b.clear_accumulator();

  // Removing a pair that is not registered changes nothing.
  CHECK_FALSE(registry.remove(b, spring));
  CHECK_FALSE(registry.remove(b, push));
  CHECK(registry.size() == 4);

  // Remove one known and the erased one: they no longer act; the rest still do.
  CHECK(registry.remove(a, gravity));
  CHECK(registry.remove(a, push));
  CHECK_FALSE(registry.remove(a, push));
  CHECK(registry.size() == 2);
  registry.update_forces(R(0.1));
  CHECK(a.force_accumulator() == Vector3<R>{R(-3), R(0), R(0)});
  CHECK(b.force_accumulator() == Vector3<R>{R(0), R(-10), R(0)});
  CHECK(push.calls == 1);
  a.clear_accumulator();
  b.clear_accumulator();

  registry.clear();
  CHECK(registry.empty());
  registry.update_forces(R(0.1));
  CHECK(a.force_accumulator() == Vector3<R>{});
  CHECK(b.force_accumulator() == Vector3<R>{});
}

TEST_CASE_TEMPLATE("known and type-erased registrations give the same forces", R, float, double) {
  forces::ForceRegistry<Particle<R>, forces::Drag<R>, forces::Buoyancy<R>> known;
  forces::ForceRegistry<Particle<R>> erased;  // every generator type-erased
  forces::Drag<R> drag(R(0.3), R(0.02));
  forces::Buoyancy<R> buoyancy(R(0.5), R(0.002), R(0));
  Particle<R> p = at<R>({R(0), R(-0.1), R(0)});
  p.set_velocity({R(1), R(-2), R(0.5)});
  Particle<R> q = p;
  known.add(p, drag);
  known.add(p, buoyancy);
  erased.add(q, drag);
  erased.add(q, buoyancy);
  known.update_forces(R(0.01));
  erased.update_forces(R(0.01));
  CHECK(p.force_accumulator() == q.force_accumulator());
  CHECK(p.force_accumulator().y > R(0));  // buoyancy beats the downward speed's drag
  // The same generator may act on many particles, and one particle may have many generators.
  CHECK(erased.remove(q, drag));
  CHECK(erased.size() == 1);
}

TEST_CASE_TEMPLATE("registry over a whole simulation step: immovable particles stay put", R, float,
                   double) {
  forces::ForceRegistry<Particle<R>, forces::Gravity<R>, forces::PositionOnlyStiffSpring<R>>
      registry;
  forces::Gravity<R> gravity({R(0), R(-10), R(0)});
  forces::PositionOnlyStiffSpring<R> spring({}, R(100), R(1));
  Particle<R> wall = at<R>({R(0), R(1), R(0)});
  wall.set_inverse_mass(R(0));
  registry.add(wall, gravity);
  registry.add(wall, spring);
  for (int i = 0; i < 10; ++i) {
    registry.update_forces(R(0.1));
    CHECK(wall.force_accumulator() == Vector3<R>{});
    wall.integrate(R(0.1));
  }
  CHECK(wall.position() == Vector3<R>{R(0), R(1), R(0)});
}
