// pointmass/forces/detail/checks.hpp — every argument check of the force generators, in one
// place, through config.hpp's contract mechanism: a failed check reports the function, the
// argument and its value, and returns false so that the caller changes nothing.
//
// Owns: check_non_negative, check_positive, check_finite (a number, a vector),
// check_duration, check_index, check_force, check_state.
// Must not include: another forces header, particle.hpp, particle_system.hpp (these checks are
// meant to move, unchanged in behaviour, into a validation header shared by the library).
#pragma once

#include <cstddef>

#include "../../config.hpp"
#include "../../real.hpp"
#include "../../vector3.hpp"

namespace pointmass::forces::detail {

template <Real R>
constexpr bool check_non_negative(const char* function, const char* argument, R value) {
  if (real_isfinite(value) && value >= R(0)) return true;
  pointmass::detail::report_scalar(function, argument, ">= 0 and finite", value);
  return false;
}

template <Real R>
constexpr bool check_positive(const char* function, const char* argument, R value) {
  if (real_isfinite(value) && value > R(0)) return true;
  pointmass::detail::report_scalar(function, argument, "> 0 and finite", value);
  return false;
}

template <Real R>
constexpr bool check_finite(const char* function, const char* argument, R value) {
  if (real_isfinite(value)) return true;
  pointmass::detail::report_scalar(function, argument, "finite", value);
  return false;
}

template <Real R>
constexpr bool check_finite(const char* function, const char* argument, const Vector3<R>& v) {
  if (is_finite(v)) return true;
  pointmass::detail::report_vector(function, argument, "finite", v);
  return false;
}

/// A step's duration: finite and >= 0.
template <Real R>
constexpr bool check_duration(const char* function, R duration) {
  if (real_isfinite(duration) && duration >= R(0)) return true;
  pointmass::detail::report_scalar(function, "duration", "finite and >= 0", duration);
  return false;
}

/// An index into bodies 0 .. size - 1.
constexpr bool check_index(const char* function, const char* argument, std::size_t index,
                           std::size_t size) {
  if (index < size) return true;
  pointmass::detail::report_scalar(function, argument, "< size() of the bodies", index);
  return false;
}

/// A generator's force from finite input: finite unless the force is beyond the range of R
/// (docs/forces.md, "Ranges"), which is reported instead of added.
template <Real R>
constexpr bool check_force(const char* function, const Vector3<R>& force) {
  if (is_finite(force)) return true;
  pointmass::detail::report_vector(
      function, "force",
      "finite: the generator's force at this body's state is beyond the range of the "
      "number type (docs/forces.md, Ranges)",
      force);
  return false;
}

/// A state a closed-form step computed from finite input: finite unless beyond the range of
/// the number type (docs/forces.md, Ranges), which is reported instead of stored.
template <Real R>
constexpr bool check_state(const char* function, const Vector3<R>& position,
                           const Vector3<R>& velocity) {
  if (is_finite(position) && is_finite(velocity)) return true;
  pointmass::detail::report_vector(
      function, is_finite(position) ? "velocity" : "position",
      "finite: the state after this step is beyond the range of the number type "
      "(docs/forces.md, Ranges)",
      is_finite(position) ? velocity : position);
  return false;
}

}  // namespace pointmass::forces::detail
