// SPDX-License-Identifier: BSL-1.0
// pointmass/detail/validate.hpp — the library's argument checks, written once.
//
// Owns: what "a valid mass", "a valid damping", "a finite vector", "a valid index", "a force
// in range", ... mean, and the report each failure makes. Every public setter of Particle,
// ParticleSystem and the force generators validates through these functions, so one rule has
// one wording.
// Each returns true when the argument is valid; otherwise it reports a ContractViolation
// (config.hpp) naming the function, the argument and its value, and returns false, and the
// caller changes nothing. NaN and infinity are found by bit pattern (real.hpp), so the checks
// hold under -ffast-math too.
//
// Must not include: anything but config.hpp, real.hpp and vector3.hpp (it is below every
// header that validates).
#pragma once

#include <concepts>
#include <cstddef>
#include <limits>
#include <type_traits>

#include "../config.hpp"
#include "../real.hpp"
#include "../vector3.hpp"

POINTMASS_DETAIL_UNFUSED_BEGIN
namespace pointmass::inline POINTMASS_ABI_NAMESPACE::detail {

/// A vector with three finite components.
template <Real R>
constexpr bool check_finite(const char* function, const char* argument, const Vector3<R>& v) {
  if (is_finite(v)) return true;
  report_vector(function, argument, "finite", v);
  return false;
}

/// A finite number.
template <Real R>
constexpr bool check_finite(const char* function, const char* argument, R value) {
  if (real_isfinite(value)) return true;
  report_scalar(function, argument, "finite", value);
  return false;
}

/// A damping value: the fraction of velocity kept, in [0, 1].
template <Real R>
constexpr bool check_damping(const char* function, R damping) {
  if (!real_isnan(damping) && damping >= R(0) && damping <= R(1)) return true;
  report_scalar(function, "damping", "in [0, 1]", damping);
  return false;
}

/// A mass: > 0 (infinity: immovable), with 1/mass finite and not subnormal, so that
/// mass() == 1 / inverse_mass() stays finite for every finite mass accepted.
template <Real R>
constexpr bool check_mass(const char* function, R mass) {
  if (!real_isnan(mass) && mass > R(0)) {  // only then divide: 1 / 0 is a division by zero
    const R inverse = R(1) / mass;
    if (real_equal(inverse, R(0)) ||
        (real_isfinite(inverse) && inverse >= std::numeric_limits<R>::min())) {
      return true;
    }
  }
  report_scalar(function, "mass", "> 0 and not NaN, with 1/mass finite and normal", mass);
  return false;
}

/// An inverse mass: 0 (immovable) or a finite normal number > 0.
template <Real R>
constexpr bool check_inverse_mass(const char* function, R inverse_mass) {
  if (real_equal(inverse_mass, R(0)) ||
      (real_isfinite(inverse_mass) && inverse_mass >= std::numeric_limits<R>::min())) {
    return true;
  }
  report_scalar(function, "inverse_mass", ">= 0 and finite, and not subnormal", inverse_mass);
  return false;
}

/// A span of time named `argument` (a step's duration, a frame's time): finite and >= 0.
template <Real R>
constexpr bool check_duration(const char* function, const char* argument, R value) {
  if (real_isfinite(value) && value >= R(0)) return true;
  report_scalar(function, argument, "finite and >= 0", value);
  return false;
}

/// A step's duration, the argument `duration`: finite and >= 0.
template <Real R>
constexpr bool check_duration(const char* function, R duration) {
  return check_duration(function, "duration", duration);
}

/// A lifetime in seconds: > 0 (infinity: for ever).
template <Real R>
constexpr bool check_lifetime(const char* function, R seconds) {
  if (!real_isnan(seconds) && seconds > R(0)) return true;
  report_scalar(function, "seconds", "> 0 (infinity: for ever)", seconds);
  return false;
}

/// A number >= 0 (and not NaN); `finite` also rejects infinity.
template <Real R>
constexpr bool check_non_negative(const char* function, const char* argument, R value,
                                  bool finite = true) {
  if (!real_isnan(value) && value >= R(0) && (!finite || real_isfinite(value))) return true;
  report_scalar(function, argument, finite ? ">= 0 and finite" : ">= 0 and not NaN", value);
  return false;
}

/// check_non_negative(function, argument, value) (>= 0 and finite), and on success
/// `member = value`: the body of a generator's setter for a non-negative parameter.
template <Real R>
constexpr bool assign_non_negative(const char* function, const char* argument, R value, R& member) {
  if (!check_non_negative(function, argument, value)) return false;
  member = value;
  return true;
}

/// A number > 0 and finite.
template <Real R>
constexpr bool check_positive(const char* function, const char* argument, R value) {
  if (real_isfinite(value) && value > R(0)) return true;
  report_scalar(function, argument, "> 0 and finite", value);
  return false;
}

/// An index of a live particle: < size.
constexpr bool check_index(const char* function, std::size_t index, std::size_t size) {
  if (index < size) return true;
  report_scalar(function, "index", "< size()", index);
  return false;
}

/// An index named `argument` into a batch of bodies 0 .. size - 1 (forces::apply_links).
constexpr bool check_index(const char* function, const char* argument, std::size_t index,
                           std::size_t size) {
  if (index < size) return true;
  report_scalar(function, argument, "< size() of the bodies", index);
  return false;
}

/// A force generator's force from finite input: finite unless the force is beyond the range
/// of R (docs/forces.md, "Ranges"), which is reported instead of added.
template <Real R>
constexpr bool check_force(const char* function, const Vector3<R>& force) {
  if (is_finite(force)) return true;
  report_vector(function, "force",
                "finite: the generator's force at this body's state is beyond the range of "
                "the number type (docs/forces.md, Ranges)",
                force);
  return false;
}

/// Law `index` of a fused step (forces::Laws) gave a force beyond the range of the number
/// type on at least one particle; it was not added to those particles.
inline void report_law_range(const char* function, unsigned index) {
  report_scalar(function, "law",
                "giving a finite force: this law's force on at least one particle is beyond "
                "the range of the number type (docs/forces.md, Ranges) and was not added to it",
                index);
}

/// A state a closed-form step computed from finite input: finite unless beyond the range of
/// the number type (docs/forces.md, Ranges), which is reported instead of stored.
template <Real R>
constexpr bool check_state(const char* function, const Vector3<R>& position,
                           const Vector3<R>& velocity) {
  if (is_finite(position) && is_finite(velocity)) return true;
  report_vector(function, is_finite(position) ? "velocity" : "position",
                "finite: the state after this step is beyond the range of the number type "
                "(docs/forces.md, Ranges)",
                is_finite(position) ? velocity : position);
  return false;
}

/// A finite value whose stored (narrower) form `stored` is finite too: a position set on a
/// particle that stores it as Compensated<R> must lie within R's range.
template <Real W, Real R>
constexpr bool check_representable(const char* function, const char* argument,
                                   const Vector3<W>& value, const Vector3<R>& stored) {
  if (is_finite(stored)) return true;
  report_vector(function, argument, "within the range of the position's stored Real", value);
  return false;
}

// "'out' = 2 elements for size() = 3 must be at least size() elements long": a span or buffer
// of `length` elements where `bound` (named `bound_name`) are needed.
[[gnu::cold]] [[gnu::noinline]] inline void report_length(
    const char* function, const char* argument, const char* requirement, std::size_t length,
    const char* bound_name, std::size_t bound) {
  ContractViolation violation{
      function, argument, requirement, {static_cast<long double>(length), 0.0L, 0.0L}, 1, {}};
  std::size_t used = 0;
  append_number(violation.text, used, length);
  append_text(violation.text, used, " elements for ");
  append_text(violation.text, used, bound_name);
  append_text(violation.text, used, " = ");
  append_number(violation.text, used, bound);
  report(violation, used);
}

/// A caller's buffer with room for `needed` (the system's size()) elements.
constexpr bool check_buffer(const char* function, const char* argument, std::size_t size,
                            std::size_t needed) {
  if (size >= needed) return true;
  report_length(function, argument, "at least size() elements long", size, "size()", needed);
  return false;
}

/// A span of a batch adapter (forces::SpanBodies, SoaBodies) with an element for each of the
/// `size` bodies: a shorter one would be read or written beyond its end.
constexpr bool check_span(const char* function, const char* argument, std::size_t span_size,
                          std::size_t size) {
  if (span_size >= size) return true;
  report_length(function, argument,
                "at least size() elements long (size() is the length of the forces)", span_size,
                "size()", size);
  return false;
}

/// A fraction of a step (interpolation's alpha): in [0, 1].
template <Real R>
constexpr bool check_fraction(const char* function, const char* argument, R value) {
  if (!real_isnan(value) && value >= R(0) && value <= R(1)) return true;
  report_scalar(function, argument, "in [0, 1]", value);
  return false;
}

/// A count of at least `least` (a stride of 3 numbers, a cap of 1 step), reported as given
/// (a negative int stays negative in the report).
template <std::integral I>
constexpr bool check_at_least(const char* function, const char* argument, I value,
                              std::type_identity_t<I> least) {
  if (value >= least) return true;
  report_scalar(function, argument,
                least == 1   ? ">= 1"
                : least == 3 ? ">= 3 (x, y and z)"
                             : ">= the least allowed",
                value);
  return false;
}

/// A caller's buffer of `available` elements, where `needed` are written.
constexpr bool check_strided_buffer(const char* function, std::size_t available,
                                    std::size_t needed) {
  if (available >= needed) return true;
  report_length(function, "out", "at least that many elements long", available,
                "(size() - 1) * stride + 3", needed);
  return false;
}

/// A pass of a system that calls the caller's code for each particle while it removes or
/// adds them: an expiry callback (step with on_expire), kill_if's predicate, spawn_burst's
/// generator (whose particles must stay the last ones). Inside one, the calls that remove or
/// step particles are refused (the pass is walking the indices); spawning is allowed.
enum class RemovalPass : unsigned char { none, expiry, predicate, burst };

/// Not inside a removal pass, for a call that removes particles; `index` is the particle the
/// call would have removed.
constexpr bool check_not_removing(const char* function, RemovalPass pass, std::size_t index) {
  if (pass == RemovalPass::none) return true;
  report_scalar(function, "index",
                pass == RemovalPass::expiry
                    ? "removed after the expiry callback returns (spawn there; kill after the "
                      "step)"
                : pass == RemovalPass::burst
                    ? "removed after spawn_burst's generator returns"
                    : "removed after kill_if's predicate returns (or return true to remove the "
                      "particle it is asked about)",
                index);
  return false;
}
/// Not inside a removal pass, for a call that steps (or expires) particles; `argument` and
/// `value` are the call's (step's duration, finish_step's particle count).
template <class T>
constexpr bool check_not_stepping(const char* function, const char* argument, RemovalPass pass,
                                  T value) {
  if (pass == RemovalPass::none) return true;
  report_scalar(function, argument,
                pass == RemovalPass::expiry  ? "stepped after the expiry callback returns"
                : pass == RemovalPass::burst ? "stepped after spawn_burst's generator returns"
                                             : "stepped after kill_if's predicate returns",
                value);
  return false;
}

/// A view handed to finish_step: begun by this system's begin_step and not finished yet
/// (`mine`), over the particles begin_step saw (`unchanged`); `size` is the view's.
constexpr bool check_step_view(const char* function, bool mine, bool unchanged, std::size_t size) {
  if (!mine) {
    report_scalar(function, "view", "from this system's begin_step, not finished yet", size);
    return false;
  }
  if (!unchanged) {
    report_scalar(function, "view",
                  "over the particles begin_step saw (none spawned or killed since)", size);
    return false;
  }
  return true;
}

/// A range of live particles: begin <= end <= size.
constexpr bool check_range(const char* function, std::size_t begin, std::size_t end,
                           std::size_t size) {
  if (end > size) {
    report_scalar(function, "end", "<= size()", end);
    return false;
  }
  if (begin > end) {
    report_scalar(function, "begin", "<= end", begin);
    return false;
  }
  return true;
}

}  // namespace pointmass::detail
POINTMASS_DETAIL_UNFUSED_END
