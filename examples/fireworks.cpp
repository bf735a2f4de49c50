// fireworks — the reference engine's fireworks demo on the batch ParticleSystem.
//
// Nine firework types (rules): each has a fuse range, a box its launch velocity is drawn
// from, a damping (per second) and a payload: when the fuse burns out the firework bursts
// into a number of fireworks of other types, each inheriting its velocity plus its own
// random velocity. Types 1, 2, 6, 7 and 9 are launched from x = -5, 0 or 5; the others
// appear only in bursts.
//
// "Skip what a scene doesn't need": every particle of a type shares the type's damping, so
// the scene keeps one ParticleSystem per type with uniform damping and uniform gravity:
// d^t is computed once per type per frame, not once per spark, and nothing but position,
// velocity, age and fuse is stored per spark.
//
// The random generator is seeded (--seed N), so a run is reproducible. Each second the
// program prints the live sparks and the bursts; at the end it checks its own accounting
// (every spark spawned is alive or has burnt out; every burnt-out fuse was within its type's
// range) and prints "accounting: ok" or what went wrong (exit status 1).
//
//   fireworks [--seconds S] [--seed N] [--csv FILE]   (CSV: t,type,x,y,z every 0.25 s)
#include <pointmass/particle_system.hpp>
#include <pointmass/pointmass.hpp>

#include <array>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <random>
#include <vector>

namespace {

using namespace pointmass;
using Number = float;  // the precision of the whole show
using Sparks = ParticleSystem<Number, damping::PerSecond, position::Euler, features::Lifetime>;

struct Payload {
  int type;
  int count;
};

struct Rule {
  Number min_fuse, max_fuse;
  Vector3<Number> min_velocity, max_velocity;
  Number damping;
  std::array<Payload, 2> payloads;  // count 0: none
};

// The reference engine's nine rules (index 0 is type 1).
const std::array<Rule, 9> rules{{
    {0.5f, 1.4f, {-5, 25, -5}, {5, 28, 5}, 0.1f, {{{3, 5}, {5, 5}}}},
    {0.5f, 1.0f, {-5, 10, -5}, {5, 20, 5}, 0.8f, {{{4, 2}, {0, 0}}}},
    {0.5f, 1.5f, {-5, -5, -5}, {5, 5, 5}, 0.1f, {{{0, 0}, {0, 0}}}},
    {0.25f, 0.5f, {-20, 5, -5}, {20, 5, 5}, 0.2f, {{{0, 0}, {0, 0}}}},
    {0.5f, 1.0f, {-20, 2, -5}, {20, 18, 5}, 0.01f, {{{3, 5}, {0, 0}}}},
    {3.0f, 5.0f, {-5, 5, -5}, {5, 10, 5}, 0.95f, {{{0, 0}, {0, 0}}}},
    {4.0f, 5.0f, {-5, 50, -5}, {5, 60, 5}, 0.01f, {{{8, 10}, {0, 0}}}},
    {0.25f, 0.5f, {-1, -1, -1}, {1, 1, 1}, 0.01f, {{{0, 0}, {0, 0}}}},
    {3.0f, 5.0f, {-15, 10, -5}, {15, 15, 5}, 0.95f, {{{0, 0}, {0, 0}}}},
}};

constexpr std::array<int, 5> launched_types{1, 2, 6, 7, 9};

/// Uniform in [low, high) from the generator's raw bits (the same on every platform, unlike
/// std::uniform_real_distribution).
Number uniform(std::mt19937& random, Number low, Number high) {
  const Number unit = Number(random() >> 8) * Number(1.0 / 16777216.0);  // 24 bits: [0, 1)
  return low + (high - low) * unit;
}

struct Show {
  std::array<Sparks, 9> sparks;
  std::mt19937 random;
  long spawned = 0, burnt_out = 0, bursts = 0, bad_fuses = 0;

  explicit Show(std::uint32_t seed) : random(seed) {
    for (std::size_t t = 0; t < sparks.size(); ++t) {
      sparks[t].reserve(4096);
      sparks[t].set_damping(rules[t].damping);
      sparks[t].set_acceleration(gravity<Number>());
    }
  }

  void create(int type, const Vector3<Number>& position, const Vector3<Number>& inherited) {
    const Rule& rule = rules[static_cast<std::size_t>(type - 1)];
    const Vector3<Number> velocity{uniform(random, rule.min_velocity.x, rule.max_velocity.x),
                                 uniform(random, rule.min_velocity.y, rule.max_velocity.y),
                                 uniform(random, rule.min_velocity.z, rule.max_velocity.z)};
    Sparks& system = sparks[static_cast<std::size_t>(type - 1)];
    const std::size_t i = system.spawn(position, inherited + velocity);
    system.set_lifetime(i, uniform(random, rule.min_fuse, rule.max_fuse));
    ++spawned;
  }

  void launch() {
    const int type = launched_types[random() % launched_types.size()];
    const Number x = Number(5) * Number(static_cast<int>(random() % 3) - 1);
    create(type, {x, Number(0), Number(0)}, {});
  }

  /// One frame: fireworks whose fuse ends in this step burst (at their state before it).
  void frame(Number dt) {
    struct Burst {
      int type;
      Vector3<Number> position, velocity;
    };
    std::vector<Burst> bursting;
    for (std::size_t t = 0; t < sparks.size(); ++t) {
      Sparks& system = sparks[t];
      const Rule& rule = rules[t];
      for (std::size_t i = 0; i < system.size(); ++i) {
        if (system.age(i) + dt < system.lifetime(i)) continue;
        ++burnt_out;
        if (system.lifetime(i) < rule.min_fuse || system.lifetime(i) > rule.max_fuse) ++bad_fuses;
        bursting.push_back({static_cast<int>(t + 1),
                            {system.position_x()[i], system.position_y()[i], system.position_z()[i]},
                            {system.velocity_x()[i], system.velocity_y()[i], system.velocity_z()[i]}});
      }
      system.step(dt);  // steps every spark and removes the burnt-out ones
    }
    for (const Burst& burst : bursting) {
      bool burst_any = false;
      for (const Payload& payload : rules[static_cast<std::size_t>(burst.type - 1)].payloads) {
        for (int n = 0; n < payload.count; ++n) {
          create(payload.type, burst.position, burst.velocity);
          burst_any = true;
        }
      }
      if (burst_any) ++bursts;
    }
  }

  long live() const {
    long count = 0;
    for (const Sparks& system : sparks) count += static_cast<long>(system.size());
    return count;
  }
};

}  // namespace

int main(int argc, char** argv) {
  int seconds = 10;
  std::uint32_t seed = 1;
  const char* csv_path = nullptr;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--seconds") == 0 && i + 1 < argc) {
      seconds = std::atoi(argv[++i]);
    } else if (std::strcmp(argv[i], "--seed") == 0 && i + 1 < argc) {
      seed = static_cast<std::uint32_t>(std::strtoul(argv[++i], nullptr, 10));
    } else if (std::strcmp(argv[i], "--csv") == 0 && i + 1 < argc) {
      csv_path = argv[++i];
    } else {
      std::fprintf(stderr, "usage: %s [--seconds S] [--seed N] [--csv FILE]\n", argv[0]);
      return 2;
    }
  }
  std::FILE* csv = csv_path != nullptr ? std::fopen(csv_path, "w") : nullptr;
  if (csv_path != nullptr && csv == nullptr) {
    std::fprintf(stderr, "cannot write %s\n", csv_path);
    return 1;
  }
  if (csv != nullptr) std::fprintf(csv, "t,type,x,y,z\n");

  constexpr int frames_per_second = 60;
  const Number dt = Number(1) / Number(frames_per_second);
  Show show(seed);
  long bursts_before = 0;
  for (int frame = 0; frame < seconds * frames_per_second; ++frame) {
    if (frame % (frames_per_second / 2) == 0) show.launch();  // two launches a second
    show.frame(dt);
    const int next = frame + 1;
    if (csv != nullptr && next % (frames_per_second / 4) == 0) {
      for (std::size_t t = 0; t < show.sparks.size(); ++t) {
        Sparks& system = show.sparks[t];
        for (std::size_t i = 0; i < system.size(); ++i) {
          std::fprintf(csv, "%.2f,%zu,%.3f,%.3f,%.3f\n", double(next) / frames_per_second, t + 1,
                       double(system.position_x()[i]), double(system.position_y()[i]),
                       double(system.position_z()[i]));
        }
      }
    }
    if (next % frames_per_second == 0) {
      std::printf("t = %2d s: %5ld live sparks, %3ld bursts this second\n",
                  next / frames_per_second, show.live(), show.bursts - bursts_before);
      bursts_before = show.bursts;
    }
  }
  if (csv != nullptr) std::fclose(csv);

  std::printf("spawned %ld, burnt out %ld, live %ld, bursts %ld\n", show.spawned, show.burnt_out,
              show.live(), show.bursts);
  if (show.spawned != show.burnt_out + show.live() || show.bad_fuses != 0) {
    std::printf("accounting: FAILED (%ld fuses out of range)\n", show.bad_fuses);
    return 1;
  }
  std::printf("accounting: ok\n");
  return 0;
}
