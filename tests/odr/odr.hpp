// SPDX-License-Identifier: BSL-1.0
// What the translation units of the mixed-settings programs share.
#pragma once
#include <pointmass/particle_system.hpp>

// checks.cpp: built with the checks off; mixed_checks.cpp (the program) has them on.
void released_step(pointmass::ParticleSystem<float>& system, float duration);

// no_exceptions.cpp, built with -fno-exceptions.
void no_exceptions_contract_reports();         // a check's report reaches the installed handler
void no_exceptions_reserve_beyond_max_size();  // reported with the default handler: abort()
