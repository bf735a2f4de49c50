// SPDX-License-Identifier: BSL-1.0
// Test support: comparisons with tolerances in units of the type's epsilon.
#pragma once

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>

#include <pointmass/vector3.hpp>

namespace pointmass::test {

/// |a - b| <= ulps * epsilon * max(|a|, |b|, floor): a relative bound, with an absolute floor
/// (in the same units as a and b) for values near zero.
template <class R>
bool close(R a, R b, std::type_identity_t<R> ulps, std::type_identity_t<R> floor = R(1)) {
  const R scale = std::max({std::abs(a), std::abs(b), floor});
  return std::abs(a - b) <= ulps * std::numeric_limits<R>::epsilon() * scale;
}

template <class R>
bool close(const Vector3<R>& a, const Vector3<R>& b, std::type_identity_t<R> ulps,
           std::type_identity_t<R> floor = R(1)) {
  return close(a.x, b.x, ulps, floor) && close(a.y, b.y, ulps, floor) &&
         close(a.z, b.z, ulps, floor);
}

}  // namespace pointmass::test

namespace doctest {
template <class T>
struct StringMaker<pointmass::Vector3<T>> {
  static String convert(const pointmass::Vector3<T>& v) {
    return String("(") + toString(v.x) + ", " + toString(v.y) + ", " + toString(v.z) + ")";
  }
};
}  // namespace doctest

/// Checks a == b within `ulps` epsilons (relative, floor 1), printing both on failure.
#define POINTMASS_CHECK_CLOSE(a, b, ulps)                    \
  do {                                                       \
    const auto pm_lhs_ = (a);                                \
    const auto pm_rhs_ = (b);                                \
    INFO("lhs = ", pm_lhs_, ", rhs = ", pm_rhs_);            \
    CHECK(::pointmass::test::close(pm_lhs_, pm_rhs_, ulps)); \
  } while (false)
