// SPDX-License-Identifier: BSL-1.0
// Compiled (not run) by the vectorisation tests: steps one configuration, the system type
// POINTMASS_PROBE_SYSTEM given on the command line, so that the compiler's vectorisation
// report can only be about that configuration's loops (the list of configurations is in
// CMakeLists.txt). With POINTMASS_PROBE_BACKWARD it instantiates only the backward walk
// (step_range_backward), and no other loop (Lifetime's expiry pass), so a vectorised loop
// in the report can only be that walk's. With POINTMASS_PROBE_EXPIRY it instantiates only
// finish_step, whose expiry pass scans a block of particles for an expired one. With
// POINTMASS_PROBE_LAWS it steps with every library law (the law pass, detail/law_pass.hpp).
// With POINTMASS_PROBE_RELATIVE it compiles only copy_positions(out, origin) of a system with double
// positions, or with POINTMASS_PROBE_COMPENSATED as well of one with compensated positions
// (the renderer's hand-off from wide positions; round_via_odd has no branch).
// With POINTMASS_PROBE_EXPONENTIAL=<loop> it compiles only that loop of the library's
// exponential (detail/exponential.hpp) over per-particle damping, a loop in this file:
//   1 pow_unit_loop<float>   2 pow_unit_loop<double>   (d^t, PerSecond's per-particle factor)
//   3 exp_unit_loop<float>   4 exp_unit_loop<double>   (d^t and d^t - 1, Exact's)
#if defined(POINTMASS_PROBE_RELATIVE)
#include <span>

#include <pointmass/particle_system.hpp>

namespace pm = pointmass;

#if defined(POINTMASS_PROBE_COMPENSATED)
using Probed = pm::Precision<float, pm::Compensated<float>>;
#else
using Probed = pm::Precision<float, double>;
#endif

void relative_probe(const pm::ParticleSystem<Probed>& system, const pm::Vector3<double>& camera,
                    std::span<pm::Vector3<float>> offsets) {
  system.copy_positions(offsets, camera);
}

#elif defined(POINTMASS_PROBE_EXPONENTIAL)
#include <cstddef>

#include <pointmass/detail/exponential.hpp>

namespace detail = pointmass::detail;

// The trip count a multiple of 16 and the arrays independent, as the system's step loop.
template <class R>
void pow_unit_loop(const detail::SplitLog<R>* ln_d, R* out, std::size_t n, R t) {
  const std::size_t m = n - n % 16;
#if defined(__clang__)
#pragma clang loop vectorize(assume_safety)
#else
#pragma GCC ivdep
#endif
  for (std::size_t i = 0; i < m; ++i) out[i] = detail::pow_unit(ln_d[i], t);
}

template <class R>
void exp_unit_loop(const detail::SplitLog<R>* ln_d, R* kept, R* kept_minus_one, std::size_t n,
                   R t) {
  const std::size_t m = n - n % 16;
#if defined(__clang__)
#pragma clang loop vectorize(assume_safety)
#else
#pragma GCC ivdep
#endif
  for (std::size_t i = 0; i < m; ++i) {
    const auto power = detail::exp_unit(ln_d[i], t);
    kept[i] = power.kept;
    kept_minus_one[i] = power.kept_minus_one;
  }
}

#if POINTMASS_PROBE_EXPONENTIAL == 1
template void pow_unit_loop<float>(const detail::SplitLog<float>*, float*, std::size_t, float);
#elif POINTMASS_PROBE_EXPONENTIAL == 2
template void pow_unit_loop<double>(const detail::SplitLog<double>*, double*, std::size_t, double);
#elif POINTMASS_PROBE_EXPONENTIAL == 3
template void exp_unit_loop<float>(const detail::SplitLog<float>*, float*, float*, std::size_t,
                                   float);
#elif POINTMASS_PROBE_EXPONENTIAL == 4
template void exp_unit_loop<double>(const detail::SplitLog<double>*, double*, double*, std::size_t,
                                    double);
#endif

#else
#include <pointmass/forces.hpp>
#include <pointmass/particle_system.hpp>

namespace pm = pointmass;

#if !defined(POINTMASS_PROBE_SYSTEM)
#error "POINTMASS_PROBE_SYSTEM (a ParticleSystem type) must be defined"
#endif

using ProbedSystem = POINTMASS_PROBE_SYSTEM;

void step_probe(ProbedSystem& system, ProbedSystem::real t) {
#if defined(POINTMASS_PROBE_LAWS)
  using R = ProbedSystem::real;  // every library law, fused into the step (the law pass)
  namespace forces = pointmass::forces;
  system.step(t, forces::laws(forces::Gravity<R>(), forces::Drag<R>(R(0.1), R(0.01)),
                              forces::AnchoredSpring<R>({R(0), R(2), R(0)}, R(4), R(1)),
                              forces::AnchoredBungee<R>({R(1), R(2), R(0)}, R(4), R(1)),
                              forces::Buoyancy<R>(R(0.5), R(0.1), R(0))));
#elif defined(POINTMASS_PROBE_EXPIRY)
  static_cast<void>(t);
  system.finish_step();  // the expiry pass alone
#elif defined(POINTMASS_PROBE_BACKWARD)
  pointmass::detail::SystemAccess::Kernel<ProbedSystem>::step_range_backward(
      pointmass::detail::SystemAccess::arrays(system), 0, system.size(), system.step_parameters(t));
#else
  system.step(t);
#endif
}
#endif  // POINTMASS_PROBE_EXPONENTIAL
