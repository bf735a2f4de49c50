// SPDX-License-Identifier: BSL-1.0
// position::Exact needs the exact damping factors: with damping::PerSecond it does not fit.
// The error is one sentence naming the pairs that work.
// expected-error: position::Exact works only with damping::Exact or damping::None; with damping::PerSecond, PerFrame or AccelerateThenDamp choose position::Euler, ConstantAcceleration or SemiImplicit
#include <pointmass/particle.hpp>

int main() {
  pointmass::Particle<double, pointmass::damping::PerSecond, pointmass::position::Exact> particle;
  particle.integrate(0.1);
}
