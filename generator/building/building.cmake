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
  ${CMAKE_CURRENT_LIST_DIR}/materials.cpp
  ${CMAKE_CURRENT_LIST_DIR}/export.cpp
  ${CMAKE_CURRENT_LIST_DIR}/render_view.cpp
)
# villa_render for the shared category palette (render/palette.h): floors take their room's colour.
target_link_libraries(villa_generator_building
  PUBLIC villa_layout villa_render
  PRIVATE assimp::assimp embree PNG::PNG)
villa_add_commands(build.cpp generate.cpp)
