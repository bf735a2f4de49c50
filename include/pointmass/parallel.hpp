// SPDX-License-Identifier: BSL-1.0
// pointmass/parallel.hpp — a ParticleSystem's step on the standard execution policies.
//
//   #include <pointmass/parallel.hpp>
//   pointmass::step(std::execution::par_unseq, system, 1.0f / 60);
//
// Owns: `pointmass::step(policy, system, t)` and the counting iterator it runs over. Including
// this header is the opt-in: it alone includes <execution>. With libstdc++ the parallel
// policies run on TBB, so link TBB (CMake: TBB::tbb). The serial `system.step(t)` never
// touches threads. (Defining POINTMASS_ENABLE_PARALLEL before particle_system.hpp, the former
// opt-in, still includes this header for one more release.)
//
// Must not include: anything but particle_system.hpp, denormals.hpp and the standard library.
#pragma once

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <execution>
#include <iterator>
#include <type_traits>
#include <utility>

#include "denormals.hpp"
#include "particle_system.hpp"

POINTMASS_DETAIL_UNFUSED_BEGIN
namespace pointmass::inline POINTMASS_ABI_NAMESPACE {

namespace detail {

/// A random-access iterator over the numbers 0, 1, 2, ...: the chunks a parallel step runs.
class CountingIterator {
 public:
  using iterator_category = std::random_access_iterator_tag;
  using value_type = std::size_t;
  using difference_type = std::ptrdiff_t;
  using pointer = const std::size_t*;
  using reference = std::size_t;

  CountingIterator() = default;
  explicit CountingIterator(std::size_t value) noexcept : value_(value) {}
  std::size_t operator*() const noexcept { return value_; }
  std::size_t operator[](difference_type n) const noexcept {
    return value_ + static_cast<std::size_t>(n);
  }
  CountingIterator& operator++() noexcept { return ++value_, *this; }
  CountingIterator operator++(int) noexcept { return CountingIterator(value_++); }
  CountingIterator& operator--() noexcept { return --value_, *this; }
  CountingIterator operator--(int) noexcept { return CountingIterator(value_--); }
  CountingIterator& operator+=(difference_type n) noexcept {
    value_ += static_cast<std::size_t>(n);
    return *this;
  }
  CountingIterator& operator-=(difference_type n) noexcept {
    value_ -= static_cast<std::size_t>(n);
    return *this;
  }
  friend CountingIterator operator+(CountingIterator i, difference_type n) noexcept {
    return i += n;
  }
  friend CountingIterator operator+(difference_type n, CountingIterator i) noexcept {
    return i += n;
  }
  friend CountingIterator operator-(CountingIterator i, difference_type n) noexcept {
    return i -= n;
  }
  friend difference_type operator-(CountingIterator a, CountingIterator b) noexcept {
    return static_cast<difference_type>(a.value_) - static_cast<difference_type>(b.value_);
  }
  // NOLINTNEXTLINE(modernize-use-nullptr): a finding inside the defaulted comparison
  friend auto operator<=>(CountingIterator, CountingIterator) = default;

 private:
  std::size_t value_ = 0;
};

}  // namespace detail

namespace detail {
/// The particles' step on `policy`, in chunks of 16,384 (each through the vectorised loop),
/// each under the calling thread's flush-to-zero modes (denormals.hpp), on whichever thread
/// runs it; false when there was nothing to do (see begin_step).
/// With `laws` (forces::Laws), fused in as ParticleSystem::step(duration, laws) fuses them;
/// `beyond` gets the laws whose force was beyond range on some particle (Laws::add).
/// With `substeps` > 1, each chunk takes them in one pass (ParticleSystem::step(duration,
/// laws, Substeps{k})): the view's step is then duration / substeps.
template <class ExecutionPolicy, class System, class R, class Laws = NoLaws>
typename System::StepView step_chunks(ExecutionPolicy&& policy, System& system, R duration,
                                      const Laws& laws = {}, unsigned* beyond = nullptr,
                                      std::size_t substeps = 1) {
  const R length = substeps == 1 ? duration : duration / static_cast<R>(substeps);
#if POINTMASS_HOST_CHECKS
  // A bad duration is reported as the caller gave it, not as a sub-step's; nothing is done.
  if (substeps != 1 && !check_duration("step", duration)) {
    return SystemAccess::begin_step(system, R(0));
  }
#endif
  typename System::StepView view = SystemAccess::begin_step(system, length);
  constexpr std::size_t chunk = 16384;
  const std::size_t size = view.size();
  const std::size_t chunks = (size + chunk - 1) / chunk;
  const unsigned modes = FlushModeBits::modes();
  std::atomic<unsigned> found{0};
  std::for_each(std::forward<ExecutionPolicy>(policy), CountingIterator(0),
                CountingIterator(chunks), [&](std::size_t c) {
                  const SameFlushModes same_modes(modes);
                  const std::size_t begin = c * chunk;
                  using Kernel = SystemAccess::Kernel<System>;
                  const std::size_t end = std::min(begin + chunk, size);
                  const unsigned bits =
                      substeps == 1
                          ? Kernel::step_range(view.arrays(), begin, end, view.parameters(), laws)
                          : Kernel::step_range_substeps(view.arrays(), begin, end,
                                                        view.parameters(), laws, substeps);
                  if (bits != 0) found.fetch_or(bits, std::memory_order_relaxed);
                });
  if (beyond != nullptr) *beyond = found.load(std::memory_order_relaxed);
  return view;
}

}  // namespace detail

/// Steps `system` by `duration` with the execution policy `policy` (for example
/// std::execution::par_unseq): the particles are split into chunks of 16,384, each stepped
/// by the vectorised loop, under the calling thread's flush-to-zero modes (FlushDenormals)
/// on every thread; expiry (Lifetime) then runs on the calling thread. The results are those
/// of system.step(duration), bit for bit. S is the system's first argument: a Real,
/// or a Precision (precision.hpp) whose positions are stored wider; `duration` is in the
/// system's arithmetic type (`real`), as system.step's is.
template <class ExecutionPolicy, class S, class D, class P, class... Features>
  requires(std::is_execution_policy_v<std::remove_cvref_t<ExecutionPolicy>>)
void step(ExecutionPolicy&& policy, ParticleSystem<S, D, P, Features...>& system,
          typename ParticleSystem<S, D, P, Features...>::real duration) {
  detail::SystemAccess::finish_step(
      system, detail::step_chunks(std::forward<ExecutionPolicy>(policy), system, duration));
}

/// As step(policy, system, duration), calling on_expire(i) for each particle whose lifetime is
/// over, on the calling thread, before its removal (ParticleSystem::step(t, on_expire)).
// clang-format off
template <class ExecutionPolicy, class S, class D, class P, class... Features, class OnExpire>
  requires(std::is_execution_policy_v<std::remove_cvref_t<ExecutionPolicy>> &&
           ParticleSystem<S, D, P, Features...>::template has<features::Lifetime> &&
           std::is_invocable_v<OnExpire&, std::size_t>)
void step(ExecutionPolicy&& policy, ParticleSystem<S, D, P, Features...>& system,
          typename ParticleSystem<S, D, P, Features...>::real duration, OnExpire&& on_expire) {
  // clang-format on
  detail::SystemAccess::finish_step(
      system, detail::step_chunks(std::forward<ExecutionPolicy>(policy), system, duration),
      on_expire);
}

/// As step(policy, system, duration), with `laws` (forces::Laws) fused into each chunk's loop,
/// as system.step(duration, laws, substeps) fuses them, bit for bit: with Substeps{k}, each
/// chunk takes k steps of duration / k in one pass. A law whose force was beyond range is
/// reported after the step, on the calling thread.
template <class ExecutionPolicy, class S, class D, class P, class... Features, class... G>
  requires(std::is_execution_policy_v<std::remove_cvref_t<ExecutionPolicy>>)
void step(ExecutionPolicy&& policy, ParticleSystem<S, D, P, Features...>& system,
          typename ParticleSystem<S, D, P, Features...>::real duration,
          const forces::Laws<G...>& laws, Substeps substeps = {}) {
  using System = ParticleSystem<S, D, P, Features...>;
  using R = typename System::real;
  static_assert(System::template has<features::ForceAccumulator>,
                "pointmass::step(policy, system, duration, laws): laws need each particle's mass; "
                "add features::ForceAccumulator to the system's features");
  static_assert(forces::detail::all_laws<R>(static_cast<const forces::Laws<G...>*>(nullptr)),
                "pointmass::step(policy, system, duration, laws): every law must be a force of "
                "one particle's own state, force(p, v, inverse_mass, t) returning Vector3<real>");
  static_assert(std::is_same_v<typename System::position_value, R>,
                "pointmass::step(policy, system, duration, laws): this system stores its "
                "positions wider than its arithmetic; apply the forces with forces::apply(law, "
                "forces::relative_to(system, origin), t) before the step");
  if (!detail::check_at_least("step", "substeps", substeps.count, std::size_t{1})) return;
  unsigned beyond = 0;
  detail::SystemAccess::finish_step(
      system, detail::step_chunks(std::forward<ExecutionPolicy>(policy), system, duration, laws,
                                  &beyond, substeps.count));
  if (beyond != 0) forces::report_beyond("step", beyond);
}

}  // namespace pointmass
POINTMASS_DETAIL_UNFUSED_END
