# Runs the phongrast executable once and checks what a user would see:
#   cmake -DEXE=... -DARGS="a|b|c" -DWORKDIR=... -DEXPECT_EXIT=2
#         -DEXPECT_STDERR=regex [-DEXPECT_STDOUT=regex]
#         [-DOUTPUT=file -DEXISTING=ON|OFF] -P run_cli_case.cmake
# ARGS uses '|' between arguments. With OUTPUT, the file's folder is emptied
# first; EXISTING=ON puts a known file at OUTPUT before the run. Afterwards the
# folder must hold exactly what it held before (no new image, no temporary
# file) and an existing OUTPUT must be unchanged. On EXPECT_EXIT=0 OUTPUT
# must exist instead.
cmake_minimum_required(VERSION 3.21)
string(REPLACE "|" ";" argument_list "${ARGS}")
if(NOT WORKDIR)
  set(WORKDIR "${CMAKE_CURRENT_BINARY_DIR}")
endif()

set(existing_text "an existing file that a failed run must not touch\n")
if(OUTPUT)
  get_filename_component(output_folder "${OUTPUT}" DIRECTORY)
  file(REMOVE_RECURSE "${output_folder}")
  file(MAKE_DIRECTORY "${output_folder}")
  if(EXISTING)
    file(WRITE "${OUTPUT}" "${existing_text}")
  endif()
  file(GLOB before RELATIVE "${output_folder}" "${output_folder}/*" "${output_folder}/.*")
endif()

execute_process(COMMAND "${EXE}" ${argument_list}
                WORKING_DIRECTORY "${WORKDIR}"
                RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)

set(problems "")
if(NOT "${status}" STREQUAL "${EXPECT_EXIT}")
  string(APPEND problems "exit status ${status}, expected ${EXPECT_EXIT}\n")
endif()
if(DEFINED EXPECT_STDERR AND NOT err MATCHES "${EXPECT_STDERR}")
  string(APPEND problems "stderr does not match: ${EXPECT_STDERR}\n")
endif()
if(DEFINED EXPECT_STDOUT AND NOT out MATCHES "${EXPECT_STDOUT}")
  string(APPEND problems "stdout does not match: ${EXPECT_STDOUT}\n")
endif()
if(NOT "${EXPECT_EXIT}" STREQUAL "0")
  # One message on one line (plus nothing else) for a failed run.
  string(REGEX MATCHALL "\n" newlines "${err}")
  list(LENGTH newlines line_count)
  if(line_count GREATER 1)
    string(APPEND problems "expected a one-line error message, got ${line_count} lines\n")
  endif()
endif()
if(OUTPUT)
  file(GLOB after RELATIVE "${output_folder}" "${output_folder}/*" "${output_folder}/.*")
  if("${EXPECT_EXIT}" STREQUAL "0")
    if(NOT EXISTS "${OUTPUT}")
      string(APPEND problems "no output file ${OUTPUT}\n")
    endif()
  else()
    if(NOT "${after}" STREQUAL "${before}")
      string(APPEND problems "the output folder changed: before [${before}], after [${after}]\n")
    endif()
    if(EXISTING)
      file(READ "${OUTPUT}" now)
      if(NOT now STREQUAL existing_text)
        string(APPEND problems "the existing output file was changed\n")
      endif()
    endif()
  endif()
endif()

if(problems)
  message(FATAL_ERROR "phongrast ${ARGS}\n${problems}--- stdout:\n${out}--- stderr:\n${err}")
endif()
message(STATUS "ok: exit ${status}; stderr: ${err}")
