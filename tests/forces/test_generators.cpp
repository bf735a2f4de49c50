// SPDX-License-Identifier: BSL-1.0
// Each generator against its formula worked by hand, Cyclone's bugs pinned by
// regression tests, bad parameters rejected, and the batch path equal to the particle path.
#include <doctest/doctest.h>

#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>
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

template <class R>
Particle<R> immovable_at(Vector3<R> p) {
  Particle<R> particle;
  particle.set_position(p);
  particle.set_inverse_mass(R(0));
  return particle;
}

}  // namespace

TEST_CASE_TEMPLATE("gravity adds m g, and nothing to an immovable particle", R, float, double) {
  const forces::Gravity<R> gravity({R(0), R(-9.807), R(0)});
  const Vector3<R> f = force_on(gravity, body_at<R>({}, {}, R(2)));
  CHECK(f.x == R(0));
  CHECK(close(f.y, R(-19.614), R(2)));
  CHECK(f.z == R(0));
  // Regression: Cyclone's generators that multiply by the mass give an
  // immovable particle an infinite force; here it gets none (and no contract violation).
  const Vector3<R> none = force_on(gravity, immovable_at<R>({R(1), R(2), R(3)}));
  CHECK(none == Vector3<R>{});
}

TEST_CASE_TEMPLATE("drag is k1 |v| + k2 |v|^2 against the velocity", R, float, double) {
  const forces::Drag<R> drag(R(0.5), R(0.1));
  // |v| = 5: magnitude 0.5 * 5 + 0.1 * 25 = 5, direction -(0.6, 0.8, 0).
  const Vector3<R> f = force_on(drag, body_at<R>({}, {R(3), R(4), R(0)}));
  CHECK(close(f, Vector3<R>{R(-3), R(-4), R(0)}, R(4)));
  // At rest: no direction, no force, no NaN.
  CHECK(force_on(drag, body_at<R>({R(1), R(1), R(1)})) == Vector3<R>{});
}

TEST_CASE_TEMPLATE("anchored spring: -k (|d| - L) d/|d|, pushing when compressed", R, float,
                   double) {
  const forces::AnchoredSpring<R> spring({R(1), R(0), R(0)}, R(10), R(2));
  // Stretched by 1 along +x: pulled back with 10 N.
  CHECK(close(force_on(spring, body_at<R>({R(4), R(0), R(0)})), Vector3<R>{R(-10), R(0), R(0)},
              R(2)));
  // Regression (Cyclone takes |(|d| - L)|, so a compressed spring pulls):
  // compressed by 1, the body is pushed away from the anchor.
  CHECK(
      close(force_on(spring, body_at<R>({R(2), R(0), R(0)})), Vector3<R>{R(10), R(0), R(0)}, R(2)));
  // 3-4-5 triangle: |d| = 5, extension 3, force -10 * 3 * (3, 4, 0) / 5.
  CHECK(close(force_on(spring, body_at<R>({R(4), R(4), R(0)})), Vector3<R>{R(-18), R(-24), R(0)},
              R(4)));
  // At the anchor the direction is undefined: no force, no NaN.
  CHECK(force_on(spring, body_at<R>({R(1), R(0), R(0)})) == Vector3<R>{});
}

TEST_CASE_TEMPLATE("spring between particles pulls them together, equal and opposite", R, float,
                   double) {
  Particle<R> a = body_at<R>({R(0), R(0), R(0)});
  Particle<R> b = body_at<R>({R(0), R(4), R(0)});
  const forces::Spring<Particle<R>> on_a(b, R(3), R(1));
  const forces::Spring<Particle<R>> on_b(a, R(3), R(1));
  forces::update_force(on_a, a, R(0.1));
  forces::update_force(on_b, b, R(0.1));
  // Extension 3, stiffness 3: 9 N along the line.
  CHECK(close(a.force_accumulator(), Vector3<R>{R(0), R(9), R(0)}, R(2)));
  CHECK(close(b.force_accumulator(), Vector3<R>{R(0), R(-9), R(0)}, R(2)));
  // A wrapper that refers to the other body (std::ref, std::cref) is not a temporary body.
  forces::Spring<Particle<R>> by_reference(std::ref(b), R(3), R(1));
  CHECK(by_reference.other() == &b);
  by_reference.set_other(std::cref(a));
  CHECK(by_reference.other() == &a);
}

TEST_CASE_TEMPLATE("bungee pulls when stretched and never pushes", R, float, double) {
  Particle<R> other = body_at<R>({R(0), R(0), R(0)});
  const forces::Bungee<Particle<R>> bungee(other, R(5), R(2));
  // Regression (Cyclone multiplies by -k (L - |d|): a stretched bungee pushes
  // the ends apart). Stretched by 1 at (3, 0, 0): pulled back towards the other end.
  CHECK(
      close(force_on(bungee, body_at<R>({R(3), R(0), R(0)})), Vector3<R>{R(-5), R(0), R(0)}, R(2)));
  // Slack or exactly at rest length: nothing.
  CHECK(force_on(bungee, body_at<R>({R(1), R(0), R(0)})) == Vector3<R>{});
  CHECK(force_on(bungee, body_at<R>({R(0), R(2), R(0)})) == Vector3<R>{});
  // The anchored one alike.
  const forces::AnchoredBungee<R> anchored({R(0), R(10), R(0)}, R(5), R(2));
  CHECK(close(force_on(anchored, body_at<R>({R(0), R(7), R(0)})), Vector3<R>{R(0), R(5), R(0)},
              R(2)));
  CHECK(force_on(anchored, body_at<R>({R(0), R(9), R(0)})) == Vector3<R>{});
}

TEST_CASE_TEMPLATE("buoyancy is rho V g times the submerged fraction, always upwards", R, float,
                   double) {
  // Half-height 0.5 m, 0.1 m^3, water surface at y = 0, water, g = 9.807.
  const forces::Buoyancy<R> buoyancy(R(0.5), R(0.1), R(0));
  const R full = R(1000) * R(0.1) * R(9.807);  // 980.7 N
  CHECK(force_on(buoyancy, body_at<R>({R(0), R(2), R(0)})) == Vector3<R>{});
  CHECK(force_on(buoyancy, body_at<R>({R(0), R(0.5), R(0)})) == Vector3<R>{});
  CHECK(close(force_on(buoyancy, body_at<R>({R(0), R(0), R(0)})).y, full / R(2), R(4)));
  CHECK(close(force_on(buoyancy, body_at<R>({R(0), R(-0.25), R(0)})).y, full * R(0.75), R(4)));
  // Fully submerged: the whole weight of the displaced water. Regression: the reference
  // engine adds rho V (980 times too small with g = 9.807: a mass, not a force).
  CHECK(close(force_on(buoyancy, body_at<R>({R(0), R(-0.5), R(0)})).y, full, R(4)));
  CHECK(close(force_on(buoyancy, body_at<R>({R(0), R(-30), R(0)})).y, full, R(4)));
  // Regression: Cyclone's partly-submerged force, (y - D - h) / 2 * D, is
  // negative. Here, at every depth, the force is upwards, and it grows as the body sinks.
  R previous = R(0);
  for (int i = 0; i <= 400; ++i) {
    const R y = R(2) - R(i) * R(0.01);
    const Vector3<R> f = force_on(buoyancy, body_at<R>({R(0), y, R(0)}));
    CHECK(f.x == R(0));
    CHECK(f.z == R(0));
    CHECK(f.y >= R(0));
    CHECK(f.y >= previous);
    previous = f.y;
  }
  // A different liquid and g.
  const forces::Buoyancy<R> sea(R(1), R(2), R(0), R(1025), R(10));
  CHECK(close(force_on(sea, body_at<R>({R(0), R(-5), R(0)})).y, R(20500), R(4)));
}

TEST_CASE_TEMPLATE("stiff spring: finite in every damping regime, nothing when immovable", R, float,
                   double) {
  const Particle<R> body = body_at<R>({R(1), R(0), R(0)}, {R(0), R(1), R(0)}, R(1));
  // Regression: Cyclone's fake spring takes sqrt(4 k - c^2), NaN over-damped.
  const forces::PositionOnlyStiffSpring<R> over({}, R(1), R(10));
  const Vector3<R> f_over = force_on(over, body, R(0.1));
  CHECK(pointmass::is_finite(f_over));
  CHECK(f_over.x < R(0));  // back towards the anchor
  CHECK(f_over.y < R(0));  // against the velocity
  // Regression: critically damped (c^2 = 4 k m), Cyclone adds no force at all.
  const forces::PositionOnlyStiffSpring<R> critical({}, R(4), R(4));
  const Vector3<R> f_critical = force_on(critical, body, R(0.1));
  CHECK(pointmass::is_finite(f_critical));
  CHECK(f_critical.x < R(0));
  // Huge steps and stiffness: still finite.
  const forces::PositionOnlyStiffSpring<R> stiff({}, R(1e6), R(0.01));
  CHECK(pointmass::is_finite(force_on(stiff, body, R(100))));
  CHECK(pointmass::is_finite(force_on(over, body, R(1e4))));
  // Immovable, or a zero step: nothing.
  CHECK(force_on(stiff, immovable_at<R>({R(1), R(0), R(0)})) == Vector3<R>{});
  CHECK(force_on(stiff, body, R(0)) == Vector3<R>{});
}

// --- contracts ------------------------------------------------------------------------------

namespace {

template <class F>
std::string violation_message(F&& make) {
  try {
    make();
  } catch (const std::invalid_argument& error) {
    return error.what();
  }
  return "(no violation)";
}

int returning_handler_calls = 0;
void returning_handler(const pointmass::ContractViolation&) { ++returning_handler_calls; }

}  // namespace

TEST_CASE_TEMPLATE("bad parameters are rejected, naming the argument and its value", R, float,
                   double) {
  Particle<R> other;
  const auto msg_stiffness = violation_message([] { forces::AnchoredSpring<R>({}, R(-1), R(1)); });
  CHECK(msg_stiffness.find("'stiffness' = -1") != std::string::npos);
  const auto msg_rest = violation_message([&] { forces::Spring<Particle<R>>(other, R(1), R(-2)); });
  CHECK(msg_rest.find("'rest_length' = -2") != std::string::npos);
  const auto msg_volume = violation_message([] { forces::Buoyancy<R>(R(1), R(0), R(0)); });
  CHECK(msg_volume.find("set_volume: argument 'volume' = 0") != std::string::npos);
  const auto msg_depth = violation_message([] { forces::Buoyancy<R>(R(-1), R(1), R(0)); });
  CHECK(msg_depth.find("'max_depth' = -1") != std::string::npos);
  const auto msg_k1 = violation_message([] { forces::Drag<R>(R(-0.5), R(0)); });
  CHECK(msg_k1.find("'k1' = -0.5") != std::string::npos);
  const auto msg_damping = violation_message(
      [] { forces::PositionOnlyStiffSpring<R>({}, R(1), std::numeric_limits<R>::quiet_NaN()); });
  CHECK(msg_damping.find("'damping' = nan") != std::string::npos);
  const auto msg_gravity = violation_message([] {
    forces::Gravity<R>({R(0), std::numeric_limits<R>::infinity(), R(0)});
  });
  CHECK(msg_gravity.find("'gravity'") != std::string::npos);
  // Valid parameters raise nothing.
  CHECK(violation_message([] { forces::Buoyancy<R>(R(1), R(1), R(0)); }) == "(no violation)");
}

TEST_CASE_TEMPLATE("with a handler that returns, a rejected value changes nothing", R, float,
                   double) {
  const auto previous = pointmass::set_contract_handler(&returning_handler);
  returning_handler_calls = 0;
  forces::AnchoredSpring<R> spring({}, R(7), R(1));
  spring.set_stiffness(R(-3));
  spring.set_rest_length(R(-1));
  CHECK(spring.stiffness() == R(7));
  CHECK(spring.rest_length() == R(1));
  // A constructor's rejected volume keeps the harmless default: no force.
  const forces::Buoyancy<R> buoyancy(R(1), R(0), R(0));
  CHECK(force_on(buoyancy, body_at<R>({R(0), R(-5), R(0)})) == Vector3<R>{});
  CHECK(returning_handler_calls == 3);
  pointmass::set_contract_handler(previous);
}

TEST_CASE_TEMPLATE("a constructor that rejects any argument leaves the generator inert", R, float,
                   double) {
  const auto previous = pointmass::set_contract_handler(&returning_handler);
  returning_handler_calls = 0;
  const R nan = std::numeric_limits<R>::quiet_NaN();
  // A moving body, away from every anchor and under every water surface: each generator here,
  // built with valid arguments, gives it a force.
  const Particle<R> body = body_at<R>({R(3), R(-2), R(1)}, {R(1), R(0.5), R(0)});
  const Vector3<R> none{};
  CHECK(force_on(forces::Gravity<R>({R(0), nan, R(0)}), body) == none);
  CHECK(force_on(forces::Drag<R>(R(-1), R(0.5)), body) == none);
  CHECK(force_on(forces::Drag<R>(R(0.5), nan), body) == none);
  const forces::AnchoredSpring<R> hook({nan, R(5), R(0)}, R(40), R(0.5));
  CHECK(force_on(hook, body) == none);
  CHECK(hook.stiffness() == R(0));
  CHECK(force_on(forces::AnchoredSpring<R>({}, R(40), R(-1)), body) == none);
  CHECK(force_on(forces::AnchoredBungee<R>({}, R(40), R(-200)), body) == none);
  Particle<R> other = body_at<R>({});
  CHECK(force_on(forces::Spring<Particle<R>>(other, R(20), R(-1)), body) == none);
  CHECK(force_on(forces::Bungee<Particle<R>>(other, nan, R(1)), body) == none);
  CHECK(force_on(forces::Buoyancy<R>(R(-0.5), R(0.1), R(10)), body) == none);
  CHECK(force_on(forces::Buoyancy<R>(R(0.5), R(0.1), nan), body) == none);
  CHECK(force_on(forces::Buoyancy<R>(R(0.5), R(0.1), R(10), R(-1)), body) == none);
  CHECK(force_on(forces::Buoyancy<R>(R(0.5), R(0.1), R(10), R(1000), R(-9.807)), body) == none);
  CHECK(force_on(forces::PositionOnlyStiffSpring<R>({nan, R(0), R(0)}, R(50), R(1)), body) == none);
  CHECK(force_on(forces::PositionOnlyStiffSpring<R>({}, R(50), R(-1)), body) == none);
  // Two bad arguments: each is reported.
  CHECK(force_on(forces::Drag<R>(R(-1), R(-2)), body) == none);

  const std::array<Vector3<R>, 2> positions{{{R(0), R(0), R(0)}, {R(0), R(-3), R(0)}}};
  const std::array<Vector3<R>, 2> velocities{};
  std::array<Vector3<R>, 2> f{};
  forces::SpanBodies<R> bodies{positions, velocities, {}, f};
  const std::array<forces::Link, 1> links{{{0, 1}}};
  forces::apply_links(forces::LinkSprings<R>(R(10), R(-1)), std::span<const forces::Link>(links),
                      bodies);
  CHECK(f == std::array<Vector3<R>, 2>{});

  // A stiff spring with a rejected argument steps the body as no spring would: x + v t.
  for (const auto& stiff : {forces::StiffSpring<R>({nan, R(0), R(0)}, R(100), R(1)),
                            forces::StiffSpring<R>({}, R(100), R(-1))}) {
    Particle<R> moved = body;
    stiff.integrate(moved, R(0.5));
    CHECK(close(moved.position(), body.position() + body.velocity() * R(0.5), R(4)));
    CHECK(moved.velocity() == body.velocity());
  }
  CHECK(returning_handler_calls == 19);
  pointmass::set_contract_handler(previous);
}

// --- the batch path ---------------------------------------------------------------------------

namespace {

template <class R, class G>
void check_batch_matches_particles(const G& generator) {
  const std::array<Vector3<R>, 4> positions{
      {{R(1), R(2), R(3)}, {R(-0.3), R(0.2), R(0)}, {R(0), R(-4), R(1)}, {R(5), R(5), R(-5)}}};
  const std::array<Vector3<R>, 4> velocities{
      {{R(0), R(1), R(0)}, {R(2), R(-1), R(0.5)}, {R(0), R(0), R(0)}, {R(-3), R(0), R(1)}}};
  const std::array<R, 4> inverse_masses{R(1), R(0.5), R(0), R(4)};
  const R dt = R(1) / R(30);

  std::array<Vector3<R>, 4> aos_forces{};
  forces::SpanBodies<R> aos{positions, velocities, inverse_masses, aos_forces};
  forces::apply(generator, aos, dt);

  std::array<R, 4> px{}, py{}, pz{}, vx{}, vy{}, vz{}, fx{}, fy{}, fz{};
  for (std::size_t i = 0; i < 4; ++i) {
    px[i] = positions[i].x, py[i] = positions[i].y, pz[i] = positions[i].z;
    vx[i] = velocities[i].x, vy[i] = velocities[i].y, vz[i] = velocities[i].z;
  }
  forces::SoaBodies<R> soa{px, py, pz, vx, vy, vz, inverse_masses, fx, fy, fz};
  forces::apply(generator, soa, dt);

  for (std::size_t i = 0; i < 4; ++i) {
    Particle<R> particle;
    particle.set_position(positions[i]);
    particle.set_velocity(velocities[i]);
    particle.set_inverse_mass(inverse_masses[i]);
    forces::update_force(generator, particle, dt);
    CHECK(aos_forces[i] == particle.force_accumulator());
    CHECK(Vector3<R>{fx[i], fy[i], fz[i]} == particle.force_accumulator());
  }
}

}  // namespace

TEST_CASE_TEMPLATE("a batch gets the same bits as particles, generator by generator", R, float,
                   double) {
  check_batch_matches_particles<R>(forces::Gravity<R>({R(0), R(-20), R(0)}));
  check_batch_matches_particles<R>(forces::Drag<R>(R(0.2), R(0.05)));
  check_batch_matches_particles<R>(forces::AnchoredSpring<R>({R(0), R(1), R(0)}, R(8), R(1)));
  check_batch_matches_particles<R>(forces::AnchoredBungee<R>({R(0), R(1), R(0)}, R(8), R(3)));
  check_batch_matches_particles<R>(forces::Buoyancy<R>(R(0.5), R(0.01), R(0)));
  check_batch_matches_particles<R>(
      forces::PositionOnlyStiffSpring<R>({R(0), R(1), R(0)}, R(50), R(3)));
}

TEST_CASE_TEMPLATE("links add equal and opposite spring forces in a batch", R, float, double) {
  const std::array<Vector3<R>, 3> positions{
      {{R(0), R(0), R(0)}, {R(0), R(-3), R(0)}, {R(0), R(-4), R(0)}}};
  const std::array<Vector3<R>, 3> velocities{};
  std::array<Vector3<R>, 3> f{};
  forces::SpanBodies<R> bodies{positions, velocities, {}, f};
  const std::array<forces::Link, 2> links{{{0, 1}, {1, 2}}};
  forces::apply_links(forces::LinkSprings<R>(R(10), R(2)), std::span<const forces::Link>(links),
                      bodies);
  // Link 0-1 stretched by 1: 10 N pulling them together; link 1-2 compressed by 1: pushes.
  CHECK(close(f[0], Vector3<R>{R(0), R(-10), R(0)}, R(2)));
  CHECK(close(f[1], Vector3<R>{R(0), R(10) + R(10), R(0)}, R(2)));
  CHECK(close(f[2], Vector3<R>{R(0), R(-10), R(0)}, R(2)));
  // A bungee link does not push: only the stretched link acts.
  std::array<Vector3<R>, 3> g{};
  forces::SpanBodies<R> again{positions, velocities, {}, g};
  forces::apply_links(forces::LinkBungees<R>(R(10), R(2)), std::span<const forces::Link>(links),
                      again);
  CHECK(close(g[1], Vector3<R>{R(0), R(10), R(0)}, R(2)));
  CHECK(g[2] == Vector3<R>{});
}

TEST_CASE_TEMPLATE("apply_link pulls two single particles with equal and opposite forces", R, float,
                   double) {
  // 3 m apart on y, a spring of 10 N/m at rest at 2 m: stretched by 1, 10 N pulling together.
  Particle<R> top = body_at<R>({R(0), R(0), R(0)});
  Particle<R> bottom = body_at<R>({R(0), R(-3), R(0)});
  // What the two registrations Spring needs, one at each end, add.
  const Vector3<R> on_top = force_on(forces::Spring<Particle<R>>(bottom, R(10), R(2)), top);
  const Vector3<R> on_bottom = force_on(forces::Spring<Particle<R>>(top, R(10), R(2)), bottom);
  forces::apply_link(forces::LinkSprings<R>(R(10), R(2)), top, bottom);
  CHECK(close(top.force_accumulator(), Vector3<R>{R(0), R(-10), R(0)}, R(2)));
  CHECK(close(bottom.force_accumulator(), Vector3<R>{R(0), R(10), R(0)}, R(2)));
  CHECK(top.force_accumulator() == on_top);
  CHECK(bottom.force_accumulator() == on_bottom);
  // A bungee does not push: 1 m apart, compressed, no force.
  Particle<R> near = body_at<R>({R(0), R(-1), R(0)});
  Particle<R> other = body_at<R>({R(0), R(0), R(0)});
  forces::apply_link(forces::LinkBungees<R>(R(10), R(2)), near, other);
  CHECK(near.force_accumulator() == Vector3<R>{});
  CHECK(other.force_accumulator() == Vector3<R>{});
}
