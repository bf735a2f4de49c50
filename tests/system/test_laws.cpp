// SPDX-License-Identifier: BSL-1.0
// Force laws fused into the step (forces/laws.hpp, system/laws_step.hpp): the bits of
// forces::apply then step for every library law and a user's, in a system and in a Particle;
// sub-steps in one pass against separate steps, with lifetimes and interpolation; the range
// check of apply kept.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include <pointmass/forces.hpp>
#include <pointmass/particle_system.hpp>

#include "system_support.hpp"

using namespace pointmass;
using pointmass::test::same_bits;

namespace {

// A user's law: lift that grows with height, written as plain arithmetic.
template <class R>
struct Lift {
  R per_metre = R(0.25);
  [[nodiscard]] constexpr Vector3<R> force(const Vector3<R>& p, const Vector3<R>& v, R,
                                           R) const noexcept {
    return {R(0), p.y * per_metre - v.y * R(0.125), R(0)};
  }
};

template <class R>
auto user_lambda() {
  return forces::law([](const Vector3<R>& p, const Vector3<R>& v, R inverse_mass, R t) {
    return Vector3<R>{-p.x * inverse_mass, v.z * t, p.z - v.x};
  });
}

// Particles of varied state, some heavy, two immovable, each with an accumulated force (the
// laws' are added after it).
template <class System>
System scene(std::size_t count, unsigned seed) {
  using R = typename System::real;
  std::mt19937 engine(seed);
  System system;
  std::uniform_real_distribution<R> mass(R(0.5), R(4));
  for (std::size_t i = 0; i < count; ++i) {
    const std::size_t k =
        system.spawn(test::random_vector(engine, R(8)), test::random_vector(engine, R(5)));
    if (i % 97 == 3) {
      system.set_inverse_mass(k, R(0));
    } else {
      system.set_mass(k, mass(engine));
    }
    system.add_force(k, test::random_vector(engine, R(2)));
  }
  return system;
}

template <class System>
bool same_state(const System& a, const System& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (!same_bits(a.position(i), b.position(i)) || !same_bits(a.velocity(i), b.velocity(i)) ||
        !same_bits(a.force_accumulator(i), b.force_accumulator(i))) {
      return false;
    }
  }
  return true;
}

template <class R>
struct Generators {
  forces::Gravity<R> gravity{Vector3<R>{R(0), R(-9.807), R(0)}};
  forces::Drag<R> drag{R(0.1), R(0.02)};
  forces::AnchoredSpring<R> spring{Vector3<R>{R(0), R(5), R(0)}, R(3), R(1)};
  forces::AnchoredBungee<R> bungee{Vector3<R>{R(1), R(2), R(-1)}, R(4), R(6)};
  forces::Buoyancy<R> buoyancy{R(0.5), R(0.001), R(1)};
  Lift<R> lift{};
};

// `steps` steps of apply(law, a) for each law then a.step(t), against b.step(t, laws).
template <class System, class... G>
void check_fused(unsigned seed, const G&... laws) {
  using R = typename System::real;
  const R t = R(1) / R(60);
  System unfused = scene<System>(203, seed);
  System fused = unfused;
  for (int s = 0; s < 30; ++s) {
    (forces::apply(laws, unfused, t), ...);
    unfused.step(t);
    fused.step(t, forces::laws(laws...));
    if (s == 10) {  // a force added between steps is composed with the laws' in the next
      unfused.add_force(5, Vector3<R>{R(1), R(2), R(3)});
      fused.add_force(5, Vector3<R>{R(1), R(2), R(3)});
    }
  }
  CHECK(same_state(unfused, fused));
}

template <class R, class D, class P, class... F>
using WithForces = ParticleSystem<R, D, P, features::ForceAccumulator, F...>;

}  // namespace

TEST_CASE_TEMPLATE(
    "laws: each library law and a user's fused into the step, bits of apply then step", R, float,
    double) {
  using Sparks = WithForces<R, damping::PerSecond, position::Euler>;
  const Generators<R> g;
  check_fused<Sparks>(1, g.gravity);
  check_fused<Sparks>(2, g.drag);
  check_fused<Sparks>(3, g.spring);
  check_fused<Sparks>(4, g.bungee);
  check_fused<Sparks>(5, g.buoyancy);
  check_fused<Sparks>(6, g.lift);
  check_fused<Sparks>(7, user_lambda<R>());
  check_fused<Sparks>(8, g.gravity, g.drag, g.spring, g.bungee, g.buoyancy, g.lift);
}

TEST_CASE_TEMPLATE("laws: fused in every position policy, interpolation and the second order", R,
                   float, double) {
  const Generators<R> g;
  check_fused<
      WithForces<R, damping::PerFrame, position::ConstantAcceleration, features::Interpolation>>(
      11, g.drag, g.spring);
  check_fused<WithForces<R, damping::PerSecond, position::SemiImplicit>>(12, g.drag, g.spring);
  check_fused<WithForces<R, damping::PerSecond, position::VelocityVerlet, features::Lifetime>>(
      13, g.drag, g.spring, g.bungee);
  check_fused<WithForces<R, damping::Exact, position::Exact, features::PerParticleDamping>>(
      14, g.drag, g.spring);
}

TEST_CASE_TEMPLATE(
    "laws: a Particle stepped with forces::integrate, bits of update_force then integrate", R,
    float, double) {
  const Generators<R> g;
  const R t = R(1) / R(60);
  Particle<R> unfused;
  unfused.set_mass(R(2));
  unfused.set_position({R(1), R(3), R(-2)});
  unfused.set_velocity({R(4), R(-1), R(0.5)});
  unfused.add_force({R(0.5), R(0), R(0)});
  Particle<R> fused = unfused;
  const auto user = user_lambda<R>();
  const auto laws = forces::laws(g.drag, g.spring, g.lift, user);
  for (int s = 0; s < 50; ++s) {
    forces::update_force(g.drag, unfused, t);
    forces::update_force(g.spring, unfused, t);
    forces::update_force(g.lift, unfused, t);
    forces::update_force(user, unfused, t);
    unfused.integrate(t);
    forces::integrate(fused, t, laws);
  }
  CHECK(same_bits(unfused.position(), fused.position()));
  CHECK(same_bits(unfused.velocity(), fused.velocity()));
  // And the system agrees with the particle, law for law.
  WithForces<R, damping::PerSecond, position::Euler> system;
  Particle<R> single;
  single.set_mass(R(2));
  single.set_position({R(1), R(3), R(-2)});
  single.set_velocity({R(4), R(-1), R(0.5)});
  system.spawn(single);
  for (int s = 0; s < 50; ++s) {
    forces::integrate(single, t, laws);
    system.step(t, laws);
  }
  CHECK(same_bits(system.position(0), single.position()));
  CHECK(same_bits(system.velocity(0), single.velocity()));
}

TEST_CASE_TEMPLATE("laws: inputs beyond the plain formulas' range take force()'s bits", R, float,
                   double) {
  // At rest, at the spring's anchor, a speed whose square overflows, one whose square
  // underflows, a length whose square underflows: the fused forms are unsure there, and the
  // law pass adds force() (a scalar loop), as apply does; particles around them are sure.
  using Sparks = WithForces<R, damping::PerSecond, position::Euler>;
  const Generators<R> g;
  const R t = R(1) / R(60);
  const R huge = std::numeric_limits<R>::max() / R(2);  // its square overflows
  const R big = R(2) * std::sqrt(huge);                 // |v|^2 = 4 huge: overflows
  Sparks unfused;
  for (int copy = 0; copy < 40; ++copy) {  // 200 particles: whole vectors and a remainder
    unfused.spawn({R(1), R(2), R(3)}, {R(0), R(0), R(0)});
    unfused.spawn({R(0), R(5), R(0)}, {R(1), R(0), R(0)});  // the spring's anchor
    unfused.spawn({R(1), R(1), R(1)}, {big, R(0), R(0)});
    unfused.spawn({R(1), R(1), R(1)}, {std::numeric_limits<R>::min(), R(0), R(0)});
    unfused.spawn({std::numeric_limits<R>::min(), R(5), R(0)}, {R(0), R(1), R(0)});
  }
  for (std::size_t i = 0; i < unfused.size(); ++i) unfused.set_mass(i, R(2));
  Sparks fused = unfused;
  forces::apply(g.drag, unfused, t);
  forces::apply(g.spring, unfused, t);
  forces::apply(g.gravity, unfused, t);
  unfused.step(t);
  fused.step(t, forces::laws(g.drag, g.spring, g.gravity));
  CHECK(same_state(unfused, fused));
}

namespace {
// k separate steps of t / k against one pass of k sub-steps, particle by particle (the spawn
// number column follows each through the removals of expiry).
template <class System, class... G>
void check_substeps(std::size_t k, unsigned seed, const G&... laws) {
  using R = typename System::real;
  const R t = R(1) / R(30);
  System separate = scene<System>(1000, seed);
  for (std::size_t i = 0; i < separate.size(); ++i) {
    separate.template set_column<test::SpawnTag>(i, static_cast<std::uint32_t>(i));
    if constexpr (System::template has<features::Lifetime>) {
      separate.set_lifetime(i, R(0.05) + R(0.01) * static_cast<R>(i % 37));
    }
  }
  System pass = separate;
  const auto fused = forces::laws(laws...);
  std::vector<std::uint32_t> expired_separately;
  std::vector<std::uint32_t> expired_in_pass;
  for (int frame = 0; frame < 12; ++frame) {
    std::vector<Vector3<R>> before(1000);  // by spawn number: expiry reorders the particles
    for (std::size_t i = 0; i < pass.size(); ++i) {
      before[pass.template column<test::SpawnTag>()[i]] = pass.position(i);
    }
    for (std::size_t s = 0; s < k; ++s) {
      if constexpr (System::template has<features::Lifetime>) {
        separate.step(t / static_cast<R>(k), fused, [&](std::size_t i) {
          expired_separately.push_back(separate.template column<test::SpawnTag>()[i]);
        });
      } else {
        separate.step(t / static_cast<R>(k), fused);
      }
    }
    if constexpr (System::template has<features::Lifetime>) {
      std::vector<std::uint32_t> order;
      pass.step(t, fused, Substeps{k}, [&](std::size_t i) {
        const auto tag = pass.template column<test::SpawnTag>()[i];
        order.push_back(tag);
        expired_in_pass.push_back(tag);
        // The callback sees the state the separate steps leave at the particle's expiry: its
        // age reached its lifetime at the last sub-step it took.
        const R age = pass.age(i);
        CHECK(age >= pass.lifetime(i));
        CHECK(age < pass.lifetime(i) + t / static_cast<R>(k) * R(1.001));
      });
    } else {
      pass.step(t, fused, Substeps{k});
    }
    if constexpr (System::template has<features::Interpolation>) {
      bool kept = true;  // the previous position is the one before the pass
      for (std::size_t i = 0; i < pass.size(); ++i) {
        kept = kept && same_bits(pass.previous_position(i),
                                 before[pass.template column<test::SpawnTag>()[i]]);
      }
      CHECK(kept);
    }
  }
  REQUIRE(separate.size() == pass.size());
  // Particle by particle, found by its spawn number.
  std::vector<std::size_t> where(1000, 0);
  for (std::size_t i = 0; i < pass.size(); ++i)
    where[pass.template column<test::SpawnTag>()[i]] = i;
  bool same = true;
  for (std::size_t i = 0; i < separate.size(); ++i) {
    const std::size_t j = where[separate.template column<test::SpawnTag>()[i]];
    same = same && same_bits(separate.position(i), pass.position(j)) &&
           same_bits(separate.velocity(i), pass.velocity(j));
    if constexpr (System::template has<features::Lifetime>) {
      same = same && same_bits(separate.age(i), pass.age(j));
    }
  }
  CHECK(same);
  std::sort(expired_separately.begin(), expired_separately.end());
  std::sort(expired_in_pass.begin(), expired_in_pass.end());
  CHECK(expired_separately == expired_in_pass);
  if constexpr (System::template has<features::Lifetime>) CHECK(!expired_in_pass.empty());
}
}  // namespace

TEST_CASE_TEMPLATE("laws: k sub-steps in one pass, bits of k steps of t / k", R, float, double) {
  const Generators<R> g;
  using Column = features::Column<test::SpawnTag, std::uint32_t>;
  for (const std::size_t k : {std::size_t{1}, std::size_t{2}, std::size_t{8}}) {
    CAPTURE(k);
    check_substeps<WithForces<R, damping::PerSecond, position::Euler, Column>>(k, 21, g.drag,
                                                                               g.spring);
    check_substeps<WithForces<R, damping::PerSecond, position::VelocityVerlet, Column,
                              features::Interpolation>>(k, 22, g.drag, g.spring, g.lift);
    check_substeps<WithForces<R, damping::PerFrame, position::ConstantAcceleration, Column,
                              features::Lifetime, features::Interpolation>>(k, 23, g.drag,
                                                                            g.bungee);
    check_substeps<WithForces<R, damping::Exact, position::Exact, Column,
                              features::PerParticleDamping, features::Lifetime>>(k, 24, g.drag,
                                                                                 g.spring);
  }
}

namespace {
std::vector<std::string> reports;  // NOLINT: the handler below is a plain function
void record(const ContractViolation& violation) { reports.push_back(describe(violation)); }
struct RecordedContracts {
  ContractHandler previous = set_contract_handler(&record);
  RecordedContracts() { reports.clear(); }
  RecordedContracts(const RecordedContracts&) = delete;
  RecordedContracts& operator=(const RecordedContracts&) = delete;
  ~RecordedContracts() { set_contract_handler(previous); }
};

// A law whose force is infinite for the particles right of x = 0.
template <class R>
struct Blowup {
  [[nodiscard]] constexpr Vector3<R> force(const Vector3<R>& p, const Vector3<R>&, R,
                                           R) const noexcept {
    return {p.x > R(0) ? std::numeric_limits<R>::infinity() : R(1), R(0), R(0)};
  }
};
}  // namespace

TEST_CASE_TEMPLATE("laws: a force beyond range is reported once, naming the law, and not added", R,
                   float, double) {
  using Sparks = WithForces<R, damping::PerSecond, position::Euler>;
  const Generators<R> g;
  const R t = R(1) / R(60);
  Sparks system = scene<Sparks>(100, 31);
  Sparks expected = system;
  const RecordedContracts recorded;
  system.step(t, forces::laws(g.drag, Blowup<R>{}));
#if POINTMASS_CHECKS
  REQUIRE(reports.size() == 1);
  CHECK(reports[0].find("argument 'law'") != std::string::npos);
  CHECK(reports[0].find("= 1") != std::string::npos);  // the second law (index 1)
  // The law's force is added where it was finite (x <= 0), and only there.
  for (std::size_t i = 0; i < expected.size(); ++i) {
    const Vector3<R> p = expected.position(i);
    expected.add_force(i, g.drag.force(p, expected.velocity(i), expected.inverse_mass(i), t));
    if (!(p.x > R(0))) expected.add_force(i, Vector3<R>{R(1), R(0), R(0)});
  }
  expected.step(t);
  CHECK(same_state(system, expected));
#endif
  SUBCASE("no sub-steps is a contract violation that changes nothing") {
    const Sparks before = system;
    reports.clear();
    system.step(t, forces::laws(g.drag), Substeps{0});
    REQUIRE(reports.size() == 1);
    CHECK(reports[0].find("argument 'substeps'") != std::string::npos);
    CHECK(same_state(system, before));
  }
}
