# SPDX-License-Identifier: BSL-1.0
# The accuracy comparison needs the reference solutions (Boost.Odeint, tests/support/).
target_link_libraries(accuracy_comparison PRIVATE pointmass_support)
if(POINTMASS_BUILD_TESTS)
  # The per-shot tables: in every shot, the rows of the pairs that are the model's exact flow
  # (Exact + Exact, and None with ConstantAcceleration or Exact against the undamped model) have double
  # errors below 1e-9 m at every frame time (rounding: the test fails on any of them at 1e-9
  # or above), and the Exact + Exact row reads "exact" with all four below 1e-10 in at least
  # one shot; in the summary, double Exact + Exact at 1/240 s is below 1e-10 m too. Nothing is
  # NaN or infinite.
  set(_exact_row "\\| (Exact \\+ Exact|None \\+ ConstantAcceleration|None \\+ Exact) \\|")
  set(_large " [0-9.]+e(\\+|-0)[0-9]+ \\|")  # an error of 1e-9 or more
  set(_any " [^|]+ \\|")
  set(_small " [0-9.]+e-1[0-9] \\|")
  add_test(NAME example.accuracy_comparison COMMAND accuracy_comparison --quick)
  set_tests_properties(example.accuracy_comparison PROPERTIES
    PASS_REGULAR_EXPRESSION
      "\\| Exact \\+ Exact \\|${_small}${_small}${_small}${_small} exact \\|.*double Exact \\+ Exact +1/240 +[0-9.]+e-1[0-9]"
    FAIL_REGULAR_EXPRESSION
      "nan|inf;${_exact_row}${_large};${_exact_row}${_any}${_large};${_exact_row}${_any}${_any}${_large};${_exact_row}${_any}${_any}${_any}${_large}")
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
