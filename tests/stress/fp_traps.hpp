// SPDX-License-Identifier: BSL-1.0
// Traps the floating-point exceptions that mean a NaN or an infinity was made (invalid,
// divide-by-zero, overflow) while the guard lives: the process stops with SIGFPE at the
// faulting operation, so the test fails there. Where feenableexcept is missing the flags
// are still collected and `raised()` reports them.
#pragma once

#include <cfenv>

namespace pointmass::test {

class TrapFloatingPointExceptions {
 public:
  static constexpr int traps = FE_INVALID | FE_DIVBYZERO | FE_OVERFLOW;
  TrapFloatingPointExceptions() {
    std::feclearexcept(FE_ALL_EXCEPT);
#if defined(__GLIBC__)
    feenableexcept(traps);
#endif
  }
  ~TrapFloatingPointExceptions() {
#if defined(__GLIBC__)
    fedisableexcept(traps);
#endif
  }
  TrapFloatingPointExceptions(const TrapFloatingPointExceptions&) = delete;
  TrapFloatingPointExceptions& operator=(const TrapFloatingPointExceptions&) = delete;

  /// True if a trapped exception's flag is set (only reachable without feenableexcept).
  static bool raised() { return std::fetestexcept(traps) != 0; }
};

}  // namespace pointmass::test
