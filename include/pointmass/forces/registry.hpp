// SPDX-License-Identifier: BSL-1.0
// pointmass/forces/registry.hpp — ForceRegistry: (particle, generator) pairs, applied each
// step.
//
// Owns: ForceRegistry and the GeneratorFor concept (what a registry can hold: anything
// `forces::update_force(generator, particle, t)` accepts: a field generator, or a type with
// its own `update_force(particle, t)` member).
// Must not include: particle.hpp, particle_system.hpp (the particle type is a parameter), a
// generator's header (a registry holds any generator type).
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>

#include "apply.hpp"

POINTMASS_DETAIL_UNFUSED_BEGIN
namespace pointmass::inline POINTMASS_ABI_NAMESPACE::forces {

/// What a registry can hold for particles of type P.
template <class G, class P>
concept GeneratorFor = requires(G& g, P& p, typename P::real t) {
  forces::update_force(g, p, t);
};

/// (particle, generator) pairs, like Cyclone's `ParticleForceRegistry`; `update_forces(t)` adds
/// every generator's force to its particle. Two ways to register:
///   * owning (the safe default): `add_owned(particle, generator)` stores a copy (or a moved
///     generator) and `emplace<G>(particle, args...)` builds one in place; both return a
///     reference to the registry's generator, which lives until its registration is removed
///     or the registry is destroyed;
///   * non-owning: `add(particle, generator)` keeps a pointer; the generator must outlive its
///     registration (a generator in a std::vector that grows afterwards does not: use the
///     owning form). A temporary is refused at compile time.
/// Particles are never owned: a particle must outlive its registrations.
/// Generators of the listed types Known... (registered non-const) are stored in one vector per
/// type and called directly; any other type, or a const generator, is type-erased and called
/// through one function pointer.
/// Changing the registry from inside update_forces (a generator that removes itself or
/// another, adds a registration, or clears) is safe and deferred: the pass calls exactly the
/// registrations that existed when it began and are not removed before their turn; one added
/// during the pass first acts in the next pass; a removed generator the registry owns is
/// destroyed after the pass. A generator that replaces the registry (assigns, moves or swaps
/// it) ends the pass there; the registrations it replaced (their owned generators, the one
/// running among them) live until the pass ends.
// clang-format off
template <class P, class... Known>
  requires(GeneratorFor<Known, P> && ...)
class ForceRegistry {
  // clang-format on
 public:
  using particle_type = P;
  using real = typename P::real;

  ForceRegistry() = default;
  // The registrations move; a pass in progress (passes_) stays with the object it walks.
  ForceRegistry(ForceRegistry&& other) noexcept
      : known_(std::move(other.known_)),
        erased_(std::move(other.erased_)),
        removed_(std::exchange(other.removed_, 0)) {
    other.keep_removed(known_, erased_, removed_);
    other.replaced({}, {});
  }
  ForceRegistry& operator=(ForceRegistry&& other) noexcept {
    if (this != &other) {
      Known_ known = std::move(other.known_);
      std::vector<ErasedEntry> erased = std::move(other.erased_);
      std::size_t removed = std::exchange(other.removed_, 0);
      other.keep_removed(known, erased, removed);
      other.replaced({}, {});
      replaced(std::move(known), std::move(erased));
      removed_ = removed;
    }
    return *this;
  }
  ~ForceRegistry() = default;

  /// Registers a copy of `generator` (or the generator moved in), owned by the registry, to act
  /// on `particle`; returns the registry's generator.
  template <class G>
  G& add_owned(P& particle, G generator) {
    return emplace<G>(particle, std::move(generator));
  }

  /// Builds a generator G from `args` (constructor arguments, or an aggregate's members) in the
  /// registry, to act on `particle`; returns it.
  template <class G, class... Args>
  G& emplace(P& particle, Args&&... args) {
    static_assert(GeneratorFor<G, P>,
                  "ForceRegistry::emplace: G needs a force(p, v, "
                  "inverse_mass, t) or an update_force(particle, t) member");
    std::unique_ptr<G> owned;
    if constexpr (std::is_constructible_v<G, Args&&...>) {
      owned = std::make_unique<G>(std::forward<Args>(args)...);
    } else {  // an aggregate, for compilers without C++20's parenthesised aggregate init
      owned.reset(new G{std::forward<Args>(args)...});
    }
    G& generator = *owned;
    insert<G>(particle, generator, std::move(owned));
    return generator;
  }

  /// Registers `generator` (not owned: it must outlive the registration) to act on `particle`.
  template <class G>
  void add(P& particle, G& generator) {
    static_assert(
        !std::is_const_v<G> || GeneratorFor<G, P> || !GeneratorFor<std::remove_const_t<G>, P>,
        "ForceRegistry::add: this generator is const but its update_force member is "
        "not: pass a non-const generator, or make update_force a const member.");
    static_assert(
        GeneratorFor<G, P> || (std::is_const_v<G> && GeneratorFor<std::remove_const_t<G>, P>),
        "ForceRegistry::add: a generator needs a force(p, v, inverse_mass, t) or an "
        "update_force(particle, t) member.");
    insert<G>(particle, generator, nullptr);
  }

  /// A temporary would be destroyed while still registered.
  template <class G>
    requires(!std::is_lvalue_reference_v<G>)
  void add(P&, G&&) {
    static_assert(std::is_lvalue_reference_v<G>,
                  "ForceRegistry::add keeps a pointer to the generator, and this one is a "
                  "temporary: use add_owned (or emplace) to let the registry own it.");
  }

  /// Removes the first registration of `generator` on `particle`; returns whether there was
  /// one. Inside update_forces the registration stops acting at once and is erased (an owned
  /// generator destroyed) after the pass.
  template <class G>
  bool remove(const P& particle, const G& generator) {
    const void* address = &generator;
    const bool removed = [&] {
      // A const registration is type-erased whatever its type.
      if constexpr (GeneratorFor<const G, P>) {
        if (mark_first(erased_, particle, address, &call<const G>)) return true;
      }
      if constexpr (is_known<G>) {
        return mark_first(std::get<std::vector<Entry<G>>>(known_), particle, address);
      } else {
        return mark_first(erased_, particle, address, &call<G>);
      }
    }();
    compact_unless_updating();
    return removed;
  }

  /// Removes every registration (after the pass, when called inside update_forces).
  void clear() noexcept {
    std::apply([&](auto&... entries) { (mark_all(entries), ...); }, known_);
    mark_all(erased_);
    compact_unless_updating();
  }

  [[nodiscard]] std::size_t size() const noexcept {
    return std::apply([](const auto&... entries) { return (entries.size() + ... + 0u); }, known_) +
           erased_.size() - removed_;
  }
  [[nodiscard]] bool empty() const noexcept { return size() == 0; }

  /// Asks every registered generator to add its force to its particle for a step of
  /// `duration`: the known types first (in the order of Known...), then the others, each in
  /// the order they were added. A negative, NaN or infinite duration is a contract
  /// violation, checked when POINTMASS_CHECKS is on: reported once, and no force is added.
  /// When the known types are all field generators whose registrations name the same
  /// particles in the same order, each once (one of each per particle, added walking an
  /// array), they are walked together, eight registrations of each in turn: each particle's
  /// forces are added in the same order, in one pass over the particles, not one per type.
  void update_forces(real duration) {
#if POINTMASS_CHECKS
    if (!pointmass::detail::check_duration("ForceRegistry::update_forces", duration)) return;
#endif
    const Pass pass(*this);
    const std::uint32_t replacements = replacements_;
    // Every vector's count when the pass begins: a registration a generator adds to a vector
    // the pass has not reached yet first acts in the next pass too.
    const auto counts = std::apply(
        [](const auto&... e) {
          return std::array{e.size()..., std::size_t{0}};
        },
        known_);
    const std::size_t erased = erased_.size();
    if constexpr (lockstep_types) {
      if (in_lockstep()) {
        if (update_lockstep(counts[0], duration, replacements)) {
          static_cast<void>(update_all(erased_, erased, duration, replacements));
        }
        return;
      }
    }
    std::size_t k = 0;
    const auto all = [&](const auto& entries, std::size_t count) {
      return update_all(entries, count, duration, replacements);
    };
    std::apply(
        [&](const auto&... entries) {
          static_cast<void>((all(entries, counts[k++]) && ...) && all(erased_, erased));
        },
        known_);
  }

 private:
  template <class G>
  static constexpr bool is_known = (std::is_same_v<G, Known> || ...);

  template <class G>
  struct Entry {
    P* particle;  // nullptr: removed, erased after the pass
    G* generator;
    std::unique_ptr<G> owned;
    void update(real duration) const { forces::update_force(*generator, *particle, duration); }
  };
  using Update = void (*)(void*, P&, real);
  struct ErasedEntry {
    P* particle;  // nullptr: removed, erased after the pass
    void* generator;
    Update call;
    std::unique_ptr<void, void (*)(void*)> owned;
    void update(real duration) const { call(generator, *particle, duration); }
  };
  using Known_ = std::tuple<std::vector<Entry<Known>>...>;
  struct Retired {
    Known_ known;
    std::vector<ErasedEntry> erased;
  };

  template <class G>
  static void call(void* generator, P& particle, real duration) {
    forces::update_force(*static_cast<G*>(generator), particle, duration);
  }
  template <class G>
  static void destroy(void* generator) noexcept {
    delete static_cast<G*>(generator);
  }

  template <class G>
  void insert(P& particle, G& generator, std::unique_ptr<G> owned) {
    if constexpr (is_known<G>) {
      std::get<std::vector<Entry<G>>>(known_).push_back({&particle, &generator, std::move(owned)});
    } else {
      using Stored = std::remove_const_t<G>;
      void* address = const_cast<Stored*>(&generator);
      void* owned_address = const_cast<Stored*>(owned.release());
      erased_.push_back({&particle, address, &call<G>, {owned_address, &destroy<Stored>}});
    }
  }

  // Entries called in a pass are the first `count`, those present when it began; an entry
  // removed during the pass is skipped from then on. Indices, not iterators: an add may
  // reallocate the vector.
  // False when a generator replaced the registry: the pass ends.
  template <class Vec>
  [[nodiscard]] bool update_all(const Vec& entries, std::size_t count, real duration,
                                std::uint32_t replacements) const {
    using E = typename Vec::value_type;
    if constexpr (!std::is_same_v<E, ErasedEntry>) {
      using G = std::remove_pointer_t<decltype(E::generator)>;
      if constexpr (!HasUpdateForce<G, P> && FieldGenerator<G, real>) {
        return update_block(entries, 0, count, duration, replacements);
      }
    }
    for (std::size_t i = 0; i < count; ++i) {
      if (entries[i].particle == nullptr) continue;
      entries[i].update(duration);
      if (replacements_ != replacements) return false;
    }
    return true;
  }
  // A known field generator's registrations, eight at a time: their forces first (pure:
  // force(p, v, inverse_mass, t) reads only its body), then added in order, so the square
  // roots and divisions of eight bodies overlap. A report runs the user's handler, which may
  // change a body or the registry: the rest of that block is then computed afresh, one after
  // another (update_each).
  template <class Vec>
  [[nodiscard]] bool update_block(const Vec& entries, std::size_t first, std::size_t last,
                                  real duration, std::uint32_t replacements) const {
    std::array<Vector3<real>, block> f;
    for (std::size_t i = first; i < last; i += block) {
      const std::size_t m = std::min(block, last - i);
      for (std::size_t j = 0; j < m; ++j) {
        const auto& e = entries[i + j];
        if (e.particle == nullptr) continue;
        const P& b = *e.particle;
        f[j] = e.generator->force(b.position(), b.velocity(), b.inverse_mass(), duration);
      }
      for (std::size_t j = 0; j < m; ++j) {
        const auto& e = entries[i + j];
        if (e.particle == nullptr) continue;
        if (pointmass::detail::check_force("forces::update_force", f[j])) {
          e.particle->add_force(f[j]);
        } else {
          if (!update_each(entries, i + j + 1, i + m, duration, replacements)) return false;
          break;
        }
      }
    }
    return true;
  }
  static constexpr std::size_t block = 8;
  // Every known type a field generator (forces computed apart from their additions), and more
  // than one of them: a walk in lockstep can save passes.
  static constexpr bool lockstep_types = sizeof...(Known) > 1 &&
                                         ((!HasUpdateForce<Known, P> &&
                                           FieldGenerator<Known, real>)&&...);
  // Whether the known types' registrations name the same particles at the same indices, each
  // once (addresses rising): then a walk in lockstep adds each particle's forces in the same
  // order. Each index is checked once; a mismatch (misaligned) stands until a removal.
  static constexpr std::size_t misaligned = static_cast<std::size_t>(-1);
  bool in_lockstep() noexcept {
    const auto sizes = std::apply([](const auto&... e) { return std::array{e.size()...}; }, known_);
    const auto equal = [&](std::size_t size) { return size == sizes[0]; };
    if (checked_ == misaligned || !std::all_of(sizes.begin(), sizes.end(), equal)) return false;
    const auto& lead = std::get<0>(known_);
    for (; checked_ < sizes[0]; ++checked_) {
      const P* particle = lead[checked_].particle;
      const bool same = std::apply(
          [&](const auto&... e) { return ((e[checked_].particle == particle) && ...); }, known_);
      const bool rising = checked_ == 0 || std::less<>{}(lead[checked_ - 1].particle, particle);
      if (particle == nullptr || !same || !rising) {
        checked_ = misaligned;
        return false;
      }
    }
    return true;
  }
  // The known types' first `count` registrations, `block` of each type in turn (in_lockstep).
  [[nodiscard]] bool update_lockstep(std::size_t count, real duration,
                                     std::uint32_t replacements) const {
    for (std::size_t i = 0; i < count; i += block) {
      const std::size_t last = std::min(count, i + block);
      const bool going = std::apply(
          [&](const auto&... entries) {
            return (update_block(entries, i, last, duration, replacements) && ...);
          },
          known_);
      if (!going || replacements_ != replacements) return false;
    }
    return true;
  }
  // Registrations [first, last), one after another; false once the registry was replaced.
  template <class Vec>
  [[nodiscard]] bool update_each(const Vec& entries, std::size_t first, std::size_t last,
                                 real duration, std::uint32_t replacements) const {
    if (replacements_ != replacements) return false;
    for (std::size_t k = first; k < last; ++k) {
      if (entries[k].particle == nullptr) continue;
      entries[k].update(duration);
      if (replacements_ != replacements) return false;
    }
    return true;
  }
  // The registrations become `known` and `erased`; inside a pass the old ones are kept until
  // it ends (the generator running may be one of them).
  void replaced(Known_ known, std::vector<ErasedEntry> erased) noexcept {
    if (passes_ > 0) {
      retired_.push_back({std::move(known_), std::move(erased_)});
    }
    known_ = std::move(known);
    erased_ = std::move(erased);
    removed_ = 0;
    checked_ = 0;  // in_lockstep checks again
    ++replacements_;
  }

  // Registrations removed during this registry's pass stay with it when it hands the others
  // over (moved or swapped away): destroyed as its pass ends, not when the receiver compacts.
  void keep_removed(Known_& known, std::vector<ErasedEntry>& erased, std::size_t& removed) {
    if (passes_ == 0 || removed == 0) return;
    Retired kept;
    const auto split = [](auto& from, auto& to) {
      for (auto& e : from) {
        if (e.particle == nullptr) to.push_back(std::move(e));
      }
      std::erase_if(from, [](const auto& e) { return e.particle == nullptr; });
    };
    const auto split_known = [&]<std::size_t... I>(std::index_sequence<I...>) {
      (split(std::get<I>(known), std::get<I>(kept.known)), ...);
    };
    split_known(std::index_sequence_for<Known...>{});
    split(erased, kept.erased);
    retired_.push_back(std::move(kept));
    removed = 0;
  }

  template <class Vec, class... Match>
  bool mark_first(Vec& entries, const P& particle, const void* generator, Match... call_fn) {
    for (auto& e : entries) {
      bool same = e.particle == &particle && static_cast<const void*>(e.generator) == generator;
      if constexpr (sizeof...(Match) == 1) same = same && ((e.call == call_fn) && ...);
      if (same) {
        e.particle = nullptr;
        ++removed_;
        checked_ = 0;  // in_lockstep checks again
        return true;
      }
    }
    return false;
  }
  template <class Vec>
  void mark_all(Vec& entries) noexcept {
    checked_ = 0;  // in_lockstep checks again
    for (auto& e : entries) {
      if (e.particle != nullptr) ++removed_;
      e.particle = nullptr;
    }
  }
  void compact_unless_updating() noexcept {
    if (passes_ > 0 || removed_ == 0) return;
    const auto erase_removed = [](auto& entries) {
      std::erase_if(entries, [](const auto& e) { return e.particle == nullptr; });
    };
    std::apply([&](auto&... entries) { (erase_removed(entries), ...); }, known_);
    erase_removed(erased_);
    removed_ = 0;
  }

  /// Marks a pass in progress; at the end of the outermost pass, erases what it removed.
  class Pass {
   public:
    explicit Pass(ForceRegistry& registry) noexcept : registry_(registry) { ++registry_.passes_; }
    ~Pass() {
      --registry_.passes_;
      registry_.compact_unless_updating();
      if (registry_.passes_ == 0) registry_.retired_.clear();
    }
    Pass(const Pass&) = delete;
    Pass& operator=(const Pass&) = delete;

   private:
    ForceRegistry& registry_;
  };

  Known_ known_;
  std::vector<ErasedEntry> erased_;
  std::size_t removed_ = 0;
  int passes_ = 0;
  std::uint32_t replacements_ = 0;  // changed by every move and assignment: a pass ends
  std::size_t checked_ = 0;         // registrations found in lockstep (in_lockstep)
  std::vector<Retired> retired_;    // replaced during a pass, destroyed after it
};

}  // namespace pointmass::forces
POINTMASS_DETAIL_UNFUSED_END
