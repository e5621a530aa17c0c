# The LLM client's tests run a local OpenAI-compatible server (cpp-httplib) on 127.0.0.1.
if(TARGET villa_tests_llm)
  pkg_check_modules(HTTPLIB REQUIRED IMPORTED_TARGET cpp-httplib)
  target_link_libraries(villa_tests_llm PRIVATE PkgConfig::HTTPLIB Threads::Threads)
endif()
