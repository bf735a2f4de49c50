// SPDX-License-Identifier: BSL-1.0
// variant_steps — what a step costs for every compile-time variant, in ns per particle-step, with
// hand-written loops of the same maths as baselines in the same run. scripts/sweep.sh runs
// it (interleaved repetitions, medians), pairs each variant's time with its error from the
// accuracy comparison and draws docs/images/pareto-*.svg.
//
// Benchmarks (names as reported; VARIANT is "float PerSecond + Euler" and so on, the names
// the accuracy comparison prints). The variants: float and double with every policy pair,
// and float arithmetic with wide positions (Precision<float, double>, "float/double-pos",
// and Precision<float, Compensated<float>>, "float/compensated-pos") with the pairs
// accuracy::for_each_wide_combination names (PerSecond + Euler, Exact + Exact):
//   Particle/ballistic/VARIANT   64 Particles (the four ballistic shots, 16 of each) fly the
//                                scene's 5 s at 1/60 s: each frame steps every particle once
//   Particle/spring/VARIANT      64 Particles (the undamped and the damped spring, 32 of
//                                each) fly 10 s at 1/60 s; each step adds the spring force
//   ParticleSystem/sparks/VARIANT  a ParticleSystem of 1,024 particles with uniform damping
//                                (0.99 per second) and gravity, 300 steps of 1/60 s
//   hand-written/ballistic/REAL, hand-written/spring/REAL, hand-written/sparks/REAL
//                                the same scenes over plain arrays with the maths of
//                                PerSecond + Euler written out (v = v d^t + a t, p = p + v0 t),
//                                d^t computed once before the loop
// Every iteration restarts the scene from its launch state (a copy of a few KiB, under 1% of
// the iteration), so the values stay those of the scene however long the run.
// Counters: items_per_second = particle-steps per second; per_step = seconds per
// particle-step; steps = particle-steps per iteration (cpu_time / steps = ns per step).
//
// The frame time is read once from a volatile global before each timed loop (set in main at
// run time), never through benchmark::DoNotOptimize, and main checks at start-up that a step
// of every benchmarked loop moves every particle and that the hand-written loops agree with
// the library: otherwise the timings would be of no work, and the program stops.

#include <pointmass/particle_system.hpp>

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <cstdlib>
#include <new>
#include <string>
#include <vector>

#include "accuracy.hpp"

namespace {

/// The counters every benchmark here reports, for `steps` particle-steps per iteration:
/// items processed, "steps", and "per_step" (seconds per particle-step).
void report_steps(benchmark::State& state, double steps) {
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(steps));
  state.counters["steps"] = steps;
  state.counters["per_step"] =
      benchmark::Counter(steps * static_cast<double>(state.iterations()),
                         benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

using namespace pointmass;
namespace accuracy = pointmass::accuracy;

/// 1/60 s, written in main from a run-time value, read once before each timed loop.
volatile double frame_time_source = 0.0;
constexpr double nominal_frame_time = 1.0 / 60;

template <Real R>
R frame_time() {
  return static_cast<R>(frame_time_source);
}

template <Real R>
const char* real_name() {
  return sizeof(R) == sizeof(float) ? "float" : "double";
}

/// The position a spring force is computed from, in the arithmetic's Real: the position itself
/// when it is stored as that Real, else the float offset from the spring's anchor (the
/// origin) that position_relative_to computes from the whole stored position.
template <class S, class D, class P>
Vector3<real_of_t<S>> spring_position(const Particle<S, D, P>& particle) {
  if constexpr (Particle<S, D, P>::plain_position) return particle.position();
  else return particle.position_relative_to({});
}

constexpr std::size_t copies_per_scene = 16;    // ballistic: 4 shots x 16 = 64 particles
constexpr std::size_t copies_per_spring = 32;   // spring: 2 scenes x 32 = 64 particles
constexpr std::size_t system_particles = 1024;  // sparks

// --- scalar Particles --------------------------------------------------------------------

/// The particles of a scene at launch, the per-particle friction (spring scenes) and the
/// number of frames of one flight at 1/60 s.
template <class S, class D, class P>
struct ScalarScene {
  using R = real_of_t<S>;
  std::vector<Particle<S, D, P>> launched;
  std::vector<R> friction;
  R stiffness = R(0);
  long frames = 0;
};

template <class S, class D, class P>
ScalarScene<S, D, P> scalar_scene(bool spring) {
  using R = real_of_t<S>;
  ScalarScene<S, D, P> scene;
  const auto scenes =
      spring ? std::vector<accuracy::Scene>{accuracy::spring(false, 10), accuracy::spring(true, 10)}
             : accuracy::ballistic_scenes();
  const std::size_t copies = spring ? copies_per_spring : copies_per_scene;
  for (std::size_t copy = 0; copy < copies; ++copy) {
    for (const auto& s : scenes) {
      scene.launched.push_back(accuracy::make_particle<S, D, P>(s, nominal_frame_time));
      scene.friction.push_back(static_cast<R>(s.friction));
      scene.stiffness = static_cast<R>(s.stiffness);
      scene.frames = accuracy::steps_for(s, nominal_frame_time);
    }
  }
  return scene;
}

/// One flight: every frame, each particle gets its spring force (if any) and one step.
template <bool Spring, class S, class D, class P>
void fly(std::vector<Particle<S, D, P>>& particles, const ScalarScene<S, D, P>& scene,
         real_of_t<S> t) {
  const real_of_t<S> minus_stiffness = -scene.stiffness;
  for (long frame = 0; frame < scene.frames; ++frame) {
    for (std::size_t i = 0; i < particles.size(); ++i) {
      auto& particle = particles[i];
      if constexpr (Spring) {
        particle.add_force(spring_position(particle) * minus_stiffness +
                           particle.velocity() * -scene.friction[i]);
      }
      particle.integrate(t);
    }
  }
}

template <class S, class D, class P, bool Spring>
void BM_Particle(benchmark::State& state) {
  using R = real_of_t<S>;
  const auto scene = scalar_scene<S, D, P>(Spring);
  auto particles = scene.launched;
  const R t = frame_time<R>();
  for (auto _ : state) {
    std::copy(scene.launched.begin(), scene.launched.end(), particles.begin());
    fly<Spring>(particles, scene, t);
    benchmark::DoNotOptimize(particles.data());
    benchmark::ClobberMemory();
  }
  report_steps(state, static_cast<double>(scene.frames) * static_cast<double>(particles.size()));
}

// --- ParticleSystem ----------------------------------------------------------------------

template <class S, class D, class P>
ParticleSystem<S, D, P> sparks() {
  using R = real_of_t<S>;
  ParticleSystem<S, D, P> system(system_particles);
  const auto& shots = scenes::ballistic_shots<R>;
  for (std::size_t i = 0; i < system_particles; ++i) {
    const auto& shot = shots[i % shots.size()];
    const R spread = R(1) + static_cast<R>(i) / R(system_particles);
    system.spawn(scenes::ballistic_origin<typename ParticleSystem<S, D, P>::position_value>,
                 shot.velocity * spread);
  }
  system.set_acceleration({R(0), R(-9.807), R(0)});
  if constexpr (ParticleSystem<S, D, P>::stores_damping) {
    const double d =
        std::is_same_v<D, damping::PerFrame> ? std::pow(0.99, nominal_frame_time) : 0.99;
    system.set_damping(static_cast<R>(d));
  }
  return system;
}

constexpr long system_frames = 300;

template <class S, class D, class P>
void restore(ParticleSystem<S, D, P>& system, const ParticleSystem<S, D, P>& launched) {
  std::ranges::copy(launched.template column<pointmass::Column::position_x>(),
                    system.template column<pointmass::Column::position_x>().begin());
  std::ranges::copy(launched.template column<pointmass::Column::position_y>(),
                    system.template column<pointmass::Column::position_y>().begin());
  std::ranges::copy(launched.template column<pointmass::Column::position_z>(),
                    system.template column<pointmass::Column::position_z>().begin());
  if constexpr (ParticleSystem<S, D, P>::template stores<Column::position_error_x>) {
    std::ranges::copy(launched.template column<Column::position_error_x>(),
                      system.template column<Column::position_error_x>().begin());
    std::ranges::copy(launched.template column<Column::position_error_y>(),
                      system.template column<Column::position_error_y>().begin());
    std::ranges::copy(launched.template column<Column::position_error_z>(),
                      system.template column<Column::position_error_z>().begin());
  }
  std::ranges::copy(launched.template column<pointmass::Column::velocity_x>(),
                    system.template column<pointmass::Column::velocity_x>().begin());
  std::ranges::copy(launched.template column<pointmass::Column::velocity_y>(),
                    system.template column<pointmass::Column::velocity_y>().begin());
  std::ranges::copy(launched.template column<pointmass::Column::velocity_z>(),
                    system.template column<pointmass::Column::velocity_z>().begin());
}

template <class S, class D, class P>
void BM_System(benchmark::State& state) {
  using R = real_of_t<S>;
  const auto launched = sparks<S, D, P>();
  auto system = launched;
  const R t = frame_time<R>();
  for (auto _ : state) {
    restore(system, launched);
    for (long frame = 0; frame < system_frames; ++frame) system.step(t);
    benchmark::DoNotOptimize(system.template column<pointmass::Column::position_x>().data());
    benchmark::ClobberMemory();
  }
  report_steps(state, static_cast<double>(system_frames * static_cast<long>(system_particles)));
}

// --- hand-written baselines --------------------------------------------------------------

/// Structure-of-arrays copies of a scene in one block, each array staggered within its page
/// (as ParticleSystem does). Index: 0-2 position, 3-5 velocity, 6-8 acceleration, 9 d^t,
/// 10 friction x inverse mass, 11 stiffness x inverse mass.
template <Real R>
struct HandArrays {
  static constexpr std::size_t count = 12;
  HandArrays(std::size_t n, long frames_) : size(n), frames(frames_) {
    const std::size_t span = (n * sizeof(R) + 4095) / 4096 * 4096 + 448;
    block = static_cast<R*>(::operator new (count* span, std::align_val_t{64}));
    for (std::size_t k = 0; k < count; ++k) {
      array[k] = reinterpret_cast<R*>(reinterpret_cast<char*>(block) + k * span);
      std::fill(array[k], array[k] + n, R(0));
    }
  }
  ~HandArrays() { ::operator delete (block, std::align_val_t{64}); }
  HandArrays(const HandArrays&) = delete;
  HandArrays& operator=(const HandArrays&) = delete;
  void copy_state_from(const HandArrays& other) {
    for (std::size_t k = 0; k < 6; ++k) std::copy(other.array[k], other.array[k] + size, array[k]);
  }
  void copy_all_from(const HandArrays& other) {
    for (std::size_t k = 0; k < count; ++k)
      std::copy(other.array[k], other.array[k] + size, array[k]);
  }
  R* block;
  R* array[count];
  std::size_t size;
  long frames;
};

std::size_t hand_size(bool spring) { return spring ? 2 * copies_per_spring : 4 * copies_per_scene; }
long hand_frames(bool spring) {
  return accuracy::steps_for(spring ? accuracy::spring(false, 10) : accuracy::ballistic_scenes()[0],
                             nominal_frame_time);
}

/// The scalar scenes' particles as arrays, with d^t for the frame time t.
template <Real R>
void fill_hand_arrays(HandArrays<R>& arrays, bool spring, R t) {
  const auto scene = scalar_scene<R, damping::PerSecond, position::Euler>(spring);
  for (std::size_t i = 0; i < arrays.size; ++i) {
    const auto& particle = scene.launched[i];
    const Vector3<R> values[3] = {particle.position(), particle.velocity(),
                                  particle.acceleration()};
    for (std::size_t k = 0; k < 3; ++k) {
      arrays.array[3 * k][i] = values[k].x;
      arrays.array[3 * k + 1][i] = values[k].y;
      arrays.array[3 * k + 2][i] = values[k].z;
    }
    arrays.array[9][i] = real_pow(particle.damping(), t);
    arrays.array[10][i] = scene.friction[i] * particle.inverse_mass();
    arrays.array[11][i] = scene.stiffness * particle.inverse_mass();
  }
}

/// One frame of PerSecond + Euler by hand: v1 = v0 d^t + (a + spring force / m) t,
/// p1 = p0 + v0 t. (Restrict-qualified parameters: the arrays do not overlap.)
template <bool Spring, Real R>
void hand_frame(R* __restrict px, R* __restrict py, R* __restrict pz, R* __restrict vx,
                R* __restrict vy, R* __restrict vz, const R* __restrict ax, const R* __restrict ay,
                const R* __restrict az, const R* __restrict kept, const R* __restrict friction,
                const R* __restrict stiffness, std::size_t n, R t) {
  for (std::size_t i = 0; i < n; ++i) {
    const R x = vx[i], y = vy[i], z = vz[i];
    R gx = ax[i], gy = ay[i], gz = az[i];
    if constexpr (Spring) {
      gx += -stiffness[i] * px[i] - friction[i] * x;
      gy += -stiffness[i] * py[i] - friction[i] * y;
      gz += -stiffness[i] * pz[i] - friction[i] * z;
    }
    vx[i] = x * kept[i] + gx * t;
    vy[i] = y * kept[i] + gy * t;
    vz[i] = z * kept[i] + gz * t;
    px[i] += x * t;
    py[i] += y * t;
    pz[i] += z * t;
  }
}

template <bool Spring, Real R>
void hand_fly(HandArrays<R>& arrays, R t) {
  R* const* a = arrays.array;
  for (long frame = 0; frame < arrays.frames; ++frame) {
    hand_frame<Spring>(a[0], a[1], a[2], a[3], a[4], a[5], a[6], a[7], a[8], a[9], a[10], a[11],
                       arrays.size, t);
  }
}

template <Real R, bool Spring>
void BM_Hand(benchmark::State& state) {
  const R t = frame_time<R>();
  HandArrays<R> launched(hand_size(Spring), hand_frames(Spring));
  fill_hand_arrays(launched, Spring, t);
  HandArrays<R> arrays(launched.size, launched.frames);
  arrays.copy_all_from(launched);
  for (auto _ : state) {
    arrays.copy_state_from(launched);
    hand_fly<Spring>(arrays, t);
    benchmark::DoNotOptimize(arrays.block);
    benchmark::ClobberMemory();
  }
  report_steps(state, static_cast<double>(arrays.frames) * static_cast<double>(arrays.size));
}

/// One step of the sparks (uniform damping and gravity, PerSecond + Euler) by hand.
template <Real R>
void hand_sparks_step(R* __restrict px, R* __restrict py, R* __restrict pz, R* __restrict vx,
                      R* __restrict vy, R* __restrict vz, std::size_t n, R t, R kept,
                      Vector3<R> g) {
  for (std::size_t i = 0; i < n; ++i) {
    const R x = vx[i], y = vy[i], z = vz[i];
    vx[i] = x * kept + g.x * t;
    vy[i] = y * kept + g.y * t;
    vz[i] = z * kept + g.z * t;
    px[i] += x * t;
    py[i] += y * t;
    pz[i] += z * t;
  }
}

/// The sparks' flight by hand: d^t once per step, as ParticleSystem computes it.
template <Real R>
void hand_sparks(HandArrays<R>& arrays, R t, R damping, Vector3<R> g) {
  R* const* a = arrays.array;
  for (long frame = 0; frame < arrays.frames; ++frame) {
    hand_sparks_step(a[0], a[1], a[2], a[3], a[4], a[5], arrays.size, t, real_pow(damping, t), g);
  }
}

template <Real R>
void fill_sparks_arrays(HandArrays<R>& arrays) {
  const auto system = sparks<R, damping::PerSecond, position::Euler>();
  for (std::size_t i = 0; i < arrays.size; ++i) {
    const Vector3<R> p = system.position(i), v = system.velocity(i);
    arrays.array[0][i] = p.x, arrays.array[1][i] = p.y, arrays.array[2][i] = p.z;
    arrays.array[3][i] = v.x, arrays.array[4][i] = v.y, arrays.array[5][i] = v.z;
  }
}

template <Real R>
void BM_HandSparks(benchmark::State& state) {
  const R t = frame_time<R>();
  HandArrays<R> launched(system_particles, system_frames);
  fill_sparks_arrays(launched);
  HandArrays<R> arrays(system_particles, system_frames);
  const auto system = sparks<R, damping::PerSecond, position::Euler>();
  const R damping = system.damping();
  const Vector3<R> g = system.acceleration();
  for (auto _ : state) {
    arrays.copy_state_from(launched);
    hand_sparks(arrays, t, damping, g);
    benchmark::DoNotOptimize(arrays.block);
    benchmark::ClobberMemory();
  }
  report_steps(state, static_cast<double>(system_frames * static_cast<long>(system_particles)));
}

// --- start-up checks ---------------------------------------------------------------------

bool failed = false;

void fail(const std::string& what) {
  std::fprintf(stderr, "variant_steps: %s; the timings would be void\n", what.c_str());
  failed = true;
}

/// Every particle of every benchmarked loop moves in one flight.
template <class S, class D, class P>
void check_variant() {
  using R = real_of_t<S>;
  const std::string name = accuracy::variant_name<S, D, P>();
  const R t = frame_time<R>();
  if (!(t > R(0))) fail(std::string("the ") + real_name<R>() + " frame time is not positive");
  for (const bool spring : {false, true}) {
    const auto scene = scalar_scene<S, D, P>(spring);
    auto particles = scene.launched;
    if (spring) fly<true>(particles, scene, t);
    else fly<false>(particles, scene, t);
    for (std::size_t i = 0; i < particles.size(); ++i) {
      if (particles[i].position() == scene.launched[i].position()) {
        fail("Particle " + name + " did not move in a flight");
        break;
      }
    }
  }
  const auto launched = sparks<S, D, P>();
  auto system = launched;
  system.step(t);
  for (std::size_t i = 0; i < system.size(); ++i) {
    if (system.position(i) == launched.position(i)) {
      fail("ParticleSystem " + name + " did not move in a step");
      break;
    }
  }
}

/// The hand-written loops compute what PerSecond + Euler computes (to a few hundred ulps
/// of the largest coordinate: d^t is rounded once instead of every step).
template <Real R>
void check_hand() {
  const R t = frame_time<R>();
  const R tolerance = R(1000) * std::numeric_limits<R>::epsilon();
  for (const bool spring : {false, true}) {
    const auto scene = scalar_scene<R, damping::PerSecond, position::Euler>(spring);
    auto particles = scene.launched;
    if (spring) fly<true>(particles, scene, t);
    else fly<false>(particles, scene, t);
    HandArrays<R> arrays(hand_size(spring), hand_frames(spring));
    fill_hand_arrays(arrays, spring, t);
    if (spring) hand_fly<true>(arrays, t);
    else hand_fly<false>(arrays, t);
    for (std::size_t i = 0; i < particles.size(); ++i) {
      const Vector3<R> p = particles[i].position();
      const Vector3<R> hand{arrays.array[0][i], arrays.array[1][i], arrays.array[2][i]};
      const R scale = std::max({R(1), std::abs(p.x), std::abs(p.y), std::abs(p.z)});
      if (!(magnitude(p - hand) <= tolerance * scale) || hand == scene.launched[i].position()) {
        fail(std::string("the hand-written ") + (spring ? "spring" : "ballistic") + " loop (" +
             real_name<R>() + ") disagrees with Particle PerSecond + Euler");
        break;
      }
    }
  }
  auto system = sparks<R, damping::PerSecond, position::Euler>();
  HandArrays<R> arrays(system_particles, 1);
  fill_sparks_arrays(arrays);
  hand_sparks(arrays, t, system.damping(), system.acceleration());
  system.step(t);
  for (std::size_t i = 0; i < system.size(); ++i) {
    const Vector3<R> hand{arrays.array[0][i], arrays.array[1][i], arrays.array[2][i]};
    if (!(magnitude(system.position(i) - hand) <= tolerance * R(100))) {
      fail(std::string("the hand-written sparks loop (") + real_name<R>() +
           ") disagrees with ParticleSystem");
      break;
    }
  }
}

// --- registration ------------------------------------------------------------------------

/// Checks and registers the three benchmarks of variant (S, D, P).
template <class S>
struct RegisterVariant {
  template <class D, class P>
  void operator()() const {
    check_variant<S, D, P>();
    const std::string name = accuracy::variant_name<S, D, P>();
    benchmark::RegisterBenchmark(("Particle/ballistic/" + name).c_str(),
                                 BM_Particle<S, D, P, false>);
    benchmark::RegisterBenchmark(("Particle/spring/" + name).c_str(), BM_Particle<S, D, P, true>);
    benchmark::RegisterBenchmark(("ParticleSystem/sparks/" + name).c_str(), BM_System<S, D, P>);
  }
};

/// Every policy pair of R, and R's hand-written baselines.
template <Real R>
void register_variants() {
  accuracy::for_each_combination(RegisterVariant<R>{});
  check_hand<R>();
  const std::string real = real_name<R>();
  benchmark::RegisterBenchmark(("hand-written/ballistic/" + real).c_str(), BM_Hand<R, false>);
  benchmark::RegisterBenchmark(("hand-written/spring/" + real).c_str(), BM_Hand<R, true>);
  benchmark::RegisterBenchmark(("hand-written/sparks/" + real).c_str(), BM_HandSparks<R>);
}

}  // namespace

int main(int argc, char** argv) {
  // 1/60 s from a run-time value (the argument count is at least 1), so no timed loop can
  // treat the frame time as a constant.
  frame_time_source = nominal_frame_time * (argc > 0 ? 1.0 : 2.0);
  register_variants<float>();
  register_variants<double>();
  accuracy::for_each_wide_combination(RegisterVariant<accuracy::FloatWithDoublePositions>{});
  accuracy::for_each_wide_combination(RegisterVariant<accuracy::FloatWithCompensatedPositions>{});
  if (failed) return 1;
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
