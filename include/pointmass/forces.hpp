// SPDX-License-Identifier: BSL-1.0
// pointmass/forces.hpp — force generators and the registry that applies them each step: the
// umbrella of include/pointmass/forces/. What each generator computes, where Cyclone's
// differ, the ranges, the stiff spring and the registry's ownership rules:
// docs/forces.md.
//
//   forces/bodies.hpp      what a generator acts on: PlainBody, SteppableBody, Bodies concepts;
//                          SpanBodies and SoaBodies adapters; relative_to (a particle or
//                          system with wide positions, seen from a local origin)
//   forces/apply.hpp       FieldGenerator; update_force(generator, body, t); apply(generator,
//                          bodies, t)
//   forces/generators.hpp  Gravity, Drag, AnchoredSpring/Bungee, Spring/Bungee, Buoyancy,
//                          LinkSprings/LinkBungees and apply_links
//   forces/oscillator.hpp  damped_oscillator (closed form), StiffSpring (integrate: exact step),
//                          PositionOnlyStiffSpring (Cyclone's force form)
//   forces/registry.hpp    ForceRegistry (owning and non-owning registrations)
//   detail/validate.hpp       the argument checks (shared with Particle and ParticleSystem)
//
// Owns: nothing but the list of forces headers (standard library only).
// Must not include: particle.hpp or particle_system.hpp (the generators are written against
// the body concepts).
#pragma once

#include "forces/apply.hpp"
#include "forces/bodies.hpp"
#include "forces/generators.hpp"
#include "forces/laws.hpp"
#include "forces/oscillator.hpp"
#include "forces/registry.hpp"
