# SPDX-License-Identifier: BSL-1.0
if(POINTMASS_BUILD_TESTS)
  # Sizes worked out by hand: four 3-vectors and the inverse mass are 13 numbers; a damping
  # value adds one, the exact policy's ln d another. A system stores 6 numbers per particle
  # (position, velocity), +3 for Lifetime (age, its rounding, fuse), +4 for Forces (1/m, f), +3 for
  # per-particle acceleration, +1 for per-particle per-second damping.
  add_test(NAME example.variants COMMAND variants --quick)
  set_tests_properties(example.variants PROPERTIES PASS_REGULAR_EXPRESSION
    "float, +damping::None, +position::Euler +> +52 bytes.*float, +damping::PerSecond, +position::Euler +> +72 bytes.*float, +damping::Exact, +position::Exact +> +80 bytes.*double, +damping::None, +position::Euler +> +104 bytes.*double, +damping::Exact, +position::Exact +> +160 bytes.*Euler +> +24 bytes per particle,  6 arrays.*Lifetime +> +36 bytes.*ForceAccumulator +> +40 bytes.*PerParticleAcceleration +> +36 bytes.*PerParticleDamping +> +40 bytes.*all four +> +80 bytes per particle, 20 arrays")
endif()
