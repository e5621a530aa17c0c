# The LLM client's tests run a local OpenAI-compatible server (cpp-httplib) on 127.0.0.1.
if(TARGET villa_tests_generator_text)
  pkg_check_modules(HTTPLIB REQUIRED IMPORTED_TARGET cpp-httplib)
  target_link_libraries(villa_tests_generator_text PRIVATE PkgConfig::HTTPLIB Threads::Threads)
endif()
# The brief parser is tested on the annotator's drafted descriptions when the annotator is built.
if(TARGET villa_tests_generator_text AND TARGET villa_annotator)
  target_link_libraries(villa_tests_generator_text PRIVATE villa_annotator)
  target_compile_definitions(villa_tests_generator_text PRIVATE VILLA_HAVE_ANNOTATOR=1)
endif()
