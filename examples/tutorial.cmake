# SPDX-License-Identifier: BSL-1.0
if(POINTMASS_BUILD_TESTS)
  # The program checks each part against values worked apart from it (the closed forms of
  # the ball's and the shell's motion, the sparks left after 1 s and their height, the bob's
  # rest position, the sparks of the burst) and prints "FAILED: ..." and exits 1 at the
  # first that does not hold.
  add_test(NAME example.tutorial COMMAND tutorial)
  set_tests_properties(example.tutorial PROPERTIES
    PASS_REGULAR_EXPRESSION "tutorial: all checks passed"
    FAIL_REGULAR_EXPRESSION "FAILED")
  # docs/tutorial.md quotes the program: every cpp block of it verbatim.
  add_test(NAME docs.quotes.docs/tutorial.md
    COMMAND ${CMAKE_COMMAND} -DDOCUMENT=${PROJECT_SOURCE_DIR}/docs/tutorial.md
            -DSOURCES=${CMAKE_CURRENT_SOURCE_DIR}/tutorial.cpp
            -P ${PROJECT_SOURCE_DIR}/cmake/CheckQuoted.cmake)
endif()
