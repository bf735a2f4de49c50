// SPDX-License-Identifier: BSL-1.0
// Finite input never gives NaN, and input beyond a generator's range is reported, not added:
// positions and velocities near the top of the range (1e20 in float, 1e155 in double, where
// x^2 overflows) and springs compressed below where x^2 underflows; huge masses, depths,
// damping, tiny steps and inverse masses. A rejected batch call changes nothing. The registry
// survives being changed during update_forces, accepts const generators, and owns generators
// on request (the idiom of registering the back of a growing vector passes AddressSanitizer).
#include <doctest/doctest.h>

#include <array>
#include <cmath>
#include <limits>
#include <memory>
#include <span>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <pointmass/forces.hpp>
#include <pointmass/particle.hpp>

#include "body.hpp"
#include "tolerance.hpp"

namespace {

using pointmass::Particle;
using pointmass::Vector3;
namespace forces = pointmass::forces;
using pointmass::test::body_at;
using pointmass::test::close;
using pointmass::test::force_on;

/// A component where x^2 overflows R, and one where it underflows to below the smallest
/// normal number (1e20, 1e-23 in float; 1e155, 1e-170 in double).
template <class R>
constexpr R huge = std::is_same_v<R, float> ? R(1e20L) : R(1e155L);
template <class R>
constexpr R tiny = std::is_same_v<R, float> ? R(1e-23L) : R(1e-170L);

template <class F>
std::string violation_message(F&& call) {
  try {
    call();
  } catch (const std::invalid_argument& error) {
    return error.what();
  }
  return "(no violation)";
}

int violations = 0;
void count_violation(const pointmass::ContractViolation&) { ++violations; }

}  // namespace

TEST_CASE_TEMPLATE("magnitude and normalized neither overflow nor underflow", R, float, double) {
  for (const R scale : {huge<R>, tiny<R>, std::numeric_limits<R>::max() / R(2),
                        std::numeric_limits<R>::denorm_min() * R(4)}) {
    CAPTURE(scale);
    const Vector3<R> v{scale * R(0.75), R(0), -scale};  // |v| = 1.25 scale
    CHECK(close(pointmass::magnitude(v), R(1.25) * scale, R(4), R(0)));
    const Vector3<R> unit = pointmass::normalized(v);
    CHECK(close(pointmass::magnitude(unit), R(1), R(4)));
    CHECK(close(unit, Vector3<R>{R(0.6), R(0), R(-0.8)}, R(4)));
  }
  // Beyond the largest R the magnitude is infinite, the direction still a unit vector.
  const R max = std::numeric_limits<R>::max();
  CHECK(pointmass::magnitude(Vector3<R>{max, max, R(0)}) == std::numeric_limits<R>::infinity());
  CHECK(close(pointmass::normalized(Vector3<R>{max, max, R(0)}).x, R(std::sqrt(0.5)), R(4)));
  // Ordinary vectors: the plain formula's bits.
  const Vector3<R> ordinary{R(0.3), R(-1.7), R(2.9)};
  CHECK(pointmass::magnitude(ordinary) ==
        std::sqrt(ordinary.x * ordinary.x + ordinary.y * ordinary.y + ordinary.z * ordinary.z));
}

TEST_CASE_TEMPLATE("springs and drag far from the origin: finite, and zero when they should be", R,
                   float, double) {
  const R h = huge<R>;
  const Particle<R> far = body_at<R>({h, h, -h}, {h, -h, h});
  // No stiffness, no drag: no force (before the fix: NaN from 0 * infinity).
  CHECK(force_on(forces::AnchoredSpring<R>({}, R(0), R(1)), far) == Vector3<R>{});
  CHECK(force_on(forces::AnchoredBungee<R>({}, R(0), R(1)), far) == Vector3<R>{});
  CHECK(force_on(forces::Drag<R>(R(0), R(0)), far) == Vector3<R>{});
  // Some stiffness and drag: finite and of the right size, -k |d| d / |d|, -k1 v.
  const Vector3<R> spring = force_on(forces::AnchoredSpring<R>({}, R(1e-3), R(0)), far);
  CHECK(close(spring, Vector3<R>{R(-1e-3) * h, R(-1e-3) * h, R(1e-3) * h}, R(16), R(0)));
  const Vector3<R> drag = force_on(forces::Drag<R>(R(2), R(0)), far);
  CHECK(close(drag, Vector3<R>{R(-2) * h, R(2) * h, R(-2) * h}, R(4), R(0)));
  // Two ends at opposite ends of the range: p - q overflows, a weak spring's force does not.
  const R max = std::numeric_limits<R>::max();
  const Particle<R> top = body_at<R>({max, R(0), R(0)});
  const Vector3<R> across =
      force_on(forces::AnchoredSpring<R>({-max, R(0), R(0)}, R(1e-3), R(0)), top);
  CHECK(close(across.x, R(-2e-3) * max, R(16), R(0)));
  // ... with its rest length: stretched to 2 max from max / 2, it pulls with k 1.5 max.
  const Vector3<R> stretched =
      force_on(forces::AnchoredSpring<R>({-max, R(0), R(0)}, R(1e-3), max / R(2)), top);
  CHECK(close(stretched.x, R(-1.5e-3) * max, R(16), R(0)));
  CHECK(stretched.y == R(0));
  // A spring compressed to a length whose square underflows pushes with k (L - |d|).
  const Particle<R> close_in = body_at<R>({tiny<R>, R(0), R(0)});
  const Vector3<R> push = force_on(forces::AnchoredSpring<R>({}, R(10), R(2)), close_in);
  CHECK(close(push, Vector3<R>{R(20), R(0), R(0)}, R(4)));
  // The batch path alike.
  const std::array<Vector3<R>, 2> positions{{{R(0), R(0), R(0)}, {tiny<R>, R(0), R(0)}}};
  const std::array<Vector3<R>, 2> velocities{};
  std::array<Vector3<R>, 2> f{};
  forces::SpanBodies<R> bodies{positions, velocities, {}, f};
  const std::array<forces::Link, 1> link{{{1, 0}}};
  forces::apply_links(forces::LinkSprings<R>(R(10), R(2)), std::span<const forces::Link>(link),
                      bodies);
  CHECK(close(f[1], Vector3<R>{R(20), R(0), R(0)}, R(4)));
}

#if POINTMASS_CHECKS
TEST_CASE_TEMPLATE(
    "apply: a force beyond the range on the last body is reported, and no body "
    "gets a force",
    R, float, double) {
  // Drag of 4 |v| on three bodies: 4 N on the first two, beyond the largest R on the last.
  const R max = std::numeric_limits<R>::max();
  const std::array<Vector3<R>, 3> positions{};
  const std::array<Vector3<R>, 3> velocities{
      {{R(1), R(0), R(0)}, {R(1), R(0), R(0)}, {max / R(2), R(0), R(0)}}};
  std::array<Vector3<R>, 3> f{};
  forces::SpanBodies<R> bodies{positions, velocities, {}, f};
  const std::string message =
      violation_message([&] { forces::apply(forces::Drag<R>(R(4), R(0)), bodies, R(0.01)); });
  CHECK(message.find("forces::apply: argument 'force' = (-inf, ") != std::string::npos);
  CHECK(f == std::array<Vector3<R>, 3>{});
}
#endif

TEST_CASE_TEMPLATE("gravity beyond the range is reported, buoyancy with a huge depth is right", R,
                   float, double) {
  // m g overflows for m = max / 4 (float: 8.5e37, accepted by set_mass): reported, not added.
  Particle<R> heavy;
  heavy.set_mass(std::numeric_limits<R>::max() / R(4));
  const forces::Gravity<R> gravity({R(0), R(-9.807), R(0)});
  const std::string message =
      violation_message([&] { forces::update_force(gravity, heavy, R(0.1)); });
  CHECK(message.find("forces::update_force: argument 'force' = (0, -inf, 0) must be finite") !=
        std::string::npos);
  CHECK(heavy.force_accumulator() == Vector3<R>{});
  // A depth whose double overflows: fully submerged below h - D, half at h.
  const R depth = std::numeric_limits<R>::max() / R(1.5);
  const forces::Buoyancy<R> buoyancy(depth, R(1), R(0), R(1), R(1));
  CHECK(force_on(buoyancy, body_at<R>({R(0), -depth, R(0)})).y == R(1));
  CHECK(force_on(buoyancy, body_at<R>({R(0), R(0), R(0)})).y == R(0.5));
  CHECK(force_on(buoyancy, body_at<R>({R(0), depth, R(0)})).y == R(0));
}

TEST_CASE_TEMPLATE("drag and buoyancy inside their ranges: no sum or product overflows first", R,
                   float, double) {
  const R max = std::numeric_limits<R>::max();
  // Drag k1 = k2 = 0.9 max at |v| = 0.5: ||v|| (k1 + k2 ||v||) = 0.675 max is in the range, but
  // k1 + k2 ||v|| = 1.35 max is not (it gave (-inf, NaN, NaN)).
  const R k = R(0.9) * max;
  const Vector3<R> drag = force_on(forces::Drag<R>(k, k), body_at<R>({}, {R(0.5), R(0), R(0)}));
  CHECK(close(drag.x, R(-0.675) * max, R(4), R(0)));
  CHECK(drag.y == R(0));
  CHECK(drag.z == R(0));
  // ||v|| beyond the range with finite components and a subnormal k2: the force k2 ||v|| v
  // is in it (it gave (-inf, -inf, NaN)). Expected in long double, whose range holds ||v||.
  const R tiny = std::numeric_limits<R>::denorm_min();
  const Vector3<R> fast = force_on(forces::Drag<R>(R(0), tiny), body_at<R>({}, {max, max, R(0)}));
  const long double expected =
      -static_cast<long double>(max) *
      (static_cast<long double>(tiny) * std::sqrt(2.0L) * static_cast<long double>(max));
  CHECK(fast.x == fast.y);
  CHECK(std::abs(static_cast<long double>(fast.x) - expected) <=
        8 * static_cast<long double>(std::numeric_limits<R>::epsilon()) * std::abs(expected));
  CHECK(fast.z == R(0));
  // Inside the range the force is as before, bit for bit: v (-(k1 + k2 ||v||)).
  const Vector3<R> v{R(3), R(-4), R(0)};  // ||v|| = 5 exactly
  const Vector3<R> usual = force_on(forces::Drag<R>(R(0.5), R(0.25)), body_at<R>({}, v));
  CHECK(usual == v * -(R(0.5) + R(0.25) * R(5)));
  // Buoyancy with rho V beyond the range: g = 0 weighs nothing (it gave NaN), and rho V g
  // within the range is that force (it gave inf).
  const R big = std::is_same_v<R, float> ? R(1e30L) : R(1e300L);
  const R small = R(1) / big;
  const Particle<R> under = body_at<R>({R(0), R(-5), R(0)});  // fully submerged
  CHECK(force_on(forces::Buoyancy<R>(R(1), big, R(0), big, R(0)), under).y == R(0));
  CHECK(
      close(force_on(forces::Buoyancy<R>(R(1), big, R(0), big, small), under).y, big, R(4), R(0)));
  // The usual case as before: rho V g times the fraction, in that order.
  const forces::Buoyancy<R> water(R(1), R(0.5), R(0), R(1000), R(9.807));
  CHECK(force_on(water, under).y == R(1000) * R(0.5) * R(9.807) * R(1));
}

TEST_CASE_TEMPLATE("stiff springs: tiny steps, tiny inverse masses, huge stiffness and damping", R,
                   float, double) {
  const Vector3<R> x{R(1), R(0), R(0)};
  const Vector3<R> v{R(0), R(2), R(0)};
  const forces::PositionOnlyStiffSpring<R> spring({}, R(50), R(3));
  // Tiny steps and inverse masses: the limit -(k x + c v) / 2 (before: NaN or infinity from
  // 1 / t^2 and 1 / (inverse_mass t)); continuous across the switch to the difference quotient.
  for (const R dt : {R(1e-30), std::numeric_limits<R>::denorm_min(), R(1e-3)}) {
    for (const R inverse_mass : {R(1), R(1e-30), std::numeric_limits<R>::denorm_min()}) {
      CAPTURE(dt);
      CAPTURE(inverse_mass);
      const Vector3<R> f = spring.force(x, v, inverse_mass, dt);
      CHECK(pointmass::is_finite(f));
      CHECK(close(f, Vector3<R>{R(-25), R(-3), R(0)}, R(0.05) / std::numeric_limits<R>::epsilon()));
    }
  }
  // Huge damping (gamma^2 overflows float): strongly over-damped, the body barely moves from
  // x0 + v0 / (2 gamma); before the fix the closed form returned x0 / 2.
  const R gamma = std::is_same_v<R, float> ? R(1e20) : R(1e160);
  const auto s = forces::damped_oscillator(R(1), gamma, x, v, R(1));
  CHECK(close(s.position, x, R(4)));
  CHECK(pointmass::is_finite(s.velocity));
  const forces::StiffSpring<R> sticky({}, R(1), R(2) * gamma);
  Particle<R, pointmass::damping::None, pointmass::position::SemiImplicit> body;
  body.set_position(x);
  body.set_velocity(v);
  sticky.integrate(body, R(1));
  CHECK(close(body.position(), x, R(4)));
  // Huge stiffness (w0 = 1e18 rad/s in float): finite, at the anchor's distance at most.
  const forces::StiffSpring<R> rigid({}, R(1e36), R(0));
  rigid.integrate(body, R(0.25));
  CHECK(pointmass::is_finite(body.position()));
  CHECK(pointmass::magnitude(body.position()) <= R(1.0001));
}

TEST_CASE_TEMPLATE("apply_links with a bad index changes nothing", R, float, double) {
  const std::array<Vector3<R>, 3> positions{
      {{R(0), R(0), R(0)}, {R(0), R(-3), R(0)}, {R(0), R(-4), R(0)}}};
  const std::array<Vector3<R>, 3> velocities{};
  std::array<Vector3<R>, 3> f{};
  forces::SpanBodies<R> bodies{positions, velocities, {}, f};
  const std::array<forces::Link, 2> links{{{0, 1}, {1, 5}}};
  const std::string message = violation_message([&] {
    forces::apply_links(forces::LinkSprings<R>(R(10), R(2)), std::span<const forces::Link>(links),
                        bodies);
  });
  CHECK(message.find("forces::apply_links: argument 'link.second' = 5 must be < size()") !=
        std::string::npos);
  // Before the fix the first link's force was added before the second was rejected.
  CHECK(f == std::array<Vector3<R>, 3>{});
}

TEST_CASE_TEMPLATE("an adapter with a span shorter than its size() is reported, with no force", R,
                   float, double) {
  // size() is the length of the forces (3); every other span is a view of the first 2
  // elements of storage for 3, so a read of element 2 stays inside the storage.
  const std::array<Vector3<R>, 3> positions{
      {{R(1), R(0), R(0)}, {R(2), R(0), R(0)}, {R(3), R(0), R(0)}}};
  const std::array<Vector3<R>, 3> velocities{
      {{R(1), R(0), R(0)}, {R(1), R(0), R(0)}, {R(1), R(0), R(0)}}};
  const std::array<R, 3> inverse_masses{R(1), R(1), R(1)};
  const std::span<const Vector3<R>> p_all(positions), v_all(velocities);
  const std::span<const R> m_all(inverse_masses);
  const forces::Drag<R> drag(R(1), R(0));
  const forces::LinkSprings<R> springs(R(10), R(0));
  const std::array<forces::Link, 1> links{{{0, 2}}};
  const auto link_span = std::span<const forces::Link>(links);

  std::array<Vector3<R>, 3> f{};
  forces::SpanBodies<R> short_positions{p_all.first(2), v_all, m_all, f};
  CHECK(violation_message([&] { forces::apply(drag, short_positions, R(0.01)); }) ==
        "pointmass: forces::apply: argument 'positions' = 2 elements for size() = 3 must be at "
        "least size() elements long (size() is the length of the forces)");
  CHECK(violation_message([&] {
          forces::apply_links(springs, link_span, short_positions);
        }).find("forces::apply_links: argument 'positions' = 2 elements for size() = 3") !=
        std::string::npos);
  forces::SpanBodies<R> short_velocities{p_all, v_all.first(2), m_all, f};
  CHECK(violation_message([&] {
          forces::apply(drag, short_velocities, R(0.01));
        }).find("'velocities' = 2 elements for size() = 3") != std::string::npos);
  forces::SpanBodies<R> short_masses{p_all, v_all, m_all.first(1), f};
  CHECK(violation_message([&] {
          forces::apply(drag, short_masses, R(0.01));
        }).find("'inverse_masses' = 1 elements for size() = 3") != std::string::npos);
  CHECK(f == std::array<Vector3<R>, 3>{});
  // An empty inverse_masses is the uniform one, and longer spans are fine.
  std::array<Vector3<R>, 2> f2{};
  forces::SpanBodies<R> uniform{p_all, v_all, {}, f2};
  CHECK(violation_message([&] { forces::apply(drag, uniform, R(0.01)); }) == "(no violation)");
  CHECK(f2[1] == Vector3<R>{R(-1), R(0), R(0)});

  std::array<R, 3> px{}, py{}, pz{}, vx{R(1), R(1), R(1)}, vy{}, vz{}, fx{}, fy{}, fz{};
  for (std::size_t i = 0; i < 3; ++i) px[i] = positions[i].x;
  const auto first2 = [](const std::array<R, 3>& a) { return std::span<const R>(a).first(2); };
  forces::SoaBodies<R> soa_short_vz{px, py, pz, vx, vy, first2(vz), {}, fx, fy, fz};
  CHECK(violation_message([&] {
          forces::apply(drag, soa_short_vz, R(0.01));
        }).find("forces::apply: argument 'vz' = 2 elements for size() = 3") != std::string::npos);
  CHECK(violation_message([&] {
          forces::apply_links(springs, link_span, soa_short_vz);
        }).find("forces::apply_links: argument 'vz' = 2") != std::string::npos);
  forces::SoaBodies<R> soa_short_px{first2(px), py, pz, vx, vy, vz, {}, fx, fy, fz};
  CHECK(violation_message([&] {
          forces::apply_links(springs, link_span, soa_short_px);
        }).find("forces::apply_links: argument 'px' = 2") != std::string::npos);
  // The forces are written through fx, fy and fz: fz too short is a write beyond its end.
  forces::SoaBodies<R> soa_short_fz{px, py, pz, vx, vy, vz, {}, fx, fy, std::span<R>(fz).first(2)};
  CHECK(violation_message([&] {
          forces::apply(drag, soa_short_fz, R(0.01));
        }).find("'fz' = 2 elements for size() = 3") != std::string::npos);
  CHECK(fx == std::array<R, 3>{});
  CHECK(fz == std::array<R, 3>{});

  // With a handler that returns: reported once per call, and still no force.
  const auto previous = pointmass::set_contract_handler(&count_violation);
  violations = 0;
  forces::apply(drag, short_positions, R(0.01));
  forces::apply_links(springs, link_span, soa_short_px);
  forces::apply(drag,
                forces::SoaBodies<R>{px, py, pz, vx, vy, vz, {}, fx, fy, std::span<R>(fz).first(2)},
                R(0.01));
  pointmass::set_contract_handler(previous);
  CHECK(violations == 3);
  CHECK(f == std::array<Vector3<R>, 3>{});
  CHECK(fx == std::array<R, 3>{});
}

// --- the registry ------------------------------------------------------------------------------

namespace {

/// Counts its calls and, on its first call, does `act` to the registry it is told about.
template <class Registry>
struct Meddler {
  using R = typename Registry::real;
  Registry* registry = nullptr;
  int calls = 0;
  enum class Act { remove_self, add_other, clear } act = Act::remove_self;
  Meddler<Registry>* other = nullptr;

  void update_force(Particle<R>& particle, R) {
    if (++calls != 1) return;
    if (act == Act::remove_self) registry->remove(particle, *this);
    if (act == Act::add_other) {
      for (int i = 0; i < 64; ++i) registry->add(particle, *other);  // reallocates
    }
    if (act == Act::clear) registry->clear();
  }
};

}  // namespace

TEST_CASE_TEMPLATE("registry changed during update_forces: deferred to after the pass", R, float,
                   double) {
  using Registry = forces::ForceRegistry<Particle<R>>;
  Particle<R> particle;
  {  // A generator removes itself: every other generator is called once, itself once.
    Registry registry;
    std::array<Meddler<Registry>, 4> meddlers{};
    for (auto& m : meddlers) m = {&registry, 0, Meddler<Registry>::Act::add_other, nullptr};
    meddlers[1].act = Meddler<Registry>::Act::remove_self;
    Meddler<Registry> idle{&registry, 1};  // calls = 1: does nothing
    for (auto& m : meddlers) m.other = &idle;
    meddlers[0].act = meddlers[2].act = meddlers[3].act = Meddler<Registry>::Act::clear;
    meddlers[0].calls = meddlers[2].calls = meddlers[3].calls = 1;  // already acted
    for (auto& m : meddlers) registry.add(particle, m);
    registry.update_forces(R(0.1));
    // Before the fix: meddlers[2] was skipped (the vector shifted under the loop).
    CHECK(meddlers[0].calls == 2);
    CHECK(meddlers[1].calls == 1);
    CHECK(meddlers[2].calls == 2);
    CHECK(meddlers[3].calls == 2);
    CHECK(registry.size() == 3);
  }
  {  // A generator adds 64 registrations (the vector reallocates under the loop): they act
     // from the next pass on. Before the fix: a heap-use-after-free.
    Registry registry;
    Meddler<Registry> idle{&registry, 1};
    Meddler<Registry> adder{&registry, 0, Meddler<Registry>::Act::add_other, &idle};
    Meddler<Registry> after{&registry, 1};
    registry.add(particle, adder);
    registry.add(particle, after);
    registry.update_forces(R(0.1));
    CHECK(adder.calls == 1);
    CHECK(after.calls == 2);
    CHECK(idle.calls == 1);
    CHECK(registry.size() == 66);
    registry.update_forces(R(0.1));
    CHECK(idle.calls == 65);
  }
  {  // A generator clears the registry: the ones not yet reached are not called.
    Registry registry;
    Meddler<Registry> clearer{&registry, 0, Meddler<Registry>::Act::clear};
    Meddler<Registry> later{&registry, 1};
    registry.add(particle, clearer);
    registry.add(particle, later);
    registry.update_forces(R(0.1));
    CHECK(later.calls == 1);
    CHECK(registry.empty());
  }
}

namespace {
// A generator owned by the registry it runs in, counting its calls; on its first call it
// replaces that registry (assigns an empty one, moves it into `elsewhere`, or swaps the two),
// or, with How::count, only counts.
template <class Registry>
struct Replacer {
  enum class How { count, assign, move_out, swap };
  using R = typename Registry::real;
  Registry* registry;
  Registry* elsewhere;
  How how;
  int* calls;
  void update_force(typename Registry::particle_type& particle, R) {
    if (++*calls != 1 || how == How::count) return;
    if (how == How::assign) *registry = Registry{};
    if (how == How::move_out) *elsewhere = std::move(*registry);
    if (how == How::swap) std::swap(*registry, *elsewhere);
    particle.add_force({R(1), R(0), R(0)});  // after the replacement: this generator lives on
  }
};
}  // namespace

TEST_CASE_TEMPLATE("a generator that replaces its registry ends the pass, and later passes work", R,
                   float, double) {
  using Registry = forces::ForceRegistry<Particle<R>>;
  using How = typename Replacer<Registry>::How;
  for (const How how : {How::assign, How::move_out, How::swap}) {
    CAPTURE(static_cast<int>(how));
    Particle<R> particle;
    Registry registry;
    Registry elsewhere;
    int calls[3] = {0, 0, 0};
    for (int k = 0; k < 3; ++k) {
      registry.add_owned(particle, Replacer<Registry>{&registry, &elsewhere,
                                                      k == 1 ? how : How::count, &calls[k]});
    }
    registry.update_forces(R(0.1));  // the second generator replaces the registry
    CHECK(calls[0] == 1);
    CHECK(calls[1] == 1);
    CHECK(calls[2] == 0);  // the pass ended with the replacement
    CHECK(particle.force_accumulator().x == R(1));
    CHECK(registry.empty());
    // Moved or swapped away, the registrations act once a pass where they went (the pass
    // counter did not go with them: before, it read -1 there and passes skipped generators).
    const bool moved = how != How::assign;
    CHECK(elsewhere.size() == (moved ? 3u : 0u));
    for (int pass = 0; pass < 3; ++pass) elsewhere.update_forces(R(0.1));
    registry.update_forces(R(0.1));
    CHECK(calls[0] == (moved ? 4 : 1));
    CHECK(calls[1] == (moved ? 4 : 1));
    CHECK(calls[2] == (moved ? 3 : 0));
  }
}

namespace {
template <class R>
struct Hub;
// A generator of a known type that, on each call, registers hub->added (a type-erased one).
template <class R>
struct KnownAdder {
  Hub<R>* hub;
  void update_force(Particle<R>& particle, R) const;
};
template <class R>
struct Plain {
  int calls = 0;
  void update_force(Particle<R>&, R) { ++calls; }
};
template <class R>
struct Hub {
  forces::ForceRegistry<Particle<R>, KnownAdder<R>> registry;
  Plain<R> added;
};
template <class R>
void KnownAdder<R>::update_force(Particle<R>& particle, R) const {
  hub->registry.add(particle, hub->added);
}
}  // namespace

TEST_CASE_TEMPLATE("a type-erased registration added by a known generator waits for the next pass",
                   R, float, double) {
  Hub<R> hub;
  Particle<R> particle;
  KnownAdder<R> adder{&hub};
  hub.registry.add(particle, adder);  // a known type: called before the type-erased ones
  hub.registry.update_forces(R(0.1));
  // Before the fix: 1 (the type-erased vector's count was read when the pass reached it).
  CHECK(hub.added.calls == 0);
  CHECK(hub.registry.size() == 2);
  hub.registry.update_forces(R(0.1));
  CHECK(hub.added.calls == 1);
}

namespace {
// Counts the instances alive; on its first call removes itself or moves its registry away.
template <class R>
struct Counted {
  using Registry = forces::ForceRegistry<Particle<R>>;
  enum class Mode { remove_self, move_out };
  Registry* registry;
  Registry* elsewhere;
  Mode mode;
  int* alive;
  bool acted = false;
  Counted(Registry* r, Registry* e, Mode m, int* a) : registry(r), elsewhere(e), mode(m), alive(a) {
    ++*alive;
  }
  Counted(const Counted& other)
      : registry(other.registry),
        elsewhere(other.elsewhere),
        mode(other.mode),
        alive(other.alive),
        acted(other.acted) {
    ++*alive;
  }
  Counted& operator=(const Counted&) = default;
  ~Counted() { --*alive; }
  void update_force(Particle<R>& particle, R) {
    if (std::exchange(acted, true)) return;
    if (mode == Mode::remove_self) registry->remove(particle, *this);
    else *elsewhere = std::move(*registry);
  }
};
}  // namespace

TEST_CASE_TEMPLATE("a generator removed in a pass is destroyed as it ends, its registry moved away",
                   R, float, double) {
  using Registry = forces::ForceRegistry<Particle<R>>;
  using Mode = typename Counted<R>::Mode;
  Particle<R> particle;
  int alive = 0;
  Registry registry;
  Registry elsewhere;
  registry.add_owned(particle, Counted<R>(&registry, &elsewhere, Mode::remove_self, &alive));
  registry.add_owned(particle, Counted<R>(&registry, &elsewhere, Mode::move_out, &alive));
  REQUIRE(alive == 2);
  registry.update_forces(R(0.1));  // the first removes itself, the second moves the registry
  // Before the fix: 2 (the removed one went to `elsewhere`, alive until that compacted).
  CHECK(alive == 1);
  CHECK(elsewhere.size() == 1);
  CHECK(registry.empty());
}

TEST_CASE_TEMPLATE("registry accepts const generators", R, float, double) {
  // Before the fix: "invalid static_cast ... to void*" inside the registry.
  forces::ForceRegistry<Particle<R>, forces::Drag<R>> registry;
  const forces::Drag<R> drag(R(2), R(0));
  const forces::Gravity<R> gravity({R(0), R(-10), R(0)});
  Particle<R> particle = body_at<R>({}, {R(1), R(0), R(0)});
  registry.add(particle, drag);
  registry.add(particle, gravity);
  registry.update_forces(R(0.1));
  CHECK(particle.force_accumulator() == Vector3<R>{R(-2), R(-10), R(0)});
  CHECK(registry.remove(particle, drag));
  CHECK(registry.remove(particle, gravity));
  CHECK(registry.empty());
}

TEST_CASE_TEMPLATE("owning registry: the emplace_back idiom is safe", R, float, double) {
  // The idiom that is a heap-use-after-free with a non-owning registry: springs built in a
  // vector that grows after each registration. The owning form copies each one; this test
  // runs under AddressSanitizer in the sanitizer configuration.
  forces::ForceRegistry<Particle<R>, forces::AnchoredSpring<R>> registry;
  std::array<Particle<R>, 16> particles{};
  std::vector<forces::AnchoredSpring<R>> springs;
  std::vector<forces::AnchoredSpring<R>*> registered;
  for (std::size_t i = 0; i < particles.size(); ++i) {
    particles[i].set_position({R(1) + R(i), R(0), R(0)});
    springs.emplace_back(Vector3<R>{}, R(2), R(1));
    registered.push_back(&registry.add_owned(particles[i], springs.back()));
  }
  springs.clear();
  springs.shrink_to_fit();
  registry.update_forces(R(0.1));
  for (std::size_t i = 0; i < particles.size(); ++i) {
    CHECK(particles[i].force_accumulator() == Vector3<R>{R(-2) * R(i), R(0), R(0)});
  }
  // emplace builds in place; an owned generator removes like any other, and a generator the
  // registry owns that removes itself during the pass is destroyed only after it.
  auto& drag = registry.template emplace<forces::Drag<R>>(particles[0], R(1), R(0));
  CHECK(registry.size() == 17);
  CHECK(registry.remove(particles[0], drag));
  CHECK(registry.remove(particles[3], *registered[3]));
  CHECK(registry.size() == 15);
  using Self = Meddler<forces::ForceRegistry<Particle<R>, forces::AnchoredSpring<R>>>;
  auto& self = registry.template emplace<Self>(particles[1], &registry);
  registry.update_forces(R(0.1));
  CHECK(registry.size() == 15);
  static_cast<void>(self);
}
