# SPDX-License-Identifier: BSL-1.0
# variant_steps sets up its scenes with the accuracy support (tests/support/accuracy.hpp), so
# its particles start exactly as the accuracy comparison's do.
target_link_libraries(variant_steps PRIVATE pointmass_support)
