// SPDX-License-Identifier: BSL-1.0
// The headers under nvcc -std=c++20: kernels that step Particles (every damping and position
// policy, float and double) and a ParticleSystem through its POINTMASS_HD step_particle,
// as a CUDA loop over the particles would. Compiled only (no GPU is needed): the test is that
// nvcc accepts device code calling the library, with warnings as errors.
#include <cstddef>

#include <pointmass/particle.hpp>
#include <pointmass/particle_system.hpp>

namespace {

using namespace pointmass;

template <class Body>
__global__ void step_particles(Body* bodies, int count, typename Body::real duration, int steps) {
  const int i = static_cast<int>(blockIdx.x * blockDim.x + threadIdx.x);
  if (i >= count) return;
  Body body = bodies[i];
  for (int k = 0; k < steps; ++k) {
    body.add_force({typename Body::real(0), typename Body::real(1), typename Body::real(0)});
    body.integrate(duration);
  }
  bodies[i] = body;
}

template <class System>
__global__ void step_system(typename System::StepView::Arrays arrays,
                            typename System::StepView::Parameters parameters) {
  const std::size_t i = blockIdx.x * static_cast<std::size_t>(blockDim.x) + threadIdx.x;
  if (i < arrays.size) System::StepView::step_particle(arrays, i, parameters);
}

template <class Body>
void launch_particles(Body* bodies, int count) {
  step_particles<Body><<<(count + 255) / 256, 256>>>(bodies, count, typename Body::real(1) / 60, 4);
}

template <class System>
void launch_system(System& system, typename System::real duration) {
  // On a real device the arrays would be copied to device memory first; the kernel is the
  // same either way.
  const auto count = static_cast<unsigned>(system.size());
  auto view = system.begin_step(duration);
  step_system<System><<<(count + 255) / 256, 256>>>(view.arrays(), view.parameters());
  system.finish_step(std::move(view));
}

template <class R>
void instantiate_all(Particle<R>* any) {
  launch_particles(reinterpret_cast<Particle<R, damping::None, position::Euler>*>(any), 1);
  launch_particles(reinterpret_cast<Particle<R, damping::None, position::Exact>*>(any), 1);
  launch_particles(
      reinterpret_cast<Particle<R, damping::PerFrame, position::ConstantAcceleration>*>(any), 1);
  launch_particles(reinterpret_cast<Particle<R, damping::PerSecond, position::Euler>*>(any), 1);
  launch_particles(
      reinterpret_cast<Particle<R, damping::AccelerateThenDamp, position::SemiImplicit>*>(any), 1);
  launch_particles(reinterpret_cast<Particle<R, damping::Exact, position::Exact>*>(any), 1);

  ParticleSystem<R> sparks(64);
  launch_system(sparks, R(1) / 60);
  ParticleSystem<R, damping::Exact, position::Exact, features::PerParticleDamping,
                 features::PerParticleAcceleration, features::ForceAccumulator, features::Lifetime>
      everything(64);
  launch_system(everything, R(1) / 60);
}

}  // namespace

int main() {
  // Not run (no GPU here); main exists so that the host side links.
  instantiate_all<float>(nullptr);
  instantiate_all<double>(nullptr);
  return 0;
}
