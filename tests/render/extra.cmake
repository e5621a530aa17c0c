# The render tests decode the PNGs they check with stb_image (libstb-dev, pkg-config "stb").
if(TARGET villa_tests_render)
  pkg_check_modules(STB REQUIRED IMPORTED_TARGET stb)
  target_link_libraries(villa_tests_render PRIVATE PkgConfig::STB)
endif()
