"""setuptools drives CMake to build the phongrast extension module.

Why setuptools: it is packaged by Debian 12 (python3-setuptools, with
python3-wheel), and every build dependency must come from Debian's packages
(no other package index is reachable); scikit-build-core, the usual CMake
backend, is not packaged in Debian 12.

The build configures this checkout with CMake (Release; the library, the I/O
library and the Python module only, for the interpreter running pip) and
copies the module and its type stubs into the wheel:
  phongrast.<abi>.so          the module
  phongrast_openexr.so, phongrast_openimageio.so  the modules it loads on first use
  phongrast.pyi               stubs next to the module (IDEs, pyright)
  phongrast-stubs/__init__.pyi  the same stubs as a PEP 561 stub package (mypy)

Environment:
  PHONGRAST_CMAKE_ARGS  extra arguments for the CMake configure step
  PHONGRAST_BUILD_DIR   an already configured build folder to build the module
                        in instead of a fresh one (the install test uses the
                        test build's, so that it does not compile everything
                        a second time)
  CMAKE_BUILD_PARALLEL_LEVEL  parallel jobs (default: all cores)
"""
import os
import pathlib
import re
import shlex
import shutil
import subprocess
import sys

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

SOURCE = pathlib.Path(__file__).resolve().parent


def project_version():
    text = (SOURCE / "CMakeLists.txt").read_text()
    return re.search(r"project\(phongrast VERSION ([0-9.]+)", text).group(1)


class CMakeExtension(Extension):
    def __init__(self, name):
        super().__init__(name, sources=[])


class CMakeBuild(build_ext):
    def build_extension(self, ext):
        given = os.environ.get("PHONGRAST_BUILD_DIR")
        build = pathlib.Path(given) if given else pathlib.Path(self.build_temp).resolve() / "cmake"
        if not given:
            build.mkdir(parents=True, exist_ok=True)
            configure = ["cmake", "-S", str(SOURCE), "-B", str(build), "-DCMAKE_BUILD_TYPE=Release",
                         "-DPHONGRAST_BUILD_PYTHON=ON", "-DPHONGRAST_BUILD_IO=ON", "-DPHONGRAST_BUILD_APPS=OFF",
                         "-DPHONGRAST_BUILD_TESTS=OFF", "-DPHONGRAST_INSTALL=OFF",
                         f"-DPython3_EXECUTABLE={sys.executable}"]
            configure += shlex.split(os.environ.get("PHONGRAST_CMAKE_ARGS", ""))
            subprocess.run(configure, check=True)
        jobs = os.environ.get("CMAKE_BUILD_PARALLEL_LEVEL", str(os.cpu_count() or 1))
        subprocess.run(["cmake", "--build", str(build), "--target", "phongrast_python", "-j", jobs], check=True)

        built = sorted((build / "python").glob("phongrast*.so"))
        if len(built) != 1:
            raise RuntimeError(f"expected one phongrast module in {build / 'python'}, found {built}: "
                               "did CMake skip the Python module? (its configure output says why)")
        target = pathlib.Path(self.get_ext_fullpath(ext.name))
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(built[0], target)
        # The modules phongrast_io loads on first use (EXR files, other image
        # formats), found next to the extension module.
        for module in ("phongrast_openexr.so", "phongrast_openimageio.so"):
            if (build / "lib" / "phongrast" / module).exists():
                shutil.copyfile(build / "lib" / "phongrast" / module, target.parent / module)
        stubs = SOURCE / "src" / "python" / "phongrast.pyi"
        shutil.copyfile(stubs, target.parent / "phongrast.pyi")
        stub_package = target.parent / "phongrast-stubs"
        stub_package.mkdir(exist_ok=True)
        shutil.copyfile(stubs, stub_package / "__init__.pyi")


# packages=[] and py_modules=[]: no automatic discovery (it would take src/ for a src-layout package).
setup(version=project_version(), ext_modules=[CMakeExtension("phongrast")], cmdclass={"build_ext": CMakeBuild},
      packages=[], py_modules=[],
      zip_safe=False)
