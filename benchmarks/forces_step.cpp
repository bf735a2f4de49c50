// SPDX-License-Identifier: BSL-1.0
// Cyclone's force-driven job, side by side: every particle under gravity, damped 0.99 per
// second, with its own drag (k1 |v| + k2 |v|^2) and its own spring to one anchor, stepped at
// 1/60 s, against
//   * the engine's particles and its force registry (tests/support/reference_engine.*: a
//     virtual update_force per (particle, generator) pair, 2N pairs, then integrate) — the
//     baseline every ratio is taken against;
//   * a vector of Particle<R> under pointmass's ForceRegistry (the same 2N registrations);
//   * the same particles, each given both forces by forces::update_force, then stepped;
//   * a ParticleSystem with ForceAccumulator: forces::apply for each generator, then step;
//   * the same system stepped with both laws fused into the step, step(t, forces::laws(...));
//   * a hand-written loop computing both forces and the step in one pass;
//   * the roofs: the registry's walk with generators that add nothing (its memory roof), and
//     the compute roofs of the fused step and of the per-particle forces (support/law_roofs.hpp).
// scripts/benchmark-forces.sh runs it and writes docs/results/forces.md.
// Counters: items_per_second = particle-steps/s.
#include <pointmass/forces.hpp>
#include <pointmass/particle.hpp>
#include <pointmass/particle_system.hpp>

#include <benchmark/benchmark.h>

#include <cmath>
#include <cstddef>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "reference_engine.hpp"
#include "support/bench_support.hpp"
#include "support/law_roofs.hpp"

namespace {

using namespace pointmass;
using pointmass_benchmarks::duration;

template <class R>
constexpr R k1 = R(0.1);
template <class R>
constexpr R k2 = R(0.01);
template <class R>
constexpr R stiffness = R(4);
template <class R>
constexpr R rest = R(2);
template <class R>
constexpr R kept_per_second = R(0.99);
template <class R>
constexpr R g = R(9.81);

// Particle k's start: spread over a few metres around the anchor at the origin, moving.
template <class R>
Vector3<R> start_position(std::size_t k) {
  const R f = static_cast<R>(k % 1000) / R(1000);
  return {R(3) * f - R(1.5), R(2) - f, f};
}
template <class R>
Vector3<R> start_velocity(std::size_t k) {
  const R f = static_cast<R>(k % 997) / R(997);
  return {R(1) - f, R(2) * f, f - R(0.5)};
}
template <class R>
R mass_of(std::size_t k) {
  return R(1) + static_cast<R>(k % 5) / R(4);
}

// The job's two laws, as pointmass's generators.
template <class R>
struct Laws {
  forces::Drag<R> drag{k1<R>, k2<R>};
  forces::AnchoredSpring<R> spring{{R(0), R(0), R(0)}, stiffness<R>, rest<R>};
};

// Runs `frame` once an iteration; items_per_second = particle-steps/s.
template <class Frame>
void time_frames(benchmark::State& state, Frame&& frame) {
  for (auto _ : state) {
    frame();
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations() * state.range(0));
}

template <class R>
void BM_Cyclone(benchmark::State& state) {
  const auto n = static_cast<std::size_t>(state.range(0));
  std::vector<reference_engine::Particle<R>> particles(n);
  reference_engine::Vector3<R> anchor(R(0), R(0), R(0));
  std::vector<reference_engine::ParticleDrag<R>> drags(n, {k1<R>, k2<R>});
  std::vector<reference_engine::ParticleAnchoredSpring<R>> springs(
      n, {&anchor, stiffness<R>, rest<R>});
  reference_engine::ParticleForceRegistry<R> registry;
  for (std::size_t k = 0; k < n; ++k) {
    const Vector3<R> p = start_position<R>(k);
    const Vector3<R> v = start_velocity<R>(k);
    particles[k].set_position({p.x, p.y, p.z});
    particles[k].set_velocity({v.x, v.y, v.z});
    particles[k].set_acceleration({R(0), -g<R>, R(0)});
    particles[k].set_damping(kept_per_second<R>);
    particles[k].set_mass(mass_of<R>(k));
    registry.add(&particles[k], &drags[k]);
    registry.add(&particles[k], &springs[k]);
  }
  time_frames(state, [&] {
    registry.update_forces(duration<R>());
    for (auto& particle : particles) particle.integrate(duration<R>());
  });
}

template <class R>
using Body = Particle<R>;  // the defaults: PerSecond, p + v t (the engine's arithmetic)

template <class R>
std::vector<Body<R>> bodies(std::size_t n) {
  std::vector<Body<R>> particles(n);
  for (std::size_t k = 0; k < n; ++k) {
    particles[k].set_position(start_position<R>(k));
    particles[k].set_velocity(start_velocity<R>(k));
    particles[k].set_acceleration({R(0), -g<R>, R(0)});
    particles[k].set_damping(kept_per_second<R>);
    particles[k].set_mass(mass_of<R>(k));
  }
  return particles;
}

template <class R>
void BM_Registry(benchmark::State& state) {
  const auto n = static_cast<std::size_t>(state.range(0));
  auto particles = bodies<R>(n);
  Laws<R> laws;
  forces::ForceRegistry<Body<R>, forces::Drag<R>, forces::AnchoredSpring<R>> registry;
  for (auto& particle : particles) {
    registry.add(particle, laws.drag);
    registry.add(particle, laws.spring);
  }
  time_frames(state, [&] {
    registry.update_forces(duration<R>());
    for (auto& particle : particles) particle.integrate(duration<R>());
  });
}

// The registry's memory roof: the same 2N registrations and step, but field generators whose
// force is zero (the particle read, its accumulator read and written, no arithmetic of the
// laws): the walk's own cost and the traffic of its passes over the particles.
template <class R>
struct Touch {
  [[nodiscard]] Vector3<R> force(const Vector3<R>&, const Vector3<R>&, R, R) const { return {}; }
};
template <class R>
struct TouchToo : Touch<R> {};

template <class R>
void BM_RegistryRoof(benchmark::State& state) {
  const auto n = static_cast<std::size_t>(state.range(0));
  auto particles = bodies<R>(n);
  Touch<R> first;
  TouchToo<R> second;
  forces::ForceRegistry<Body<R>, Touch<R>, TouchToo<R>> registry;
  for (auto& particle : particles) {
    registry.add(particle, first);
    registry.add(particle, second);
  }
  time_frames(state, [&] {
    registry.update_forces(duration<R>());
    for (auto& particle : particles) particle.integrate(duration<R>());
  });
}

// The step alone (no force): what every row pays for integrate.
template <class R>
void BM_StepOnly(benchmark::State& state) {
  const auto n = static_cast<std::size_t>(state.range(0));
  auto particles = bodies<R>(n);
  time_frames(state, [&] {
    for (auto& particle : particles) particle.integrate(duration<R>());
  });
}

template <class R>
void BM_UpdateForce(benchmark::State& state) {
  const auto n = static_cast<std::size_t>(state.range(0));
  auto particles = bodies<R>(n);
  Laws<R> laws;
  time_frames(state, [&] {
    for (auto& particle : particles) {
      forces::update_force(laws.drag, particle, duration<R>());
      forces::update_force(laws.spring, particle, duration<R>());
      particle.integrate(duration<R>());
    }
  });
}

template <class R>
using ForceSystem = ParticleSystem<R, damping::PerSecond, position::Euler,
                                   features::PerParticleDamping, features::ForceAccumulator>;

// The job's n particles in a ForceSystem.
template <class R>
ForceSystem<R> force_system(std::size_t n) {
  ForceSystem<R> system(n);
  system.set_acceleration({R(0), -g<R>, R(0)});
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t i = system.spawn(start_position<R>(k), start_velocity<R>(k));
    system.set_damping(i, kept_per_second<R>);
    system.set_mass(i, mass_of<R>(k));
  }
  return system;
}

template <class R>
void BM_SystemApply(benchmark::State& state) {
  ForceSystem<R> system = force_system<R>(static_cast<std::size_t>(state.range(0)));
  const Laws<R> laws;
  time_frames(state, [&] {
    forces::apply(laws.drag, system, duration<R>());
    forces::apply(laws.spring, system, duration<R>());
    system.step(duration<R>());
  });
}

template <class R>
void BM_SystemLaws(benchmark::State& state) {
  ForceSystem<R> system = force_system<R>(static_cast<std::size_t>(state.range(0)));
  const Laws<R> laws;
  const auto fused = forces::laws(laws.drag, laws.spring);
  time_frames(state, [&] { system.step(duration<R>(), fused); });
}

// Both forces and the step in one pass over a plain struct, d^t kept per particle (as a
// hand-tuned game loop would), the square roots as the library's generators take them.
template <class R>
struct HandBody {
  Vector3<R> position, velocity;
  R inverse_mass, retention;
};

template <class R>
void BM_HandFused(benchmark::State& state) {
  const auto n = static_cast<std::size_t>(state.range(0));
  std::vector<HandBody<R>> particles(n);
  for (std::size_t k = 0; k < n; ++k) {
    particles[k] = {start_position<R>(k), start_velocity<R>(k), R(1) / mass_of<R>(k),
                    std::pow(kept_per_second<R>, duration<R>())};
  }
  time_frames(state, [&] {
    const R t = duration<R>();
    for (auto& b : particles) {
      const Vector3<R> v = b.velocity;
      const R speed = std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z);
      const R drag = speed > R(0) ? -(k1<R> + k2<R> * speed) : R(0);  // (k1 s + k2 s^2) / s
      const Vector3<R> d = b.position;
      const R length = std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
      const R pull = length > R(0) ? stiffness<R> * (rest<R> - length) / length : R(0);
      const Vector3<R> force = v * drag + d * pull;
      const Vector3<R> a = Vector3<R>{R(0), -g<R>, R(0)} + force * b.inverse_mass;
      b.position = b.position + v * t;
      b.velocity = v * b.retention + a * t;
    }
  });
}

// The compute roofs (support/law_roofs.hpp) of the job: the fused laws and step, vectorised,
// for step(t, laws); each force() and integrate, per particle, for the registry.
template <class R>
pointmass_benchmarks::RoofStart<R> roof_start(std::size_t k) {
  return {start_position<R>(k), start_velocity<R>(k), mass_of<R>(k)};
}
template <class R>
void BM_FusedRoof(benchmark::State& state) {
  const Laws<R> laws;
  pointmass_benchmarks::fused_compute_roof(state, laws.drag, laws.spring, {R(0), -g<R>, R(0)},
                                           kept_per_second<R>, duration<R>(), roof_start<R>);
}
template <class R>
void BM_ScalarRoof(benchmark::State& state) {
  const Laws<R> laws;
  pointmass_benchmarks::scalar_compute_roof(state, laws.drag, laws.spring, {R(0), -g<R>, R(0)},
                                            kept_per_second<R>, duration<R>(), roof_start<R>);
}

void sizes(benchmark::internal::Benchmark* b) {
  b->Arg(1024);
  if (std::getenv("POINTMASS_BENCHMARK_SMOKE") == nullptr) b->Arg(100000)->Arg(1000000);
}

#define POINTMASS_FORCES_BENCHMARKS(R)         \
  BENCHMARK(BM_Cyclone<R>)->Apply(sizes);      \
  BENCHMARK(BM_Registry<R>)->Apply(sizes);     \
  BENCHMARK(BM_RegistryRoof<R>)->Apply(sizes); \
  BENCHMARK(BM_StepOnly<R>)->Apply(sizes);     \
  BENCHMARK(BM_UpdateForce<R>)->Apply(sizes);  \
  BENCHMARK(BM_SystemApply<R>)->Apply(sizes);  \
  BENCHMARK(BM_SystemLaws<R>)->Apply(sizes);   \
  BENCHMARK(BM_HandFused<R>)->Apply(sizes);    \
  BENCHMARK(BM_FusedRoof<R>)->Apply(sizes);    \
  BENCHMARK(BM_ScalarRoof<R>)->Apply(sizes)

POINTMASS_FORCES_BENCHMARKS(float);
POINTMASS_FORCES_BENCHMARKS(double);

}  // namespace

int main(int argc, char** argv) {
  pointmass_benchmarks::set_duration(argc);
  return pointmass_benchmarks::run_benchmarks(argc, argv);
}
