// SPDX-License-Identifier: BSL-1.0
// Boost.Odeint on a Boost.Units state: the mass on a spring, integrated by odeint's classic
// Runge-Kutta with a state of (length, velocity) quantities, is the reference for the SI
// particle. This file compiles slowly (odeint's fusion algebra over quantities) and is the
// only one that includes odeint with units.
#define DOCTEST_CONFIG_IMPLEMENT_WITH_MAIN
#include <doctest/doctest.h>

#include <cmath>
#include <numbers>

#include <boost/fusion/container.hpp>
#include <boost/fusion/sequence.hpp>
#include <boost/numeric/odeint.hpp>
#include <boost/numeric/odeint/algebra/fusion_algebra.hpp>
#include <boost/numeric/odeint/algebra/fusion_algebra_dispatcher.hpp>
#include <boost/units/systems/si/frequency.hpp>

#include <pointmass/extras/scenes.hpp>
#include <pointmass/units.hpp>

namespace pm = pointmass;
namespace si = boost::units::si;
namespace odeint = boost::numeric::odeint;
namespace fusion = boost::fusion;
using boost::units::quantity;

namespace {

using length_t = pm::units::length<double>;
using velocity_t = pm::units::velocity<double>;
using acceleration_t = pm::units::acceleration<double>;
using duration_t = pm::units::time<double>;
using state_type = fusion::vector<length_t, velocity_t>;
using deriv_type = fusion::vector<velocity_t, acceleration_t>;

/// x'' = -(k / m) x, written on quantities: a dimension slip here would not compile.
struct Spring {
  quantity<si::frequency, double> omega;
  void operator()(const state_type& x, deriv_type& dxdt, duration_t) const {
    fusion::at_c<0>(dxdt) = fusion::at_c<1>(x);
    fusion::at_c<1>(dxdt) = -omega * omega * fusion::at_c<0>(x);
  }
};

const pm::scenes::SpringScene<double> scene{};

/// odeint's RK4 on the quantity state, from the scene's start to `end`, in 4096 steps a second.
length_t reference_position(duration_t end) {
  odeint::runge_kutta4<state_type, double, deriv_type, duration_t> stepper;
  state_type x(scene.start.x * si::meters, 0.0 * si::meters_per_second);
  const quantity<si::frequency, double> omega = std::sqrt(scene.stiffness / scene.mass) * si::hertz;
  const duration_t dt = (1.0 / 4096) * si::seconds;
  odeint::integrate_const(stepper, Spring{omega}, x, 0.0 * si::seconds, end, dt);
  return fusion::at_c<0>(x);
}

/// The SI particle on the same spring: force -k x added every step.
template <class Position>
length_t particle_position(duration_t end, int steps_per_second) {
  pm::units::Particle<double, pm::damping::None, Position> particle;
  particle.set_position(scene.start * si::meters);
  particle.set_mass(scene.mass * si::kilograms);
  const auto stiffness = scene.stiffness * si::newtons / si::meters;
  const duration_t dt = (1.0 / steps_per_second) * si::seconds;
  const int steps = static_cast<int>(std::lround(pm::in_seconds(end) * steps_per_second));
  for (int i = 0; i < steps; ++i) {
    particle.add_force(particle.position() * -stiffness);
    particle.integrate(dt);
  }
  return particle.position().x;
}

}  // namespace

TEST_CASE("odeint on a units state matches the closed form of the spring") {
  // x(t) = cos(w t) with w = 2 pi / s: at 1/8 s, cos(pi / 4).
  const length_t x = reference_position(0.125 * si::seconds);
  CHECK(std::abs(x.value() - std::cos(std::numbers::pi / 4)) < 1e-9);
}

TEST_CASE("the SI particle converges to the odeint reference at first order") {
  // Explicit Euler (position::Euler, no damping) is first order: halving the step halves the
  // error. At 1/8 s the position and the velocity are both non-zero, so no symmetry cancels
  // the first-order term.
  const duration_t end = 0.125 * si::seconds;
  const length_t reference = reference_position(end);
  const double coarse =
      std::abs((particle_position<pm::position::Euler>(end, 480) - reference).value());
  const double fine =
      std::abs((particle_position<pm::position::Euler>(end, 960) - reference).value());
  INFO("errors: ", coarse, " m at 1/480 s, ", fine, " m at 1/960 s");
  CHECK(fine > 0.0);
  CHECK(coarse / fine > 1.8);
  CHECK(coarse / fine < 2.2);

  // Semi-implicit Euler is first order too.
  const double semi_coarse =
      std::abs((particle_position<pm::position::SemiImplicit>(end, 480) - reference).value());
  const double semi_fine =
      std::abs((particle_position<pm::position::SemiImplicit>(end, 960) - reference).value());
  INFO("semi-implicit errors: ", semi_coarse, " m, ", semi_fine, " m");
  CHECK(semi_fine > 0.0);
  CHECK(semi_coarse / semi_fine > 1.8);
  CHECK(semi_coarse / semi_fine < 2.2);
}
