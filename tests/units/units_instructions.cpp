// SPDX-License-Identifier: BSL-1.0
// units_instructions — the work whose instruction count scripts/units-cost.sh compares: the
// same scene stepped by the plain and the SI particle (1024 particles launched with the four
// shots, a push and a step each frame for 150 frames of 1/30 s, as benchmarks/units_cost).
// Counted by valgrind, instructions are exact and repeatable, unlike times on a busy machine.
//
//   units_instructions plain|si|setup VARIANT     VARIANT: 0..3 (see `variants` below)
// "setup" launches the particles and steps nothing: its count is subtracted from the others.
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

#include <pointmass/extras/scenes.hpp>
#include <pointmass/particle.hpp>
#include <pointmass/units.hpp>

#include "units_scene.hpp"

namespace pm = pointmass;
namespace si = boost::units::si;

namespace {

template <class Particle>
double run(bool step, const auto& frame, const auto& push) {
  std::vector<Particle> particles(pm::test::units_scene_particles);
  pm::test::launch_units_scene(particles);
  if (step) pm::test::fly_units_scene(particles, frame, push);
  double sum = 0;  // the result is printed, so no step can be dropped
  for (std::size_t i = 0; i < particles.size(); ++i) {
    if constexpr (requires { particles[i].position().x.value(); }) {
      sum += static_cast<double>(particles[i].position().z.value());
    } else {
      sum += static_cast<double>(particles[i].position().z);
    }
  }
  return sum;
}

template <class R, class D, class P>
double variant(const char* mode) {
  const R frame = R(1) / R(30);
  const pm::Vector3<R> push{R(0.5), R(-2), R(1)};
  if (std::strcmp(mode, "si") == 0) {
    return run<pm::units::Particle<R, D, P>>(true, frame * si::seconds, push * si::newtons);
  }
  return run<pm::Particle<R, D, P>>(std::strcmp(mode, "plain") == 0, frame, push);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3 || (std::strcmp(argv[1], "plain") != 0 && std::strcmp(argv[1], "si") != 0 &&
                    std::strcmp(argv[1], "setup") != 0)) {
    std::fprintf(stderr, "usage: %s plain|si|setup 0..3\n", argv[0]);
    return 2;
  }
  using namespace pm::damping;
  using namespace pm::position;
  double sum = 0;
  switch (std::atoi(argv[2])) {
    case 0: sum = variant<float, None, ConstantAcceleration>(argv[1]); break;
    case 1: sum = variant<float, PerSecond, Euler>(argv[1]); break;
    case 2: sum = variant<double, PerSecond, Euler>(argv[1]); break;
    case 3: sum = variant<double, pm::damping::Exact, pm::position::Exact>(argv[1]); break;
    default: return 2;
  }
  std::printf("%s %.6f\n", argv[1], sum);
  return 0;
}
