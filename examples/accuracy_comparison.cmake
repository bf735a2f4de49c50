# The accuracy comparison needs the reference solutions (Boost.Odeint, tests/support/).
target_link_libraries(accuracy_comparison PRIVATE pointmass_support)
if(POINTMASS_BUILD_TESTS)
  # Smoke test: it runs and reports the exact pair as exact on every shot.
  add_test(NAME example.accuracy_comparison COMMAND accuracy_comparison)
  set_tests_properties(example.accuracy_comparison PROPERTIES
    PASS_REGULAR_EXPRESSION "Exact \\+ Exact \\|[^\n]*\\| exact \\|")
endif()
