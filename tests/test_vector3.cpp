// SPDX-License-Identifier: BSL-1.0
// Vector3: arithmetic, products, magnitude and normalisation, in float and double, and the
// conversions between precisions.
#include <doctest/doctest.h>

#include <limits>
#include <type_traits>

#include <pointmass/vector3.hpp>

#include "tolerance.hpp"

using pointmass::Vector3;

// constexpr throughout: the operations are checked at compile time too.
static_assert(Vector3<float>{1, 2, 3} + Vector3<float>{4, 5, 6} == Vector3<float>{5, 7, 9});
static_assert(Vector3<double>{1, 2, 3} * 2.0 == Vector3<double>{2, 4, 6});
static_assert(pointmass::dot(Vector3<double>{1, 2, 3}, Vector3<double>{4, 5, 6}) == 32.0);
static_assert(pointmass::cross(Vector3<double>{1, 0, 0}, Vector3<double>{0, 1, 0}) ==
              Vector3<double>{0, 0, 1});
static_assert(pointmass::magnitude(Vector3<double>{3, 4, 12}) == 13.0);
static_assert(pointmass::normalized(Vector3<double>{0, 0, 0}) == Vector3<double>{0, 0, 0});

TEST_CASE_TEMPLATE("Vector3 arithmetic", T, float, double) {
  const Vector3<T> a{T(1), T(-2), T(3)};
  const Vector3<T> b{T(0.5), T(4), T(-8)};

  CHECK(a + b == Vector3<T>{T(1.5), T(2), T(-5)});
  CHECK(a - b == Vector3<T>{T(0.5), T(-6), T(11)});
  CHECK(-a == Vector3<T>{T(-1), T(2), T(-3)});
  CHECK(a * T(2) == Vector3<T>{T(2), T(-4), T(6)});
  CHECK(T(2) * a == a * T(2));
  CHECK(b / T(2) == Vector3<T>{T(0.25), T(2), T(-4)});

  Vector3<T> c = a;
  c += b;
  CHECK(c == a + b);
  c -= b;
  CHECK(c == a);
  c *= T(3);
  CHECK(c == Vector3<T>{T(3), T(-6), T(9)});
  c /= T(3);
  CHECK(c == a);
  c.add_scaled_vector(b, T(2));
  CHECK(c == Vector3<T>{T(2), T(6), T(-13)});
  CHECK(a != b);
}

TEST_CASE_TEMPLATE("Vector3 products", T, float, double) {
  const Vector3<T> a{T(1), T(-2), T(3)};
  const Vector3<T> b{T(0.5), T(4), T(-8)};
  CHECK(pointmass::component_product(a, b) == Vector3<T>{T(0.5), T(-8), T(-24)});
  CHECK(pointmass::dot(a, b) == T(0.5 - 8 - 24));
  // a x b = (-2*-8 - 3*4, 3*0.5 - 1*-8, 1*4 - -2*0.5) = (4, 9.5, 5)
  const auto c = pointmass::cross(a, b);
  CHECK(c == Vector3<T>{T(4), T(9.5), T(5)});
  // The cross product is perpendicular to both factors and anti-commutes.
  CHECK(pointmass::dot(c, a) == T(0));
  CHECK(pointmass::dot(c, b) == T(0));
  CHECK(pointmass::cross(b, a) == -c);
}

TEST_CASE_TEMPLATE("Vector3 magnitude and normalisation", T, float, double) {
  const Vector3<T> v{T(2), T(-3), T(6)};
  CHECK(pointmass::square_magnitude(v) == T(49));
  CHECK(pointmass::magnitude(v) == T(7));

  Vector3<T> n = v;
  n.normalize();
  POINTMASS_CHECK_CLOSE(n, (Vector3<T>{T(2) / T(7), T(-3) / T(7), T(6) / T(7)}), T(2));
  POINTMASS_CHECK_CLOSE(pointmass::magnitude(n), T(1), T(2));

  Vector3<T> zero{};
  zero.normalize();  // stays zero: no division by zero, no NaN
  CHECK(zero == Vector3<T>{});
  CHECK(pointmass::is_finite(v));
  CHECK_FALSE(pointmass::is_finite(Vector3<T>{T(0), std::numeric_limits<T>::infinity(), T(0)}));
  CHECK_FALSE(pointmass::is_finite(Vector3<T>{std::numeric_limits<T>::quiet_NaN(), T(0), T(0)}));
}

TEST_CASE("Vector3 converts between precisions: implicitly when exact, explicitly when it rounds") {
  static_assert(std::is_convertible_v<Vector3<float>, Vector3<double>>);
  static_assert(std::is_convertible_v<Vector3<double>, Vector3<long double>>);
  static_assert(!std::is_convertible_v<Vector3<double>, Vector3<float>>);  // it rounds
  static_assert(std::is_constructible_v<Vector3<float>, Vector3<double>>);
  const Vector3<double> third{1.0 / 3.0, -2.0 / 3.0, 1e300};
  const auto narrowed = static_cast<Vector3<float>>(third);
  CHECK(narrowed.x == static_cast<float>(1.0 / 3.0));
  CHECK(narrowed.y == static_cast<float>(-2.0 / 3.0));
  CHECK(narrowed.z == std::numeric_limits<float>::infinity());  // out of float's range
  const Vector3<double> widened = Vector3<float>{0.1f, 0.2f, 0.3f};
  CHECK(widened.x == static_cast<double>(0.1f));
  CHECK(widened.z == static_cast<double>(0.3f));
}
