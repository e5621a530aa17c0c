# The asset tests write zip archives (zlib) with PNG textures (stb_image_write) in the test.
if(TARGET villa_tests_assets)
  find_package(ZLIB REQUIRED)
  pkg_check_modules(STB REQUIRED IMPORTED_TARGET stb)
  target_link_libraries(villa_tests_assets PRIVATE ZLIB::ZLIB PkgConfig::STB)
endif()
# ... and talk to a local OpenAI-compatible server (cpp-httplib) playing embedding and vision models.
if(TARGET villa_tests_assets)
  pkg_check_modules(HTTPLIB REQUIRED IMPORTED_TARGET cpp-httplib)
  target_link_libraries(villa_tests_assets PRIVATE PkgConfig::HTTPLIB Threads::Threads)
endif()
