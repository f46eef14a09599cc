# SPDX-License-Identifier: BSD-3-Clause
"""The build step of pyproject.toml: kinestat._core is built by the project's CMake (the library
and the module only: no tests, benchmarks or PETSc) and copied into the wheel. Nothing is
downloaded. Settings (environment):

KINESTAT_CMAKE_BUILD_DIR  a CMake build folder to configure (once) and build in; default a
                          folder under setuptools' build_temp
KINESTAT_CORE_MODULE      an already built _core*.so to package instead (no CMake at all)
CMAKE_BUILD_PARALLEL_LEVEL  as for cmake --build
"""

import os
import pathlib
import re
import shutil
import subprocess
import sys

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = pathlib.Path(__file__).resolve().parent


def project_version():
    # The one version of the project: CMakeLists.txt's project(kinestat VERSION x.y.z).
    text = (ROOT / "CMakeLists.txt").read_text(encoding="utf-8")
    return re.search(r"project\(kinestat VERSION ([0-9.]+)", text).group(1)


class CMakeExtension(Extension):
    def __init__(self, name):
        super().__init__(name, sources=[])


class CMakeBuild(build_ext):
    def build_extension(self, ext):
        target = pathlib.Path(self.get_ext_fullpath(ext.name))
        target.parent.mkdir(parents=True, exist_ok=True)
        prebuilt = os.environ.get("KINESTAT_CORE_MODULE")
        if prebuilt:
            shutil.copyfile(prebuilt, target)
            return
        build = pathlib.Path(os.environ.get("KINESTAT_CMAKE_BUILD_DIR") or pathlib.Path(self.build_temp).resolve() / "cmake")
        if not (build / "CMakeCache.txt").exists():
            generator = ["-G", "Ninja"] if shutil.which("ninja") else []
            subprocess.run(["cmake", "-S", str(ROOT), "-B", str(build), *generator,
                            "-DCMAKE_BUILD_TYPE=Release", "-DCMAKE_UNITY_BUILD=ON",
                            "-DKINESTAT_BUILD_TESTS=OFF", "-DKINESTAT_BUILD_BENCHMARKS=OFF", "-DKINESTAT_PETSC=OFF",
                            "-DKINESTAT_INSTALL=OFF", "-DKINESTAT_PYTHON=ON",
                            # The interpreter pip runs (a venv's python3 is Debian's, same ABI).
                            f"-DPYTHON_EXECUTABLE={sys.executable}"], check=True)
        subprocess.run(["cmake", "--build", str(build), "--target", "kinestat_python"], check=True)
        built = sorted((build / "python" / "kinestat").glob("_core*.so"))
        if not built:
            raise RuntimeError(f"CMake built no kinestat/_core*.so in {build / 'python'}")
        shutil.copyfile(built[0], target)


# Metadata scratch (kinestat.egg-info) under the ignored build folder, not beside the sources.
EGG_BASE = ROOT / "build" / "pip"
EGG_BASE.mkdir(parents=True, exist_ok=True)

setup(version=project_version(), ext_modules=[CMakeExtension("kinestat._core")], cmdclass={"build_ext": CMakeBuild},
      options={"egg_info": {"egg_base": os.path.relpath(EGG_BASE, ROOT)}})
