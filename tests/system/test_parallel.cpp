// SPDX-License-Identifier: BSL-1.0
// pointmass::step(std::execution::par_unseq, system, t) computes what system.step(t) does,
// bit for bit, over many chunks, and under FlushDenormals as well; like it, it keeps the
// damping factors for its step length.
#include <pointmass/denormals.hpp>
#include <pointmass/forces.hpp>
#include <pointmass/parallel.hpp>

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <execution>
#include <limits>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include "counting_damping.hpp"
#include "system_support.hpp"

using namespace pointmass;
using pointmass::test::random_vector;
using pointmass::test::same_bits;

TEST_CASE_TEMPLATE("a parallel step equals the serial step", S, float, double,
                   Precision<float, double>, Precision<float, Compensated<float>>) {
  using System =
      ParticleSystem<S, damping::PerSecond, position::ConstantAcceleration, features::Lifetime>;
  using R = typename System::real;
  using Value = typename System::position_value;
  constexpr std::size_t count = 100'003;  // 7 chunks, the last partial
  std::mt19937 engine(5);
  System serial(count);
  serial.set_damping(R(0.7));
  serial.set_acceleration({R(0), R(-9.807), R(0)});
  for (std::size_t i = 0; i < count; ++i) {
    // Far from the origin, where positions stored wider keep what float rounds away.
    const Vector3<R> p = random_vector(engine, R(50));
    serial.spawn({Value(1e6) + Value(p.x), Value(p.y), Value(p.z)}, random_vector(engine, R(20)));
    serial.set_lifetime(i, R(0.01) * static_cast<R>(i % 50 + 1));
  }
  System parallel = serial;
  // Every other step with an expiry callback: it takes every system step takes.
  std::size_t serial_expired = 0;
  std::size_t parallel_expired = 0;
  for (int step = 0; step < 8; ++step) {
    if (step % 2 == 0) {
      serial.step(R(1) / R(30));
      pointmass::step(std::execution::par_unseq, parallel, R(1) / R(30));
    } else {
      serial.step(R(1) / R(30), [&](std::size_t) { ++serial_expired; });
      pointmass::step(std::execution::par_unseq, parallel, R(1) / R(30),
                      [&](std::size_t) { ++parallel_expired; });
    }
  }
  REQUIRE(serial.size() == parallel.size());
  CHECK(serial.size() < count);  // lifetimes expired some
  CHECK(serial_expired > 0);
  CHECK(parallel_expired == serial_expired);
  bool same = true;
  for (std::size_t i = 0; i < serial.size(); ++i) {
    same = same && same_bits(serial.position(i), parallel.position(i)) &&
           same_bits(serial.velocity(i), parallel.velocity(i));
  }
  CHECK(same);
  CHECK(parallel.position(0).y != Value(0));
}

TEST_CASE_TEMPLATE("a parallel VelocityVerlet step under forces equals the serial step", S, float,
                   double, Precision<float, double>, Precision<float, Compensated<float>>) {
  using System = ParticleSystem<S, damping::PerSecond, position::VelocityVerlet,
                                features::ForceAccumulator, features::Lifetime>;
  using R = typename System::real;
  using Value = typename System::position_value;
  constexpr std::size_t count = 70'001;  // 5 chunks, the last partial
  std::mt19937 engine(9);
  System serial(count);
  serial.set_damping(R(0.5));
  for (std::size_t i = 0; i < count; ++i) {
    const Vector3<R> p = random_vector(engine, R(5));
    serial.spawn({Value(1e5) + Value(p.x), Value(p.y), Value(p.z)}, random_vector(engine, R(2)));
    serial.set_mass(i, R(1) + R(i % 7));
    serial.set_lifetime(i, R(0.05) * static_cast<R>(i % 20 + 1));
  }
  System parallel = serial;
  // A spring to each particle's start (through the accumulator), then steps of two lengths:
  // the kicks credited at one length are settled at the next.
  for (int step = 0; step < 8; ++step) {
    for (System* system : {&serial, &parallel}) {
      for (std::size_t i = 0; i < system->size(); ++i) {
        const Vector3<Value> p = system->position(i);
        system->add_force(i, {R(-40) * R(p.x - Value(1e5)), R(-40) * R(p.y), R(-40) * R(p.z)});
      }
    }
    const R t = step % 3 == 0 ? R(1) / R(30) : R(1) / R(60);
    serial.step(t);
    pointmass::step(std::execution::par_unseq, parallel, t);
  }
  REQUIRE(serial.size() == parallel.size());
  CHECK(serial.size() < count);
  bool same = true;
  for (std::size_t i = 0; i < serial.size(); ++i) {
    same = same && same_bits(serial.position(i), parallel.position(i)) &&
           same_bits(serial.velocity(i), parallel.velocity(i));
  }
  CHECK(same);
  const auto kicks = [](const System& system) {
    std::vector<R> all;
    for (const auto column :
         {system.template column<Column::kick_x>(), system.template column<Column::kick_y>(),
          system.template column<Column::kick_z>(),
          system.template column<Column::kick_half_step>()}) {
      all.insert(all.end(), column.begin(), column.end());
    }
    return all;
  };
  CHECK(kicks(serial) == kicks(parallel));  // the credited kicks and their half steps too
}

TEST_CASE("a parallel step with an expiry callback reports what the serial one does") {
  struct Id {};
  using System = ParticleSystem<double, damping::None, position::Euler, features::Lifetime,
                                features::Column<Id, int>>;
  System serial(40'000);
  for (int i = 0; i < 40'000; ++i) {
    const std::size_t index = serial.spawn({double(i), 0, 0}, {0, 1, 0}, i);
    serial.set_lifetime(index, 0.01 * (i % 7 + 1));
  }
  System parallel = serial;
  std::vector<int> serial_seen, parallel_seen;
  for (int step = 0; step < 4; ++step) {
    serial.step(0.02, [&](std::size_t i) { serial_seen.push_back(serial.column<Id>(i)); });
    pointmass::step(std::execution::par_unseq, parallel, 0.02,
                    [&](std::size_t i) { parallel_seen.push_back(parallel.column<Id>(i)); });
  }
  CHECK(serial_seen.size() > 30'000);
  CHECK(serial_seen == parallel_seen);  // the same particles, in the same order
  CHECK(serial.size() == parallel.size());
}

TEST_CASE("a parallel step keeps each particle's d^t for its step length, as the serial one") {
  // Per-particle PerSecond damping keeps d^t for the last step length (the damping_retention
  // column); a step of the same length then computes no exponential. The parallel step must
  // leave the column known to hold d^t for its length, as system.step does, and agree with
  // the serial step bit for bit over steps of one length and of another.
  using System =
      ParticleSystem<float, damping::PerSecond, position::Euler, features::PerParticleDamping>;
  static_assert(System::stores<Column::damping_retention>);
  std::mt19937 engine(11);
  System serial(40'000);
  for (std::size_t i = 0; i < 40'000; ++i) {
    serial.spawn(random_vector(engine, 50.0f), random_vector(engine, 20.0f));
    serial.set_damping(i, 0.5f + 0.5f * static_cast<float>(i % 97) / 97.0f);
  }
  System parallel = serial;
  const float lengths[] = {1.0f / 60.0f, 1.0f / 60.0f, 1.0f / 30.0f, 1.0f / 30.0f};
  for (const float t : lengths) {
    serial.step(t);
    pointmass::step(std::execution::par_unseq, parallel, t);
    CHECK_FALSE(serial.begin_step(t).parameters().refresh);
    CHECK_FALSE(parallel.begin_step(t).parameters().refresh);  // d^t kept for t: no refresh
    CHECK(parallel.begin_step(t / 2).parameters().refresh);    // another length: computed again
  }
  bool same = true;
  for (std::size_t i = 0; i < serial.size(); ++i) {
    same = same && same_bits(serial.position(i), parallel.position(i)) &&
           same_bits(serial.velocity(i), parallel.velocity(i));
  }
  CHECK(same);
}

TEST_CASE_TEMPLATE(
    "a parallel step keeps the uniform damping factors for its step length, as "
    "the serial one",
    R, float, double) {
  // step keeps the factors of its last length (ParticleSystem::begin_step reads them);
  // the parallel step must keep them too, forget them with set_damping, and step as the
  // serial step does with them, bit for bit.
  using System = ParticleSystem<R, pointmass::test::CountingPerSecond>;
  std::mt19937 engine(13);
  System serial(40'000);
  for (std::size_t i = 0; i < 40'000; ++i) {
    serial.spawn(random_vector(engine, R(50)), random_vector(engine, R(20)));
  }
  serial.set_damping(R(0.5));
  System parallel = serial;
  auto& calls = pointmass::test::CountingPerSecond::factor_calls;
  calls = 0;
  for (int step = 0; step < 3; ++step) {
    pointmass::step(std::execution::par_unseq, parallel, R(0.1));
  }
  CHECK(calls == 1);  // a fixed step: computed once, then kept
  pointmass::step(std::execution::par_unseq, parallel, R(0.2));
  CHECK(calls == 2);  // a new length
  static_cast<void>(parallel.begin_step(R(0.2)));
  CHECK(calls == 2);  // what the parallel step kept, begin_step reads
  parallel.set_damping(R(0.9));
  pointmass::step(std::execution::par_unseq, parallel, R(0.2));
  CHECK(calls == 3);  // a new damping, the same length
  serial.step(R(0.1));
  serial.step(R(0.1));
  serial.step(R(0.1));
  serial.step(R(0.2));
  serial.set_damping(R(0.9));
  serial.step(R(0.2));
  bool same = true;
  for (std::size_t i = 0; i < serial.size(); ++i) {
    same = same && same_bits(serial.position(i), parallel.position(i)) &&
           same_bits(serial.velocity(i), parallel.velocity(i));
  }
  CHECK(same);
}

// Skipped (and reported so) where there are no modes to set, or one hardware thread: there
// "every thread" is the calling one, and the test would pass without a worker.
TEST_CASE("a parallel step under FlushDenormals flushes on every thread, as the serial step" *
          doctest::skip(!FlushDenormals::supported || std::thread::hardware_concurrency() < 2)) {
  // pointmass::step runs every chunk under the calling thread's modes, so a guard around the
  // call covers the workers too. TBB's workers keep the modes they had when its pool first
  // ran: the pool runs here once without the guard first, so that its workers do not flush
  // by themselves and the step has to give them the caller's modes.
  if (!FlushDenormals::supported) return;    // (only run with --no-skip)
  constexpr std::size_t count = 16384 * 16;  // 16 chunks, for both threads to take some
  const float tiny = std::numeric_limits<float>::min() / 64.0f;
  ParticleSystem<float> serial(count);
  serial.set_damping(0.9f);
  for (std::size_t i = 0; i < count; ++i) serial.spawn({1.0f, 2.0f, 3.0f}, {tiny, 1.0f, -tiny});
  ParticleSystem<float> parallel = serial;
  std::vector<float> warm_up(count, 1.0f);
  std::for_each(std::execution::par_unseq, warm_up.begin(), warm_up.end(),
                [](float& x) { x *= 2.0f; });
  REQUIRE_FALSE(FlushDenormals::active());
  {
    FlushDenormals flush;
    // The precondition: a parallel algorithm runs on two threads or more here, so that a
    // worker's modes are at stake. Each item does some tens of microseconds of work (so that
    // a worker wakes and takes some before the calling thread has done them all, also while
    // other tests load the machine) and notes its thread: one write per item, no
    // synchronisation, as par_unseq requires. A few tries. (Inside the guard.)
    struct Item {
      std::thread::id thread;
      float work = 1.0f;
    };
    std::vector<Item> items(4096);
    std::vector<std::thread::id> ran_on(items.size());
    std::size_t threads = 0;
    for (int attempt = 0; attempt < 20 && threads < 2; ++attempt) {
      std::for_each(std::execution::par_unseq, items.begin(), items.end(), [](Item& item) {
        for (int k = 0; k < 20000; ++k) item.work = item.work * 0.999999f + 1e-7f;
        item.thread = std::this_thread::get_id();
      });
      for (std::size_t i = 0; i < items.size(); ++i) ran_on[i] = items[i].thread;
      std::sort(ran_on.begin(), ran_on.end());
      threads =
          static_cast<std::size_t>(std::unique(ran_on.begin(), ran_on.end()) - ran_on.begin());
    }
    CAPTURE(std::thread::hardware_concurrency());
    REQUIRE(threads >= 2);
    serial.step(1.0f / 60.0f);
    pointmass::step(std::execution::par_unseq, parallel, 1.0f / 60.0f);
  }
  std::size_t subnormal = 0;
  std::size_t different = 0;
  for (std::size_t i = 0; i < count; ++i) {
    subnormal += std::fpclassify(parallel.template column<pointmass::Column::velocity_x>()[i]) ==
                 FP_SUBNORMAL;
    different += !same_bits(parallel.velocity(i), serial.velocity(i));
  }
  CHECK(subnormal == 0);
  CHECK(different == 0);
  CHECK(serial.velocity(0).x == 0.0f);
}

TEST_CASE_TEMPLATE("a parallel step with force laws equals the serial step with them", R, float,
                   double) {
  using System = ParticleSystem<R, damping::PerSecond, position::Euler, features::ForceAccumulator,
                                features::Interpolation>;
  constexpr std::size_t count = 50'003;  // 4 chunks, the last partial
  std::mt19937 engine(12);
  System serial(count);
  for (std::size_t i = 0; i < count; ++i) {
    serial.spawn(random_vector(engine, R(6)), random_vector(engine, R(3)));
    serial.set_mass(i, R(1) + R(i % 5));
  }
  System parallel = serial;
  const auto laws =
      forces::laws(forces::Drag<R>(R(0.2), R(0.05)),
                   forces::AnchoredSpring<R>(Vector3<R>{R(0), R(4), R(0)}, R(6), R(2)));
  for (int step = 0; step < 6; ++step) {
    serial.add_force(7, Vector3<R>{R(3), R(0), R(0)});  // composed with the laws
    parallel.add_force(7, Vector3<R>{R(3), R(0), R(0)});
    serial.step(R(1) / R(60), laws);
    pointmass::step(std::execution::par_unseq, parallel, R(1) / R(60), laws);
  }
  bool same = true;
  for (std::size_t i = 0; i < count; ++i) {
    same = same && same_bits(serial.position(i), parallel.position(i)) &&
           same_bits(serial.velocity(i), parallel.velocity(i)) &&
           same_bits(serial.previous_position(i), parallel.previous_position(i));
  }
  CHECK(same);
  CHECK(!same_bits(serial.position(7), serial.previous_position(7)));
}

TEST_CASE_TEMPLATE("parallel sub-steps with force laws equal the serial sub-steps", R, float,
                   double) {
  using System =
      ParticleSystem<R, damping::PerSecond, position::VelocityVerlet, features::ForceAccumulator,
                     features::Interpolation, features::Lifetime>;
  constexpr std::size_t count = 40'001;  // 3 chunks, the last partial
  std::mt19937 engine(13);
  System serial(count);
  for (std::size_t i = 0; i < count; ++i) {
    // Lifetimes from 0.01 s: some particles expire within a frame's sub-steps.
    serial.spawn(random_vector(engine, R(6)), random_vector(engine, R(3)));
    serial.set_lifetime(i, R(0.01) + R(i % 97) / R(100));
    serial.set_mass(i, R(1) + R(i % 5));
  }
  System parallel = serial;
  const auto laws =
      forces::laws(forces::Drag<R>(R(0.2), R(0.05)),
                   forces::AnchoredSpring<R>(Vector3<R>{R(0), R(4), R(0)}, R(60), R(2)));
  std::vector<std::size_t> expired_serial;
  std::vector<std::size_t> expired_parallel;
  for (int frame = 0; frame < 4; ++frame) {
    serial.step(R(1) / R(60), laws, Substeps{4},
                [&](std::size_t i) { expired_serial.push_back(i); });
    pointmass::step(std::execution::par_unseq, parallel, R(1) / R(60), laws, Substeps{4});
  }
  REQUIRE(!expired_serial.empty());
  REQUIRE(serial.size() == parallel.size());
  bool same = true;
  for (std::size_t i = 0; i < serial.size(); ++i) {
    same = same && same_bits(serial.position(i), parallel.position(i)) &&
           same_bits(serial.velocity(i), parallel.velocity(i)) &&
           same_bits(serial.previous_position(i), parallel.previous_position(i)) &&
           same_bits(serial.age(i), parallel.age(i));
  }
  CHECK(same);
}

namespace {
std::vector<std::string> parallel_reports;  // NOLINT: the handler below is a plain function
void record_parallel(const ContractViolation& violation) {
  parallel_reports.push_back(describe(violation));
}
}  // namespace

TEST_CASE("parallel sub-steps: none, or a bad duration, is reported by name and changes nothing") {
  using System = ParticleSystem<float, damping::PerSecond, position::Euler,
                                features::ForceAccumulator, features::Interpolation>;
  std::mt19937 engine(14);
  System system(20'000);
  for (std::size_t i = 0; i < 20'000; ++i) {
    system.spawn(random_vector(engine, 6.0f), random_vector(engine, 3.0f));
  }
  const System before = system;
  const auto laws = forces::laws(forces::Drag<float>(0.2f, 0.05f));
  parallel_reports.clear();
  const ContractHandler previous = set_contract_handler(&record_parallel);
  pointmass::step(std::execution::par_unseq, system, 1.0f / 60, laws, Substeps{0});
  REQUIRE(parallel_reports.size() == 1);
  CHECK(parallel_reports[0].find("argument 'substeps' = 0") != std::string::npos);
#if POINTMASS_CHECKS  // a duration is checked only with the checks on, as system.step's
  pointmass::step(std::execution::par_unseq, system, -1.0f / 60, laws, Substeps{4});
  REQUIRE(parallel_reports.size() == 2);
  // The duration as given, not a sub-step's (-1/240).
  CHECK(parallel_reports[1].find("argument 'duration' = -0.0166") != std::string::npos);
#endif
  set_contract_handler(previous);
  bool same = true;
  for (std::size_t i = 0; i < system.size(); ++i) {
    same = same && same_bits(system.position(i), before.position(i)) &&
           same_bits(system.velocity(i), before.velocity(i)) &&
           same_bits(system.previous_position(i), before.previous_position(i));
  }
  CHECK(same);
}
