# Helpers shared by every stage's CMakeLists.txt.
include_guard(GLOBAL)

# One INTERFACE target carries the language standard and the warnings for the whole project.
add_library(rt_options INTERFACE)
target_compile_features(rt_options INTERFACE cxx_std_20)
set(CMAKE_CXX_EXTENSIONS OFF)  # -std=c++20, not gnu++20
if(CMAKE_CXX_COMPILER_ID MATCHES "GNU|Clang")
  target_compile_options(rt_options INTERFACE -Wall -Wextra -Wpedantic -Wshadow -Wconversion
                                              -Wno-sign-conversion)
endif()
# GCC 12 reports a false -Wrestrict inside libstdc++ for "literal" + std::string (GCC bug
# 105651, fixed in GCC 13); the warning says nothing about our code there.
if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU" AND CMAKE_CXX_COMPILER_VERSION VERSION_LESS 13)
  target_compile_options(rt_options INTERFACE -Wno-restrict)
endif()
if(NOT CMAKE_BUILD_TYPE AND NOT CMAKE_CONFIGURATION_TYPES)
  set(CMAKE_BUILD_TYPE Release CACHE STRING "Build type" FORCE)
endif()

# rt_resolve_last_stage(<out> <requested> <stage>...): maps "stage04" or "stage04_camera" to the
# folder name; empty stays empty (build everything). An unknown name is a configure error.
function(rt_resolve_last_stage out requested)
  set(result "")
  if(NOT requested STREQUAL "")
    foreach(stage IN LISTS ARGN)
      if(stage STREQUAL requested OR stage MATCHES "^${requested}_")
        set(result ${stage})
        break()
      endif()
    endforeach()
    if(result STREQUAL "")
      string(REPLACE ";" ", " known "${ARGN}")
      message(FATAL_ERROR "RT_LAST_STAGE='${requested}' names no stage; expected one of: ${known}")
    endif()
  endif()
  set(${out} "${result}" PARENT_SCOPE)
endfunction()

# rt_add_stage_library(<target> SOURCES ... DEPENDS ...): a stage's library with include/ public.
function(rt_add_stage_library target)
  cmake_parse_arguments(ARG "" "" "SOURCES;DEPENDS" ${ARGN})
  add_library(${target} STATIC ${ARG_SOURCES})
  target_include_directories(${target} PUBLIC "${CMAKE_CURRENT_SOURCE_DIR}/include")
  target_link_libraries(${target} PUBLIC rt_options ${ARG_DEPENDS})
endfunction()

# rt_add_stage_tests(<label> SOURCES ... DEPENDS ...): one GoogleTest executable per stage, its
# tests labelled <label> so that `ctest -L <label>` selects exactly that stage. The target is
# <label>_tests: scripts/grade builds it to grade the stage.
function(rt_add_stage_tests label)
  if(NOT RT_BUILD_TESTS)
    return()
  endif()
  cmake_parse_arguments(ARG "" "" "SOURCES;DEPENDS" ${ARGN})
  set(exe ${label}_tests)
  add_executable(${exe} ${ARG_SOURCES})
  target_link_libraries(${exe} PRIVATE rt_options ${ARG_DEPENDS} GTest::gmock GTest::gtest
                                       GTest::gtest_main)
  # Tests that render write their images under the build tree, never into the sources.
  gtest_discover_tests(${exe}
    WORKING_DIRECTORY "${CMAKE_BINARY_DIR}"
    PROPERTIES LABELS ${label}
    DISCOVERY_TIMEOUT 60)
endfunction()

macro(rt_require_gtest)
  find_package(GTest QUIET)
  if(NOT GTest_FOUND OR NOT TARGET GTest::gmock)
    message(FATAL_ERROR "GoogleTest/GoogleMock not found: install the Debian packages "
                        "libgtest-dev and libgmock-dev (apt-get install libgtest-dev libgmock-dev)")
  endif()
  include(GoogleTest)
endmacro()

# stb (Debian libstb-dev): headers in /usr/include/stb and a compiled libstb.
function(rt_require_stb)
  if(TARGET rt::stb)
    return()
  endif()
  find_path(STB_INCLUDE_DIR stb_image_write.h PATH_SUFFIXES stb)
  find_library(STB_LIBRARY stb)
  if(NOT STB_INCLUDE_DIR OR NOT STB_LIBRARY)
    message(FATAL_ERROR "stb not found: install the Debian package libstb-dev "
                        "(apt-get install libstb-dev)")
  endif()
  add_library(rt::stb UNKNOWN IMPORTED GLOBAL)
  set_target_properties(rt::stb PROPERTIES IMPORTED_LOCATION "${STB_LIBRARY}"
                                           INTERFACE_INCLUDE_DIRECTORIES "${STB_INCLUDE_DIR}")
endfunction()

# nlohmann-json (Debian nlohmann-json3-dev): the scene files and the JSON that rt prints.
macro(rt_require_nlohmann_json)
  find_package(nlohmann_json 3 QUIET)
  if(NOT nlohmann_json_FOUND)
    message(FATAL_ERROR "nlohmann-json not found: install the Debian package nlohmann-json3-dev "
                        "(apt-get install nlohmann-json3-dev)")
  endif()
endmacro()

# CLI11 (Debian libcli11-dev, header-only): the command line of rt.
macro(rt_require_cli11)
  find_package(CLI11 2 QUIET)
  if(NOT CLI11_FOUND)
    message(FATAL_ERROR "CLI11 not found: install the Debian package libcli11-dev "
                        "(apt-get install libcli11-dev)")
  endif()
endmacro()
