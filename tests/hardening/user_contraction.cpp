// SPDX-License-Identifier: BSL-1.0
// The consumer's own contraction setting holds in its code after the library's headers (which
// turn contraction off for their own code only, and restore it): with clang's default
// (-ffp-contract=on) and fused multiply-adds, the consumer's a * b + c is one fused
// multiply-add. Exits 1 if it is not (determinism_native.sh runs it where there is FMA).
#include <cmath>
#include <cstdio>

#include <pointmass/forces.hpp>
#include <pointmass/pointmass.hpp>

namespace {
double user_expression(double a, double b, double c) { return a * b + c; }
}  // namespace

int main() {
  // a * b = 1 - 2^-60 exactly: the unfused sum rounds it to 1 first and gives 0; fused, -2^-60.
  volatile double va = 1.0 + 0x1p-30, vb = 1.0 - 0x1p-30, vc = -1.0;
  const double a = va, b = vb, c = vc;
  const double fused = std::fma(a, b, c);
  const double got = user_expression(a, b, c);
  if (got != fused || fused == 0.0) {
    std::printf("FAILED: the consumer's a * b + c = %a, fused %a: not fused\n", got, fused);
    return 1;
  }
  std::printf("the consumer's a * b + c is fused after the library's headers\n");
  return 0;
}
