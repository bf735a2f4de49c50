// The accuracy comparison: the reference engine's four ballistic shots, stepped by every
// compile-time variant of the particle at 30, 60, 120 and 240 frames a second, against the
// exact solution of the motion each variant models. Prints, per shot, the largest position
// error over the 5 s flight (metres), the observed order as the frame time halves, and the
// run time per step of each variant (indicative: for figures to compare, use benchmarks/).
//
//   scripts/demo.sh            (builds in release and runs this program)
#include <chrono>
#include <cstdio>
#include <string>

#include "accuracy.hpp"

namespace accuracy = pointmass::accuracy;

namespace {

/// Nanoseconds per step of variant <D, P> in double on a shot, over many runs at 1/60 s.
template <class D, class P>
double nanoseconds_per_step(const accuracy::Scene& s) {
  const double h = 1.0 / 60;
  const long steps = accuracy::steps_for(s, h);
  double sink = 0;
  long total = 0;
  const auto start = std::chrono::steady_clock::now();
  for (int run = 0; run < 2000; ++run) {
    auto particle = accuracy::make_particle<double, D, P>(s, h);
    for (long n = 0; n < steps; ++n) particle.integrate(h);
    sink += particle.position().z;
    total += steps;
  }
  const std::chrono::duration<double, std::nano> elapsed = std::chrono::steady_clock::now() - start;
  if (sink == 0.125) std::puts("");  // keeps the runs from being optimised away
  return elapsed.count() / static_cast<double>(total);
}

}  // namespace

int main() {
  std::puts("pointmass: accuracy of every policy combination on the reference engine's ballistic shots");
  std::puts("(largest position error in metres over 5 s against the exact solution, double;");
  std::puts(" 'exact' = the step is the model's exact flow, the error is rounding)\n");
  for (const accuracy::Scene& s : accuracy::ballistic_scenes()) {
    std::printf("## %s: mass %g kg, damping %g per second\n\n", s.name.c_str(), s.mass, s.damping);
    std::fputs(accuracy::error_table(s).c_str(), stdout);
    std::puts("");
  }
  std::puts("## run time per step (double, pistol shot, 1/60 s; indicative)\n");
  const accuracy::Scene pistol = accuracy::ballistic_scenes()[0];
  accuracy::for_each_combination([&]<class D, class P>() {
    std::printf("%-34s %6.2f ns\n", accuracy::combination_name<D, P>().c_str(),
                nanoseconds_per_step<D, P>(pistol));
  });
  return 0;
}
