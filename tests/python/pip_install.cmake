# The README's Python installation, as a user runs it from a checkout:
#   python3 -m venv --system-site-packages VENV
#   VENV/bin/pip install --no-build-isolation SOURCE
# then imports the module from outside the source tree with the venv's Python
# and checks the stubs were installed with it. --no-index: nothing may come
# from a package index (numpy, setuptools and wheel are Debian's). The build
# reuses this test build's folder (PHONGRAST_BUILD_DIR, see setup.py), so the
# test does not compile the library a second time; a fresh build runs the
# same setup.py code with its own CMake configure step.
file(REMOVE_RECURSE "${VENV}")
execute_process(COMMAND "${PYTHON}" -m venv --system-site-packages "${VENV}" RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "python3 -m venv failed (${status}); Debian: apt-get install python3-venv")
endif()
execute_process(
  COMMAND "${CMAKE_COMMAND}" -E env "PHONGRAST_BUILD_DIR=${BUILD_DIR}" "CMAKE_BUILD_PARALLEL_LEVEL=2"
          "${VENV}/bin/pip" install --no-build-isolation --no-index --quiet "${SOURCE_DIR}"
  RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "pip install --no-build-isolation failed (${status})")
endif()
execute_process(
  COMMAND "${VENV}/bin/python" -c [=[
import inspect, pathlib, sys
import numpy as np
import phongrast
module = pathlib.Path(phongrast.__file__)
assert module.is_relative_to(sys.argv[1]), phongrast.__file__
assert (module.parent / "phongrast.pyi").is_file(), "stubs next to the module"
assert (module.parent / "phongrast-stubs" / "__init__.pyi").is_file(), "PEP 561 stub package"
mesh = phongrast.Mesh([[0, 0, 0], [1, 0, 0], [0, 1, 0]], [[0, 1, 2]])
image, stats = phongrast.render(phongrast.Scene.from_mesh(mesh, 8, 8))
assert image.shape == (8, 8, 3) and stats["triangles_drawn"] == 1
assert "scene" in inspect.signature(phongrast.render).parameters
print("pip-installed", phongrast.__file__)
]=] "${VENV}"
  WORKING_DIRECTORY "${VENV}"
  RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "importing the pip-installed module from ${VENV} failed")
endif()
