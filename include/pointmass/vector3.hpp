// SPDX-License-Identifier: BSL-1.0
// pointmass/vector3.hpp — Vector3<T>, a 3-vector of any arithmetic-like T.
//
// T is usually a Real, but may be a dimensioned quantity (units.hpp): the arithmetic is
// heterogeneous, so Vector3<velocity> * time is a Vector3<length>, and the integrator's
// equations type-check their dimensions when instantiated on quantities. Products that
// change the element type are free functions; compound assignment keeps the type.
//
// Products: `v * s` scales; `component_product(a, b)` multiplies element by element (the
// Cyclone's `%` operator is the cross product there; here it is spelled `cross`).
//
// `magnitude` and `normalized` work for every finite vector: when x^2 + y^2 + z^2 would
// overflow (components from about 1e19 in float, 1e154 in double) or underflow and lose digits
// (below about 1e-16 in float, 1e-146 in double) they divide by the largest component first.
// Elsewhere they compute exactly what the plain formula computes, bit for bit. A magnitude
// above the largest finite value (only possible beyond about 0.58 of it per component) is
// infinity; a direction is always a unit vector.
//
// Owns: Vector3<T>, its arithmetic, magnitude and normalized (scaled, no overflow), and the
// conversion to and from the user's vector types (VectorTraits).
// Must not include: anything but config.hpp and real.hpp.
#pragma once

#include <limits>
#include <type_traits>

#include "config.hpp"
#include "real.hpp"

POINTMASS_DETAIL_UNFUSED_BEGIN
namespace pointmass::inline POINTMASS_ABI_NAMESPACE {

template <class T>
struct Vector3;

// --- the user's own vector types ---------------------------------------------------------------
//
// A game already has a vector type (glm::vec3, Eigen::Vector3f, its own struct). VectorTraits<V>
// says how to read x, y and z from a V and how to make a V; with it, a V converts to a Vector3
// and a Vector3 to a V, implicitly when nothing is lost (float into a Vector3<float> or a
// Vector3<double>), explicitly (static_cast) when the conversion narrows (double into
// Vector3<float>). Each conversion copies three numbers (constexpr, noexcept).
//
// A type with public x, y and z data members (glm, most engines' own structs) needs nothing:
//   particle.set_position(glm::vec3(0, 1.5f, 0));   glm::vec3 p = particle.position();
// For any other type, specialise VectorTraits, as for Eigen's operator() access:
//   template <> struct pointmass::VectorTraits<Eigen::Vector3f> {
//     using value_type = float;
//     static float x(const Eigen::Vector3f& v) { return v(0); }   // y: v(1), z: v(2)
//     static Eigen::Vector3f make(float x, float y, float z) { return {x, y, z}; }
//   };
// (make is optional: without it, the type converts into a Vector3 only.)

/// How to read (x, y, z, value_type) and make (make) a user's vector type V. Empty: V is not a
/// vector. Specialise it for your type; types with x, y and z members have it already.
template <class V>
struct VectorTraits {};

namespace detail {

template <class V>
concept HasXyzMembers = requires(const V& v) {
  v.x;
  v.y;
  v.z;
  requires std::is_same_v<std::remove_cvref_t<decltype(v.x)>, std::remove_cvref_t<decltype(v.y)>>;
  requires std::is_same_v<std::remove_cvref_t<decltype(v.x)>, std::remove_cvref_t<decltype(v.z)>>;
};

template <class T>
inline constexpr bool is_vector3 = false;
template <class T>
inline constexpr bool is_vector3<Vector3<T>> = true;

}  // namespace detail

/// The traits of a type with x, y and z data members of one type (glm::vec3, a user's struct).
// clang-format off
template <class V>
  requires(detail::HasXyzMembers<V> && (!detail::is_vector3<V>))
struct VectorTraits<V> {
  // clang-format on
  using value_type = std::remove_cvref_t<decltype(std::declval<const V&>().x)>;
  POINTMASS_HD static constexpr value_type x(const V& v) noexcept { return v.x; }
  POINTMASS_HD static constexpr value_type y(const V& v) noexcept { return v.y; }
  POINTMASS_HD static constexpr value_type z(const V& v) noexcept { return v.z; }
  // clang-format off
  POINTMASS_HD static constexpr V make(value_type x, value_type y, value_type z)
    requires(requires { V{x, y, z}; })
  // clang-format on
  {
    return V{x, y, z};
  }
};

namespace detail {

/// V is a user's vector type whose numbers convert to T.
template <class V, class T>
concept UserVectorOf = !is_vector3<std::remove_cvref_t<V>> && requires(const V& v) {
  typename VectorTraits<V>::value_type;
  { VectorTraits<V>::x(v) } -> std::convertible_to<typename VectorTraits<V>::value_type>;
  { VectorTraits<V>::y(v) } -> std::convertible_to<typename VectorTraits<V>::value_type>;
  { VectorTraits<V>::z(v) } -> std::convertible_to<typename VectorTraits<V>::value_type>;
  requires std::is_constructible_v<T, typename VectorTraits<V>::value_type>;
};

/// ... and V can be made from three numbers converted from T.
template <class V, class T>
concept MakeableUserVectorOf = !is_vector3<std::remove_cvref_t<V>> && requires(const T& t) {
  typename VectorTraits<V>::value_type;
  requires std::is_constructible_v<typename VectorTraits<V>::value_type, T>;
  {
    VectorTraits<V>::make(typename VectorTraits<V>::value_type(t),
                          typename VectorTraits<V>::value_type(t),
                          typename VectorTraits<V>::value_type(t))
    } -> std::same_as<V>;
};

/// Every From converts to To without loss: the same type, or floating-point types where To has
/// at least From's precision and range (float to double; not double to float, not int to float).
template <class From, class To>
inline constexpr bool converts_exactly_v =
    std::is_same_v<From, To> ||
    (std::is_floating_point_v<From> && std::is_floating_point_v<To> &&
     std::numeric_limits<To>::digits >= std::numeric_limits<From>::digits &&
     std::numeric_limits<To>::max_exponent >= std::numeric_limits<From>::max_exponent);

}  // namespace detail

// --- Vector3 ----------------------------------------------------------------------------------

template <class T>
struct Vector3 {
  using value_type = T;

  T x{};
  T y{};
  T z{};

  /// The zero vector.
  constexpr Vector3() = default;
  POINTMASS_HD constexpr Vector3(T x_value, T y_value, T z_value) noexcept
      : x(x_value), y(y_value), z(z_value) {}

  /// From a Vector3 of another floating-point type: implicit when every number converts
  /// exactly (float to double), explicit otherwise (double to float rounds each component).
  template <class U>
    requires(std::is_floating_point_v<T>&& std::is_floating_point_v<U> && !std::is_same_v<T, U>)
  POINTMASS_HD constexpr explicit(!detail::converts_exactly_v<U, T>)
      Vector3(const Vector3<U>& v) noexcept
      : x(static_cast<T>(v.x)), y(static_cast<T>(v.y)), z(static_cast<T>(v.z)) {}

  // --- to and from the user's vector types (VectorTraits, above) -------------------------------
  /// From a user's vector: implicit when every number converts exactly, explicit otherwise.
  template <class V>
    requires(detail::UserVectorOf<V, T>)
  POINTMASS_HD constexpr explicit(
      !detail::converts_exactly_v<typename VectorTraits<V>::value_type, T>)
      Vector3(const V& v) noexcept
      : x(static_cast<T>(VectorTraits<V>::x(v))),
        y(static_cast<T>(VectorTraits<V>::y(v))),
        z(static_cast<T>(VectorTraits<V>::z(v))) {}
  /// To a user's vector: implicit when every number converts exactly, explicit otherwise.
  // clang-format off
  template <class V>
    requires(detail::MakeableUserVectorOf<V, T>)
  POINTMASS_HD constexpr explicit(
      !detail::converts_exactly_v<T, typename VectorTraits<V>::value_type>) operator V() const {
    // clang-format on
    using U = typename VectorTraits<V>::value_type;
    return VectorTraits<V>::make(static_cast<U>(x), static_cast<U>(y), static_cast<U>(z));
  }
  // --- end of the user's vector types ----------------------------------------------------------

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

  /// *this += v * scale, in place (Cyclone's `addScaledVector`).
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
  POINTMASS_HD constexpr Vector3& normalize() noexcept requires Real<T>;

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
[[nodiscard]] POINTMASS_HD constexpr auto component_product(const Vector3<T>& a,
                                                            const Vector3<U>& b) noexcept
    -> Vector3<decltype(a.x * b.x)> {
  return {a.x * b.x, a.y * b.y, a.z * b.z};
}

template <class T, class U>
[[nodiscard]] POINTMASS_HD constexpr auto dot(const Vector3<T>& a, const Vector3<U>& b) noexcept
    -> decltype(a.x * b.x) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}

/// Right-handed cross product.
template <class T, class U>
[[nodiscard]] POINTMASS_HD constexpr auto cross(const Vector3<T>& a, const Vector3<U>& b) noexcept
    -> Vector3<decltype(a.x * b.x)> {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

template <Real T>
[[nodiscard]] POINTMASS_HD constexpr T square_magnitude(const Vector3<T>& v) noexcept {
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
  const T x = real_abs(v.x);
  const T y = real_abs(v.y);
  const T z = real_abs(v.z);
  if (real_isnan(x) || real_isnan(y) || real_isnan(z)) return x + y + z;
  const T xy = x > y ? x : y;
  return xy > z ? xy : z;
}

}  // namespace detail

template <Real T>
[[nodiscard]] POINTMASS_HD constexpr T magnitude(const Vector3<T>& v) noexcept {
  const T square = square_magnitude(v);
  if (detail::square_is_exact_enough(square)) return real_sqrt(square);
  // Scaled: |v| = s |v / s| with s the largest component, so nothing over- or underflows.
  const T scale = detail::largest_component(v);
  if (!(scale > T(0)) || !real_isfinite(scale)) return scale;  // zero, infinity or NaN
  return real_sqrt(square_magnitude(v / scale)) * scale;
}

template <class T>
POINTMASS_HD constexpr Vector3<T>& Vector3<T>::normalize() noexcept requires Real<T> {
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
[[nodiscard]] POINTMASS_HD constexpr Vector3<T> normalized(Vector3<T> v) noexcept {
  return v.normalize();
}

template <Real T>
[[nodiscard]] POINTMASS_HD constexpr bool is_finite(const Vector3<T>& v) noexcept {
  return real_isfinite(v.x) && real_isfinite(v.y) && real_isfinite(v.z);
}

}  // namespace pointmass
POINTMASS_DETAIL_UNFUSED_END
