// Compiled (not run) by the vectorisation tests: steps the common configurations so that
// the compiler's vectorisation report can be checked for the step loop of
// particle_system.hpp (see CMakeLists.txt). With POINTMASS_PROBE_BACKWARD it instantiates
// only the backward walk (step_range_backward), and no configuration with another loop
// (Lifetime's expiry pass), so a vectorised loop in the report can only be that walk's.
// With POINTMASS_PROBE_EXPONENTIAL=<loop> it compiles only that loop of the library's
// exponential (detail/exponential.hpp) over per-particle damping, a loop in this file:
//   1 pow_unit_loop<float>   2 pow_unit_loop<double>   (d^t, PerSecond's per-particle factor)
//   3 exp_unit_loop<float>   4 exp_unit_loop<double>   (d^t and d^t - 1, Exact's)
#if defined(POINTMASS_PROBE_EXPONENTIAL)
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
void exp_unit_loop(const detail::SplitLog<R>* ln_d, R* kept, R* kept_minus_one, std::size_t n, R t) {
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
template void exp_unit_loop<double>(const detail::SplitLog<double>*, double*, double*,
                                    std::size_t, double);
#endif

#else
#include <pointmass/particle_system.hpp>

namespace pm = pointmass;

namespace {

template <class System>
void probe(System& system, typename System::real t) {
#if defined(POINTMASS_PROBE_BACKWARD)
  System::step_range_backward(system.arrays(), 0, system.size(), system.step_parameters(t));
#else
  system.step(t);
#endif
}

}  // namespace

void step_sparks(pm::ParticleSystem<float>& system, float t) { probe(system, t); }
void step_sparks(pm::ParticleSystem<double>& system, double t) { probe(system, t); }
void step_undamped(pm::ParticleSystem<float, pm::damping::None>& system, float t) {
  probe(system, t);
}
#if defined(POINTMASS_PROBE_BACKWARD)
void step_featured(pm::ParticleSystem<float, pm::damping::PerFrame, pm::position::Kinematic,
                                      pm::features::PerParticleAcceleration,
                                      pm::features::Forces>& system,
                   float t) {
  probe(system, t);
}
#else
void step_featured(pm::ParticleSystem<float, pm::damping::PerFrame, pm::position::Kinematic,
                                      pm::features::PerParticleAcceleration,
                                      pm::features::Forces, pm::features::Lifetime>& system,
                   float t) {
  probe(system, t);
}
#endif
#endif  // POINTMASS_PROBE_EXPONENTIAL
