// SPDX-License-Identifier: BSL-1.0
// The Kokkos suite's main: Kokkos initialised with 2 threads (what a threaded backend such as
// OpenMP then uses; Serial has one), doctest run, Kokkos finalised.
#define DOCTEST_CONFIG_IMPLEMENT
#include <doctest/doctest.h>

#include <Kokkos_Core.hpp>

int main(int argc, char** argv) {
#if KOKKOS_VERSION >= 30700
  Kokkos::initialize(Kokkos::InitializationSettings().set_num_threads(2));
#else
  Kokkos::InitArguments arguments;
  arguments.num_threads = 2;
  Kokkos::initialize(arguments);
#endif
  int result = 0;
  {
    doctest::Context context(argc, argv);
    result = context.run();
  }
  Kokkos::finalize();
  return result;
}
