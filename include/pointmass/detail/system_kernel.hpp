// SPDX-License-Identifier: BSL-1.0
// pointmass/detail/system_kernel.hpp — the step of a ParticleSystem's arrays.
//
// Owns: what a step shares (StepParameters), the step of one particle (step_particle), the
// vectorised loop over a segment of particles, and the forward and backward walks
// (step_range, step_range_backward). All static: the kernel holds no data, so a CUDA, Thrust
// or Kokkos loop over step_particle runs the same arithmetic as ParticleSystem::step.
//
// Vectorisation: the step loop runs over a trip count that is a multiple of vector_block (the
// rest apart) and tells the compiler its arrays do not overlap (`#pragma GCC ivdep`, or
// clang's `vectorize(assume_safety)`), so g++ and clang vectorise it at plain -O2 as well as
// at -O3; -march=native (or -mavx2 -mfma) widens the vectors. See docs/performance.md. Not on
// 32-bit ARM with clang: its vector unit (NEON) does not keep IEEE arithmetic, so clang does not
// vectorise floating-point loops there, and a hint it cannot honour warns (-Wpass-failed) in
// the user's build.
//
// Traversal: while the arrays take more than `alternation_floor_bytes` (32 KiB) and at most
// `alternation_limit_bytes` (8 MiB), ParticleSystem::step walks the particles forwards and
// backwards in turn, so each step begins on the data the previous one left in cache.
//
// Must not include: particle_system.hpp, parallel.hpp (the kernel is below the public API).
#pragma once

#include <cstddef>
#include <cstdint>
#include <type_traits>

#include "../config.hpp"
#include "../damping.hpp"
#include "../particle.hpp"
#include "../position.hpp"
#include "../real.hpp"
#include "../vector3.hpp"
#include "exponential.hpp"
#include "law_pass.hpp"
#include "movable_step.hpp"
#include "validate.hpp"

#if defined(__clang__) && !defined(__arm__)
#define POINTMASS_DETAIL_INDEPENDENT_ITERATIONS _Pragma("clang loop vectorize(assume_safety)")
#elif defined(__GNUC__) && !defined(__clang__)
#define POINTMASS_DETAIL_INDEPENDENT_ITERATIONS _Pragma("GCC ivdep")
#else
#define POINTMASS_DETAIL_INDEPENDENT_ITERATIONS
#endif

// The step kernel is inlined into its loop at any -O level: a call stops vectorisation.
POINTMASS_DETAIL_UNFUSED_BEGIN
namespace pointmass::inline POINTMASS_ABI_NAMESPACE::detail {

struct NoFactors {};

// Adds a step of t to an age kept as age + error (Kahan's sum): the steps' exact sum.
template <class R>
POINTMASS_HD constexpr void count_age(R& age, R& error, R t) noexcept {
  POINTMASS_DETAIL_IN_ORDER  // reordered, the error would be 0 (config.hpp)
  const R step = t + error;
  const R sum = age + step;
  error = step - (sum - age);  // exact while age >= step; 0 on the first step
  age = sum;  // once it overflows, age + error is NaN: lifetime_expired reads that as expired
}

// A particle of this age (age + error, count_age; NaN once it overflowed) and lifetime has
// expired (an infinite lifetime never does). Branch free, so that the block scan vectorises.
template <class R>
POINTMASS_HD constexpr bool lifetime_expired(R age, R error, R lifetime) noexcept {
  return !(age + error < lifetime) & (lifetime < real_infinity<R>);
}

// P is checked by ParticleSystem (detail::check_policy_pair), with one sentence.
template <Real R, DampingPolicy D, class P, class Layout>
class SystemKernel {
 public:
  using Arrays = typename Layout::Arrays;
  using damping_factors = damping_factors_t<D, R>;
  using position_storage = typename Layout::position_storage;
  using position_element = typename Layout::position_element;
  static constexpr bool plain_positions =
      std::is_same_v<position_element, R> && !Layout::compensated_positions;

  /// What every particle's step shares: the duration, uniform damping factors and acceleration.
  struct StepParameters {
    R duration{};
    [[no_unique_address]] std::conditional_t<Layout::per_particle_damping, NoFactors,
                                             damping_factors>
        factors{};
    Vector3<R> acceleration{};
    /// With the damping_retention column (features.hpp): compute each particle's d^t into it
    /// before its step. True unless the system knows the column holds this duration's already
    /// (step_parameters says), so a loop of one's own that builds its parameters is right.
    bool refresh = true;
  };

  /// False when a step calls a power function per particle: per-particle damping with a
  /// policy of the user's. PerFrame needs no function, Exact the library's branch-free
  /// exponential (detail/exponential.hpp), and PerSecond and AccelerateThenDamp read the
  /// damping_retention column (refreshed in a loop of its own: AccelerateThenDamp's powf does
  /// not vectorise there). Only a vectorisable loop is marked for vectorisation.
  static constexpr bool vectorisable =
      !Layout::per_particle_damping || Layout::per_particle_retention ||
      std::is_same_v<D, damping::PerFrame> ||
      ((std::is_same_v<D, damping::PerSecond> ||
        std::is_same_v<D, damping::Exact>)&&!wider_than_double_v<R>);

  /// True when the step loop skips the select that keeps immovable particles in place, for
  /// segments whose particles are all movable (forces, positions stored as R, float or
  /// double): a scene's particles usually all are. The select is six a particle (position
  /// and velocity, x, y, z), nearly as many instructions as the rest of the step; the test
  /// costs one comparison. (The immovable particles cannot be counted as set_mass sets them
  /// instead: the inverse mass column is the user's to write through column() and arrays().)
  static constexpr bool skips_movable_select =
      Layout::has_forces && plain_positions && !wider_than_double_v<R>;

  /// The most particles whose inverse masses one test covers (skips_movable_select): the
  /// forward walk's segments; a multiple of backward_chunk (the backward walk's), and few
  /// enough that their inverse masses stay in the L1 cache for the step.
  static constexpr std::size_t movable_chunk = 1024;

  /// The loop's trip count is a multiple of this (the widest vector: 16 floats, 8 doubles).
  static constexpr std::size_t vector_block = 16;
  /// The backward walk's chunk, a multiple of vector_block.
  static constexpr std::size_t backward_chunk = 256;
  static_assert(backward_chunk % vector_block == 0);
  static_assert(movable_chunk % backward_chunk == 0);

  /// While the arrays take at most this many bytes, `step` walks the particles forwards and
  /// backwards in turn: each step then starts on the particles the step before finished
  /// with, still in the processor's caches, instead of on those evicted longest ago. The
  /// results are the same either way (every particle's step is independent of the others).
  /// Beyond a few times the size of a core's L2 cache, the cached share is too small to
  /// repay the backward walk's weaker hardware prefetch, so larger systems always walk
  /// forwards. docs/results/system.md has the measurements on both sides of the limit.
  static constexpr std::size_t alternation_limit_bytes = std::size_t{8} << 20;
  /// Arrays that fit in a 32 KiB L1 data cache stay there whichever way a step walks, so
  /// systems this small (1,365 float or 682 double particles with six arrays) always walk
  /// forwards, the cheaper loop.
  static constexpr std::size_t alternation_floor_bytes = std::size_t{32} << 10;

  /// True when `step` alternates its walk for a system of `count` particles: when their
  /// arrays take more than alternation_floor_bytes and at most alternation_limit_bytes.
  static constexpr bool alternates(std::size_t count) noexcept {
    const std::size_t limit_count = alternation_limit_bytes / Layout::bytes_per_particle;
    const std::size_t floor_count = alternation_floor_bytes / Layout::bytes_per_particle;
    return count > floor_count && count <= limit_count;
  }

  /// The step of particle i, as Particle::integrate computes it:
  ///   a  = acceleration + force * inverse_mass;  v1 = D::velocity(v0, a, t, f);
  ///   p1 = P::position(p0, v0, v1, a, t, f);     force = 0;  age += t
  /// on each of x, y and z (integrate<D, P> in particle.hpp; with positions stored wider or
  /// compensated, detail::integrate_stored); with features::Interpolation, p0 is kept as the
  /// previous position first. The user's columns are not touched. A particle of inverse mass
  /// 0 does not move. Plain arithmetic on the arrays: runs on a GPU as it runs here (see
  /// docs/hardening.md for the compiler settings under which a device gives the same bits).
  POINTMASS_DETAIL_ALWAYS_INLINE POINTMASS_HD static constexpr void step_particle(
      const Arrays& arrays, std::size_t i, const StepParameters& parameters) noexcept {
    if constexpr (Layout::per_particle_retention) {
      if (parameters.refresh) refresh_retention(arrays, i, parameters.duration);
    }
    step_kept(arrays, i, parameters);
  }

  /// Particle i's retention for a step of `duration`, written to the damping_retention column.
  POINTMASS_DETAIL_ALWAYS_INLINE POINTMASS_HD static constexpr void refresh_retention(
      const Arrays& arrays, std::size_t i, R duration) noexcept {
    if constexpr (Layout::per_particle_retention) {
      arrays.damping_retention[i] = D::factors(Layout::load_damping(arrays, i), duration).kept;
    }
  }

 protected:
  // step_particle once the retention column (if any) holds d^t for this duration.
  // AllMovable: the caller has found particle i movable (all_movable), so the step is taken
  // without selecting between the stepped and the unchanged values: the same bits, since for
  // a movable particle the select keeps the stepped ones.
  // StorePrevious: false for the sub-steps after the first of a pass, which keep the
  // position from before the pass.
  template <bool AllMovable = false, bool StorePrevious = true>
  POINTMASS_DETAIL_ALWAYS_INLINE POINTMASS_HD static constexpr void step_kept(
      const Arrays& arrays, std::size_t i, const StepParameters& parameters) noexcept {
    const R t = parameters.duration;
    if constexpr (Layout::has_interpolation && StorePrevious) {  // the position before, drawn
      arrays.previous_position_x[i] = arrays.position_x[i];
      arrays.previous_position_y[i] = arrays.position_y[i];
      arrays.previous_position_z[i] = arrays.position_z[i];
    }
    const auto factors = factors_of(arrays, i, parameters);
    R ax;
    R ay;
    R az;
    if constexpr (Layout::per_particle_acceleration) {
      ax = arrays.acceleration_x[i];
      ay = arrays.acceleration_y[i];
      az = arrays.acceleration_z[i];
    } else {
      ax = parameters.acceleration.x;
      ay = parameters.acceleration.y;
      az = parameters.acceleration.z;
    }
    R none = R(0);  // every kick of a policy that keeps none: 0, never written
    R& kx = kick_of(arrays.kick_x, i, none);
    R& ky = kick_of(arrays.kick_y, i, none);
    R& kz = kick_of(arrays.kick_z, i, none);
    // The half step that credited the kick (0 before the particle's first step); a step that
    // moves the particle keeps its own, t / 2 (integrate_kicked's product: the same bits).
    [[maybe_unused]] R& kept_half = kick_of(arrays.kick_half_step, i, none);
    const R h = kept_half;
    [[maybe_unused]] const R half = t * R(0.5);
    if constexpr (!plain_positions) {  // stored wider or compensated (precision.hpp)
      bool movable = true;
      if constexpr (Layout::has_forces) {
        const R inverse_mass = apply_forces(arrays, i, ax, ay, az);
        movable = inverse_mass > R(0);
      }
      integrate_stored_if<D, P, Layout>(movable, arrays.position_x[i], arrays.position_error_x, i,
                                        arrays.velocity_x[i], kx, ax, t, h, factors);
      integrate_stored_if<D, P, Layout>(movable, arrays.position_y[i], arrays.position_error_y, i,
                                        arrays.velocity_y[i], ky, ay, t, h, factors);
      integrate_stored_if<D, P, Layout>(movable, arrays.position_z[i], arrays.position_error_z, i,
                                        arrays.velocity_z[i], kz, az, t, h, factors);
      if constexpr (Layout::has_kicks) kept_half = select_if(movable, half, kept_half);
    } else if constexpr (Layout::has_forces && AllMovable) {
      apply_forces(arrays, i, ax, ay, az);
      integrate_component<D, P>(arrays.position_x[i], arrays.velocity_x[i], kx, ax, t, h, factors);
      integrate_component<D, P>(arrays.position_y[i], arrays.velocity_y[i], ky, ay, t, h, factors);
      integrate_component<D, P>(arrays.position_z[i], arrays.velocity_z[i], kz, az, t, h, factors);
      if constexpr (Layout::has_kicks) kept_half = half;
    } else if constexpr (Layout::has_forces) {
      const R inverse_mass = apply_forces(arrays, i, ax, ay, az);
      integrate_if_movable<D, P, Layout>(inverse_mass, arrays.position_x[i], arrays.velocity_x[i],
                                         kx, ax, t, h, factors);
      integrate_if_movable<D, P, Layout>(inverse_mass, arrays.position_y[i], arrays.velocity_y[i],
                                         ky, ay, t, h, factors);
      integrate_if_movable<D, P, Layout>(inverse_mass, arrays.position_z[i], arrays.velocity_z[i],
                                         kz, az, t, h, factors);
      if constexpr (Layout::has_kicks)
        kept_half = select_if_less(R(0), inverse_mass, half, kept_half);
    } else {
      integrate_component<D, P>(arrays.position_x[i], arrays.velocity_x[i], kx, ax, t, h, factors);
      integrate_component<D, P>(arrays.position_y[i], arrays.velocity_y[i], ky, ay, t, h, factors);
      integrate_component<D, P>(arrays.position_z[i], arrays.velocity_z[i], kz, az, t, h, factors);
      if constexpr (Layout::has_kicks) kept_half = half;
    }
    if constexpr (Layout::has_lifetime) count_age(arrays.age[i], arrays.age_error[i], t);
  }

 public:
#if defined(__clang__)
#pragma clang diagnostic push
  // Some configurations do not vectorise (a power function per particle; clang 14 also
  // declines float damping::Exact). clang reports that against the function, not the loop,
  // so the whole function is in the region where the warning is off: -Werror builds of
  // users' code must not fail on it.
#pragma clang diagnostic ignored "-Wpass-failed"
#endif
  /// Steps particles [begin, end) of `arrays`: the vectorised loop over step_particle, with
  /// `laws` (forces::Laws) added to each chunk of law_chunk particles just before its step
  /// (detail/law_pass.hpp); returns the laws whose force was beyond range (bit I for law I).
  /// begin <= end <= arrays.size is a precondition, checked when POINTMASS_CHECKS is on.
  template <class Laws = NoLaws>
  static unsigned step_range(const Arrays& arrays_in, std::size_t begin, std::size_t end,
                             const StepParameters& parameters_in,
                             const Laws& laws_in = {}) noexcept(!POINTMASS_HOST_CHECKS) {
#if POINTMASS_HOST_CHECKS
    if (!check_range("step_range", begin, end, arrays_in.size)) return 0;
#endif
    // Local copies: the loop's stores cannot alias them, so the compiler keeps the shared
    // values in registers instead of reloading them for every vector of particles.
    const Arrays arrays = arrays_in;
    const StepParameters parameters = parameters_in;
    const Laws laws = laws_in;
    const auto fused = fused_of(laws);
    unsigned beyond = 0;
    // Segments of movable_chunk particles, each tested for immovable ones (step_segment), or
    // with laws of law_chunk, each given its forces first.
    constexpr std::size_t segment = std::is_same_v<Laws, NoLaws> ? movable_chunk : law_chunk;
    if constexpr (skips_movable_select || !std::is_same_v<Laws, NoLaws>) {
      for (; end - begin > segment; begin += segment) {
        beyond |= forces_of(arrays, begin, segment, parameters.duration, fused, laws);
        step_segment(arrays, begin, segment, parameters);
      }
    }
    beyond |= forces_of(arrays, begin, end - begin, parameters.duration, fused, laws);
    step_segment(arrays, begin, end - begin, parameters);
    return beyond;
  }

  /// Steps particles [begin, end) as step_range does, with the same results, but walks them
  /// from the end: the part past the last whole chunk of backward_chunk first, then whole
  /// chunks from the last to the first, each chunk forwards through the same vectorised
  /// loop (a single copy of it in this function: clang 14 lost the loop's no-alias mark on
  /// a second inlined copy and left that copy scalar). Same precondition as step_range.
  template <class Laws = NoLaws>
  static unsigned step_range_backward(const Arrays& arrays_in, std::size_t begin, std::size_t end,
                                      const StepParameters& parameters_in,
                                      const Laws& laws_in = {}) noexcept(!POINTMASS_HOST_CHECKS) {
#if POINTMASS_HOST_CHECKS
    if (!check_range("step_range_backward", begin, end, arrays_in.size)) return 0;
#endif
    const Arrays arrays = arrays_in;  // local copies, as in step_range
    const StepParameters parameters = parameters_in;
    const Laws laws = laws_in;
    const auto fused = fused_of(laws);
    static_assert(backward_chunk <= law_chunk);
    unsigned beyond = 0;
    std::size_t first = end - (end - begin) % backward_chunk;
    std::size_t count = end - first;
    for (;;) {
      beyond |= forces_of(arrays, first, count, parameters.duration, fused, laws);
      step_segment(arrays, first, count, parameters);
      if (first == begin) return beyond;
      first -= backward_chunk;
      count = backward_chunk;
    }
  }

 protected:
  // Particles [first, first + count): the loop marked for vectorisation (when the
  // configuration can vectorise) over a trip count that is a multiple of vector_block, which
  // lets g++'s -O2 cost model vectorise it without a remainder loop; then the remainder.
  template <bool StorePrevious = true>
  POINTMASS_DETAIL_ALWAYS_INLINE static void step_segment(
      const Arrays& arrays, std::size_t first, std::size_t count,
      const StepParameters& parameters) noexcept {
    const std::size_t blocked = count & ~(vector_block - 1);
    if constexpr (Layout::per_particle_retention) {
      if (parameters.refresh) refresh_segment(arrays, first, count, blocked, parameters.duration);
    }
    if constexpr (vectorisable && skips_movable_select) {
      // When every particle of the segment (at most movable_chunk) is movable, its loop
      // takes no select; else (an immovable particle, a NaN inverse mass) the loop with it.
      if (all_movable(arrays.inverse_mass + first, blocked)) {
        step_loop<true, StorePrevious>(arrays, first, blocked, parameters);
      } else {
        step_loop<false, StorePrevious>(arrays, first, blocked, parameters);
      }
    } else if constexpr (vectorisable) {
      step_loop<false, StorePrevious>(arrays, first, blocked, parameters);
    }
    if constexpr (vectorisable) {
      // The remainder (under vector_block particles) marked too: with -march=native it runs
      // as one or two shorter vectors instead of up to 15 scalar steps.
      POINTMASS_DETAIL_INDEPENDENT_ITERATIONS
      for (std::size_t k = blocked; k < count; ++k) {
        step_kept<false, StorePrevious>(arrays, first + k, parameters);
      }
    } else {  // a power function per particle: no vector loop to ask for
      for (std::size_t k = 0; k < count; ++k) {
        step_kept<false, StorePrevious>(arrays, first + k, parameters);
      }
    }
  }
  // A new step length t: each particle's d^t first, in a loop of its own (vectorised for
  // PerSecond; AccelerateThenDamp's powf is a call), so that the step's loop stays one.
  POINTMASS_DETAIL_ALWAYS_INLINE static void refresh_segment(const Arrays& arrays,
                                                             std::size_t first, std::size_t count,
                                                             std::size_t blocked, R t) noexcept {
    if constexpr (std::is_same_v<D, damping::PerSecond> && !wider_than_double_v<R>) {
      POINTMASS_DETAIL_INDEPENDENT_ITERATIONS
      for (std::size_t k = 0; k < blocked; ++k) refresh_retention(arrays, first + k, t);
    } else {
      for (std::size_t k = 0; k < blocked; ++k) refresh_retention(arrays, first + k, t);
    }
    for (std::size_t k = blocked; k < count; ++k) refresh_retention(arrays, first + k, t);
  }
  // The step loop over particles [first, first + count), count a multiple of vector_block
  // (said again by the mask, so that the compiler needs no remainder loop): one source line
  // for both instantiations, so that the vectorisation probes see each of them.
  template <bool AllMovable, bool StorePrevious>
  POINTMASS_DETAIL_ALWAYS_INLINE static void step_loop(const Arrays& arrays, std::size_t first,
                                                       std::size_t count,
                                                       const StepParameters& parameters) noexcept {
    const std::size_t blocked = count & ~(vector_block - 1);
    POINTMASS_DETAIL_INDEPENDENT_ITERATIONS  // the step loop (tests/system probes this line)
    for (std::size_t k = 0; k < blocked; ++k)
      step_kept<AllMovable, StorePrevious>(arrays, first + k, parameters);
  }

  // True when each of the `count` inverse masses from `inverse_mass` makes its particle
  // movable as integrate_if_movable's select decides it (0 < m + 0: false for zeros of either
  // sign and NaN, and for a subnormal m where the processor flushes it to zero): then their
  // step needs no select. A reduction the compiler vectorises, one load per particle.
  POINTMASS_DETAIL_ALWAYS_INLINE static bool all_movable(const R* inverse_mass,
                                                         std::size_t count) noexcept {
    int immovable = 0;
    for (std::size_t k = 0; k < count; ++k) immovable |= !(inverse_mass[k] + R(0) > R(0));
    return immovable == 0;
  }

#if defined(__clang__)
#pragma clang diagnostic pop
#endif

  POINTMASS_DETAIL_ALWAYS_INLINE POINTMASS_HD static constexpr auto factors_of(
      const Arrays& arrays, std::size_t i, const StepParameters& parameters) noexcept {
    if constexpr (Layout::per_particle_retention) {
      return damping_factors{arrays.damping_retention[i]};
    } else if constexpr (Layout::per_particle_damping) {
      return D::factors(Layout::load_damping(arrays, i), parameters.duration);
    } else {
      static_cast<void>(arrays);
      static_cast<void>(i);
      return parameters.factors;
    }
  }

  // Adds the particle's accumulated force times its inverse mass to (ax, ay, az), clears the
  // accumulator, and returns the inverse mass.
  POINTMASS_DETAIL_ALWAYS_INLINE POINTMASS_HD static constexpr R apply_forces(const Arrays& arrays,
                                                                              std::size_t i, R& ax,
                                                                              R& ay,
                                                                              R& az) noexcept {
    const R inverse_mass = arrays.inverse_mass[i];
    ax = ax + arrays.force_x[i] * inverse_mass;
    ay = ay + arrays.force_y[i] * inverse_mass;
    az = az + arrays.force_z[i] * inverse_mass;
    arrays.force_x[i] = R(0);
    arrays.force_y[i] = R(0);
    arrays.force_z[i] = R(0);
    return inverse_mass;
  }

  // Particle i's element of a kick column, or `none` where the policy keeps no kick.
  POINTMASS_DETAIL_ALWAYS_INLINE POINTMASS_HD static constexpr R& kick_of(R* column, std::size_t i,
                                                                          R& none) noexcept {
    if constexpr (Layout::has_kicks) return column[i];
    static_cast<void>(column);
    static_cast<void>(i);
    return none;
  }
};

}  // namespace pointmass::detail
POINTMASS_DETAIL_UNFUSED_END

#undef POINTMASS_DETAIL_INDEPENDENT_ITERATIONS
