#!/bin/sh
# Fails when a Catch2 test case name in the .cpp files under FOLDER contains
# ';'. CMake's catch_discover_tests splits names at ';' (a CMake list
# separator), so ctest would run the pieces, which match no test: "No tests
# ran", reported as passed, and the test case never runs.
# Usage: check_test_names.sh FOLDER [SUBFOLDER NAME TO SKIP]
skip="${2:-}"
if grep -rnE --include='*.cpp' ${skip:+--exclude-dir="$skip"} 'TEST_CASE\("[^"]*;' "$1"; then
  echo "check_test_names: the test case names above contain ';'; ctest would never run them" >&2
  exit 1
fi
exit 0
