# villa_generator: text -> validated layout (brief parser, procedural and LLM backends, `villa plan`,
# `villa eval`). It links the building half (layout -> 3D) when that is built, so villa_generator is the
# whole generator. Included from generator/CMakeLists.txt; paths are relative to this folder.
set(VILLA_GENERATOR_TEXT_DIR ${CMAKE_CURRENT_LIST_DIR})
add_library(villa_generator STATIC
  ${VILLA_GENERATOR_TEXT_DIR}/brief.cpp
  ${VILLA_GENERATOR_TEXT_DIR}/brief_check.cpp
  ${VILLA_GENERATOR_TEXT_DIR}/recount.cpp
  ${VILLA_GENERATOR_TEXT_DIR}/llm_plan.cpp
  ${VILLA_GENERATOR_TEXT_DIR}/procedural.cpp
  ${VILLA_GENERATOR_TEXT_DIR}/plan.cpp
  ${VILLA_GENERATOR_TEXT_DIR}/eval.cpp
)
target_include_directories(villa_generator PUBLIC ${PROJECT_SOURCE_DIR})
target_link_libraries(villa_generator
  PUBLIC villa_partitioner villa_finetune villa_render villa_llm villa_layout villa_util nlohmann_json::nlohmann_json
  PRIVATE Threads::Threads)
if(TARGET villa_building)
  target_link_libraries(villa_generator PUBLIC villa_building)
endif()
villa_add_commands(plan.cpp eval.cpp)
# The furnishing stage's object vocabulary (assets/category.h) lets the brief parser read furniture wishes
# it has no word for in its own lexicon ("bookshelves full of books") as wishes, not as words not understood.
if(TARGET villa_assets)
  target_link_libraries(villa_generator PUBLIC villa_assets)
  target_compile_definitions(villa_generator PRIVATE VILLA_HAVE_ASSET_VOCABULARY=1)
endif()
# The furnishing's request reader (scene/request.h) tells the procedural backend how many people a
# dining or meeting table is to seat, so that it prefers layouts whose room can hold them.
if(TARGET villa_scene)
  target_link_libraries(villa_generator PUBLIC villa_scene)
  target_compile_definitions(villa_generator PRIVATE VILLA_HAVE_SCENE_REQUEST=1)
endif()
