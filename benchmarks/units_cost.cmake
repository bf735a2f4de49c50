# SPDX-License-Identifier: BSL-1.0
# benchmarks/units_cost.cpp compares the plain and the SI particle: it needs pointmass::units.
target_link_libraries(units_cost PRIVATE pointmass::units)
target_link_libraries(units_cost PRIVATE pointmass_support)
