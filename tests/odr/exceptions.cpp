// SPDX-License-Identifier: BSL-1.0
// The mixed-exceptions program: this unit has exceptions, no_exceptions.cpp (linked first, so
// that its definitions would be the ones kept were the names shared) has none. Each unit's
// failures are reported its own way: here std::invalid_argument and std::length_error.
// With the argument "abort", the other unit's reserve beyond max_size() must print the report
// and abort(), not throw into code built without exceptions (std::terminate).
#define POINTMASS_ENABLE_CHECKS 1
#include <cstdio>
#include <cstring>
#include <stdexcept>

#include "odr.hpp"

int main(int argc, char** argv) {
  if (argc > 1 && std::strcmp(argv[1], "abort") == 0) {
    no_exceptions_reserve_beyond_max_size();
    return 0;  // not reached
  }
  pointmass::ParticleSystem<float> system;
  system.spawn({}, {});
  bool invalid_argument = false;
  bool length_error = false;
  try {
    system.step(-1.0f);
  } catch (const std::invalid_argument&) {
    invalid_argument = true;
  }
  try {
    system.reserve(system.max_size() + 1);
  } catch (const std::length_error&) {
    length_error = true;
  }
  no_exceptions_contract_reports();
  std::printf("with exceptions: invalid_argument %s, length_error %s\n",
              invalid_argument ? "thrown" : "not thrown", length_error ? "thrown" : "not thrown");
  if (invalid_argument && length_error) std::printf("odr: ok\n");
  return invalid_argument && length_error ? 0 : 1;
}
