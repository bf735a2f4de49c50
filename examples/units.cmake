# SPDX-License-Identifier: BSL-1.0
# examples/units.cpp needs Boost.Units (pointmass::units). Smoke test: every shot is reported.
target_link_libraries(units PRIVATE pointmass::units)
if(POINTMASS_BUILD_TESTS)
  add_test(NAME example.units COMMAND units)
  set_tests_properties(example.units PROPERTIES
    PASS_REGULAR_EXPRESSION "pistol.*artillery.*fireball.*laser.*y = [-0-9.e]+ m, vy = [-0-9.e]+ m s\\^-1")
endif()
