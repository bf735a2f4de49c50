// SPDX-License-Identifier: BSL-1.0
// Position precision (precision.hpp). Each variant — Precision<float, double> and
// Precision<float, Compensated<float>> — against the exactly accumulated trajectory of the
// same float inputs: the displacement an all-float particle computes each step (the position
// policy from p0 = 0, read from a float particle reset to the origin before every step), summed
// in long double (exact: the displacements' bits all lie above long double's ulp at 1e8 m).
// Far from the origin, with and without drag, per-frame and per-second damping, every position
// policy; Particle and ParticleSystem bit for bit; near the origin never worse than all-float;
// render-relative positions exact; the precision pieces checked at compile time.
#include <doctest/doctest.h>

#include <charconv>
#include <cmath>
#include <cstddef>
#include <limits>
#include <optional>
#include <random>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include <pointmass/pointmass.hpp>
#include <pointmass/units.hpp>

#include "ulp.hpp"

namespace pm = pointmass;
using pm::Vector3;

namespace {

using DoublePositions = pm::Precision<float, double>;
using CompensatedPositions = pm::Precision<float, pm::Compensated<float>>;

// --- compile time --------------------------------------------------------------------------

static_assert(pm::PositionPrecision<double, float>);
static_assert(pm::PositionPrecision<float, float>);
static_assert(pm::PositionPrecision<pm::Compensated<float>, float>);
static_assert(!pm::PositionPrecision<float, double>, "narrower positions are refused");
static_assert(!pm::PositionPrecision<pm::Compensated<double>, float>,
              "a pair of another Real is refused");
static_assert(!pm::PositionPrecision<int, float>);
static_assert(pm::PrecisionChoice<float> && pm::PrecisionChoice<DoublePositions> &&
              pm::PrecisionChoice<CompensatedPositions>);
static_assert(!pm::PrecisionChoice<int>);
// Precision<R> is R: today's spellings are today's types.
static_assert(std::is_same_v<pm::Particle<pm::Precision<float>>, pm::Particle<float>>);
static_assert(std::is_same_v<pm::Particle<pm::Precision<double, double>>, pm::Particle<double>>);
static_assert(std::is_same_v<pm::Particle<float>::position_type, float>);
static_assert(std::is_same_v<pm::Particle<DoublePositions>::position_type, double>);
static_assert(std::is_same_v<pm::Particle<CompensatedPositions>::position_type, double>);
static_assert(std::is_same_v<pm::Particle<DoublePositions>::real, float>);
static_assert(
    std::is_same_v<pm::units::Particle<DoublePositions>::position_type, pm::units::length<double>>);
static_assert(
    std::is_same_v<pm::units::Particle<DoublePositions>::length_type, pm::units::length<float>>);
// Bytes per particle: six floats today; three doubles and three floats, or six floats and
// three error floats (36 both: the 36/24).
static_assert(pm::ParticleSystem<float>::storage_bytes_per_particle == 24);
static_assert(pm::ParticleSystem<DoublePositions>::storage_bytes_per_particle == 36);
static_assert(pm::ParticleSystem<CompensatedPositions>::storage_bytes_per_particle == 36);
static_assert(
    pm::detail::SystemAccess::Layout<pm::ParticleSystem<CompensatedPositions>>::array_count == 9);
static_assert(pm::ParticleSystem<CompensatedPositions>::stores<pm::Column::position_error_x>);
static_assert(!pm::ParticleSystem<DoublePositions>::stores<pm::Column::position_error_x>);
static_assert(std::is_same_v<pm::ParticleSystem<DoublePositions>::position_element, double>);
// The particle with Compensated<float> stores 3 floats more than the float one; with double
// positions 3 doubles instead of 3 floats.
static_assert(sizeof(pm::Particle<CompensatedPositions, pm::damping::None>) ==
              sizeof(pm::Particle<float, pm::damping::None>) + 3 * sizeof(float));

// --- the flights ---------------------------------------------------------------------------

using Wide = long double;

Vector3<Wide> widen(const Vector3<double>& v) { return {Wide(v.x), Wide(v.y), Wide(v.z)}; }
Vector3<Wide> widen(const Vector3<float>& v) { return {Wide(v.x), Wide(v.y), Wide(v.z)}; }
double distance(const Vector3<Wide>& a, const Vector3<Wide>& b) {
  const Wide dx = a.x - b.x, dy = a.y - b.y, dz = a.z - b.z;
  return static_cast<double>(std::sqrt(dx * dx + dy * dy + dz * dz));
}
double largest(const Vector3<Wide>& v) {
  return static_cast<double>(std::fmax(std::fabs(v.x), std::fmax(std::fabs(v.y), std::fabs(v.z))));
}
/// The spacing of floats at |x|.
double float_ulp(double x) { return x < 1e-30 ? 1e-45 : std::ldexp(1.0, std::ilogb(x) - 23); }
using pointmass::test::same_bits;

struct Launch {
  Vector3<double> start;
  Vector3<float> velocity;
  Vector3<float> acceleration;
  float damping = 1.0f;
  long steps = 0;
};

struct Result {
  double drift = 0;                 ///< |variant - exact| at the end, m
  double float_drift = 0;           ///< |all-float - exact| at the end, m
  double from_float = 0;            ///< largest |variant - all-float| over the run, m
  double float_rounding = 0;        ///< what all-float's position roundings can add up to, m
  double own_rounding = 0;          ///< what the variant's own roundings can add up to, m
  bool velocities_as_float = true;  ///< the variant's velocity is all-float's, bit for bit
  bool systems_as_particle = true;  ///< both systems' particles are the Particle's, bit for bit
};

template <class P>
void configure(P& particle, const Launch& launch) {
  particle.set_velocity(launch.velocity);
  particle.set_acceleration(launch.acceleration);
  if constexpr (P::stores_damping) particle.set_damping(launch.damping);
}

template <class System, class Particle>
bool system_matches(const System& system, std::size_t i, const Particle& particle) {
  const auto& a = pointmass::detail::SystemAccess::arrays(system);
  const Vector3<typename System::position_element> stored{a.position_x[i], a.position_y[i],
                                                          a.position_z[i]};
  bool same = same_bits(stored, particle.stored_position()) &&
              same_bits(system.velocity(i), particle.velocity());
  if constexpr (System::template stores<pm::Column::position_error_x>) {
    same = same && same_bits(Vector3<float>{a.position_error_x[i], a.position_error_y[i],
                                            a.position_error_z[i]},
                             particle.stored_position_error());
  }
  return same;
}

/// Flies `launch` as the variant S (Particle, a uniform system and a featured one, each of
/// 17 copies so that the vectorised loop and its remainder both run), as all-float, and as the
/// exact sum of the float displacements.
template <class S, class D, class P>
Result fly(const Launch& launch) {
  const float h = 1.0f / 60.0f;
  pm::Particle<S, D, P> variant;
  pm::Particle<float, D, P> plain;
  pm::Particle<float, D, P> mover;  // reset to the origin before each step: its position after
                                    // the step is the float displacement
  variant.set_position(launch.start);
  plain.set_position(Vector3<float>{static_cast<float>(launch.start.x),
                                    static_cast<float>(launch.start.y),
                                    static_cast<float>(launch.start.z)});
  configure(variant, launch);
  configure(plain, launch);
  configure(mover, launch);

  constexpr std::size_t copies = 17;
  pm::ParticleSystem<S, D, P> uniform(copies);
  if constexpr (decltype(uniform)::stores_damping) uniform.set_damping(launch.damping);
  uniform.set_acceleration(launch.acceleration);
  using Featured = std::conditional_t<
      pm::Particle<float, D, P>::stores_damping,
      pm::ParticleSystem<S, D, P, pm::features::PerParticleDamping, pm::features::ForceAccumulator,
                         pm::features::PerParticleAcceleration>,
      pm::ParticleSystem<S, D, P, pm::features::ForceAccumulator,
                         pm::features::PerParticleAcceleration>>;
  Featured featured(copies);
  for (std::size_t k = 0; k < copies; ++k) {
    uniform.spawn(variant);
    featured.spawn(variant);
  }

  Result result;
  Vector3<Wide> exact = widen(launch.start);
  for (long n = 0; n < launch.steps; ++n) {
    mover.set_position({});
    mover.integrate(h);
    const Vector3<float> d = mover.position();
    exact += widen(d);
    variant.integrate(h);
    plain.integrate(h);
    uniform.step(h);
    featured.step(h);

    const Vector3<Wide> p_plain = widen(plain.position());
    const Vector3<Wide> p_variant = widen(variant.position());
    // All-float rounds the position at each addition that involves p0 (two for the forms
    // with an a t^2 term): half an ulp each, per component.
    const int additions = std::is_same_v<P, pm::position::ConstantAcceleration> ||
                                  std::is_same_v<P, pm::position::Exact>
                              ? 2
                              : 1;
    result.float_rounding += std::sqrt(3.0) * additions * float_ulp(largest(p_plain)) / 2;
    // The variant's own: double rounds p0 + d (half a double ulp); the pair rounds d + lo
    // (half a float ulp of |d| + |lo|, |lo| at most half a float ulp of p).
    const double p_size = largest(p_variant);
    const double own = std::is_same_v<S, DoublePositions>
                           ? std::ldexp(p_size, -53)
                           : float_ulp(largest(widen(d)) + float_ulp(p_size)) / 2;
    result.own_rounding += std::sqrt(3.0) * own;
    result.from_float = std::max(result.from_float, distance(p_variant, p_plain));
    result.velocities_as_float = result.velocities_as_float &&
                                 same_bits(variant.velocity(), plain.velocity()) &&
                                 same_bits(variant.velocity(), mover.velocity());
    if (n % 4096 == 0 || n + 1 == launch.steps) {
      for (std::size_t k : {std::size_t{0}, copies - 1}) {
        result.systems_as_particle = result.systems_as_particle &&
                                     system_matches(uniform, k, variant) &&
                                     system_matches(featured, k, variant);
      }
    }
  }
  result.drift = distance(widen(variant.position()), exact);
  result.float_drift = distance(widen(plain.position()), exact);
  return result;
}

constexpr double millimetre = 1e-3;

// The free flight of docs/accuracy.md, the artillery shot (gravity, per-second drag), sparks
// (per-frame drag): 10^6 steps of 1/60 s (4.6 hours) from 1e6 m, or at 1e8 m.
Launch free_flight(double from) { return {{from, 0, 0}, {10, 0, 5}, {0, 0, 0}, 1.0f, 1'000'000}; }
Launch artillery(double from) {
  return {{from, 0, from / 4}, {300, 400, 0}, {0, -9.81f, 0}, 0.9f, 1'000'000};
}
Launch sparks(double from) { return {{0, from, 0}, {3, 8, -2}, {0, -9.81f, 0}, 0.995f, 1'000'000}; }

/// At 1e6 m both variants hold the target, 1 mm. At 1e8 m double positions still do;
/// a float pair resolves 2^-48 of the position (0.4 um at 1e8 m), and its roundings of
/// d + lo, which a steady flight repeats with a bias, add up to centimetres over 10^6 steps
/// (docs/large-worlds.md): there it is held to what those roundings allow.
template <class S, class D, class P>
void check_far(const Launch& launch) {
  const Result r = fly<S, D, P>(launch);
  MESSAGE("drift ", r.drift, " m (all-float ", r.float_drift, " m; own rounding bound ",
          r.own_rounding, " m)");
  const bool planet = largest(widen(launch.start)) > 1e7;
  if (!planet || std::is_same_v<S, DoublePositions>) CHECK(r.drift <= millimetre);
  CHECK(r.drift <= r.own_rounding);  // what the variant's own roundings allow
  CHECK(r.velocities_as_float);
  CHECK(r.systems_as_particle);
}

}  // namespace

TEST_CASE_TEMPLATE("far from the origin: within 1 mm of the exact sum of the float steps", S,
                   DoublePositions, CompensatedPositions) {
  namespace d = pm::damping;
  namespace p = pm::position;
  SUBCASE("free flight from 1e6 m, no drag") { check_far<S, d::None, p::Euler>(free_flight(1e6)); }
  SUBCASE("free flight from 1e8 m, no drag") {
    check_far<S, d::None, p::ConstantAcceleration>(free_flight(1e8));
  }
  SUBCASE("artillery from 1e6 m, per-second drag (Exact, Exact)") {
    check_far<S, d::Exact, p::Exact>(artillery(1e6));
  }
  SUBCASE("artillery from 1e8 m, per-second drag (PerSecond, Euler)") {
    check_far<S, d::PerSecond, p::Euler>(artillery(1e8));
  }
  SUBCASE("sparks from 1e6 m, per-frame drag (PerFrame, ConstantAcceleration)") {
    check_far<S, d::PerFrame, p::ConstantAcceleration>(sparks(1e6));
  }
  SUBCASE("artillery from 1e6 m, Cyclone's drag (AccelerateThenDamp, SemiImplicit)") {
    check_far<S, d::AccelerateThenDamp, p::SemiImplicit>(artillery(1e6));
  }
}

TEST_CASE("far from the origin: all-float drifts by kilometres on the same flight") {
  // What the variants are for: the same run in all-float (docs/accuracy.md's 25 km).
  const Result r = fly<DoublePositions, pm::damping::None, pm::position::Euler>(free_flight(1e6));
  MESSAGE("all-float drift ", r.float_drift, " m");
  CHECK(r.float_drift > 1000.0);
  CHECK(r.drift < r.float_drift * 1e-6);
}

TEST_CASE_TEMPLATE("near the origin: never worse than all-float beyond its position rounding", S,
                   DoublePositions, CompensatedPositions) {
  namespace d = pm::damping;
  namespace p = pm::position;
  const auto check_near = []<class D, class P>(const Launch& launch) {
    const Result r = fly<S, D, P>(launch);
    MESSAGE("from all-float ", r.from_float, " m (its rounding ", r.float_rounding, " m); drift ",
            r.drift, " m against all-float's ", r.float_drift, " m");
    CHECK(r.velocities_as_float);
    CHECK(r.systems_as_particle);
    // The variant and all-float differ by all-float's rounding of the positions (and the
    // variant's own, far smaller).
    CHECK(r.from_float <= r.float_rounding + r.own_rounding);
    // Never worse against the exact sum than all-float, beyond the variant's own rounding.
    CHECK(r.drift <= r.float_drift + r.own_rounding);
  };
  // A ten-second shot from the origin (600 steps), and 10^4 steps of sparks near it.
  const Launch shot{{0, 0, 0}, {30, 40, 0}, {0, -9.81f, 0}, 0.9f, 600};
  const Launch near_sparks{{0.5, 1.0, -0.25}, {3, 8, -2}, {0, -9.81f, 0}, 0.995f, 10'000};
  check_near.template operator()<d::Exact, p::Exact>(shot);
  check_near.template operator()<d::PerSecond, p::Euler>(shot);
  check_near.template operator()<d::None, p::ConstantAcceleration>(shot);
  check_near.template operator()<d::PerFrame, p::SemiImplicit>(near_sparks);
}

// --- the pair's step: Fast2Sum -------------------------------------------------------------

// What one step does to a (hi, lo) pair, against double arithmetic, which holds every sum here
// exactly (float operands within 2^28 of each other in magnitude): where hi's exponent is at
// least y's (y = d + lo, the step's displacement with the carried error) the new pair is
// exactly hi + y; elsewhere (a particle within one step of the origin on that axis) it is
// within one float ulp of y of it. The pairs are drawn over many binades each way.
TEST_CASE("Fast2Sum: exact where hi's exponent is at least y's, within an ulp of y elsewhere") {
  using Pair = pm::detail::PositionStorage<pm::Compensated<float>>;
  std::mt19937_64 random(2024);
  std::uniform_real_distribution<double> exponent(-10.0, 17.0);
  std::uniform_real_distribution<double> fraction(-0.5, 0.5);
  std::uniform_int_distribution<int> sign(0, 1);
  const auto draw = [&] {
    return static_cast<float>((sign(random) != 0 ? -1.0 : 1.0) * std::exp2(exponent(random)));
  };
  long exact_cases = 0;
  long near_cases = 0;
  double worst_near = 0;  // the largest loss, in ulps of y
  for (int k = 0; k < 200000; ++k) {
    float hi = draw();
    const float d = draw();
    // The carried error: at most half a float ulp of hi, as add leaves it.
    float lo = static_cast<float>(float_ulp(std::fabs(static_cast<double>(hi))) * fraction(random));
    const float y = d + lo;  // what add computes first, rounded as it rounds it
    const double before = static_cast<double>(hi) + static_cast<double>(y);
    const bool exact = hi == 0.0f || std::ilogb(hi) >= std::ilogb(y);
    Pair::add(hi, lo, d);
    const double after = static_cast<double>(hi) + static_cast<double>(lo);
    if (exact) {
      ++exact_cases;
      if (after != before) {
        FAIL_CHECK("not exact: the pair misses hi + y = ", before, " by ", after - before);
        break;
      }
    } else {
      ++near_cases;
      const double loss = std::fabs(after - before) / float_ulp(std::fabs(static_cast<double>(y)));
      worst_near = std::max(worst_near, loss);
    }
  }
  MESSAGE(exact_cases, " exact cases, ", near_cases, " nearer the origin, worst loss there ",
          worst_near, " ulp of y");
  CHECK(exact_cases > 50000);
  CHECK(near_cases > 50000);
  CHECK(worst_near <= 1.0);
}

// The displacement is the policy's p0 + x from p0 = -0, which is x to the last bit: a step that
// moves nothing leaves a position of -0 at -0, as all-float's p0 + v0 t does (from p0 = +0 the
// displacement of a velocity of -0 would come out +0, and -0 + +0 is +0). A compensated -0 is
// hi = -0 and lo = -0 (with lo = +0, hi + lo would read +0).
TEST_CASE_TEMPLATE(
    "wide positions: a step of zero displacement keeps the sign of zero, as "
    "all-float's",
    S, DoublePositions, CompensatedPositions) {
  const Vector3<float> minus_zero{-0.0f, -0.0f, -0.0f};
  pm::Particle<float> plain;
  plain.set_position(minus_zero);
  plain.set_velocity(minus_zero);
  pm::Particle<S> wide;
  wide.set_position({-0.0, -0.0, -0.0});
  wide.set_velocity(minus_zero);
  pm::ParticleSystem<S> system(1);
  system.spawn({-0.0, -0.0, -0.0}, minus_zero);
  plain.integrate(1.0f / 60);
  wide.integrate(1.0f / 60);
  system.step(1.0f / 60);
  REQUIRE(std::signbit(plain.position().x));  // what all-float does
  CHECK(std::signbit(wide.position().x));
  CHECK(std::signbit(wide.position().y));
  CHECK(std::signbit(wide.position().z));
  CHECK(std::signbit(system.position(0).x));
  CHECK(system_matches(system, 0, wide));
}

TEST_CASE("compensated positions: a zero set keeps its sign, and so does position() set back") {
  pm::Particle<CompensatedPositions> particle;
  particle.set_position({-0.0, 0.0, -0.0});
  CHECK(std::signbit(particle.position().x));
  CHECK(!std::signbit(particle.position().y));
  CHECK(std::signbit(particle.stored_position_error().x));
  particle.set_position(particle.position());
  CHECK(std::signbit(particle.position().x));
  CHECK(!std::signbit(particle.position().y));
  pm::ParticleSystem<CompensatedPositions> system(1);
  system.spawn({1.0, 2.0, -0.0}, {});
  CHECK(std::signbit(system.position(0).z));
  system.set_position(0, system.position(0));
  CHECK(std::signbit(system.position(0).z));
  system.set_position(0, particle.position());
  CHECK(system_matches(system, 0, particle));
}

// --- render-relative positions --------------------------------------------------------------

TEST_CASE("render-relative: double positions, exact wherever the true offset is a float") {
  std::mt19937_64 random(16);
  std::uniform_real_distribution<double> far(-1e8, 1e8);
  std::uniform_real_distribution<float> offset(-5000.0f, 5000.0f);
  pm::Particle<DoublePositions> particle;
  pm::ParticleSystem<DoublePositions> system(64);
  std::vector<Vector3<double>> origins;
  std::vector<Vector3<float>> offsets;
  int checked = 0;
  for (int n = 0; n < 64; ++n) {
    const Vector3<double> p{far(random), far(random), far(random)};
    const Vector3<float> t{offset(random), offset(random), offset(random)};
    const Vector3<double> o{p.x - double(t.x), p.y - double(t.y), p.z - double(t.z)};
    // Keep the cases where the camera is a double exactly p - t away.
    if (Wide(o.x) != Wide(p.x) - Wide(t.x) || Wide(o.y) != Wide(p.y) - Wide(t.y) ||
        Wide(o.z) != Wide(p.z) - Wide(t.z)) {
      continue;
    }
    particle.set_position(p);
    CHECK(same_bits(particle.position_relative_to(o), t));
    system.spawn(p, {});
    origins.push_back(o);
    offsets.push_back(t);
    ++checked;
  }
  CHECK(checked > 32);
  for (std::size_t i = 0; i < system.size(); ++i) {
    CHECK(same_bits(system.position_relative_to(i, origins[i]), offsets[i]));
  }
}

TEST_CASE(
    "render-relative: compensated positions, from hi + lo, exact wherever the offset is a float") {
  // Particles that have flown (so lo carries real error terms), cameras at hi + lo - t for
  // random float offsets t (kept where that is a double).
  std::mt19937_64 random(15);
  std::uniform_real_distribution<float> speed(-300.0f, 300.0f);
  std::uniform_real_distribution<float> offset(-2000.0f, 2000.0f);
  pm::ParticleSystem<CompensatedPositions, pm::damping::None> system(40);
  for (int n = 0; n < 40; ++n) {
    system.spawn({1e6 * (n + 1), -3e7 + 1e5 * n, 12345.678 * n},
                 {speed(random), speed(random), speed(random)});
  }
  for (int k = 0; k < 1000; ++k) system.step(1.0f / 60.0f);

  std::vector<Vector3<float>> buffer(system.size());
  int checked = 0;
  int with_error_term = 0;
  for (int round = 0; round < 20; ++round) {
    const Vector3<float> t{offset(random), offset(random), offset(random)};
    const auto& a = pointmass::detail::SystemAccess::arrays(system);
    // One camera for the whole system, placed for particle j; every other particle's offset is
    // checked against the exact offset rounded once to float.
    const std::size_t j = static_cast<std::size_t>(round) % system.size();
    const Vector3<Wide> true_position{Wide(a.position_x[j]) + Wide(a.position_error_x[j]),
                                      Wide(a.position_y[j]) + Wide(a.position_error_y[j]),
                                      Wide(a.position_z[j]) + Wide(a.position_error_z[j])};
    const Vector3<Wide> wanted{true_position.x - Wide(t.x), true_position.y - Wide(t.y),
                               true_position.z - Wide(t.z)};
    const Vector3<double> camera{double(wanted.x), double(wanted.y), double(wanted.z)};
    if (Wide(camera.x) != wanted.x || Wide(camera.y) != wanted.y || Wide(camera.z) != wanted.z) {
      continue;
    }
    with_error_term += a.position_error_x[j] != 0.0f;
    system.copy_positions(buffer, camera);
    CHECK(same_bits(buffer[j], t));
    CHECK(same_bits(system.position_relative_to(j, camera), t));
    for (std::size_t i = 0; i < system.size(); ++i) {
      const Vector3<float> rounded{
          static_cast<float>(Wide(a.position_x[i]) + Wide(a.position_error_x[i]) - Wide(camera.x)),
          static_cast<float>(Wide(a.position_y[i]) + Wide(a.position_error_y[i]) - Wide(camera.y)),
          static_cast<float>(Wide(a.position_z[i]) + Wide(a.position_error_z[i]) - Wide(camera.z))};
      // The exact offset (hi + lo - camera: its bits span fewer than long double's 64)
      // rounded once to float.
      CHECK(same_bits(buffer[i], rounded));
    }
    ++checked;
  }
  CHECK(checked >= 10);
  CHECK(with_error_term > 0);
}

TEST_CASE(
    "render-relative: rounded once, also where the offset rounded to double is a float "
    "midpoint") {
  // 1 + 2^-24 (a float midpoint) from a camera at -2^-80: the offset 1 + 2^-24 + 2^-80 lies
  // above the midpoint and rounds to 1 + 2^-23; rounded to double first it is the midpoint,
  // which then rounds to even, 1.
  const double midpoint = 1.0 + 0x1p-24;
  const Vector3<double> camera{-0x1p-80, 0x1p-80, 0};
  const Vector3<float> wanted{1.0f + 0x1p-23f, 1.0f, 0};
  const auto check = [&]<class S>() {  // a particle and a system of each wide precision
    pm::Particle<S> particle;
    particle.set_position({midpoint, midpoint, 0});
    CHECK(same_bits(particle.position_relative_to(camera), wanted));
    pm::ParticleSystem<S> system(1);
    system.spawn(Vector3<double>{midpoint, midpoint, 0}, {});
    CHECK(same_bits(system.position_relative_to(0, camera), wanted));
  };
  check.template operator()<DoublePositions>();
  check.template operator()<CompensatedPositions>();
}

TEST_CASE("render-relative: rounded once at the edge of the range too") {
  // Halfway between the largest float and 2^128 is M = 2^128 - 2^103, a double; an offset a
  // little short of it (the camera at +1e-30) is below the midpoint and rounds to the largest
  // float, where M alone rounds to even, infinity.
  const double M = 0x1p128 - 0x1p103;
  pm::Particle<DoublePositions> far;
  far.set_position({M, -M, 0});
  const Vector3<float> offset = far.position_relative_to({1e-30, -1e-30, 0});
  CHECK(offset.x == std::numeric_limits<float>::max());
  CHECK(offset.y == -std::numeric_limits<float>::max());
  pm::ParticleSystem<DoublePositions> system(1);
  system.spawn(far);
  Vector3<float> batch[1];  // the branch-free rounding of copy_positions(out, origin)
  system.copy_positions(batch, {1e-30, -1e-30, 0});
  CHECK(batch[0].x == std::numeric_limits<float>::max());
  CHECK(batch[0].y == -std::numeric_limits<float>::max());
  // The same for double from long double, where long double is wider.
  if constexpr (std::numeric_limits<long double>::digits > std::numeric_limits<double>::digits) {
    // (ldexp, not the literal 0x1p1024L: a long double that is double would warn at it)
    const long double Md = std::ldexp(1.0L, 1024) - std::ldexp(1.0L, 970);
    CHECK(pm::detail::PositionStorage<long double>::relative<double>(Md, 1e-300L) ==
          std::numeric_limits<double>::max());
  }
}

TEST_CASE("round_via_odd: round_once's float, branch-free, for every kind of double offset") {
  // copy_positions(out, origin) rounds each offset z + r (z the double nearest, r of the sign of
  // what z dropped) to float by way of rounding to odd; round_once (checked against long
  // double below) does it with branches. They must agree bit for bit on float midpoints
  // from either side, exact values, offsets in float's subnormal range and beyond its
  // largest value, zero, and an infinite z.
  using pm::detail::round_once;
  using pm::detail::round_via_odd;
  std::mt19937_64 random(97);
  std::uniform_int_distribution<int> exponent(-160, 130);
  std::uniform_real_distribution<double> unit(1, 2);
  std::uniform_int_distribution<int> kind(0, 3);
  const double tiny_r[] = {0.0, -0.0, 1e-300, -1e-300};
  int midpoints_inexact = 0;  // a float midpoint z with r nonzero: where rounding z alone errs
  int r_decides = 0;          // round_once's float is not z's own: the error term r decides
  const auto compare = [&](double z, double r) {
    const float odd = round_via_odd<float>(z, r);
    const float once = round_once<float>(z, r);
    if (!same_bits(odd, once)) {
      INFO("z = ", z, " (", std::hexfloat, z, "), r = ", r, std::defaultfloat);
      CHECK(same_bits(odd, once));
    }
  };
  for (int n = 0; n < 200000; ++n) {
    const double sign = n % 2 == 0 ? 1 : -1;
    double z = sign * std::ldexp(unit(random), exponent(random));
    switch (kind(random)) {
      case 0: {  // a float midpoint: halfway between z rounded to float and its neighbour
        const float f = static_cast<float>(z);
        if (!std::isfinite(f) || f == 0) break;
        z = (double(f) + double(std::nextafter(f, 2 * f))) / 2;
        break;
      }
      case 1: z = double(static_cast<float>(z)); break;  // a float
      case 2: z = std::nextafter(z, 0.0); break;         // an even or odd last bit
      default: break;
    }
    // r: zero, or below half an ulp of z either way (what a TwoSum's error can be).
    const double half_ulp = (std::nextafter(std::fabs(z), 1e308) - std::fabs(z)) / 2;
    const double r =
        n % 5 == 0 ? tiny_r[n % 4] : (n % 3 == 0 ? -1 : 1) * half_ulp * unit(random) / 2;
    const float f = static_cast<float>(z);
    const float toward_z = std::nextafter(f, z > double(f) ? 1e30f : -1e30f);
    midpoints_inexact += r != 0 && std::isfinite(f) && double(f) != z &&
                         std::fabs(z - double(f)) * 2 == std::fabs(double(toward_z) - double(f));
    r_decides += !same_bits(round_once<float>(z, r), static_cast<float>(z));
    compare(z, r);
  }
  // The edges: zero with an error term either way, the largest float's midpoint with
  // 2^128, the smallest subnormal float's halfway point, an infinite z with a NaN error.
  const double big = 0x1p128 - 0x1p103;
  for (const double z : {0.0, -0.0, big, -big, 0x1p-150, -0x1p-150, 0x1p-149 * 1.5}) {
    for (const double r : {0.0, -0.0, 1e-320, -1e-320, 1e-60, -1e-60}) compare(z, r);
  }
  const double inf = std::numeric_limits<double>::infinity();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  compare(inf, nan);
  compare(-inf, nan);
  CHECK(midpoints_inexact > 10000);
  CHECK(r_decides > 10000);
}

TEST_CASE_TEMPLATE("render-relative: the exact offset rounded once to float, against long double",
                   S, DoublePositions, CompensatedPositions) {
  // Positions p and cameras o within a factor of 2^8 of each other (so p - o is exact in long
  // double's 64 bits), o placed so that p - o lies within a double's ulp of a float midpoint:
  // there a difference rounded to double and then to float is rounded twice.
  std::mt19937_64 random(23);
  std::uniform_int_distribution<int> exponent(-30, 30);
  std::uniform_real_distribution<double> unit(1, 2);
  std::uniform_real_distribution<double> ratio(1.0 / 256, 0.5);
  pm::Particle<S> particle;
  pm::ParticleSystem<S> system(1);
  system.spawn(Vector3<double>{}, {});
  int checked = 0;
  int twice_differs = 0;  // cases where rounding the double difference would be wrong
  for (int n = 0; n < 20000; ++n) {
    // A float midpoint m, the camera o beside it, and p = m + o rounded (to double, then to
    // what S stores): p - o is m plus what p rounded.
    const float f = static_cast<float>(std::ldexp(unit(random), exponent(random)));
    const double m = double(f) + double(std::nextafter(f, 2 * f) - f) / 2;
    const double o = (n % 2 == 0 ? 1 : -1) * m * ratio(random);
    particle.set_position({m + o, -(m + o), 0});
    const double p = particle.position().x;
    if (p == 0 || -particle.position().y != p) continue;
    const Wide exact = Wide(p) - Wide(o);
    if (Wide(o) != Wide(p) - exact) continue;  // not exact after all
    const float oracle = static_cast<float>(exact);
    twice_differs += static_cast<float>(p - o) != oracle;
    const Vector3<double> camera{o, -o, 0};
    const Vector3<float> got = particle.position_relative_to(camera);
    system.set_position(0, particle.position());
    Vector3<float>
        batch[1];  // copy_positions(out, origin): the branch-free rounding (round_via_odd)
    system.copy_positions(batch, camera);
    if (!same_bits(got, Vector3<float>{oracle, -oracle, 0}) ||
        !same_bits(system.position_relative_to(0, camera), got) || !same_bits(batch[0], got)) {
      INFO("p = ", p, ", o = ", o);
      CHECK(same_bits(got, Vector3<float>{oracle, -oracle, 0}));
      CHECK(same_bits(system.position_relative_to(0, camera), got));
      CHECK(same_bits(batch[0], got));
    }
    ++checked;
  }
  // Where long double is double itself (32-bit ARM), p - o is exact in it only where it is a
  // double, so that no difference is rounded twice: the cases it can check, it checks.
  if constexpr (std::numeric_limits<Wide>::digits > std::numeric_limits<double>::digits) {
    CHECK(checked > 10000);
    CHECK(twice_differs > 100);
  }
}

TEST_CASE("render-relative: compensated pairs whose hi + lo is no double, at a float midpoint") {
  // relative() takes a shorter road where hi + lo is a double. A double holds 29 bits below
  // hi's last bit; here lo's top bit lies 7 to 16 bits below it, so its last bits do not fit,
  // or 31 to 39, so none does (many steps can leave such an error term), and the full road
  // must be taken. The camera is placed so that hi - camera is
  // a float midpoint m, and the offset m + lo must round to m's neighbour on lo's side: the
  // road for double sums would round hi + lo to double first and, where that drops lo (30 to
  // 38 bits down), land on m itself and round to even.
  using Pair = pm::detail::PositionStorage<pm::Compensated<float>>;
  std::mt19937_64 random(61);
  std::uniform_int_distribution<int> exponent(-20, 30);
  std::uniform_int_distribution<int> small_gap(6, 15);
  std::uniform_int_distribution<int> large_gap(30, 38);
  std::uniform_real_distribution<double> unit(1, 2);
  std::uniform_real_distribution<double> ratio(0.25, 0.5);
  int checked = 0;
  int dropped_by_double = 0;  // lo below half a double ulp of hi: hi + lo rounds to hi
  for (int n = 0; n < 20000; ++n) {
    const int e = exponent(random);
    const double sign = n % 2 == 0 ? 1 : -1;
    const float hi = static_cast<float>(sign * std::ldexp(unit(random), e));
    const int gap = n % 4 < 2 ? small_gap(random) : large_gap(random);
    const float lo =
        static_cast<float>(std::ldexp(unit(random) * (n % 3 == 0 ? -1 : 1), e - 24 - gap));
    // m: halfway between two floats, below and above, a quarter to a half of hi.
    const float below = static_cast<float>(double(hi) * ratio(random));
    const float above = std::nextafter(below, std::copysign(1e30f, below));
    const double m = (double(below) + double(above)) / 2;
    const double origin = double(hi) - m;
    if (double(hi) - origin != m) continue;  // not exact after all
    const float wanted = (lo > 0) == (above > below) ? above : below;
    dropped_by_double += double(hi) + double(lo) == double(hi);
    const float got = Pair::relative<float>(hi, lo, origin);
    const float branch_free = Pair::relative<float, true>(hi, lo, origin);
    if (!same_bits(got, wanted) || !same_bits(branch_free, wanted)) {
      INFO("hi = ", hi, ", lo = ", lo, ", origin = ", origin);
      CHECK(same_bits(got, wanted));
      CHECK(same_bits(branch_free, wanted));
    }
    ++checked;
  }
  CHECK(checked > 15000);
  CHECK(dropped_by_double > 5000);
}

TEST_CASE("render-relative: a particle and the system agree, and a short buffer writes nothing") {
  pm::Particle<CompensatedPositions, pm::damping::None> particle;
  particle.set_position({4.0e7, 1.0, -2.5e6});
  particle.set_velocity({250.0f, -30.0f, 17.0f});
  pm::ParticleSystem<CompensatedPositions, pm::damping::None> system(4);
  system.spawn(particle);
  system.spawn(particle);
  for (int k = 0; k < 5000; ++k) {
    particle.integrate(1.0f / 60.0f);
    system.step(1.0f / 60.0f);
  }
  const Vector3<double> camera{4.0e7 + 20000.0, 0.0, -2.5e6};
  std::vector<Vector3<float>> buffer(2);
  system.copy_positions(buffer, camera);
  CHECK(same_bits(buffer[0], particle.position_relative_to(camera)));
  CHECK(same_bits(buffer[1], particle.position_relative_to(camera)));

  std::vector<Vector3<float>> short_buffer(1, Vector3<float>{7.0f, 7.0f, 7.0f});
  CHECK_THROWS_WITH_AS(system.copy_positions(short_buffer, camera),
                       doctest::Contains("copy_positions: argument 'out'"), std::invalid_argument);
  CHECK(same_bits(short_buffer[0], Vector3<float>{7.0f, 7.0f, 7.0f}));
}

// A zero offset's sign is IEEE's p - origin (-0 - +0 is -0, every other zero difference +0) on
// every road: the batch's branch-free one (which once gave +0 for a compensated -0, hi = lo =
// -0, from a +0 origin), the one-particle one and the particle's.
TEST_CASE_TEMPLATE("render-relative: a zero offset has IEEE's sign of zero on every road", S,
                   DoublePositions, CompensatedPositions) {
  const double values[] = {-0.0, 0.0, -3.0};
  for (const double p : values) {
    for (const double o : values) {
      CAPTURE(p);
      CAPTURE(o);
      pm::Particle<S> particle;
      particle.set_position({p, p, p});
      pm::ParticleSystem<S> system(1);
      system.spawn(particle);
      const Vector3<double> origin{o, o, o};
      const auto wanted = static_cast<float>(p - o);
      const Vector3<float> expected{wanted, wanted, wanted};
      Vector3<float> batch[1];
      system.copy_positions(batch, origin);
      CHECK(same_bits(batch[0], expected));
      CHECK(same_bits(system.position_relative_to(0, origin), expected));
      CHECK(same_bits(particle.position_relative_to(origin), expected));
    }
  }
}

// The origin is the one of the call, even where it is read from the buffer being written (a
// float system's origin and offsets are both Vector3<float>): particle 1 is not measured from
// the offset just written for particle 0.
TEST_CASE("render-relative: an origin read from the buffer being written is the call's origin") {
  pm::ParticleSystem<float> system(3);
  system.spawn({1.0f, 2.0f, 3.0f}, {});
  system.spawn({4.0f, 5.0f, 6.0f}, {});
  system.spawn({7.0f, 8.0f, 9.0f}, {});
  std::vector<Vector3<float>> buffer(3, Vector3<float>{1.0f, 1.0f, 1.0f});
  system.copy_positions(buffer, buffer[0]);
  CHECK(same_bits(buffer[0], Vector3<float>{0.0f, 1.0f, 2.0f}));
  CHECK(same_bits(buffer[1], Vector3<float>{3.0f, 4.0f, 5.0f}));
  CHECK(same_bits(buffer[2], Vector3<float>{6.0f, 7.0f, 8.0f}));
}

TEST_CASE(
    "spawn(particle) copies a compensated position's error term: the system goes on bit for bit") {
  pm::Particle<CompensatedPositions, pm::damping::PerSecond, pm::position::ConstantAcceleration>
      particle;
  particle.set_position({3.0e6, -1.0e6, 5.0e5});
  particle.set_velocity({123.0f, 45.0f, -67.0f});
  particle.set_acceleration(pm::gravity<float>());
  particle.set_damping(0.8f);
  for (int k = 0; k < 1000; ++k) particle.integrate(1.0f / 60.0f);
  REQUIRE(particle.stored_position_error().x != 0.0f);  // lo carries something by now
  pm::ParticleSystem<CompensatedPositions, pm::damping::PerSecond,
                     pm::position::ConstantAcceleration>
      system(1);
  system.set_acceleration(pm::gravity<float>());
  system.set_damping(0.8f);
  system.spawn(particle);
  for (int k = 0; k < 1000; ++k) {
    particle.integrate(1.0f / 60.0f);
    system.step(1.0f / 60.0f);
  }
  CHECK(system_matches(system, 0, particle));
}

TEST_CASE("copy_positions of compensated positions: hi + lo, rounded once to the buffer's type") {
  // 1e6 + 0.01 m: float keeps 1e6, lo the 0.01. A double buffer gets the whole position, as
  // position(i) gives it; a float buffer hi + lo rounded once (here 1e6). Before, every
  // buffer got hi alone.
  pm::ParticleSystem<CompensatedPositions> system(2);
  system.spawn({1.0e6 + 0.01, -3.0e7 - 0.5, 0.25}, {});
  system.spawn({-1.0e6 - 0.01, 7.0, 4.0e6 + 0.125}, {});
  REQUIRE(system.column<pm::Column::position_error_x>()[0] != 0.0f);
  std::vector<double> packed(6, -1.0);
  system.copy_positions(std::span<double>(packed));
  struct DoubleVertex {
    double x, y, z;
  };
  std::vector<DoubleVertex> vertices(2);
  system.copy_positions(std::span<DoubleVertex>(vertices));
  std::vector<float> floats(6, -1.0f);
  system.copy_positions(std::span<float>(floats));
  for (std::size_t i = 0; i < 2; ++i) {
    const Vector3<double> p = system.position(i);
    CAPTURE(i);
    CHECK(same_bits(Vector3<double>{packed[3 * i], packed[3 * i + 1], packed[3 * i + 2]}, p));
    CHECK(same_bits(Vector3<double>{vertices[i].x, vertices[i].y, vertices[i].z}, p));
    CHECK(same_bits(Vector3<float>{floats[3 * i], floats[3 * i + 1], floats[3 * i + 2]},
                    Vector3<float>{float(p.x), float(p.y), float(p.z)}));
  }
  CHECK(packed[0] != 1.0e6);  // the error term is in it
}

TEST_CASE("render-relative into a type wider than the stored position: rounded once, in it") {
  // float positions, a double offset: 2^25 - 1 is a double, not a float; rounded to float
  // first it came out 2^25.
  pm::ParticleSystem<float> system(1);
  system.spawn({33554432.0f, 0.0f, -0.0f}, {});
  CHECK(system.position_relative_to<double>(0, {1.0f, 0.0f, 0.0f}).x == 33554431.0);
  pm::Particle<float> particle;
  particle.set_position({33554432.0f, 0.0f, 0.0f});
  CHECK(particle.position_relative_to<double>({1.0f, 0.0f, 0.0f}).x == 33554431.0);
  if constexpr (std::numeric_limits<long double>::digits > std::numeric_limits<double>::digits) {
    // double positions, a long double offset: 2^60 - 1.
    pm::Particle<DoublePositions> wide;
    wide.set_position({1152921504606846976.0, 0.0, 0.0});
    CHECK(wide.position_relative_to<long double>({1.0, 0.0, 0.0}).x == 1152921504606846975.0L);
    // compensated float positions read as double, a long double offset: 2^60 - 1 too.
    pm::Particle<CompensatedPositions> pair;
    pair.set_position({1152921504606846976.0, 0.0, 0.0});
    CHECK(pair.position_relative_to<long double>({1.0, 0.0, 0.0}).x == 1152921504606846975.0L);
  }
}

TEST_CASE(
    "features::Handles: the handle slot column is read-only (the table indexes itself with it)") {
  using System =
      pm::ParticleSystem<float, pm::damping::PerSecond, pm::position::Euler, pm::features::Handles>;
  System system(1);
  system.spawn({}, {});
  using Span = decltype(system.column<pm::Column::handle_slot>());
  static_assert(std::is_const_v<typename Span::element_type>);
  CHECK(system.column<pm::Column::handle_slot>().size() == 1);
}

// --- the game features with wide positions -----------------------------------------------------

struct OwnerTag {};

TEST_CASE_TEMPLATE(
    "game features with wide positions: previous positions, interpolation, user columns, handles",
    S, DoublePositions, CompensatedPositions) {
  using System = pm::ParticleSystem<S, pm::damping::PerSecond, pm::position::Euler,
                                    pm::features::Interpolation, pm::features::Handles,
                                    pm::features::Column<OwnerTag, int>>;
  using E = typename System::position_element;
  System system(4);
  system.set_acceleration(pm::gravity<float>());
  system.set_damping(0.9f);
  const double far = 1.0e6 + 0.25;  // the quarter is lo for the pair, and exact in double
  const std::size_t a = system.spawn({far, 2.0, -far}, {10.0f, 0.0f, 5.0f}, 7);
  const std::size_t b = system.spawn({-far, 0.0, 3.0}, {0.0f, 1.0f, 0.0f}, 8);
  const auto handle_b = system.handle(b);
  // Spawned: the previous position is the stored position column, whole.
  CHECK(system.previous_position(a).x ==
        system.template column<pointmass::Column::position_x>()[a]);
  CHECK(system.previous_position(a).z ==
        system.template column<pointmass::Column::position_z>()[a]);

  std::vector<E> before_x(system.template column<pointmass::Column::position_x>().begin(),
                          system.template column<pointmass::Column::position_x>().end());
  system.step(1.0f / 60.0f);
  for (std::size_t i = 0; i < system.size(); ++i) {
    CHECK(system.previous_position(i).x == before_x[i]);  // kept by the step, bit for bit
    CHECK(system.interpolated_position(i, 0.0f).x == before_x[i]);
    CHECK(system.interpolated_position(i, 1.0f).x ==
          system.template column<pointmass::Column::position_x>()[i]);
  }
  // Halfway lies between, in the column's own precision.
  const E middle = system.interpolated_position(a, 0.5f).x;
  CHECK(middle > before_x[a]);
  CHECK(middle < system.template column<pointmass::Column::position_x>()[a]);
  if constexpr (std::is_same_v<E, double>) {
    // The midpoint rounded once, bit for bit: before and after lie within a factor 2 of each
    // other (1e6 m, 0.17 m apart), so after - before is exact (Sterbenz), and so is its half;
    // before + half then rounds once, to the double nearest (before + after) / 2. Long
    // double holds that sum exactly (54 bits: 2^20 down to the ulp at 1e6 m, 2^-33 m), so its
    // half rounded to double is the same double. A tolerance would be 0 ulp: nothing to allow.
    const double after = system.template column<pointmass::Column::position_x>()[a];
    CHECK(same_bits(middle, before_x[a] + (after - before_x[a]) * 0.5));
    if constexpr (std::numeric_limits<Wide>::digits > std::numeric_limits<double>::digits) {
      CHECK(same_bits(middle, static_cast<double>((Wide(before_x[a]) + Wide(after)) / 2)));
    }
  }

  // A swap-remove carries the wide position (and, for the pair, its error term), the user
  // column and the handle together.
  const auto position_b = system.position(b);
  system.kill(a);
  const std::optional<std::size_t> moved = system.find(handle_b);
  REQUIRE(moved.has_value());
  CHECK(system.template column<OwnerTag>(*moved) == 8);
  CHECK(system.position(*moved).x == position_b.x);
  CHECK(system.position(*moved).z == position_b.z);

  // set_position is a jump: the previous position follows it.
  system.set_position(*moved, {far, far, far});
  CHECK(system.position(*moved).x == far);
  CHECK(system.previous_position(*moved).y ==
        system.template column<pointmass::Column::position_y>()[*moved]);
}

// --- setting positions -------------------------------------------------------------------------

TEST_CASE(
    "set_position on compensated positions: split into hi + lo, beyond float's range refused") {
  pm::Particle<CompensatedPositions> particle;
  const double wanted = 16777216.0 + 0.375;  // 2^24 + 3/8: a float holds 2^24, lo 3/8
  particle.set_position({wanted, -wanted, 1.0});
  CHECK(particle.position().x == wanted);
  CHECK(particle.position().y == -wanted);
  CHECK(particle.stored_position().x == 16777216.0f);
  CHECK(particle.stored_position_error().x == 0.375f);

  CHECK_THROWS_WITH_AS(particle.set_position({1e39, 0.0, 0.0}),
                       doctest::Contains("set_position: argument 'position'"),
                       std::invalid_argument);
  CHECK(particle.position().x == wanted);  // unchanged

  pm::ParticleSystem<CompensatedPositions> system(2);
  CHECK_THROWS_AS(system.spawn({0.0, -1e40, 0.0}, {}), std::invalid_argument);
  CHECK(system.size() == 0);
  const std::size_t i = system.spawn({wanted, 0.0, 0.0}, {});
  CHECK(system.position(i).x == wanted);
  CHECK_THROWS_AS(system.set_position(i, {0.0, 0.0, 5e38}), std::invalid_argument);
  CHECK(system.position(i).x == wanted);
}

TEST_CASE(
    "set_position on compensated positions: every position() the pair gives is taken back, "
    "up to the midpoint above the largest float") {
  const double largest = static_cast<double>(std::numeric_limits<float>::max());  // 2^128 - 2^104
  const double midpoint = largest + 0x1p103;  // half its ulp above
  const double inside = midpoint - 0x1p76;    // lo = 2^103 - 2^76 rounds to 2^103
  const double beyond = std::nextafter(midpoint, 1e300);
  for (const double sign : {1.0, -1.0}) {
    CAPTURE(sign);
    pm::Particle<CompensatedPositions> particle;
    particle.set_position({sign * inside, 0.0, 0.0});
    CHECK(particle.stored_position().x == static_cast<float>(sign * largest));
    CHECK(particle.stored_position_error().x == static_cast<float>(sign * 0x1p103));
    CHECK(particle.position().x == sign * midpoint);
    particle.set_position(particle.position());  // the midpoint itself: the same pair
    CHECK(particle.position().x == sign * midpoint);
    CHECK(particle.stored_position().x == static_cast<float>(sign * largest));
    CHECK_THROWS_WITH_AS(particle.set_position({sign * beyond, 0.0, 0.0}),
                         doctest::Contains("set_position: argument 'position'"),
                         std::invalid_argument);
    CHECK(particle.position().x == sign * midpoint);  // unchanged

    pm::ParticleSystem<CompensatedPositions> system(2);
    const std::size_t i = system.spawn(particle);
    CHECK(system.position(i).x == sign * midpoint);
    system.set_position(i, system.position(i));
    CHECK(system.position(i).x == sign * midpoint);
    CHECK_THROWS_AS(system.spawn({0.0, sign * beyond, 0.0}, {}), std::invalid_argument);
    CHECK(system.size() == 1);
  }
  // The same edge for compensated doubles, read as long double (where it is wider): the
  // midpoint itself, which rounds to infinity as a double, is the largest double plus 2^970.
  if constexpr (std::numeric_limits<long double>::digits > std::numeric_limits<double>::digits) {
    using Pair = pm::Precision<double, pm::Compensated<double>>;
    const long double top = static_cast<long double>(std::numeric_limits<double>::max());
    const long double mid = top + 0x1p970L;
    const long double up = std::numeric_limits<long double>::infinity();  // nextafter's way
    pm::Particle<Pair> particle;
    particle.set_position({mid, 0.0L, 0.0L});
    CHECK(particle.stored_position().x == std::numeric_limits<double>::max());
    CHECK(particle.stored_position_error().x == 0x1p970);
    CHECK(particle.position().x == mid);
    CHECK_THROWS_AS(particle.set_position({std::nextafter(mid, up), 0.0L, 0.0L}),
                    std::invalid_argument);

    // The report's text holds all three refused components, each reading back as itself,
    // at long double's longest: 21 significant digits for x87's 64 bits, 36 for a 113-bit
    // quad, where three of them need more than 128 characters.
    const long double past = std::nextafter(mid, up);
    const long double refused[3] = {-past, past, -std::nextafter(past, up)};
    std::string message;
    try {
      particle.set_position({refused[0], refused[1], refused[2]});
    } catch (const std::invalid_argument& error) {
      message = error.what();
    }
    CAPTURE(message);
    const std::size_t open = message.find("' = (");
    const std::size_t close = message.find(") must be");
    REQUIRE(open != std::string::npos);
    REQUIRE(close != std::string::npos);
    const char* first = message.data() + open + 5;
    const char* const last = message.data() + close;
    for (int k = 0; k < 3; ++k) {
      CAPTURE(k);
      long double read = 0.0L;
      const auto [end, error] = std::from_chars(first, last, read);
      REQUIRE(error == std::errc{});
      CHECK(read == refused[k]);
      const bool separated = k < 2 && last - end > 2 && end[0] == ',' && end[1] == ' ';
      REQUIRE((end == last) != separated);
      first = end + 2;
    }
    CHECK(particle.position().x == mid);  // unchanged
  }
}

TEST_CASE(
    "set_position on compensated positions: taken exactly when within the midpoint above "
    "the largest float, and position() set back gives the same value") {
  const double largest = static_cast<double>(std::numeric_limits<float>::max());
  const double midpoint = largest + 0x1p103;
  std::mt19937_64 random(33);
  std::uniform_int_distribution<int> exponent(-150, 130);
  std::uniform_real_distribution<double> fraction(1.0, 2.0);
  std::uniform_int_distribution<int> near_edge(-(1 << 14), 1 << 14);
  int taken = 0;
  int refused = 0;
  int at_edge = 0;
  int at_midpoint = 0;
  for (int n = 0; n < 20000; ++n) {
    // Half the values anywhere in float's exponents and beyond, half within 2^14 steps of
    // 2^68 around the midpoint, where the largest float and the refusals meet: below it, a
    // sixteenth of them have v - largest round to 2^103 as a float, so position() is the
    // midpoint itself.
    const double x = (n % 2 == 0) ? std::ldexp(fraction(random), exponent(random))
                                  : midpoint + static_cast<double>(near_edge(random)) * 0x1p68;
    const double v = (n % 4 < 2) ? x : -x;
    CAPTURE(v);
    pm::Particle<CompensatedPositions> particle;
    const bool within = std::fabs(v) <= midpoint;
    if (!within) {
      ++refused;
      CHECK_THROWS_AS(particle.set_position({0.0, v, 0.0}), std::invalid_argument);
      CHECK(particle.position().y == 0.0);
      continue;
    }
    ++taken;
    if (std::fabs(v) > largest) ++at_edge;
    particle.set_position({0.0, v, 0.0});
    const float hi = particle.stored_position().y;
    const float lo = particle.stored_position_error().y;
    REQUIRE(std::isfinite(hi));
    REQUIRE(std::isfinite(lo));
    // hi is v rounded to float (the largest where that overflows), lo what is left rounded.
    const double expected_hi = std::fabs(v) > largest ? std::copysign(largest, v)
                                                      : static_cast<double>(static_cast<float>(v));
    CHECK(static_cast<double>(hi) == expected_hi);
    CHECK(static_cast<double>(lo) == static_cast<double>(static_cast<float>(v - expected_hi)));
    const double p = particle.position().y;
    CHECK(p == static_cast<double>(hi) + static_cast<double>(lo));
    if (std::fabs(p) == midpoint) ++at_midpoint;
    particle.set_position({0.0, p, 0.0});
    CHECK(particle.position().y == p);
  }
  CHECK(taken > 10000);
  CHECK(refused > 1000);
  CHECK(at_edge > 1000);
  CHECK(at_midpoint > 100);
}

// --- the units face ----------------------------------------------------------------------------

TEST_CASE_TEMPLATE("units face: a Precision particle of SI quantities steps as the plain one", S,
                   DoublePositions, CompensatedPositions) {
  namespace si = boost::units::si;
  pm::units::Particle<S, pm::damping::Exact, pm::position::Exact> typed;
  pm::Particle<S, pm::damping::Exact, pm::position::Exact> plain;
  typed.set_position(Vector3<double>{1e7, 2e3, -5e6} * si::meters);
  plain.set_position({1e7, 2e3, -5e6});
  typed.set_velocity(Vector3<float>{300, 400, 0} * si::meters_per_second);
  plain.set_velocity({300, 400, 0});
  typed.set_acceleration(pm::units::gravity<float>());
  plain.set_acceleration(pm::gravity<float>());
  typed.set_damping(0.9f);
  plain.set_damping(0.9f);
  for (int k = 0; k < 3000; ++k) {
    typed.integrate(1.0f / 60.0f * si::seconds);
    plain.integrate(1.0f / 60.0f);
  }
  CHECK(same_bits(typed.stored_position(), plain.stored_position()));
  CHECK(same_bits(typed.velocity().x.value(), plain.velocity().x));
  CHECK(same_bits(typed.position().y.value(), plain.position().y));
  CHECK(same_bits(typed.position_relative_to(Vector3<double>{1e7, 0, -5e6} * si::meters),
                  plain.position_relative_to({1e7, 0, -5e6})));
}

TEST_CASE_TEMPLATE("copy_positions rounds a compensated hi + lo to the buffer's type once", R,
                   float, double) {
  // hi = 1, lo = half an ulp of 1 and a little more: hi + lo is just above the midpoint between
  // 1 and the next R, so it rounds up. Rounded first to x87's long double (the value of a
  // double pair), the little more is lost, and the midpoint then rounds to even: 1.
  using System = pm::ParticleSystem<pm::Precision<R, pm::Compensated<R>>>;
  System system;
  system.spawn({}, {});
  constexpr R ulp = std::numeric_limits<R>::epsilon();
  const R lo = ulp / R(2) + ulp * ulp;  // an R: its two bits lie within R's digits
  system.template column<pm::Column::position_x>()[0] = R(1);
  system.template column<pm::Column::position_error_x>()[0] = lo;
  const R up = R(1) + ulp;  // hi + lo rounded to R once
  std::vector<R> packed(3, R(-1));
  system.copy_positions(std::span<R>(packed));
  CHECK(same_bits(packed[0], up));
  std::vector<Vector3<R>> vectors(1);
  system.copy_positions(std::span<Vector3<R>>(vectors));
  CHECK(same_bits(vectors[0].x, up));
  if constexpr (std::is_same_v<R, double>) {
    // Into float: 1 + 2^-24 + 2^-76 rounds up to the float above 1 (a long double keeps 1 +
    // 2^-24, the midpoint, which rounds to even).
    system.template column<pm::Column::position_error_x>()[0] =
        std::ldexp(1.0, -24) + std::ldexp(1.0, -76);
    std::vector<float> floats(3, -1.0f);
    system.copy_positions(std::span<float>(floats));
    CHECK(same_bits(floats[0], 1.0f + std::numeric_limits<float>::epsilon()));
  }
}
