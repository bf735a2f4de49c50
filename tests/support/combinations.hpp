// SPDX-License-Identifier: BSL-1.0
// Test support: every precision x damping x position combination, as a type list for
// doctest's TEST_CASE_TEMPLATE_APPLY, and an independent long double oracle of one step of
// each policy's equation (written from the equations, not from the library's code).
#pragma once

#include <cmath>
#include <tuple>
#include <type_traits>

#include <pointmass/particle.hpp>

namespace pointmass::test {

template <class R, class D, class P>
struct Combination {
  using real = R;
  using damping = D;
  using position = P;
  using particle = Particle<R, D, P>;
};

template <class R, class D>
using WithEveryPosition = std::tuple<Combination<R, D, position::Euler>,
                                     Combination<R, D, position::ConstantAcceleration>,
                                     Combination<R, D, position::SemiImplicit>>;

template <class... Tuples>
using Concat = decltype(std::tuple_cat(std::declval<Tuples>()...));

template <class R>
using CombinationsOf =
    Concat<WithEveryPosition<R, damping::None>, WithEveryPosition<R, damping::PerFrame>,
           WithEveryPosition<R, damping::PerSecond>,
           WithEveryPosition<R, damping::AccelerateThenDamp>, WithEveryPosition<R, damping::Exact>,
           std::tuple<Combination<R, damping::Exact, position::Exact>,
                      Combination<R, damping::None, position::Exact>>>;

/// All 51 combinations: float, double and long double, 17 each.
using AllCombinations =
    Concat<CombinationsOf<float>, CombinationsOf<double>, CombinationsOf<long double>>;

/// One step of the model in long double, from the equations (SPEC.md):
/// d is the damping value, t the step, a the resulting acceleration.
struct OracleState {
  long double p[3];
  long double v[3];
};

template <class D, class P>
OracleState oracle_step(const OracleState& s, const long double (&a)[3], long double d,
                        long double t) {
  OracleState out{};
  const long double k = std::log(d);  // per-second rate (only where used)
  for (int i = 0; i < 3; ++i) {
    const long double v0 = s.v[i];
    long double v1 = 0;
    if constexpr (std::is_same_v<D, damping::None>) v1 = v0 + a[i] * t;
    else if constexpr (std::is_same_v<D, damping::PerFrame>) v1 = v0 * d + a[i] * t;
    else if constexpr (std::is_same_v<D, damping::PerSecond>) v1 = v0 * std::pow(d, t) + a[i] * t;
    else if constexpr (std::is_same_v<D, damping::AccelerateThenDamp>)
      v1 = (v0 + a[i] * t) * std::pow(d, t);
    else if constexpr (std::is_same_v<D, damping::Exact>)
      v1 = d == 1 ? v0 + a[i] * t : v0 * std::pow(d, t) + a[i] * std::expm1(k * t) / k;

    long double p1 = 0;
    if constexpr (std::is_same_v<P, position::Euler>) p1 = s.p[i] + v0 * t;
    else if constexpr (std::is_same_v<P, position::ConstantAcceleration>)
      p1 = s.p[i] + v0 * t + a[i] * t * t / 2;
    else if constexpr (std::is_same_v<P, position::SemiImplicit>) p1 = s.p[i] + v1 * t;
    else if constexpr (std::is_same_v<P, position::Exact>) {
      // p1 = p0 + v0 t phi1(x) + a t^2 phi2(x), x = k t, phi1 = (e^x - 1) / x,
      // phi2 = (e^x - 1 - x) / x^2; their Taylor series where x is tiny (no cancellation),
      // summed until the terms no longer change the sums: a fixed number of terms would hold
      // for one long double (x87's 64 bits) and fall short of another (a 113-bit quad).
      const long double x = std::is_same_v<D, damping::None> || d == 1 ? 0.0L : k * t;
      long double phi1 = 1, phi2 = 0.5L;
      if (std::fabs(x) < 1e-3L) {
        phi1 = 0;
        phi2 = 0;
        long double term1 = 1, term2 = 0.5L;  // x^n / (n + 1)! and x^n / (n + 2)!
        for (int n = 0; n < 64 && (phi1 + term1 != phi1 || phi2 + term2 != phi2); ++n) {
          phi1 += term1;
          phi2 += term2;
          term1 *= x / static_cast<long double>(n + 2);
          term2 *= x / static_cast<long double>(n + 3);
        }
      } else if (std::isinf(x)) {
        phi1 = 0;
        phi2 = 0;
      } else {
        phi1 = std::expm1(x) / x;
        phi2 = (std::expm1(x) - x) / (x * x);
      }
      p1 = s.p[i] + v0 * t * phi1 + a[i] * t * t * phi2;
    }
    out.p[i] = p1;
    out.v[i] = v1;
  }
  return out;
}

}  // namespace pointmass::test
