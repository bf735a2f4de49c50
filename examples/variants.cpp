// SPDX-License-Identifier: BSL-1.0
// variants — how to configure the library at compile time, and what each choice costs.
//
// Every Particle variant (precision x damping x position) with its size and what it stores,
// then the batch ParticleSystem's storage per particle for each feature set, then a rough
// time per step of each Particle variant on this machine (the benchmarks measure it
// properly; here it only shows the order of the costs: no power function < per-frame <
// per-second, exact).
//
//   variants [--quick]   (--quick: a shorter timing run)
#include <pointmass/extras/scenes.hpp>
#include <pointmass/particle_system.hpp>
#include <pointmass/pointmass.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

namespace {

using namespace pointmass;

int rounds = 200;  // timing: steps per particle per repetition

template <class D>
const char* stores() {
  if constexpr (std::is_same_v<D, damping::None>) return "p v a f 1/m";
  else if constexpr (std::is_same_v<D, damping::Exact>) return "p v a f 1/m d ln(d)";
  else return "p v a f 1/m d";
}

template <class Body>
double ns_per_step() {
  std::vector<Body> bodies(256);
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    scenes::launch(bodies[i], scenes::ballistic_shots<double>[i % 4]);
  }
  using R = typename Body::real;
  const R dt = R(1) / R(60);
  std::vector<double> samples;
  for (int repetition = 0; repetition < 5; ++repetition) {
    const auto start = std::chrono::steady_clock::now();
    for (int round = 0; round < rounds; ++round) {
      for (auto& body : bodies) body.integrate(dt);
    }
    const auto stop = std::chrono::steady_clock::now();
    samples.push_back(std::chrono::duration<double, std::nano>(stop - start).count() /
                      (rounds * static_cast<double>(bodies.size())));
  }
  if (!is_finite(bodies[0].position())) std::puts("non-finite position");
  std::sort(samples.begin(), samples.end());
  return samples[2];
}

template <class R, class D, class P>
void particle_row(const char* real, const char* damping, const char* position) {
  using Body = Particle<R, D, P>;
  std::printf("Particle<%-6s damping::%-18s position::%-12s> %4zu bytes  %-20s %7.2f ns/step\n",
              (std::string(real) + ",").c_str(), (std::string(damping) + ",").c_str(), position,
              sizeof(Body), stores<D>(), ns_per_step<Body>());
}

template <class R>
void particle_rows(const char* real) {
  particle_row<R, damping::None, position::Euler>(real, "None", "Euler");
  particle_row<R, damping::None, position::ConstantAcceleration>(real, "None",
                                                                 "ConstantAcceleration");
  particle_row<R, damping::PerFrame, position::Euler>(real, "PerFrame", "Euler");
  particle_row<R, damping::PerSecond, position::Euler>(real, "PerSecond", "Euler");
  particle_row<R, damping::PerSecond, position::SemiImplicit>(real, "PerSecond", "SemiImplicit");
  particle_row<R, damping::AccelerateThenDamp, position::Euler>(real, "AccelerateThenDamp",
                                                                "Euler");
  particle_row<R, damping::Exact, position::Exact>(real, "Exact", "Exact");
}

template <class System>
void system_row(const char* features) {
  std::printf("ParticleSystem<float, PerSecond, Euler%-44s> %3zu bytes per particle, %2zu arrays\n",
              features, System::storage_bytes_per_particle,
              pointmass::detail::SystemAccess::Layout<System>::array_count);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc == 2 && std::strcmp(argv[1], "--quick") == 0) {
    rounds = 5;
  } else if (argc != 1) {
    std::fprintf(stderr, "usage: %s [--quick]\n", argv[0]);
    return 2;
  }
  std::printf("Particle variants: size, what one particle stores, time per step\n");
  std::printf(
      "(p position, v velocity, a acceleration, f force accumulator, 1/m inverse mass,"
      " d damping)\n\n");
  particle_rows<float>("float");
  particle_rows<double>("double");

  std::printf(
      "\nParticleSystem: what a feature set stores per particle (uniform damping and\n"
      "gravity are stored once for the whole system)\n\n");
  using namespace features;
  using D = damping::PerSecond;
  using P = position::Euler;
  system_row<ParticleSystem<float, D, P>>("");
  system_row<ParticleSystem<float, D, P, Lifetime>>(", Lifetime");
  system_row<ParticleSystem<float, D, P, ForceAccumulator>>(", ForceAccumulator");
  system_row<ParticleSystem<float, D, P, PerParticleAcceleration>>(", PerParticleAcceleration");
  system_row<ParticleSystem<float, D, P, PerParticleDamping>>(", PerParticleDamping");
  system_row<ParticleSystem<float, D, P, PerParticleDamping, PerParticleAcceleration,
                            ForceAccumulator, Lifetime>>(", all four");
  return 0;
}
