// SPDX-License-Identifier: BSL-1.0
// pointmass/kokkos.hpp — a ParticleSystem's arrays in Kokkos Views, stepped by Kokkos.
//
//   #include <pointmass/kokkos.hpp>          // only for users who have Kokkos (CMake:
//                                            // pointmass::kokkos); the core needs no Kokkos
//   using Sparks = pointmass::ParticleSystem<float, pointmass::damping::PerSecond,
//                                            pointmass::position::Euler,
//                                            pointmass::features::Lifetime>;
//   Sparks host(100'000);                    // spawn, set values on the host ...
//   pointmass::KokkosSystem<Sparks> device(host);     // ... copy every stored array over
//   for (int k = 0; k < 600; ++k) device.step(Kokkos::DefaultExecutionSpace(), 1.0f / 60);
//   device.copy_to(host);                    // and back, when the host needs them
//
// Owns: `KokkosSystem<System, MemorySpace>`, which keeps the arrays of a ParticleSystem
// configuration in one Kokkos allocation in MemorySpace, copies them to and from a
// ParticleSystem (every array the configuration stores, found through the layout's table,
// detail::SystemLayout::for_each_array and for_each_array_pair: an array added to the table
// comes along without an edit here), steps them with Kokkos::parallel_for over
// ParticleSystem::StepView::step_particle in any execution space that can reach MemorySpace (on the
// host by chunks through the library's vectorised loop over step_particle), and
// expires particles (Lifetime) in that execution space too.
//
// The same results. Every particle's step is ParticleSystem::StepView::step_particle, the function
// ParticleSystem::step runs, so the arrays equal those of system.step(t) bit for bit when the
// compiler evaluates both the same way: on the host, build without contraction into fused
// multiply-adds (-ffp-contract=off; g++ in GNU mode contracts by default where the target
// has FMA, e.g. -march=native); under nvcc pass --fmad=false (docs/scale.md lists the rules).
// tests/kokkos/ proves it on Kokkos' host backends for every policy pair and feature set.
//
// Expiry keeps ParticleSystem's order. ParticleSystem::finish_step removes expired particles
// by swap-remove, walking from index 0: the survivors among the first m = size - expired
// indices stay where they are, and the holes among them (expired particles), in increasing
// order, receive the survivors from indices >= m in decreasing order. `expire` computes that
// order in parallel: a reduction counts the expired particles (m), a scan over [m, size)
// from the end ranks the survivors there, a scan over [0, m) ranks the holes, and hole r
// receives survivor r. The particles, their order and their values are those of the host.
//
// Device code: the functors below are KOKKOS_INLINE_FUNCTION; step_particle is POINTMASS_HD
// (__host__ __device__ under nvcc). The expiry's particle move goes through the layout's
// table, constexpr functions: a CUDA build needs Kokkos_ENABLE_CUDA_CONSTEXPR
// (--expt-relaxed-constexpr), as Kokkos' own CUDA builds usually have. No GPU run has happened
// (docs/scale.md).
//
// Must not include: parallel.hpp or anything that starts threads other than Kokkos.
#pragma once

#include <Kokkos_Core.hpp>

#include <array>
#include <cstddef>
#include <type_traits>
#include <utility>

#include "config.hpp"
#include "detail/soa_block.hpp"
#include "detail/system_kernel.hpp"
#include "detail/validate.hpp"
#include "features.hpp"
#include "particle_system.hpp"
#include "real.hpp"
#include "vector3.hpp"

POINTMASS_DETAIL_UNFUSED_BEGIN
namespace pointmass::inline POINTMASS_ABI_NAMESPACE {

namespace detail {

// The table and the step kernel of a ParticleSystem configuration, so that whatever selects
// the arrays (feature tags, user columns) is the table's business and not this header's.
template <class System>
using layout_of_t = SystemAccess::Layout<System>;
template <class System>
using kernel_of_t = SystemAccess::Kernel<System>;

// The Kokkos loops, as functors (plain structs: no extended lambdas needed under nvcc).
template <class System>
struct KokkosStep {
  typename System::StepView::Arrays arrays;
  typename System::StepView::Parameters parameters;
  KOKKOS_INLINE_FUNCTION void operator()(std::size_t i) const {
    System::StepView::step_particle(arrays, i, parameters);
  }
};

// The host backends' loop: chunks of particles, each through the library's vectorised loop
// (the kernel's step_range, step_particle over the chunk), as pointmass::step(par_unseq, ...)
// does.
template <class System>
struct KokkosStepChunks {
  static constexpr std::size_t chunk = 16384;
  typename System::StepView::Arrays arrays;
  typename System::StepView::Parameters parameters;
  void operator()(std::size_t c) const {
    const std::size_t begin = c * chunk;
    const std::size_t end = arrays.size - begin < chunk ? arrays.size : begin + chunk;
    kernel_of_t<System>::step_range(arrays, begin, end, parameters);
  }
};

/// True when ExecutionSpace runs on the host (its memory is the host's): KokkosSystem::step
/// then steps chunks through the vectorised loop, elsewhere one particle per index.
template <class ExecutionSpace>
inline constexpr bool kokkos_host_space_v =
    Kokkos::SpaceAccessibility<Kokkos::HostSpace,
                               typename ExecutionSpace::memory_space>::accessible;

/// One step of `arrays` in `space`, one particle per index of a Kokkos::parallel_for over
/// StepView::step_particle: KokkosSystem::step's loop on a device.
template <class System, class ExecutionSpace>
void kokkos_step_each(const ExecutionSpace& space, const typename System::StepView::Arrays& arrays,
                      const typename System::StepView::Parameters& parameters) {
  Kokkos::parallel_for(
      "pointmass::KokkosSystem::step",
      Kokkos::RangePolicy<ExecutionSpace, Kokkos::IndexType<std::size_t>>(space, 0, arrays.size),
      KokkosStep<System>{arrays, parameters});
}

/// One step of `arrays` in `space`, by chunks of 16,384 particles through the vectorised
/// loop: KokkosSystem::step's loop on the host. The same results as kokkos_step_each.
template <class System, class ExecutionSpace>
void kokkos_step_chunks(const ExecutionSpace& space,
                        const typename System::StepView::Arrays& arrays,
                        const typename System::StepView::Parameters& parameters) {
  constexpr std::size_t chunk = KokkosStepChunks<System>::chunk;
  Kokkos::parallel_for("pointmass::KokkosSystem::step",
                       Kokkos::RangePolicy<ExecutionSpace, Kokkos::IndexType<std::size_t>>(
                           space, 0, (arrays.size + chunk - 1) / chunk),
                       KokkosStepChunks<System>{arrays, parameters});
}

// ParticleSystem's expiry test (detail::lifetime_expired) on particle i.
template <class Arrays>
KOKKOS_INLINE_FUNCTION constexpr bool expired_at(const Arrays& arrays, std::size_t i) {
  return lifetime_expired(arrays.age[i], arrays.age_error[i], arrays.lifetime[i]);
}

template <class System>
struct KokkosCountExpired {
  typename System::StepView::Arrays arrays;
  KOKKOS_INLINE_FUNCTION void operator()(std::size_t i, std::size_t& count) const {
    count += expired_at(arrays, i) ? 1 : 0;
  }
};

// Survivors at indices >= kept, ranked from the end: sources(r) is the index of the r-th
// survivor counted from the last particle down.
template <class System, class IndexView>
struct KokkosRankSurvivors {
  typename System::StepView::Arrays arrays;
  std::size_t size;
  IndexView sources;
  KOKKOS_INLINE_FUNCTION void operator()(std::size_t u, std::size_t& rank, bool final) const {
    const std::size_t j = size - 1 - u;
    if (expired_at(arrays, j)) return;
    if (final) sources(rank) = j;
    ++rank;
  }
};

// Holes (expired particles) at indices < kept, ranked from the start: hole r receives
// survivor r, in every stored array.
template <class System, class IndexView>
struct KokkosFillHoles {
  using Layout = layout_of_t<System>;
  typename System::StepView::Arrays arrays;
  IndexView sources;
  KOKKOS_INLINE_FUNCTION void operator()(std::size_t i, std::size_t& rank, bool final) const {
    if (!expired_at(arrays, i)) return;
    if (final) {
      const std::size_t from = sources(rank);
      Layout::for_each_array(arrays, [&](auto* array) { array[i] = array[from]; });
    }
    ++rank;
  }
};

}  // namespace detail

/// The arrays of a ParticleSystem configuration `System` in one Kokkos allocation in
/// `MemorySpace`, with the system's uniform values (damping, acceleration), stepped in any
/// Kokkos execution space that can access MemorySpace.
template <class System, class MemorySpace = Kokkos::DefaultExecutionSpace::memory_space>
class KokkosSystem {
  using Layout = detail::layout_of_t<System>;
  // The handle table lives beside the host's arrays: a device that removes particles could
  // not keep it, and copy_to would leave it naming other particles.
  static_assert(!Layout::has_handles,
                "KokkosSystem: features::Handles is not supported on a device (the handle "
                "table stays on the host); step a system with Handles on the host, or "
                "without Handles on the device");
  using Block = detail::SoaBlock<Layout>;
  template <class T>
  using Unmanaged = Kokkos::View<T*, MemorySpace, Kokkos::MemoryTraits<Kokkos::Unmanaged>>;
  template <class T>
  using HostUnmanaged =
      Kokkos::View<T*, Kokkos::HostSpace, Kokkos::MemoryTraits<Kokkos::Unmanaged>>;

 public:
  using system_type = System;
  using memory_space = MemorySpace;
  using real = typename System::real;
  /// Raw pointers into MemorySpace (nullptr for arrays not stored) and the live count.
  using Arrays = typename System::StepView::Arrays;
  using StepParameters = typename System::StepView::Parameters;
  template <Column C>
  using element_t = typename Layout::template element_t<C>;
  /// An unmanaged View of one array's live particles.
  template <Column C>
  using View = Unmanaged<element_t<C>>;

  KokkosSystem() = default;
  /// A copy of `system`'s particles (every stored array) and uniform values in MemorySpace.
  explicit KokkosSystem(const System& system) { copy_from(system); }
  // Not copyable: a copy of the Views would share the arrays with the original while each
  // kept a particle count of its own. A move takes the allocation and leaves the source
  // empty, with no arrays: stepping it moves nothing of the new owner's.
  KokkosSystem(const KokkosSystem&) = delete;
  KokkosSystem& operator=(const KokkosSystem&) = delete;
  KokkosSystem(KokkosSystem&& other) noexcept
      : block_(std::move(other.block_)),
        sources_(std::move(other.sources_)),
        arrays_(other.arrays_),
        capacity_(other.capacity_),
        settings_(std::move(other.settings_)) {
    other.release();
  }
  KokkosSystem& operator=(KokkosSystem&& other) noexcept {
    if (this != &other) {
      block_ = std::move(other.block_);
      sources_ = std::move(other.sources_);
      arrays_ = other.arrays_;
      capacity_ = other.capacity_;
      settings_ = std::move(other.settings_);
      other.release();
    }
    return *this;
  }
  ~KokkosSystem() = default;

  std::size_t size() const noexcept { return arrays_.size; }
  bool empty() const noexcept { return size() == 0; }
  std::size_t capacity() const noexcept { return capacity_; }

  /// Replaces the particles and uniform values with `system`'s: every array the
  /// configuration stores is copied (Kokkos::deep_copy). Allocates when the capacity is
  /// smaller than system.size().
  void copy_from(const System& system) {
    reserve(system.size());
    arrays_.size = system.size();
    const std::size_t count = size();
    Layout::for_each_array_pair(
        arrays_, detail::SystemAccess::arrays(system), [count](auto* to, auto* from) {
          using T = std::remove_pointer_t<decltype(to)>;
          Kokkos::deep_copy(Unmanaged<T>(to, count), HostUnmanaged<T>(from, count));
        });
    copy_uniform(system, settings_);
  }

  /// Makes `system`'s particles and uniform values these: its size becomes size() (killing
  /// from the end, or spawning at the origin, before the copy), then every stored array is
  /// copied back. Grows `system` when it has too little room.
  void copy_to(System& system) const {
    system.reserve(size());
    while (system.size() > size()) system.kill(system.size() - 1);
    while (system.size() < size()) {
      system.spawn(Vector3<typename System::position_value>{}, Vector3<real>{});
    }
    Arrays host = detail::SystemAccess::arrays(system);
    const std::size_t count = size();
    Layout::for_each_array_pair(host, arrays_, [count](auto* to, auto* from) {
      using T = std::remove_pointer_t<decltype(to)>;
      Kokkos::deep_copy(HostUnmanaged<T>(to, count), Unmanaged<T>(from, count));
    });
    detail::SystemAccess::arrays_changed(system);
    copy_uniform(settings_, system);
  }

  /// Room for `capacity` particles (no-op if there is room already); keeps the particles.
  void reserve(std::size_t capacity) {
    if (capacity <= capacity_) return;
    if (capacity > System::max_size()) System().reserve(capacity);  // throws, naming it
    KokkosSystem grown;
    grown.allocate(capacity);
    grown.arrays_.size = size();
    const std::size_t count = size();
    Layout::for_each_array_pair(grown.arrays_, arrays_, [count](auto* to, auto* from) {
      using T = std::remove_pointer_t<decltype(to)>;
      Kokkos::deep_copy(Unmanaged<T>(to, count), Unmanaged<T>(from, count));
    });
    grown.settings_ = settings_;
    *this = std::move(grown);
  }

  /// The raw arrays in MemorySpace, for loops of your own over StepView::step_particle.
  const Arrays& arrays() const noexcept { return arrays_; }
  /// Array C of the live particles, as an unmanaged View in MemorySpace.
  // clang-format off
  template <Column C>
    requires(System::template stores<C>)
  View<C> view() const noexcept {
    // clang-format on
    return View<C>(arrays_.*(Layout::template entry<C>::member), size());
  }

  /// The uniform values (damping, acceleration), held by a ParticleSystem with no
  /// particles: set them there, with its checks (`settings().set_acceleration(g)`).
  System& settings() noexcept { return settings_; }
  const System& settings() const noexcept { return settings_; }
  /// What every particle's step of `duration` shares (settings().step_parameters).
  StepParameters step_parameters(real duration) const noexcept {
    return detail::SystemAccess::step_parameters(settings_, duration);
  }

  /// Advances every particle by `duration` seconds in `space` (Kokkos::parallel_for over
  /// StepView::step_particle: on a device one particle per index; on the host by chunks of
  /// 16,384 through the library's vectorised loop, the kernel's step_range: a loop of one call
  /// per index is not vectorised, and measured half the speed in float), then expires those whose
  /// lifetime is over (Lifetime), as
  /// ParticleSystem::step does, with its results. A negative, NaN or infinite duration is a
  /// contract violation, checked when POINTMASS_CHECKS is on; zero changes nothing. Returns
  /// when the step is complete (space.fence()).
  template <class ExecutionSpace>
  void step(const ExecutionSpace& space, real duration) {
    static_assert(Kokkos::is_execution_space<ExecutionSpace>::value,
                  "KokkosSystem::step: the first argument must be a Kokkos execution space");
    static_assert(Kokkos::SpaceAccessibility<ExecutionSpace, MemorySpace>::accessible,
                  "KokkosSystem::step: this execution space cannot access the memory space "
                  "the arrays are in");
#if POINTMASS_HOST_CHECKS
    if (!detail::check_duration("KokkosSystem::step", duration)) return;
#endif
    if (real_equal(duration, real(0)) || empty()) return;
    // The uniform damping factors, kept in settings_ for the next step of this length, as
    // ParticleSystem::step keeps them.
    const StepParameters parameters =
        detail::SystemAccess::keep_step_parameters(settings_, duration);
    if constexpr (detail::kokkos_host_space_v<ExecutionSpace>) {
      detail::kokkos_step_chunks<System>(space, arrays_, parameters);
    } else {
      detail::kokkos_step_each<System>(space, arrays_, parameters);
    }
    expire(space);
    space.fence();
  }

  /// Removes the particles whose age reached their (finite) lifetime, in `space`, leaving
  /// the others in ParticleSystem::finish_step's order; returns how many it removed. Called
  /// by step; call it after stepping through step_particle in a loop of your own.
  template <class ExecutionSpace>
  std::size_t expire(const ExecutionSpace& space) {
    if constexpr (!Layout::has_lifetime) {
      static_cast<void>(space);
      return 0;
    } else {
      const std::size_t count = size();
      if (count == 0) return 0;
      std::size_t expired = 0;
      Kokkos::parallel_reduce("pointmass::KokkosSystem::count_expired", policy(space, count),
                              detail::KokkosCountExpired<System>{arrays_}, expired);
      if (expired == 0) return 0;
      const std::size_t kept = count - expired;
      if (kept > 0) {
        if (sources_.extent(0) < expired) {
          sources_ = IndexView(
              Kokkos::view_alloc(Kokkos::WithoutInitializing, "pointmass::KokkosSystem::sources"),
              capacity_);
        }
        using Rank = detail::KokkosRankSurvivors<System, IndexView>;
        using Fill = detail::KokkosFillHoles<System, IndexView>;
        Kokkos::parallel_scan("pointmass::KokkosSystem::rank_survivors", policy(space, expired),
                              Rank{arrays_, count, sources_});
        Kokkos::parallel_scan("pointmass::KokkosSystem::fill_holes", policy(space, kept),
                              Fill{arrays_, sources_});
      }
      space.fence();
      arrays_.size = kept;
      return expired;
    }
  }

 private:
  using IndexView = Kokkos::View<std::size_t*, MemorySpace>;

  template <class ExecutionSpace>
  static auto policy(const ExecutionSpace& space, std::size_t count) {
    return Kokkos::RangePolicy<ExecutionSpace, Kokkos::IndexType<std::size_t>>(space, 0, count);
  }

  static void copy_uniform(const System& from, System& to) {
    if constexpr (!Layout::per_particle_acceleration) to.set_acceleration(from.acceleration());
    if constexpr (!std::is_same_v<typename System::damping_policy, damping::None> &&
                  !Layout::per_particle_damping) {
      to.set_damping(from.damping());
    }
  }

  // One allocation, each array 64-byte aligned and staggered within its page as
  // ParticleSystem's block places them (detail/soa_block.hpp says why).
  void allocate(std::size_t capacity) {
    std::size_t total = 0;
    Layout::for_each_array(arrays_,
                           [&](auto* array) { total += span_bytes(capacity * sizeof(*array)); });
    block_ = Kokkos::View<std::byte*, MemorySpace>(
        Kokkos::view_alloc(Kokkos::WithoutInitializing, "pointmass::KokkosSystem::arrays"), total);
    capacity_ = capacity;
    std::size_t offset = 0;
    Layout::for_each_array(arrays_, [&](auto*& array) {
      using T = std::remove_reference_t<decltype(*array)>;
      array = reinterpret_cast<T*>(block_.data() + offset);
      offset += span_bytes(capacity * sizeof(T));
    });
  }
  void release() noexcept {
    block_ = {};
    sources_ = {};
    arrays_ = {};
    capacity_ = 0;
  }
  static std::size_t span_bytes(std::size_t bytes) noexcept {
    return (bytes + Block::page - 1) / Block::page * Block::page + Block::stagger;
  }

  Kokkos::View<std::byte*, MemorySpace> block_;
  IndexView sources_;  // expiry's scratch: survivor indices
  Arrays arrays_{};
  std::size_t capacity_ = 0;
  System settings_;
};

}  // namespace pointmass
POINTMASS_DETAIL_UNFUSED_END
