# cmake -P driver for the consumer tests: configure, build and run
# tests/consumers/project in a fresh binary folder, failing on the first step that fails.
#
#   -DMODE=find_package|add_subdirectory|fetchcontent
#   -DCONSUMER_SOURCE_DIR=<tests/consumers/project>   -DCONSUMER_BINARY_DIR=<fresh folder>
#   -DPHONGRAST_SOURCE_DIR=<phongrast source>         -DPREFIX=<install prefix> (find_package)
#   -DVERSION=<x.y.z>  -DEXPECT_IO=ON|OFF
#   -DGENERATOR=...  -DCXX_COMPILER=...  -DCXX_FLAGS=...  -DBUILD_TYPE=...
cmake_minimum_required(VERSION 3.21)

foreach(required IN ITEMS MODE CONSUMER_SOURCE_DIR CONSUMER_BINARY_DIR GENERATOR CXX_COMPILER BUILD_TYPE)
  if(NOT DEFINED ${required} OR "${${required}}" STREQUAL "")
    message(FATAL_ERROR "run_consumer.cmake: -D${required}=... is required")
  endif()
endforeach()

# run(<what> COMMAND ...): runs one step, prints its output, stops the test when it fails.
function(run what)
  execute_process(${ARGN} RESULT_VARIABLE status COMMAND_ECHO STDOUT)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "consumer (${MODE}): ${what} failed (${status})")
  endif()
endfunction()

file(REMOVE_RECURSE "${CONSUMER_BINARY_DIR}")

set(configure_args
  -S "${CONSUMER_SOURCE_DIR}" -B "${CONSUMER_BINARY_DIR}" -G "${GENERATOR}"
  "-DCMAKE_CXX_COMPILER=${CXX_COMPILER}"
  "-DCMAKE_CXX_FLAGS=${CXX_FLAGS}"
  "-DCMAKE_BUILD_TYPE=${BUILD_TYPE}"
  "-DPHONGRAST_CONSUMER_MODE=${MODE}"
)
if(MODE STREQUAL "find_package")
  list(APPEND configure_args
    "-DCMAKE_PREFIX_PATH=${PREFIX}"
    "-DPHONGRAST_EXPECTED_VERSION=${VERSION}"
    "-DPHONGRAST_EXPECT_IO=${EXPECT_IO}")
else()
  # phongrast's own code must still build warning-free under -Werror as a
  # subproject, while the consumer's deliberate warning stays a warning.
  list(APPEND configure_args
    "-DPHONGRAST_SOURCE_DIR=${PHONGRAST_SOURCE_DIR}"
    "-DPHONGRAST_WERROR=ON")
endif()

run(configure COMMAND "${CMAKE_COMMAND}" ${configure_args})
run(build COMMAND "${CMAKE_COMMAND}" --build "${CONSUMER_BINARY_DIR}" --config "${BUILD_TYPE}" --parallel 2)

# Single-config generators put the programs at the top; multi-config ones in <config>/.
function(find_program_file name out)
  set(file "${CONSUMER_BINARY_DIR}/${name}${CMAKE_EXECUTABLE_SUFFIX}")
  if(NOT EXISTS "${file}")
    set(file "${CONSUMER_BINARY_DIR}/${BUILD_TYPE}/${name}${CMAKE_EXECUTABLE_SUFFIX}")
  endif()
  set(${out} "${file}" PARENT_SCOPE)
endfunction()

find_program_file(phongrast_consumer program)
run("running phongrast_consumer" COMMAND "${program}")
if(EXPECT_IO)
  find_program_file(phongrast_consumer_io program)
  run("running phongrast_consumer_io" COMMAND "${program}" "${CONSUMER_BINARY_DIR}/triangle.exr")
endif()
