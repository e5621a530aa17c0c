# The residual tests evaluate the solver's internal cost functors (solver/residuals.h) with Ceres.
if(TARGET villa_tests_solver)
  find_package(Ceres REQUIRED)
  target_link_libraries(villa_tests_solver PRIVATE Ceres::ceres)
endif()
