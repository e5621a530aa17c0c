# The building's solids are cross-checked with CGAL (tests/building/cgal_solids_test.cpp).
if(TARGET villa_tests_building)
  find_package(CGAL REQUIRED)
  target_link_libraries(villa_tests_building PRIVATE CGAL::CGAL)
endif()
# The door-swing cross-check builds synthesized layouts when the partitioner is part of the build.
if(TARGET villa_tests_building AND TARGET villa_partitioner)
  target_link_libraries(villa_tests_building PRIVATE villa_partitioner)
  target_compile_definitions(villa_tests_building PRIVATE VILLA_TEST_WITH_PARTITIONER)
endif()
