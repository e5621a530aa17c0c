# The critic's tests run a local OpenAI-compatible server (cpp-httplib on 127.0.0.1) that plays a model.
if(TARGET villa_tests_critic)
  pkg_check_modules(HTTPLIB REQUIRED IMPORTED_TARGET cpp-httplib)
  target_link_libraries(villa_tests_critic PRIVATE PkgConfig::HTTPLIB Threads::Threads)
endif()
