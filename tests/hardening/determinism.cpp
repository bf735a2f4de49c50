// SPDX-License-Identifier: BSL-1.0
// Determinism: steps a damped spring scene with every damping and position policy pair,
// float and double, through scalar Particles and through a ParticleSystem side by side, and
//   * exits 1 unless the two agree bit for bit at every step (the batch promise);
//   * prints one digest (FNV-1a over the bits of every position and velocity at every step)
//     per configuration and one over all of them, so that two runs, or two builds, can be
//     compared (determinism.cmake does: run after run, and across compilers and flags).
// Usage: pointmass_determinism [steps]   (default 300)
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <type_traits>
#include <vector>

#include <pointmass/particle.hpp>
#include <pointmass/particle_system.hpp>

namespace {

using namespace pointmass;

struct Digest {
  std::uint64_t value = 14695981039346656037ull;
  template <class T>
  void add(const T& x) {
    unsigned char bytes[sizeof(T)];
    std::memcpy(bytes, &x, sizeof(T));
    for (unsigned char b : bytes) value = (value ^ b) * 1099511628211ull;
  }
  template <class R>
  void add(const Vector3<R>& v) {
    add(v.x), add(v.y), add(v.z);
  }
};

template <class R>
bool identical(const Vector3<R>& a, const Vector3<R>& b) {
  return std::memcmp(&a, &b, sizeof a) == 0;
}

template <class R>
Vector3<R> spring_force(const Vector3<R>& p, const Vector3<R>& v) {
  // A damped spring to the origin: f = -k p - c v (k = 4 N/m, c = 0.3 N s/m).
  return p * R(-4) - v * R(0.3);
}

bool all_agree = true;

template <class R, class D, class P>
std::uint64_t run(const char* name, int steps, Digest& overall) {
  constexpr int count = 21;  // a vector block of 16 and a remainder
  const R durations[] = {R(1) / R(60), R(1) / R(30), R(0.1), R(0.005), R(1) / R(120)};
  const Vector3<R> gravity{R(0), R(-9.807), R(0)};
  std::vector<Particle<R, D, P>> bodies(count);
  // Per-particle damping where the policy has a damping value (None has none).
  using System = std::conditional_t<
      std::is_empty_v<typename D::template State<R>>,
      ParticleSystem<R, D, P, features::ForceAccumulator>,
      ParticleSystem<R, D, P, features::PerParticleDamping, features::ForceAccumulator>>;
  System system(count);
  system.set_acceleration(gravity);
  for (int i = 0; i < count; ++i) {
    auto& body = bodies[static_cast<std::size_t>(i)];
    const R k = static_cast<R>(i);
    body.set_position({R(0.5) * k, R(10) - k / R(3), R(1) / (k + R(1))});
    body.set_velocity({R(3) - k / R(7), R(4.5), -k / R(11)});
    body.set_acceleration(gravity);
    body.set_mass(R(0.5) + k / R(4));
    if constexpr (System::stores_damping) body.set_damping(R(0.5) + k / R(50));
    system.spawn(body);
  }
  Digest digest;
  for (int step = 0; step < steps; ++step) {
    const R t = durations[step % 5];
    for (std::size_t i = 0; i < bodies.size(); ++i) {
      bodies[i].add_force(spring_force(bodies[i].position(), bodies[i].velocity()));
      system.add_force(i, spring_force(system.position(i), system.velocity(i)));
      bodies[i].integrate(t);
    }
    system.step(t);
    for (std::size_t i = 0; i < bodies.size(); ++i) {
      if (!identical(bodies[i].position(), system.position(i)) ||
          !identical(bodies[i].velocity(), system.velocity(i))) {
        if (all_agree) {
          std::printf("MISMATCH %s: particle %zu differs at step %d\n", name, i, step);
        }
        all_agree = false;
      }
      digest.add(bodies[i].position());
      digest.add(bodies[i].velocity());
    }
  }
  std::printf("%-40s %016llx\n", name, static_cast<unsigned long long>(digest.value));
  overall.add(digest.value);
  return digest.value;
}

template <class R>
void run_all(const char* precision, int steps, Digest& overall) {
  char name[64];
#define POINTMASS_RUN(D, P)                                        \
  std::snprintf(name, sizeof name, "%s %s %s", precision, #D, #P); \
  run<R, damping::D, position::P>(name, steps, overall)
  POINTMASS_RUN(None, Euler);
  POINTMASS_RUN(None, ConstantAcceleration);
  POINTMASS_RUN(None, SemiImplicit);
  POINTMASS_RUN(None, Exact);
  POINTMASS_RUN(PerFrame, Euler);
  POINTMASS_RUN(PerFrame, ConstantAcceleration);
  POINTMASS_RUN(PerFrame, SemiImplicit);
  POINTMASS_RUN(PerSecond, Euler);
  POINTMASS_RUN(PerSecond, ConstantAcceleration);
  POINTMASS_RUN(PerSecond, SemiImplicit);
  POINTMASS_RUN(AccelerateThenDamp, Euler);
  POINTMASS_RUN(AccelerateThenDamp, ConstantAcceleration);
  POINTMASS_RUN(AccelerateThenDamp, SemiImplicit);
  POINTMASS_RUN(Exact, Euler);
  POINTMASS_RUN(Exact, ConstantAcceleration);
  POINTMASS_RUN(Exact, SemiImplicit);
  POINTMASS_RUN(Exact, Exact);
#undef POINTMASS_RUN
}

}  // namespace

int main(int argc, char** argv) {
  const int steps = argc > 1 ? std::atoi(argv[1]) : 300;
  Digest overall;
  run_all<float>("float", steps, overall);
  run_all<double>("double", steps, overall);
  std::printf("all %016llx\n", static_cast<unsigned long long>(overall.value));
  std::printf("scalar and batch %s\n", all_agree ? "agree bit for bit" : "DIFFER");
  return all_agree ? 0 : 1;
}
