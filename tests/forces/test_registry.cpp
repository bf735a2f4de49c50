// SPDX-License-Identifier: BSL-1.0
// The registry: add, remove and clear work (Cyclone declares remove and clear
// but never defines them), and compile-time known and type-erased generators give the same
// forces.
#include <doctest/doctest.h>

#include <algorithm>
#include <limits>
#include <vector>

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

namespace {
// A contract handler that, reporting particle 2's force, changes what the pass has not
// reached yet in the same block of registrations: particle 5's velocity, and particle 6's
// drag registration (removed).
struct Meddling {
  void* registry;
  void* particles;
  const void* drag;
  int reports;
};
Meddling meddling{};
template <class Registry, class R>
void meddle(const pointmass::ContractViolation&) {
  ++meddling.reports;
  auto& particles = *static_cast<std::vector<Particle<R>>*>(meddling.particles);
  particles[5].set_velocity({R(3), R(0), R(0)});
  static_cast<Registry*>(meddling.registry)
      ->remove(particles[6], *static_cast<const forces::Drag<R>*>(meddling.drag));
}
}  // namespace

TEST_CASE_TEMPLATE("registry: known field generators add update_force's bits, in turn", R, float,
                   double) {
  using Registry = forces::ForceRegistry<Particle<R>, forces::Drag<R>, forces::AnchoredSpring<R>>;
  forces::Drag<R> drag(R(0.1), R(0.01));  // non-const: the known types' own vectors
  forces::AnchoredSpring<R> spring({R(0), R(0), R(0)}, R(4), R(2));
  std::vector<Particle<R>> particles(21), direct(21);  // two blocks and a part
  for (std::size_t k = 0; k < particles.size(); ++k) {
    const R f = static_cast<R>(k) / R(7);
    particles[k].set_position({R(3) * f - R(1.5), R(2) - f, f});
    particles[k].set_velocity({R(1) - f, R(2) * f, f - R(0.5)});
    particles[k].set_mass(R(1) + f);
  }
  direct = particles;
  Registry registry;
  for (auto& p : particles) registry.add(p, drag);
  for (auto& p : particles) registry.add(p, spring);
  registry.update_forces(R(0.01));
  for (auto& p : direct) forces::update_force(drag, p, R(0.01));
  for (auto& p : direct) forces::update_force(spring, p, R(0.01));
  for (std::size_t k = 0; k < particles.size(); ++k) {
    CHECK(particles[k].force_accumulator() == direct[k].force_accumulator());
  }

  // Particle 2's drag is beyond the range: reported, and the handler changes particle 5 and
  // removes particle 6's drag; the pass sees both, as one registration after another would.
  for (auto& p : particles) p.clear_accumulator();
  const R huge = std::numeric_limits<R>::max() / R(2);
  particles[2].set_velocity({huge, huge, R(0)});
  meddling = {&registry, &particles, &drag, 0};
  const auto previous = pointmass::set_contract_handler(&meddle<Registry, R>);
  registry.update_forces(R(0.01));
  pointmass::set_contract_handler(previous);
  CHECK(meddling.reports == 1);
  CHECK(registry.size() == 41);
  Particle<R> fifth = particles[5];
  fifth.clear_accumulator();
  forces::update_force(drag, fifth, R(0.01));
  forces::update_force(spring, fifth, R(0.01));
  CHECK(particles[5].force_accumulator() == fifth.force_accumulator());
  Particle<R> sixth = particles[6];
  sixth.clear_accumulator();
  forces::update_force(spring, sixth, R(0.01));  // its drag was removed before its turn
  CHECK(particles[6].force_accumulator() == sixth.force_accumulator());
}

namespace {
// A known generator type with its own update_force, walked before the drags: it removes
// particle 3's drag registration before the drags' turn.
template <class R>
struct DragRemover {
  void (*remove)(void*);  // the registry's type names this one: reached through a callback
  void* context;
  void update_force(Particle<R>&, R) { remove(context); }
};
}  // namespace

TEST_CASE_TEMPLATE("registry: a known registration removed before its turn adds nothing", R, float,
                   double) {
  using Registry = forces::ForceRegistry<Particle<R>, DragRemover<R>, forces::Drag<R>>;
  struct Context {
    Registry registry;
    forces::Drag<R> drag{R(0.1), R(0.01)};
    std::vector<Particle<R>> particles = std::vector<Particle<R>>(11);
  } c;
  auto& [registry, drag, particles] = c;
  for (auto& p : particles) p.set_velocity({R(1), R(2), R(0)});
  DragRemover<R> remover{[](void* context) {
                           auto& x = *static_cast<Context*>(context);
                           x.registry.remove(x.particles[3], x.drag);
                         },
                         &c};
  registry.add(particles[0], remover);
  for (auto& p : particles) registry.add(p, drag);
  registry.update_forces(R(0.01));
  CHECK(particles[3].force_accumulator() == Vector3<R>{});
  CHECK(particles[4].force_accumulator() == particles[2].force_accumulator());
  CHECK(registry.size() == 11);
}

namespace {
// A known field generator that logs its calls: a constant push, and its id in `log`.
template <class R, int Type>
struct Logged {
  Vector3<R> push;
  int id;
  std::vector<int>* log;
  [[nodiscard]] Vector3<R> force(const Vector3<R>&, const Vector3<R>&, R, R) const {
    log->push_back(id);
    return push;
  }
};
}  // namespace

TEST_CASE_TEMPLATE("registry: field generator types in lockstep only while aligned", R, float,
                   double) {
  using A = Logged<R, 0>;
  using B = Logged<R, 1>;
  using Registry = forces::ForceRegistry<Particle<R>, A, B>;
  std::vector<int> log;
  std::vector<Particle<R>> particles(20);
  std::vector<A> as;
  std::vector<B> bs;
  for (int k = 0; k < 20; ++k) {
    as.push_back({{R(1), R(0), R(0)}, k, &log});
    bs.push_back({{R(0), R(1), R(0)}, 100 + k, &log});
  }
  std::vector<int> lockstep;  // eight of A, eight of B, in turn
  for (int first = 0; first < 20; first += 8) {
    for (int k = first; k < std::min(first + 8, 20); ++k) lockstep.push_back(k);
    for (int k = first; k < std::min(first + 8, 20); ++k) lockstep.push_back(100 + k);
  }

  SUBCASE("the same particles in the same order: walked together, eight at a time") {
    Registry registry;
    for (std::size_t k = 0; k < 20; ++k) {
      registry.add(particles[k], as[k]);
      registry.add(particles[k], bs[k]);
    }
    registry.update_forces(R(0.01));
    CHECK(log == lockstep);
    CHECK(particles[7].force_accumulator() == Vector3<R>{R(1), R(1), R(0)});

    // Each type loses one registration (particle 0's A, particle 19's B): the sizes are equal
    // again, the particles not the same: type by type.
    registry.remove(particles[0], as[0]);
    registry.remove(particles[19], bs[19]);
    log.clear();
    registry.update_forces(R(0.01));
    std::vector<int> by_type;
    for (int k = 1; k < 20; ++k) by_type.push_back(k);
    for (int k = 0; k < 19; ++k) by_type.push_back(100 + k);
    CHECK(log == by_type);
  }
  SUBCASE("the second type in the reverse order: type by type") {
    Registry registry;
    for (std::size_t k = 0; k < 20; ++k) registry.add(particles[k], as[k]);
    for (std::size_t k = 20; k-- > 0;) registry.add(particles[k], bs[k]);
    registry.update_forces(R(0.01));
    std::vector<int> by_type;
    for (int k = 0; k < 20; ++k) by_type.push_back(k);
    for (int k = 19; k >= 0; --k) by_type.push_back(100 + k);
    CHECK(log == by_type);
  }
  SUBCASE("a particle twice in each type, a block apart: type by type, its sums in that order") {
    // Particle 0 gets A 1, then A -1, then B d, then B d: 0 + d + d = 2d. In lockstep it would
    // get 1, d, -1, d: (1 + d) rounds to 1, so d.
    const R d = std::numeric_limits<R>::epsilon() / R(4);
    Registry registry;
    std::vector<A> a2;
    std::vector<B> b2;
    for (int k = 0; k < 9; ++k) {
      a2.push_back({{k == 8 ? R(-1) : R(1), R(0), R(0)}, k, &log});
      b2.push_back({{d, R(0), R(0)}, 100 + k, &log});
    }
    for (std::size_t k = 0; k < 9; ++k) registry.add(particles[k % 8], a2[k]);
    for (std::size_t k = 0; k < 9; ++k) registry.add(particles[k % 8], b2[k]);
    registry.update_forces(R(0.01));
    REQUIRE(((R(1) + d) + R(-1)) + d != ((R(1) + R(-1)) + d) + d);  // the orders differ
    CHECK(particles[0].force_accumulator().x == ((R(1) + R(-1)) + d) + d);
  }
}
