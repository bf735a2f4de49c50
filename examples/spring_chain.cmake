# SPDX-License-Identifier: BSL-1.0
# The spring chain checks its own rest state against the equilibrium worked by hand and
# prints "equilibrium: PASS" only when every particle is within 1 mm of it.
if(POINTMASS_BUILD_TESTS)
  add_test(NAME example.spring_chain COMMAND spring_chain)
  set_tests_properties(example.spring_chain PROPERTIES
    PASS_REGULAR_EXPRESSION "equilibrium: PASS"
    FAIL_REGULAR_EXPRESSION "equilibrium: FAIL")
endif()
