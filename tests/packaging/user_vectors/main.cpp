// SPDX-License-Identifier: BSL-1.0
// The user's own vector types go in and out of the library: glm's (x, y, z members: nothing
// to write), Eigen's (operator() access: a VectorTraits specialisation), and a plain struct.
#include <pointmass/pointmass.hpp>

#include <Eigen/Core>
#include <glm/vec3.hpp>

#include <cstdio>
#include <cstring>
#include <type_traits>

namespace pm = pointmass;

// Eigen reads its elements with operator(): the user says so once.
template <>
struct pointmass::VectorTraits<Eigen::Vector3d> {
  using value_type = double;
  static double x(const Eigen::Vector3d& v) { return v(0); }
  static double y(const Eigen::Vector3d& v) { return v(1); }
  static double z(const Eigen::Vector3d& v) { return v(2); }
  static Eigen::Vector3d make(double x, double y, double z) { return {x, y, z}; }
};
template <>
struct pointmass::VectorTraits<Eigen::Vector3f> {
  using value_type = float;
  static float x(const Eigen::Vector3f& v) { return v(0); }
  static float y(const Eigen::Vector3f& v) { return v(1); }
  static float z(const Eigen::Vector3f& v) { return v(2); }
  static Eigen::Vector3f make(float x, float y, float z) { return {x, y, z}; }
};

namespace {

struct Engine {  // a game's own vector
  float x, y, z;
};

// Implicit where nothing is lost, explicit where the numbers narrow.
static_assert(std::is_convertible_v<glm::vec3, pm::Vector3<float>>);
static_assert(std::is_convertible_v<glm::vec3, pm::Vector3<double>>);
static_assert(std::is_convertible_v<pm::Vector3<float>, glm::vec3>);
static_assert(std::is_convertible_v<pm::Vector3<float>, glm::dvec3>);
static_assert(!std::is_convertible_v<glm::dvec3, pm::Vector3<float>>);
static_assert(std::is_constructible_v<pm::Vector3<float>, glm::dvec3>);
static_assert(!std::is_convertible_v<pm::Vector3<double>, glm::vec3>);
static_assert(!std::is_convertible_v<glm::ivec3, pm::Vector3<float>>);
static_assert(std::is_convertible_v<Eigen::Vector3f, pm::Vector3<double>>);
static_assert(std::is_convertible_v<pm::Vector3<double>, Eigen::Vector3d>);
static_assert(!std::is_convertible_v<Eigen::Vector3d, pm::Vector3<float>>);
// Not every type is a vector: the conversions are there only for types with traits.
static_assert(!std::is_convertible_v<float, pm::Vector3<float>>);
static_assert(!std::is_convertible_v<pm::Vector3<float>, bool>);
// Between the library's own precisions, the same rule as for a user's vectors: exact widening
// is implicit, rounding is explicit.
static_assert(std::is_convertible_v<pm::Vector3<float>, pm::Vector3<double>>);
static_assert(!std::is_convertible_v<pm::Vector3<double>, pm::Vector3<float>>);
static_assert(!std::is_convertible_v<Eigen::Vector2f, pm::Vector3<float>>);

// A conversion copies three numbers and nothing more: it runs at compile time, and the types
// stay trivially copyable.
constexpr pm::Vector3<float> from_engine = Engine{1.0f, 2.0f, 3.0f};
constexpr Engine back = from_engine;
static_assert(from_engine.x == 1.0f && from_engine.y == 2.0f && from_engine.z == 3.0f);
static_assert(back.x == 1.0f && back.y == 2.0f && back.z == 3.0f);
static_assert(std::is_trivially_copyable_v<pm::Vector3<float>>);

int failures = 0;

template <class A, class B>
void check_same_bits(const char* what, const A& a, const B& b) {
  static_assert(sizeof(a) == sizeof(b));
  if (std::memcmp(&a, &b, sizeof(a)) != 0) {
    std::printf("user_vectors: %s differs\n", what);
    ++failures;
  }
}

}  // namespace

int main() {
  // glm in: the particle fed glm vectors steps exactly as the one fed Vector3s.
  pm::Particle<float, pm::damping::PerSecond, pm::position::ConstantAcceleration> with_glm;
  with_glm.set_position(glm::vec3(0.0f, 1.5f, 0.0f));
  with_glm.set_velocity(glm::vec3(0.0f, 30.0f, 40.0f));
  with_glm.set_acceleration(glm::vec3(0.0f, -20.0f, 0.0f));
  with_glm.add_force(glm::vec3(5.0f, 0.0f, 0.0f));
  pm::Particle<float, pm::damping::PerSecond, pm::position::ConstantAcceleration> plain;
  plain.set_position({0.0f, 1.5f, 0.0f});
  plain.set_velocity({0.0f, 30.0f, 40.0f});
  plain.set_acceleration({0.0f, -20.0f, 0.0f});
  plain.add_force({5.0f, 0.0f, 0.0f});
  for (int frame = 0; frame < 30; ++frame) {
    with_glm.integrate(1.0f / 60);
    plain.integrate(1.0f / 60);
  }
  // glm out.
  const glm::vec3 position = with_glm.position();
  const glm::vec3 velocity = with_glm.velocity();
  const pm::Vector3<float> expected_position = plain.position();
  const pm::Vector3<float> expected_velocity = plain.velocity();
  check_same_bits("glm position", position, expected_position);
  check_same_bits("glm velocity", velocity, expected_velocity);
  if (!(position.y > 1.5f) || !(position.z > 0.0f)) {
    std::printf("user_vectors: the glm particle did not move as launched\n");
    ++failures;
  }

  // Eigen in and out, in double, and a float Eigen vector widened into a double particle.
  pm::Particle<double> with_eigen;
  with_eigen.set_position(Eigen::Vector3d(1.0, 2.0, 3.0));
  with_eigen.set_velocity(Eigen::Vector3f(0.5f, -0.25f, 0.125f));
  const Eigen::Vector3d eigen_position = with_eigen.position();
  const Eigen::Vector3d eigen_velocity = with_eigen.velocity();
  const double expected_eigen_position[3] = {1.0, 2.0, 3.0};
  const double expected_eigen_velocity[3] = {0.5, -0.25, 0.125};
  check_same_bits("Eigen position", *reinterpret_cast<const double(*)[3]>(eigen_position.data()),
                  expected_eigen_position);
  check_same_bits("Eigen velocity", *reinterpret_cast<const double(*)[3]>(eigen_velocity.data()),
                  expected_eigen_velocity);

  // Narrowing asks for a cast, and then converts each number.
  const pm::Vector3<float> narrowed = static_cast<pm::Vector3<float>>(glm::dvec3(0.1, 0.2, 0.3));
  const pm::Vector3<float> expected_narrowed{0.1f, 0.2f, 0.3f};
  check_same_bits("narrowed glm::dvec3", narrowed, expected_narrowed);
  const glm::vec3 narrowed_out = static_cast<glm::vec3>(pm::Vector3<double>{0.1, 0.2, 0.3});
  check_same_bits("narrowed to glm::vec3", narrowed_out, expected_narrowed);

  if (failures != 0) return 1;
  std::printf("user_vectors: ok\n");
  return 0;
}
