# cmake -P: fails, listing file:line and the include, when any header under
# INCLUDE_DIR includes something matching FORBIDDEN (a regex of path prefixes).
#   -DINCLUDE_DIR=<folder>  -DFORBIDDEN=<regex>
cmake_minimum_required(VERSION 3.21)

file(GLOB_RECURSE headers RELATIVE "${INCLUDE_DIR}" "${INCLUDE_DIR}/*.hpp" "${INCLUDE_DIR}/*.h")
if(NOT headers)
  message(FATAL_ERROR "no headers found under ${INCLUDE_DIR}")
endif()

set(offenders "")
foreach(header IN LISTS headers)
  # One list element per line. C++ is full of ';' and brackets, which a CMake list
  # would split on or group by, so they are neutralised first (only #include lines matter).
  file(READ "${INCLUDE_DIR}/${header}" text)
  string(REPLACE ";" "," text "${text}")
  string(REPLACE "[" "(" text "${text}")
  string(REPLACE "]" ")" text "${text}")
  string(REPLACE "\n" ";" lines "${text}")
  set(line_number 0)
  foreach(line IN LISTS lines)
    math(EXPR line_number "${line_number} + 1")
    if(line MATCHES "^[ \t]*#[ \t]*include[ \t]*[<\"](${FORBIDDEN})")
      string(STRIP "${line}" line)
      list(APPEND offenders "${header}:${line_number}: ${line}")
    endif()
  endforeach()
endforeach()

list(LENGTH headers header_count)
if(offenders)
  list(JOIN offenders "\n  " offender_lines)
  message(FATAL_ERROR "public headers include private dependencies:\n  ${offender_lines}")
endif()
message(STATUS "${header_count} public headers, none includes a private dependency")
