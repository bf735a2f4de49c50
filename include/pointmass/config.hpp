// SPDX-License-Identifier: BSL-1.0
// pointmass/config.hpp — the library's configuration and its one contract mechanism.
//
// POINTMASS_HD        marks every function a GPU kernel may call (`__host__ __device__`
//                     under a CUDA compiler, nothing otherwise).
// POINTMASS_VERSION   the library's version, as major * 10000 + minor * 100 + patch.
//
// Contracts. Two kinds of check, one mechanism:
//   * Setters (`set_mass`, `set_damping`, ...) always validate: they are off the hot path.
//   * Hot-path preconditions (`integrate`'s duration, `add_force`'s vector) are checked when
//     POINTMASS_CHECKS is 1: by default in debug builds (NDEBUG undefined). Define
//     POINTMASS_ENABLE_CHECKS to check in release builds too, or POINTMASS_DISABLE_CHECKS
//     to check nowhere.
// A failed check calls the installed ContractHandler with a ContractViolation that names the
// function, the argument and its value, and the requirement it broke. The default handler
// throws std::invalid_argument where exceptions are enabled; with -fno-exceptions it prints
// the message to stderr and aborts. `set_contract_handler` installs another. If a handler
// returns, the call that failed its check returns without changing anything.
//
// Owns: the version, POINTMASS_HD, the checks settings (POINTMASS_CHECKS, POINTMASS_HOST_CHECKS),
// the inline namespace keyed by the exceptions setting, the contract handler, and the scope of
// the library's uncontracted arithmetic (POINTMASS_DETAIL_UNFUSED_BEGIN / _END).
// Must not include: any other pointmass header (every header includes this one).
#pragma once

#include <atomic>
#include <charconv>
#include <cstddef>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <string>

#if defined(__cpp_exceptions) || defined(__EXCEPTIONS)
#include <stdexcept>
#define POINTMASS_HAS_EXCEPTIONS 1
#else
#define POINTMASS_HAS_EXCEPTIONS 0
#endif

#define POINTMASS_VERSION_MAJOR 0
#define POINTMASS_VERSION_MINOR 1
#define POINTMASS_VERSION_PATCH 0
#define POINTMASS_VERSION \
  (POINTMASS_VERSION_MAJOR * 10000 + POINTMASS_VERSION_MINOR * 100 + POINTMASS_VERSION_PATCH)

#if defined(__CUDACC__)
#define POINTMASS_HD __host__ __device__
#else
#define POINTMASS_HD
#endif

#if defined(POINTMASS_DISABLE_CHECKS)
#define POINTMASS_CHECKS 0
#elif defined(POINTMASS_ENABLE_CHECKS) || !defined(NDEBUG)
#define POINTMASS_CHECKS 1
#else
#define POINTMASS_CHECKS 0
#endif

// Settings and the one-definition rule.
//   * POINTMASS_CHECKS changes no type: a translation unit built with checks and one built
//     without share every pointmass type, so a Release library and a Debug program link.
//     An inline function compiled both ways is kept once by the linker: a program that
//     mixes the settings gets one unit's copy of it, checked or not. To be sure of the
//     checks, give every unit the same setting.
//   * Exceptions change the types: with them the declarations live in pointmass::v0, without
//     them (-fno-exceptions) in pointmass::v0_no_exceptions. Each unit then reports a failure
//     as its own setting says (a throw, or a message and abort()); sharing an object between
//     the two kinds of unit fails at link time instead of choosing the wrong failure.
//   * -fno-math-errno changes how a fused law's square root is formed (the hardware's, not the
//     library's arithmetic: forces/fused.hpp), never its bits: units built either way agree.
// User code names everything pointmass::X; the contract handler is one for the whole program.
#if POINTMASS_HAS_EXCEPTIONS
#define POINTMASS_ABI_NAMESPACE v0
#else
#define POINTMASS_ABI_NAMESPACE v0_no_exceptions
#endif

// Whether this compilation pass checks hot-path preconditions: POINTMASS_CHECKS on the host;
// never in device code (a GPU kernel has no contract handler to call). Decided here once;
// call sites write `#if POINTMASS_HOST_CHECKS`.
#if POINTMASS_CHECKS && !defined(__CUDA_ARCH__)
#define POINTMASS_HOST_CHECKS 1
#else
#define POINTMASS_HOST_CHECKS 0
#endif

// Inlined into the caller at any optimisation level: the hot paths whose call from a loop
// would stop vectorisation (a batch's kernel, the damping factors, the exponential) or cost
// more than the work (a Particle's step once its factors are known).
#if defined(__GNUC__)
#define POINTMASS_DETAIL_ALWAYS_INLINE [[gnu::always_inline]]
#else
#define POINTMASS_DETAIL_ALWAYS_INLINE
#endif

// The error-free steps (TwoSum, Fast2Sum, rounding to an integer by adding 1.5 * 2^(p-1))
// hold only in the order they are written: -fassociative-math (part of -ffast-math) lets the
// compiler simplify (a + b) - a to b and so cancel them (d^t would be 1; a far compensated
// position would never move). clang, which names no macro for the flag, keeps the order of every
// function body that begins with POINTMASS_DETAIL_IN_ORDER (a pragma; a no-op in ordinary
// builds). g++ names it (__ASSOCIATIVE_MATH__) but has no barrier that its vectoriser keeps
// (__builtin_assoc_barrier is lost where it vectorises a Particle's x and y): refused.
#if defined(__clang__)
#define POINTMASS_DETAIL_IN_ORDER _Pragma("clang fp reassociate(off)")
#else
#define POINTMASS_DETAIL_IN_ORDER
#endif
// POINTMASS_STRICT_FP=1 (pointmass::strict_fp defines it): the library's arithmetic is what
// it is written as, whatever the consumer's contraction setting. Every header's code lies
// between POINTMASS_DETAIL_UNFUSED_BEGIN and _END (a test checks), which with clang then turn
// contraction (a * b + c into one fused multiply-add) off there and restore the consumer's
// setting after; -ffp-contract=fast (and -ffast-math) overrides them. Not the default: with
// FMA, unfused arithmetic slows the exponential's polynomial (a changing step) up to 2x.
// g++ has no such scope: it decides contraction per function, after inlining, and an optimize
// attribute would keep the library from being inlined at all. Its consumers compile with
// -ffp-contract=off (pointmass::strict_fp adds it), see docs/numerics.md.
#ifndef POINTMASS_STRICT_FP
#define POINTMASS_STRICT_FP 0
#endif
#if defined(__clang__) && !defined(__NVCC__) && POINTMASS_STRICT_FP
#define POINTMASS_DETAIL_UNFUSED_BEGIN \
  _Pragma("float_control(push)") _Pragma("clang fp contract(off)")
#define POINTMASS_DETAIL_UNFUSED_END _Pragma("float_control(pop)")
#else
#define POINTMASS_DETAIL_UNFUSED_BEGIN
#define POINTMASS_DETAIL_UNFUSED_END
#endif
#if defined(__ASSOCIATIVE_MATH__) && !defined(__clang__)
#error \
    "pointmass: -fassociative-math (part of -ffast-math) reorders the library's exact sums and breaks damping and compensated positions: add -fno-associative-math"
#endif

namespace pointmass {

/// Room for ContractViolation::text at its longest, three long doubles: each with a sign, a
/// point, max_digits10 digits and an exponent of up to five digits (21 digits for x87's 64-bit
/// long double, 36 for a 113-bit quad), "(", two ", ", ")" and the terminating zero; 128 at
/// least.
inline constexpr std::size_t contract_text_size =
    3 * (std::numeric_limits<long double>::max_digits10 + 9) + 6 > 128
        ? 3 * (std::numeric_limits<long double>::max_digits10 + 9) + 6
        : 128;

/// What a failed check reports: enough to write "integrate: duration = -0.1 must be >= 0".
struct ContractViolation {
  const char* function;     ///< the public function whose precondition failed
  const char* argument;     ///< the argument's name, as documented
  const char* requirement;  ///< what the argument must satisfy
  long double value[3];     ///< the offending value (a vector uses all three)
  int components;           ///< 1 for a number, 3 for a vector
  /// The value as written in its own precision: "-2.5", "(0, inf, 0)".
  char text[contract_text_size];
  /// When the value is one of many a call takes (spawn_burst: the particle its generator
  /// returned for k), that call's name and the element's index; otherwise null and 0.
  const char* within = nullptr;
  std::size_t element = 0;
};

using ContractHandler = void (*)(const ContractViolation&);

/// "set_mass: argument 'mass' = -1 must be > 0 and not NaN".
inline std::string describe(const ContractViolation& violation) {
  std::string message = "pointmass: ";
  message += violation.function;
  message += ": argument '";
  message += violation.argument;
  message += "' = ";
  message += violation.text;
  message += " must be ";
  message += violation.requirement;
  if (violation.within != nullptr) {
    message += " (in ";
    message += violation.within;
    message += ", element ";
    message += std::to_string(violation.element);
    message += ")";
  }
  return message;
}

// The installed handler: one for the whole program, whatever each translation unit's
// settings (so it stays outside the inline namespace); null means each unit's default.
namespace shared_state {
inline std::atomic<ContractHandler> contract_handler{nullptr};
}  // namespace shared_state

inline namespace POINTMASS_ABI_NAMESPACE {

/// The default handler: throw std::invalid_argument, or print and abort without exceptions.
/// Either way it never returns.
[[noreturn]] inline void default_contract_handler(const ContractViolation& violation) {
#if POINTMASS_HAS_EXCEPTIONS
  throw std::invalid_argument(describe(violation));
#else
  const std::string message = describe(violation);
  std::fputs(message.c_str(), stderr);
  std::fputc('\n', stderr);
  std::abort();
#endif
}

/// The handler a failed check calls.
inline ContractHandler contract_handler() noexcept {
  const ContractHandler installed = shared_state::contract_handler.load();
  return installed != nullptr ? installed : &default_contract_handler;
}

/// Installs `handler` (nullptr restores the default) and returns the one it replaces.
inline ContractHandler set_contract_handler(ContractHandler handler) noexcept {
  const ContractHandler previous = shared_state::contract_handler.exchange(
      handler != &default_contract_handler ? handler : nullptr);
  return previous != nullptr ? previous : &default_contract_handler;
}

}  // namespace POINTMASS_ABI_NAMESPACE

namespace shared_state {
/// The element a many-valued call is checking on this thread (ContractViolation::within and
/// element), copied into every violation reported meanwhile.
struct ReportElement {
  const char* within = nullptr;
  std::size_t element = 0;
};
inline thread_local ReportElement report_element{};
}  // namespace shared_state

}  // namespace pointmass

namespace pointmass::inline POINTMASS_ABI_NAMESPACE::detail {

// Appends x, in the shortest form that reads back as the same T, to text at *used.
template <class T>
void append_number(char (&text)[contract_text_size], std::size_t& used, T x) {
  const auto result = std::to_chars(text + used, text + sizeof text - 1, x);
  used = static_cast<std::size_t>(result.ptr - text);
}
inline void append_text(char (&text)[contract_text_size], std::size_t& used, const char* part) {
  while (*part != '\0' && used + 1 < sizeof text) text[used++] = *part++;
}

[[gnu::cold]] inline void report(ContractViolation& violation, std::size_t used) {
  violation.text[used] = '\0';
  violation.within = shared_state::report_element.within;
  violation.element = shared_state::report_element.element;
  pointmass::contract_handler()(violation);
}

/// Names, for its lifetime, the element of `within` whose values the checks look at (put
/// into every violation reported meanwhile on this thread); the previous one is back after
/// it, whether the scope ends normally or by an exception.
class ReportingElement {
 public:
  ReportingElement(const char* within, std::size_t element) noexcept
      : previous_(shared_state::report_element) {
    shared_state::report_element = {within, element};
  }
  ReportingElement(const ReportingElement&) = delete;
  ReportingElement& operator=(const ReportingElement&) = delete;
  ~ReportingElement() { shared_state::report_element = previous_; }

 private:
  shared_state::ReportElement previous_;
};

// Out of line and cold, so that a check costs the hot path one compare and one branch.
template <class T>
[[gnu::cold]] [[gnu::noinline]] void report_scalar(const char* function, const char* argument,
                                                   const char* requirement, T value) {
  ContractViolation violation{
      function, argument, requirement, {static_cast<long double>(value), 0.0L, 0.0L}, 1, {}};
  std::size_t used = 0;
  append_number(violation.text, used, value);
  report(violation, used);
}

template <class V>
[[gnu::cold]] [[gnu::noinline]] void report_vector(const char* function, const char* argument,
                                                   const char* requirement, const V& value) {
  ContractViolation violation{function,
                              argument,
                              requirement,
                              {static_cast<long double>(value.x), static_cast<long double>(value.y),
                               static_cast<long double>(value.z)},
                              3,
                              {}};
  std::size_t used = 0;
  append_text(violation.text, used, "(");
  append_number(violation.text, used, value.x);
  append_text(violation.text, used, ", ");
  append_number(violation.text, used, value.y);
  append_text(violation.text, used, ", ");
  append_number(violation.text, used, value.z);
  append_text(violation.text, used, ")");
  report(violation, used);
}

}  // namespace pointmass::inline POINTMASS_ABI_NAMESPACE::detail
