# The MJCF test loads the written scene with MuJoCo itself (Debian libmujoco-dev 2.2). Its CMake target
# names /usr/include/libqhull_r, which bookworm's package does not need: the library and header by hand.
if(TARGET villa_tests_physics)
  find_library(VILLA_MUJOCO_LIBRARY NAMES mujoco REQUIRED)
  find_path(VILLA_MUJOCO_INCLUDE mujoco/mujoco.h REQUIRED)
  target_include_directories(villa_tests_physics PRIVATE ${VILLA_MUJOCO_INCLUDE})
  target_link_libraries(villa_tests_physics PRIVATE ${VILLA_MUJOCO_LIBRARY})
endif()
