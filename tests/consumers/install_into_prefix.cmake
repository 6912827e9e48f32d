# cmake -P: `cmake --install` this build into a fresh prefix, then check that the
# files a user relies on are there. Setup fixture of the find_package consumer test.
#
#   -DBUILD_DIR=<phongrast build>  -DPREFIX=<fresh folder>  -DCONFIG=<build type>
#   -DEXPECT_FILES=<paths relative to PREFIX, |-separated>
cmake_minimum_required(VERSION 3.21)

file(REMOVE_RECURSE "${PREFIX}")
# add_test would split a ;-list into several arguments, so the list comes |-separated.
string(REPLACE "|" ";" EXPECT_FILES "${EXPECT_FILES}")
set(config_args "")
if(NOT CONFIG STREQUAL "")  # a single-config build without CMAKE_BUILD_TYPE has no config name
  set(config_args --config "${CONFIG}")
endif()
execute_process(
  COMMAND "${CMAKE_COMMAND}" --install "${BUILD_DIR}" --prefix "${PREFIX}" ${config_args}
  RESULT_VARIABLE status COMMAND_ECHO STDOUT)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "cmake --install failed (${status})")
endif()

set(missing "")
foreach(file IN LISTS EXPECT_FILES)
  if(NOT EXISTS "${PREFIX}/${file}")
    list(APPEND missing "${file}")
  endif()
endforeach()
if(missing)
  list(JOIN missing "\n  " missing_lines)
  message(FATAL_ERROR "cmake --install did not install:\n  ${missing_lines}")
endif()

# A private dependency's headers must not be installed with phongrast's.
file(GLOB_RECURSE installed_headers RELATIVE "${PREFIX}/include" "${PREFIX}/include/*")
foreach(header IN LISTS installed_headers)
  if(NOT header MATCHES "^phongrast/")
    message(FATAL_ERROR "cmake --install put a header outside include/phongrast/: ${header}")
  endif()
endforeach()
list(LENGTH EXPECT_FILES expected_count)
message(STATUS "installed into ${PREFIX}; all ${expected_count} expected files present")
