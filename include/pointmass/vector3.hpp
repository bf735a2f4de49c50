// pointmass/vector3.hpp — Vector3<T>, a 3-vector of any arithmetic-like T.
//
// T is usually a Real, but may be a dimensioned quantity (units.hpp): the arithmetic is
// heterogeneous, so Vector3<velocity> * time is a Vector3<length>, and the integrator's
// equations type-check their dimensions when instantiated on quantities. Products that
// change the element type are free functions; compound assignment keeps the type.
//
// Products: `v * s` scales; `component_product(a, b)` multiplies element by element (the
// reference engine's `%` operator is the cross product there; here it is spelled `cross`).
//
// `magnitude` and `normalized` work for every finite vector: when x^2 + y^2 + z^2 would
// overflow (components from about 1e19 in float, 1e154 in double) or underflow and lose digits
// (below about 1e-16 in float, 1e-146 in double) they divide by the largest component first.
// Elsewhere they compute exactly what the plain formula computes, bit for bit. A magnitude
// above the largest finite value (only possible beyond about 0.58 of it per component) is
// infinity; a direction is always a unit vector.
#pragma once

#include <limits>
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

  /// Makes this a unit vector in the same direction, for any finite non-zero vector (no
  /// overflow or underflow in between). The zero vector stays zero (no division by zero, no
  /// NaN); a vector with an infinite or NaN component is left as it is.
  POINTMASS_HD constexpr Vector3& normalize() noexcept
    requires Real<T>;

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

namespace detail {

/// Whether x^2 + y^2 + z^2 = `square` was formed without overflow and without an underflow
/// that cost digits: at or above min / epsilon, a component whose square underflowed changes
/// the sum by less than epsilon^2 of it.
template <Real T>
POINTMASS_HD constexpr bool square_is_exact_enough(T square) noexcept {
  return square >= std::numeric_limits<T>::min() / std::numeric_limits<T>::epsilon() &&
         square <= std::numeric_limits<T>::max();
}

/// The largest |component| (NaN if a component is NaN).
template <Real T>
POINTMASS_HD constexpr T largest_component(const Vector3<T>& v) noexcept {
  const T x = real_abs(v.x), y = real_abs(v.y), z = real_abs(v.z);
  if (real_isnan(x) || real_isnan(y) || real_isnan(z)) return x + y + z;
  const T xy = x > y ? x : y;
  return xy > z ? xy : z;
}

}  // namespace detail

template <Real T>
POINTMASS_HD constexpr T magnitude(const Vector3<T>& v) noexcept {
  const T square = square_magnitude(v);
  if (detail::square_is_exact_enough(square)) return real_sqrt(square);
  // Scaled: |v| = s |v / s| with s the largest component, so nothing over- or underflows.
  const T scale = detail::largest_component(v);
  if (!(scale > T(0)) || !real_isfinite(scale)) return scale;  // zero, infinity or NaN
  return real_sqrt(square_magnitude(v / scale)) * scale;
}

template <class T>
POINTMASS_HD constexpr Vector3<T>& Vector3<T>::normalize() noexcept
  requires Real<T>
{
  const T square = square_magnitude(*this);
  if (detail::square_is_exact_enough(square)) return *this /= real_sqrt(square);
  const T scale = detail::largest_component(*this);
  if (!(scale > T(0)) || !real_isfinite(scale)) return *this;  // zero, infinity or NaN
  *this /= scale;
  return *this /= real_sqrt(square_magnitude(*this));
}

/// A unit vector in v's direction for any finite non-zero v; the zero vector for the zero
/// vector.
template <Real T>
POINTMASS_HD constexpr Vector3<T> normalized(Vector3<T> v) noexcept {
  return v.normalize();
}

template <Real T>
POINTMASS_HD constexpr bool is_finite(const Vector3<T>& v) noexcept {
  return real_isfinite(v.x) && real_isfinite(v.y) && real_isfinite(v.z);
}

}  // namespace pointmass
