# SPDX-License-Identifier: BSL-1.0
if(POINTMASS_BUILD_TESTS)
  # Where each round ends at 1/60 s, from the closed form p0 + v0 t phi1(kt) + a t^2 phi2(kt)
  # worked apart from the program: pistol lands at step 105 (t = 1.75 s, z = 60.715 m),
  # artillery at step 183 (3.05 s, 120.149 m), the fireball still flies at 5 s
  # (y = 7.840, z = 38.868 m) and the laser leaves the range at step 122 (201.270 m).
  add_test(NAME example.ballistics COMMAND ballistics)
  set_tests_properties(example.ballistics PROPERTIES PASS_REGULAR_EXPRESSION
    "pistol +lands +at t = 1\\.750 s: x 0\\.000 y -0\\.022 z 60\\.715 m\nartillery +lands +at t = 3\\.050 s: x 0\\.000 y -0\\.470 z 120\\.149 m\nfireball +still flying +at t = 5\\.000 s: x 0\\.000 y 7\\.840 z 38\\.868 m\nlaser +out of range +at t = 2\\.033 s: x 0\\.000 y 1\\.500 z 201\\.270 m")
endif()
