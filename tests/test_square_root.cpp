// SPDX-License-Identifier: BSL-1.0
// detail::square_root against std::sqrt, bit for bit: the edge cases, every float of a dense
// sample (all of them in the stress suite) and a large sample of doubles with the hard cases.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <pointmass/detail/square_root.hpp>
#include <random>

namespace {

template <class R>
using bits_t = typename pointmass::detail::FloatBits<R>::type;

// The same bits, or both NaN (a negative x's NaN is the platform's own).
template <class R>
bool same_root(R x) {
  const R ours = pointmass::detail::square_root(x);
  const R theirs = std::sqrt(x);
  if (std::isnan(theirs)) return std::isnan(ours);
  return __builtin_bit_cast(bits_t<R>, ours) == __builtin_bit_cast(bits_t<R>, theirs);
}

template <class R>
R from_bits(bits_t<R> b) {
  return __builtin_bit_cast(R, b);
}

template <class R>
void check_edges() {
  using limits = std::numeric_limits<R>;
  const R edges[] = {R(0),
                     -R(0),
                     limits::denorm_min(),
                     limits::min(),
                     limits::max(),
                     limits::infinity(),
                     -limits::infinity(),
                     limits::quiet_NaN(),
                     R(-1),
                     -limits::denorm_min(),
                     R(1),
                     R(2),
                     R(4),
                     limits::epsilon()};
  for (const R x : edges) CHECK_MESSAGE(same_root(x), x);
  for (int e = limits::min_exponent - limits::digits; e < limits::max_exponent; ++e) {
    const R power = std::ldexp(R(1), e);
    CHECK(same_root(power));
    CHECK(same_root(std::nextafter(power, R(0))));
    CHECK(same_root(std::nextafter(power, limits::infinity())));
  }
}

}  // namespace

TEST_CASE("square_root: the edge cases and every power of 2 with its neighbours, float") {
  check_edges<float>();
}
TEST_CASE("square_root: the edge cases and every power of 2 with its neighbours, double") {
  check_edges<double>();
}

TEST_CASE("square_root: std::sqrt's bits for every 61st float") {
  long wrong = 0;
  for (std::uint64_t b = 0; b <= 0x7f800000u; b += 61) {
    if (!same_root(from_bits<float>(static_cast<std::uint32_t>(b)))) ++wrong;
  }
  CHECK(wrong == 0);
}

TEST_CASE("square_root: std::sqrt's bits for random doubles, squares and their neighbours") {
  std::mt19937_64 random(20240601);
  long wrong = 0;
  for (int i = 0; i < 200000; ++i) {
    const double x = from_bits<double>(random() & 0x7fffffffffffffffu);
    if (!same_root(x)) ++wrong;
    // y^2 rounded, and its neighbours: roots next to a midpoint or exact.
    const double y = std::ldexp(static_cast<double>(random() >> 11) + 1.0, -26 - i % 60);
    const double square = y * y;
    if (!same_root(square)) ++wrong;
    if (!same_root(std::nextafter(square, 0.0))) ++wrong;
    if (!same_root(std::nextafter(square, 1e300))) ++wrong;
    const double small = std::ldexp(static_cast<double>(random() >> 12), -1074);  // subnormal
    if (!same_root(small)) ++wrong;
  }
  CHECK(wrong == 0);
}
