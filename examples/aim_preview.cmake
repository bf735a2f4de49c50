# SPDX-License-Identifier: BSL-1.0
if(POINTMASS_BUILD_TESTS)
  # The preview's answers, worked apart from the program from the closed form
  # p0 + v0 t phi1(kt) + a t^2 phi2(kt) (k = ln 0.99) by bisection: at 30 degrees the shell
  # reaches the wall (z = 60 m) at 1.395 s, 16.761 m up (hits: the apex is 16.995 m), lands
  # at 2.549 s, 108.962 m; at 45 degrees 1.712 s, 32.368 m (clears), apex 32.385 m, lands at
  # 3.557 s, 123.547 m; at 60 degrees 2.429 s, 46.880 m, climbs through 40 m at 1.265 s
  # (apex 47.706 m), lands at 4.334 s, 106.025 m. The apexes below 40 m give "never".
  add_test(NAME example.aim_preview COMMAND aim_preview)
  set_tests_properties(example.aim_preview PROPERTIES PASS_REGULAR_EXPRESSION
    "aim 30 deg: wall at t = 1\\.395 s, y = 16\\.761 m \\(hits\\); 40 m never; lands at t = 2\\.549 s, z = 108\\.962 m\naim 45 deg: wall at t = 1\\.712 s, y = 32\\.368 m \\(clears\\); 40 m never; lands at t = 3\\.557 s, z = 123\\.547 m\naim 60 deg: wall at t = 2\\.429 s, y = 46\\.880 m \\(clears\\); 40 m at t = 1\\.265 s; lands at t = 4\\.334 s, z = 106\\.025 m\nstepped at 60 Hz, the shells pass where the preview says: PASS"
    FAIL_REGULAR_EXPRESSION "FAIL")
endif()
