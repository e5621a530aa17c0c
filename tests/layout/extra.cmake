# The geometry tests cross-check RingProblem against Boost.Geometry's is_valid (villa_layout keeps Boost
# private, so the test links it itself).
if(TARGET villa_tests_layout)
  target_link_libraries(villa_tests_layout PRIVATE Boost::headers)
endif()
