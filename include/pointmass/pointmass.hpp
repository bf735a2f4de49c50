// SPDX-License-Identifier: BSL-1.0
// pointmass/pointmass.hpp — the umbrella header: the whole library but the Boost.Units face,
// standard library only. (Boost.Units support is apart, in <pointmass/units.hpp>.)
//
// Owns: nothing but the list of core headers.
// Must not include: units.hpp (Boost), parallel.hpp (<execution>), kokkos.hpp, extras/.
#pragma once

#include "config.hpp"
#include "damping.hpp"
#include "denormals.hpp"
#include "features.hpp"
#include "fixed_step.hpp"
#include "forces.hpp"
#include "gravity.hpp"
#include "particle.hpp"
#include "particle_system.hpp"
#include "position.hpp"
#include "quantities.hpp"
#include "real.hpp"
#include "snapshot.hpp"
#include "trajectory.hpp"
#include "vector3.hpp"
