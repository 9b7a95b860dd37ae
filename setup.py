"""Builds the Python package wrc with the project's CMake (pyproject.toml): the module wrc._wrc and the reader
plugins only, then puts into the wheel the package (python/wrc, the generated stub) and the data the engine reads
(scripts, profiles, plugins) under wrc/share/wrc and wrc/lib/wrc/plugins, where the module finds them."""
import os
import pathlib
import shlex
import shutil
import subprocess
import sys

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = pathlib.Path(__file__).resolve().parent
# setuptools' own build folder: not build/, which is the README's CMake build.
BUILD_BASE = os.environ.get("WRC_SETUP_BUILD", str(ROOT / "build-python"))
os.makedirs(BUILD_BASE, exist_ok=True)


class CMakeBuild(build_ext):
    def build_extension(self, ext):
        build = pathlib.Path(self.build_temp).resolve() / "cmake"
        package = pathlib.Path(self.get_ext_fullpath(ext.name)).resolve().parent
        jobs = os.environ.get("WRC_BUILD_JOBS", "2")
        # CMAKE_ARGS (the environment variable conda-build and scikit-build also read): more configure arguments.
        extra = shlex.split(os.environ.get("CMAKE_ARGS", ""))
        subprocess.run(["cmake", "-S", str(ROOT), "-B", str(build), "-DCMAKE_BUILD_TYPE=Release",
                        "-DWRC_BUILD_TESTS=OFF", f"-DWRC_PYTHON_EXECUTABLE={sys.executable}", *extra], check=True)
        subprocess.run(["cmake", "--build", str(build), "-j", jobs, "--target", "wrc_python", "wrc_plugins"],
                       check=True)
        built = build / "python" / "wrc"
        if not any(built.glob("_wrc*.so")):
            sys.exit(f"setup.py: CMake built no module in {built} (is python3-pybind11 installed for {sys.executable}?)")
        package.mkdir(parents=True, exist_ok=True)
        for f in built.iterdir():
            if f.is_file():
                shutil.copy2(f, package / f.name)
        share = package / "share" / "wrc"
        for folder in ("scripts", "profiles"):
            shutil.rmtree(share / folder, ignore_errors=True)
            shutil.copytree(ROOT / folder, share / folder)
        plugins = package / "lib" / "wrc" / "plugins"
        shutil.rmtree(plugins, ignore_errors=True)
        plugins.mkdir(parents=True)
        for f in (build / "plugins").glob("*.so"):
            shutil.copy2(f, plugins / f.name)


setup(
    packages=["wrc"],
    package_dir={"": "python"},
    package_data={"wrc": ["py.typed", "*.pyi"]},
    ext_modules=[Extension("wrc._wrc", sources=[])],
    cmdclass={"build_ext": CMakeBuild},
    zip_safe=False,
    options={"build": {"build_base": BUILD_BASE}, "egg_info": {"egg_base": BUILD_BASE}},
)
