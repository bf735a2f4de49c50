// SPDX-License-Identifier: BSL-1.0
// Real: the concept, and maths functions that stay in the precision they are given.
#include <doctest/doctest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <type_traits>
#include <utility>

#include <pointmass/damping.hpp>
#include <pointmass/real.hpp>
#include <pointmass/vector3.hpp>

#include "ulp.hpp"

using pointmass::Real;
using pointmass::test::same_bits;

static_assert(Real<float> && Real<double> && Real<long double>);
static_assert(!Real<int> && !Real<float&> && !Real<const double> && !Real<char>);

// Each function returns the type it is given: a float computation never becomes double.
static_assert(std::is_same_v<decltype(pointmass::real_pow(1.0f, 1.0f)), float>);
static_assert(std::is_same_v<decltype(pointmass::real_pow(1.0, 1.0)), double>);
static_assert(std::is_same_v<decltype(pointmass::real_pow(1.0L, 1.0L)), long double>);
static_assert(std::is_same_v<decltype(pointmass::real_expm1(1.0f)), float>);
static_assert(std::is_same_v<decltype(pointmass::real_log(1.0f)), float>);
static_assert(std::is_same_v<decltype(pointmass::real_sqrt(1.0f)), float>);
// The per-step factor of a float particle is a float.
static_assert(std::is_same_v<pointmass::damping_factors_t<pointmass::damping::PerSecond, float>,
                             pointmass::damping::Retention<float>>);
static_assert(pointmass::real_sqrt(2.25) == 1.5);  // usable in constant expressions

namespace {

/// pow(b, e) correctly rounded to float: powl (64-bit significand, within an ulp of its own)
/// rounded once to float. Accepted only where the double pow rounded to float agrees, so two
/// independent evaluations vouch for it (a result within 2^-40 of a float midpoint, where
/// rounding twice could differ, would show as a disagreement).
bool correctly_rounded_pow(float b, float e, float& result) {
  const float from_long_double =
      static_cast<float>(::powl(static_cast<long double>(b), static_cast<long double>(e)));
  const float from_double =
      static_cast<float>(std::pow(static_cast<double>(b), static_cast<double>(e)));
  result = from_long_double;
  return from_long_double == from_double;
}

/// Inputs for the square root: bit patterns of positive finite R, every exponent (subnormals
/// too) with scrambled significands, then each near a perfect square (k^2 and its neighbours,
/// where a root that is one ulp off shows first).
constexpr int sqrt_chunk = 256;
template <class R>
constexpr R sqrt_input(int index) {
  using Bits = std::conditional_t<sizeof(R) == 4, std::uint32_t, std::uint64_t>;
  constexpr int digits = std::numeric_limits<R>::digits;
  constexpr int exponents = 2 * std::numeric_limits<R>::max_exponent - 1;  // 255 or 2047
  std::uint64_t h = 0x9e3779b97f4a7c15u * static_cast<std::uint64_t>(index + 1);
  h ^= h >> 29;
  h *= 0xbf58476d1ce4e5b9u;
  h ^= h >> 32;
  if (index % 3 == 2) {  // a square of an integer, or one of its neighbours
    const auto k = static_cast<R>(h % (std::uint64_t{1} << (digits / 2)) + 1);
    const Bits square = __builtin_bit_cast(Bits, k * k);
    return __builtin_bit_cast(R, static_cast<Bits>(square + (h >> 40) % 3 - 1));
  }
  const std::uint64_t exponent = static_cast<std::uint64_t>(index) % exponents;
  const std::uint64_t significand = h & ((std::uint64_t{1} << (digits - 1)) - 1);
  const std::uint64_t bits = (exponent << (digits - 1)) | significand;
  return bits == 0 ? std::numeric_limits<R>::denorm_min() : __builtin_bit_cast(R, Bits(bits));
}
template <class R, int Chunk>
constexpr std::array<R, sqrt_chunk> constant_roots() {
  std::array<R, sqrt_chunk> roots{};
  for (int i = 0; i < sqrt_chunk; ++i) {
    const R x = sqrt_input<R>(Chunk * sqrt_chunk + i);
    roots[static_cast<std::size_t>(i)] = pointmass::real_sqrt(x);
  }
  return roots;
}
/// How many of chunk Chunk's roots, computed in a constant expression, differ from std::sqrt's
/// (IEEE: correctly rounded) at run time.
template <class R, int Chunk>
int constant_roots_off() {
  static constexpr std::array<R, sqrt_chunk> roots = constant_roots<R, Chunk>();
  int off = 0;
  for (int i = 0; i < sqrt_chunk; ++i) {
    volatile R x = sqrt_input<R>(Chunk * sqrt_chunk + i);
    if (!same_bits(roots[static_cast<std::size_t>(i)], std::sqrt(static_cast<R>(x)))) {
      if (off == 0) MESSAGE("first input whose roots differ: ", static_cast<R>(x));
      ++off;
    }
  }
  return off;
}
template <class R, int... Chunks>
int constant_roots_off(std::integer_sequence<int, Chunks...>) {
  return (constant_roots_off<R, Chunks>() + ...);
}

}  // namespace

TEST_CASE_TEMPLATE("real_sqrt in a constant expression is correctly rounded, as at run time", R,
                   float, double) {
  // 12 chunks of 256 (each its own constant expression, within clang's step limit).
  CHECK(constant_roots_off<R>(std::make_integer_sequence<int, 12>{}) == 0);
  constexpr R edges[] = {std::numeric_limits<R>::denorm_min(),
                         std::numeric_limits<R>::min(),
                         std::numeric_limits<R>::max(),
                         R(1),
                         R(2),
                         R(0.5)};
  constexpr R edge_roots[] = {pointmass::real_sqrt(edges[0]), pointmass::real_sqrt(edges[1]),
                              pointmass::real_sqrt(edges[2]), pointmass::real_sqrt(edges[3]),
                              pointmass::real_sqrt(edges[4]), pointmass::real_sqrt(edges[5])};
  for (int i = 0; i < 6; ++i) {
    volatile R x = edges[i];
    CHECK(same_bits(edge_roots[i], std::sqrt(static_cast<R>(x))));
  }
  // magnitude and normalized through it: 1 + 4 + 72.25, whose root Newton's iteration got
  // one ulp high.
  constexpr pointmass::Vector3<R> v{1, 2, R(8.5)};
  constexpr R length = pointmass::magnitude(v);
  constexpr pointmass::Vector3<R> unit = pointmass::normalized(v);
  volatile R z = R(8.5);
  const pointmass::Vector3<R> w{1, 2, static_cast<R>(z)};
  CHECK(same_bits(length, std::sqrt(R(77.25))));
  CHECK(same_bits(length, pointmass::magnitude(w)));
  CHECK(same_bits(unit, pointmass::normalized(w)));
}

TEST_CASE("real_pow of floats is powf, not pow on promoted doubles") {
  // pow on doubles rounded to float is the correctly rounded result almost always; powf (glibc:
  // within 1 ulp) is not, at a few inputs in a thousand. Those inputs tell the two forms apart:
  // search the damping factors of frame times (d in [0.5, 1), every 97th float, t = 1/30 s and
  // 1/60 s) for them, and there real_pow must give powf's bits, differ from the correctly
  // rounded result, and be within powf's 1 ulp of it.
  for (const float e : {1.0f / 30, 1.0f / 60}) {
    CAPTURE(e);
    int found = 0;  // for each exponent
    for (float b = 0.5f; b < 1.0f && found < 8; b = std::nextafter(b + b * 5.8e-6f, 1.0f)) {
      float correct = 0;
      if (!correctly_rounded_pow(b, e, correct) || ::powf(b, e) == correct) continue;
      ++found;
      const float value = pointmass::real_pow(b, e);
      INFO("base ", b, ", exponent ", e, ": real_pow ", value, ", correctly rounded ", correct);
      CHECK(value == ::powf(b, e));
      CHECK(value != correct);
      CHECK(std::abs(value - correct) <= std::nextafter(correct, 2.0f) - correct);
    }
    CHECK_MESSAGE(found >= 8,
                  "too few inputs where powf differs from the correctly rounded "
                  "power: on this platform real_pow's float path cannot be told "
                  "from the promoted one");
  }
  CHECK(pointmass::real_pow(0.99, 1.0 / 30) == std::pow(0.99, 1.0 / 30));
  CHECK(pointmass::real_pow(0.99L, 1.0L / 30) == ::powl(0.99L, 1.0L / 30));
}

TEST_CASE("the listing's factor is powf's bit for bit, and eq. 3.6's is float's own exponential") {
  // AccelerateThenDamp reproduces Cyclone, which calls powf: the same bits.
  // PerSecond computes e^(t ln d) in float, within 4 ulp of the correctly rounded d^t
  // (tests/test_exponential.cpp), and never promotes to double (the type is checked above).
  using pointmass::damping::AccelerateThenDamp;
  using pointmass::damping::PerSecond;
  for (const float d : {0.99f, 0.5f, 0.1f, 0.995f, 1e-6f, 0.0f, 1.0f}) {
    for (const float t : {1.0f / 30, 1.0f / 60, 0.25f, 0.3f, 2.5f}) {
      CAPTURE(d);
      CAPTURE(t);
      CHECK(AccelerateThenDamp::factors(AccelerateThenDamp::State<float>(d), t).kept ==
            ::powf(d, t));
      const float kept = PerSecond::factors(PerSecond::State<float>(d), t).kept;
      const long double exact = std::pow(static_cast<long double>(d), static_cast<long double>(t));
      CHECK(std::fabs(static_cast<long double>(kept) - exact) <=
            2 * static_cast<long double>(std::numeric_limits<float>::epsilon()) * exact);
    }
  }
}

TEST_CASE_TEMPLATE("classification raises nothing and is exact", T, float, double, long double) {
  const T inf = std::numeric_limits<T>::infinity();
  const T nan = std::numeric_limits<T>::quiet_NaN();
  CHECK(pointmass::real_isnan(nan));
  CHECK_FALSE(pointmass::real_isnan(inf));
  CHECK_FALSE(pointmass::real_isfinite(inf));
  CHECK_FALSE(pointmass::real_isfinite(nan));
  CHECK(pointmass::real_isfinite(std::numeric_limits<T>::max()));
  CHECK(pointmass::real_abs(T(-2.5)) == T(2.5));
  CHECK(pointmass::real_sqrt(T(6.25)) == T(2.5));
  CHECK(pointmass::real_expm1(T(0)) == T(0));
}

// The step's two value tests on bit patterns (detail::same_bits, detail::is_zero): a kept
// step length against a new one, and a zero duration or inverse mass of either sign.
TEST_CASE_TEMPLATE(
    "is_zero is x == 0 for every x, and same_bits is x == y where neither is NaN "
    "or a zero",
    T, float, double, long double) {
  using pointmass::detail::is_zero;
  const T values[] = {T(0),
                      -T(0),
                      std::numeric_limits<T>::denorm_min(),
                      -std::numeric_limits<T>::denorm_min(),
                      std::numeric_limits<T>::min(),
                      T(1) / T(60),
                      T(1),
                      -T(1),
                      std::numeric_limits<T>::max(),
                      std::numeric_limits<T>::infinity(),
                      -std::numeric_limits<T>::infinity(),
                      std::numeric_limits<T>::quiet_NaN()};
  for (const T x : values) {
    CAPTURE(x);
    CHECK(is_zero(x) == pointmass::real_equal(x, T(0)));
    for (const T y : values) {
      if (pointmass::real_isnan(x) || pointmass::real_isnan(y) || pointmass::real_equal(x, T(0)) ||
          pointmass::real_equal(y, T(0))) {
        continue;
      }
      CAPTURE(y);
      CHECK(pointmass::detail::same_bits(x, y) == pointmass::real_equal(x, y));
    }
  }
  // A step length one ulp away is another length.
  const T t = T(1) / T(60);
  CHECK_FALSE(pointmass::detail::same_bits(t, std::nextafter(t, T(1))));
  static_assert(is_zero(-T(0)) && !is_zero(std::numeric_limits<T>::denorm_min()));
}
