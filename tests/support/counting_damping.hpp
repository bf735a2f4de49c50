// SPDX-License-Identifier: BSL-1.0
// Test support: per-second damping that counts how often its per-step factors (the power
// function) run, to see when a Particle or a ParticleSystem computes them and when it keeps
// them. (It states no order or exactness: a user's policy need not, and is taken as first
// order.)
#pragma once

#include <pointmass/damping.hpp>

namespace pointmass::test {

struct CountingPerSecond {
  template <Real R>
  using State = damping::PerSecond::State<R>;
  template <Real R>
  using Factors = damping::Retention<R>;
  static inline int factor_calls = 0;

  template <Real R, class T>
  static Factors<R> factors(const State<R>& state, const T& t) noexcept {
    ++factor_calls;
    return damping::PerSecond::factors(state, t);
  }
  template <class V, class A, class T, class R>
  static constexpr V velocity(const V& v0, const A& a, const T& t, const Factors<R>& f) noexcept {
    return damping::PerSecond::velocity(v0, a, t, f);
  }
};

}  // namespace pointmass::test
