// SPDX-License-Identifier: BSL-1.0
// Force generators on particles and systems whose positions are stored wider than their float
// arithmetic (Precision<float, double>, Precision<float, Compensated<float>>), through
// forces::relative_to(body, origin): the positions a generator sees are exact where the offset
// is a float; a spring 1e6 m out moves as the same spring near the origin, where all-float
// misses by centimetres; drag (velocity only) gives all-float's velocities bit for bit; a
// Particle and a ParticleSystem get the same bits.
#include <doctest/doctest.h>

#include <cmath>
#include <cstddef>
#include <random>
#include <span>
#include <vector>

#include <pointmass/forces.hpp>
#include <pointmass/particle.hpp>
#include <pointmass/particle_system.hpp>

#include "ulp.hpp"

namespace {

namespace pm = pointmass;
namespace forces = pointmass::forces;
using pm::Vector3;

using DoublePositions = pm::Precision<float, double>;
using CompensatedPositions = pm::Precision<float, pm::Compensated<float>>;

template <class S>
using System = pm::ParticleSystem<S, pm::damping::PerSecond, pm::position::Euler,
                                  pm::features::ForceAccumulator>;

static_assert(forces::WideBodies<System<DoublePositions>> &&
              forces::WideBodies<System<CompensatedPositions>>);
static_assert(!forces::Bodies<System<DoublePositions>>, "a wide system is not Bodies itself");
static_assert(forces::Bodies<forces::RelativeBodies<System<CompensatedPositions>>>);
static_assert(!forces::WideBodies<System<float>> && forces::Bodies<System<float>>);
static_assert(forces::WideBody<pm::Particle<DoublePositions>> &&
              !forces::PlainBody<pm::Particle<DoublePositions>, float>);
static_assert(forces::PlainBody<forces::RelativeBody<pm::Particle<CompensatedPositions>>, float>);
static_assert(!forces::WideBody<pm::Particle<float>>);

using pointmass::test::same_bits;
float largest_difference(const Vector3<float>& a, const Vector3<float>& b) {
  return std::fmax(std::fabs(a.x - b.x), std::fmax(std::fabs(a.y - b.y), std::fabs(a.z - b.z)));
}

/// The largest magnitude among a vector's components.
float largest_component(const Vector3<float>& v) {
  return std::fmax(std::fabs(v.x), std::fmax(std::fabs(v.y), std::fabs(v.z)));
}
/// What the near bodies' own position roundings can add up to over `steps` steps: half the
/// spacing of floats at the largest coordinate they reached, a step.
float rounding_budget(float largest, int steps) {
  return float(steps) * (std::nextafter(largest, 2 * largest + 1) - largest) / 2;
}

// The anchor, 1e6 m out: a float exactly, so that all-float starts from the same state.
constexpr Vector3<double> anchor{1e6, -2.5e5, 5e5};
constexpr float dt = 1.0f / 60;
constexpr int steps = 600;
constexpr std::size_t count = 17;  // the vectorised loop and its remainder both run

Vector3<double> far_from(const Vector3<float>& offset) {  // exact: the sum fits a double
  return {anchor.x + double(offset.x), anchor.y + double(offset.y), anchor.z + double(offset.z)};
}

/// Offsets within 5 m of the anchor and velocities within 2 m/s, the same for every system.
std::vector<std::pair<Vector3<float>, Vector3<float>>> starts() {
  std::mt19937 random(20);
  std::uniform_real_distribution<float> offset(-5.0f, 5.0f);
  std::uniform_real_distribution<float> speed(-2.0f, 2.0f);
  std::vector<std::pair<Vector3<float>, Vector3<float>>> result(count);
  for (auto& [p, v] : result) {
    p = {offset(random), offset(random), offset(random)};
    v = {speed(random), speed(random), speed(random)};
  }
  return result;
}

template <class S, class Position>
System<S> system_at(Position position) {
  System<S> system(count);
  system.set_damping(0.8f);
  for (const auto& [p, v] : starts()) system.spawn(position(p), v);
  return system;
}

}  // namespace

TEST_CASE_TEMPLATE(
    "relative_to: the positions generators see are exact where the offset is a float", S,
    DoublePositions, CompensatedPositions) {
  // 2^-20 m beyond 1e6 m: a double, and for the pair hi = 1e6, lo = 2^-20; a float at 1e6 m
  // rounds it away.
  const double tiny = std::ldexp(1.0, -20);
  const Vector3<double> p{anchor.x + tiny, anchor.y - 3 * tiny, anchor.z + 0.375};
  System<S> system(1);
  system.spawn(p, {});
  auto local = forces::relative_to(system, anchor);
  const Vector3<float> expected{float(tiny), float(-3 * tiny), 0.375f};
  CHECK(same_bits(local.position(0), expected));
  pm::Particle<S> particle;
  particle.set_position(p);
  particle.set_velocity({1.5f, -2.0f, 0.25f});
  particle.set_mass(4.0f);
  const auto body = forces::relative_to(particle, anchor);
  CHECK(same_bits(body.position(), expected));
  // The rest is the particle's own.
  CHECK(same_bits(body.velocity(), Vector3<float>{1.5f, -2.0f, 0.25f}));
  CHECK(body.inverse_mass() == 0.25f);
}

TEST_CASE_TEMPLATE("relative_to: a spring 1e6 m out moves as the same spring near the origin", S,
                   DoublePositions, CompensatedPositions) {
  // The anchor is the local origin, so the spring's anchor is {0, 0, 0} in its frame.
  const forces::AnchoredSpring<float> spring({0, 0, 0}, 20.0f, 1.0f);
  System<S> far = system_at<S>(far_from);
  System<float> near = system_at<float>([](const Vector3<float>& p) { return p; });
  System<float> far_float = system_at<float>([](const Vector3<float>& p) {
    const Vector3<double> q = far_from(p);
    return Vector3<float>{float(q.x), float(q.y), float(q.z)};
  });
  auto local = forces::relative_to(far, anchor);
  float from_near = 0;
  float float_from_near = 0;
  float largest = 0;
  for (int n = 0; n < steps; ++n) {
    forces::apply(spring, local, dt);
    forces::apply(spring, near, dt);
    // All-float 1e6 m out, with the anchor as a float there: what the wide storage saves.
    forces::apply(forces::AnchoredSpring<float>({float(anchor.x), float(anchor.y), float(anchor.z)},
                                                20.0f, 1.0f),
                  far_float, dt);
    far.step(dt);
    near.step(dt);
    far_float.step(dt);
    for (std::size_t i = 0; i < count; ++i) {
      from_near = std::fmax(from_near, largest_difference(local.position(i), near.position(i)));
      largest = std::fmax(largest, largest_component(near.position(i)));
      const Vector3<float> q = far_float.position(i);
      const Vector3<float> float_offset{float(double(q.x) - anchor.x),
                                        float(double(q.y) - anchor.y),
                                        float(double(q.z) - anchor.z)};
      float_from_near =
          std::fmax(float_from_near, largest_difference(float_offset, near.position(i)));
    }
  }
  // The near system rounds its positions by at most half an ulp of its largest coordinate a
  // step; the wide one far less (1e-10 m at 1e6 m in double). So the two differ by no more
  // than the near system's rounding budget; rounding each position to float at 1e6 m (1/16 m
  // apart) would be far beyond it.
  const float budget = rounding_budget(largest, steps);
  INFO("largest difference from the near system: "
       << from_near << " m; all-float's: " << float_from_near << " m; budget " << budget
       << " m (largest coordinate " << largest << " m)");
  CHECK(from_near <= budget);
  CHECK(float_from_near > 100 * budget);
}

TEST_CASE_TEMPLATE(
    "relative_to: drag gives all-float's velocities bit for bit, the particle the system's bits", S,
    DoublePositions, CompensatedPositions) {
  const forces::Drag<float> drag(0.3f, 0.05f);
  const forces::AnchoredSpring<float> spring({1, 0, 0}, 12.0f, 0.5f);
  System<S> wide = system_at<S>(far_from);
  System<float> plain = system_at<float>([](const Vector3<float>& p) { return p; });
  auto local = forces::relative_to(wide, anchor);
  // Particle 0 of the wide system as a Particle, with the spring too (update_force).
  pm::Particle<S> particle;
  particle.set_position(far_from(starts()[0].first));
  particle.set_velocity(starts()[0].second);
  particle.set_damping(0.8f);
  System<S> with_spring = system_at<S>(far_from);
  auto spring_local = forces::relative_to(with_spring, anchor);
  bool velocities_as_float = true;
  bool particle_as_system = true;
  for (int n = 0; n < steps; ++n) {
    forces::apply(drag, local, dt);
    forces::apply(drag, plain, dt);
    wide.step(dt);
    plain.step(dt);
    for (std::size_t i = 0; i < count; ++i) {
      velocities_as_float = velocities_as_float && same_bits(wide.velocity(i), plain.velocity(i));
    }
    auto body = forces::relative_to(particle, anchor);
    forces::update_force(drag, body, dt);
    forces::update_force(spring, body, dt);
    forces::apply(drag, spring_local, dt);
    forces::apply(spring, spring_local, dt);
    particle.integrate(dt);
    with_spring.step(dt);
    particle_as_system = particle_as_system &&
                         same_bits(particle.velocity(), with_spring.velocity(0)) &&
                         particle.position() == with_spring.position(0);
  }
  CHECK(velocities_as_float);
  CHECK(particle_as_system);
}

TEST_CASE_TEMPLATE(
    "relative_to: springs between bodies 1e6 m out move as the same springs near the origin", S,
    DoublePositions, CompensatedPositions) {
  // A chain of links in a system (apply_links), and a Spring each way between two particles.
  const auto s = starts();
  std::vector<forces::Link> links;
  for (std::size_t i = 0; i + 1 < count; ++i) links.push_back({i, i + 1});
  const forces::LinkSprings<float> chain(15.0f, 1.5f);
  System<S> far = system_at<S>(far_from);
  System<float> near = system_at<float>([](const Vector3<float>& p) { return p; });
  auto local = forces::relative_to(far, anchor);

  pm::Particle<S> a, b;
  pm::Particle<float> near_a, near_b;
  a.set_position(far_from(s[0].first));
  b.set_position(far_from(s[1].first));
  near_a.set_position(s[0].first);
  near_b.set_position(s[1].first);
  auto view_a = forces::relative_to(a, anchor);
  auto view_b = forces::relative_to(b, anchor);
  const forces::Spring<forces::RelativeBody<pm::Particle<S>>> a_to_b(view_b, 25.0f, 2.0f);
  const forces::Spring<forces::RelativeBody<pm::Particle<S>>> b_to_a(view_a, 25.0f, 2.0f);
  const forces::Spring<pm::Particle<float>> near_a_to_b(near_b, 25.0f, 2.0f);
  const forces::Spring<pm::Particle<float>> near_b_to_a(near_a, 25.0f, 2.0f);

  float from_near = 0;
  float largest = 0;
  for (int n = 0; n < steps; ++n) {
    forces::apply_links(chain, std::span<const forces::Link>(links), local);
    forces::apply_links(chain, std::span<const forces::Link>(links), near);
    far.step(dt);
    near.step(dt);
    forces::update_force(a_to_b, view_a, dt);
    forces::update_force(b_to_a, view_b, dt);
    forces::update_force(near_a_to_b, near_a, dt);
    forces::update_force(near_b_to_a, near_b, dt);
    for (auto* p : {&a, &b}) p->integrate(dt);
    for (auto* p : {&near_a, &near_b}) p->integrate(dt);
    for (std::size_t i = 0; i < count; ++i) {
      from_near = std::fmax(from_near, largest_difference(local.position(i), near.position(i)));
      largest = std::fmax(largest, largest_component(near.position(i)));
    }
    from_near = std::fmax(from_near, largest_difference(view_a.position(), near_a.position()));
    from_near = std::fmax(from_near, largest_difference(view_b.position(), near_b.position()));
    largest = std::fmax(largest, std::fmax(largest_component(near_a.position()),
                                           largest_component(near_b.position())));
  }
  // As for the anchored spring: within the near bodies' own rounding budget.
  const float budget = rounding_budget(largest, steps);
  INFO("largest difference from the near bodies: "
       << from_near << " m; budget " << budget << " m (largest coordinate " << largest << " m)");
  CHECK(from_near <= budget);
}

TEST_CASE_TEMPLATE("relative_to: a view passed as a temporary adds what a named view adds", S,
                   DoublePositions, CompensatedPositions) {
  // `apply(drag, forces::relative_to(debris, camera), t)` in one line: the temporary view's
  // forces land in the system (and the particle) it refers to, as through a named view.
  const forces::AnchoredSpring<float> spring({1.0f, 2.0f, -0.5f}, 30.0f, 0.5f);
  const forces::Drag<float> drag(0.4f, 0.1f);
  auto named = system_at<S>(far_from);
  auto temporary = system_at<S>(far_from);
  auto local = forces::relative_to(named, anchor);
  forces::apply(spring, local, dt);
  forces::apply(drag, local, dt);
  forces::apply(spring, forces::relative_to(temporary, anchor), dt);
  forces::apply(drag, forces::relative_to(temporary, anchor), dt);
  const forces::LinkSprings<float> links_spring(12.0f, 1.5f);
  std::vector<forces::Link> links;
  for (std::size_t i = 0; i + 1 < count; ++i) links.push_back({i, i + 1});
  forces::apply_links(links_spring, links, local);
  forces::apply_links(links_spring, links, forces::relative_to(temporary, anchor));
  for (std::size_t i = 0; i < count; ++i) {
    REQUIRE(largest_component(named.force_accumulator(i)) > 0.0f);
    CHECK(same_bits(temporary.force_accumulator(i), named.force_accumulator(i)));
  }

  pm::Particle<S> a;
  pm::Particle<S> b;
  for (auto* particle : {&a, &b}) {
    particle->set_position(far_from({3.0f, -1.0f, 2.0f}));
    particle->set_velocity({1.5f, -2.0f, 0.25f});
  }
  forces::AnchoredSpring<float> particle_spring = spring;
  auto body = forces::relative_to(a, anchor);
  forces::update_force(particle_spring, body, dt);
  forces::update_force(particle_spring, forces::relative_to(b, anchor), dt);
  REQUIRE(largest_component(a.force_accumulator()) > 0.0f);
  CHECK(same_bits(b.force_accumulator(), a.force_accumulator()));
}

namespace {

/// A user's generator with its own update_force member for a wide particle: it handles the
/// wide position itself (this one needs none: a thrust in the particle's frame).
template <class S>
struct Thruster {
  Vector3<float> thrust{1.0f, 2.0f, -0.5f};
  void update_force(pm::Particle<S>& particle, float) const { particle.add_force(thrust); }
};

}  // namespace

TEST_CASE_TEMPLATE("a generator with its own update_force member is called on a wide particle", S,
                   DoublePositions, CompensatedPositions) {
  // A field generator needs relative_to (compile-fail forces_on_wide_particle*); a generator
  // with its own member is called, through update_force and through a registry.
  pm::Particle<S> ship;
  ship.set_position(far_from({3.0f, -1.0f, 2.0f}));
  const Thruster<S> thruster;
  forces::update_force(thruster, ship, dt);
  CHECK(ship.force_accumulator() == thruster.thrust);
  ship.clear_accumulator();

  forces::ForceRegistry<pm::Particle<S>, Thruster<S>> known;
  forces::ForceRegistry<pm::Particle<S>> erased;
  known.template emplace<Thruster<S>>(ship);
  erased.add_owned(ship, thruster);
  erased.add(ship, thruster);  // a const generator, type-erased
  known.update_forces(dt);
  erased.update_forces(dt);
  CHECK(ship.force_accumulator() == thruster.thrust * 3.0f);
}
