# Installs only the `python` component into PREFIX and imports the module from
# there (not from the build tree), with the interpreter it was built for.
file(REMOVE_RECURSE "${PREFIX}")
execute_process(COMMAND "${CMAKE_COMMAND}" --install "${BUILD_DIR}" --component python --prefix "${PREFIX}"
                RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "cmake --install --component python failed (${status})")
endif()
if(IS_ABSOLUTE "${INSTALL_DIR}")
  message(FATAL_ERROR "PHONGRAST_PYTHON_INSTALL_DIR is absolute (${INSTALL_DIR}); this test needs it under the prefix")
endif()
set(site "${PREFIX}/${INSTALL_DIR}")
file(GLOB installed "${site}/phongrast*.so")
if(NOT installed)
  message(FATAL_ERROR "no phongrast module in ${site}")
endif()
file(GLOB_RECURSE everything RELATIVE "${PREFIX}" "${PREFIX}/*")
foreach(file IN LISTS everything)
  if(NOT file MATCHES "^${INSTALL_DIR}/phongrast[^/]*\\.so$" AND NOT file STREQUAL "${INSTALL_DIR}/phongrast.pyi")
    message(FATAL_ERROR "the python component installed more than the module and its stubs: ${file}")
  endif()
endforeach()
execute_process(
  COMMAND "${CMAKE_COMMAND}" -E env "PYTHONPATH=${site}" "${PYTHON}" -c
    "import phongrast, numpy, sys; assert phongrast.__file__.startswith(sys.argv[1]), phongrast.__file__; img = phongrast.render(phongrast.Scene.from_mesh(phongrast.Mesh([[0,0,0],[1,0,0],[0,1,0]], [[0,1,2]]), 8, 8))[0]; assert img.shape == (8, 8, 3); print('imported', phongrast.__file__)"
    "${site}"
  WORKING_DIRECTORY "${PREFIX}"
  RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "importing the installed module from ${site} failed")
endif()
