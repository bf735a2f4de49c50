// pointmass/pointmass.hpp — the umbrella header: the whole core, standard library only.
// (Boost.Units support is apart, in <pointmass/units.hpp>.)
#pragma once

#include "config.hpp"
#include "damping.hpp"
#include "forces.hpp"
#include "gravity.hpp"
#include "particle.hpp"
#include "position.hpp"
#include "quantities.hpp"
#include "real.hpp"
#include "vector3.hpp"
#include "scenes.hpp"
