// Accuracy measurement shared by the reference tests, the accuracy report and the
// accuracy-comparison example: the scenes as continuous models, every policy combination,
// simulation with the library, errors against the reference, orders, error bounds, energy
// drift and stability limits. Everything here is double unless a Real is named.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <limits>
#include <string>
#include <type_traits>
#include <vector>

#include <pointmass/damping.hpp>
#include <pointmass/particle.hpp>
#include <pointmass/position.hpp>
#include <pointmass/extras/scenes.hpp>
#include <pointmass/vector3.hpp>

#include "reference_solution.hpp"

namespace pointmass::accuracy {

// --- scenes --------------------------------------------------------------------------------

/// A scene as initial values and a continuous model (per unit mass).
struct Scene {
  std::string name;
  Vector3<double> start_position{};
  Vector3<double> start_velocity{};
  Vector3<double> gravity{};  ///< the particle's constant acceleration
  double mass = 1;
  double damping = 1;    ///< per second; a PerFrame particle gets damping^h per frame
  double stiffness = 0;  ///< spring to the origin, N/m, added each step with add_force
  double friction = 0;   ///< N s/m, added each step with add_force
  double duration = 5;   ///< s

  bool has_spring() const { return stiffness != 0 || friction != 0; }
  double angular_frequency() const { return std::sqrt(stiffness / mass); }
};

inline Vector3<double> to_double(const Vector3<double>& v) { return v; }

/// The reference engine's four ballistic shots (scene 2), 5 s from (0, 1.5, 0).
inline std::vector<Scene> ballistic_scenes() {
  std::vector<Scene> scenes;
  for (const auto& shot : scenes::ballistic_shots<double>) {
    Scene s;
    s.name = std::string(shot.name);
    s.start_position = scenes::ballistic_origin<double>;
    s.start_velocity = shot.velocity;
    s.gravity = shot.acceleration;
    s.mass = shot.mass;
    s.damping = shot.damping;
    s.duration = scenes::ballistic_duration<double>;
    scenes.push_back(s);
  }
  return scenes;
}

/// Scene 1: free flight under Earth gravity, no damping, 5 s.
inline Scene free_flight() {
  Scene s;
  s.name = "free flight";
  s.start_position = {0, 1.5, 0};
  s.start_velocity = {3, 20, 4};
  s.gravity = {0, -9.807, 0};
  s.duration = 5;
  return s;
}

/// Scene 3: the mass on a spring (scenes::SpringScene: period 1 s), undamped or damped
/// (friction 0.5 N s/m through add_force and per-second damping 0.5), over `duration`.
inline Scene spring(bool damped, double duration, double stiffness = scenes::SpringScene<double>{}.stiffness) {
  const scenes::SpringScene<double> spring_scene{};
  Scene s;
  s.name = damped ? "damped spring" : "spring";
  s.start_position = spring_scene.start;
  s.mass = spring_scene.mass;
  s.stiffness = stiffness;
  s.friction = damped ? 0.5 : 0.0;
  s.damping = damped ? 0.5 : 1.0;
  s.duration = duration;
  return s;
}

// --- combinations ----------------------------------------------------------------------------

template <class D>
constexpr const char* damping_name() {
  if constexpr (std::is_same_v<D, damping::None>) return "None";
  else if constexpr (std::is_same_v<D, damping::PerFrame>) return "PerFrame";
  else if constexpr (std::is_same_v<D, damping::PerSecond>) return "PerSecond";
  else if constexpr (std::is_same_v<D, damping::AccelerateThenDamp>) return "AccelerateThenDamp";
  else return "Exact";
}
template <class P>
constexpr const char* position_name() {
  if constexpr (std::is_same_v<P, position::Euler>) return "Euler";
  else if constexpr (std::is_same_v<P, position::Kinematic>) return "Kinematic";
  else if constexpr (std::is_same_v<P, position::SemiImplicit>) return "SemiImplicit";
  else return "Exact";
}
template <class D, class P>
std::string combination_name() {
  return std::string(damping_name<D>()) + " + " + position_name<P>();
}

/// Calls f.template operator()<D, P>() for every valid combination (17: position::Exact
/// needs damping::None or damping::Exact).
template <class F>
void for_each_combination(F&& f) {
  const auto with_damping = [&]<class D>() {
    f.template operator()<D, position::Euler>();
    f.template operator()<D, position::Kinematic>();
    f.template operator()<D, position::SemiImplicit>();
    if constexpr (std::is_same_v<D, damping::None> || std::is_same_v<D, damping::Exact>) {
      f.template operator()<D, position::Exact>();
    }
  };
  with_damping.template operator()<damping::None>();
  with_damping.template operator()<damping::PerFrame>();
  with_damping.template operator()<damping::PerSecond>();
  with_damping.template operator()<damping::AccelerateThenDamp>();
  with_damping.template operator()<damping::Exact>();
}

/// The per-second damping rate k of the model combination D approximates (0 for None).
template <class D>
double damping_rate(const Scene& s) {
  if constexpr (std::is_same_v<D, damping::None>) return 0.0;
  else return s.damping == 1.0 ? 0.0 : std::log(s.damping);
}

template <class D>
reference::Model model_of(const Scene& s) {
  return {s.gravity, s.stiffness / s.mass, s.friction / s.mass, damping_rate<D>(s)};
}

/// True when the combination's step is the model's exact flow for this scene (so its error
/// is rounding only); otherwise it is first order.
template <class D, class P>
bool is_exact_for(const Scene& s) {
  if (s.has_spring()) return false;  // the force is frozen over each step
  const bool no_damping = damping_rate<D>(s) == 0.0;
  const bool no_acceleration = s.gravity == Vector3<double>{};
  // The policies' own traits: the pair is exact for any constant acceleration and damping,
  // or it meets a scene without the part it approximates.
  if constexpr (is_exact_for_constant_acceleration_v<D, P>) return true;
  if (no_damping && is_exact_for_constant_acceleration_v<damping::None, P>) return true;
  return no_damping && no_acceleration;  // uniform motion: every pair is exact
}

// --- simulation ----------------------------------------------------------------------------

template <Real R>
Vector3<R> cast(const Vector3<double>& v) {
  return {static_cast<R>(v.x), static_cast<R>(v.y), static_cast<R>(v.z)};
}
template <Real R>
Vector3<double> widen(const Vector3<R>& v) {
  return {static_cast<double>(v.x), static_cast<double>(v.y), static_cast<double>(v.z)};
}

/// A particle of combination (R, D, P) set up for scene s at frame time h.
template <Real R, class D, class P>
Particle<R, D, P> make_particle(const Scene& s, double h) {
  Particle<R, D, P> particle;
  particle.set_position(cast<R>(s.start_position));
  particle.set_velocity(cast<R>(s.start_velocity));
  particle.set_acceleration(cast<R>(s.gravity));
  particle.set_mass(static_cast<R>(s.mass));
  if constexpr (Particle<R, D, P>::stores_damping) {
    // PerFrame: the fraction kept per frame that removes the scene's per-second fraction.
    const double d = std::is_same_v<D, damping::PerFrame> ? std::pow(s.damping, h) : s.damping;
    particle.set_damping(static_cast<R>(d));
  }
  return particle;
}

/// One frame: the scene's spring and friction forces (from the state at the start of the
/// frame) through add_force, then integrate(h).
template <Real R, class D, class P>
void step(Particle<R, D, P>& particle, const Scene& s, R h) {
  if (s.has_spring()) {
    const Vector3<R> force = particle.position() * static_cast<R>(-s.stiffness) +
                             particle.velocity() * static_cast<R>(-s.friction);
    particle.add_force(force);
  }
  particle.integrate(h);
}

/// The particle's samples at n h, n = 0 .. steps.
template <Real R, class D, class P>
std::vector<reference::Sample> simulate(const Scene& s, double h, long steps) {
  auto particle = make_particle<R, D, P>(s, h);
  std::vector<reference::Sample> samples;
  samples.reserve(static_cast<std::size_t>(steps) + 1);
  samples.push_back({widen(particle.position()), widen(particle.velocity())});
  const R frame = static_cast<R>(h);
  for (long n = 0; n < steps; ++n) {
    step(particle, s, frame);
    samples.push_back({widen(particle.position()), widen(particle.velocity())});
  }
  return samples;
}

inline long steps_for(const Scene& s, double h) { return std::lround(s.duration / h); }

/// Far from the origin: free flight at (10, 0, 5) m/s from (1e6, 0, 0) m for `steps` steps of
/// h = 1/60 s, flown in float and in double. Returns the final positions (in double).
struct FarFlight {
  Vector3<double> single;  ///< the float particle's
  Vector3<double> twin;    ///< the double particle's
  double h = 0;            ///< the step, s
};
inline FarFlight fly_far_from_origin(long steps) {
  const double h = 1.0 / 60;
  Particle<float, damping::None, position::Euler> single;
  Particle<double, damping::None, position::Euler> twin;
  single.set_position({1e6f, 0.0f, 0.0f});
  twin.set_position({1e6, 0.0, 0.0});
  single.set_velocity({10.0f, 0.0f, 5.0f});
  twin.set_velocity({10.0, 0.0, 5.0});
  for (long n = 0; n < steps; ++n) {
    single.integrate(static_cast<float>(h));
    twin.integrate(h);
  }
  return {widen(single.position()), twin.position(), h};
}

/// The reference for combination D on scene s: the closed form without a spring, Odeint
/// otherwise.
template <class D>
std::vector<reference::Sample> reference_trajectory(const Scene& s, double h, long steps) {
  const auto model = model_of<D>(s);
  if (s.has_spring()) return reference::odeint_trajectory(model, s.start_position, s.start_velocity, h, steps);
  std::vector<reference::Sample> samples;
  samples.reserve(static_cast<std::size_t>(steps) + 1);
  for (long n = 0; n <= steps; ++n) {
    samples.push_back(reference::analytic_ballistic(s.start_position, s.start_velocity, s.gravity,
                                                    model.damping_rate,
                                                    static_cast<double>(n) * h));
  }
  return samples;
}

/// Global error: the largest distance between the samples' positions (or velocities).
struct GlobalError {
  double position = 0;  ///< m
  double velocity = 0;  ///< m/s
};
inline GlobalError global_error(const std::vector<reference::Sample>& a,
                                const std::vector<reference::Sample>& b) {
  GlobalError e;
  for (std::size_t n = 0; n < std::min(a.size(), b.size()); ++n) {
    e.position = std::max(e.position, magnitude(a[n].position - b[n].position));
    e.velocity = std::max(e.velocity, magnitude(a[n].velocity - b[n].velocity));
  }
  return e;
}

/// The largest |p| and |v| along a trajectory.
struct Extent {
  double position = 0;
  double velocity = 0;
};
inline Extent extent(const std::vector<reference::Sample>& samples) {
  Extent e;
  for (const auto& s : samples) {
    e.position = std::max(e.position, magnitude(s.position));
    e.velocity = std::max(e.velocity, magnitude(s.velocity));
  }
  return e;
}

/// Observed order between errors at steps h and h / 2.
inline double observed_order(double error_h, double error_half) {
  return std::log2(error_h / error_half);
}

/// A bound on the global position error of a first-order combination at frame time h,
/// derived from its local truncation error (see docs/accuracy.md, "How the test bounds are
/// derived"). Every first-order combination's local error per step, to leading order, is
/// at most
///   position  h^2/2 (|a| + |k| V)        velocity  h^2/2 (|a'| + |k| |a|)
/// with a the resulting acceleration (without damping), a' its rate of change (a spring
/// changes it), k the damping rate and V, P the largest speed and distance. The factor 2
/// covers the O(h^3) remainder at the frame times used (omega h, |k| h < 0.25).
///   Without a spring: the velocity error decays (k <= 0) and reaches the position through
///   the remaining time, so |e_p(T)| <= N (tau_p + tau_v T) = T h/2 (A + |k| V + (A' + |k| A) T).
///   With a spring: in the norm max(omega |p|, |v|) the model is Lipschitz with
///   L = sqrt(2) (omega + |k| + c/m), so |e| <= tau (e^{LT} - 1) / (L h), and |e_p| <= |e| / omega.
inline double first_order_bound(const Scene& s, double k, const Extent& x, double h) {
  const double omega = s.angular_frequency();
  const double friction = s.friction / s.mass;
  const double speed = x.velocity, distance = x.position;
  const double acceleration = magnitude(s.gravity) + omega * omega * distance + friction * speed;
  const double jerk = omega * omega * speed + friction * (acceleration + std::abs(k) * speed);
  const double tau_p = h * h / 2 * (acceleration + std::abs(k) * speed);
  const double tau_v = h * h / 2 * (jerk + std::abs(k) * acceleration);
  const double T = s.duration;
  if (!s.has_spring()) return 2 * (T / h) * (tau_p + tau_v * T);
  const double L = std::sqrt(2.0) * (omega + std::abs(k) + friction);
  const double tau = std::max(omega * tau_p, tau_v) * std::sqrt(2.0);
  return 2 * tau * std::expm1(L * T) / (L * h) / omega;
}

/// A bound on the extra position error of a float run over a double one, N steps:
/// each step rounds the position update (p + v h, up to three operations and the rounding of
/// h itself) by at most 4 eps (|p| + |v| h), and the velocity update (v d^t + a t, with powf's
/// error of at most 2 ulps) by at most 6 eps (|v| + |a| h); a velocity error made at step n
/// moves the position by at most that error times the time left. Summed without cancellation:
///   N (4 eps (P + V h) + 6 eps (V + A h) T),   eps = 2^-23.
/// With a spring the errors also feed back through the force: multiply by e^{L T} as above.
inline double float_rounding_bound(const Scene& s, double k, const Extent& x, double h) {
  const double eps = static_cast<double>(std::numeric_limits<float>::epsilon());
  const double omega = s.angular_frequency();
  const double friction = s.friction / s.mass;
  const double acceleration = magnitude(s.gravity) + omega * omega * x.position + friction * x.velocity;
  const double T = s.duration, N = T / h;
  double bound = N * (4 * eps * (x.position + x.velocity * h) +
                      6 * eps * (x.velocity + acceleration * h) * T);
  if (s.has_spring()) bound *= std::exp(std::sqrt(2.0) * (omega + std::abs(k) + friction) * T);
  return bound;
}

// --- energy and stability --------------------------------------------------------------------

/// Mechanical energy of a spring scene: m v^2 / 2 + K p^2 / 2.
inline double energy(const Scene& s, const reference::Sample& x) {
  return s.mass * square_magnitude(x.velocity) / 2 + s.stiffness * square_magnitude(x.position) / 2;
}

/// Relative energy change over the scene: (E(T) - E(0)) / E(0).
template <Real R, class D, class P>
double energy_drift(const Scene& s, double h) {
  const auto samples = simulate<R, D, P>(s, h, steps_for(s, h));
  return energy(s, samples.back()) / energy(s, samples.front()) - 1;
}

/// Whether the spring run of `steps` steps at omega h = r stays bounded: the largest energy
/// of the second half of the run is at most twice that of the first half. Stops early (and
/// says unbounded) when the energy passes 1e12 times its start.
template <class D, class P>
bool bounded_at(Scene s, double r, long steps) {
  const double h = r / s.angular_frequency();
  s.duration = h * static_cast<double>(steps);
  auto particle = make_particle<double, D, P>(s, h);
  const double start = energy(s, {widen(particle.position()), widen(particle.velocity())});
  double first_half = 0, second_half = 0;
  for (long n = 0; n < steps; ++n) {
    step(particle, s, h);
    const double e = energy(s, {particle.position(), particle.velocity()});
    if (!(e < 1e12 * start)) return false;
    (n < steps / 2 ? first_half : second_half) = std::max(n < steps / 2 ? first_half : second_half, e);
  }
  return second_half <= 2 * first_half;
}

/// The stability limit in omega h: bisection between 0 and 4 on `bounded_at`, to 1e-6.
/// A combination unbounded at every step tried reports the smallest step it could resolve.
template <class D, class P>
double stability_limit(const Scene& s, long steps) {
  double stable = 0, unstable = 4;
  if (bounded_at<D, P>(s, unstable, steps)) return unstable;
  while (unstable - stable > 1e-6) {
    const double middle = (stable + unstable) / 2;
    (bounded_at<D, P>(s, middle, steps) ? stable : unstable) = middle;
  }
  return stable;
}

// --- tables ----------------------------------------------------------------------------------

inline std::string format(const char* pattern, double value) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, pattern, value);
  return buffer;
}

/// The error table of one scene, as Markdown: for every combination the largest position
/// error (m) against the reference at each standard frame time, in double (and float at
/// 1/60 s), and the observed order between consecutive frame times ("exact" where the step
/// is the model's exact flow and the error is rounding).
inline std::string error_table(const Scene& s) {
  std::string out = "| combination |";
  for (const double h : scenes::standard_frame_times) out += format(" h = 1/%.0f s |", 1 / h);
  out += " order (30/60, 60/120, 120/240) | float, 1/60 s |\n|---|";
  for (std::size_t i = 0; i < scenes::standard_frame_times.size(); ++i) out += "---:|";
  out += "---|---:|\n";
  for_each_combination([&]<class D, class P>() {
    out += "| " + combination_name<D, P>() + " |";
    std::vector<double> errors;
    double float_error = 0;
    for (const double h : scenes::standard_frame_times) {
      const long steps = steps_for(s, h);
      const auto ref = reference_trajectory<D>(s, h, steps);
      errors.push_back(global_error(simulate<double, D, P>(s, h, steps), ref).position);
      if (h == scenes::standard_frame_times[1]) {
        float_error = global_error(simulate<float, D, P>(s, h, steps), ref).position;
      }
      out += format(" %.2e |", errors.back());
    }
    if (is_exact_for<D, P>(s)) {
      out += " exact |";
    } else {
      out += " ";
      for (std::size_t i = 1; i < errors.size(); ++i) {
        out += format(i == 1 ? "%.2f" : ", %.2f", observed_order(errors[i - 1], errors[i]));
      }
      out += " |";
    }
    out += format(" %.2e |\n", float_error);
  });
  return out;
}

}  // namespace pointmass::accuracy
