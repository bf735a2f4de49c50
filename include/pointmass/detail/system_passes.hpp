// SPDX-License-Identifier: BSL-1.0
// pointmass/detail/system_passes.hpp — what a ParticleSystem does over all its particles: the
// step's walk and what it keeps between steps, the passes that call the user's code (spawn
// bursts, kill_if, expiry with and without a callback) and the copy-out of positions.
//
// Owns: SystemPasses (over detail/system_state.hpp's SystemState, whose data it works on)
// and SystemStateBase, the bottom of ParticleSystem's facets.
// Must not include: particle_system.hpp, parallel.hpp.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <type_traits>
#include <utility>

#include "../config.hpp"
#include "../damping.hpp"
#include "../real.hpp"
#include "../vector3.hpp"
#include "system_kernel.hpp"
#include "system_state.hpp"
#include "validate.hpp"

POINTMASS_DETAIL_UNFUSED_BEGIN
namespace pointmass::inline POINTMASS_ABI_NAMESPACE::detail {

// The expiry pass without a callback.
struct NoExpiryCallback {
  void operator()(std::size_t) const noexcept {}
};

template <class S, DampingPolicy D, class P, class... Features>
class SystemPasses : public SystemState<S, D, P, Features...> {
  using Base = SystemState<S, D, P, Features...>;

 protected:
  using Base::acceleration_;
  using Base::arrays;
  using Base::backward_;
  using Base::compensated;
  using Base::damping_;
  using Base::has_interpolation;
  using Base::keeps_factors;
  using Base::kept_;
  using Base::make_room;
  using Base::remove;
  using Base::removing_;
  using Base::replacements_;
  using Base::retention_duration_;
  using Base::size;
  using typename Base::Arrays;
  using typename Base::Kernel;
  using typename Base::Layout;
  using typename Base::position_value;
  using typename Base::R;
  using typename Base::StepParameters;
  using typename Base::Storage;

  // --- passes that call the user's code --------------------------------------------------------

  // spawn_burst: `count` particles, made[k] = generator(k) each added by spawn_one(made[k])
  // (npos when rejected), with removals and steps refused meanwhile (the burst's particles
  // are the last ones); on a throw, this call's particles are removed again.
  template <class Generator, class SpawnOne>
  std::size_t spawn_each(std::size_t count, Generator& generator, const SpawnOne& spawn_one) {
    make_room(count);
    const std::size_t before = size();
    const std::uint16_t replacements = replacements_;
    const auto spawn_all = [&]() -> std::size_t {
      const PassScope burst(removing_, RemovalPass::burst);
      std::size_t spawned = 0;
      for (std::size_t k = 0; k < count; ++k) {
        decltype(auto) made = generator(k);
        // The generator replaced the particles whole (assigned, swapped or moved the system):
        // those this call added left with them, and the burst ends.
        if (replacements_ != replacements) return 0;
        const ReportingElement reporting("spawn_burst", k);
        if (spawn_one(made) != static_cast<std::size_t>(-1)) ++spawned;
      }
      return spawned;
    };
#if POINTMASS_HAS_EXCEPTIONS
    try {
      return spawn_all();
    } catch (...) {
      // The last particles are this call's: removing the last moves no other particle.
      // (Particles replaced whole by the generator are not this call's: left as they are.)
      if (replacements_ == replacements) {
        while (size() > before) remove(size() - 1);
      }
      throw;
    }
#else
    static_cast<void>(before);
    return spawn_all();
#endif
  }
  // kill_if: the predicate runs inside RemovalPass::predicate, where removals and steps are
  // refused; should it have replaced the particles whole (assigned, swapped or moved the
  // system), the pass ends there.
  template <class Predicate>
  std::size_t remove_if(Predicate& predicate) {
    std::size_t removed = 0;
    std::size_t i = 0;
    while (i < size()) {
      bool remove_it = false;
      const std::uint16_t replacements = replacements_;
      {
        const PassScope scope(removing_, RemovalPass::predicate);
        remove_it = static_cast<bool>(predicate(std::as_const(i)));
      }
      if (replacements_ != replacements) break;
      if (remove_it) {
        remove(i);
        ++removed;
      } else {
        ++i;
      }
    }
    return removed;
  }

  // --- the step ------------------------------------------------------------------------------

  // The kept factors where the last step had this length, else computed (the scalar form, the
  // same bits): reads the system only, so begin_step keeps nothing (the library's steps do).
  [[nodiscard]] StepParameters step_parameters(R duration) const noexcept {
    if constexpr (keeps_factors) {
      if (same_bits(duration, kept_.duration)) return parameters_with(duration, kept_.factors);
    }
    if constexpr (Layout::per_particle_damping) {
      return parameters_with(duration, NoFactors{});
    } else {
      return parameters_with(duration, scalar_factors<D>(damping_, duration));
    }
  }
  // step_parameters for the library's steps (walk, and through SystemAccess the parallel and
  // Kokkos steps), which keep the factors of a new length.
  StepParameters keep_step_parameters(R duration) noexcept {
    if constexpr (keeps_factors) {
      if (!same_bits(duration, kept_.duration)) {
        kept_.factors = scalar_factors<D>(damping_, duration);
        kept_.duration = duration;
      }
      return parameters_with(duration, kept_.factors);
    } else {
      return step_parameters(duration);
    }
  }
  // The damping changed: the next step computes its factors.
  void forget_factors() noexcept {
    if constexpr (keeps_factors) kept_.duration = R(-1);
  }
  template <class Factors>
  [[nodiscard]] [[nodiscard]] StepParameters parameters_with(
      R duration, const Factors& factors) const noexcept {
    StepParameters parameters{};
    parameters.duration = duration;
    if constexpr (!Layout::per_particle_damping) parameters.factors = factors;
    parameters.acceleration = acceleration_;
    if constexpr (Layout::per_particle_retention) {
      parameters.refresh = !real_equal(duration, retention_duration_);
    }
    return parameters;
  }
  // `function`: the call a report names (step's own, or begin_step called by the user).
  bool begin_step(R duration, const char* function = "begin_step") const {
#if POINTMASS_HOST_CHECKS
    if (!check_duration(function, duration)) return false;
#endif
    if (!check_not_stepping(function, "duration", removing_, duration)) return false;
    return !real_equal(duration, R(0)) && size() != 0;
  }
  // The damping_retention column may no longer hold the retention for retention_duration_
  // (written from outside, or stepped by a loop of the caller's): the next step recomputes it.
  void forget_retention() noexcept {
    if constexpr (Layout::per_particle_retention) retention_duration_ = R(-1);
  }
  // Every particle has just stepped through step_particle with step_parameters(duration):
  // the damping_retention column holds the retention for this duration.
  void record_retention(R duration) noexcept {
    if constexpr (Layout::per_particle_retention) retention_duration_ = duration;
  }
  // Steps every particle, walking in the direction due, with `laws` (forces::Laws) fused in,
  // in `substeps` steps of duration / substeps (one pass: forwards); false when there was
  // nothing to do. `beyond`: the laws whose force was beyond range, for the caller to report.
  // A branch picks the walk: through a function pointer it was not inlined, and slower.
  template <class Laws = NoLaws>
  bool walk(R duration, const Laws& laws = {}, std::size_t substeps = 1,
            unsigned* beyond = nullptr) {
    if (!begin_step(duration, "step")) return false;
    const R length = substeps == 1 ? duration : duration / static_cast<R>(substeps);
    if (!(length > R(0))) return false;  // a sub-step below the least R: nothing moves
    const StepParameters parameters = keep_step_parameters(length);
    unsigned out = 0;
    if (substeps != 1) {
      out = Kernel::step_range_substeps(arrays(), 0, size(), parameters, laws, substeps);
    } else if (backward_) {
      out = Kernel::step_range_backward(arrays(), 0, size(), parameters, laws);
    } else {
      out = Kernel::step_range(arrays(), 0, size(), parameters, laws);
    }
    if (substeps == 1) backward_ = !backward_ && Kernel::alternates(size());
    record_retention(length);
    if (beyond != nullptr) *beyond = out;
    return true;
  }

  // For the facets, which see only their base's members (system/deprecated.hpp).
  using NoCallback = NoExpiryCallback;
  POINTMASS_HD static constexpr bool expired(R age, R lifetime) noexcept {
    return lifetime_expired(age, R(0), lifetime);
  }
  // Marks the system as inside a removal pass (an expiry callback, kill_if's predicate) while
  // it lives.
  struct PassScope {
    RemovalPass& flag;
    RemovalPass outer;
    PassScope(RemovalPass& pass, RemovalPass inner) noexcept : flag(pass), outer(pass) {
      flag = inner;
    }
    PassScope(const PassScope&) = delete;
    PassScope& operator=(const PassScope&) = delete;
    ~PassScope() { flag = outer; }
  };
  // kill_if's order and result, but a step expires few particles: a block of vector_block
  // particles none of which has expired (a test that vectorises) is skipped whole; only a
  // block with an expiry is walked one particle at a time.
  template <class OnExpire>
  void expire(OnExpire& on_expire, const char* function = "step") {
    if constexpr (Layout::has_lifetime) {
      // (step refuses earlier, in begin_step; finish_step reaches here)
      if (!check_not_stepping(function, "particles", removing_, size())) return;
      constexpr std::size_t block = Kernel::vector_block;
      std::size_t i = 0;
      while (i < size()) {
        const R* age = arrays().age;
        const R* age_error = arrays().age_error;
        const R* lifetime = arrays().lifetime;
        if (i % block == 0 && i + block <= size()) {
          // age >= lifetime is all an expiry needs (and a plain comparison vectorises); the
          // particle test below then leaves infinite lifetimes alone. The comparisons are
          // or-ed as unsigned, and the loop is not unrolled first: so g++ vectorises it too
          // (with a bool, or unrolled whole at -O3, it compared one particle at a time).
          unsigned expiring = 0;
#if defined(__GNUC__) && !defined(__CUDACC__)  // (nvcc's front end does not know it)
#pragma GCC unroll 1
#endif
          // the expiry scan (tests/system probes this line)
          for (std::size_t k = 0; k < block; ++k) {
            expiring |= static_cast<unsigned>(!(age[i + k] + age_error[i + k] < lifetime[i + k]));
          }
          if (expiring == 0) {
            i += block;
            continue;
          }
        }
        if (!lifetime_expired(age[i], age_error[i], lifetime[i])) {
          ++i;
        } else if (!expire_one(i, on_expire)) {
          return;
        }
      }
    }
  }
  // Particle i, expired: on_expire(i), then its removal. False when the callback replaced the
  // particles whole (assigned, swapped or moved the system): the pass ends there. A callback
  // that throws has been called for i: i is removed all the same (each particle is reported
  // once), and the expired particles not yet reached wait for the next step.
  template <class OnExpire>
  POINTMASS_DETAIL_ALWAYS_INLINE bool expire_one(std::size_t i, OnExpire& on_expire) {
    if constexpr (!std::is_same_v<std::remove_cvref_t<OnExpire>, NoExpiryCallback>) {
      const std::uint16_t replacements = replacements_;
#if POINTMASS_HAS_EXCEPTIONS
      try {
        const PassScope scope(removing_, RemovalPass::expiry);
        on_expire(std::as_const(i));
      } catch (...) {
        if (replacements_ == replacements) remove(i);
        throw;
      }
#else
      {
        const PassScope scope(removing_, RemovalPass::expiry);
        on_expire(std::as_const(i));
      }
#endif
      // The callback may only spawn (which keeps i).
      if (replacements_ != replacements) return false;
    }
    remove(i);
    return true;
  }

  // --- copy-out ------------------------------------------------------------------------------

  // store(i, x, y, z) with load(i)'s x, y and z for particles [first, last): the loop of
  // for_each_output_position. Scattered: each particle's components go a stride apart
  // (copy_strided with a stride other than 3), and the loop is not vectorised under clang,
  // whose vectorised form scatters them (AVX-512's scatter stores), at about half the speed
  // of the plain stores (hand-off table, stride 6). Otherwise both compilers vectorise it.
  template <bool Scattered, class Load, class Store>
  POINTMASS_DETAIL_ALWAYS_INLINE static void output_loop(std::size_t first, std::size_t last,
                                                         const Load& load, Store& store) {
    if constexpr (Scattered) {
#if defined(__clang__)
#pragma clang loop vectorize(disable)
#endif
      for (std::size_t i = first; i < last; ++i) {
        const auto p = load(i);
        store(i, p.x, p.y, p.z);
      }
    } else {
      for (std::size_t i = first; i < last; ++i) {
        const auto p = load(i);
        store(i, p.x, p.y, p.z);
      }
    }
  }

  // Calls store(i, x, y, z) for particles [first, last) with the position at the fraction
  // alpha of the last step (alpha 1: the current position; without Interpolation always).
  // The choice of alpha is made once, outside the loop, so 0 and 1 copy bits. A compensated
  // position goes to the store as an Out: hi + lo rounded to Out once.
  template <class Out = position_value, bool Scattered = false, class Store>
  void for_each_output_position(R alpha, std::size_t first, std::size_t last,
                                Store&& store_one) const {
    using E = typename Layout::position_element;
    const Arrays& a = arrays();
    bool current = true;
    if constexpr (has_interpolation) current = real_equal(alpha, R(1));
    if (current) {
      if constexpr (compensated) {
        output_loop<Scattered>(
            first, last,
            [&](std::size_t i) {
              return Vector3<Out>{rounded_once<Out>(a.position_x[i], a.position_error_x[i]),
                                  rounded_once<Out>(a.position_y[i], a.position_error_y[i]),
                                  rounded_once<Out>(a.position_z[i], a.position_error_z[i])};
            },
            store_one);
      } else {
        output_loop<Scattered>(
            first, last,
            [&](std::size_t i) {
              return Vector3<E>{a.position_x[i], a.position_y[i], a.position_z[i]};
            },
            store_one);
      }
      return;
    }
    if constexpr (has_interpolation) {
      if (real_equal(alpha, R(0))) {
        output_loop<Scattered>(
            first, last,
            [&](std::size_t i) {
              return Vector3<E>{a.previous_position_x[i], a.previous_position_y[i],
                                a.previous_position_z[i]};
            },
            store_one);
        return;
      }
      const E fraction = static_cast<E>(alpha);
      output_loop<Scattered>(
          first, last,
          [&](std::size_t i) {
            const E px = a.previous_position_x[i];
            const E py = a.previous_position_y[i];
            const E pz = a.previous_position_z[i];
            return Vector3<E>{px + (a.position_x[i] - px) * fraction,
                              py + (a.position_y[i] - py) * fraction,
                              pz + (a.position_z[i] - pz) * fraction};
          },
          store_one);
    }
  }
  // hi + lo rounded to Out once: one addition in Out where Out holds each part (it rounds the
  // exact sum), otherwise the offset from 0 (PositionStorage::relative rounds it once).
  template <class Out>
  POINTMASS_DETAIL_ALWAYS_INLINE static Out rounded_once(
      typename Layout::position_element hi, typename Layout::position_element lo) noexcept {
    if constexpr (std::numeric_limits<Out>::digits >=
                  std::numeric_limits<typename Layout::position_element>::digits) {
      return static_cast<Out>(hi) + static_cast<Out>(lo);
    } else {
      return Storage::template relative<Out, true>(hi, lo, position_value(0));
    }
  }
  template <class T>
  void copy_strided(const char* function, R alpha, std::span<T> out, std::size_t stride) const {
    if (!check_at_least(function, "stride", stride, 3)) return;
    if (size() == 0) return;
    // (size() - 1) * stride + 3 elements, saturated: a stride too large for any buffer must
    // not wrap around to a small count.
    const std::size_t rows = size() - 1;
    constexpr auto most = static_cast<std::size_t>(-1);
    const std::size_t needed = rows != 0 && stride > (most - 3) / rows ? most : rows * stride + 3;
    if (!check_strided_buffer(function, out.size(), needed)) return;
    T* data = out.data();
    const auto store = [&](std::size_t i, auto x, auto y, auto z) {
      T* vertex = data + i * stride;
      vertex[0] = static_cast<T>(x);
      vertex[1] = static_cast<T>(y);
      vertex[2] = static_cast<T>(z);
    };
    // Packed (x, y, z of one particle after another's): vectorised; any other stride
    // scatters (output_loop).
    if (stride == 3) for_each_output_position<T>(alpha, 0, size(), store);
    else for_each_output_position<T, true>(alpha, 0, size(), store);
  }
  template <class V>
  void copy_vectors(const char* function, R alpha, std::span<V> out) const {
    if (!check_buffer(function, "out", out.size(), size())) return;
    V* data = out.data();
    using T = std::remove_cvref_t<decltype(data->x)>;
    for_each_output_position<T>(alpha, 0, size(), [&](std::size_t i, auto x, auto y, auto z) {
      data[i].x = static_cast<T>(x);
      data[i].y = static_cast<T>(y);
      data[i].z = static_cast<T>(z);
    });
  }
};

// The state at the bottom of ParticleSystem's facets (system/*.hpp): a protected base, so
// that its members reach the facets and the class above them, and a system does not convert
// to it outside them.
template <class S, DampingPolicy D, class P, class... Features>
class SystemStateBase : protected SystemPasses<S, D, P, Features...> {};

}  // namespace pointmass::inline POINTMASS_ABI_NAMESPACE::detail
POINTMASS_DETAIL_UNFUSED_END
