// SPDX-License-Identifier: BSL-1.0
// pointmass/features.hpp — what a ParticleSystem may store, and the table of its arrays.
//
// Owns: the feature tags (namespace pointmass::features), the `Column` names of the arrays,
// and `detail::SystemLayout`, the compile-time table of which arrays a configuration stores,
// of what element type. Everything that walks the arrays (allocation, copy, swap-remove, the
// step) is generated from it: adding an array is one line in it (and its name in `Column`).
// Must not include: particle.hpp, particle_system.hpp or anything that steps.
#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>
#include <tuple>
#include <type_traits>
#include <utility>

#include "damping.hpp"
#include "precision.hpp"
#include "real.hpp"

POINTMASS_DETAIL_UNFUSED_BEGIN
namespace pointmass::inline POINTMASS_ABI_NAMESPACE::features {
/// Each particle has its own damping value (set_damping(i, d)).
struct PerParticleDamping {};
/// Each particle has its own acceleration (set_acceleration(i, a)); otherwise one for all.
struct PerParticleAcceleration {};
/// Each particle has an inverse mass and a force accumulator (add_force(i, f)).
struct ForceAccumulator {};
/// Each particle has an age (age + age_error, exact) and a lifetime: a step removes it then.
struct Lifetime {};

/// Each particle keeps its position before the last step (previous_position_x, y, z), for
/// drawing between steps: ParticleSystem::interpolated_position(i, alpha).
struct Interpolation {};

/// Stable handles: ParticleSystem::handle(i) names particle i for as long as it lives,
/// through every swap-remove; find(handle) gives its current index, or nothing once it has
/// died. Stores the particle's slot (a std::uint32_t) per particle, plus a table of slots
/// (slot -> index and generation) beside the block. A slot's generation counts its deaths in
/// G; a slot whose generation reaches the largest G is retired (never reused), so an old
/// handle can never answer for a newer particle (std::uint32_t: after 4,294,967,295 lives).
template <class G>
struct BasicHandles {
  static_assert(std::is_unsigned_v<G> && !std::is_same_v<G, bool>,
                "features::BasicHandles<G>: the generation G is an unsigned integer type");
  using generation_type = G;
};
using Handles = BasicHandles<std::uint32_t>;

/// A column of the user's own type T per particle, named by the tag type `Tag`: stored in the
/// same block and moved with its particle by every swap-remove (kill, kill_if, expiry); given
/// at spawn, read and written through column<Tag>() (a span), column<Tag>(i) and
/// set_column<Tag>(i, value). Not stepped. T is trivially copyable and trivially destructible
/// (the block is copied with memcpy and freed without destructors), default-constructible
/// (spawn without a value stores T{}), and aligned to at most 64 bytes.
template <class Tag, class T>
struct Column {
  static_assert(std::is_trivially_copyable_v<T> && std::is_trivially_destructible_v<T>,
                "features::Column<Tag, T>: T must be trivially copyable and destructible");
  static_assert(std::is_default_constructible_v<T>,
                "features::Column<Tag, T>: T must be default-constructible");
  static_assert(alignof(T) <= 64, "features::Column<Tag, T>: T aligned to at most 64 bytes");
  using tag = Tag;
  using type = T;
};

using Forces [[deprecated("renamed features::ForceAccumulator")]] = ForceAccumulator;

}  // namespace pointmass::features

namespace pointmass::inline POINTMASS_ABI_NAMESPACE {

/// The arrays a ParticleSystem's block can hold, for `system.column<Column::age>()`; in the
/// order of the table in detail::SystemLayout.
enum class Column : unsigned char {
  position_x,
  position_y,
  position_z,
  position_error_x,  ///< Compensated positions only: the error carried beside position_x
  position_error_y,
  position_error_z,
  velocity_x,
  velocity_y,
  velocity_z,
  acceleration_x,
  acceleration_y,
  acceleration_z,
  inverse_mass,
  force_x,
  force_y,
  force_z,
  damping,
  damping_log_hi,
  damping_log_lo,
  damping_retention,  ///< the retention for the last step's length (PerSecond, AccelerateThenDamp)
  age,
  age_error,  ///< Lifetime only: what the age's rounding dropped (the age is age + age_error)
  lifetime,
  previous_position_x,
  previous_position_y,
  previous_position_z,
  handle_slot,
  kick_x,  ///< position::VelocityVerlet only: the half kick the velocity holds on credit
  kick_y,
  kick_z,
  kick_half_step,  ///< position::VelocityVerlet only: the step length / 2 that credited it
};

/// A stable name of one particle of a ParticleSystem with features::BasicHandles<G> (see
/// there). A default handle names no particle.
template <class G>
struct ParticleHandle {
  std::uint32_t slot = std::numeric_limits<std::uint32_t>::max();
  G generation = 0;
  friend constexpr bool operator==(const ParticleHandle&, const ParticleHandle&) = default;
};

namespace detail {

template <class T, class... List>
inline constexpr bool contains_v = (std::is_same_v<T, List> || ...);

/// Not a user's feature: the layout of a system whose position policy kicks (the kick columns).
struct Kicks {};

template <class T>
struct is_user_column : std::false_type {};
template <class Tag, class T>
struct is_user_column<features::Column<Tag, T>> : std::true_type {};

template <class T>
struct is_handles : std::false_type {};
template <class G>
struct is_handles<features::BasicHandles<G>> : std::true_type {};

template <class T>
inline constexpr bool is_feature_v =
    contains_v<T, features::PerParticleDamping, features::PerParticleAcceleration,
               features::ForceAccumulator, features::Lifetime, features::Interpolation> ||
    is_user_column<T>::value || is_handles<T>::value;

/// True when `Feature` names `Configured`, one of a system's features: the same tag, any
/// handles for features::Handles (whatever their generations), or the tag of a user column.
template <class Feature, class Configured>
inline constexpr bool names_feature_v = std::is_same_v<Feature, Configured> ||
                                        (is_handles<Feature>::value &&
                                         is_handles<Configured>::value);
template <class Tag, class T>
inline constexpr bool names_feature_v<Tag, features::Column<Tag, T>> = true;
/// ParticleSystem::has<Feature>.
template <class Feature, class... Features>
inline constexpr bool has_feature_v = (names_feature_v<Feature, Features> || ...);

/// The handles feature among Features (void when there is none).
template <class... Features>
struct handles_of {
  using type = void;
};
template <class First, class... Rest>
struct handles_of<First, Rest...> {
  using type =
      std::conditional_t<is_handles<First>::value, First, typename handles_of<Rest...>::type>;
};

/// The user columns among Features, in order, as a std::tuple of features::Column types.
template <class... Features>
using user_columns_t = decltype(std::tuple_cat(
    std::declval<std::conditional_t<is_user_column<Features>::value, std::tuple<Features>,
                                    std::tuple<>>>()...));
/// Pointer I of a layout's user columns (one base per column, so the pack of pointers stays
/// an aggregate-like, trivially copyable struct that a device loop may take by value).
template <std::size_t I, class T>
struct UserPointer {
  T* pointer = nullptr;
};
template <class Sequence, class Columns>
struct UserPointersBuilder;
template <std::size_t... I, class... Columns>
struct UserPointersBuilder<std::index_sequence<I...>, std::tuple<Columns...>> {
  struct type : UserPointer<I, typename Columns::type>... {};
};
/// The user columns' pointers (an empty struct when there are none).
template <class Columns>
using UserPointers =
    typename UserPointersBuilder<std::make_index_sequence<std::tuple_size_v<Columns>>,
                                 Columns>::type;
/// The bytes per particle of the user columns Columns, and the largest element among them.
template <class Columns>
struct UserColumnSizes;
template <class... Columns>
struct UserColumnSizes<std::tuple<Columns...>> {
  static constexpr std::size_t bytes = (std::size_t{0} + ... + sizeof(typename Columns::type));
  static constexpr std::size_t largest = [] {
    std::size_t result = 0;
    ((result = sizeof(typename Columns::type) > result ? sizeof(typename Columns::type) : result),
     ...);
    return result;
  }();
};
/// The index of the user column tagged Tag in Columns (the count when there is none).
template <class Tag, class Columns, std::size_t I = 0>
constexpr std::size_t user_column_index() {
  // NOLINTNEXTLINE(bugprone-branch-clone): the end of the list and a match both answer I
  if constexpr (I == std::tuple_size_v<Columns>) {
    return I;
  } else if constexpr (std::is_same_v<typename std::tuple_element_t<I, Columns>::tag, Tag>) {
    return I;
  } else {
    return user_column_index<Tag, Columns, I + 1>();
  }
}

/// One entry of the table: the Arrays member that holds the column, and whether this
/// configuration stores it (a column not stored is never allocated, copied or stepped).
template <auto Member, bool Stored>
struct ColumnEntry {
  static constexpr auto member = Member;
  static constexpr bool stored = Stored;
};

template <class Class, class T>
T element_of(T* Class::*);

// The table: one line per array, in block order (the order of `Column`).
//   X(name,            element type,   stored when)
#define POINTMASS_DETAIL_COLUMNS(X)                           \
  X(position_x, position_element, true)                       \
  X(position_y, position_element, true)                       \
  X(position_z, position_element, true)                       \
  X(position_error_x, R, compensated_positions)               \
  X(position_error_y, R, compensated_positions)               \
  X(position_error_z, R, compensated_positions)               \
  X(velocity_x, R, true)                                      \
  X(velocity_y, R, true)                                      \
  X(velocity_z, R, true)                                      \
  X(acceleration_x, R, per_particle_acceleration)             \
  X(acceleration_y, R, per_particle_acceleration)             \
  X(acceleration_z, R, per_particle_acceleration)             \
  X(inverse_mass, R, has_forces)                              \
  X(force_x, R, has_forces)                                   \
  X(force_y, R, has_forces)                                   \
  X(force_z, R, has_forces)                                   \
  X(damping, damping_column_t, per_particle_damping)          \
  X(damping_log_hi, R, per_particle_log_damping)              \
  X(damping_log_lo, R, per_particle_log_damping)              \
  X(damping_retention, R, per_particle_retention)             \
  X(age, R, has_lifetime)                                     \
  X(age_error, R, has_lifetime)                               \
  X(lifetime, R, has_lifetime)                                \
  X(previous_position_x, position_element, has_interpolation) \
  X(previous_position_y, position_element, has_interpolation) \
  X(previous_position_z, position_element, has_interpolation) \
  X(handle_slot, std::uint32_t, has_handles)                  \
  X(kick_x, R, has_kicks)                                     \
  X(kick_y, R, has_kicks)                                     \
  X(kick_z, R, has_kicks)                                     \
  X(kick_half_step, R, has_kicks)

#define POINTMASS_DETAIL_MEMBER(name, type, stored) type* name = nullptr;
#define POINTMASS_DETAIL_ENTRY(name, type, stored) ColumnEntry<&Arrays::name, (stored)>{},

/// What a configuration stores. Features may come in any order. S is a Real or a
/// Precision<R, Position> (precision.hpp): R for every column but the positions.
template <PrecisionChoice S, DampingPolicy D, class... Features>
struct SystemLayout {
  using R = real_of_t<S>;
  using damping_state = typename D::template State<R>;
  /// How positions are stored (precision.hpp), and the element of the position columns
  /// (R, or a wider Real).
  using position_storage = PositionStorage<position_precision_of_t<S>>;
  using position_element = typename position_storage::element;
  /// Compensated<R> positions: an error column beside each position column.
  static constexpr bool compensated_positions = position_storage::compensated;
  /// The handles feature (features::BasicHandles<G>), or void.
  using handles = typename handles_of<Features...>::type;
  /// The user's columns (features::Column<Tag, T>), in the order given, as a std::tuple.
  using user_columns = user_columns_t<Features...>;
  static constexpr std::size_t user_column_count = std::tuple_size_v<user_columns>;
  using user_pointers = UserPointers<user_columns>;

  static constexpr bool per_particle_damping =
      contains_v<features::PerParticleDamping, Features...>;
  /// Per-particle damping states of the library's kinds are stored as columns of R: d in
  /// `damping`, and for LogDamping (PerSecond, Exact) ln d's two parts in `damping_log_hi`
  /// and `damping_log_lo`. A step then reads plain arrays (an array of three-member structs
  /// is a strided load, which g++ -O2 does not vectorise); a policy of the user's with another
  /// state keeps that state whole in `damping`. load_damping and SystemState::store_damping
  /// convert.
  static constexpr bool log_damping_state = std::is_same_v<damping_state, damping::LogDamping<R>>;
  static constexpr bool value_damping_state =
      log_damping_state || std::is_same_v<damping_state, damping::StoredDamping<R>>;
  static constexpr bool per_particle_log_damping = per_particle_damping && log_damping_state;
  using damping_column_t = std::conditional_t<value_damping_state, R, damping_state>;
  /// Per-particle PerSecond and AccelerateThenDamp damping also store each particle's
  /// retention for the last step's length (`damping_retention`): a run of steps of one
  /// length (a fixed step) computes no exponential and reads 4 bytes instead of d and ln d; a
  /// new length refreshes the column first (ParticleSystem::step, StepParameters::refresh).
  static constexpr bool per_particle_retention =
      per_particle_damping &&
      (std::is_same_v<D, damping::PerSecond> || std::is_same_v<D, damping::AccelerateThenDamp>);
  static constexpr bool per_particle_acceleration =
      contains_v<features::PerParticleAcceleration, Features...>;
  static constexpr bool has_forces = contains_v<features::ForceAccumulator, Features...>;
  static constexpr bool has_lifetime = contains_v<features::Lifetime, Features...>;
  static constexpr bool has_interpolation = contains_v<features::Interpolation, Features...>;
  static constexpr bool has_handles = !std::is_void_v<handles>;
  static constexpr bool has_kicks = contains_v<Kicks, Features...>;

  /// Raw pointers to the arrays (nullptr for those the configuration does not store) and
  /// the number of live particles: what step_particle works on. `user` holds the pointers of
  /// the user's columns (`user_pointer<I>`), which the step never touches.
  struct Arrays {
    POINTMASS_DETAIL_COLUMNS(POINTMASS_DETAIL_MEMBER)
    std::size_t size = 0;
    [[no_unique_address]] user_pointers user{};
  };

  /// Particle i's damping state, from the damping columns (per_particle_damping only).
  POINTMASS_HD static constexpr damping_state load_damping(const Arrays& arrays,
                                                           std::size_t i) noexcept {
    if constexpr (log_damping_state) {
      return damping_state(arrays.damping[i],
                           detail::SplitLog<R>{arrays.damping_log_hi[i], arrays.damping_log_lo[i]});
    } else if constexpr (value_damping_state) {
      return damping_state(arrays.damping[i]);
    } else {
      return arrays.damping[i];
    }
  }
  /// True for the columns that hold parts of a damping state that must agree with each
  /// other (d, ln d and the retention for the last step length), and for the handle table's
  /// slot of each particle, which the table itself indexes (a slot written through a span
  /// would have kill read and write outside the table): ParticleSystem::column gives them
  /// read-only (set_damping writes the damping columns together; spawn and kill the slots).
  template <Column C>
  static constexpr bool read_only = C == Column::handle_slot || C == Column::damping_retention ||
                                    ((log_damping_state || per_particle_retention) &&
                                     C == Column::damping) ||
                                    (log_damping_state &&
                                     (C == Column::damping_log_hi || C == Column::damping_log_lo));
  /// The element type of user column I.
  template <std::size_t I>
  using user_element_t = typename std::tuple_element_t<I, user_columns>::type;
  /// The pointer of user column I in `arrays` (a const Arrays gives a const pointer member).
  template <std::size_t I, class A>
  static constexpr auto& user_pointer(A& arrays) noexcept {
    using Base = UserPointer<I, user_element_t<I>>;
    using Qualified = std::conditional_t<std::is_const_v<A>, const Base, Base>;
    return static_cast<Qualified&>(arrays.user).pointer;
  }
  /// The index of the user column tagged Tag (user_column_count when there is none).
  template <class Tag>
  static constexpr std::size_t user_index = user_column_index<Tag, user_columns>();

 private:
  template <class A, class F, std::size_t... I>
  static constexpr void for_each_user_array(A& arrays, F& f, std::index_sequence<I...>) {
    (f(user_pointer<I>(arrays)), ...);
  }
  template <class F, std::size_t... I>
  static constexpr void for_each_user_pair(Arrays& to, const Arrays& from, F& f,
                                           std::index_sequence<I...>) {
    (f(user_pointer<I>(to), user_pointer<I>(from)), ...);
  }

 public:
  /// Every column's entry, in block order.
  static constexpr auto columns = std::tuple{POINTMASS_DETAIL_COLUMNS(POINTMASS_DETAIL_ENTRY)};

  template <Column C>
  using entry = std::tuple_element_t<static_cast<std::size_t>(C), decltype(columns)>;
  /// The element type of column C.
  template <Column C>
  using element_t = decltype(element_of(entry<C>::member));
  /// True when this configuration stores column C.
  template <Column C>
  static constexpr bool stores = entry<C>::stored;

  /// Calls f(pointer) for every stored array of `arrays`, in block order.
  template <class A, class F>
  static constexpr void for_each_array(A& arrays, F&& f) {
    std::apply(
        [&](auto... entry) {
          (
              [&] {
                if constexpr (decltype(entry)::stored) f(arrays.*(decltype(entry)::member));
              }(),
              ...);
        },
        columns);
    for_each_user_array(arrays, f, std::make_index_sequence<user_column_count>{});
  }

  /// Calls f(pointer of `to`, pointer of `from`) for every stored array, in block order.
  template <class F>
  static constexpr void for_each_array_pair(Arrays& to, const Arrays& from, F&& f) {
    std::apply(
        [&](auto... entry) {
          (
              [&] {
                if constexpr (decltype(entry)::stored) {
                  f(to.*(decltype(entry)::member), from.*(decltype(entry)::member));
                }
              }(),
              ...);
        },
        columns);
    for_each_user_pair(to, from, f, std::make_index_sequence<user_column_count>{});
  }

  /// How many arrays the block holds.
  static constexpr std::size_t array_count =
      std::apply([](auto... entry) { return (std::size_t{decltype(entry)::stored} + ...); },
                 columns) +
      user_column_count;

  /// Bytes each particle occupies in the arrays.
  static constexpr std::size_t bytes_per_particle =
      std::apply(
          [](auto... entry) {
            return ((decltype(entry)::stored ? sizeof(decltype(element_of(decltype(entry)::member)))
                                             : std::size_t{0}) +
                    ...);
          },
          columns) +
      UserColumnSizes<user_columns>::bytes;

  /// The largest element of any stored array.
  static constexpr std::size_t largest_element = std::apply(
      [](auto... entry) {
        std::size_t largest = 0;
        ((largest = decltype(entry)::stored &&
                            sizeof(decltype(element_of(decltype(entry)::member))) > largest
                        ? sizeof(decltype(element_of(decltype(entry)::member)))
                        : largest),
         ...);
        return largest > UserColumnSizes<user_columns>::largest
                   ? largest
                   : UserColumnSizes<user_columns>::largest;
      },
      columns);
};

#undef POINTMASS_DETAIL_ENTRY
#undef POINTMASS_DETAIL_MEMBER
#undef POINTMASS_DETAIL_COLUMNS
}  // namespace detail
}  // namespace pointmass
POINTMASS_DETAIL_UNFUSED_END
