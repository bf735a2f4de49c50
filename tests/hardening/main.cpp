// SPDX-License-Identifier: BSL-1.0
// doctest's main for the suites that build doctest with other settings: without exceptions,
// and under -ffast-math.
#define DOCTEST_CONFIG_IMPLEMENT_WITH_MAIN
#include <doctest/doctest.h>
