"""The build step behind `pip install .` (pyproject.toml): the extension granular._core is built by
the project's own CMake, as for the tools, and copied into the wheel beside python/granular.

The library is linked statically into the extension (GRANULAR_SHARED=OFF) so the installed package
needs no libgranular.so beside it; tests, tools and benchmarks are not built.

Environment:
  GRANULAR_CMAKE_ARGS         extra CMake arguments, e.g. "-DGRANULAR_NATIVE=OFF" (a wheel for
                              other CPUs; -march=native is the default)
  CMAKE_BUILD_PARALLEL_LEVEL  build jobs (default: every core)
  GRANULAR_PREBUILT_EXTENSION path of an already built _core*.so to package instead of building
                              one (the packaging test uses the build tree's)
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

ROOT = pathlib.Path(__file__).resolve().parent


def project_version():
    """The version of record: CMakeLists.txt's project(granular VERSION x.y.z)."""
    text = (ROOT / "CMakeLists.txt").read_text()
    match = re.search(r"project\(granular VERSION ([0-9.]+)", text)
    if not match:
        raise RuntimeError("setup.py: no 'project(granular VERSION ...)' in CMakeLists.txt")
    return match.group(1)


class CMakeBuild(build_ext):
    def build_extension(self, ext):
        target = pathlib.Path(self.get_ext_fullpath(ext.name)).resolve()
        target.parent.mkdir(parents=True, exist_ok=True)
        prebuilt = os.environ.get("GRANULAR_PREBUILT_EXTENSION")
        if prebuilt:
            shutil.copy2(prebuilt, target)
            return
        build = pathlib.Path(self.build_temp).resolve() / "cmake"
        configure = [
            "cmake", "-S", str(ROOT), "-B", str(build),
            "-DCMAKE_BUILD_TYPE=Release",
            f"-DPython_EXECUTABLE={sys.executable}",
            "-DGRANULAR_SHARED=OFF", "-DBUILD_TESTING=OFF", "-DGRANULAR_BENCHMARKS=OFF",
        ] + shlex.split(os.environ.get("GRANULAR_CMAKE_ARGS", ""))
        subprocess.run(configure, check=True)
        jobs = os.environ.get("CMAKE_BUILD_PARALLEL_LEVEL", str(os.cpu_count() or 1))
        subprocess.run(["cmake", "--build", str(build), "--target", "granular_python", "-j", jobs], check=True)
        built = sorted((build / "python" / "granular").glob("_core*.so"))
        if not built:
            raise RuntimeError(f"setup.py: CMake built no _core*.so under {build / 'python' / 'granular'}")
        shutil.copy2(built[0], target)


setup(
    version=project_version(),
    ext_modules=[Extension("granular._core", sources=[])],
    cmdclass={"build_ext": CMakeBuild},
    # Not ./build: that is the CMake build tree of the README's commands.
    options={"build": {"build_base": "build-pip"}},
)
