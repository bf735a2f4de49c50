// SPDX-License-Identifier: BSL-1.0
// The unit of the mixed-exceptions program built with -fno-exceptions: its failures must be
// reported its way (the handler, then abort()) even though exceptions.cpp instantiates the
// same functions with exceptions.
#define POINTMASS_ENABLE_CHECKS 1
#include <cstdlib>

#include "odr.hpp"

namespace {
int reports = 0;
void count(const pointmass::ContractViolation&) { ++reports; }
}  // namespace

void no_exceptions_contract_reports() {
  const pointmass::ContractHandler previous = pointmass::set_contract_handler(&count);
  pointmass::ParticleSystem<float> system;
  system.spawn({}, {});
  system.step(-1.0f);  // reported; the handler returns, and the step changes nothing
  pointmass::set_contract_handler(previous);
  if (reports != 1 || system.position(0).x != 0.0f) std::abort();
}

void no_exceptions_reserve_beyond_max_size() {
  pointmass::ParticleSystem<float> system;
  system.reserve(system.max_size() + 1);
}
