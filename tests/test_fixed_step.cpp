// SPDX-License-Identifier: BSL-1.0
// FixedStep: the steps, dropped time and alpha of each frame, the cap, and frame times beyond
// the clock's range.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <pointmass/fixed_step.hpp>

using namespace pointmass;

TEST_CASE("FixedStep: the steps of an irregular frame sequence, never more than the cap") {
  // Step 1/64 s; frame times in 1/256 s (exact in binary), so an integer model is exact.
  FixedStep<double> clock(1.0 / 64, 3);
  const std::vector<int> frames{1, 3, 4, 0, 7, 9, 40, 2, 13, 64, 5, 3, 1, 12, 200, 0, 6};
  int model = 0;  // accumulated, in 1/256 s
  int total = 0;
  bool capped = false;
  for (const int f : frames) {
    const auto frame = clock.advance(f / 256.0);
    model += f;
    const int due = model / 4;
    const int expected = std::min(due, 3);
    CHECK(frame.steps == expected);
    CHECK(frame.steps <= clock.max_steps());
    model -= expected * 4;
    if (model >= 4) {  // the cap dropped whole steps
      CHECK(frame.dropped == (model / 4) * 4 / 256.0);
      model %= 4;
      capped = true;
    } else {
      CHECK(frame.dropped == 0.0);
    }
    CHECK(frame.alpha == model / 4.0);
    CHECK(clock.accumulated() == model / 256.0);
    total += frame.steps;
  }
  CHECK(capped);
  CHECK(total > 20);
}

TEST_CASE("FixedStep: frame times whose sum is beyond the clock's range stay finite") {
  // The accumulated time once overflowed to infinity, and fmod(inf, step) made the clock NaN
  // for good: every later frame took no step and drew at a NaN alpha.
  const double big = std::numeric_limits<double>::max();
  FixedStep<double> huge(big, 8);
  CHECK(huge.advance(0.9 * big).steps == 0);
  const auto due = huge.advance(0.9 * big);  // 1.8 max in all: one step, 0.8 max left
  CHECK(due.steps == 1);
  CHECK(due.dropped == 0.0);
  CHECK(huge.accumulated() == doctest::Approx(0.8 * big).epsilon(1e-12));
  CHECK(due.alpha == doctest::Approx(0.8).epsilon(1e-12));
  const float most = std::numeric_limits<float>::max();
  FixedStep<float> wide(0.6f * most, 8);
  CHECK(wide.advance(0.5f * most).steps == 0);
  CHECK(wide.advance(0.9f * most).steps == 2);  // 1.4 max in all: two steps, 0.2 max left
  CHECK(double(wide.accumulated()) == doctest::Approx(double(0.2f * most)).epsilon(1e-5));
  // The largest frame time on a game's step: the cap, the rest dropped in whole steps.
  for (FixedStep<float> clock : {FixedStep<float>(1.0f / 60, 8), FixedStep<float>()}) {
    clock.advance(0.01f);
    const auto frame = clock.advance(most);
    CHECK(frame.steps == 8);
    CHECK(std::isfinite(frame.dropped));
    CHECK(frame.dropped > 0.0f);
    CHECK(clock.accumulated() >= 0.0f);
    CHECK(clock.accumulated() < clock.step());
    CHECK(frame.alpha >= 0.0f);
    CHECK(frame.alpha < 1.0f);
    const auto next = clock.advance(1.0f / 60);  // and the clock still works
    CHECK(next.steps <= 1);
    CHECK(std::isfinite(next.alpha));
  }
}
