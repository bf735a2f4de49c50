# SPDX-License-Identifier: BSL-1.0
if(POINTMASS_BUILD_TESTS)
  # The program checks its own accounting (spawned = burnt out + live; each spark burns out
  # with the fuse and colour it was spawned with, found by its serial number, and its fuse in
  # its type's range); the test also needs bursts to have happened and sparks to be alive.
  add_test(NAME example.fireworks COMMAND fireworks --seconds 6 --seed 7)
  set_tests_properties(example.fireworks PROPERTIES
    PASS_REGULAR_EXPRESSION "live [1-9][0-9]*, bursts [1-9][0-9]*\naccounting: ok"
    FAIL_REGULAR_EXPRESSION "FAILED")
endif()
