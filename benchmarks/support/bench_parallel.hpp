// SPDX-License-Identifier: BSL-1.0
// bench_support.hpp's read-modify-write loop on the standard parallel algorithms (libstdc++
// runs them on TBB: the program links TBB::tbb).
#pragma once

#include <pointmass/parallel.hpp>

#include <algorithm>
#include <cstddef>
#include <execution>

#include "bench_support.hpp"

namespace pointmass_benchmarks {

/// bandwidth, in chunks of 16,384 elements run by std::for_each(par_unseq).
template <class R>
void bandwidth_parallel(benchmark::State& state, StaggeredArrays<R>& arrays) {
  const auto n = static_cast<std::size_t>(state.range(0));
  const R c = duration<R>();
  R** a = arrays.array;
  constexpr std::size_t chunk = 16384;
  const std::size_t chunks = (n + chunk - 1) / chunk;
  for (auto _ : state) {
    std::for_each(std::execution::par_unseq, pointmass::detail::CountingIterator(0),
                  pointmass::detail::CountingIterator(chunks), [&](std::size_t k) {
                    const std::size_t begin = k * chunk;
                    const std::size_t end = std::min(begin + chunk, n);
                    rmw(a[0] + begin, a[1] + begin, a[2] + begin, a[3] + begin, a[4] + begin,
                        a[5] + begin, end - begin, c);
                  });
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations() * state.range(0));
}

}  // namespace pointmass_benchmarks
