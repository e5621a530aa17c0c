# The building's solids are cross-checked with CGAL (tests/building/cgal_solids_test.cpp).
if(TARGET villa_tests_building)
  find_package(CGAL REQUIRED)
  target_link_libraries(villa_tests_building PRIVATE CGAL::CGAL)
endif()
