// SPDX-License-Identifier: BSL-1.0
// pointmass/precision.hpp — the precision of a particle's position, chosen apart from the
// precision of everything else.
//
//   first template argument                      arithmetic  position stored as     per particle
//   float                  (today)               float       float                  3 floats
//   double                 (today)               double      double                 3 doubles
//   Precision<float, double>                     float       double                 3 doubles
//   Precision<float, Compensated<float>>         float       float + float error    6 floats
//   Precision<float>       is float, Precision<double> is double (the same types)
//
// Velocity, acceleration, damping, mass, force and the step's arithmetic use the first
// argument; only the stored position uses the second. A step computes the displacement
// exactly as the all-float particle would (the position policy applied from p0 = -0 in the
// arithmetic precision: -0 + x is x, every bit, so nothing is added for the origin) and adds
// it to the stored position in the position's precision:
//
//   d  = P::position(-0, v0, v1, a, t, f)        in float: the same float inputs as today
//   p1 = p0 + d                                  in double, or compensated:
//   Compensated<float>, hi + lo:  y = d + lo;  s = hi + y;  lo = y - (s - hi);  hi = s
//     (Dekker's Fast2Sum: lo carries what hi could not hold, and the next step adds it back,
//      as compensated summation does. Exact, the error-free sum, whenever hi's exponent is at
//      least y's, which is every step of a particle farther from the origin than one step's
//      displacement; on a step nearer, hi + y loses at most a float ulp of y, about what
//      rounding y = d + lo already may. Three additions fewer than TwoSum, a third of the
//      compensated step's arithmetic: docs/large-worlds.md)
//
// So far from the origin the position loses only what the wide storage rounds (about 1e-10 m
// a step at 1e6 m), not the 1/32 m a float rounds there. Near the origin the velocities are
// bit for bit those of the all-float particle, and the positions differ only by the float
// rounding that all-float makes and the wide storage does not.
//
// A wide position is read and set as its value type (`position_value_t`): double for double
// and for Compensated<float> (hi + lo rounded to double; a set double is split into hi and
// lo), long double for Compensated<double>. A renderer wants a float position relative to
// its camera: `position_relative_to(origin)` (Particle) and `copy_positions(out,
// origin)` (ParticleSystem) compute it from the full stored position, exact wherever the true
// offset is a float.
//
// Owns: Precision<R, Position>, Compensated<R>, and how such a position is stored, stepped
// and read relative to an origin (detail::PositionStorage).
// Must not include: anything but config.hpp and real.hpp (it is below the quantities).
#pragma once

#include <concepts>
#include <limits>
#include <type_traits>

#include "config.hpp"
#include "real.hpp"

POINTMASS_DETAIL_UNFUSED_BEGIN
namespace pointmass::inline POINTMASS_ABI_NAMESPACE {

/// A position stored as two R: the rounded position and the rounding error carried forward.
/// Twice R's storage, nearly twice its digits; steps in R's own arithmetic (no wider type).
template <Real R>
struct Compensated {
  using value_type = R;
};

namespace detail {

template <class T>
inline constexpr bool is_compensated_v = false;
template <class R>
inline constexpr bool is_compensated_v<Compensated<R>> = true;

template <class T>
struct CompensatedOf {
  using type = void;
};
template <class R>
struct CompensatedOf<Compensated<R>> {
  using type = R;
};

}  // namespace detail

/// A position precision usable with arithmetic R: a Real with at least R's digits, or
/// Compensated<R> of R itself.
template <class Position, class R>
concept PositionPrecision = Real<R> &&
    ((Real<Position> && std::numeric_limits<Position>::digits >= std::numeric_limits<R>::digits) ||
     std::same_as<typename detail::CompensatedOf<Position>::type, R>);

namespace detail {

/// One sentence for a mismatched pair, instead of a page of unmet constraints.
template <class R, class Position>
constexpr bool check_position_precision() {
  static_assert(PositionPrecision<Position, R>,
                "Precision<Real, Position>: the position must be a Real at least as wide as "
                "Real (Precision<float, double>) or Compensated<Real> of the same Real "
                "(Precision<float, Compensated<float>>); a narrower position would round away "
                "what the step computes");
  return true;
}

/// Arithmetic in R, positions stored as Position (see the file comment): what
/// Precision<R, Position> names when Position is not R (a user names only Precision).
template <Real R, class Position>
struct PositionsStoredAs {
  static_assert(check_position_precision<R, Position>());
  using real = R;
  using position = Position;
};

}  // namespace detail

/// The precision of a particle: arithmetic in R, positions stored as Position. Give it as the
/// first template argument of Particle, ParticleSystem or units::Particle. Precision<R> (and
/// Precision<R, R>) is R itself, so today's spellings are today's types and a Particle<R>
/// still lets generic code deduce R.
template <Real R, class Position = R>
using Precision =
    std::conditional_t<std::is_same_v<R, Position>, R, detail::PositionsStoredAs<R, Position>>;

namespace detail {

// Plain specialisations, without constraints: g++ 12 chose constrained partial
// specialisations here nondeterministically (a build failed about once in ten compiles).
template <class S>
struct PrecisionTraits {};
template <class R>
struct RealPrecision {
  using real = R;
  using position = R;
};
template <>
struct PrecisionTraits<float> : RealPrecision<float> {};
template <>
struct PrecisionTraits<double> : RealPrecision<double> {};
template <>
struct PrecisionTraits<long double> : RealPrecision<long double> {};
// Read through Precision's members, so that naming a mismatched Precision anywhere stops at
// its one sentence (the static_assert in its body).
template <class R, class Position>
struct PrecisionTraits<PositionsStoredAs<R, Position>> {
  using real = typename PositionsStoredAs<R, Position>::real;
  using position = typename PositionsStoredAs<R, Position>::position;
};

}  // namespace detail

/// What a particle's first template argument may be: a Real, or a Precision<R, Position>
/// whose position fits R.
template <class S>
concept PrecisionChoice = requires {
  typename detail::PrecisionTraits<S>::real;
  typename detail::PrecisionTraits<S>::position;
}
&&PositionPrecision<typename detail::PrecisionTraits<S>::position,
                    typename detail::PrecisionTraits<S>::real>;

/// The arithmetic Real of a precision choice (velocity, acceleration, mass, time, ...).
template <class S>
using real_of_t = typename detail::PrecisionTraits<S>::real;
/// The position precision of a choice: a Real or Compensated<R>.
template <class S>
using position_precision_of_t = typename detail::PrecisionTraits<S>::position;
/// A choice in its shortest spelling: Precision<R, R> is R.
template <class S>
using canonical_precision_t =
    std::conditional_t<std::is_same_v<real_of_t<S>, position_precision_of_t<S>>, real_of_t<S>,
                       Precision<real_of_t<S>, position_precision_of_t<S>>>;

namespace detail {

/// round_once where z overflowed T (y is static_cast<T>(z), infinite): only a z exactly halfway
/// between the largest T and the next power of two, with x short of it (r pointing back
/// towards zero), rounds to the largest T.
template <Real T, Real W>
POINTMASS_HD constexpr T round_once_overflowed(T y, W z, W r) noexcept {
  using Bits = typename FloatBits<T>::type;
  const T largest = std::numeric_limits<T>::max();
  const T below = __builtin_bit_cast(T, static_cast<Bits>(__builtin_bit_cast(Bits, largest) - 1u));
  const W midpoint =
      static_cast<W>(largest) + (static_cast<W>(largest) - static_cast<W>(below)) / W(2);
  if (real_equal(z, midpoint) && r < W(0)) return largest;
  if (real_equal(z, -midpoint) && r > W(0)) return -largest;
  return y;
}

/// x = z + r rounded once to T, for z of a wider Real W, where z is x rounded to nearest in W
/// and r has the sign of x - z (0 when z is x): static_cast<T>(z) unless z lies halfway
/// between two T (a T midpoint is a W, so only there can rounding z differ from rounding x);
/// there the neighbour on r's side. Where W is no wider than T, z itself.
template <Real T, Real W>
POINTMASS_HD constexpr T round_once(W z, W r) noexcept {
  if constexpr (std::numeric_limits<W>::digits <= std::numeric_limits<T>::digits) {
    return static_cast<T>(z);
  } else {
    const T y = static_cast<T>(z);
    if (real_equal(r, W(0))) return y;
    using Bits = typename FloatBits<T>::type;
    if (!real_isfinite(y)) return round_once_overflowed(y, z, r);
    const W d = z - static_cast<W>(y);  // exact: z and y are within half an ulp of T
    if (real_equal(d, W(0))) return y;
    // y's neighbour on z's side, by its bits (T is float or double where W is wider).
    const Bits bits = __builtin_bit_cast(Bits, y);
    const Bits smallest_negative = static_cast<Bits>(FloatBits<T>::magnitude_mask + 2u);
    const bool outward = (d > W(0)) == (y > T(0));
    const Bits next_bits = real_equal(y, T(0)) ? (d > W(0) ? Bits{1} : smallest_negative)
                                               : static_cast<Bits>(outward ? bits + 1u : bits - 1u);
    const T next = __builtin_bit_cast(T, next_bits);
    if (!real_equal(static_cast<W>(next) - static_cast<W>(y), d + d)) return y;  // no tie
    return (r > W(0)) == (d > W(0)) ? next : y;  // x beyond the midpoint, or before it
  }
}

/// The same result as round_once<T>(z, r), without a branch, so that a loop over many offsets
/// (copy_positions(out, origin)) vectorises and does not mispredict: z is first rounded to odd in W
/// (z itself when exact or when its last bit is odd, else its neighbour on r's side, the other W
/// around x), then to nearest in T. Rounding to odd with at least two more digits than T's and then
/// to nearest rounds once: every T and every midpoint between two T (the boundaries of rounding to
/// nearest, overflow's included) is a W with an even last bit, so an odd W lies strictly on x's
/// side of each. z must be x rounded to nearest in W (or either W around x), r of the sign of x -
/// z; z = 0 is taken as exact (x is then too small for any T but 0), and an infinite z or a NaN r
/// as z. For W of IEEE bits only (float or double) with T at least two digits narrower; round_once
/// otherwise.
template <Real T, Real W>
POINTMASS_HD constexpr T round_via_odd(W z, W r) noexcept {
  if constexpr (!has_ieee_bits_v<W> ||
                std::numeric_limits<W>::digits < std::numeric_limits<T>::digits + 2) {
    return round_once<T>(z, r);
  } else {
    using Bits = typename FloatBits<W>::type;
    constexpr int sign_shift = int(sizeof(W) * 8 - 1);
    const Bits bits = __builtin_bit_cast(Bits, z);
    // 1 when z is inexact (r nonzero, z nonzero and finite) and its last bit is even.
    const W magnitude =
        __builtin_bit_cast(W, static_cast<Bits>(bits & FloatBits<W>::magnitude_mask));
    // (& and |, not && and ||: no branch for a loop's vectoriser to give up on)
    const bool inexact = ((r < W(0)) | (r > W(0))) & (magnitude > W(0)) &
                         (magnitude <= std::numeric_limits<W>::max());
    const Bits step = static_cast<Bits>(inexact) & ~bits & Bits{1};
    // Towards x: magnitude up when r has z's sign (bits + 1), down otherwise (bits - 1).
    const Bits down = static_cast<Bits>((__builtin_bit_cast(Bits, r) ^ bits) >> sign_shift);
    const Bits odd = static_cast<Bits>(bits + step - ((step & down) << 1));
    return static_cast<T>(__builtin_bit_cast(W, odd));
  }
}

/// round_via_odd where BranchFree (a loop over many offsets, whose branches would mispredict
/// and keep it from vectorising), round_once otherwise (one offset at a time: its branches
/// predict, and it costs less). The same T either way.
template <Real T, bool BranchFree, Real W>
POINTMASS_HD constexpr T round_offset(W z, W r) noexcept {
  if constexpr (BranchFree) return round_via_odd<T>(z, r);
  else return round_once<T>(z, r);
}

/// How a position of precision Position is stored and stepped. For a Real: one number.
template <class Position>
struct PositionStorage {
  /// The element of the position columns.
  using element = Position;
  /// What position() returns and set_position takes (per component).
  using value = Position;
  /// True when an error term is stored beside each component.
  static constexpr bool compensated = false;

  /// p + d, the displacement d (in the arithmetic's Real) added in the position's precision.
  template <Real R>
  POINTMASS_HD static constexpr void add(element& p, R d) noexcept {
    p = p + static_cast<element>(d);
  }
  POINTMASS_HD static constexpr value value_of(element p) noexcept { return p; }
  /// The stored component of a value (the value is already finite).
  POINTMASS_HD static constexpr element element_of(value x) noexcept { return x; }
  /// p - origin, rounded once to T (float for a renderer, the arithmetic's Real for a force
  /// generator): the difference s rounded in the element's precision, its error e (TwoSum,
  /// exact) and round_offset(s, e) (round_once, or round_via_odd: the same T without a
  /// branch), so a difference rounded to an element and then to T is not rounded twice.
  /// Exact when the true offset is a T (then it is an element too, and IEEE subtraction
  /// returns it exactly). A T wider than the element takes the difference in T: rounded once
  /// there, not first to the element.
  template <Real T = float, bool BranchFree = false>
  POINTMASS_HD static constexpr T relative(element p, value origin) noexcept {
    if constexpr (std::numeric_limits<element>::digits < std::numeric_limits<T>::digits) {
      return static_cast<T>(p) - static_cast<T>(origin);
    } else if constexpr (std::numeric_limits<element>::digits == std::numeric_limits<T>::digits) {
      return static_cast<T>(p - origin);
    } else {
      POINTMASS_DETAIL_IN_ORDER  // TwoSum: reordered, e would be 0 (config.hpp)
      const element s = p - origin;
      const element b = s - p;
      const element e = (p - (s - b)) + (-origin - b);
      return round_offset<T, BranchFree>(s, e);
    }
  }
};

/// The next wider Real: what a pair of R is read as.
template <class R>
using wider_real_t = std::conditional_t<std::is_same_v<R, float>, double, long double>;

/// A Compensated<R> position: hi (the element) and lo (the error term), hi + lo.
template <class R>
struct PositionStorage<Compensated<R>> {
  using element = R;
  using value = wider_real_t<R>;
  static constexpr bool compensated = true;
  /// R's largest plus half its ulp, 2^(max_exponent - digits - 1): the midpoint between the
  /// largest R and the next power of two, the most a pair's hi + lo reaches (element_of).
  static constexpr value beyond_largest = [] {
    auto half_ulp = value(1);
    for (int i = 0; i < std::numeric_limits<R>::max_exponent - std::numeric_limits<R>::digits - 1;
         ++i) {
      half_ulp *= value(2);
    }
    return static_cast<value>(std::numeric_limits<R>::max()) + half_ulp;
  }();

  /// (hi, lo) + d. y = d + lo is the step's displacement with the carried error; Fast2Sum
  /// adds it to hi and leaves in lo what the new hi could not hold: exactly when hi's
  /// exponent is at least y's (s - hi is then exact), and within an ulp of y otherwise.
  POINTMASS_HD static constexpr void add(R& hi, R& lo, R d) noexcept {
    POINTMASS_DETAIL_IN_ORDER  // Fast2Sum: reordered, lo would be 0 (config.hpp)
    const R y = d + lo;
    const R s = hi + y;
    lo = y - (s - hi);
    hi = s;
  }
  POINTMASS_HD static constexpr value value_of(R hi, R lo) noexcept {
    return static_cast<value>(hi) + static_cast<value>(lo);
  }
  /// The rounded part of a value (the error part: error_of): x rounded to R, except that a
  /// value above R's largest, up to the midpoint above it (which rounds to infinity), keeps
  /// the largest as hi (what is left, at most half its ulp, is an R). So a pair with a finite
  /// hi and lo within half hi's ulp, as a split leaves, gives a hi + lo (the midpoint
  /// included) that splits again into a finite pair: position() set back is taken. Beyond
  /// the midpoint: infinity, which the setters refuse.
  POINTMASS_HD static constexpr R element_of(value x) noexcept {
    constexpr R largest = std::numeric_limits<R>::max();
    const value magnitude = x < value(0) ? -x : x;
    if (magnitude > static_cast<value>(largest) && magnitude <= beyond_largest) {
      return x < value(0) ? -largest : largest;
    }
    return static_cast<R>(x);
  }
  /// What x holds beyond element_of(x), rounded to R. A zero x is its own error part, so that
  /// hi + lo keeps the sign of a zero set (-0 - -0 is +0, and -0 + +0 would read back +0).
  POINTMASS_HD static constexpr R error_of(value x) noexcept {
    const value rest = x - static_cast<value>(element_of(x));
    return static_cast<R>(real_equal(x, value(0)) ? x : rest);
  }
  /// hi + lo - origin: hi - origin = s + e exactly (TwoSum), s + lo = s2 + e2 exactly
  /// (TwoSum), and the offset is s2 + e + e2: e + e2 = t + te and s2 + t = z + ze (TwoSum
  /// each), so the offset is z + (ze + te), z the offset rounded to the wider type (within
  /// what te, tiny beside it, moves) and ze + te the sign of what it rounded away;
  /// round_offset rounds it to T (float, or R) once. For a camera near the particle
  /// (|origin| within a factor of two of |hi|) e is 0; an offset that is a T comes out
  /// exact. Where hi + lo is itself a wider number (lo within the wider type's digits of hi,
  /// as a set position's split and the usual steps leave it), one TwoSum of it and origin
  /// does the same.
  template <Real T = float, bool BranchFree = false>
  POINTMASS_HD static constexpr T relative(R hi, R lo, value origin) noexcept {
    POINTMASS_DETAIL_IN_ORDER  // TwoSums: reordered, their errors would be 0 (config.hpp)
    if constexpr (std::numeric_limits<value>::digits < std::numeric_limits<T>::digits) {
      // T wider than the pair's value: hi + lo is a T (as it is a value), and the difference
      // in T is rounded once there.
      return (static_cast<T>(hi) + static_cast<T>(lo)) - static_cast<T>(origin);
    }
    const auto h = static_cast<value>(hi);
    const auto l = static_cast<value>(lo);
    // The usual case first: hi + lo held exactly by the wider type (lo within its digits of
    // hi; TwoSum's error says so), so the offset is p - origin, one TwoSum and round_once.
    // Not in a loop over many offsets (BranchFree): there the branch kept the loop from
    // vectorising, and the full road below, which gives the same result for every pair,
    // vectorised costs less than half the time of the two roads with the branch.
    if constexpr (!BranchFree) {
      const value p = h + l;
      const value bp = p - h;
      if (real_equal((h - (p - bp)) + (l - bp), value(0))) {
        const value s = p - origin;
        const value b = s - p;
        return round_offset<T, BranchFree>(s, (p - (s - b)) + (-origin - b));
      }
    }
    // Each error term is taken negated (TwoSum's subtractions reversed, as exact), so that
    // where every one is zero they come out +0 and z = s2 - +0 keeps s2's zero: -0 (only for
    // hi = lo = -0 and a +0 origin) as the road above and IEEE's -0 - +0 give it. With the
    // terms added, s2 + +0 turned that -0 into +0.
    const value s = h - origin;
    const value b = s - h;
    const value ne = ((s - b) - h) + (b + origin);  // -e: hi - origin = s + e
    const value s2 = s + l;
    const value b2 = s2 - s;
    const value ne2 = ((s2 - b2) - s) + (b2 - l);  // -e2: s + lo = s2 + e2
    const value nt = ne + ne2;                     // -t, rounded: e + e2 = t + te
    const value bt = nt - ne;
    const value nte = ((nt - bt) - ne) + (bt - ne2);  // -te
    const value z = s2 - nt;                          // s2 + t = z + ze
    const value bz = z - s2;
    const value ze = (s2 - (z - bz)) - (nt + bz);
    return round_offset<T, BranchFree>(z, ze - nte);
  }
};

}  // namespace detail

/// What a position of precision choice S is read and set as, per component.
template <class S>
using position_value_t = typename detail::PositionStorage<position_precision_of_t<S>>::value;

}  // namespace pointmass
POINTMASS_DETAIL_UNFUSED_END
