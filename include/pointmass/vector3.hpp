// pointmass/vector3.hpp — Vector3<T>, a 3-vector of any arithmetic-like T.
//
// T is usually a Real, but may be a dimensioned quantity (units.hpp): the arithmetic is
// heterogeneous, so Vector3<velocity> * time is a Vector3<length>, and the integrator's
// equations type-check their dimensions when instantiated on quantities. Products that
// change the element type are free functions; compound assignment keeps the type.
//
// Products: `v * s` scales; `component_product(a, b)` multiplies element by element (the
// reference engine's `%` operator is the cross product there; here it is spelled `cross`).
#pragma once

#include <type_traits>

#include "config.hpp"
#include "real.hpp"

namespace pointmass {

template <class T>
struct Vector3 {
  using value_type = T;

  T x{};
  T y{};
  T z{};

  POINTMASS_HD constexpr Vector3& operator+=(const Vector3& other) noexcept {
    x += other.x;
    y += other.y;
    z += other.z;
    return *this;
  }
  POINTMASS_HD constexpr Vector3& operator-=(const Vector3& other) noexcept {
    x -= other.x;
    y -= other.y;
    z -= other.z;
    return *this;
  }
  template <class S>
  POINTMASS_HD constexpr Vector3& operator*=(const S& scale) noexcept {
    x *= scale;
    y *= scale;
    z *= scale;
    return *this;
  }
  template <class S>
  POINTMASS_HD constexpr Vector3& operator/=(const S& divisor) noexcept {
    x /= divisor;
    y /= divisor;
    z /= divisor;
    return *this;
  }

  /// *this += v * scale, in place (the reference engine's addScaledVector).
  template <class U, class S>
  POINTMASS_HD constexpr Vector3& add_scaled_vector(const Vector3<U>& v, const S& scale) noexcept {
    x += v.x * scale;
    y += v.y * scale;
    z += v.z * scale;
    return *this;
  }

  /// The zero vector stays zero (no division by zero, no NaN).
  POINTMASS_HD constexpr Vector3& normalize() noexcept
    requires Real<T>
  {
    const T length = magnitude(*this);
    if (length > T(0)) *this /= length;
    return *this;
  }

  friend constexpr bool operator==(const Vector3&, const Vector3&) = default;
};

template <class T>
struct IsVector3 : std::false_type {};
template <class T>
struct IsVector3<Vector3<T>> : std::true_type {};
template <class T>
inline constexpr bool is_vector3_v = IsVector3<std::remove_cvref_t<T>>::value;

template <class T, class U>
POINTMASS_HD constexpr auto operator+(const Vector3<T>& a, const Vector3<U>& b) noexcept
    -> Vector3<decltype(a.x + b.x)> {
  return {a.x + b.x, a.y + b.y, a.z + b.z};
}

template <class T, class U>
POINTMASS_HD constexpr auto operator-(const Vector3<T>& a, const Vector3<U>& b) noexcept
    -> Vector3<decltype(a.x - b.x)> {
  return {a.x - b.x, a.y - b.y, a.z - b.z};
}

template <class T>
POINTMASS_HD constexpr Vector3<T> operator-(const Vector3<T>& a) noexcept {
  return {-a.x, -a.y, -a.z};
}

template <class T, class S>
  requires(!is_vector3_v<S>)
POINTMASS_HD constexpr auto operator*(const Vector3<T>& v, const S& s) noexcept
    -> Vector3<decltype(v.x * s)> {
  return {v.x * s, v.y * s, v.z * s};
}

template <class S, class T>
  requires(!is_vector3_v<S>)
POINTMASS_HD constexpr auto operator*(const S& s, const Vector3<T>& v) noexcept
    -> Vector3<decltype(s * v.x)> {
  return {s * v.x, s * v.y, s * v.z};
}

template <class T, class S>
  requires(!is_vector3_v<S>)
POINTMASS_HD constexpr auto operator/(const Vector3<T>& v, const S& s) noexcept
    -> Vector3<decltype(v.x / s)> {
  return {v.x / s, v.y / s, v.z / s};
}

/// Element-by-element product (x1 x2, y1 y2, z1 z2).
template <class T, class U>
POINTMASS_HD constexpr auto component_product(const Vector3<T>& a, const Vector3<U>& b) noexcept
    -> Vector3<decltype(a.x * b.x)> {
  return {a.x * b.x, a.y * b.y, a.z * b.z};
}

template <class T, class U>
POINTMASS_HD constexpr auto dot(const Vector3<T>& a, const Vector3<U>& b) noexcept
    -> decltype(a.x * b.x) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}

/// Right-handed cross product.
template <class T, class U>
POINTMASS_HD constexpr auto cross(const Vector3<T>& a, const Vector3<U>& b) noexcept
    -> Vector3<decltype(a.x * b.x)> {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

template <Real T>
POINTMASS_HD constexpr T square_magnitude(const Vector3<T>& v) noexcept {
  return dot(v, v);
}

template <Real T>
POINTMASS_HD constexpr T magnitude(const Vector3<T>& v) noexcept {
  return real_sqrt(square_magnitude(v));
}

/// A unit vector in v's direction; the zero vector for the zero vector.
template <Real T>
POINTMASS_HD constexpr Vector3<T> normalized(Vector3<T> v) noexcept {
  return v.normalize();
}

template <Real T>
POINTMASS_HD constexpr bool is_finite(const Vector3<T>& v) noexcept {
  return real_isfinite(v.x) && real_isfinite(v.y) && real_isfinite(v.z);
}

}  // namespace pointmass
