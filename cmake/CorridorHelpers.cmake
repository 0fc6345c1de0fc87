# corridor_add_library(NAME SOURCES ... HEADERS ... DEPS ...): one library per module. Its private
# headers (HEADERS, not installed) are included by their path from the root ("perception/x.h");
# the public ones live in include/corridor_depth/ and are included as "corridor_depth/x.h".
set(CORRIDOR_WARNINGS -Wall -Wextra -Wpedantic -Wshadow -Wnon-virtual-dtor -Wswitch)
if(CORRIDOR_WERROR)
  list(APPEND CORRIDOR_WARNINGS -Werror)
endif()


function(corridor_add_library name)
  cmake_parse_arguments(ARG "" "" "SOURCES;HEADERS;DEPS" ${ARGN})
  add_library(${name} ${ARG_SOURCES} ${ARG_HEADERS})
  add_library(corridor_depth::${name} ALIAS ${name})
  target_include_directories(${name} PUBLIC
    $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}/include>
    $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}>
    $<INSTALL_INTERFACE:include>)
  target_compile_options(${name} PRIVATE ${CORRIDOR_WARNINGS})
  target_link_libraries(${name} PUBLIC ${ARG_DEPS})
  set_target_properties(${name} PROPERTIES EXPORT_NAME ${name})
endfunction()

# corridor_add_executable(NAME SOURCES ... DEPS ...)
function(corridor_add_executable name)
  cmake_parse_arguments(ARG "" "" "SOURCES;DEPS" ${ARGN})
  add_executable(${name} ${ARG_SOURCES})
  target_compile_options(${name} PRIVATE ${CORRIDOR_WARNINGS})
  target_link_libraries(${name} PRIVATE ${ARG_DEPS})
endfunction()

# The definitions every test binary (and the tests' shared precompiled header) compiles with.
set(CORRIDOR_TEST_DEFINITIONS
  CORRIDOR_SOURCE_DIR="${PROJECT_SOURCE_DIR}"
  CORRIDOR_BINARY_DIR="${PROJECT_BINARY_DIR}")

# What the tests' shared precompiled header includes from, linked into every test binary.
set(CORRIDOR_TEST_PCH_DEPS GTest::gtest opencv_core opencv_imgproc Eigen3::Eigen)

# corridor_add_test(NAME SOURCES ... DEPS ... [LABELS ...] [ENVIRONMENT ...] [COST N]): a GoogleTest
# binary registered with ctest, one ctest test per GoogleTest test; or, with
# CORRIDOR_TEST_PER_BINARY, one per binary, which starts each binary once instead of once per test
# (a sanitized binary takes a third of a second to start). COST starts a long binary first in a
# parallel run that has no timings of its own yet (a fresh build).
option(CORRIDOR_TEST_PER_BINARY "Register each test binary as one ctest test" OFF)
function(corridor_add_test name)
  cmake_parse_arguments(ARG "" "COST" "SOURCES;DEPS;LABELS;ENVIRONMENT" ${ARGN})
  add_executable(${name} ${ARG_SOURCES})
  target_compile_options(${name} PRIVATE ${CORRIDOR_WARNINGS})
  target_link_libraries(${name} PRIVATE ${ARG_DEPS} ${CORRIDOR_TEST_PCH_DEPS} GTest::gtest_main)
  target_compile_definitions(${name} PRIVATE ${CORRIDOR_TEST_DEFINITIONS})
  if(TARGET corridor_test_pch)
    target_precompile_headers(${name} REUSE_FROM corridor_test_pch)
  endif()
  if(CORRIDOR_TEST_PER_BINARY)
    add_test(NAME ${name} COMMAND ${name})
    set_tests_properties(${name} PROPERTIES LABELS "${ARG_LABELS}")
    if(ARG_ENVIRONMENT)
      set_tests_properties(${name} PROPERTIES ENVIRONMENT "${ARG_ENVIRONMENT}")
    endif()
    if(ARG_COST)
      set_tests_properties(${name} PROPERTIES COST ${ARG_COST})
    endif()
  else()
    include(GoogleTest)
    set(properties LABELS "${ARG_LABELS}")
    if(ARG_ENVIRONMENT)
      list(APPEND properties ENVIRONMENT "${ARG_ENVIRONMENT}")
    endif()
    gtest_discover_tests(${name} TEST_PREFIX "${name}." DISCOVERY_TIMEOUT 60
                         PROPERTIES ${properties})
  endif()
endfunction()
