"""The compiled part of `pip install .`: CMake builds the `_meshstep` target (the core and
the binding, MESHSTEP_PYTHON_ONLY) for the interpreter running pip, and the result is copied
where setuptools packs the extension. Everything else is in pyproject.toml."""
import os
import pathlib
import shutil
import subprocess
import sys

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = pathlib.Path(__file__).resolve().parent


class CMakeBuild(build_ext):
    def build_extension(self, ext):
        # Beside build/ (MESHSTEP_PIP_BUILD_DIR to change): the compiler cache finds the
        # objects of a build/ made with the same flags.
        build_dir = pathlib.Path(os.environ.get("MESHSTEP_PIP_BUILD_DIR", ROOT / "build-pip"))
        configure = ["cmake", "-S", str(ROOT), "-B", str(build_dir), "-DCMAKE_BUILD_TYPE=Release",
                     "-DMESHSTEP_PYTHON_ONLY=ON", f"-DPython_EXECUTABLE={sys.executable}"]
        if shutil.which("ninja"):
            configure += ["-G", "Ninja"]
        if shutil.which("ccache"):
            configure += ["-DCMAKE_CXX_COMPILER_LAUNCHER=ccache"]
        subprocess.run(configure, check=True)
        jobs = str(os.cpu_count() or 2)
        subprocess.run(["cmake", "--build", str(build_dir), "--target", "_meshstep", "-j", jobs], check=True)
        built = sorted((build_dir / "python" / "meshstep").glob("_meshstep*.so"))
        if not built:
            raise RuntimeError(f"CMake built no _meshstep module in {build_dir / 'python' / 'meshstep'}")
        target = pathlib.Path(self.get_ext_fullpath(ext.name))
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(built[-1], target)


setup(ext_modules=[Extension("meshstep._meshstep", sources=[])], cmdclass={"build_ext": CMakeBuild})
