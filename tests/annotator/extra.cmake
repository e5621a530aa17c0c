# The annotator's tests also run the drafter, the fixes and --auto over fresh partitioner layouts (all six
# footprint classes, one to three floors) when the partitioner is part of the build.
if(TARGET villa_tests_annotator AND TARGET villa_partitioner)
  target_link_libraries(villa_tests_annotator PRIVATE villa_partitioner)
  target_compile_definitions(villa_tests_annotator PRIVATE VILLA_TEST_WITH_PARTITIONER)
endif()
