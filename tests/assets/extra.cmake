# The asset tests write zip archives (zlib) with PNG textures (stb_image_write) in the test.
if(TARGET villa_tests_assets)
  find_package(ZLIB REQUIRED)
  pkg_check_modules(STB REQUIRED IMPORTED_TARGET stb)
  target_link_libraries(villa_tests_assets PRIVATE ZLIB::ZLIB PkgConfig::STB)
endif()
