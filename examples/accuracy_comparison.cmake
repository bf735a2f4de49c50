# The accuracy comparison needs the reference solutions (Boost.Odeint, tests/support/).
target_link_libraries(accuracy_comparison PRIVATE pointmass_support)
if(POINTMASS_BUILD_TESTS)
  # Smoke test: the per-shot tables report the exact pair as exact, and in the summary the
  # exact pair and the full position update without damping are exact to rounding (errors
  # of order 1e-10 m or below in double); nothing is NaN or infinite.
  add_test(NAME example.accuracy_comparison COMMAND accuracy_comparison --quick)
  set_tests_properties(example.accuracy_comparison PROPERTIES
    PASS_REGULAR_EXPRESSION "Exact \\+ Exact \\|[^\n]*\\| exact \\|.*double Exact \\+ Exact +1/240 +[0-9.]+e-1[0-9]"
    FAIL_REGULAR_EXPRESSION "nan|inf")
endif()
