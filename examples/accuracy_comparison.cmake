# SPDX-License-Identifier: BSL-1.0
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
if(POINTMASS_BUILD_TESTS)
  # Far from the origin (the shots launched 1e6 m out): the program checks that the wide
  # positions (Precision<float, double> and Precision<float, Compensated<float>>) keep, at
  # every frame time, float's near-origin error within a factor 2, and that float itself is
  # at least ten times worse there at the finest frame time; otherwise it prints "do NOT
  # keep" (and "NOT KEPT" on the row) and exits 1.
  add_test(NAME example.accuracy_comparison.far
           COMMAND accuracy_comparison --scene far --quick --summary-only --frame-times 15,60,480)
  set_tests_properties(example.accuracy_comparison.far PROPERTIES
    PASS_REGULAR_EXPRESSION "far from the origin, the wide positions keep float's near-origin error"
    FAIL_REGULAR_EXPRESSION "nan|inf|NOT")
endif()
