// Real: the concept, and maths functions that stay in the precision they are given.
#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <type_traits>

#include <pointmass/damping.hpp>
#include <pointmass/real.hpp>

using pointmass::Real;

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

TEST_CASE("real_pow calls the power function of the argument's precision") {
  // Bit for bit what powf gives (a double pow rounded to float differs for some inputs;
  // these are checked to be equal to powf, whatever they are).
  const float bases[] = {0.99f, 0.5f, 0.1f, 0.995f, 1e-6f};
  const float exponents[] = {1.0f / 30, 1.0f / 60, 0.3f, 2.5f, 10.0f};
  for (const float b : bases) {
    for (const float e : exponents) {
      CHECK(pointmass::real_pow(b, e) == ::powf(b, e));
    }
  }
  CHECK(pointmass::real_pow(0.99, 1.0 / 30) == std::pow(0.99, 1.0 / 30));
}

TEST_CASE("the listing's factor is powf's, bit for bit; eq. 3.6's is float's own exponential") {
  // AccelerateThenDamp reproduces the reference engine, which calls powf: the same bits.
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
