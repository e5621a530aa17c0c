# villa_generator_building: layout -> 3D building (meshes, glTF/OBJ export, Embree preview pictures).
# Included from generator/CMakeLists.txt. assimp and Embree stay inside this library's .cpp files.
find_package(assimp REQUIRED)
find_package(embree 3 REQUIRED)
find_package(PNG REQUIRED)

add_library(villa_generator_building STATIC
  ${CMAKE_CURRENT_LIST_DIR}/mesh.cpp
  ${CMAKE_CURRENT_LIST_DIR}/triangulate.cpp
  ${CMAKE_CURRENT_LIST_DIR}/solids.cpp
  ${CMAKE_CURRENT_LIST_DIR}/building.cpp
)
target_link_libraries(villa_generator_building
  PUBLIC villa_layout
  PRIVATE assimp::assimp embree PNG::PNG)
if(TARGET villa_render)
  target_link_libraries(villa_generator_building PUBLIC villa_render)
endif()
villa_add_commands()
