// SPDX-License-Identifier: BSL-1.0
// doctest's main, compiled once (pointmass_doctest_main) for every suite that builds doctest
// with its default settings.
#define DOCTEST_CONFIG_IMPLEMENT_WITH_MAIN
#include <doctest/doctest.h>
