// SPDX-License-Identifier: BSL-1.0
// fireworks — Cyclone's fireworks demo on the batch ParticleSystem.
//
// Nine firework types (rules): each has a fuse range, a box its launch velocity is drawn
// from, a damping (per second) and a payload: when the fuse burns out the firework bursts
// into a number of fireworks of other types, each inheriting its velocity plus its own
// random velocity, and its colour. Types 1, 2, 6, 7 and 9 are launched from x = -5, 0 or 5
// in a colour of their own; the others appear only in bursts.
//
// "Skip what a scene doesn't need": every particle of a type shares the type's damping, so
// the scene keeps one ParticleSystem per type with uniform damping and uniform gravity:
// d^t is computed once per type per step, not once per spark. Per spark it stores position,
// velocity, age and fuse, the position before the last step (features::Interpolation), the
// spark's colour and its serial number (user columns, moved with the spark whenever another
// burns out).
//
// A game's loop: physics at a fixed 60 Hz (FixedStep), rendering at whatever rate the frames
// come (here an irregular, seeded sequence around 50 frames a second), each frame drawing the
// sparks between the last two steps (copy_interpolated_positions at the accumulator's alpha).
// A spark whose fuse ends is reported by the step's expiry callback in its final state; its
// payload is created after the step, so it flies from the next step on.
//
// The random generator is seeded (--seed N), so a run is reproducible. Each second the
// program prints the live sparks and the bursts; at the end it checks its own accounting
// (every spark spawned is alive or has burnt out; each spark that burns out still has the
// fuse and colour it was spawned with, looked up by its serial number, so the columns moved
// with it; every child has its parent's colour) and prints "accounting: ok" or what went
// wrong (exit status 1).
//
//   fireworks [--seconds S] [--seed N] [--csv FILE]   (CSV: t,type,x,y,z,rgb every 0.25 s,
//                                                      drawn positions)
#include <pointmass/fixed_step.hpp>
#include <pointmass/particle_system.hpp>
#include <pointmass/pointmass.hpp>

#include <array>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <random>
#include <span>
#include <vector>

namespace {

using namespace pointmass;
using Number = float;          // the precision of the whole show
struct ColourTag {};           // names the colour column
struct SerialTag {};           // names the serial number column
using Colour = std::uint32_t;  // 0xRRGGBB
using Serial = std::uint32_t;  // the spark's place in the show's record of what it spawned
using Sparks = ParticleSystem<Number, damping::PerSecond, position::Euler, features::Lifetime,
                              features::Interpolation, features::Column<ColourTag, Colour>,
                              features::Column<SerialTag, Serial>>;

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

// Cyclone's nine rules (index 0 is type 1).
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
constexpr std::array<Colour, 6> palette{0xff3030, 0x30ff30, 0x3060ff, 0xffd700, 0xff40ff, 0xffffff};

/// Uniform in [low, high) from the generator's raw bits (the same on every platform, unlike
/// std::uniform_real_distribution).
Number uniform(std::mt19937& random, Number low, Number high) {
  const Number unit = Number(random() >> 8) * Number(1.0 / 16777216.0);  // 24 bits: [0, 1)
  return low + (high - low) * unit;
}

struct Show {
  /// What a spark was spawned with, by serial number.
  struct Record {
    Number fuse;
    Colour colour;
  };
  std::array<Sparks, 9> sparks;
  std::vector<Record> spawned_sparks;
  std::mt19937 random;
  long spawned = 0, burnt_out = 0, bursts = 0, bad_fuses = 0, wrong_colours = 0;

  explicit Show(std::uint32_t seed) : random(seed) {
    for (std::size_t t = 0; t < sparks.size(); ++t) {
      sparks[t].reserve(4096);
      sparks[t].set_damping(rules[t].damping);
      sparks[t].set_acceleration(gravity<Number>());
    }
  }

  void create(int type, const Vector3<Number>& position, const Vector3<Number>& inherited,
              Colour colour) {
    const Rule& rule = rules[static_cast<std::size_t>(type - 1)];
    const Vector3<Number> velocity{uniform(random, rule.min_velocity.x, rule.max_velocity.x),
                                   uniform(random, rule.min_velocity.y, rule.max_velocity.y),
                                   uniform(random, rule.min_velocity.z, rule.max_velocity.z)};
    Sparks& system = sparks[static_cast<std::size_t>(type - 1)];
    const Number fuse = uniform(random, rule.min_fuse, rule.max_fuse);
    const auto serial = static_cast<Serial>(spawned_sparks.size());
    const std::size_t i = system.spawn(position, inherited + velocity, colour, serial);
    system.set_lifetime(i, fuse);
    spawned_sparks.push_back({fuse, colour});
    ++spawned;
  }

  void launch() {
    const int type = launched_types[random() % launched_types.size()];
    const Number x = Number(5) * Number(static_cast<int>(random() % 3) - 1);
    create(type, {x, Number(0), Number(0)}, {}, palette[random() % palette.size()]);
  }

  /// One fixed step: every spark moves; each whose fuse ends bursts from its final state.
  void step(Number dt) {
    struct Burst {
      int type;
      Vector3<Number> position, velocity;
      Colour colour;
    };
    std::vector<Burst> bursting;
    for (std::size_t t = 0; t < sparks.size(); ++t) {
      Sparks& system = sparks[t];
      const Rule& rule = rules[t];
      system.step(dt, [&](std::size_t i) {  // spark i burns out: called once, before removal
        ++burnt_out;
        const Record& record = spawned_sparks[system.column<SerialTag>(i)];
        if (system.lifetime(i) != record.fuse || system.lifetime(i) < rule.min_fuse ||
            system.lifetime(i) > rule.max_fuse) {
          ++bad_fuses;
        }
        if (system.column<ColourTag>(i) != record.colour) ++wrong_colours;
        bursting.push_back({static_cast<int>(t + 1), system.position(i), system.velocity(i),
                            system.column<ColourTag>(i)});
      });
    }
    // The payloads go into other types' systems, some already stepped this step: creating
    // them after every system has stepped makes every child fly from the next step on.
    for (const Burst& burst : bursting) {
      bool burst_any = false;
      for (const Payload& payload : rules[static_cast<std::size_t>(burst.type - 1)].payloads) {
        if (payload.count == 0) continue;  // no payload (and type 0, which names no system)
        Sparks& children = sparks[static_cast<std::size_t>(payload.type - 1)];
        for (int n = 0; n < payload.count; ++n) {
          create(payload.type, burst.position, burst.velocity, burst.colour);
          if (children.column<ColourTag>(children.size() - 1) != burst.colour) ++wrong_colours;
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
  if (csv != nullptr) std::fprintf(csv, "t,type,x,y,z,rgb\n");

  constexpr int steps_per_second = 60;
  const Number dt = Number(1) / Number(steps_per_second);
  FixedStep<double> clock(1.0 / steps_per_second, 4);  // at most 4 steps a rendered frame
  std::mt19937 frame_jitter(seed + 1);
  Show show(seed);
  long bursts_before = 0;
  long steps = 0;
  double next_csv = 0.25;
  std::vector<Number> drawn;  // the renderer's buffer: x, y, z per spark
  while (steps < long(seconds) * steps_per_second) {
    // A rendered frame of 15 to 25 ms: the fixed steps it is due, then the picture between.
    const double frame_time = 0.015 + 0.010 * double(frame_jitter() % 1001) / 1000.0;
    const auto frame = clock.advance(frame_time);
    for (int s = 0; s < frame.steps && steps < long(seconds) * steps_per_second; ++s) {
      if (steps % (steps_per_second / 2) == 0) show.launch();  // two launches a second
      show.step(dt);
      ++steps;
      if (steps % steps_per_second == 0) {
        std::printf("t = %2ld s: %5ld live sparks, %3ld bursts this second\n",
                    steps / steps_per_second, show.live(), show.bursts - bursts_before);
        bursts_before = show.bursts;
      }
    }
    const double drawn_at = (double(steps) + frame.alpha) / steps_per_second;
    if (csv != nullptr && drawn_at >= next_csv) {
      next_csv += 0.25;
      for (std::size_t t = 0; t < show.sparks.size(); ++t) {
        const Sparks& system = show.sparks[t];
        drawn.resize(3 * system.size());
        system.copy_interpolated_positions(Number(frame.alpha), std::span<Number>(drawn));
        for (std::size_t i = 0; i < system.size(); ++i) {
          std::fprintf(csv, "%.3f,%zu,%.3f,%.3f,%.3f,%06x\n", drawn_at, t + 1, double(drawn[3 * i]),
                       double(drawn[3 * i + 1]), double(drawn[3 * i + 2]),
                       unsigned(system.column<ColourTag>(i)));
        }
      }
    }
  }
  if (csv != nullptr) std::fclose(csv);

  std::printf("spawned %ld, burnt out %ld, live %ld, bursts %ld\n", show.spawned, show.burnt_out,
              show.live(), show.bursts);
  if (show.spawned != show.burnt_out + show.live() || show.bad_fuses != 0 ||
      show.wrong_colours != 0) {
    std::printf(
        "accounting: FAILED (%ld sparks with another's fuse or one out of range, %ld "
        "sparks or children in another colour)\n",
        show.bad_fuses, show.wrong_colours);
    return 1;
  }
  std::printf("accounting: ok\n");
  return 0;
}
