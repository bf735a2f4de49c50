# SPDX-License-Identifier: BSL-1.0
if(POINTMASS_BUILD_TESTS)
  # The shell climbs from 1.5 m at 30 m/s under 20 m/s^2 for 1 s: about 1.5 + 30 - 10 = 21.5 m
  # up (less with drag and the short position update: 20 to 22 m), and about 40 m along z.
  add_test(NAME example.quick_start COMMAND quick_start)
  set_tests_properties(example.quick_start PROPERTIES
    PASS_REGULAR_EXPRESSION "after 1 s: x 0\\.000 y 2[01]\\.[0-9]+ z 39\\.[0-9]+ m")
  # The README and docs/examples.md quote the examples: they must not drift apart.
  file(GLOB _example_sources "${CMAKE_CURRENT_SOURCE_DIR}/*.cpp")
  foreach(document IN ITEMS README.md docs/examples.md)
    add_test(NAME docs.quotes.${document}
      COMMAND ${CMAKE_COMMAND} -DDOCUMENT=${PROJECT_SOURCE_DIR}/${document}
              "-DSOURCES=${_example_sources}" -P ${PROJECT_SOURCE_DIR}/cmake/CheckQuoted.cmake)
  endforeach()
endif()
