// SPDX-License-Identifier: BSL-1.0
// The doctest main for the batch (ParticleSystem) suite.
#define DOCTEST_CONFIG_IMPLEMENT_WITH_MAIN
#include <doctest/doctest.h>
