// SPDX-License-Identifier: BSL-1.0
// Code ported from Cyclone keeps its trajectories: Particle<R,
// damping::AccelerateThenDamp, position::Euler> against the engine's particle as the
// specification describes it (tests/support/reference_engine.*, its integrate compiled in its
// own translation unit), bit for bit at every step, float and double: damping from none to
// heavy, masses, forces, gravity, steps that change length, an immovable particle.
#include <doctest/doctest.h>

#include <cstring>

#include <pointmass/particle.hpp>

#include "reference_engine.hpp"

namespace {

using namespace pointmass;

template <class R>
bool same_bits(const Vector3<R>& ours, const reference_engine::Vector3<R>& theirs) {
  const R values[3] = {theirs.x, theirs.y, theirs.z};
  const R mine[3] = {ours.x, ours.y, ours.z};
  return std::memcmp(values, mine, sizeof values) == 0;
}

}  // namespace

TEST_CASE_TEMPLATE("the listing's policy replays Cyclone's particles bit for bit", R, float,
                   double) {
  using Ported = Particle<R, damping::AccelerateThenDamp, position::Euler>;
  constexpr int count = 6;
  const R dampings[count] = {R(1), R(0.99), R(0.995), R(0.5), R(0.05), R(0.999)};
  const R masses[count] = {R(1), R(2.5), R(0.1), R(70), R(1e-3), R(3)};
  Ported ours[count];
  reference_engine::Particle<R> theirs[count];
  for (int i = 0; i < count; ++i) {
    const R k = static_cast<R>(i);
    ours[i].set_position({k, R(2) * k, R(-1)});
    theirs[i].set_position({k, R(2) * k, R(-1)});
    ours[i].set_velocity({R(10) - k, R(35) + k, R(0.5) * k});
    theirs[i].set_velocity({R(10) - k, R(35) + k, R(0.5) * k});
    ours[i].set_acceleration({R(0), R(-9.81f) - k, R(0.25)});
    theirs[i].set_acceleration({R(0), R(-9.81f) - k, R(0.25)});
    ours[i].set_damping(dampings[i]);
    theirs[i].set_damping(dampings[i]);
    ours[i].set_mass(masses[i]);
    theirs[i].set_mass(masses[i]);
  }
  // The last one immovable: neither moves it.
  ours[count - 1].set_inverse_mass(R(0));
  theirs[count - 1].set_inverse_mass(R(0));
  const R steps[] = {R(1) / R(60), R(1) / R(60), R(0.033), R(1) / R(30), R(0.0171), R(1) / R(60)};
  int differing = 0;
  for (int n = 0; n < 600; ++n) {
    const R t = steps[n % 6];
    for (int i = 0; i < count; ++i) {
      if (n % 3 == 0) {  // a force now and then, as a game's generators add them
        const Vector3<R> f{R(0.5) * static_cast<R>(i), R(3), R(-1)};
        ours[i].add_force(f);
        theirs[i].add_force({f.x, f.y, f.z});
      }
      ours[i].integrate(t);
      theirs[i].integrate(t);
      if (!same_bits(ours[i].position(), theirs[i].position()) ||
          !same_bits(ours[i].velocity(), theirs[i].velocity())) {
        ++differing;
      }
    }
  }
  CHECK(differing == 0);
  // And they did move (an engine that never stepped would agree with one that never stepped).
  CHECK(ours[1].position().y != R(2));
  CHECK(same_bits(ours[count - 1].position(), theirs[count - 1].position()));
  CHECK(ours[count - 1].position() == Vector3<R>{R(5), R(10), R(-1)});
}
