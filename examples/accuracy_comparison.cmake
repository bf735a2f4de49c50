# Smoke test: the table is complete and says what must be true of it — the exact pair and
# the full position update without damping are exact to rounding (an error of order 1e-10 m
# or less in double), and nothing is NaN or infinite.
if(POINTMASS_BUILD_TESTS)
  add_test(NAME example.accuracy_comparison COMMAND accuracy_comparison --quick)
  set_tests_properties(example.accuracy_comparison PROPERTIES
    PASS_REGULAR_EXPRESSION "double None Kinematic +1/30 +[0-9.]+e-1[0-9].*double Exact Exact +1/240 +[0-9.]+e-1[0-9]"
    FAIL_REGULAR_EXPRESSION "nan|inf")
endif()
