// SPDX-License-Identifier: BSL-1.0
// ParticleSystem's contracts and size arithmetic: impossible capacities are refused without
// changing anything, indices and ranges are checked (this executable is built with
// POINTMASS_ENABLE_CHECKS), a copy is steppable through arrays(), infinite lifetimes never
// expire, a zero step leaves a system and a Particle in the same state, and the force
// generators refuse a bad duration.
#include <doctest/doctest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>

#include <pointmass/pointmass.hpp>

using namespace pointmass;

namespace {

using Sparks = ParticleSystem<float>;
using Forced =
    ParticleSystem<float, damping::PerSecond, position::Euler, features::ForceAccumulator>;
using Aging = ParticleSystem<float, damping::None, position::Euler, features::Lifetime>;

template <class System>
System three_particles() {
  System system;
  for (int i = 0; i < 3; ++i) {
    system.spawn({float(i), 0, 0}, {0, float(i), 0});
  }
  return system;
}

template <class System>
bool same_particles(const System& a, const System& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (!(a.position(i) == b.position(i)) || !(a.velocity(i) == b.velocity(i))) return false;
  }
  return true;
}

// The message of the std::invalid_argument that f throws ("" if none).
template <class F>
std::string invalid_argument_of(F f) {
  try {
    f();
  } catch (const std::invalid_argument& error) {
    return error.what();
  }
  return "";
}

}  // namespace

TEST_CASE("reserve refuses a capacity whose size arithmetic would overflow, and changes nothing") {
  Sparks system = three_particles<Sparks>();
  const std::size_t capacity = system.capacity();
  const Sparks before = system;
  for (std::size_t huge :
       {std::numeric_limits<std::size_t>::max(), std::numeric_limits<std::size_t>::max() / 2,
        std::numeric_limits<std::size_t>::max() / 24 + 1, Sparks::max_size() + 1}) {
    CAPTURE(huge);
    CHECK_THROWS_AS(system.reserve(huge), std::length_error);
    CHECK(system.capacity() == capacity);
    CHECK(same_particles(system, before));
  }
  // The refusal names the function, the argument and its value.
  try {
    system.reserve(std::numeric_limits<std::size_t>::max());
  } catch (const std::length_error& error) {
    const std::string message = error.what();
    CHECK(message.find("reserve") != std::string::npos);
    CHECK(message.find("capacity") != std::string::npos);
    CHECK(message.find(std::to_string(std::numeric_limits<std::size_t>::max())) !=
          std::string::npos);
  }
  // Spawning afterwards still writes inside the block (AddressSanitizer would report it).
  for (int i = 0; i < 100; ++i) system.spawn({1, 2, 3}, {4, 5, 6});
  CHECK(system.size() == 103);
  CHECK(system.position(0) == before.position(0));
  CHECK(system.position(2) == before.position(2));
  // max_size() times the bytes of the stored arrays fits in a ptrdiff_t.
  CHECK(Sparks::max_size() <= std::size_t(PTRDIFF_MAX) / Sparks::storage_bytes_per_particle);
}

namespace {
struct WideTag {};
// a + b and a * b, or SIZE_MAX where the exact result would not fit.
std::size_t saturated_add(std::size_t a, std::size_t b) {
  return b > std::numeric_limits<std::size_t>::max() - a ? std::numeric_limits<std::size_t>::max()
                                                         : a + b;
}
std::size_t saturated_multiply(std::size_t a, std::size_t b) {
  return b != 0 && a > std::numeric_limits<std::size_t>::max() / b
             ? std::numeric_limits<std::size_t>::max()
             : a * b;
}

// A system and the layout of its arrays.
template <class S, class D, class... Features>
struct Sized {
  using System = ParticleSystem<S, D, position::Euler, Features...>;
  using Layout = detail::SystemLayout<S, D, Features...>;
};
}  // namespace

TEST_CASE_TEMPLATE(
    "at max_size() the block's bytes, every array rounded up to its pages and "
    "staggered, still fit in a ptrdiff_t",
    Case, Sized<float, damping::PerSecond>, Sized<double, damping::PerSecond>,
    Sized<Precision<float, Compensated<float>>, damping::PerSecond>,
    Sized<float, damping::PerSecond, features::Column<WideTag, std::array<double, 4>>>) {
  // The sum the block's allocation makes (detail/soa_block.hpp), at the largest capacity
  // reserve accepts, for every array, the user's columns and their element sizes included.
  using System = typename Case::System;
  using Layout = typename Case::Layout;
  using Block = detail::SoaBlock<Layout>;
  static_assert(std::is_same_v<typename System::Arrays, typename Layout::Arrays>);
  const std::size_t capacity = System::max_size();
  typename Layout::Arrays arrays{};
  std::size_t total = 0;
  std::size_t arrays_seen = 0;
  Layout::for_each_array(arrays, [&](auto* array) {
    const std::size_t bytes = saturated_multiply(capacity, sizeof(*array));
    const std::size_t pages = saturated_add(bytes, Block::page - 1) / Block::page * Block::page;
    total = saturated_add(total, saturated_add(pages, Block::stagger));
    ++arrays_seen;
  });
  CAPTURE(capacity);
  CAPTURE(total);
  CHECK(arrays_seen == pointmass::detail::SystemAccess::Layout<System>::array_count);
  CHECK(total <= std::size_t(PTRDIFF_MAX));
}

TEST_CASE("a copy's step view has the copy's size, so a step_particle loop over it steps all") {
  const Sparks original = three_particles<Sparks>();
  Sparks copy = original;
  auto view = copy.begin_step(0.5f);
  REQUIRE(view.size() == 3);
  REQUIRE(view.arrays().size == 3);
  for (std::size_t i = 0; i < view.size(); ++i) view.step_particle(i);
  copy.finish_step(std::move(view));
  Sparks stepped = original;
  stepped.step(0.5f);
  CHECK(same_particles(copy, stepped));
  Sparks empty_copy = Sparks{};
  CHECK(empty_copy.begin_step(0.5f).size() == 0);
}

TEST_CASE("finish_step refuses a view of another system, finished, or over changed particles") {
  Aging a = three_particles<Aging>();
  a.set_lifetime(1, 0.01f);
  Aging b = a;
  const Aging b_before = b;
  auto view = a.begin_step(0.02f);
  for (std::size_t i = 0; i < view.size(); ++i) view.step_particle(i);
  CHECK(invalid_argument_of([&] {
          view.step_particle(3);
        }).find("StepView::step_particle: argument 'index' = 3 must be < size()") !=
        std::string::npos);
  CHECK(invalid_argument_of([&] { b.finish_step(std::move(view)); })
            .find("finish_step: argument 'view' = 3 must be from this system's begin_step, not "
                  "finished yet") != std::string::npos);
  CHECK(same_particles(b, b_before));                                 // nothing expired there
  CHECK(invalid_argument_of([&] { a.finish_step(std::move(view)); })  // moved from: finished
            .find("must be from this system's begin_step") != std::string::npos);
  CHECK(a.size() == 3);  // the particle whose lifetime is over is still there
  auto stale = a.begin_step(0.02f);
  a.spawn({}, {});
  CHECK(invalid_argument_of([&] {
          a.finish_step(std::move(stale));
        }).find("finish_step: argument 'view' = 3 must be over the particles begin_step saw") !=
        std::string::npos);
  CHECK(a.size() == 4);
  auto fresh = a.begin_step(0.02f);
  a.finish_step(std::move(fresh));
  CHECK(a.size() == 3);  // now it expires
}

TEST_CASE("index reads and writes beyond size() are reported, naming the function and the index") {
  Forced system = three_particles<Forced>();
  const Forced before = system;
  // "FUNCTION: argument 'index' = 3 must be < size()": each names itself, not another.
  const auto reported = [](const char* function, auto f) {
    const std::string message = invalid_argument_of(f);
    const bool named = message.find(std::string(function) +
                                    ": argument 'index' = 3 must be < size()") != std::string::npos;
    if (!named) MESSAGE("expected a report from ", std::string(function), ", got: ", message);
    return named;
  };
  CHECK(reported("position", [&] { (void)system.position(3); }));
  CHECK(reported("velocity", [&] { (void)system.velocity(3); }));
  CHECK(reported("acceleration", [&] { (void)system.acceleration(3); }));
  CHECK(reported("damping", [&] { (void)system.damping(3); }));
  CHECK(reported("inverse_mass", [&] { (void)system.inverse_mass(3); }));
  CHECK(reported("add_force", [&] { system.add_force(3, {1, 1, 1}); }));
  CHECK(reported("kill", [&] { system.kill(3); }));
  CHECK(reported("set_position", [&] { system.set_position(3, {1, 1, 1}); }));
  CHECK(reported("set_velocity", [&] { system.set_velocity(3, {1, 1, 1}); }));
  CHECK(reported("set_mass", [&] { system.set_mass(3, 2.0f); }));
  CHECK(reported("set_inverse_mass", [&] { system.set_inverse_mass(3, 0.5f); }));
  CHECK(same_particles(system, before));
  CHECK(system.force_accumulator(2) == Vector3<float>{});
  CHECK(system.inverse_mass(2) == before.inverse_mass(2));
  // Each particle's own acceleration and damping.
  using Own = ParticleSystem<float, damping::PerSecond, position::Euler,
                             features::PerParticleAcceleration, features::PerParticleDamping>;
  Own own = three_particles<Own>();
  CHECK(reported("set_acceleration", [&] { own.set_acceleration(3, {1, 1, 1}); }));
  CHECK(reported("set_damping", [&] { own.set_damping(3, 0.5f); }));
  CHECK(same_particles(own, three_particles<Own>()));
  // The features' own.
  using Game = ParticleSystem<float, damping::None, position::Euler, features::Lifetime,
                              features::Interpolation>;
  Game game = three_particles<Game>();
  game.set_lifetime(2, 5.0f);
  CHECK(reported("set_lifetime", [&] { game.set_lifetime(3, 1.0f); }));
  CHECK(reported("lifetime", [&] { (void)game.lifetime(3); }));
  CHECK(reported("age", [&] { (void)game.age(3); }));
  CHECK(reported("previous_position", [&] { (void)game.previous_position(3); }));
  CHECK(reported("interpolated_position", [&] { (void)game.interpolated_position(3, 0.5f); }));
  CHECK(game.lifetime(2) == 5.0f);
}

TEST_CASE("step_range and step_range_backward check their range against arrays().size") {
  Sparks system = three_particles<Sparks>();
  const Sparks before = system;
  const auto view = system.begin_step(0.1f);
  const auto& parameters = view.parameters();
  CHECK(invalid_argument_of([&] {
          view.step_range(0, 4);
        }).find("argument 'end' = 4 must be <= size()") != std::string::npos);
  CHECK(invalid_argument_of([&] {
          view.step_range(2, 1);
        }).find("argument 'begin' = 2 must be <= end") != std::string::npos);
  CHECK(invalid_argument_of([&] {
          pointmass::detail::SystemAccess::Kernel<Sparks>::step_range_backward(
              pointmass::detail::SystemAccess::arrays(system), 2, 1, parameters);
        }).find("argument 'begin' = 2 must be <= end") != std::string::npos);
  CHECK(invalid_argument_of([&] {
          pointmass::detail::SystemAccess::Kernel<Sparks>::step_range_backward(
              pointmass::detail::SystemAccess::arrays(system), 0, 17, parameters);
        }).find("argument 'end' = 17 must be <= size()") != std::string::npos);
  CHECK(same_particles(system, before));
  // A valid empty range is fine and changes nothing.
  view.step_range(1, 1);
  CHECK(same_particles(system, before));
}

TEST_CASE("an infinite lifetime never expires, even when the age overflows") {
  Aging system;
  system.spawn({}, {});
  system.spawn({}, {});
  system.set_lifetime(1, std::numeric_limits<float>::max());
  for (int step = 0; step < 4; ++step) system.step(std::numeric_limits<float>::max());
  REQUIRE(system.size() == 1);  // the finite one expired, the infinite one did not
  CHECK(system.lifetime(0) == std::numeric_limits<float>::infinity());
  CHECK(system.age(0) == std::numeric_limits<float>::infinity());
}

TEST_CASE("a zero step leaves an immovable particle's force in a Particle as in a system") {
  Particle<float> particle;
  particle.set_inverse_mass(0.0f);
  particle.add_force({1, 2, 3});
  Forced system;
  system.spawn(particle);
  particle.integrate(0.0f);
  system.step(0.0f);
  CHECK(particle.force_accumulator() == Vector3<float>{1, 2, 3});
  CHECK(system.force_accumulator(0) == particle.force_accumulator());
  particle.integrate(0.5f);
  system.step(0.5f);
  CHECK(particle.force_accumulator() == Vector3<float>{});
  CHECK(system.force_accumulator(0) == particle.force_accumulator());
  CHECK(system.position(0) == particle.position());
}

TEST_CASE_TEMPLATE("a finite mass is accepted only when mass() stays finite", R, float, double) {
  Particle<R> particle;
  const R huge = std::numeric_limits<R>::max();
  const std::string message = invalid_argument_of([&] { particle.set_mass(huge); });
  CHECK(message.find("argument 'mass'") != std::string::npos);
  CHECK(particle.mass() == R(1));  // unchanged
  // The largest accepted mass has a finite mass() whenever has_finite_mass() says so.
  const R largest = R(1) / std::numeric_limits<R>::min();
  particle.set_mass(largest);
  CHECK(particle.has_finite_mass());
  CHECK(real_isfinite(particle.mass()));
  // An inverse mass so small that its mass would overflow is refused too; 0 is immovable.
  CHECK(invalid_argument_of([&] {
          particle.set_inverse_mass(std::numeric_limits<R>::denorm_min());
        }).find("argument 'inverse_mass'") != std::string::npos);
  particle.set_inverse_mass(R(0));
  CHECK_FALSE(particle.has_finite_mass());
  ParticleSystem<R, damping::PerSecond, position::Euler, features::ForceAccumulator> system;
  system.spawn({}, {});
  CHECK(invalid_argument_of([&] { system.set_mass(0, huge); }).find("argument 'mass'") !=
        std::string::npos);
  CHECK(system.inverse_mass(0) == R(1));
}

TEST_CASE("a removal pass refuses steps and removals from its callback, and outlives a reset") {
  using Game =
      ParticleSystem<float, damping::None, position::Euler, features::Lifetime, features::Handles>;
  // An expiry callback that steps: refused by step and finish_step, naming the argument; only
  // the expiring particle goes, and the others are where a plain step leaves them.
  Game system = three_particles<Game>();
  system.set_lifetime(1, 0.01f);
  Game plain = system;
  plain.step(0.02f);
  std::string step_message, begin_message, finish_message;
  auto begun = system.begin_step(0.02f);  // finished, wrongly, inside the callback below
  system.step(0.02f, [&](std::size_t) {
    step_message = invalid_argument_of([&] { system.step(0.25f); });
    begin_message = invalid_argument_of([&] { static_cast<void>(system.begin_step(0.25f)); });
    finish_message = invalid_argument_of([&] { system.finish_step(std::move(begun)); });
  });
  CHECK(begin_message.find("begin_step: argument 'duration' = 0.25 must be stepped after the "
                           "expiry callback returns") != std::string::npos);
  CHECK(step_message.find("step: argument 'duration' = 0.25 must be stepped after the "
                          "expiry callback returns") != std::string::npos);
  CHECK(finish_message.find("finish_step: argument 'particles' = 3 must be stepped after the "
                            "expiry callback returns") != std::string::npos);
  CHECK(same_particles(system, plain));

  // kill_if's predicate: removing or stepping is refused; it removes what it returns true for
  // and nothing else, and every handle still finds its own particle.
  Game culled = three_particles<Game>();
  const Game::Handle first = culled.handle(0);
  const Game::Handle last = culled.handle(2);
  std::string kill_message, clear_message, step_in_predicate;
  const std::size_t removed = culled.kill_if([&](std::size_t i) {
    if (i == 0) {
      kill_message = invalid_argument_of([&] { culled.kill(2); });
      clear_message = invalid_argument_of([&] { culled.clear(); });
      step_in_predicate = invalid_argument_of([&] { culled.step(0.5f); });
    }
    return culled.position(i).x == 1.0f;
  });
  CHECK(kill_message.find("kill: argument 'index' = 2 must be removed after kill_if's "
                          "predicate returns") != std::string::npos);
  CHECK(clear_message.find("clear") != std::string::npos);
  CHECK(step_in_predicate.find("step: argument 'duration' = 0.5 must be stepped after "
                               "kill_if's predicate returns") != std::string::npos);
  CHECK(removed == 1);
  REQUIRE(culled.size() == 2);
  REQUIRE(culled.find(first).has_value());
  REQUIRE(culled.find(last).has_value());
  CHECK(culled.position(*culled.find(first)).x == 0.0f);
  CHECK(culled.position(*culled.find(last)).x == 2.0f);
  CHECK(culled.position(*culled.find(last)).y == 0.0f);  // not stepped (its velocity is 2 m/s)

  // A callback or predicate that replaces the particles whole (assignment: not a removal the
  // pass can refuse) ends the pass: the system stays as assigned, even when what it was given
  // would have been removed (here: particles whose lifetime is over, and a predicate that
  // says yes to everything).
  Game expired_already;
  for (int i = 0; i < 4; ++i) expired_already.spawn({float(i), 0, 0}, {});
  expired_already.step(0.02f);  // ages 0.02, lifetimes infinite
  for (std::size_t i = 0; i < 4; ++i) expired_already.set_lifetime(i, 0.01f);  // over
  Game reset = three_particles<Game>();
  reset.set_lifetime(2, 0.01f);
  std::size_t callbacks = 0;
  reset.step(0.02f, [&](std::size_t) {
    if (callbacks++ == 0) reset = expired_already;
  });
  CHECK(callbacks == 1);
  CHECK(reset.size() == 4);
  Game emptied = three_particles<Game>();
  bool assigned = false;
  CHECK(emptied.kill_if([&](std::size_t) {
    if (!assigned) emptied = three_particles<Game>();
    assigned = true;
    return true;
  }) == 0);
  CHECK(emptied.size() == 3);
  // A predicate's result need only be testable as a bool (an optional, a pointer).
  CHECK(emptied.kill_if([&](std::size_t i) {
    return emptied.position(i).x == 1.0f ? std::optional<int>(1) : std::nullopt;
  }) == 1);
  CHECK(emptied.size() == 2);
}

TEST_CASE("spawn_burst names the count it refuses") {
  Sparks system = three_particles<Sparks>();
  const std::size_t count = std::numeric_limits<std::size_t>::max();
  std::string message;
  try {
    (void)system.spawn_burst(count, [](std::size_t) {
      return std::tuple{Vector3<float>{}, Vector3<float>{}};
    });
  } catch (const std::length_error& error) {
    message = error.what();
  }
  CHECK(message.find("spawn_burst: argument 'count' = " + std::to_string(count) +
                     " must be <= max_size() - size() = " +
                     std::to_string(system.max_size() - 3)) != std::string::npos);
  CHECK(system.size() == 3);
}

TEST_CASE("the game features' arguments: removals in an expiry callback, buffers, strides, alpha") {
  using Game = ParticleSystem<float, damping::None, position::Euler, features::Lifetime,
                              features::Interpolation, features::Handles>;
  Game system = three_particles<Game>();
  system.set_lifetime(1, 0.01f);
  // Removing inside the callback is refused, and nothing but the expiring particle goes.
  std::string kill_message, kill_if_message, clear_message;
  system.step(0.02f, [&](std::size_t i) {
    CHECK(i == 1);
    kill_message = invalid_argument_of([&] { system.kill(0); });
    kill_if_message =
        invalid_argument_of([&] { (void)system.kill_if([](std::size_t) { return true; }); });
    clear_message = invalid_argument_of([&] { system.clear(); });
  });
  CHECK(kill_message.find(
            "kill: argument 'index' = 0 must be removed after the expiry callback returns") !=
        std::string::npos);
  CHECK(kill_if_message.find("kill_if") != std::string::npos);
  CHECK(clear_message.find("clear") != std::string::npos);
  CHECK(system.size() == 2);
  // After the step, removing works again.
  system.kill(0);
  CHECK(system.size() == 1);
  system.spawn({5, 5, 5}, {});
  const Game before = system;
  // Copy-out: a stride below 3 and a buffer too short are reported; nothing is written.
  std::vector<float> buffer(5, -1.0f);
  CHECK(invalid_argument_of([&] {
          system.copy_positions(std::span<float>(buffer), 2);
        }).find("copy_positions: argument 'stride' = 2 must be >= 3") != std::string::npos);
  CHECK(invalid_argument_of([&] { system.copy_positions(std::span<float>(buffer), 3); })
            .find("copy_positions: argument 'out' = 5 elements for (size() - 1) * stride + 3 = 6 "
                  "must be at least that many elements long") != std::string::npos);
  CHECK(buffer == std::vector<float>(5, -1.0f));
  std::vector<Vector3<float>> one(1);
  CHECK(invalid_argument_of([&] { system.copy_positions(std::span<Vector3<float>>(one)); })
            .find("copy_positions: argument 'out' = 1 elements for size() = 2 must be at least "
                  "size() elements long") != std::string::npos);
  // A stride so large that (size() - 1) * stride + 3 wraps around to a small count: the
  // needed size saturates instead, so the buffer is refused and nothing is written.
  const std::size_t wrapping = std::numeric_limits<std::size_t>::max() - 1;  // 1 * it + 3 = 1
  REQUIRE(system.size() == 2);
  CHECK(invalid_argument_of([&] { system.copy_positions(std::span<float>(buffer), wrapping); })
            .find("copy_positions: argument 'out' = 5 elements for (size() - 1) * stride + 3 = " +
                  std::to_string(std::numeric_limits<std::size_t>::max())) != std::string::npos);
  CHECK(buffer == std::vector<float>(5, -1.0f));
  // Alpha outside [0, 1] (or NaN), for the packed buffer and for a buffer of Vector3.
  std::vector<Vector3<float>> vectors(2, Vector3<float>{-1.0f, -1.0f, -1.0f});
  for (const float alpha : {-0.5f, 1.5f, std::numeric_limits<float>::quiet_NaN()}) {
    CAPTURE(alpha);
    CHECK(invalid_argument_of([&] {
            (void)system.interpolated_position(0, alpha);
          }).find("interpolated_position: argument 'alpha'") != std::string::npos);
    CHECK(invalid_argument_of([&] {
            system.copy_interpolated_positions(alpha, std::span<float>(buffer));
          }).find("must be in [0, 1]") != std::string::npos);
    CHECK(invalid_argument_of([&] {
            system.copy_interpolated_positions(alpha, std::span<Vector3<float>>(vectors));
          }).find("copy_interpolated_positions: argument 'alpha'") != std::string::npos);
    // The free interpolate, for a lone Particle's loop, checks it the same way.
    CHECK(invalid_argument_of([&] {
            (void)interpolate(Vector3<float>{1, 2, 3}, Vector3<float>{3, 4, 5}, alpha);
          }).find("interpolate: argument 'alpha'") != std::string::npos);
  }
  CHECK(buffer == std::vector<float>(5, -1.0f));
  CHECK(vectors == std::vector<Vector3<float>>(2, Vector3<float>{-1.0f, -1.0f, -1.0f}));
  CHECK(invalid_argument_of([&] { (void)system.handle(7); }).find("handle: argument 'index' = 7") !=
        std::string::npos);
  CHECK(same_particles(system, before));
}

TEST_CASE("spawn_handle: the new particle's handle, or a handle that finds nothing") {
  using Tracked = ParticleSystem<float, damping::None, position::Euler, features::Handles>;
  Tracked system(2);
  const Tracked::Handle first = system.spawn_handle(Vector3<float>{1, 2, 3}, Vector3<float>{});
  const Tracked::Handle second = system.spawn_handle(Vector3<float>{4, 5, 6}, Vector3<float>{});
  REQUIRE(system.find(second).has_value());
  CHECK(system.position(*system.find(second)).x == 4.0f);
  system.kill(0);  // the second particle moves into index 0; the first is gone
  CHECK_FALSE(system.contains(first));
  CHECK(system.find(second) == std::optional<std::size_t>(0));
  const float nan = std::numeric_limits<float>::quiet_NaN();
  Tracked::Handle rejected = second;
  CHECK(invalid_argument_of([&] {
          rejected = system.spawn_handle(Vector3<float>{nan, 0, 0}, Vector3<float>{});
        }).find("spawn: argument 'position'") != std::string::npos);
  CHECK(system.size() == 1);
  CHECK_FALSE(system.contains(Tracked::Handle{}));  // what a rejected spawn returns unchecked
}

TEST_CASE("FixedStep and the trajectory queries report bad arguments and keep their state") {
  FixedStep<double> clock(1.0 / 64, 4);
  CHECK(invalid_argument_of([&] { clock.set_step(0.0); }).find("set_step: argument 'step' = 0") !=
        std::string::npos);
  CHECK(invalid_argument_of([&] {
          clock.set_max_steps(0);
        }).find("set_max_steps: argument 'max_steps' = 0 must be >= 1") != std::string::npos);
  CHECK(invalid_argument_of([&] {
          clock.set_max_steps(-5);
        }).find("set_max_steps: argument 'max_steps' = -5 must be >= 1") != std::string::npos);
  CHECK(clock.step() == 1.0 / 64);
  CHECK(clock.max_steps() == 4);
  (void)clock.advance(1.0 / 128);
  CHECK(invalid_argument_of([&] {
          (void)clock.advance(-1.0);
        }).find("advance: argument 'frame_time' = -1") != std::string::npos);
  CHECK(clock.accumulated() == 1.0 / 128);
  // With a handler that returns, a rejected frame takes no step and draws where the clock
  // stands: half way to the next step.
  static int reported = 0;
  reported = 0;
  const auto previous = set_contract_handler([](const ContractViolation&) { ++reported; });
  const FixedStep<double>::Frame rejected = clock.advance(std::numeric_limits<double>::quiet_NaN());
  set_contract_handler(previous);
  CHECK(reported == 1);
  CHECK(rejected.steps == 0);
  CHECK(rejected.alpha == 0.5);
  CHECK(clock.accumulated() == 1.0 / 128);

  Particle<double, damping::Exact, position::Exact> shell;
  shell.set_velocity({0, 10, 0});
  CHECK(invalid_argument_of([&] {
          (void)state_at(shell, -1.0);
        }).find("state_at: argument 'time' = -1") != std::string::npos);
  CHECK(invalid_argument_of([&] {
          (void)time_to_reach(shell, Axis::y, std::numeric_limits<double>::infinity());
        }).find("time_to_reach: argument 'value'") != std::string::npos);
}

TEST_CASE(
    "spawn_burst takes its particles back when a rejected one's report throws, or the generator") {
  using Game =
      ParticleSystem<float, damping::None, position::Euler, features::Lifetime, features::Handles>;
  Game system = three_particles<Game>();
  const Game before = system;
  const typename Game::Handle first = system.handle(0);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  // Particle 2 of 4 has a NaN position: the default handler throws after 0 and 1 were added.
  const std::string message = invalid_argument_of([&] {
    (void)system.spawn_burst(4, [&](std::size_t k) {
      return std::tuple{Vector3<float>{float(k), k == 2 ? nan : 0.0f, 0}, Vector3<float>{}};
    });
  });
  CHECK(message.find("spawn: argument 'position'") != std::string::npos);
  CHECK(message.find("(in spawn_burst, element 2)") != std::string::npos);
  CHECK(system.size() == 3);
  CHECK(same_particles(system, before));
  // The generator itself throws at particle 3.
  bool thrown = false;
  try {
    (void)system.spawn_burst(5, [&](std::size_t k) {
      if (k == 3) throw std::runtime_error("generator");
      return std::tuple{Vector3<float>{float(k), 1, 0}, Vector3<float>{}};
    });
  } catch (const std::runtime_error&) {
    thrown = true;
  }
  CHECK(thrown);
  CHECK(system.size() == 3);
  CHECK(same_particles(system, before));
  // The handles of the particles that were there still find them; a burst that succeeds
  // adds its particles after them.
  CHECK(system.find(first) == std::optional<std::size_t>(0));
  CHECK(system.spawn_burst(2, [](std::size_t k) {
    return std::tuple{Vector3<float>{float(k), 2, 0}, Vector3<float>{}};
  }) == 2);
  CHECK(system.size() == 5);
  CHECK(system.position(4) == Vector3<float>{1, 2, 0});
}

TEST_CASE("spawn_burst's generator may not remove or step, and replacing the particles ends it") {
  // The burst's particles are the last ones: a generator that killed one moved another
  // particle among them, and the rollback after a throw then took the wrong ones away; one
  // that assigned the system another state had that state's particles removed.
  using Game = ParticleSystem<float, damping::None, position::Euler, features::Lifetime>;
  Game system = three_particles<Game>();
  const Game before = system;
  std::string kill_message;
  std::string step_message;
  std::string clear_message;
  const auto refused = [&](std::size_t k) {
    if (k == 1) {
      kill_message = invalid_argument_of([&] { system.kill(0); });
      step_message = invalid_argument_of([&] { system.step(0.1f); });
      clear_message = invalid_argument_of([&] { system.clear(); });
    }
    return std::tuple{Vector3<float>{100.0f + float(k), 0, 0}, Vector3<float>{}};
  };
  CHECK(system.spawn_burst(3, refused) == 3);
  CHECK(kill_message.find("kill: argument 'index' = 0 must be removed after spawn_burst's "
                          "generator returns") != std::string::npos);
  CHECK(step_message.find("must be stepped after spawn_burst's generator returns") !=
        std::string::npos);
  CHECK(clear_message.find("after spawn_burst's generator returns") != std::string::npos);
  REQUIRE(system.size() == 6);  // nothing removed: the first three, then the burst's
  for (std::size_t i = 0; i < 3; ++i) {
    CHECK(system.position(i) == before.position(i));
    CHECK(system.position(3 + i) == Vector3<float>{100.0f + float(i), 0, 0});
  }
  // A refused kill, then a throw: the rollback leaves exactly the particles of before.
  Game rolled = before;
  CHECK_THROWS_AS(
      (void)rolled.spawn_burst(
          3,
          [&](std::size_t k) {
            if (k == 1) {
              static_cast<void>(invalid_argument_of([&] { rolled.kill(0); }));
              throw std::runtime_error("generator");
            }
            return std::tuple{Vector3<float>{100.0f + float(k), 0, 0}, Vector3<float>{}};
          }),
      std::runtime_error);
  CHECK(same_particles(rolled, before));
  // The generator assigns the system another state, then throws: that state stays whole.
  Game other = three_particles<Game>();
  other.kill(0);
  for (int i = 0; i < 3; ++i) other.spawn({-1.0f - float(i), 0, 0}, {});  // five, not before's
  const Game other_before = other;
  Game replaced = before;
  CHECK_THROWS_AS(
      (void)replaced.spawn_burst(
          3,
          [&](std::size_t k) {
            if (k == 1) {
              replaced = other;
              throw std::runtime_error("generator");
            }
            return std::tuple{Vector3<float>{100.0f + float(k), 0, 0}, Vector3<float>{}};
          }),
      std::runtime_error);
  CHECK(same_particles(replaced, other_before));
  // Without a throw the burst ends at the replacement, and names none as its own.
  Game ended = before;
  CHECK(ended.spawn_burst(3, [&](std::size_t k) {
    if (k == 1) ended = other;
    return std::tuple{Vector3<float>{100.0f + float(k), 0, 0}, Vector3<float>{}};
  }) == 0);
  CHECK(same_particles(ended, other_before));
}

TEST_CASE("begin_step names itself in its report, step names step") {
  ParticleSystem<float> system = three_particles<ParticleSystem<float>>();
  const float nan = std::numeric_limits<float>::quiet_NaN();
  CHECK(invalid_argument_of([&] {
          (void)system.begin_step(nan);
        }).find("begin_step: argument 'duration' = nan") != std::string::npos);
  CHECK(invalid_argument_of([&] {
          system.step(nan);
        }).find("pointmass: step: argument 'duration' = nan") != std::string::npos);
}

namespace {
std::vector<ContractViolation> burst_reports;
bool throw_after_report = false;
}  // namespace

TEST_CASE("spawn_burst names the element whose particle it rejects, and only inside the burst") {
  ParticleSystem<float> system;
  const float inf = std::numeric_limits<float>::infinity();
  burst_reports.clear();
  throw_after_report = false;
  const ContractHandler previous = set_contract_handler([](const ContractViolation& v) {
    burst_reports.push_back(v);
    if (throw_after_report) throw std::invalid_argument("handler");
  });
  // Element 3 of 5 is rejected (a handler that returns: it is skipped).
  const std::size_t added = system.spawn_burst(5, [&](std::size_t k) {
    return std::pair{Vector3<float>{float(k), 0, 0}, Vector3<float>{k == 3 ? inf : 0.0f, 0, 0}};
  });
  (void)system.spawn(Vector3<float>{0, inf, 0}, Vector3<float>{});  // after the burst
  // Element 1 of 2 is rejected by a handler that throws: the exception leaves the burst
  // while element 1's checks run, and the report after it names no element.
  throw_after_report = true;
  bool thrown = false;
  try {
    (void)system.spawn_burst(2, [&](std::size_t k) {
      return std::pair{Vector3<float>{}, Vector3<float>{k == 1 ? inf : 0.0f, 0, 0}};
    });
  } catch (const std::invalid_argument&) {
    thrown = true;
  }
  throw_after_report = false;
  (void)system.spawn(Vector3<float>{inf, 0, 0}, Vector3<float>{});
  set_contract_handler(previous);
  CHECK(added == 4);
  CHECK(thrown);
  REQUIRE(burst_reports.size() == 4);
  const std::size_t elements[] = {3, 0, 1, 0};
  const bool in_burst[] = {true, false, true, false};
  for (std::size_t r = 0; r < 4; ++r) {
    CAPTURE(r);
    CHECK(std::string(burst_reports[r].argument) == (r % 2 == 1 ? "position" : "velocity"));
    CHECK(burst_reports[r].element == elements[r]);
    const std::string message = describe(burst_reports[r]);
    if (in_burst[r]) {
      REQUIRE(burst_reports[r].within != nullptr);
      CHECK(std::string(burst_reports[r].within) == "spawn_burst");
      CHECK(message.find("(in spawn_burst, element " + std::to_string(elements[r]) + ")") !=
            std::string::npos);
    } else {
      CHECK(burst_reports[r].within == nullptr);
      CHECK(message.find("(in ") == std::string::npos);
    }
  }
}

TEST_CASE_TEMPLATE(
    "the positions relative to a camera refuse a non-finite origin and write nothing", S, float,
    Precision<float, double>, Precision<float, Compensated<float>>) {
  using Value = position_value_t<S>;
  ParticleSystem<S> system;
  system.spawn(Vector3<Value>{Value(1e6), Value(2), Value(-3)}, Vector3<float>{});
  system.spawn(Vector3<Value>{Value(-5), Value(1e6), Value(7)}, Vector3<float>{});
  Particle<S> particle;
  particle.set_position(Vector3<Value>{Value(1e6), Value(2), Value(-3)});
  const Vector3<Value> good{Value(1e6), Value(0), Value(0)};
  const Vector3<float> unwritten{7.0f, 7.0f, 7.0f};
  for (const Value bad :
       {std::numeric_limits<Value>::quiet_NaN(), std::numeric_limits<Value>::infinity(),
        -std::numeric_limits<Value>::infinity()}) {
    for (int axis = 0; axis < 3; ++axis) {
      Vector3<Value> origin = good;
      (axis == 0 ? origin.x : axis == 1 ? origin.y : origin.z) = bad;
      std::vector<Vector3<float>> buffer(2, unwritten);
      CHECK(invalid_argument_of([&] {
              system.copy_positions(std::span(buffer), origin);
            }).find("copy_positions: argument 'origin'") != std::string::npos);
      CHECK(buffer == std::vector<Vector3<float>>(2, unwritten));
      CHECK(invalid_argument_of([&] {
              (void)system.position_relative_to(1, origin);
            }).find("position_relative_to: argument 'origin'") != std::string::npos);
      CHECK(invalid_argument_of([&] {
              (void)particle.position_relative_to(origin);
            }).find("position_relative_to: argument 'origin'") != std::string::npos);
    }
  }
  // A finite origin is taken.
  std::vector<Vector3<float>> buffer(2, unwritten);
  system.copy_positions(std::span(buffer), good);
  CHECK(buffer[0] == Vector3<float>{0, 2, -3});
  CHECK(buffer[0] == particle.position_relative_to(good));
}

TEST_CASE_TEMPLATE(
    "a negative, NaN or infinite duration is reported by update_force, apply and "
    "update_forces, and no force is added",
    R, float, double) {
  const forces::Gravity<R> gravity(Vector3<R>{R(0), R(-10), R(0)});
  const forces::Drag<R> drag(R(1), R(0));
  Particle<R> particle;
  particle.set_velocity({R(1), R(0), R(0)});
  forces::ForceRegistry<Particle<R>, forces::Gravity<R>> registry;
  forces::Gravity<R> registered(Vector3<R>{R(0), R(-10), R(0)});
  registry.add(particle, registered);
  const std::array<Vector3<R>, 2> positions{};
  const std::array<Vector3<R>, 2> velocities{{{R(1), R(0), R(0)}, {R(0), R(2), R(0)}}};
  std::array<Vector3<R>, 2> f{};
  forces::SpanBodies<R> bodies{positions, velocities, {}, f};
  for (const R bad : {R(-1), -std::numeric_limits<R>::denorm_min(),
                      std::numeric_limits<R>::quiet_NaN(), std::numeric_limits<R>::infinity()}) {
    CAPTURE(bad);
    CHECK(invalid_argument_of([&] {
            forces::update_force(gravity, particle, bad);
          }).find("forces::update_force: argument 'duration'") != std::string::npos);
    CHECK(invalid_argument_of([&] {
            forces::apply(drag, bodies, bad);
          }).find("forces::apply: argument 'duration'") != std::string::npos);
    CHECK(invalid_argument_of([&] {
            registry.update_forces(bad);
          }).find("ForceRegistry::update_forces: argument 'duration'") != std::string::npos);
    CHECK(particle.force_accumulator() == Vector3<R>{});
    CHECK(f == std::array<Vector3<R>, 2>{});
  }
  // Zero and a positive duration are taken.
  forces::update_force(gravity, particle, R(0));
  registry.update_forces(R(0.5));
  CHECK(particle.force_accumulator() == Vector3<R>{R(0), R(-20), R(0)});
  forces::apply(drag, bodies, R(0.5));
  CHECK(f[1] == Vector3<R>{R(0), R(-2), R(0)});
}

TEST_CASE("damped_oscillator reports an argument outside its domain and returns the state it got") {
  const Vector3<double> x0{1, 0, 0}, v0{0, 1, 0};
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  struct Bad {
    double w0_squared, gamma;
    Vector3<double> x, v;
    double t;
    const char* argument;
  };
  const Bad cases[] = {{-1, 0, x0, v0, 1, "w0_squared"},  {nan, 0, x0, v0, 1, "w0_squared"},
                       {inf, 0, x0, v0, 1, "w0_squared"}, {1, -1, x0, v0, 1, "gamma"},
                       {1, nan, x0, v0, 1, "gamma"},      {1, 0, {nan, 0, 0}, v0, 1, "x0"},
                       {1, 0, x0, {0, inf, 0}, 1, "v0"},  {1, 0, x0, v0, -1, "t"},
                       {1, 0, x0, v0, nan, "t"},          {1, 0, x0, v0, inf, "t"}};
  for (const Bad& bad : cases) {
    CAPTURE(bad.argument);
    CHECK(invalid_argument_of([&] {
            (void)forces::damped_oscillator(bad.w0_squared, bad.gamma, bad.x, bad.v, bad.t);
          }).find(std::string("forces::damped_oscillator: argument '") + bad.argument + "'") !=
          std::string::npos);
  }
  // With a handler that returns, the result is the state given.
  const ContractHandler previous = set_contract_handler([](const ContractViolation&) {});
  const auto s = forces::damped_oscillator(-1.0, 0.0, x0, v0, 1.0);
  set_contract_handler(previous);
  CHECK(s.position == x0);
  CHECK(s.velocity == v0);
  // Inside the domain, undamped with w0 = 1, from (1, 0, 0) at rest: x = cos t, v = -sin t.
  const auto quarter = forces::damped_oscillator(1.0, 0.0, x0, Vector3<double>{}, 0.5);
  CHECK(quarter.position.x == doctest::Approx(std::cos(0.5)).epsilon(1e-15));
  CHECK(quarter.velocity.x == doctest::Approx(-std::sin(0.5)).epsilon(1e-15));
}
