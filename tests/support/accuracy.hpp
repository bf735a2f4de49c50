// SPDX-License-Identifier: BSL-1.0
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
#include <utility>
#include <vector>

#include <pointmass/damping.hpp>
#include <pointmass/extras/scenes.hpp>
#include <pointmass/particle.hpp>
#include <pointmass/position.hpp>
#include <pointmass/precision.hpp>
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
  /// Where the scene's frame sits in the world: the particle is launched from offset +
  /// start_position, and its samples are taken relative to offset (exactly, in double), so
  /// the continuous reference is computed near the origin and is not limited by double's
  /// resolution at the offset. The spring is anchored at offset.
  Vector3<double> offset{};

  bool has_spring() const { return stiffness != 0 || friction != 0; }
  double angular_frequency() const { return std::sqrt(stiffness / mass); }
};

inline Vector3<double> to_double(const Vector3<double>& v) { return v; }

/// Cyclone's four ballistic shots (scene 2), 5 s from (0, 1.5, 0).
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

/// The ballistic shots launched far from the origin: from offset + (0, 1.5, 0), by default
/// 1e6 m out along every axis (the shots move in y and z), where a float resolves 1/16 m.
inline std::vector<Scene> far_ballistic_scenes(const Vector3<double>& offset = {1e6, 1e6, 1e6}) {
  auto scenes = ballistic_scenes();
  for (auto& s : scenes) {
    s.name += " far from the origin";
    s.offset = offset;
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
inline Scene spring(bool damped, double duration,
                    double stiffness = scenes::SpringScene<double>{}.stiffness) {
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
  else if constexpr (std::is_same_v<P, position::ConstantAcceleration>)
    return "ConstantAcceleration";
  else if constexpr (std::is_same_v<P, position::SemiImplicit>) return "SemiImplicit";
  else if constexpr (std::is_same_v<P, position::VelocityVerlet>) return "VelocityVerlet";
  else return "Exact";
}
template <class D, class P>
std::string combination_name() {
  return std::string(damping_name<D>()) + " + " + position_name<P>();
}

/// The name of a precision choice (the first template argument of Particle): "float",
/// "double", "float/double-pos" (Precision<float, double>), "float/compensated-pos"
/// (Precision<float, Compensated<float>>).
template <class S>
std::string precision_name() {
  using R = real_of_t<S>;
  using Position = position_precision_of_t<S>;
  const std::string real = std::is_same_v<R, float>    ? "float"
                           : std::is_same_v<R, double> ? "double"
                                                       : "long-double";
  if constexpr (std::is_same_v<R, Position>) return real;
  else if constexpr (detail::is_compensated_v<Position>) return real + "/compensated-pos";
  else return real + (std::is_same_v<Position, double> ? "/double-pos" : "/long-double-pos");
}
/// A variant's name: precision, damping + position ("float/double-pos Exact + Exact").
template <class S, class D, class P>
std::string variant_name() {
  return precision_name<S>() + " " + combination_name<D, P>();
}

/// The position precisions beside float and double that the run-time-against-error sweep
/// covers (Precision<float, double> and Precision<float, Compensated<float>>), each with the
/// policy pairs that matter for them (for_each_wide_combination).
using FloatWithDoublePositions = Precision<float, double>;
using FloatWithCompensatedPositions = Precision<float, Compensated<float>>;

/// Calls f.template operator()<D, P>() for the pairs the wide-position variants are swept
/// with: the default (PerSecond + Euler) and the exact pair (Exact + Exact).
template <class F>
void for_each_wide_combination(F&& f) {
  f.template operator()<damping::PerSecond, position::Euler>();
  f.template operator()<damping::Exact, position::Exact>();
}

/// Calls f.template operator()<D, P>() for every valid combination (17: position::Exact
/// needs damping::None or damping::Exact).
template <class F>
void for_each_combination(F&& f) {
  const auto with_damping = [&]<class D>() {
    f.template operator()<D, position::Euler>();
    f.template operator()<D, position::ConstantAcceleration>();
    f.template operator()<D, position::SemiImplicit>();
    if constexpr (std::is_same_v<D, damping::None> || std::is_same_v<D, damping::Exact>) {
      f.template operator()<D, position::Exact>();
    }
    if constexpr (!std::is_same_v<D, damping::AccelerateThenDamp>) {
      f.template operator()<D, position::VelocityVerlet>();
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

/// The particle's position relative to `offset`, in double: exact for a position within a
/// factor of two of the offset (then the difference is a double), and for a compensated
/// position hi + lo computed as (hi - offset) + lo, so lo is not rounded away at the offset.
template <class S, class D, class P>
Vector3<double> relative_position(const Particle<S, D, P>& particle,
                                  const Vector3<double>& offset) {
  if constexpr (requires { particle.stored_position_error(); }) {
    return (widen(particle.stored_position()) - offset) + widen(particle.stored_position_error());
  } else {
    return widen(particle.position()) - offset;
  }
}

/// A particle of combination (S, D, P) set up for scene s at frame time h (S a Real, or a
/// Precision<Real, Position>): launched from s.offset + s.start_position.
template <class S, class D, class P>
Particle<S, D, P> make_particle(const Scene& s, double h) {
  using R = real_of_t<S>;
  using Position = typename Particle<S, D, P>::position_type;
  Particle<S, D, P> particle;
  particle.set_position(cast<Position>(s.offset + s.start_position));
  particle.set_velocity(cast<R>(s.start_velocity));
  particle.set_acceleration(cast<R>(s.gravity));
  particle.set_mass(static_cast<R>(s.mass));
  if constexpr (Particle<S, D, P>::stores_damping) {
    // PerFrame: the fraction kept per frame that removes the scene's per-second fraction.
    const double d = std::is_same_v<D, damping::PerFrame> ? std::pow(s.damping, h) : s.damping;
    particle.set_damping(static_cast<R>(d));
  }
  return particle;
}

/// One frame: the scene's spring and friction forces (from the state at the start of the
/// frame, the spring from the position relative to s.offset) through add_force, then
/// integrate(h).
template <class S, class D, class P>
void step(Particle<S, D, P>& particle, const Scene& s, real_of_t<S> h) {
  using R = real_of_t<S>;
  if (s.has_spring()) {
    const Vector3<R> force =
        cast<R>(relative_position(particle, s.offset)) * static_cast<R>(-s.stiffness) +
        particle.velocity() * static_cast<R>(-s.friction);
    particle.add_force(force);
  }
  particle.integrate(h);
}

/// The particle's samples at n h, n = 0 .. steps; positions relative to s.offset.
template <class S, class D, class P>
std::vector<reference::Sample> simulate(const Scene& s, double h, long steps) {
  using R = real_of_t<S>;
  auto particle = make_particle<S, D, P>(s, h);
  std::vector<reference::Sample> samples;
  samples.reserve(static_cast<std::size_t>(steps) + 1);
  samples.push_back({relative_position(particle, s.offset), widen(particle.velocity())});
  const R frame = static_cast<R>(h);
  for (long n = 0; n < steps; ++n) {
    step(particle, s, frame);
    samples.push_back({relative_position(particle, s.offset), widen(particle.velocity())});
  }
  return samples;
}

inline long steps_for(const Scene& s, double h) { return std::lround(s.duration / h); }

/// Far from the origin: free flight at (10, 0, 5) m/s from (1e6, 0, 0) m for `steps` steps of
/// h = 1/60 s, flown in float and in double. Returns the final positions (in double).
/// Also flown: float with double positions and with compensated positions
/// (Precision<float, double>, Precision<float, Compensated<float>>), and `exact`, the exact
/// sum of the float steps (each step's float displacement, summed in long double).
struct FarFlight {
  Vector3<double> single;  ///< the float particle's
  Vector3<double> twin;    ///< the double particle's
  double h = 0;            ///< the step, s
  Vector3<double> wide;    ///< the float particle's with double positions
  Vector3<double> pair;    ///< the float particle's with compensated positions
  Vector3<double> exact;   ///< the exact sum of the float steps (rounded to double at the end)
};
inline FarFlight fly_far_from_origin(long steps) {
  const double h = 1.0 / 60;
  Particle<float, damping::None, position::Euler> single;
  Particle<double, damping::None, position::Euler> twin;
  Particle<Precision<float, double>, damping::None, position::Euler> wide;
  Particle<Precision<float, Compensated<float>>, damping::None, position::Euler> pair;
  single.set_position({1e6f, 0.0f, 0.0f});
  twin.set_position({1e6, 0.0, 0.0});
  wide.set_position({1e6, 0.0, 0.0});
  pair.set_position({1e6, 0.0, 0.0});
  single.set_velocity({10.0f, 0.0f, 5.0f});
  twin.set_velocity({10.0, 0.0, 5.0});
  wide.set_velocity({10.0f, 0.0f, 5.0f});
  pair.set_velocity({10.0f, 0.0f, 5.0f});
  long double exact_x = 1e6L, exact_z = 0.0L;
  for (long n = 0; n < steps; ++n) {
    single.integrate(static_cast<float>(h));
    twin.integrate(h);
    wide.integrate(static_cast<float>(h));
    pair.integrate(static_cast<float>(h));
    exact_x += static_cast<long double>(10.0f * static_cast<float>(h));  // Euler: v t in float
    exact_z += static_cast<long double>(5.0f * static_cast<float>(h));
  }
  return {widen(single.position()),
          twin.position(),
          h,
          wide.position(),
          pair.position(),
          {static_cast<double>(exact_x), 0.0, static_cast<double>(exact_z)}};
}

/// The reference for combination D on scene s: the closed form without a spring, Odeint
/// otherwise; in the scene's frame (relative to s.offset, as simulate's samples are).
template <class D>
std::vector<reference::Sample> reference_trajectory(const Scene& s, double h, long steps) {
  const auto model = model_of<D>(s);
  if (s.has_spring())
    return reference::odeint_trajectory(model, s.start_position, s.start_velocity, h, steps);
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

// --- convergence bounds ------------------------------------------------------------------------
//
// The error of a combination of order p at frame time h is C h^p plus higher-order terms. As
// Boost.Odeint's own convergence tests do (libs/numeric/odeint/test/numeric/runge_kutta.cpp),
// C is calibrated at the coarsest step h0 and every finer step is held to
//   e(h) <= M e(h0) (h / h0)^p,   M = convergence_margin = 2.
// Why 2: a pre-asymptotic error may still lose up to a factor M of its constant as the step
// shrinks (an observed order down to p - log2(M) / 3 over the three halvings from 1/30 to
// 1/240 s), but a method of order p - 1 (a wrong formula that no longer follows the model to
// order p) has e(h0 / 4) = 4 e(h0) (1/4)^p, twice the bound, and fails at the second halving.
// The observed order of each halving is held separately (order_tolerance).

inline constexpr double convergence_margin = 2;

/// Every halving's observed order is within order_tolerance of the pair's order_v...
inline constexpr double order_tolerance = 0.1;
/// ...except on a spring scene while the explicit forms' energy growth omega^2 h T / 2 exceeds
/// pre_asymptotic_growth (the 1 s spring at 1/30 and 1/60 s: 0.66 and 0.33), where the error
/// still shrinks faster than h^p: there the order may exceed p by up to pre_asymptotic_excess.
/// The finest halving is always held to order_tolerance.
inline constexpr double pre_asymptotic_growth = 0.2;
inline constexpr double pre_asymptotic_excess = 0.3;

/// The bound on the error at step h, from the error at the coarsest step h0 (see above).
inline double convergence_bound(double coarse_error, double coarse_h, double h, int order) {
  return convergence_margin * coarse_error * std::pow(h / coarse_h, order);
}

/// The interval the observed order of the halving from h to h / 2 must lie in, for a pair of
/// order p on scene s; `finest` is true for the last halving tried.
struct OrderInterval {
  double low = 0, high = 0;
};
inline OrderInterval order_interval(const Scene& s, double h, int order, bool finest) {
  const double growth = s.stiffness / s.mass * h * s.duration / 2;
  const double excess = s.has_spring() && growth > pre_asymptotic_growth && !finest
                            ? pre_asymptotic_excess
                            : order_tolerance;
  return {order - order_tolerance, order + excess};
}

/// The one-step map's linear part in (p, v) along one axis: the double step of combination
/// (D, P) on scene s without its constant acceleration, from (1, 0) and (0, 1). Every step is
/// affine in (p, v) with the same linear part on each axis (the spring and friction forces are
/// linear, and the constant acceleration only adds), so a perturbation e of the state grows
/// into M^k e after k more steps.
struct StepMatrix {
  double pp = 1, pv = 0, vp = 0, vv = 1;
};
template <class D, class P>
StepMatrix step_matrix(const Scene& s, double h) {
  Scene linear = s;
  linear.gravity = {};
  const auto image = [&](const Vector3<double>& p, const Vector3<double>& v) {
    auto particle = make_particle<double, D, P>(linear, h);
    particle.set_position(p);
    particle.set_velocity(v);
    step(particle, linear, h);
    return std::pair{particle.position().x, particle.velocity().x};
  };
  const auto [pp, vp] = image({1, 0, 0}, {});
  const auto [pv, vv] = image({}, {1, 0, 0});
  return {pp, pv, vp, vv};
}

/// A bound on how far a float run's positions move from the double run's, over the scene at
/// frame time h. Each rounded operation errs by at most u = 2^-24 of its result. A step rounds
/// the position update (p + v h and the a h^2 / 2 term: the product, the sums, and h itself)
/// by at most r_p = 4 u (P + V h), and the velocity update (v d^t + a t: the damping factor,
/// whose powf or expm1 is within 2 ulps = 4 u, its product, the force and a t, the sum) by at
/// most r_v = 8 u (V + A h), with P, V, A the largest distance, speed and acceleration. An
/// error made k steps before the end has moved the position by (M^k)_pp r_p + (M^k)_pv r_v
/// (M the step's own linear part, step_matrix), so, the rounding of the start values included
/// (k = N) and summed without cancellation,
///   R = sum_{k <= N} |(M^k)_pp| r_p + |(M^k)_pv| r_v.
/// Without a spring (M^k)_pv is at most k h (a velocity error carried for the time left);
/// with one M^k follows the method's own energy growth, not a Lipschitz estimate of the model.
/// Roundings mostly cancel, so the float runs' observed distance from the double runs stays
/// well below R.
template <class D, class P>
double float_rounding_bound(const Scene& s, const Extent& x, double h) {
  const double u = static_cast<double>(std::numeric_limits<float>::epsilon()) / 2;
  const double omega = s.angular_frequency();
  const double acceleration =
      magnitude(s.gravity) + omega * omega * x.position + s.friction / s.mass * x.velocity;
  const double round_p = 4 * u * (x.position + x.velocity * h);
  const double round_v = 8 * u * (x.velocity + acceleration * h);
  const StepMatrix m = step_matrix<D, P>(s, h);
  StepMatrix power;  // M^k
  double sum_pp = 0, sum_pv = 0;
  for (long k = 0; k <= steps_for(s, h); ++k) {
    sum_pp += std::abs(power.pp);
    sum_pv += std::abs(power.pv);
    power = {m.pp * power.pp + m.pv * power.vp, m.pp * power.pv + m.pv * power.vv,
             m.vp * power.pp + m.vv * power.vp, m.vp * power.pv + m.vv * power.vv};
  }
  return sum_pp * round_p + sum_pv * round_v;
}

/// Rounding of the double runs of an exact combination: a few ulps per step of the largest
/// value, over N steps (N eps (P + V T) with 8 eps per step, as in float_rounding_bound).
inline double double_rounding_bound(const Extent& x, double T, double h) {
  const double eps = std::numeric_limits<double>::epsilon();
  return (T / h) * 8 * eps * (x.position + x.velocity * T);
}

// --- energy and stability --------------------------------------------------------------------

/// Mechanical energy of a spring scene: m v^2 / 2 + K p^2 / 2.
inline double energy(const Scene& s, const reference::Sample& x) {
  return s.mass * square_magnitude(x.velocity) / 2 + s.stiffness * square_magnitude(x.position) / 2;
}

/// The largest relative energy error over the scene, max |E(t) - E(0)| / E(0), from the
/// position and velocity read after every step.
template <Real R, class D, class P>
double energy_error(const Scene& s, double h) {
  const auto samples = simulate<R, D, P>(s, h, steps_for(s, h));
  const double start = energy(s, samples.front());
  double largest = 0;
  for (const auto& x : samples) largest = std::max(largest, std::abs(energy(s, x) / start - 1));
  return largest;
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
    (n < steps / 2 ? first_half : second_half) =
        std::max(n < steps / 2 ? first_half : second_half, e);
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
