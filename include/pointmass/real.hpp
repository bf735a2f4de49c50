// SPDX-License-Identifier: BSL-1.0
// pointmass/real.hpp — the floating-point types the library computes in, and the maths
// functions matched to each precision.
//
// `Real` is float, double or long double; any other type is rejected by the concept. Every
// function here computes in the precision of its argument and returns that type:
// `real_pow(float, float)` calls `powf`, never `pow` on promoted doubles, so a float particle
// stays in float arithmetic end to end (the library builds clean under -Wdouble-promotion;
// its constants are written R(0.5), never 0.5).
//
// `scalar_t<T>` is the Real a (possibly dimensioned) type is made of: `float` for float,
// `Y` for a Boost.Units `quantity<Unit, Y>` (specialised in units.hpp).
//
// Owns: the Real concept, the maths functions matched to each precision, NaN and infinity by
// bit pattern, real_equal.
// Must not include: anything but config.hpp.
#pragma once

#include <cmath>
#include <concepts>
#include <cstdint>
#include <limits>
#include <type_traits>

#include "config.hpp"

POINTMASS_DETAIL_UNFUSED_BEGIN
namespace pointmass::inline POINTMASS_ABI_NAMESPACE {

/// The precisions the library computes in.
template <class T>
concept Real = std::same_as<T, float> || std::same_as<T, double> || std::same_as<T, long double>;

/// What a value's number is made of; specialised for dimensioned types by units.hpp.
template <class T>
struct ScalarOf {
  using type = T;
};
template <class T>
using scalar_t = typename ScalarOf<T>::type;

/// True for long double where it is wider than double (x87's 80 bits, or 128): the precision
/// that calls the C library where float and double use the library's own code. Written with
/// sizeof, so that device code, where long double is double, never names long double.
template <class R>
inline constexpr bool wider_than_double_v = sizeof(R) > sizeof(double);

namespace detail {

/// The unsigned integer of R's size and R's exponent field, for float and double.
template <class R>
struct FloatBits {
  using type = std::conditional_t<sizeof(R) == 4, std::uint32_t, std::uint64_t>;
  static constexpr type exponent_mask =
      static_cast<type>(sizeof(R) == 4 ? 0x7f800000u : 0x7ff0000000000000u);
  static constexpr type magnitude_mask =
      static_cast<type>(sizeof(R) == 4 ? 0x7fffffffu : 0x7fffffffffffffffu);
};

template <class R>
inline constexpr bool has_ieee_bits_v = (std::same_as<R, float> && sizeof(float) == 4) ||
                                        (std::same_as<R, double> && sizeof(double) == 8);

}  // namespace detail

// NaN and infinity are told apart by their bit patterns (float and double), so validation
// holds under -ffast-math and -ffinite-math-only, where the compilers fold isnan(x) to false.
// The builtins (what <cmath> calls) serve long double, whose layout varies; they, too, are
// usable in constant expressions and raise no floating-point exception on NaN or infinity.
// docs/numerics.md says what still changes under those flags.

template <Real R>
[[nodiscard]] POINTMASS_HD constexpr bool real_isnan(R x) noexcept {
  if constexpr (detail::has_ieee_bits_v<R>) {
    using Bits = detail::FloatBits<R>;
    return (__builtin_bit_cast(typename Bits::type, x) & Bits::magnitude_mask) >
           Bits::exponent_mask;
  } else {
    return __builtin_isnan(x);
  }
}

template <Real R>
[[nodiscard]] POINTMASS_HD constexpr bool real_isfinite(R x) noexcept {
  if constexpr (detail::has_ieee_bits_v<R>) {
    using Bits = detail::FloatBits<R>;
    return (__builtin_bit_cast(typename Bits::type, x) & Bits::exponent_mask) !=
           Bits::exponent_mask;
  } else {
    return __builtin_isfinite(x);
  }
}

/// x == y, exactly. The library compares floating-point values for equality only where it
/// means an exact value: 0, 1 and infinity, cases a step treats apart (a tolerance there would
/// be wrong). The one comparison is here, with -Wfloat-equal silenced for that reason, so that
/// the headers build clean for a consumer compiling with -Wfloat-equal -Werror.
template <Real R>
[[nodiscard]] POINTMASS_HD constexpr bool real_equal(R x, R y) noexcept {
#if defined(__GNUC__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wfloat-equal"
#endif
  return x == y;
#if defined(__GNUC__)
#pragma GCC diagnostic pop
#endif
}

namespace detail {

/// x == y where neither is NaN and they are not zeros of opposite signs (a kept step length
/// against a new one: the kept one is never NaN or zero), as one integer comparison of the
/// bit patterns (float and double): x == y compiles to two branches on x86, one for the
/// unordered case, in a loop that may do nothing else besides a power function's call.
template <Real R>
POINTMASS_HD constexpr bool same_bits(R x, R y) noexcept {
  if constexpr (has_ieee_bits_v<R>) {
    using Bits = typename FloatBits<R>::type;
    return __builtin_bit_cast(Bits, x) == __builtin_bit_cast(Bits, y);
  } else {
    return real_equal(x, y);
  }
}

/// x == 0 (either sign), as one integer test of the bit pattern (float and double).
template <Real R>
POINTMASS_HD constexpr bool is_zero(R x) noexcept {
  if constexpr (has_ieee_bits_v<R>) {
    using Bits = FloatBits<R>;
    return (__builtin_bit_cast(typename Bits::type, x) & Bits::magnitude_mask) == 0;
  } else {
    return real_equal(x, R(0));
  }
}

}  // namespace detail

template <Real R>
[[nodiscard]] POINTMASS_HD constexpr R real_abs(R x) noexcept {
  if constexpr (std::same_as<R, float>) return __builtin_fabsf(x);
  else if constexpr (std::same_as<R, double>) return __builtin_fabs(x);
  else return __builtin_fabsl(x);
}

/// base^exponent in R: powf, pow or powl.
template <Real R>
[[nodiscard]] POINTMASS_HD inline R real_pow(R base, R exponent) noexcept {
  if constexpr (std::same_as<R, float>) return ::powf(base, exponent);
  else if constexpr (std::same_as<R, double>) return ::pow(base, exponent);
  else return ::powl(base, exponent);
}

namespace detail {

/// sqrt(x) correctly rounded (to nearest) for a finite x > 0, float or double, in integer
/// arithmetic that a constant expression can evaluate: x = m 2^e with e even, the integer
/// square root of m 4^s taken bit by bit with its remainder (the sticky bit), and the root
/// rounded once to R's digits. A square root is never halfway between two Reals, so the
/// result is IEEE's sqrt bit for bit.
template <Real R>
POINTMASS_HD constexpr R exact_sqrt(R x) noexcept {
  using Bits = typename FloatBits<R>::type;
  constexpr int digits = std::numeric_limits<R>::digits;  // 24 or 53, the implicit bit too
  constexpr int bias = std::numeric_limits<R>::max_exponent - 1;
  constexpr std::uint64_t implicit = std::uint64_t{1} << (digits - 1);
  const auto bits = static_cast<std::uint64_t>(__builtin_bit_cast(Bits, x));
  std::uint64_t m = bits & (implicit - 1);
  const int biased = static_cast<int>(bits >> (digits - 1));
  int e = 0;          // x = m 2^e
  if (biased == 0) {  // subnormal: normalise
    e = 1 - bias - (digits - 1);
    while ((m & implicit) == 0) {
      m <<= 1;
      --e;
    }
  } else {
    m |= implicit;
    e = biased - bias - (digits - 1);
  }
  if ((e & 1) != 0) {  // e even: sqrt(m 2^e) = sqrt(m) 2^(e/2); m < 2^(digits + 1)
    m <<= 1;
    --e;
  }
  // root = floor(sqrt(m 4^s)) >= 2^(digits + 1): two bits beyond R's for the rounding.
  constexpr int s = (digits + 4) / 2;
  std::uint64_t root = 0;
  std::uint64_t remainder = 0;
  for (int pair = (digits + 1) / 2 + s; pair >= 0; --pair) {  // m 4^s, two bits at a time
    const int shift = 2 * (pair - s);
    const std::uint64_t next = shift >= 0 ? (m >> shift) & 3u : 0u;
    remainder = (remainder << 2) | next;
    root <<= 1;
    const std::uint64_t trial = (root << 1) | 1u;
    if (remainder >= trial) {
      remainder -= trial;
      root |= 1u;
    }
  }
  int extra = 0;  // bits of root beyond R's digits
  while ((root >> (digits + extra)) != 0) ++extra;
  const std::uint64_t guard = (root >> (extra - 1)) & 1u;
  const bool sticky = remainder != 0 || (root & ((std::uint64_t{1} << (extra - 1)) - 1)) != 0;
  std::uint64_t mantissa = root >> extra;
  if (guard != 0 && (sticky || (mantissa & 1u) != 0)) ++mantissa;
  if (mantissa >> digits != 0) {  // rounded up to the next power of two
    mantissa >>= 1;
    ++extra;
  }
  const int exponent = e / 2 - s + extra + (digits - 1) + bias;  // always normal
  return __builtin_bit_cast(
      R, static_cast<Bits>((static_cast<std::uint64_t>(exponent) << (digits - 1)) |
                           (mantissa & (implicit - 1))));
}

}  // namespace detail

/// Square root in R; usable in constant expressions, where float and double take
/// detail::exact_sqrt (correctly rounded, as at run time) and long double Newton's iteration.
template <Real R>
[[nodiscard]] POINTMASS_HD constexpr R real_sqrt(R x) noexcept {
  if (std::is_constant_evaluated()) {
    if (!(x > R(0)) || !real_isfinite(x)) return real_equal(x, R(0)) || x > R(0) ? x : R(0) / R(0);
    if constexpr (detail::has_ieee_bits_v<R>) {
      return detail::exact_sqrt(x);
    } else {
      R root = x > R(1) ? x : R(1);
      for (;;) {
        const R next = (root + x / root) / R(2);
        if (!(next < root)) return root;
        root = next;
      }
    }
  }
  if constexpr (std::same_as<R, float>) return ::sqrtf(x);
  else if constexpr (std::same_as<R, double>) return ::sqrt(x);
  else return ::sqrtl(x);
}

/// Natural logarithm in R.
template <Real R>
[[nodiscard]] POINTMASS_HD inline R real_log(R x) noexcept {
  if constexpr (std::same_as<R, float>) return ::logf(x);
  else if constexpr (std::same_as<R, double>) return ::log(x);
  else return ::logl(x);
}

template <Real R>
[[nodiscard]] POINTMASS_HD inline R real_exp(R x) noexcept {
  if constexpr (std::same_as<R, float>) return ::expf(x);
  else if constexpr (std::same_as<R, double>) return ::exp(x);
  else return ::expl(x);
}

/// e^x - 1, accurate for small x (where exp(x) - 1 would cancel).
template <Real R>
POINTMASS_HD inline R real_expm1(R x) noexcept {
  if constexpr (std::same_as<R, float>) return ::expm1f(x);
  else if constexpr (std::same_as<R, double>) return ::expm1(x);
  else return ::expm1l(x);
}

template <Real R>
[[nodiscard]] POINTMASS_HD inline R real_sin(R x) noexcept {
  if constexpr (std::same_as<R, float>) return ::sinf(x);
  else if constexpr (std::same_as<R, double>) return ::sin(x);
  else return ::sinl(x);
}

template <Real R>
[[nodiscard]] POINTMASS_HD inline R real_cos(R x) noexcept {
  if constexpr (std::same_as<R, float>) return ::cosf(x);
  else if constexpr (std::same_as<R, double>) return ::cos(x);
  else return ::cosl(x);
}

template <Real R>
inline constexpr R real_infinity = std::numeric_limits<R>::infinity();

}  // namespace pointmass

namespace pointmass::inline POINTMASS_ABI_NAMESPACE {

/// How a duration type converts to a number of seconds; units.hpp specialises it for
/// Boost.Units times. A plain Real duration is already a number of seconds.
template <class T>
struct TimeTraits {
  POINTMASS_HD static constexpr T seconds(T t) noexcept { return t; }
};

/// The number of seconds in a duration, as the duration's Real.
template <class T>
[[nodiscard]] POINTMASS_HD constexpr scalar_t<T> in_seconds(const T& t) noexcept {
  return TimeTraits<T>::seconds(t);
}

}  // namespace pointmass
POINTMASS_DETAIL_UNFUSED_END
