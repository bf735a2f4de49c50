// SPDX-License-Identifier: BSL-1.0
// Fuzz target: drives Particle (every damping x position pair), ParticleSystem (eleven feature
// sets and policy pairs, and five with positions stored wider than the arithmetic: operation
// sequences checked against a reference model, see "ParticleSystem" below) and the force
// generators, float and double, through the public API with arbitrary bytes.
//
// The first byte chooses the configuration; the rest is a program of operations (setters,
// forces, steps, spawns, kills...) whose arguments are read from the input as raw bit
// patterns, special values (0, -0, infinities, NaN, subnormals, the largest finite value),
// "physical" values or tiny durations. For every operation the target checks:
//
//   * A value the contract rejects (docs/numerics.md, "Contracts") is reported exactly once
//     to the installed handler, naming the documented function and argument, with a value
//     text that reads back as the value; and nothing changes.
//   * A value the contract accepts is not reported, and takes effect.
//   * "Finite physics" gives finite results. The physics is finite while every accepted value
//     stays within bounds that make overflow impossible: position, velocity, acceleration and
//     force components |x| <= 1e4, inverse mass <= 1e4 (mass >= 1e-4, or infinite), damping
//     anything in [0, 1], steps 0 <= t <= 1 s, at most 4096 steps and 256 forces per input.
//     Then |a| <= 1e4 + 256 * 1e4 * 1e4 < 3e10, |v| <= 1e4 + 4096 * 3e10 < 2e14 and
//     |p| < 1e4 + 4096 * (2e14 + 3e10) < 1e18, far below float's 3.4e38: any non-finite
//     position or velocity is the library's fault. Outside the bounds an overflow to
//     infinity is the input's doing, and only the contracts (and the sanitizers) are checked.
//   * A ParticleSystem agrees with the same operations on scalar Particles (a mirror), bit
//     for bit, through step(), the step_particle path a GPU loop would run and step_range /
//     step_range_backward over any ranges (zeros are compared by value only once a system
//     without ForceAccumulator was given a -0 acceleration component: the scalar path adds a
//     zero force to the acceleration, which turns it into +0).
//   * The render hand-off (copy_positions(out, origin), any origin, any buffer length): the same
//     bits as position_relative_to of the system and of the mirror's particle, exact wherever
//     the true offset is a float, and nothing written past size() or when refused.
//
// Inputs starting with a byte in [0xF0, 0xF8) drive the force generators instead (see "force
// generators" below), 0xF8 and 0xF9 a ForceRegistry changed by its generators, from 0xFA
// systems with a user column that throws, also driven through a unit of the other checks
// setting (other_settings.cpp); a first byte in [0xE0, 0xF0) drives systems whose positions are stored
// wider than their arithmetic, double or compensated (see "positions stored wider" below).
//
// A failed check prints what failed and calls abort(), which libFuzzer reports as a crash
// with the input that caused it. Built with POINTMASS_ENABLE_CHECKS, so the hot-path
// contracts (integrate's duration, add_force's vector) are checked in every build type.
// Without libFuzzer, replay_main.cpp runs the same function over the corpus files.
#include <pointmass/forces.hpp>
#include <pointmass/particle.hpp>
#include <pointmass/particle_system.hpp>

#include <array>
#include <deque>
#include <span>

#include <charconv>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <string>
#include <tuple>
#include <type_traits>
#include <unordered_map>
#include <utility>
#include <vector>

#include "fuzz_shared.hpp"

namespace {

using namespace pointmass;

// --- what the handler saw -------------------------------------------------------------------

struct Report {
  int calls = 0;
  std::string function;
  std::string argument;
  std::string text;
  std::string message;
  std::string within;  // the latest report's many-valued call and element (spawn_burst)
  std::size_t element = 0;
};
Report report;

void record(const ContractViolation& violation) {
  ++report.calls;
  report.function = violation.function;
  report.argument = violation.argument;
  report.text = violation.text;
  report.message = describe(violation);
  report.within = violation.within != nullptr ? violation.within : "";
  report.element = violation.element;
}

[[noreturn]] void fail(const char* what, const char* detail = "") {
  std::fprintf(stderr, "fuzz check failed: %s %s\n", what, detail);
  std::abort();
}
void require(bool condition, const char* what, const char* detail = "") {
  if (!condition) fail(what, detail);
}

// --- reading the input ----------------------------------------------------------------------

class Input {
 public:
  Input(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}
  bool empty() const { return position_ >= size_; }
  std::uint8_t byte() { return position_ < size_ ? data_[position_++] : 0; }
  std::uint16_t word() { return static_cast<std::uint16_t>(byte() | (byte() << 8)); }

  /// Any value of R: raw bits, a special value, a physical value, a fraction, a tiny number.
  template <class R>
  R number() {
    using Bits = std::conditional_t<sizeof(R) == 4, std::uint32_t, std::uint64_t>;
    constexpr R special[] = {R(0),
                             -R(0),
                             R(1),
                             -R(1),
                             R(0.5),
                             std::numeric_limits<R>::infinity(),
                             -std::numeric_limits<R>::infinity(),
                             std::numeric_limits<R>::quiet_NaN(),
                             std::numeric_limits<R>::denorm_min(),
                             -std::numeric_limits<R>::denorm_min(),
                             std::numeric_limits<R>::min(),
                             std::numeric_limits<R>::max(),
                             -std::numeric_limits<R>::max(),
                             std::numeric_limits<R>::epsilon(),
                             R(1) - std::numeric_limits<R>::epsilon() / R(2),
                             R(1) + std::numeric_limits<R>::epsilon()};
    switch (byte() % 8) {
      case 0:
      case 1: {
        Bits bits = 0;
        for (std::size_t k = 0; k < sizeof(Bits); ++k) bits |= static_cast<Bits>(byte()) << (8 * k);
        R value;
        std::memcpy(&value, &bits, sizeof value);
        return value;
      }
      case 2: return special[byte() % (sizeof special / sizeof special[0])];
      case 3:
      case 4:
      case 5:  // -512 .. 512 in steps of 1/64
        return static_cast<R>(static_cast<std::int16_t>(word())) / R(64);
      case 6:  // [0, 1]
        return static_cast<R>(word()) / R(65535);
      default: {  // 2^-n, n up to the smallest subnormal
        constexpr int deepest =
            -std::numeric_limits<R>::min_exponent + std::numeric_limits<R>::digits;
        R value = R(1);
        for (int n = word() % (deepest + 1); n > 0; --n) value /= R(2);
        return value;
      }
    }
  }
  template <class R>
  Vector3<R> vector() {
    const R x = number<R>();
    const R y = number<R>();
    const R z = number<R>();
    return {x, y, z};
  }

 private:
  const std::uint8_t* data_;
  std::size_t size_;
  std::size_t position_ = 0;
};

// --- comparisons ----------------------------------------------------------------------------

template <class R>
bool identical(R a, R b) {                         // same bits exactly (or both NaN)
  if constexpr (std::is_same_v<R, long double>) {  // x87's 80 bits: padding is no part of it
    return (a != a && b != b) || (a == b && std::signbit(a) == std::signbit(b));
  } else {
    return (a != a && b != b) || std::memcmp(&a, &b, sizeof a) == 0;
  }
}
template <class R>
bool same(R a, R b) {  // same bits, or both zero, or both NaN
  return (a == R(0) && b == R(0)) || identical(a, b);
}
template <class R>
bool identical(const Vector3<R>& a, const Vector3<R>& b) {
  return identical(a.x, b.x) && identical(a.y, b.y) && identical(a.z, b.z);
}
template <class R>
bool same(const Vector3<R>& a, const Vector3<R>& b) {
  return same(a.x, b.x) && same(a.y, b.y) && same(a.z, b.z);
}

template <class T>
bool reads_back(const char* first, const char* last, T value) {
  T parsed{};
  const auto result = std::from_chars(first, last, parsed);
  if (result.ec != std::errc{} || result.ptr != last) return false;
  if constexpr (std::is_floating_point_v<T>) return identical(parsed, value);
  else return parsed == value;
}

// A buffer's length as a report gives it: "4 elements for size() = 9".
struct Length {
  std::size_t elements;
};

// The handler was called exactly once for (function, argument), and its text reads back as
// `value` (a number, "(x, y, z)", or a Length: the number before " elements for ").
template <class T>
void expect_rejected(const char* function, const char* argument, const T& value) {
  require(report.calls == 1, "rejected value not reported once:", function);
  require(report.function == function, "wrong function in report:", report.message.c_str());
  require(report.argument == argument, "wrong argument in report:", report.message.c_str());
  const std::string expected_start =
      std::string("pointmass: ") + function + ": argument '" + argument + "' = ";
  require(report.message.rfind(expected_start, 0) == 0, "message format:", report.message.c_str());
  const char* text = report.text.c_str();
  const char* end = text + report.text.size();
  if constexpr (is_vector3_v<T>) {
    // "(x, y, z)"
    require(report.text.size() > 2 && text[0] == '(' && end[-1] == ')', "vector text:", text);
    const char* first = text + 1;
    const typename T::value_type components[3] = {value.x, value.y, value.z};
    for (int k = 0; k < 3; ++k) {
      const char* stop = k < 2 ? std::strstr(first, ", ") : end - 1;
      require(stop != nullptr && reads_back(first, stop, components[k]),
              "vector value text:", text);
      first = stop + 2;
    }
  } else if constexpr (std::is_same_v<T, Length>) {
    const char* stop = std::strstr(text, " elements for ");
    require(stop != nullptr && reads_back(text, stop, value.elements),
            "length text does not read back:", text);
  } else {
    require(reads_back(text, end, value), "value text does not read back:", text);
  }
  report = {};
}
void expect_accepted(const char* function) {
  require(report.calls == 0, "accepted value reported:", function);
}

// --- bounds of finite physics ---------------------------------------------------------------

constexpr double bound = 1e4;  // position, velocity, acceleration, force components
constexpr double inverse_mass_bound = 1e4;
constexpr double step_bound = 1.0;  // seconds
constexpr int max_steps = 4096;
constexpr int max_forces = 256;

struct Budget {
  bool finite_physics = true;
  int steps = 0;
  int forces = 0;

  template <class R>
  void value(R x, double limit = bound) {
    if (!(static_cast<double>(x < R(0) ? -x : x) <= limit)) finite_physics = false;
  }
  template <class R>
  void vector(const Vector3<R>& v, double limit = bound) {
    value(v.x, limit), value(v.y, limit), value(v.z, limit);
  }
  void step(int count, double t) {
    steps += count;
    if (steps > max_steps || !(t <= step_bound)) finite_physics = false;
  }
  void force() {
    if (++forces > max_forces) finite_physics = false;
  }
};

template <class R>
bool finite(const Vector3<R>& v) {
  return is_finite(v);
}

template <class R>
bool mass_accepted(R m) {  // detail::check_mass's rule, written out
  if (!(m > R(0))) return false;
  const R inverse = R(1) / m;
  return inverse == R(0) || (real_isfinite(inverse) && inverse >= std::numeric_limits<R>::min());
}
template <class R>
bool inverse_mass_accepted(R im) {
  return im == R(0) || (real_isfinite(im) && im >= std::numeric_limits<R>::min());
}

// --- Particle -------------------------------------------------------------------------------

template <class Particle>
bool same_state(const Particle& a, const Particle& b) {
  return identical(a.position(), b.position()) && identical(a.velocity(), b.velocity()) &&
         identical(a.acceleration(), b.acceleration()) &&
         identical(a.force_accumulator(), b.force_accumulator()) &&
         identical(a.inverse_mass(), b.inverse_mass()) && identical(a.damping(), b.damping());
}

template <class R, class D, class P>
void fuzz_particle(Input& in) {
  using Body = Particle<R, D, P>;
  Body body;
  Budget budget;
  for (int op = 0; op < 200 && !in.empty(); ++op) {
    const Body before = body;
    bool rejected = false;
    switch (in.byte() % 10) {
      case 0: {
        const auto p = in.vector<R>();
        body.set_position(p);
        if ((rejected = !finite(p))) expect_rejected("set_position", "position", p);
        else require(identical(body.position(), p), "set_position did not take effect");
        budget.vector(p);
        break;
      }
      case 1: {
        const auto v = in.vector<R>();
        body.set_velocity(v);
        if ((rejected = !finite(v))) expect_rejected("set_velocity", "velocity", v);
        else require(identical(body.velocity(), v), "set_velocity did not take effect");
        budget.vector(v);
        break;
      }
      case 2: {
        const auto a = in.vector<R>();
        body.set_acceleration(a);
        if ((rejected = !finite(a))) expect_rejected("set_acceleration", "acceleration", a);
        else require(identical(body.acceleration(), a), "set_acceleration did not take effect");
        budget.vector(a);
        break;
      }
      case 3: {
        const R m = in.number<R>();
        body.set_mass(m);
        // Documented: mass > 0, not NaN, 1/mass finite and normal (infinity: immovable).
        rejected = !mass_accepted(m);
        if (rejected) {
          expect_rejected("set_mass", "mass", m);
        } else {
          require(identical(body.inverse_mass(), R(1) / m), "set_mass did not take effect");
          budget.value(R(1) / m, inverse_mass_bound);
        }
        break;
      }
      case 4: {
        const R im = in.number<R>();
        body.set_inverse_mass(im);
        rejected = !inverse_mass_accepted(im);  // 0, or finite, normal and > 0
        if (rejected) expect_rejected("set_inverse_mass", "inverse_mass", im);
        else require(identical(body.inverse_mass(), im), "set_inverse_mass did not take effect");
        if (!rejected) budget.value(im, inverse_mass_bound);
        break;
      }
      case 5: {
        if constexpr (Body::stores_damping) {
          const R d = in.number<R>();
          body.set_damping(d);
          rejected = d != d || d < R(0) || d > R(1);
          if (rejected) expect_rejected("set_damping", "damping", d);
          else require(identical(body.damping(), d), "set_damping did not take effect");
        }
        break;
      }
      case 6: {
        const auto f = in.vector<R>();
        body.add_force(f);
        if ((rejected = !finite(f))) {
          expect_rejected("add_force", "force", f);
        } else {
          budget.vector(f);
          budget.force();
        }
        break;
      }
      case 7:
      case 8:
      case 9: {
        const R t = in.number<R>();
        const int count = in.byte() % 17;
        for (int k = 0; k < (count == 0 ? 1 : count); ++k) {
          const Body start = body;
          body.integrate(t);
          rejected = !real_isfinite(t) || t < R(0);
          if (rejected) {
            expect_rejected("integrate", "duration", t);
            require(same_state(body, start), "rejected integrate changed the particle");
            break;
          }
          expect_accepted("integrate");
          if (!body.has_finite_mass()) {
            require(identical(body.position(), start.position()) &&
                        identical(body.velocity(), start.velocity()),
                    "an immovable particle moved");
          }
          if (t == R(0)) {  // a zero step, immovable or not (docs/numerics.md, "The model")
            require(same_state(body, start), "a zero step changed the particle");
          } else {
            require(identical(body.force_accumulator(), Vector3<R>{}), "accumulator not cleared");
          }
        }
        if (!rejected) budget.step(count == 0 ? 1 : count, static_cast<double>(t));
        break;
      }
      default: break;
    }
    if (rejected) {
      require(same_state(body, before), "a rejected call changed the particle");
    } else {
      expect_accepted("setter");
    }
    if (budget.finite_physics) {
      require(finite(body.position()) && finite(body.velocity()),
              "finite physics gave a non-finite particle");
    }
  }
}

// --- ParticleSystem, against a mirror of scalar Particles ------------------------------------
//
// Operation sequences on a system, each checked against a reference model (the mirror): a
// std::vector of the equivalent Particles, killed by the documented swap-remove, aged and
// expired by the documented rule (age >= lifetime, the age counted as Kahan's sum of the
// steps, and an infinite lifetime never expires).
// After every operation the system agrees with the mirror bit for bit: positions,
// velocities, accelerations, inverse masses, forces, damping, ages, lifetimes, and with
// features::Interpolation the previous positions (the stored position before the particle's
// last step, or as spawned or set since), which interpolated_position gives at alpha 0, as
// it gives the position at alpha 1. A damping set between two steps of one length takes
// effect on the second (the system keeps d^t from step to step). With features::Handles,
// every handle taken at a spawn (the latest 256) finds its particle's index while it lives
// and nothing once it has died, and handle(i) finds i; the user column (features::Column)
// holds what spawn or set_column gave the particle, T{} otherwise, through swap-removes and
// clear() (kill_if's mode 0xFF). The one
// documented exception (docs/numerics.md, "Determinism"): a Particle adds its zero force to
// its acceleration, turning a -0 acceleration component into +0, so once an input gives a
// configuration without ForceAccumulator a -0 acceleration, zeros are compared by value.
//
// The operations: spawn (a position and velocity, with a user column's value or without,
// or copies of particles), kill, kill_if, clear,
// every setter with any value and any index (huge ones too), every accessor with any index
// (an index >= size() is reported and changes nothing), step, the step_particle loop a
// device runs, step_range and step_range_backward over any [begin, end) (a range outside
// [0, size()] or reversed is reported and changes nothing), reserve with any count, copy,
// copy assignment, move, move assignment and swap with a second system.
//
// reserve with a count beyond max_size() throws std::length_error: checked where the target
// has exceptions (the libFuzzer build). The replay driver is built without exceptions, where
// the refusal reports and aborts (hardening.no-exceptions.aborts.reserve checks that), so
// there those counts are skipped. Counts between reserve_limit and max_size() would really
// allocate that much and are skipped everywhere (tests/test_system_contracts.cpp has the
// exception's message and the "changes nothing" of the refusal for the edge counts).

constexpr std::size_t max_particles = 1400;  // enough for step to alternate its walk
constexpr std::size_t reserve_limit = 4096;

// --- positions stored wider than the arithmetic (precision.hpp) -----------------------------
//
// The same operations drive systems whose positions are stored wider than R: a wider Real
// (Precision<float, double>) or Compensated<R> (hi + lo, two R). Positions then come from
// wide_number, which adds far positions with bits below R's precision and the edge of the
// storage's range, and the finite-physics bound for positions is wide_position_bound: from
// |p| <= 1e30 the displacements (< 1e18, as above) keep hi, lo and p finite in float. The
// position's own contract (docs/large-worlds.md, docs/numerics.md "Contracts"):
//
//   * accepted exactly when finite and, for Compensated<R>, no farther from 0 than the
//     midpoint between R's largest value and the next power of two (the most hi + lo
//     reaches); a refused one is reported naming the function and 'position', and changes
//     nothing, in the system and in a Particle;
//   * stored as documented: a wider Real keeps the value; Compensated<R> keeps hi = the value
//     rounded to R (R's largest, beyond it up to the midpoint) and lo = the rest rounded to R;
//   * every position() is taken back, by the system and by a Particle, and gives the same
//     position() again; spawn(particle) takes the particle's pair, lo included.

constexpr double wide_position_bound = 1e30;

template <class System>
inline constexpr bool plain_positions =
    std::is_same_v<typename System::position_value, typename System::real>;
template <class System>
inline constexpr bool compensated_positions =
    !std::is_same_v<typename System::position_element, typename System::position_value>;

/// R's largest value and the midpoint above it (between it and the next power of two), in W.
template <class W, class R>
W largest_of() {
  return static_cast<W>(std::numeric_limits<R>::max());
}
template <class W, class R>
W midpoint_above_largest() {
  const R largest = std::numeric_limits<R>::max();
  const W ulp = static_cast<W>(largest) - static_cast<W>(std::nextafter(largest, R(0)));
  return static_cast<W>(largest) + ulp / W(2);
}

/// A position component of W for arithmetic R: what number<R> gives, a double's raw bits and
/// special values, far positions with bits below R's precision, and the edge of R's range.
template <class W, class R>
W wide_number(Input& in) {
  using Near = std::conditional_t<sizeof(W) <= sizeof(double), W, double>;  // number<>'s types
  const W largest = largest_of<W, R>();
  const W midpoint = midpoint_above_largest<W, R>();
  const W half_ulp = midpoint - largest;
  const W sign = in.byte() % 2 == 0 ? W(1) : W(-1);
  switch (in.byte() % 6) {
    case 0: return static_cast<W>(in.number<R>());
    case 1: return static_cast<W>(in.number<Near>());
    case 2:
    case 3: {  // 1 to 2^128 m, with 48 significant bits
      const W fraction = W(1) + static_cast<W>(in.word()) / W(65536) +
                         static_cast<W>(in.word()) / W(65536) / W(65536) / W(65536);
      return sign * std::ldexp(fraction, in.byte() % 129);
    }
    case 4: {
      const W edge[] = {largest,
                        midpoint,
                        std::nextafter(midpoint, W(0)),
                        std::nextafter(midpoint, std::numeric_limits<W>::infinity()),
                        largest + half_ulp / W(2),
                        midpoint + half_ulp,
                        std::numeric_limits<W>::max(),
                        std::numeric_limits<W>::infinity()};
      return sign * edge[in.byte() % 8];
    }
    default:  // between R's largest and the midpoint, as a pair's hi + lo may be
      return sign * (largest + half_ulp * static_cast<W>(in.word()) / W(65535));
  }
}

/// A position for System: R's numbers where positions are stored as R (the inputs of the
/// corpus read as before), wide_number's where they are stored wider.
template <class System>
Vector3<typename System::position_value> position_vector(Input& in) {
  using R = typename System::real;
  using W = typename System::position_value;
  if constexpr (plain_positions<System>) {
    return in.vector<R>();
  } else {
    const W x = wide_number<W, R>(in);
    const W y = wide_number<W, R>(in);
    const W z = wide_number<W, R>(in);
    return {x, y, z};
  }
}

template <class System>
constexpr double position_bound = plain_positions<System> ? bound : wide_position_bound;

/// The setters' rule for a position (see above).
template <class System>
bool position_accepted(const Vector3<typename System::position_value>& p) {
  using W = typename System::position_value;
  if (!finite(p)) return false;
  if constexpr (compensated_positions<System>) {
    const W midpoint = midpoint_above_largest<W, typename System::real>();
    const auto within = [&](W x) { return (x < W(0) ? -x : x) <= midpoint; };
    return within(p.x) && within(p.y) && within(p.z);
  }
  return true;
}

/// hi and lo of a Compensated<R> position set to x.
template <class R, class W>
R expected_hi(W x) {
  const R largest = std::numeric_limits<R>::max();
  if (x > largest_of<W, R>()) return largest;
  if (x < -largest_of<W, R>()) return -largest;
  return static_cast<R>(x);
}
template <class R, class W>
R expected_lo(W x) {
  if (x == W(0)) return static_cast<R>(x);  // a zero is both parts: hi + lo keeps its sign
  return static_cast<R>(x - static_cast<W>(expected_hi<R>(x)));
}

/// Particle i of `system` stores the accepted position p as documented (see above).
template <class System>
void check_stored_position(const System& system, std::size_t i,
                           const Vector3<typename System::position_value>& p) {
  using R = typename System::real;
  const auto& a = pointmass::detail::SystemAccess::arrays(system);
  if constexpr (compensated_positions<System>) {
    const Vector3<R> hi{expected_hi<R>(p.x), expected_hi<R>(p.y), expected_hi<R>(p.z)};
    const Vector3<R> lo{expected_lo<R>(p.x), expected_lo<R>(p.y), expected_lo<R>(p.z)};
    require(identical(Vector3<R>{a.position_x[i], a.position_y[i], a.position_z[i]}, hi),
            "a compensated position's hi is not the position rounded");
    require(
        identical(Vector3<R>{a.position_error_x[i], a.position_error_y[i], a.position_error_z[i]},
                  lo),
        "a compensated position's lo is not the rest rounded");
  } else {
    require(identical(system.position(i), p), "a position was not stored as given");
  }
}
// The user column of the systems with the game features (features::Column<FuzzOwner, int>,
// or fuzz::Fuse, whose construction can throw).
using fuzz::FuzzOwner;
template <class System>
inline constexpr bool has_owner_column = System::template has<FuzzOwner>;

template <class System>
class Mirror {
 public:
  using R = typename System::real;
  using Body = typename System::particle_type;
  using E = typename System::position_element;
  using Handle = typename System::Handle;
  static constexpr std::size_t max_handles = 256;

  std::vector<Body> bodies;
  std::vector<R> ages;
  std::vector<R> age_errors;  // the age is ages + age_errors, Kahan's sum of the steps
  std::vector<R> lifetimes;
  // features::Interpolation: each particle's stored position before its last step, or as
  // spawned or set since (a jump, not a motion to draw).
  std::vector<Vector3<E>> previous;
  // Each particle's serial number (never reused), and its value in the user column (T{} as
  // spawned without one, and after spawn(particle)).
  std::vector<std::uint64_t> serials;
  std::vector<int> owners;
  std::uint64_t next_serial = 0;
  // features::Handles: handles taken at spawn (the latest max_handles), each with the serial
  // of the particle it names: find() gives that particle's index while it lives, else nothing.
  std::vector<std::pair<Handle, std::uint64_t>> handles;
  std::size_t handles_taken = 0;
  Vector3<R> acceleration{};
  R damping = R(1);
  bool zero_signs_may_differ = false;  // a -0 acceleration without ForceAccumulator

  std::size_t size() const { return bodies.size(); }

  void push(const Body& body, int owner = 0) {
    bodies.push_back(body);
    ages.push_back(R(0));
    age_errors.push_back(R(0));
    lifetimes.push_back(std::numeric_limits<R>::infinity());
    previous.push_back(body.stored_position());
    serials.push_back(next_serial++);
    owners.push_back(owner);
  }
  /// A user-column value for the particle with this serial (one per serial, so that a
  /// swap-remove moving the wrong value shows).
  static int owner_for(std::uint64_t serial) { return static_cast<int>(serial % 100003) + 1; }
  void track(const Handle& handle, std::size_t i) {
    const std::pair<Handle, std::uint64_t> entry{handle, serials[i]};
    if (handles.size() < max_handles) handles.push_back(entry);
    else handles[handles_taken % max_handles] = entry;
    ++handles_taken;
  }
  template <class Position>
  void set_position(std::size_t i, const Vector3<Position>& p) {
    bodies[i].set_position(p);
    previous[i] = bodies[i].stored_position();
  }
  template <class Position>
  void spawn(const Vector3<Position>& p, const Vector3<R>& v, int owner = 0) {
    Body body;
    body.set_position(p);
    body.set_velocity(v);
    if constexpr (!System::template has<pointmass::features::PerParticleAcceleration>)
      body.set_acceleration(acceleration);
    if constexpr (System::stores_damping &&
                  !System::template has<pointmass::features::PerParticleDamping>)
      body.set_damping(damping);
    push(body, owner);
  }
  void kill(std::size_t i) {  // swap-remove
    bodies[i] = bodies.back();
    ages[i] = ages.back();
    age_errors[i] = age_errors.back();
    lifetimes[i] = lifetimes.back();
    previous[i] = previous.back();
    serials[i] = serials.back();
    owners[i] = owners.back();
    bodies.pop_back();
    ages.pop_back();
    age_errors.pop_back();
    lifetimes.pop_back();
    previous.pop_back();
    serials.pop_back();
    owners.pop_back();
  }
  void note_acceleration(const Vector3<R>& a) {
    if constexpr (!System::template has<pointmass::features::ForceAccumulator>) {
      const auto negative_zero = [](R x) { return x == R(0) && std::signbit(x); };
      if (negative_zero(a.x) || negative_zero(a.y) || negative_zero(a.z))
        zero_signs_may_differ = true;
    }
  }
  void integrate(std::size_t i, R t) {
    previous[i] = bodies[i].stored_position();
    bodies[i].integrate(t);
    const R step = t + age_errors[i];
    const R sum = ages[i] + step;
    age_errors[i] = step - (sum - ages[i]);
    ages[i] = sum;
  }
  // The age as age(i) reports it (NaN once the count overflowed: infinity).
  [[nodiscard]] R age(std::size_t i) const {
    const R sum = ages[i] + age_errors[i];
    return std::isnan(sum) ? std::numeric_limits<R>::infinity() : sum;
  }
  static bool expired(R age, R lifetime) {
    return age >= lifetime && lifetime != std::numeric_limits<R>::infinity();
  }
  void expire() {
    if constexpr (System::template has<pointmass::features::Lifetime>) {
      std::size_t i = 0;
      while (i < bodies.size()) {
        if (expired(age(i), lifetimes[i])) kill(i);
        else ++i;
      }
    }
  }
  void step(R t) {  // ParticleSystem::step's documented effect
    if (t == R(0) || bodies.empty()) return;
    for (std::size_t i = 0; i < bodies.size(); ++i) integrate(i, t);
    expire();
  }
};

template <class System>
std::size_t immortals(const System& system) {  // particles whose lifetime is infinite
  std::size_t count = 0;
  if constexpr (System::template has<pointmass::features::Lifetime>) {
    for (std::size_t i = 0; i < system.size(); ++i) {
      count += system.lifetime(i) == std::numeric_limits<typename System::real>::infinity();
    }
  }
  return count;
}

template <class System>
void compare(const System& system, const Mirror<System>& mirror, const Budget& budget) {
  using R = typename System::real;
  require(system.size() == mirror.size(), "system and mirror differ in size");
  require(pointmass::detail::SystemAccess::arrays(system).size == system.size(),
          "arrays().size differs from size()");
  require(system.capacity() >= system.size(), "capacity below size");
  require(system.template column<pointmass::Column::position_x>().size() == system.size() &&
              system.template column<pointmass::Column::velocity_z>().size() == system.size(),
          "a span's size differs from size()");
  const bool exact = !mirror.zero_signs_may_differ;
  const auto agree = [exact](const auto& a, const auto& b) {
    return exact ? identical(a, b) : same(a, b);
  };
  for (std::size_t i = 0; i < system.size(); ++i) {
    const auto& body = mirror.bodies[i];
    const auto p = system.position(i);
    require(agree(p, body.position()), "system position differs from Particle");
    require(agree(system.velocity(i), body.velocity()), "system velocity differs from Particle");
    require(
        identical(system.template column<pointmass::Column::velocity_y>()[i], system.velocity(i).y),
        "a span differs from the accessor");
    if constexpr (plain_positions<System>) {
      require(identical(system.template column<pointmass::Column::position_x>()[i], p.x),
              "a span differs from the accessor");
    } else {  // the stored numbers too: the pair's hi and lo, or the wide value
      const auto& a = pointmass::detail::SystemAccess::arrays(system);
      const auto stored = body.stored_position();
      require(agree(a.position_x[i], stored.x) && agree(a.position_y[i], stored.y) &&
                  agree(a.position_z[i], stored.z) &&
                  identical(system.template column<pointmass::Column::position_x>()[i],
                            a.position_x[i]),
              "a system's stored position differs from Particle");
      if constexpr (compensated_positions<System>) {
        const auto error = body.stored_position_error();
        require(agree(a.position_error_x[i], error.x) && agree(a.position_error_y[i], error.y) &&
                    agree(a.position_error_z[i], error.z),
                "a system's position error differs from Particle");
      }
    }
    require(identical(system.acceleration(i), body.acceleration()), "acceleration differs");
    if constexpr (System::template has<pointmass::features::ForceAccumulator>) {
      require(identical(system.force_accumulator(i), body.force_accumulator()), "force differs");
      require(identical(system.inverse_mass(i), body.inverse_mass()), "inverse mass differs");
    }
    if constexpr (System::template has<pointmass::features::Lifetime>) {
      require(identical(system.age(i), mirror.age(i)), "age differs");
      require(identical(system.lifetime(i), mirror.lifetimes[i]), "lifetime differs");
    }
    require(identical(system.damping(i), body.damping()), "damping differs");
    if constexpr (has_owner_column<System>) {
      require(system.template column<FuzzOwner>(i) == mirror.owners[i], "user column differs");
    }
    if constexpr (System::template has<pointmass::features::Handles>) {
      const auto found = system.find(system.handle(i));
      require(found.has_value() && *found == i, "a live particle's handle does not find it");
    }
    if constexpr (System::template has<pointmass::features::Interpolation>) {
      const auto before = system.previous_position(i);
      require(agree(before, mirror.previous[i]), "previous position differs");
      // alpha 0 and 1: the previous and the current position columns, bit for bit
      require(identical(system.interpolated_position(i, R(0)), before),
              "interpolated_position at alpha 0 is not the previous position");
      if constexpr (!compensated_positions<System>) {
        require(identical(system.interpolated_position(i, R(1)), p),
                "interpolated_position at alpha 1 is not the position");
      }
    }
    if (budget.finite_physics) {
      require(finite(system.position(i)) && finite(system.velocity(i)),
              "finite physics gave a non-finite system particle");
    }
  }
  if constexpr (System::template has<pointmass::features::Handles>) {
    // Every handle taken finds the particle it named while it lives, and nothing after.
    std::unordered_map<std::uint64_t, std::size_t> index_of;
    for (std::size_t i = 0; i < mirror.size(); ++i) index_of.emplace(mirror.serials[i], i);
    for (const auto& [handle, serial] : mirror.handles) {
      const auto found = system.find(handle);
      const auto alive = index_of.find(serial);
      if (alive == index_of.end()) {
        require(!found.has_value() && !system.contains(handle),
                "a dead particle's handle finds one");
      } else {
        require(found.has_value() && *found == alive->second && system.contains(handle),
                "a handle does not find its particle");
      }
    }
  }
  expect_accepted("an accessor with a valid index");
}

/// An index: mostly a live one, sometimes just past the end, sometimes huge.
std::size_t pick_index(Input& in, std::size_t size) {
  std::size_t index = in.byte();
  if (index >= 248) {
    constexpr std::size_t max = std::numeric_limits<std::size_t>::max();
    constexpr std::size_t half_width = std::size_t{1}
                                       << (std::numeric_limits<std::size_t>::digits / 2);
    const std::size_t special[] = {size,        size + 1,   max,       max - 1,
                                   max / 2 + 1, half_width, size + 64, 255};
    index = special[index - 248];
  } else if (index < 200 && size != 0) {
    index %= size;
  }
  return index;
}

/// A bound of a range: mostly within [0, size], sometimes beyond.
std::size_t pick_bound(Input& in, std::size_t size) {
  const std::uint8_t b = in.byte();
  if (b < 224) return b % (size + 1);
  constexpr std::size_t max = std::numeric_limits<std::size_t>::max();
  const std::size_t special[] = {size + 1, size + 16, size + 257, max, max - 1, max / 2, 0, size};
  return special[b % 8];
}

/// A count for reserve: small, moderate, huge (at and around max_size()), or any 64 bits.
template <class System>
std::size_t pick_count(Input& in) {
  constexpr std::size_t max = std::numeric_limits<std::size_t>::max();
  switch (in.byte() % 4) {
    case 0: return in.byte();
    case 1: return in.word() % (reserve_limit + 1);
    case 2: {
      const std::size_t special[] = {
          System::max_size() + 1,
          System::max_size() + 2,
          max,
          max - 1,
          max / 2,
          max / System::storage_bytes_per_particle + 1,
          max / pointmass::detail::SystemAccess::Layout<System>::array_count + 1,
          max - 4095,
          2 * System::max_size(),
          (max >> 1) + 1};
      return special[in.byte() % (sizeof special / sizeof special[0])];
    }
    default: {
      std::size_t count = 0;
      for (int k = 0; k < 8; ++k) count |= static_cast<std::size_t>(in.byte()) << (8 * k);
      return count;
    }
  }
}

/// A decision about a particle that depends on its state only (zeros and NaNs canonical, so
/// the system and the mirror decide alike), for kill_if.
template <class W, class R>
bool doomed(const Vector3<W>& p, const Vector3<R>& v, std::uint8_t mode) {
  if (mode % 8 == 7) return true;
  std::uint64_t hash = 1469598103934665603u ^ mode;
  // A wide position decides by its value rounded to R (the same in the system and a mirror).
  for (R x : {static_cast<R>(p.x), static_cast<R>(p.y), static_cast<R>(p.z), v.x, v.y, v.z}) {
    if (x == R(0)) x = R(0);
    if (x != x) x = std::numeric_limits<R>::quiet_NaN();
    std::conditional_t<sizeof(R) == 4, std::uint32_t, std::uint64_t> bits;
    std::memcpy(&bits, &x, sizeof bits);
    hash = (hash ^ bits) * 1099511628211u;
  }
  hash ^= hash >> 31;  // mixed, so that every bit depends on the whole state
  hash *= 0xbf58476d1ce4e5b9u;
  hash ^= hash >> 29;
  return (hash >> 32) % 4 < mode % 4;  // mode 0: none, 3: about three in four
}

// Exact in long double: is p - origin's exact value a float? Then every road must return it.
bool exact_float_offset(long double p, long double origin, float& offset) {
  const long double a = p, b = -origin;
  const long double s = a + b;
  const long double bb = s - a;
  if ((a - (s - bb)) + (b - bb) != 0.0L) return false;  // s is not the exact difference
  offset = static_cast<float>(s);
  return static_cast<long double>(offset) == s;
}

// Component k of particle i's stored position, exactly, when long double holds it (a
// compensated pair's hi + lo may need more digits).
template <class System>
bool exact_position(const System& system, std::size_t i, int k, long double& value) {
  using E = typename System::position_element;
  const auto& a = pointmass::detail::SystemAccess::arrays(system);
  const E* const stored[3] = {a.position_x, a.position_y, a.position_z};
  const long double hi = static_cast<long double>(stored[k][i]);
  value = hi;
  if constexpr (compensated_positions<System>) {
    const E* const errors[3] = {a.position_error_x, a.position_error_y, a.position_error_z};
    const long double lo = static_cast<long double>(errors[k][i]);
    value = hi + lo;
    const long double back = value - hi;
    return (hi - (value - back)) + (lo - back) == 0.0L;  // TwoSum: no error, value is exact
  }
  return true;
}

// copy_positions(out, origin) with any origin (non-finite ones included; or one near a particle,
// the usual camera) into a buffer of any length: refused with nothing written, or every offset the same bits as position_relative_to
// of the system and of the mirror's particle, exact where the true offset is a float, and
// nothing written past size().
template <class System, class M>
void check_positions_relative_to(const System& system, const M& mirror, Input& in) {
  using W = typename System::position_value;
  const std::uint8_t mode = in.byte();
  Vector3<W> origin = position_vector<System>(in);
  if (mode % 2 == 1 && system.size() != 0) {  // a camera near particle j: the offset read
    const Vector3<W> p = system.position(std::size_t{mode} / 2 % system.size());
    origin = {p.x - origin.x, p.y - origin.y, p.z - origin.z};
  }
  const std::size_t length = in.byte() % 64;
  const Vector3<float> untouched{7.0f, -7.0f, 7.0f};
  std::vector<Vector3<float>> buffer(length, untouched);
  system.copy_positions(std::span<Vector3<float>>(buffer), origin);
  const std::size_t n = system.size();
  if (!finite(origin) || length < n) {
    if (!finite(origin)) expect_rejected("copy_positions", "origin", origin);
    else expect_rejected("copy_positions", "out", Length{length});
    for (const auto& b : buffer) require(identical(b, untouched), "a refused hand-off wrote");
    return;
  }
  expect_accepted("copy_positions");
  for (std::size_t i = 0; i < n; ++i) {
    require(identical(buffer[i], system.position_relative_to(i, origin)),
            "batch offset differs from the system's single one");
    require(identical(buffer[i], mirror.bodies[i].position_relative_to(origin)),
            "batch offset differs from the particle's");
    const W os[3] = {origin.x, origin.y, origin.z};
    const float got[3] = {buffer[i].x, buffer[i].y, buffer[i].z};
    for (int k = 0; k < 3; ++k) {
      float exact = 0.0f;
      long double p = 0.0L;
      if (exact_position(system, i, k, p) &&
          exact_float_offset(p, static_cast<long double>(os[k]), exact)) {
        require(same(got[k], exact), "an offset that is a float came out inexact");
      }
    }
  }
  expect_accepted("position_relative_to");
  for (std::size_t i = n; i < length; ++i) {
    require(identical(buffer[i], untouched), "the hand-off wrote past size()");
  }
}

// --- spawns whose user column throws, and the other checks setting --------------------------
//
// The systems chosen by a first byte from 0xFA (ExtendedConfigs below) have a user column
// fuzz::Fuse whose construction throws where the input asks (with exceptions only; without,
// the same operations spawn normally), and two more operations:
//
//   * spawn(p, v) (its T{} throws), spawn(p, v, seed) (converting the seed throws),
//     spawn(particle) (T{} throws) and spawn_burst (particle k's column throws, its T{} or its
//     seed): a refused input is reported as ever (validation comes first); a spawn that throws
//     adds nothing: size, every column, every handle and the next handle issued as before
//     (docs/particle-system.md); a burst that throws removes its particles, whose handles then
//     find nothing (particle_system.hpp, spawn_burst). A burst's refused particles are
//     reported naming spawn_burst and their element, and skipped.
//   * the same system driven through other_settings.cpp, built with the checks off: spawns,
//     kills, setters and steps (valid durations only: an unchecked step's bad duration is the
//     caller's fault) must agree with the model, and that unit reads every particle as this
//     one does.

constexpr bool fuses_blow = POINTMASS_HAS_EXCEPTIONS != 0;

/// Runs `attempt`; true when it threw fuzz::FuseBlown (never without exceptions).
template <class Attempt>
bool blows(const Attempt& attempt) {
#if POINTMASS_HAS_EXCEPTIONS
  try {
    attempt();
  } catch (const fuzz::FuseBlown&) {
    fuzz::fuse_refuses = false;
    return true;
  }
#else
  attempt();
#endif
  fuzz::fuse_refuses = false;
  return false;
}

/// A spawn that threw left `system` as `before` was: the next handle issued is the same too.
template <class System>
void expect_unchanged_by_throw(const System& system, const System& before) {
  require(system.size() == before.size(), "a spawn that threw changed size()");
  if constexpr (System::template has<pointmass::features::Handles>) {
    using W = typename System::position_value;
    using R = typename System::real;
    System probe = system;
    System expected = before;
    const auto h = probe.spawn_handle(Vector3<W>{}, Vector3<R>{});
    const auto g = expected.spawn_handle(Vector3<W>{}, Vector3<R>{});
    require(h == g, "a spawn that threw took a handle slot");
  }
}

template <class System>
void fuzz_throwing_spawn(System& system, Mirror<System>& mirror, Budget& budget, Input& in,
                         std::size_t index) {
  using R = typename System::real;
  using W = typename System::position_value;
  const std::uint8_t how = in.byte();
  const bool refuse = (how & 4) != 0;  // the column's construction throws
  const auto p = position_vector<System>(in);
  const auto v = in.vector<R>();
  if (system.size() + 16 > max_particles) return;
  const System before = system;
  const auto track_new = [&](std::size_t first) {
    for (std::size_t i = first; i < system.size(); ++i) {
      if constexpr (System::template has<pointmass::features::Handles>)
        mirror.track(system.handle(i), i);
    }
  };
  if (how % 4 != 3) {  // one spawn
    const int owner = how % 4 == 1 ? Mirror<System>::owner_for(mirror.next_serial) : 0;
    typename System::particle_type body;
    const bool copy = how % 4 == 2 && mirror.size() != 0;
    if (copy) body = mirror.bodies[index % mirror.size()];
    const Vector3<W> q = copy ? body.position() : p;
    const Vector3<R> u = copy ? body.velocity() : v;
    std::size_t i = System::npos;
    const bool threw = blows([&] {
      if (how % 4 == 1) {
        i = system.spawn(p, v, fuzz::FuzzSeed{owner, refuse});
      } else {
        fuzz::fuse_refuses = refuse;
        i = copy ? system.spawn(body) : system.spawn(p, v);
      }
    });
    if (!position_accepted<System>(q) || !finite(u)) {  // validated before any column is made
      require(!threw && i == System::npos, "a refused spawn threw or returned an index");
      if (!position_accepted<System>(q)) expect_rejected("spawn", "position", q);
      else expect_rejected("spawn", "velocity", u);
    } else if (refuse && fuses_blow) {
      require(threw, "a column that throws did not stop the spawn");
      expect_unchanged_by_throw(system, before);
    } else {
      require(!threw && i == mirror.size(), "spawn index");
      if (copy) mirror.push(body);
      else mirror.spawn(p, v, owner);
      track_new(i);
      budget.vector(q, position_bound<System>);
      budget.vector(u);
    }
    return;
  }
  // spawn_burst: particle k at p moved by k, with a seed (given) or T{}; fail_at's throws
  const std::size_t count = in.byte() % 16;
  const std::size_t fail_at = refuse ? in.byte() % (count + 1) : count;
  const bool given = (how & 8) != 0;
  const auto at = [&](std::size_t k) { return Vector3<W>{p.x + static_cast<W>(k), p.y, p.z}; };
  const auto accepted = [&](std::size_t k) {
    return position_accepted<System>(at(k)) && finite(v);
  };
  const bool throws = fuses_blow && fail_at < count && accepted(fail_at);
  using Handle = typename System::Handle;
  std::vector<Handle> made;  // the handles of this burst's particles, as they are added
  std::size_t asked = 0;
  const auto note_made = [&] {
    if constexpr (System::template has<pointmass::features::Handles>) {
      if (system.size() > before.size() + made.size())
        made.push_back(system.handle(system.size() - 1));
    }
  };
  const std::uint64_t serial = mirror.next_serial;  // particle k's value: owner_for(serial + k)
  std::size_t added = 0;
  const bool threw = blows([&] {
    if (given) {
      added = system.spawn_burst(count, [&](std::size_t k) {
        require(k == asked++, "spawn_burst asked for its elements out of order");
        note_made();
        const int owner = Mirror<System>::owner_for(serial + k);
        return std::tuple(at(k), v, fuzz::FuzzSeed{owner, k == fail_at});
      });
    } else {
      added = system.spawn_burst(count, [&](std::size_t k) {
        require(k == asked++, "spawn_burst asked for its elements out of order");
        note_made();
        fuzz::fuse_refuses = k == fail_at;
        return std::tuple(at(k), v);
      });
    }
  });
  const std::size_t reached = throws ? fail_at : count;  // the elements spawned or refused
  std::size_t refused = 0;
  std::size_t last_refused = 0;
  for (std::size_t k = 0; k < reached; ++k) {
    if (!accepted(k)) ++refused, last_refused = k;
  }
  require(report.calls == static_cast<int>(refused), "spawn_burst's refusals not reported once");
  if (refused != 0) {
    require(report.function == "spawn" && report.within == "spawn_burst" &&
                report.element == last_refused,
            "a burst's refusal does not name spawn_burst and its element:", report.message.c_str());
  }
  report = {};
  if (throws) {
    require(threw, "a burst whose column throws did not throw");
    require(system.size() == before.size(), "a burst that threw left particles");
    for (const auto& h : made) {
      if constexpr (System::template has<pointmass::features::Handles>)
        require(!system.contains(h), "a particle of a burst that threw is still found");
    }
    return;
  }
  require(!threw && added == count - refused, "spawn_burst's count");
  const std::size_t first = mirror.size();
  for (std::size_t k = 0; k < count; ++k) {
    if (!accepted(k)) continue;
    mirror.spawn(at(k), v, given ? Mirror<System>::owner_for(serial + k) : 0);
    budget.vector(at(k), position_bound<System>);
  }
  budget.vector(v);
  track_new(first);
}

template <class System>
void fuzz_other_settings(System& system, Mirror<System>& mirror, Budget& budget, Input& in,
                         std::size_t index) {
  using R = typename System::real;
  using Other = fuzz::OtherSettings<System>;
  const bool valid_index = index < system.size();
  const std::uint8_t what = in.byte();
  switch (what % 7) {
    case 0:
    case 1: {  // spawn, without a value or with one
      const auto p = position_vector<System>(in);
      const auto v = in.vector<R>();
      if (system.size() >= max_particles) break;
      const int owner = what % 7 == 1 ? Mirror<System>::owner_for(mirror.next_serial) : 0;
      const std::size_t i =
          owner != 0 ? Other::spawn(system, p, v, owner) : Other::spawn(system, p, v);
      if (!position_accepted<System>(p) || !finite(v)) {
        require(i == System::npos, "rejected spawn returned an index");
        if (!position_accepted<System>(p)) expect_rejected("spawn", "position", p);
        else expect_rejected("spawn", "velocity", v);
      } else {
        require(i == mirror.size(), "spawn index (other settings)");
        mirror.spawn(p, v, owner);
        if constexpr (System::template has<pointmass::features::Handles>)
          mirror.track(system.handle(i), i);
        budget.vector(p, position_bound<System>);
        budget.vector(v);
      }
      break;
    }
    case 2:
      Other::kill(system, index);
      if (!valid_index) expect_rejected("kill", "index", index);
      else mirror.kill(index);
      break;
    case 3: {
      const auto v = in.vector<R>();
      Other::set_velocity(system, index, v);
      if (!valid_index) expect_rejected("set_velocity", "index", index);
      else if (!finite(v)) expect_rejected("set_velocity", "velocity", v);
      else mirror.bodies[index].set_velocity(v), budget.vector(v);
      break;
    }
    case 4: {
      const int owner = -static_cast<int>(what) - 1;
      Other::set_column(system, index, owner);
      if (!valid_index) expect_rejected("set_column", "index", index);
      else mirror.owners[index] = owner;
      break;
    }
    default: {  // a step, or the step_particle loop (a valid duration: unchecked there)
      const R t = in.number<R>();
      if (!real_isfinite(t) || t < R(0)) break;
      if (what % 7 == 5) Other::step(system, t);
      else Other::step_particles(system, t);
      mirror.step(t);
      budget.step(1, static_cast<double>(t));
      break;
    }
  }
  // The other unit reads every particle as this one does.
  require(Other::size(system) == system.size(), "the other settings read another size()");
  for (std::size_t i = 0; i < system.size(); ++i) {
    const auto read = Other::read(system, i);
    require(identical(read.position, system.position(i)) &&
                identical(read.velocity, system.velocity(i)) &&
                read.owner == system.template column<FuzzOwner>(i).value &&
                read.handle == system.handle(i),
            "the other settings read a particle differently");
  }
}

// Extended: the two operations above too (codes % 25 of 23 and 24); the other systems read
// codes % 23, as the corpus was written.
template <class System, bool Extended = false>
void fuzz_system(Input& in) {
  using R = typename System::real;
  constexpr unsigned operations = Extended ? 25 : 23;
  System system(in.byte() % 40);
  Mirror<System> mirror;
  System other;  // the other side of swaps
  Mirror<System> other_mirror;
  Budget budget;
  for (int op = 0; op < 200 && !in.empty(); ++op) {
    const std::uint8_t code = in.byte();
    const std::size_t index = pick_index(in, system.size());
    const bool valid_index = index < system.size();
    const std::size_t immortal = immortals(system);
    bool stepped = false;  // the operation stepped: no particle with an infinite lifetime may go
    const unsigned operation = code % operations;
    switch (operation) {
      case 0:
      case 1: {
        const auto p = position_vector<System>(in);
        const auto v = in.vector<R>();
        if (system.size() >= max_particles) break;
        // code 1 gives the user column (if any) a value of its own; code 0 leaves it T{}
        int owner = 0;
        std::size_t i = 0;
        if constexpr (has_owner_column<System>) {
          if (operation == 1) owner = Mirror<System>::owner_for(mirror.next_serial);
          i = owner != 0 ? system.spawn(p, v, owner) : system.spawn(p, v);
        } else {
          i = system.spawn(p, v);
        }
        if (!position_accepted<System>(p)) {
          expect_rejected("spawn", "position", p);
          require(i == System::npos, "rejected spawn returned an index");
        } else if (!finite(v)) {
          expect_rejected("spawn", "velocity", v);
          require(i == System::npos, "rejected spawn returned an index");
        } else {
          expect_accepted("spawn");
          require(i == mirror.size(), "spawn index");
          check_stored_position(system, i, p);
          mirror.spawn(p, v, owner);
          if constexpr (System::template has<pointmass::features::Handles>)
            mirror.track(system.handle(i), i);
          budget.vector(p, position_bound<System>);
          budget.vector(v);
        }
        break;
      }
      case 2: {
        system.kill(index);
        if (!valid_index) expect_rejected("kill", "index", index);
        else mirror.kill(index);
        break;
      }
      case 3: {
        const auto p = position_vector<System>(in);
        system.set_position(index, p);
        if (!valid_index) {
          expect_rejected("set_position", "index", index);
        } else if (!position_accepted<System>(p)) {
          expect_rejected("set_position", "position", p);
          auto body = mirror.bodies[index];  // a Particle refuses it too, and keeps its state
          body.set_position(p);
          expect_rejected("set_position", "position", p);
          require(same_state(body, mirror.bodies[index]), "a refused position changed a Particle");
        } else {
          check_stored_position(system, index, p);
          mirror.set_position(index, p);
          budget.vector(p, position_bound<System>);
          if constexpr (!plain_positions<System>) {  // every position() is taken back
            const auto q = system.position(index);
            system.set_position(index, q);
            expect_accepted("set_position(i, position(i))");
            require(identical(system.position(index), q), "set_position(i, position(i)) moved it");
            auto& body = mirror.bodies[index];
            const auto r = body.position();
            body.set_position(r);
            expect_accepted("Particle::set_position(position())");
            require(identical(body.position(), r), "set_position(position()) moved a Particle");
          }
        }
        break;
      }
      case 4: {
        const auto v = in.vector<R>();
        system.set_velocity(index, v);
        if (!valid_index) expect_rejected("set_velocity", "index", index);
        else if (!finite(v)) expect_rejected("set_velocity", "velocity", v);
        else mirror.bodies[index].set_velocity(v), budget.vector(v);
        break;
      }
      case 5: {
        const auto a = in.vector<R>();
        if constexpr (System::template has<pointmass::features::PerParticleAcceleration>) {
          system.set_acceleration(index, a);
          if (!valid_index) {
            expect_rejected("set_acceleration", "index", index);
          } else if (!finite(a)) {
            expect_rejected("set_acceleration", "acceleration", a);
          } else {
            mirror.bodies[index].set_acceleration(a);
            mirror.note_acceleration(a);
            budget.vector(a);
          }
        } else {
          system.set_acceleration(a);
          if (!finite(a)) {
            expect_rejected("set_acceleration", "acceleration", a);
          } else {
            mirror.acceleration = a;
            for (auto& body : mirror.bodies) body.set_acceleration(a);
            mirror.note_acceleration(a);
            budget.vector(a);
          }
        }
        break;
      }
      case 6: {
        if constexpr (System::stores_damping) {
          const R d = in.number<R>();
          const bool bad = d != d || d < R(0) || d > R(1);
          if constexpr (System::template has<pointmass::features::PerParticleDamping>) {
            system.set_damping(index, d);
            if (!valid_index) expect_rejected("set_damping", "index", index);
            else if (bad) expect_rejected("set_damping", "damping", d);
            else mirror.bodies[index].set_damping(d);
          } else {
            system.set_damping(d);
            if (bad) {
              expect_rejected("set_damping", "damping", d);
            } else {
              mirror.damping = d;
              for (auto& body : mirror.bodies) body.set_damping(d);
            }
          }
        }
        break;
      }
      case 7: {
        if constexpr (System::template has<pointmass::features::ForceAccumulator>) {
          const R m = in.number<R>();
          system.set_mass(index, m);
          if (!valid_index) {
            expect_rejected("set_mass", "index", index);
          } else if (!mass_accepted(m)) {
            expect_rejected("set_mass", "mass", m);
          } else {
            mirror.bodies[index].set_mass(m);
            require(identical(system.inverse_mass(index), R(1) / m),
                    "set_mass did not take effect");
            budget.value(R(1) / m, inverse_mass_bound);
          }
        }
        break;
      }
      case 8: {
        if constexpr (System::template has<pointmass::features::ForceAccumulator>) {
          const auto f = in.vector<R>();
          system.add_force(index, f);
          if (!valid_index) {
            expect_rejected("add_force", "index", index);
          } else if (!finite(f)) {
            expect_rejected("add_force", "force", f);
          } else {
            mirror.bodies[index].add_force(f);
            budget.vector(f);
            budget.force();
          }
        }
        break;
      }
      case 9: {
        if constexpr (System::template has<pointmass::features::Lifetime>) {
          const R seconds = in.number<R>();
          system.set_lifetime(index, seconds);
          if (!valid_index) expect_rejected("set_lifetime", "index", index);
          else if (seconds != seconds || !(seconds > R(0)))
            expect_rejected("set_lifetime", "seconds", seconds);
          else mirror.lifetimes[index] = seconds;
        }
        break;
      }
      case 10: {  // the step_particle path, as a GPU loop runs it
        const R t = in.number<R>();
        if (!real_isfinite(t) || t < R(0)) break;
        if (auto view = system.begin_step(t)) {
          for (std::size_t i = 0; i < view.size(); ++i) view.step_particle(i);
          system.finish_step(std::move(view));
        }
        mirror.step(t);
        budget.step(1, static_cast<double>(t));
        stepped = true;
        break;
      }
      case 11: {  // a copy steps as the original does
        System copy = system;
        const R t = in.number<R>();
        if (!real_isfinite(t) || t < R(0)) break;
        copy.step(t);
        system.step(t);
        require(copy.size() == system.size(), "copy stepped to another size");
        for (std::size_t i = 0; i < system.size(); ++i) {
          require(identical(copy.position(i), system.position(i)) &&
                      identical(copy.velocity(i), system.velocity(i)),
                  "copy stepped differently");
        }
        mirror.step(t);
        budget.step(1, static_cast<double>(t));
        stepped = true;
        break;
      }
      case 22: {
        if ((code / 23) % 2 == 1) {  // the positions relative to any origin, into any buffer
          check_positions_relative_to(system, mirror, in);
          break;
        }
        // copy-out into a buffer of any length with any stride, huge ones included
        const std::size_t length = in.byte() % 64;
        const std::uint8_t kind = in.byte();
        const std::size_t stride = kind % 3 == 0   ? std::size_t{kind} % 8
                                   : kind % 3 == 1 ? std::numeric_limits<std::size_t>::max() - kind
                                                   : std::size_t{in.word()};
        std::vector<float> buffer(length, 7.0f);
        system.copy_positions(std::span<float>(buffer), stride);
        const std::size_t n = system.size();
        const bool fits = n == 0 || (length >= 3 && (n == 1 || stride <= (length - 3) / (n - 1)));
        if (stride < 3 || !fits) {
          if (stride < 3) expect_rejected("copy_positions", "stride", stride);
          else expect_rejected("copy_positions", "out", Length{length});
          for (const float x : buffer) require(x == 7.0f, "a refused copy-out wrote");
        } else {
          expect_accepted("copy_positions");
          // Each stored position rounded once to float (a compensated pair: hi + lo, where
          // long double holds it exactly).
          for (std::size_t i = 0; i < n; ++i) {
            for (int k = 0; k < 3; ++k) {
              long double p = 0.0L;
              if (exact_position(system, i, k, p)) {
                require(identical(buffer[i * stride + static_cast<std::size_t>(k)],
                                  static_cast<float>(p)),
                        "copy-out differs from the positions");
              }
            }
          }
        }
        break;
      }
      case 12: {
        const R t = in.number<R>();
        const int count = in.byte() % 9;
        for (int k = 0; k < (count == 0 ? 1 : count); ++k) {
          system.step(t);
          if (!real_isfinite(t) || t < R(0)) {
            expect_rejected("step", "duration", t);
            break;
          }
          mirror.step(t);
        }
        if (real_isfinite(t) && t >= R(0))
          budget.step(count == 0 ? 1 : count, static_cast<double>(t));
        stepped = true;
        break;
      }
      case 13: {  // reserve with any count
        const std::size_t count = pick_count<System>(in);
        const std::size_t capacity = system.capacity();
        if (count <= reserve_limit) {
          system.reserve(count);
          require(system.capacity() >= count, "reserve left too little room");
          if (count <= capacity)
            require(system.capacity() == capacity, "a reserve within capacity changed it");
        } else if (count > System::max_size()) {
#if POINTMASS_HAS_EXCEPTIONS
          std::string message;
          try {
            system.reserve(count);
          } catch (const std::length_error& error) {
            message = error.what();
          }
          require(!message.empty(), "reserve beyond max_size() did not throw std::length_error");
          require(message.find("reserve") != std::string::npos &&
                      message.find("'capacity' = " + std::to_string(count)) != std::string::npos,
                  "reserve's length_error does not name the call and count:", message.c_str());
          require(system.capacity() == capacity, "a refused reserve changed the capacity");
#endif
        }
        break;
      }
      case 14: {  // kill_if: the particles whose state is doomed, in swap-remove order
        const std::uint8_t mode = in.byte();
        if (mode == 0xFF) {  // mode % 8 == 7 removes all: here clear() does, keeping the capacity
          const std::size_t capacity = system.capacity();
          system.clear();
          require(system.size() == 0 && system.capacity() == capacity, "clear");
          while (mirror.size() != 0) mirror.kill(mirror.size() - 1);
          break;
        }
        const std::size_t before = system.size();
        std::size_t asked = 0;
        const std::size_t removed = system.kill_if([&](std::size_t i) {
          ++asked;
          require(i < system.size(), "kill_if asked about a dead index");
          return doomed(system.position(i), system.velocity(i), mode);
        });
        std::size_t mirror_removed = 0;
        for (std::size_t i = 0; i < mirror.size();) {
          if (doomed(mirror.bodies[i].position(), mirror.bodies[i].velocity(), mode)) {
            mirror.kill(i);
            ++mirror_removed;
          } else {
            ++i;
          }
        }
        require(asked == before, "kill_if did not ask about each particle once");
        require(removed == mirror_removed, "kill_if returned a wrong count");
        break;
      }
      case 15: {  // copy construction and copy assignment
        const System copy = system;
        require(copy.capacity() == system.capacity(), "a copy has another capacity");
        require(!pointmass::detail::SystemAccess::next_step_backward(copy),
                "a copy does not start walking forwards");
        compare(copy, mirror, budget);
        const int assigned_to = in.byte() % 3;
        switch (assigned_to) {
          case 0: system = copy; break;
          case 1: {
            const System& alias = system;
            system = alias;  // self-assignment
            break;
          }
          default:
            other = copy;
            other_mirror = mirror;
            break;
        }
        require(system.capacity() == copy.capacity(), "copy assignment changed the capacity");
        require(
            !pointmass::detail::SystemAccess::next_step_backward(assigned_to == 2 ? other : system),
            "a copy-assigned system does not start walking forwards");
        compare(copy, mirror, budget);  // the source of the copies is unchanged
        break;
      }
      case 16: {  // move construction and move assignment
        const std::size_t capacity = system.capacity();
        const bool backward = pointmass::detail::SystemAccess::next_step_backward(system);
        System moved(std::move(system));
        require(moved.capacity() == capacity &&
                    pointmass::detail::SystemAccess::next_step_backward(moved) == backward,
                "a move lost the capacity or the walk's direction");
        compare(moved, mirror, budget);
        // The moved-from system can be cleared, used and assigned to.
        system.clear();
        require(system.size() == 0, "clear left particles");
        using W = typename System::position_value;
        require(system.spawn(Vector3<W>{W(1), W(2), W(3)}, Vector3<R>{}) == 0,
                "a moved-from system does not spawn at 0");
        require(identical(system.position(0), Vector3<W>{W(1), W(2), W(3)}),
                "a moved-from system lost a new particle");
        system = std::move(moved);
        require(system.capacity() == capacity &&
                    pointmass::detail::SystemAccess::next_step_backward(system) == backward,
                "a move assignment lost the capacity or the walk's direction");
        break;
      }
      case 17: {  // swap with the other system
        const std::size_t capacities[] = {system.capacity(), other.capacity()};
        const bool directions[] = {pointmass::detail::SystemAccess::next_step_backward(system),
                                   pointmass::detail::SystemAccess::next_step_backward(other)};
        switch (in.byte() % 3) {
          case 0: system.swap(other); break;
          case 1: swap(system, other); break;
          default: std::swap(system, other); break;
        }
        std::swap(mirror, other_mirror);
        require(system.capacity() == capacities[1] && other.capacity() == capacities[0],
                "swap did not exchange the capacities");
        require(pointmass::detail::SystemAccess::next_step_backward(system) == directions[1] &&
                    pointmass::detail::SystemAccess::next_step_backward(other) == directions[0],
                "swap did not exchange the walk's direction");
        compare(other, other_mirror, budget);
        break;
      }
      case 18: {  // every accessor with any index: a bad one is reported, nothing changes
        const auto read = [&](const char* function, auto value) {
          static_cast<void>(value);
          if (valid_index) expect_accepted(function);
          else expect_rejected(function, "index", index);
        };
        read("position", system.position(index));
        read("velocity", system.velocity(index));
        read("acceleration", system.acceleration(index));
        read("damping", system.damping(index));
        if constexpr (System::template has<pointmass::features::ForceAccumulator>) {
          read("inverse_mass", system.inverse_mass(index));
          read("force_accumulator", system.force_accumulator(index));
        }
        if constexpr (System::template has<pointmass::features::Lifetime>) {
          read("age", system.age(index));
          read("lifetime", system.lifetime(index));
        }
        if constexpr (System::template has<pointmass::features::Interpolation>) {
          read("previous_position", system.previous_position(index));
          read("interpolated_position", system.interpolated_position(index, R(0)));
        }
        if constexpr (System::template has<pointmass::features::Handles>)
          read("handle", system.handle(index));
        if constexpr (has_owner_column<System>) {
          read("column", system.template column<FuzzOwner>(index));
          if ((code / 23) % 2 == 1) {  // and a value of the user column set (no input read)
            const int owner = -(op + 1);
            system.template set_column<FuzzOwner>(index, owner);
            if (valid_index) mirror.owners[index] = owner;
            read("set_column", 0);
          }
        }
        break;
      }
      case 19: {  // step_range and step_range_backward over any ranges, then finish_step
        const R t = in.number<R>();
        const int pieces = in.byte() % 6 + 1;
        auto view = system.begin_step(t);
        if (!real_isfinite(t) || t < R(0)) {
          expect_rejected("begin_step", "duration", t);
          break;
        }
        if (!view) break;
        const auto parameters = view.parameters();
        for (int k = 0; k < pieces; ++k) {
          const std::size_t begin = pick_bound(in, system.size());
          const std::size_t end = pick_bound(in, system.size());
          const bool backward = in.byte() % 2 == 1;
          const char* function = backward ? "step_range_backward" : "step_range";
          using Kernel = pointmass::detail::SystemAccess::Kernel<System>;
          if (backward) {
            Kernel::step_range_backward(view.arrays(), begin, end, parameters);
          } else {
            Kernel::step_range(view.arrays(), begin, end, parameters);
          }
          if (end > system.size()) {
            expect_rejected(function, "end", end);
          } else if (begin > end) {
            expect_rejected(function, "begin", begin);
          } else {
            for (std::size_t i = begin; i < end; ++i) mirror.integrate(i, t);
            budget.step(1, static_cast<double>(t));
          }
          compare(system, mirror, budget);
        }
        system.finish_step(std::move(view));
        mirror.expire();
        stepped = true;
        break;
      }
      case 20: {
        if constexpr (System::template has<pointmass::features::ForceAccumulator>) {
          const R im = in.number<R>();
          system.set_inverse_mass(index, im);
          if (!valid_index) {
            expect_rejected("set_inverse_mass", "index", index);
          } else if (!inverse_mass_accepted(im)) {
            expect_rejected("set_inverse_mass", "inverse_mass", im);
          } else {
            mirror.bodies[index].set_inverse_mass(im);
            budget.value(im, inverse_mass_bound);
          }
        }
        break;
      }
      case 21: {  // spawn copies of particles, moved apart (spawn(const particle_type&)): grows
        const std::size_t count = std::size_t{in.byte()} * 6;
        if (mirror.size() == 0) break;
        for (std::size_t k = 0; k < count && system.size() < max_particles; ++k) {
          auto body = mirror.bodies[(index + k) % mirror.size()];
          using W = typename System::position_value;
          const Vector3<W> p = body.position();
          // Copies that differ; a wide position is moved only every other time, so that the
          // copies of its own pairs (lo included) are spawned too.
          const Vector3<W> shifted{p.x + static_cast<W>(k), p.y, p.z};
          if (position_accepted<System>(shifted) && (plain_positions<System> || k % 2 == 1)) {
            body.set_position(shifted);
            budget.vector(shifted, position_bound<System>);
          }
          const std::size_t i = system.spawn(body);
          if (!finite(body.position())) {  // a particle stepped beyond the range of R
            expect_rejected("spawn", "position", body.position());
            require(i == System::npos, "rejected spawn returned an index");
          } else if (!finite(body.velocity())) {
            expect_rejected("spawn", "velocity", body.velocity());
            require(i == System::npos, "rejected spawn returned an index");
          } else {
            require(i == mirror.size(), "spawn(particle) index");
            mirror.push(body);
            if constexpr (System::template has<pointmass::features::Handles>)
              mirror.track(system.handle(i), i);
          }
        }
        break;
      }
      case 23: {
        if constexpr (Extended) fuzz_throwing_spawn(system, mirror, budget, in, index);
        break;
      }
      case 24: {
        if constexpr (Extended) fuzz_other_settings(system, mirror, budget, in, index);
        break;
      }
      default: break;
    }
    expect_accepted("system operation");
    if (stepped) {
      require(immortals(system) == immortal, "a particle with an infinite lifetime expired");
    }
    compare(system, mirror, budget);
  }
  compare(other, other_mirror, budget);
}

// --- force generators -----------------------------------------------------------------------
//
// Inputs whose first byte is in [0xF0, 0xF8) drive the force generators (even: float, odd:
// double): every setter with any value (a rejected one is reported once, naming the setter
// and argument, and changes nothing), then bodies with any finite state and inverse mass and
// any duration through every generator. Invariants: a force from finite input is finite, or
// forces::update_force reports it and adds nothing; inside the physical box below, it is
// finite; StiffSpring::integrate sets a finite state or reports and changes nothing;
// apply_links with any links either adds every force or, rejected, changes nothing.

/// Inside this box (each magnitude 0 or in [1/box, box]) every generator's force and every
/// closed-form step is finite (docs/forces.md, "Ranges").
template <class R>
constexpr long double physical_box = std::is_same_v<R, float> ? 1e6L : 1e30L;

template <class R>
bool in_box(R x) {
  const long double a = static_cast<long double>(x < R(0) ? -x : x);
  return a == 0.0L || (a >= 1.0L / physical_box<R> && a <= physical_box<R>);
}
template <class R>
bool in_box(const Vector3<R>& v) {
  return in_box(v.x) && in_box(v.y) && in_box(v.z);
}

/// Calls `set(value)`; the setter must accept exactly the values `valid` says, and a rejected
/// value must leave `state()` as it was.
template <class T, class Set, class State>
void fuzz_setter(const T& value, bool valid, const char* function, const char* argument, Set set,
                 State state) {
  const auto before = state();
  set(value);
  if (valid) {
    expect_accepted(function);
  } else {
    expect_rejected(function, argument, value);
    require(state() == before, "a rejected setter changed the generator:", function);
  }
}

template <class R>
struct Generators {
  forces::Gravity<R> gravity;
  forces::Drag<R> drag;
  forces::AnchoredSpring<R> spring;
  forces::AnchoredBungee<R> bungee;
  forces::Buoyancy<R> buoyancy;
  forces::StiffSpring<R> stiff;
  forces::PositionOnlyStiffSpring<R> position_only;
  forces::LinkSprings<R> links;
};

template <class R>
void fuzz_generator_setter(Input& in, Generators<R>& g) {
  const auto non_negative = [](R x) { return real_isfinite(x) && x >= R(0); };
  const auto positive = [](R x) { return real_isfinite(x) && x > R(0); };
  const auto finite_number = [](R x) { return real_isfinite(x); };
  const auto finite_vector = [](const Vector3<R>& v) { return is_finite(v); };
  const auto spring_state = [](const auto& s) {
    return std::tuple(s.stiffness(), s.rest_length());
  };
  const auto stiff_state = [](const auto& s) {
    return std::tuple(s.anchor(), s.stiffness(), s.damping());
  };
  const auto buoyancy_state = [&] {
    return std::tuple(g.buoyancy.max_depth(), g.buoyancy.volume(), g.buoyancy.water_height(),
                      g.buoyancy.liquid_density(), g.buoyancy.gravity());
  };
  switch (in.byte() % 16) {
    case 0: {
      const auto v = in.vector<R>();
      fuzz_setter(
          v, finite_vector(v), "Gravity::set_gravity", "gravity",
          [&](const auto& x) { g.gravity.set_gravity(x); }, [&] { return g.gravity.gravity(); });
      break;
    }
    case 1:
    case 2: {
      const R x = in.number<R>();
      const bool first = in.byte() % 2 == 0;
      fuzz_setter(
          x, non_negative(x), first ? "Drag::set_k1" : "Drag::set_k2", first ? "k1" : "k2",
          [&](R y) { first ? g.drag.set_k1(y) : g.drag.set_k2(y); },
          [&] { return std::tuple(g.drag.k1(), g.drag.k2()); });
      break;
    }
    case 3:
    case 4: {
      const R x = in.number<R>();
      const bool stiffness = in.byte() % 2 == 0;
      auto set = [&](auto& s) {
        fuzz_setter(
            x, non_negative(x), stiffness ? "set_stiffness" : "set_rest_length",
            stiffness ? "stiffness" : "rest_length",
            [&](R y) { stiffness ? s.set_stiffness(y) : s.set_rest_length(y); },
            [&] { return spring_state(s); });
      };
      switch (in.byte() % 3) {
        case 0: set(g.spring); break;
        case 1: set(g.bungee); break;
        default: set(g.links); break;
      }
      break;
    }
    case 5: {
      const auto v = in.vector<R>();
      auto set = [&](auto& s) {
        fuzz_setter(
            v, finite_vector(v), "set_anchor", "anchor", [&](const auto& x) { s.set_anchor(x); },
            [&] { return s.anchor(); });
      };
      if (in.byte() % 2 == 0) set(g.spring);
      else set(g.bungee);
      break;
    }
    case 6:
    case 7:
    case 8: {
      const R x = in.number<R>();
      switch (in.byte() % 5) {
        case 0:
          fuzz_setter(
              x, positive(x), "Buoyancy::set_max_depth", "max_depth",
              [&](R y) { g.buoyancy.set_max_depth(y); }, buoyancy_state);
          break;
        case 1:
          fuzz_setter(
              x, positive(x), "Buoyancy::set_volume", "volume",
              [&](R y) { g.buoyancy.set_volume(y); }, buoyancy_state);
          break;
        case 2:
          fuzz_setter(
              x, finite_number(x), "Buoyancy::set_water_height", "water_height",
              [&](R y) { g.buoyancy.set_water_height(y); }, buoyancy_state);
          break;
        case 3:
          fuzz_setter(
              x, non_negative(x), "Buoyancy::set_liquid_density", "liquid_density",
              [&](R y) { g.buoyancy.set_liquid_density(y); }, buoyancy_state);
          break;
        default:
          fuzz_setter(
              x, non_negative(x), "Buoyancy::set_gravity", "g",
              [&](R y) { g.buoyancy.set_gravity(y); }, buoyancy_state);
          break;
      }
      break;
    }
    default: {  // the two stiff springs share their parameters' setters
      auto set = [&](auto& s) {
        switch (in.byte() % 3) {
          case 0: {
            const auto v = in.vector<R>();
            fuzz_setter(
                v, finite_vector(v), "StiffSpring::set_anchor", "anchor",
                [&](const auto& y) { s.set_anchor(y); }, [&] { return stiff_state(s); });
            break;
          }
          case 1: {
            const R x = in.number<R>();
            fuzz_setter(
                x, non_negative(x), "StiffSpring::set_stiffness", "stiffness",
                [&](R y) { s.set_stiffness(y); }, [&] { return stiff_state(s); });
            break;
          }
          default: {
            const R x = in.number<R>();
            fuzz_setter(
                x, non_negative(x), "StiffSpring::set_damping", "damping",
                [&](R y) { s.set_damping(y); }, [&] { return stiff_state(s); });
            break;
          }
        }
      };
      if (in.byte() % 2 == 0) set(g.stiff);
      else set(g.position_only);
      break;
    }
  }
}

/// A finite number from the input (a non-finite one becomes `fallback`).
template <class R>
R finite_number(Input& in, R fallback = R(0)) {
  const R x = in.number<R>();
  return real_isfinite(x) ? x : fallback;
}
template <class R>
Vector3<R> finite_vector(Input& in) {
  const R x = finite_number<R>(in), y = finite_number<R>(in), z = finite_number<R>(in);
  return {x, y, z};
}

/// The force `generator` adds to `body` through forces::update_force: finite and added, or
/// reported and not added; finite when `in_range`.
template <class G, class Body>
void fuzz_update_force(const G& generator, const Body& body, typename Body::real t, bool in_range,
                       const char* name) {
  Body copy = body;
  forces::update_force(generator, copy, t);
  if (report.calls == 0) {
    require(finite(copy.force_accumulator()), "a non-finite force was added by", name);
  } else {
    require(!in_range, "a force inside the physical box was reported:", name);
    require(report.calls == 1 && report.function == "forces::update_force" &&
                report.argument == "force",
            "an overflowing force was reported wrongly:", report.message.c_str());
    require(same_state(copy, body), "a rejected update_force changed the body:", name);
    report = {};
  }
}

template <class R>
void fuzz_bodies(Input& in, const Generators<R>& g) {
  using Body = Particle<R, damping::None, position::SemiImplicit>;
  Body body;
  body.set_position(finite_vector<R>(in));
  body.set_velocity(finite_vector<R>(in));
  R inverse_mass = finite_number<R>(in, R(1));
  if (inverse_mass < R(0)) inverse_mass = -inverse_mass;
  // A subnormal inverse mass is refused (its mass() would be infinite): 0 stands for it.
  if (inverse_mass < std::numeric_limits<R>::min()) inverse_mass = R(0);
  body.set_inverse_mass(inverse_mass);
  body.set_acceleration(finite_vector<R>(in));
  expect_accepted("body setup");
  const R t = finite_number<R>(in);
  const R duration = t < R(0) ? -t : t;
  const bool body_in_box = in_box(body.position()) && in_box(body.velocity()) &&
                           in_box(body.inverse_mass()) && in_box(duration);
  const auto box = [&](auto... parameters) { return body_in_box && (in_box(parameters) && ...); };
  fuzz_update_force(g.gravity, body, duration, box(g.gravity.gravity()), "Gravity");
  fuzz_update_force(g.drag, body, duration, box(g.drag.k1(), g.drag.k2()), "Drag");
  fuzz_update_force(g.spring, body, duration,
                    box(g.spring.anchor(), g.spring.stiffness(), g.spring.rest_length()),
                    "AnchoredSpring");
  fuzz_update_force(g.bungee, body, duration,
                    box(g.bungee.anchor(), g.bungee.stiffness(), g.bungee.rest_length()),
                    "AnchoredBungee");
  fuzz_update_force(g.buoyancy, body, duration,
                    box(g.buoyancy.max_depth(), g.buoyancy.volume(), g.buoyancy.water_height(),
                        g.buoyancy.liquid_density(), g.buoyancy.gravity()),
                    "Buoyancy");
  fuzz_update_force(
      g.position_only, body, duration,
      box(g.position_only.anchor(), g.position_only.stiffness(), g.position_only.damping()),
      "PositionOnlyStiffSpring");
  // The closed-form step: a finite state, or reported and nothing changed.
  Body stepped = body;
  g.stiff.integrate(stepped, duration);
  if (report.calls == 0) {
    require(finite(stepped.position()) && finite(stepped.velocity()),
            "StiffSpring::integrate stored a non-finite state");
  } else {
    require(!box(g.stiff.anchor(), g.stiff.stiffness(), g.stiff.damping(), body.acceleration()),
            "StiffSpring::integrate reported a state inside the physical box");
    require(report.calls == 1 && report.function == "StiffSpring::integrate",
            "StiffSpring::integrate reported wrongly:", report.message.c_str());
    require(same_state(stepped, body), "a rejected integrate changed the body");
    report = {};
  }
}

template <class R>
void fuzz_links(Input& in, const Generators<R>& g) {
  std::array<Vector3<R>, 4> positions{};
  std::array<Vector3<R>, 4> velocities{};
  std::array<Vector3<R>, 4> accumulated{};
  for (auto& p : positions) p = finite_vector<R>(in);
  std::array<forces::Link, 3> links{};
  for (auto& link : links) link = {in.byte() % 6u, in.byte() % 6u};  // 4 and 5 are out of range
  forces::SpanBodies<R> bodies{positions, velocities, {}, accumulated};
  forces::apply_links(g.links, std::span<const forces::Link>(links), bodies);
  if (report.calls == 0) {
    // Each link's force is finite (their sum on one body may still overflow: that is the
    // accumulator's range, not a generator's).
    for (const auto& link : links) {
      require(finite(g.links.force_between(positions[link.first], positions[link.second])),
              "apply_links accepted a non-finite force");
    }
  } else {
    for (const auto& f : accumulated)
      require(f == Vector3<R>{}, "a rejected apply_links changed a body");
    report = {};
  }
}

template <class R>
void fuzz_forces(Input& in) {
  Generators<R> g;
  for (int op = 0; op < 200 && !in.empty(); ++op) {
    switch (in.byte() % 4) {
      case 0:
      case 1: fuzz_generator_setter(in, g); break;
      case 2: fuzz_bodies(in, g); break;
      default: fuzz_links(in, g); break;
    }
    expect_accepted("force generator operation");
  }
}

// --- a ForceRegistry whose generators change it during update_forces -------------------------
//
// Inputs whose first byte is 0xF8 (float) or 0xF9 (double) drive two ForceRegistry objects
// over four particles, with generators of a known type and of a type-erased one, owned
// (add_owned, emplace) or not (add, const or not), checked against a model of the
// registrations (registry.hpp, ForceRegistry). Outside a pass: add, remove (its result), clear,
// and replacing a registry (assigning an empty one, moving one into the other, swapping).
// Armed generators do one of the same to either registry from inside update_forces. A pass
// calls exactly the registrations present when it began (known types first, then the
// type-erased, each in the order added) that are not removed before their turn, nothing added
// during it, and nothing after its registry was replaced; each adds its force once; a
// removed owned generator lives until the pass ends (it runs on after removing itself) and is
// destroyed then; later passes, on either registry, call everything registered there.

enum class Act : std::uint8_t {
  none,
  add,
  remove_self,
  remove_other,
  clear,
  assign_new,
  move_in,
  swap
};
constexpr int acts = 8;

template <class R>
struct RegistryWorld;

template <class R, bool Known>
struct Meddler {
  RegistryWorld<R>* world;
  int id;
  Meddler(RegistryWorld<R>* w, int i) : world(w), id(i) { ++world->live; }
  Meddler(const Meddler& other) : world(other.world), id(other.id) { ++world->live; }
  Meddler& operator=(const Meddler&) = default;
  ~Meddler() { --world->live; }
  // const: a const registration can call it too (its state is the world's)
  void update_force(Particle<R>& particle, R) const {
    world->act(id, particle);
    particle.add_force(RegistryWorld<R>::force_of(id));  // after the act: it is still alive
  }
};

template <class R>
struct RegistryWorld {
  using Body = Particle<R>;
  using Known = Meddler<R, true>;
  using Erased = Meddler<R, false>;
  using Registry = forces::ForceRegistry<Body, Known>;
  struct Script {
    bool armed = false;
    Act act = Act::none;
    bool other = false;  // acts on the registry not running
    std::uint8_t a = 0;
    std::uint8_t b = 0;
  };
  struct Object {
    void* address;
    bool known;
    bool owned;
  };
  struct Reg {  // a registration of the model
    std::uint64_t serial;
    int id;
    std::size_t particle;
    bool known_vector;  // a non-const Known: called before the type-erased ones
    bool konst;
  };
  static constexpr std::size_t max_registrations = 48;

  int live = 0;  // Meddlers alive
  std::vector<Script> scripts;
  std::vector<Object> objects;
  std::array<std::vector<Reg>, 2> model;
  std::uint64_t next_serial = 0;
  // the pass in progress
  bool in_pass = false;
  std::size_t running = 0;
  std::vector<Reg> snapshot;
  std::size_t cursor = 0;
  bool ended = false;
  std::array<Vector3<R>, 4> forces{};
  std::array<Body, 4> bodies{};
  std::deque<Known> pool_known;
  std::deque<Erased> pool_erased;
  std::array<Registry, 2> registries;

  static Vector3<R> force_of(int id) { return {R(1 + id % 29), R(1), R(0)}; }
  std::size_t body_index(const Body& particle) const {
    const auto i = static_cast<std::size_t>(&particle - bodies.data());
    require(i < bodies.size(), "a generator was called for a particle it was not registered on");
    return i;
  }
  int new_object(void* address, bool known, bool owned) {
    objects.push_back({address, known, owned});
    scripts.emplace_back();
    return static_cast<int>(objects.size() - 1);
  }

  // Registers a generator (flavor % 7: owned known, emplaced known, owned type-erased, and a
  // pool object: known, type-erased, known const, type-erased const) on body j of registry r.
  void add(std::size_t r, std::size_t j, std::uint8_t flavor, std::uint8_t pick) {
    if (model[r].size() >= max_registrations) return;
    Registry& registry = registries[r];
    Body& body = bodies[j];
    int id = -1;
    bool known_vector = false;
    bool konst = false;
    const auto pooled = [&](auto& pool) -> auto& {
      using G = typename std::decay_t<decltype(pool)>::value_type;
      if (pick % 4 == 0 || pool.empty() || pool.size() >= 16) {
        if (pool.size() < 16) {
          pool.emplace_back(this, static_cast<int>(objects.size()));
          new_object(&pool.back(), std::is_same_v<G, Known>, false);
        }
      }
      auto& g = pool[pick % pool.size()];
      id = g.id;
      return g;
    };
    switch (flavor % 7) {
      case 0: {
        id = new_object(nullptr, true, true);
        objects[static_cast<std::size_t>(id)].address = &registry.add_owned(body, Known(this, id));
        known_vector = true;
        break;
      }
      case 1: {
        id = new_object(nullptr, true, true);
        objects[static_cast<std::size_t>(id)].address =
            &registry.template emplace<Known>(body, this, id);
        known_vector = true;
        break;
      }
      case 2: {
        id = new_object(nullptr, false, true);
        objects[static_cast<std::size_t>(id)].address = &registry.add_owned(body, Erased(this, id));
        break;
      }
      case 3: registry.add(body, pooled(pool_known)), known_vector = true; break;
      case 4: registry.add(body, pooled(pool_erased)); break;
      case 5: registry.add(body, std::as_const(pooled(pool_known))), konst = true; break;
      default: registry.add(body, std::as_const(pooled(pool_erased))), konst = true; break;
    }
    model[r].push_back({next_serial++, id, j, known_vector, konst});
  }

  // The model's remove: the first const registration of the object on the particle (a const
  // one is type-erased whatever its type, and looked for first), else its first other one.
  bool model_remove(std::size_t r, std::size_t j, int id) {
    auto& regs = model[r];
    for (const bool konst : {true, false}) {
      for (auto it = regs.begin(); it != regs.end(); ++it) {
        if (it->particle == j && it->id == id && it->konst == konst) {
          regs.erase(it);
          return true;
        }
      }
    }
    return false;
  }
  void remove(std::size_t r, std::size_t j, int id) {
    const Object& o = objects[static_cast<std::size_t>(id)];
    const bool removed =
        o.known ? registries[r].remove(bodies[j], *static_cast<const Known*>(o.address))
                : registries[r].remove(bodies[j], *static_cast<const Erased*>(o.address));
    require(removed == model_remove(r, j, id), "remove's result differs from the model");
  }
  // An object that is alive: a pool object, or an owned one still registered.
  int pick_object(std::uint8_t b) const {
    std::vector<int> alive;
    for (std::size_t id = 0; id < objects.size(); ++id) {
      bool registered = !objects[id].owned;
      for (const auto& regs : model) {
        for (const auto& reg : regs) registered = registered || reg.id == static_cast<int>(id);
      }
      if (registered) alive.push_back(static_cast<int>(id));
    }
    return alive.empty() ? -1 : alive[b % alive.size()];
  }
  // A particle the object is registered on (b even, when it is), else any.
  std::size_t pick_particle(int id, std::uint8_t b) const {
    if (b % 2 == 0) {
      for (const auto& regs : model) {
        for (const auto& reg : regs) {
          if (reg.id == id) return reg.particle;
        }
      }
    }
    return b / 2 % bodies.size();
  }

  // Does `act` to registry r (and the model); true when it replaced registry `running`.
  bool perform(Act act, std::size_t r, std::uint8_t a, std::uint8_t b, int self,
               std::size_t self_body) {
    switch (act) {
      case Act::none: return false;
      case Act::add: add(r, a % 4, b, a / 4); return false;
      case Act::remove_self:
        if (self >= 0) remove(r, self_body, self);
        return false;
      case Act::remove_other: {
        const int id = pick_object(b);
        if (id >= 0) remove(r, pick_particle(id, a), id);
        return false;
      }
      case Act::clear:
        registries[r].clear();
        model[r].clear();
        return false;
      case Act::assign_new:
        registries[r] = Registry{};
        model[r].clear();
        return in_pass && r == running;
      case Act::move_in:  // the other registry moved into r (or r into itself: nothing)
        if (a % 4 == 0) {
          Registry& same = registries[r];
          registries[r] = std::move(same);
          return false;
        }
        registries[r] = std::move(registries[1 - r]);
        model[r] = std::move(model[1 - r]);
        model[1 - r].clear();
        return in_pass;
      default:
        std::swap(registries[0], registries[1]);
        std::swap(model[0], model[1]);
        return in_pass;
    }
  }

  // A generator's call: the model's next registration of the pass, and its act if armed.
  void act(int id, Body& particle) {
    require(in_pass, "a generator was called outside update_forces");
    require(!ended, "a generator was called after its registry was replaced");
    const std::size_t j = body_index(particle);
    const auto present = [&](const Reg& reg) {
      for (const auto& r : model[running]) {
        if (r.serial == reg.serial) return true;
      }
      return false;
    };
    while (cursor < snapshot.size() && !present(snapshot[cursor])) ++cursor;
    require(cursor < snapshot.size(), "update_forces called a registration added during it");
    const Reg expected = snapshot[cursor++];
    require(expected.id == id && expected.particle == j,
            "update_forces called another registration than the model's next");
    forces[j] += force_of(id);
    const Script s = scripts[static_cast<std::size_t>(id)];  // an add may reallocate them
    if (!s.armed) return;
    scripts[static_cast<std::size_t>(id)].armed = false;
    const std::size_t r = s.other ? 1 - running : running;
    if (perform(s.act, r, s.a, s.b, r == running ? id : -1, j)) ended = true;
  }

  void update(std::size_t r, R t) {
    for (auto& body : bodies) body.clear_accumulator();
    forces = {};
    snapshot.clear();
    for (const bool known_vector : {true, false}) {
      for (const auto& reg : model[r]) {
        if (reg.known_vector == known_vector) snapshot.push_back(reg);
      }
    }
    cursor = 0;
    ended = false;
    running = r;
    in_pass = true;
    registries[r].update_forces(t);
    in_pass = false;
    if (!real_isfinite(t) || t < R(0)) {
      expect_rejected("ForceRegistry::update_forces", "duration", t);
      require(cursor == 0, "a rejected update_forces called a generator");
    }
    if (!ended && real_isfinite(t) && t >= R(0)) {
      const auto present = [&](const Reg& reg) {
        for (const auto& x : model[r]) {
          if (x.serial == reg.serial) return true;
        }
        return false;
      };
      while (cursor < snapshot.size() && !present(snapshot[cursor])) ++cursor;
      require(cursor == snapshot.size(), "update_forces skipped a registration");
    }
    for (std::size_t j = 0; j < bodies.size(); ++j) {
      require(identical(bodies[j].force_accumulator(), forces[j]),
              "a particle's force differs from its generators' calls");
    }
  }

  void check() const {
    std::size_t owned = 0;
    for (std::size_t r = 0; r < 2; ++r) {
      require(registries[r].size() == model[r].size() && registries[r].empty() == model[r].empty(),
              "a registry's size differs from the model");
      for (const auto& reg : model[r]) owned += objects[static_cast<std::size_t>(reg.id)].owned;
    }
    require(static_cast<std::size_t>(live) == owned + pool_known.size() + pool_erased.size(),
            "owned generators alive differ from those registered");
  }
};

template <class R>
void fuzz_registry(Input& in) {
  RegistryWorld<R> world;
  for (int op = 0; op < 200 && !in.empty(); ++op) {
    const std::uint8_t code = in.byte();
    const std::size_t r = (code / 8) % 2;
    switch (code % 8) {
      case 0:
      case 1: {
        const std::uint8_t flavor = in.byte();
        const std::uint8_t pick = in.byte();
        world.add(r, flavor % 4, flavor / 4, pick);
        break;
      }
      case 2:
      case 3: {  // arm an object: its next call acts
        const int id = world.pick_object(in.byte());
        const std::uint8_t how = in.byte();
        const std::uint8_t a = in.byte();
        const std::uint8_t b = in.byte();
        if (id >= 0)
          world.scripts[static_cast<std::size_t>(id)] = {true, static_cast<Act>(how % acts),
                                                         (how / acts) % 2 == 1, a, b};
        break;
      }
      case 4:
      case 5: world.update(r, in.number<R>()); break;
      case 6: {  // remove from outside a pass
        const int id = world.pick_object(in.byte());
        const std::uint8_t b = in.byte();
        if (id >= 0) world.remove(r, world.pick_particle(id, b), id);
        break;
      }
      default: {  // clear or replace from outside a pass
        const std::uint8_t how = in.byte();
        constexpr Act replacements[] = {Act::clear, Act::assign_new, Act::move_in, Act::swap};
        world.perform(replacements[how % 4], r, in.byte(), 0, -1, 0);
        break;
      }
    }
    expect_accepted("registry operation");
    world.check();
  }
  world.registries[0] = {};
  world.registries[1] = {};
  world.model = {};
  world.check();
}

// --- the configurations ---------------------------------------------------------------------

template <class R, class D, class P>
struct ParticleConfig {
  static void run(Input& in) { fuzz_particle<R, D, P>(in); }
};
template <class System>
struct SystemConfig {
  static void run(Input& in) { fuzz_system<System>(in); }
};
template <class System>
struct ExtendedConfig {
  static void run(Input& in) { fuzz_system<System, true>(in); }
};

template <class R>
using ParticleConfigs =
    std::tuple<ParticleConfig<R, damping::None, position::Euler>,
               ParticleConfig<R, damping::None, position::ConstantAcceleration>,
               ParticleConfig<R, damping::None, position::SemiImplicit>,
               ParticleConfig<R, damping::None, position::Exact>,
               ParticleConfig<R, damping::PerFrame, position::Euler>,
               ParticleConfig<R, damping::PerFrame, position::ConstantAcceleration>,
               ParticleConfig<R, damping::PerFrame, position::SemiImplicit>,
               ParticleConfig<R, damping::PerSecond, position::Euler>,
               ParticleConfig<R, damping::PerSecond, position::ConstantAcceleration>,
               ParticleConfig<R, damping::PerSecond, position::SemiImplicit>,
               ParticleConfig<R, damping::AccelerateThenDamp, position::Euler>,
               ParticleConfig<R, damping::AccelerateThenDamp, position::ConstantAcceleration>,
               ParticleConfig<R, damping::AccelerateThenDamp, position::SemiImplicit>,
               ParticleConfig<R, damping::Exact, position::Euler>,
               ParticleConfig<R, damping::Exact, position::ConstantAcceleration>,
               ParticleConfig<R, damping::Exact, position::SemiImplicit>,
               ParticleConfig<R, damping::Exact, position::Exact>>;

template <class R>
using SystemConfigs = std::tuple<
    SystemConfig<ParticleSystem<R>>,
    SystemConfig<
        ParticleSystem<R, damping::None, position::Exact, features::PerParticleAcceleration>>,
    SystemConfig<
        ParticleSystem<R, damping::PerFrame, position::SemiImplicit, features::ForceAccumulator>>,
    SystemConfig<ParticleSystem<R, damping::AccelerateThenDamp, position::ConstantAcceleration,
                                features::PerParticleDamping, features::Lifetime>>,
    SystemConfig<ParticleSystem<R, damping::Exact, position::Exact, features::PerParticleDamping,
                                features::PerParticleAcceleration, features::ForceAccumulator,
                                features::Lifetime>>,
    SystemConfig<ParticleSystem<R, damping::PerSecond, position::SemiImplicit,
                                features::ForceAccumulator, features::Lifetime>>>;

// More feature sets and policy pairs, after the others so that the first byte of the
// corpus's older inputs still chooses the configuration it chose.
template <class R>
using MoreSystemConfigs = std::tuple<
    SystemConfig<ParticleSystem<R, damping::PerFrame, position::Euler, features::PerParticleDamping,
                                features::ForceAccumulator>>,
    SystemConfig<ParticleSystem<R, damping::Exact, position::SemiImplicit,
                                features::PerParticleAcceleration, features::Lifetime>>,
    SystemConfig<
        ParticleSystem<R, damping::PerSecond, position::ConstantAcceleration, features::Lifetime,
                       features::PerParticleDamping, features::PerParticleAcceleration>>,
    SystemConfig<ParticleSystem<R, damping::None, position::Euler, features::ForceAccumulator,
                                features::Lifetime>>>;

// The game features (previous positions, handles, a user column): no physics of their own,
// so every invariant above holds with them; after the others, as above.
template <class R>
using GameSystemConfigs = std::tuple<SystemConfig<
    ParticleSystem<R, damping::PerSecond, position::Euler, features::Lifetime,
                   features::Interpolation, features::Handles, features::Column<FuzzOwner, int>>>>;

// The second-order step (its credited kick a column of its own); after the others, as above.
template <class R>
using VerletConfigs =
    std::tuple<ParticleConfig<R, damping::PerSecond, position::VelocityVerlet>,
               SystemConfig<ParticleSystem<R, damping::PerFrame, position::VelocityVerlet,
                                           features::ForceAccumulator, features::Lifetime>>>;

template <class... A, class... B>
auto concatenate(std::tuple<A...>, std::tuple<B...>) -> std::tuple<A..., B...>;
using Configs = decltype(concatenate(
    concatenate(concatenate(concatenate(std::declval<ParticleConfigs<float>>(),
                                        std::declval<ParticleConfigs<double>>()),
                            concatenate(std::declval<SystemConfigs<float>>(),
                                        std::declval<SystemConfigs<double>>())),
                concatenate(concatenate(std::declval<MoreSystemConfigs<float>>(),
                                        std::declval<MoreSystemConfigs<double>>()),
                            concatenate(std::declval<GameSystemConfigs<float>>(),
                                        std::declval<GameSystemConfigs<double>>()))),
    concatenate(std::declval<VerletConfigs<float>>(), std::declval<VerletConfigs<double>>())));
static_assert(std::tuple_size_v<Configs> <= 0xE0,
              "the first bytes from 0xE0 choose wide positions and the forces");

// Positions stored wider than the arithmetic ("positions stored wider" above), chosen by a
// first byte in [0xE0, 0xF0), which no input of the corpus before them starts with: so those
// inputs keep their configuration.
using WideConfigs = std::tuple<
    SystemConfig<ParticleSystem<Precision<float, double>>>,
    SystemConfig<
        ParticleSystem<Precision<float, Compensated<float>>, damping::Exact, position::Exact,
                       features::PerParticleDamping, features::PerParticleAcceleration,
                       features::ForceAccumulator, features::Lifetime>>,
    SystemConfig<ParticleSystem<Precision<float, Compensated<float>>, damping::AccelerateThenDamp,
                                position::SemiImplicit, features::ForceAccumulator>>,
    SystemConfig<ParticleSystem<Precision<double, Compensated<double>>, damping::PerFrame,
                                position::ConstantAcceleration, features::PerParticleDamping,
                                features::Lifetime>>,
    SystemConfig<
        ParticleSystem<Precision<float, double>, damping::PerSecond, position::SemiImplicit,
                       features::Lifetime, features::Interpolation, features::Handles>>>;

// The systems with a user column that throws, driven through the other checks setting too
// (fuzz_shared.hpp), chosen by a first byte from 0xFA.
using ExtendedConfigs =
    std::tuple<ExtendedConfig<fuzz::FuseFloat>, ExtendedConfig<fuzz::FuseDouble>,
               ExtendedConfig<fuzz::FuseExact>, ExtendedConfig<fuzz::FuseCompensated>>;

template <class Tuple, std::size_t... I>
void dispatch(std::size_t which, Input& in, std::index_sequence<I...>) {
  ((which == I ? (std::tuple_element_t<I, Tuple>::run(in), 0) : 0), ...);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const bool installed = (set_contract_handler(&record), true);
  static_cast<void>(installed);
  report = {};
  Input in(data, size);
  const std::uint8_t first = in.byte();
  if (first >= 0xFA) {  // a user column that throws, and the other checks setting
    constexpr std::size_t count = std::tuple_size_v<ExtendedConfigs>;
    dispatch<ExtendedConfigs>((first - 0xFAu) % count, in, std::make_index_sequence<count>{});
    return 0;
  }
  if (first >= 0xF8) {  // generators that change their registry during update_forces
    if (first % 2 == 0) fuzz_registry<float>(in);
    else fuzz_registry<double>(in);
    return 0;
  }
  if (first >= 0xF0) {  // the force generators (0xF0 to 0xF7)
    if (first % 2 == 0) fuzz_forces<float>(in);
    else fuzz_forces<double>(in);
    return 0;
  }
  if (first >= 0xE0) {  // positions stored wider than the arithmetic
    constexpr std::size_t count = std::tuple_size_v<WideConfigs>;
    dispatch<WideConfigs>((first - 0xE0u) % count, in, std::make_index_sequence<count>{});
    return 0;
  }
  constexpr std::size_t count = std::tuple_size_v<Configs>;
  dispatch<Configs>(first % count, in, std::make_index_sequence<count>{});
  return 0;
}
