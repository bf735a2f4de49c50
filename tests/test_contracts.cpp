// SPDX-License-Identifier: BSL-1.0
// Contracts: every bad argument gives the documented error, naming the argument and its
// value, and leaves the particle unchanged; a user's handler is called instead when installed.
// Built with POINTMASS_ENABLE_CHECKS, so the hot-path checks are on in every build type.
#include <doctest/doctest.h>

#include <limits>
#include <stdexcept>
#include <string>

#include <pointmass/pointmass.hpp>

using namespace pointmass;

namespace {

template <class P>
void set_up(P& p) {
  p.set_position({1, 2, 3});
  p.set_velocity({4, 5, 6});
  p.set_acceleration({0, -10, 0});
  p.set_mass(2);
  if constexpr (P::stores_damping) p.set_damping(typename P::real(0.9));
  p.add_force({7, 8, 9});
}

template <class P>
bool same_state(const P& a, const P& b) {
  return a.position() == b.position() && a.velocity() == b.velocity() &&
         a.acceleration() == b.acceleration() && a.force_accumulator() == b.force_accumulator() &&
         a.inverse_mass() == b.inverse_mass() && a.damping() == b.damping();
}

// Runs `bad` on a configured particle; checks it throws std::invalid_argument whose message
// contains each of `expected`, and that the particle is unchanged.
template <class P, class Bad>
void check_rejected(Bad bad, std::initializer_list<const char*> expected) {
  P p;
  set_up(p);
  const P before = p;
  std::string message;
  try {
    bad(p);
  } catch (const std::invalid_argument& error) {
    message = error.what();
  }
  INFO("message: ", message);
  REQUIRE_FALSE(message.empty());
  for (const char* part : expected) CHECK(message.find(part) != std::string::npos);
  CHECK(same_state(p, before));
}

constexpr float infinity = std::numeric_limits<float>::infinity();
constexpr float not_a_number = std::numeric_limits<float>::quiet_NaN();

}  // namespace

TEST_CASE("setters reject bad values, name them, and change nothing") {
  using P = Particle<float>;
  check_rejected<P>([](P& p) { p.set_mass(0); }, {"set_mass", "'mass' = 0", "> 0"});
  check_rejected<P>([](P& p) { p.set_mass(-2.5f); }, {"'mass' = -2.5"});
  check_rejected<P>([](P& p) { p.set_mass(not_a_number); }, {"'mass' = nan"});
  // So small that 1 / mass overflows float: it would be zero mass in disguise.
  check_rejected<P>([](P& p) { p.set_mass(1e-40f); }, {"set_mass", "'mass' = 1e-40"});
  check_rejected<P>([](P& p) { p.set_inverse_mass(-1); },
                    {"set_inverse_mass", "'inverse_mass' = -1", ">= 0"});
  check_rejected<P>([](P& p) { p.set_inverse_mass(not_a_number); }, {"'inverse_mass' = nan"});
  check_rejected<P>([](P& p) { p.set_inverse_mass(infinity); }, {"'inverse_mass' = inf"});
  check_rejected<P>([](P& p) { p.set_damping(1.5f); },
                    {"set_damping", "'damping' = 1.5", "[0, 1]"});
  check_rejected<P>([](P& p) { p.set_damping(-0.25f); }, {"'damping' = -0.25"});
  check_rejected<P>([](P& p) { p.set_damping(not_a_number); }, {"'damping' = nan"});
  check_rejected<P>(
      [](P& p) {
        p.set_position({0, infinity, 0});
      },
      {"set_position", "'position' = (0, inf, 0)", "finite"});
  check_rejected<P>(
      [](P& p) {
        p.set_velocity({not_a_number, 0, 0});
      },
      {"set_velocity", "'velocity'"});
  check_rejected<P>(
      [](P& p) {
        p.set_acceleration({0, 0, -infinity});
      },
      {"set_acceleration", "(0, 0, -inf)"});
}

TEST_CASE("the limits of the ranges are accepted") {
  Particle<float> p;
  p.set_damping(0);
  CHECK(p.damping() == 0);
  p.set_damping(1);
  CHECK(p.damping() == 1);
  p.set_inverse_mass(0);
  CHECK_FALSE(p.has_finite_mass());
  p.set_mass(1e-30f);
  CHECK(p.inverse_mass() == 1 / 1e-30f);
}

TEST_CASE("hot-path checks: integrate's duration and add_force's vector") {
  using P = Particle<double, damping::Exact, position::Exact>;
  for (const double bad :
       {-0.1, -std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
        std::numeric_limits<double>::quiet_NaN()}) {
    CAPTURE(bad);
    check_rejected<P>([bad](P& p) { p.integrate(bad); }, {"integrate", "'duration' = ", ">= 0"});
  }
  check_rejected<P>([](P& p) { p.integrate(-0.1); }, {"'duration' = -0.1"});
  check_rejected<P>(
      [](P& p) {
        p.add_force({1, std::numeric_limits<double>::quiet_NaN(), 0});
      },
      {"add_force", "'force' = (1, nan, 0)"});
}

namespace {
int calls = 0;
std::string last_argument;
long double last_value = 0;
void recording_handler(const ContractViolation& violation) {
  ++calls;
  last_argument = violation.argument;
  last_value = violation.value[0];
}
}  // namespace

TEST_CASE("a user's handler replaces the default, a rejected call still changes nothing") {
  const ContractHandler previous = set_contract_handler(&recording_handler);
  CHECK((previous == &default_contract_handler));
  Particle<float> p;
  set_up(p);
  const Particle<float> before = p;
  calls = 0;
  p.set_mass(-1);  // the handler returns: the setter must not go on
  p.set_damping(2);
  p.integrate(-1);
  CHECK(calls == 3);
  CHECK(last_argument == "duration");
  CHECK(last_value == -1.0L);
  CHECK(same_state(p, before));
  CHECK((set_contract_handler(nullptr) == &recording_handler));  // nullptr restores the default
  CHECK((contract_handler() == &default_contract_handler));
}

TEST_CASE("describe() formats a violation") {
  const ContractViolation v{"set_mass", "mass", "> 0", {-3.5L, 0, 0}, 1, "-3.5"};
  CHECK(describe(v) == "pointmass: set_mass: argument 'mass' = -3.5 must be > 0");
}
