// SPDX-License-Identifier: BSL-1.0
// pointmass/system/columns.hpp — a ParticleSystem's arrays as spans, and the user's columns.
//
//   system.column<Column::age>()          any column the configuration stores
//   system.column<Tag>(), system.column<Tag>(i), system.set_column<Tag>(i, value)
//                                         a column of the user's (features::Column<Tag, T>)
//
// SystemColumns<Base> is a facet of ParticleSystem: a class template over the state below it
// that adds members and no data, so a system is no bigger for it; an implementation
// detail, whose public members ParticleSystem re-exports (a user never names it).
// Spans are valid until the block grows or moves (a growing spawn, reserve,
// move, swap); an index is checked as ParticleSystem's are (POINTMASS_CHECKS).
//
// Owns: column<C>() for every stored Column; the user columns' members and traits
// (user_columns, user_column_count, user_element_t, has_column), and the traits of the
// table's columns (element_t, stores).
// Must not include: particle_system.hpp, detail/system_state.hpp or another facet (it uses
// only Base's arrays(), size() and valid_index(), and the layout's table in features.hpp).
#pragma once

#include <cstddef>
#include <span>
#include <type_traits>

#include "../config.hpp"
#include "../detail/validate.hpp"
#include "../features.hpp"

POINTMASS_DETAIL_UNFUSED_BEGIN
namespace pointmass::inline POINTMASS_ABI_NAMESPACE::detail {

template <class Base>
class SystemColumns : public Base {
 protected:
  using Layout = typename Base::Layout;
  using R = typename Base::R;
  using position_element = typename Layout::position_element;

 public:
  /// The element type of column C: R, but for Column::damping with a damping policy of the
  /// user's whose state is neither StoredDamping nor LogDamping (then that state).
  template <Column C>
  using element_t = typename Layout::template element_t<C>;
  /// True when this configuration stores column C.
  template <Column C>
  static constexpr bool stores = Layout::template stores<C>;
  /// The user's columns (features::Column<Tag, T>) as a std::tuple, and how many.
  using user_columns = typename Layout::user_columns;
  static constexpr std::size_t user_column_count = Layout::user_column_count;
  /// The element type of the user column tagged Tag.
  template <class Tag>
  using user_element_t = typename Layout::template user_element_t<Layout::template user_index<Tag>>;
  /// True when the user column tagged Tag exists.
  template <class Tag>
  static constexpr bool has_column = Layout::template user_index<Tag> < user_column_count;

  // --- spans for renderers and other engines (valid until the block grows or moves) ---------

  /// Column C of the live particles, for any column this configuration stores. The damping
  /// columns of PerSecond and Exact (d and ln d as hi + lo, which must agree) are read-only:
  /// set_damping(i, d) writes them; so is features::Handles' handle_slot (the table's own
  /// index: spawn and kill keep it).
  template <Column C>
    requires(stores<C>)
  std::span < std::conditional_t < Layout::template read_only<C>,
  const element_t<C>, element_t < C >>> column() noexcept {
    return {this->arrays().*(Layout::template entry<C>::member), this->size()};
  }
  // clang-format off
  template <Column C>
    requires(stores<C>)
  std::span<const element_t<C>> column() const noexcept {
    // clang-format on
    return {this->arrays().*(Layout::template entry<C>::member), this->size()};
  }

  // --- user columns (features::Column<Tag, T>) -----------------------------------------------

  /// The user column tagged Tag, over the live particles.
  template <class Tag>
    requires(has_column<Tag>)
  std::span<user_element_t<Tag>> column()
  noexcept { return {user_pointer<Tag>(), this->size()}; }
  // clang-format off
  template <class Tag>
    requires(has_column<Tag>)
  std::span<const user_element_t<Tag>> column() const noexcept {
    // clang-format on
    return {user_pointer<Tag>(), this->size()};
  }
  /// Particle i's value in the user column tagged Tag.
  // clang-format off
  template <class Tag>
    requires(has_column<Tag>)
  user_element_t<Tag> column(std::size_t i) const noexcept(!POINTMASS_HOST_CHECKS) {
    // clang-format on
    return this->valid_index("column", i) ? user_pointer<Tag>()[i] : user_element_t<Tag>{};
  }
  template <class Tag>
    requires(has_column<Tag>)
  void set_column(std::size_t i, const user_element_t<Tag>& value) {
    if (detail::check_index("set_column", i, this->size())) user_pointer<Tag>()[i] = value;
  }

 private:
  template <class Tag>
  [[nodiscard]] auto* user_pointer() const noexcept {
    return Layout::template user_pointer<Layout::template user_index<Tag>>(this->arrays());
  }
};

}  // namespace pointmass::inline POINTMASS_ABI_NAMESPACE::detail
POINTMASS_DETAIL_UNFUSED_END
