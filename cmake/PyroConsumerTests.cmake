# tests/consumer built out of tree against the installed package, as a user would: install into
# build/consumer-prefix, configure and build build/consumer-build, run its programs. A chain of
# fixtures, so that `ctest -R consumer_` alone runs every step before the programs.
set(PYRO_CONSUMER_PREFIX ${CMAKE_BINARY_DIR}/consumer-prefix)
set(PYRO_CONSUMER_BUILD ${CMAKE_BINARY_DIR}/consumer-build)
string(TOUPPER "${CMAKE_BUILD_TYPE}" build_type)
# The same compiler and flags as this build (a sanitizer build's libraries need its flags to link).
set(PYRO_CONSUMER_ARGS -DCMAKE_PREFIX_PATH=${PYRO_CONSUMER_PREFIX} -DCONSUMER_WINDOW=ON
  -DCMAKE_BUILD_TYPE=${CMAKE_BUILD_TYPE}
  -DCMAKE_CXX_COMPILER=${CMAKE_CXX_COMPILER}
  "-DCMAKE_CXX_FLAGS=${CMAKE_CXX_FLAGS}"
  "-DCMAKE_CXX_FLAGS_${build_type}=${CMAKE_CXX_FLAGS_${build_type}}"
  "-DCMAKE_EXE_LINKER_FLAGS=${CMAKE_EXE_LINKER_FLAGS}")
if(CMAKE_CXX_COMPILER_LAUNCHER)
  list(APPEND PYRO_CONSUMER_ARGS -DCMAKE_CXX_COMPILER_LAUNCHER=${CMAKE_CXX_COMPILER_LAUNCHER})
endif()

add_test(NAME consumer_install
  COMMAND ${CMAKE_COMMAND} --install ${CMAKE_BINARY_DIR} --prefix ${PYRO_CONSUMER_PREFIX})
add_test(NAME consumer_configure
  COMMAND ${CMAKE_COMMAND} -S ${CMAKE_SOURCE_DIR}/tests/consumer -B ${PYRO_CONSUMER_BUILD}
          ${PYRO_CONSUMER_ARGS})
add_test(NAME consumer_build COMMAND ${CMAKE_COMMAND} --build ${PYRO_CONSUMER_BUILD} -j2)
set_tests_properties(consumer_install PROPERTIES FIXTURES_SETUP consumer_installed)
set_tests_properties(consumer_configure PROPERTIES
  FIXTURES_REQUIRED consumer_installed FIXTURES_SETUP consumer_configured)
set_tests_properties(consumer_build PROPERTIES TIMEOUT 600
  FIXTURES_REQUIRED "consumer_installed;consumer_configured" FIXTURES_SETUP consumer_built)
# The build tools are not instrumented: a sanitizer preset's preloads and options stay off them.
set_tests_properties(consumer_install consumer_configure consumer_build PROPERTIES
  ENVIRONMENT_MODIFICATION "LD_PRELOAD=unset:;ASAN_OPTIONS=unset:;LSAN_OPTIONS=unset:")

# The consumer's programs (its own CMakeLists.txt registers the same for a standalone ctest).
# What they find must be the installed content, not this source tree's: no override is passed.
add_test(NAME consumer_render
  COMMAND ${PYRO_CONSUMER_BUILD}/spin_render --out ${PYRO_CONSUMER_BUILD}/spin_render.png)
add_test(NAME consumer_gtest COMMAND ${PYRO_CONSUMER_BUILD}/consumer_tests)
add_test(NAME consumer_window_gtest COMMAND ${PYRO_CONSUMER_BUILD}/consumer_window_tests)
set_tests_properties(consumer_render consumer_gtest consumer_window_gtest PROPERTIES
  FIXTURES_REQUIRED "consumer_installed;consumer_configured;consumer_built"
  ENVIRONMENT_MODIFICATION "PYRO_CONTENT_DIR=unset:;PYRO_FLIPBOOK_DIR=unset:")
# A program linking Pyrocumulus::engine from the package needs no GLFW either.
add_test(NAME consumer_links_no_glfw
  COMMAND ${CMAKE_COMMAND} -DBINARY=${PYRO_CONSUMER_BUILD}/spin_render -DFORBIDDEN=glfw
          -P ${CMAKE_SOURCE_DIR}/cmake/check_needed_libraries.cmake)
set_tests_properties(consumer_links_no_glfw PROPERTIES
  FIXTURES_REQUIRED "consumer_installed;consumer_configured;consumer_built"
  ENVIRONMENT_MODIFICATION "LD_PRELOAD=unset:;ASAN_OPTIONS=unset:;LSAN_OPTIONS=unset:")
# The package's installation and a consumer's build exercise CMake and the compiler, not the
# engine's memory safety: CI runs them in the Release half only (docs/reliability.md).
set_tests_properties(consumer_install consumer_configure consumer_build consumer_render
                     consumer_gtest consumer_window_gtest consumer_links_no_glfw PROPERTIES
  LABELS release-only)
