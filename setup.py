"""Builds conescope's compiled part with the project's CMake (see pyproject.toml).

The CMake build directory is CONESCOPE_BUILD_DIR, or build/ beside this file: a tree already built
by scripts/build.sh is reused, so the C++ core is compiled once. The module _conescope and the
conescope-cli that conescope.batch runs are copied into the package.
"""

import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

SOURCE = Path(__file__).resolve().parent
BUILD = Path(os.environ.get("CONESCOPE_BUILD_DIR", SOURCE / "build")).resolve()


def project_version():
    match = re.search(r"project\(ConeScope VERSION ([0-9.]+)", (SOURCE / "CMakeLists.txt").read_text())
    return match.group(1)


class CMakeBuild(build_ext):
    """Configures (once) and builds the targets the package needs, then copies them into it."""

    def build_extension(self, extension):
        if not (BUILD / "CMakeCache.txt").exists():
            subprocess.run(["cmake", "-S", str(SOURCE), "-B", str(BUILD), "-DCMAKE_BUILD_TYPE=Release",
                            f"-DPython3_EXECUTABLE={sys.executable}"], check=True)
        jobs = str(os.cpu_count() or 1)
        subprocess.run(["cmake", "--build", str(BUILD), "--target", "conescope_python", "conescope-cli",
                        "--parallel", jobs], check=True)
        built = BUILD / "python" / "conescope"
        modules = sorted(built.glob("_conescope*.so"))
        if not modules:
            raise RuntimeError(f"CMake built no _conescope module into {built}: is pybind11-dev installed?")
        target = Path(self.get_ext_fullpath(extension.name))
        target.parent.mkdir(parents=True, exist_ok=True)
        # The module is built for the Python CMake found; its own suffix says which one.
        shutil.copy2(modules[0], target.parent / modules[0].name)
        shutil.copy2(BUILD / "src" / "cli" / "conescope-cli", target.parent / "conescope-cli")

    def get_outputs(self):
        return []


setup(
    version=project_version(),
    packages=["conescope"],
    package_dir={"conescope": "python/conescope"},
    package_data={"conescope": ["py.typed", "*.pyi"]},
    ext_modules=[Extension("conescope._conescope", sources=[])],
    cmdclass={"build_ext": CMakeBuild},
    options={"build": {"build_base": str(BUILD / "setuptools")},
             "egg_info": {"egg_base": str(BUILD)}},
)
