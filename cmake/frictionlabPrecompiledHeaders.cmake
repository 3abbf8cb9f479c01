# Precompiled headers (option FRICTIONLAB_PRECOMPILED_HEADERS, ON by default).
#
# Why: the project has ~230 translation units, most of them tests of one file each, and every one
# parses the same standard headers (and the tests GoogleTest's). One precompiled header is built per
# kind (library code; tests) and reused by every target of that kind. Measured on four typical
# files (g++ 12 -O3, user + system CPU, 2026-11-22, with the list below less <cstdio>, <iostream>,
# <numeric>, <set>, <unordered_map> and <variant>): 13.0 s without, 10.7 s with (-17 %); the gain
# is in the test files (-18 to -26 %), nearly none in small library files.
#
# <filesystem> is left out on purpose: it brings std::quoted (<iomanip>), which argument-dependent
# lookup then finds beside a file's own quoted(std::string). The headers listed are only
# force-included: every file still includes what it uses (a build with
# -DFRICTIONLAB_PRECOMPILED_HEADERS=OFF checks that). The installed package is not affected (the
# property is not exported). ccache users: precompiled headers are cached only with
# `sloppiness = pch_defines,time_macros` in ccache.conf; otherwise every file is recompiled.
option(FRICTIONLAB_PRECOMPILED_HEADERS "Precompile the standard and GoogleTest headers (faster builds)" ON)

# The standard headers most files include (counted with g++ -H over compile_commands.json). Eigen's
# core (in ~100 files) is left out: loading the larger header cost more than it saved.
set(frictionlab_pch_headers
  <algorithm> <array> <atomic> <chrono> <cmath> <cstddef> <cstdint> <cstdio> <cstdlib> <fstream>
  <functional> <iostream> <limits> <map> <memory> <mutex> <numeric> <optional> <ostream> <set>
  <span> <sstream> <stdexcept> <string> <string_view> <unordered_map> <utility> <variant> <vector>)

# frictionlab_pch_host(NAME TYPE HEADERS...): an empty target that owns one precompiled header.
function(frictionlab_pch_host name type)
  set(source ${CMAKE_CURRENT_BINARY_DIR}/${name}.cpp)
  file(CONFIGURE OUTPUT ${source} CONTENT "// Owns the precompiled header reused by other targets.\n")
  if(type STREQUAL "EXECUTABLE")
    add_library(${name} OBJECT ${source})
    # Executables are compiled with -fPIE, libraries with -fPIC: the host must match its users.
    set_target_properties(${name} PROPERTIES POSITION_INDEPENDENT_CODE ON)
    target_compile_options(${name} PRIVATE -fPIE)
  else()
    add_library(${name} OBJECT ${source})
  endif()
  target_link_libraries(${name} PRIVATE frictionlab::warnings)
  target_precompile_headers(${name} PRIVATE ${ARGN})
endfunction()

# frictionlab_collect_targets(OUT DIR...): the library and executable targets defined in DIR and
# its subdirectories.
function(frictionlab_collect_targets out)
  set(found "")
  foreach(dir IN LISTS ARGN)
    get_property(targets DIRECTORY ${dir} PROPERTY BUILDSYSTEM_TARGETS)
    list(APPEND found ${targets})
    get_property(subdirs DIRECTORY ${dir} PROPERTY SUBDIRECTORIES)
    if(subdirs)
      frictionlab_collect_targets(sub ${subdirs})
      list(APPEND found ${sub})
    endif()
  endforeach()
  set(${out} ${found} PARENT_SCOPE)
endfunction()

# frictionlab_use_precompiled_headers(DIR...): every static library and executable of the project in
# those directories reuses the matching precompiled header. Test executables (they link GoogleTest)
# get the one with gtest.h. Targets with their own compile flags (the Python module, MuJoCo, `fit`
# with -fno-math-errno) are left out: a header precompiled with other flags would be rejected anyway.
function(frictionlab_use_precompiled_headers)
  if(NOT FRICTIONLAB_PRECOMPILED_HEADERS)
    return()
  endif()
  # GCC 12 loses the system-header status of libstdc++'s inline code read from a precompiled header,
  # so its -Wstringop-overflow, -Wstringop-overread and -Warray-bounds false positives on
  # std::string's inline copies (GCC bugs 105329, 105651: the family -Wno-restrict silences in
  # CMakeLists.txt) reach our files (four sites: "'" + std::string(...) + "'", a string compare).
  if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU" AND CMAKE_CXX_COMPILER_VERSION VERSION_GREATER_EQUAL 12
     AND CMAKE_CXX_COMPILER_VERSION VERSION_LESS 13)
    target_compile_options(frictionlab_warnings INTERFACE -Wno-stringop-overflow -Wno-stringop-overread -Wno-array-bounds)
  endif()
  frictionlab_pch_host(frictionlab_pch_library LIBRARY ${frictionlab_pch_headers})
  if(FRICTIONLAB_TESTS)
    frictionlab_pch_host(frictionlab_pch_test EXECUTABLE ${frictionlab_pch_headers} <gtest/gtest.h>)
    target_link_libraries(frictionlab_pch_test PRIVATE GTest::gtest)
    # The tests' files are compiled with their own options (CMakeLists.txt): so is their header.
    target_compile_options(frictionlab_pch_test PRIVATE ${FRICTIONLAB_TEST_COMPILE_OPTIONS})
  endif()
  frictionlab_collect_targets(targets ${ARGN})
  foreach(target IN LISTS targets)
    get_target_property(type ${target} TYPE)
    get_target_property(imported ${target} IMPORTED)
    if(imported OR NOT type MATCHES "^(STATIC_LIBRARY|EXECUTABLE)$" OR target MATCHES "mujoco|python|friction_fit")
      continue()
    endif()
    get_target_property(links ${target} LINK_LIBRARIES)
    if(type STREQUAL "EXECUTABLE" AND FRICTIONLAB_TESTS AND links MATCHES "GTest::")
      target_precompile_headers(${target} REUSE_FROM frictionlab_pch_test)
    elseif(type STREQUAL "STATIC_LIBRARY")
      target_precompile_headers(${target} REUSE_FROM frictionlab_pch_library)
    endif()
  endforeach()
endfunction()
