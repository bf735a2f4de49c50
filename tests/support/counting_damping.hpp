// SPDX-License-Identifier: BSL-1.0
// Test support: damping policies that count how often their per-step factors (the power
// function) run, to see when a Particle or a ParticleSystem computes them and when it keeps
// them. (It states no order or exactness: a user's policy need not, and is taken as first
// order.)
#pragma once

#include <pointmass/damping.hpp>

namespace pointmass::test {

/// Damping policy D, counting the factors a Particle or a ParticleSystem computes (D::factors,
/// and D::scalar_factors where D has one, as they call them). Its factors are D's, so a
/// particle with it computes what one with D does.
template <class D>
struct CountingFactors {
  template <Real R>
  using State = typename D::template State<R>;
  template <Real R>
  using Factors = typename D::template Factors<R>;
  static inline int factor_calls = 0;

  template <Real R, class T>
  static Factors<R> factors(const State<R>& state, const T& t) noexcept {
    ++factor_calls;
    return D::factors(state, t);
  }
  // clang-format off
  template <Real R, class T>
    requires(requires(const State<R>& state, const T& t) { D::scalar_factors(state, t); })
  // clang-format on
  static Factors<R> scalar_factors(const State<R>& state, const T& t) noexcept {
    ++factor_calls;
    return D::scalar_factors(state, t);
  }
  template <class V, class A, class T, class R>
  static constexpr V velocity(const V& v0, const A& a, const T& t, const Factors<R>& f) noexcept {
    return D::velocity(v0, a, t, f);
  }
};

using CountingPerSecond = CountingFactors<damping::PerSecond>;

}  // namespace pointmass::test
