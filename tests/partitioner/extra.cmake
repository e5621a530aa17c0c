# The synth CLI tests check --previews when the villa binary can draw them (render/ in the build).
if(TARGET villa_tests_partitioner AND TARGET villa_render)
  target_compile_definitions(villa_tests_partitioner PRIVATE VILLA_HAVE_RENDER=1)
endif()
