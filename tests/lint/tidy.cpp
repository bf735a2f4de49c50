// SPDX-License-Identifier: BSL-1.0
// The translation unit the static analysis reads (.clang-tidy): it instantiates the main
// configurations of every public header, so that their templates' bodies are analysed.
#include <pointmass/parallel.hpp>
#include <pointmass/pointmass.hpp>
#include <pointmass/snapshot.hpp>
#include <pointmass/units.hpp>

#include <cstdint>
#include <cstdio>
#include <exception>
#include <execution>

namespace pm = pointmass;

namespace {

struct TagColour {};

template <class P>
double fly(P particle) {
  particle.set_position({0, 1, 0});
  particle.set_velocity({0, 30, 40});
  particle.set_acceleration(pm::gravity(typename P::real(10)));
  particle.set_mass(typename P::real(2));
  for (int i = 0; i < 60; ++i) particle.integrate(typename P::real(1) / 60);
  return double(particle.position().y);
}

template <class S>
double batch(S system) {
  system.set_acceleration(pm::gravity(typename S::real(10)));
  for (int i = 0; i < 100; ++i) (void)system.spawn({0, 0, 0}, {1, 2, 3});
  system.step(typename S::real(1) / 60);
  return double(system.position(0).y);
}

double configurations() {
  using namespace pm;
  double sum = 0;
  sum += fly(Particle<float>{});
  sum += fly(Particle<double, damping::PerFrame, position::ConstantAcceleration>{});
  sum += fly(Particle<double, damping::Exact, position::Exact>{});
  sum += fly(Particle<float, damping::AccelerateThenDamp, position::SemiImplicit>{});
  sum += fly(Particle<Precision<float, double>>{});
  sum += fly(Particle<Precision<float, Compensated<float>>, damping::Exact, position::Exact>{});
  sum += batch(ParticleSystem<float>{});
  sum += batch(ParticleSystem<double, damping::Exact, position::Exact>{});
  sum += fly(Particle<float, damping::PerSecond, position::VelocityVerlet>{});
  sum += batch(
      ParticleSystem<Precision<float, Compensated<float>>, damping::PerSecond,
                     position::VelocityVerlet, features::ForceAccumulator, features::Lifetime>{});
  sum += batch(ParticleSystem<Precision<float, double>, damping::PerSecond, position::SemiImplicit,
                              features::ForceAccumulator>{});

  // Lifetimes, handles, interpolation and a user column, stepped serially and in parallel.
  using Sparks = ParticleSystem<float, damping::PerSecond, position::Euler, features::Lifetime,
                                features::Handles, features::Interpolation,
                                features::Column<TagColour, std::uint32_t>>;
  Sparks sparks;
  const auto handle =
      sparks.spawn_handle(Vector3<float>{0, 0, 0}, Vector3<float>{0, 1, 0}, std::uint32_t{7});
  sparks.set_lifetime(0, 0.5f);
  int expired = 0;
  sparks.step(0.25f, [&](std::size_t) { ++expired; });
  pm::step(std::execution::par_unseq, sparks, 0.5f, [&](std::size_t) { ++expired; });
  sum += double(sparks.contains(handle)) + expired;

  // Forces: the registry over particles, fields over a batch.
  using Body = Particle<double, damping::PerSecond, position::SemiImplicit>;
  Body a;
  Body b;
  b.set_position({0, -1, 0});
  forces::Gravity<double> gravity({0, -9.8, 0});
  forces::Drag<double> drag(0.1, 0.01);
  forces::AnchoredSpring<double> hook({0, 0, 0}, 10, 1);
  forces::Spring<Body> link(a, 10, 1);
  forces::ForceRegistry<Body, forces::Gravity<double>, forces::Drag<double>,
                        forces::AnchoredSpring<double>, forces::Spring<Body>>
      registry;
  registry.add(a, gravity);
  registry.add(a, hook);
  registry.add(b, drag);
  registry.add(b, link);
  registry.update_forces(1.0 / 60);
  a.integrate(1.0 / 60);
  b.integrate(1.0 / 60);
  ParticleSystem<float, damping::PerSecond, position::SemiImplicit, features::ForceAccumulator>
      forced;
  (void)forced.spawn({0, 0, 0}, {1, 0, 0});
  forces::apply(forces::Drag<float>(0.1f, 0.01f), forced, 1.0f / 60);
  forced.step(1.0f / 60);
  sum += b.position().y + double(forced.position(0).x);

  // The fixed-step clock and the closed form.
  FixedStep<double> clock(1.0 / 60, 4);
  const auto frame = clock.advance(0.1);
  sum += frame.alpha + frame.steps;
  return sum;
}

// Every call of snapshot.hpp, on a configuration with handles and a user column.
double snapshots() {
  using Saved = pm::ParticleSystem<float, pm::damping::PerSecond, pm::position::SemiImplicit,
                                   pm::features::Lifetime, pm::features::Handles,
                                   pm::features::Column<TagColour, std::uint32_t>>;
  Saved system;
  (void)system.spawn({0, 0, 0}, {1, 2, 3});
  const pm::Snapshot<Saved> saved(system);
  system.step(1.0F / 60);
  saved.restore(system);
  Saved loaded;
  const bool same =
      pm::load_bytes(loaded, pm::save_bytes(system)) && pm::state_hash(loaded) == saved.hash();
  return same ? 1.0 : 0.0;
}

double with_units() {
  namespace si = boost::units::si;
  pm::units::Particle<double, pm::damping::PerSecond, pm::position::ConstantAcceleration> shell;
  shell.set_velocity(pm::Vector3<double>{0, 10, 0} * si::meters_per_second);
  shell.set_mass(2.0 * si::kilograms);
  shell.integrate(0.5 * si::seconds);
  return shell.position().y.value();
}

}  // namespace

int main() try {
  std::printf("%g\n", configurations() + with_units() + snapshots());
  return 0;
} catch (const std::exception& e) {
  std::fputs(e.what(), stderr);
  return 1;
}
