"""The build of `pip install .` and `python -m build --wheel` (pyproject.toml): setuptools packs
the module `tetcut` that the project's own CMake builds.

Where CMake builds it:
  - TETCUT_CMAKE_BUILD_DIR set (an environment variable): in that existing, configured build
    tree (`cmake --preset release` makes build/release), by `cmake --build DIR --target
    tetcut_python`, which does nothing when the module is up to date. For a developer who has
    built the tree already, and for ctest's install tests, which reuse the module just built.
    The tree must have been configured for this interpreter's ABI (its Python3_EXECUTABLE).
  - otherwise: in build/python-<interpreter tag>/ of this checkout, configured on first use for
    the running interpreter (Release, the module's targets only) and built incrementally after:
    a fresh checkout builds from scratch (minutes on two cores), a second install takes seconds.
CMake's own environment applies: CMAKE_BUILD_PARALLEL_LEVEL, CMAKE_CXX_COMPILER_LAUNCHER (ccache).
setuptools' own scratch folders (build/, *.egg-info) go into a temporary folder of each run, not
into the checkout, so that two builds at once do not share them.
"""
import atexit
import os
import pathlib
import shutil
import subprocess
import sys
import sysconfig
import tempfile

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

SOURCE = pathlib.Path(__file__).resolve().parent


def cmake_build_dir():
    """(the CMake build tree, whether it is the caller's own)."""
    given = os.environ.get("TETCUT_CMAKE_BUILD_DIR")
    if given:
        return pathlib.Path(given).resolve(), True
    tag = sys.implementation.cache_tag or f"py{sys.version_info[0]}{sys.version_info[1]}"
    return SOURCE / "build" / f"python-{tag}", False


def run(command):
    print("$", " ".join(str(c) for c in command), flush=True)
    subprocess.run([str(c) for c in command], check=True)


class CMakeExtension(Extension):
    """The module, built by CMake rather than by setuptools' compiler."""

    def __init__(self, name):
        super().__init__(name, sources=[])


class CMakeBuild(build_ext):
    def build_extension(self, ext):
        build_dir, given = cmake_build_dir()
        if given and not (build_dir / "CMakeCache.txt").exists():
            raise SystemExit(f"TETCUT_CMAKE_BUILD_DIR={build_dir}: not a configured CMake build tree "
                             "(cmake --preset release makes build/release)")
        if not given and not (build_dir / "CMakeCache.txt").exists():
            configure = ["cmake", "-S", SOURCE, "-B", build_dir, "-DCMAKE_BUILD_TYPE=Release",
                         f"-DPython3_EXECUTABLE={sys.executable}", "-DTETCUT_BUILD_PYTHON=ON",
                         "-DTETCUT_BUILD_TESTS=OFF", "-DTETCUT_BUILD_BENCH=OFF", "-DTETCUT_INSTALL=OFF"]
            if shutil.which("ninja"):
                configure += ["-G", "Ninja"]
            run(configure)
        run(["cmake", "--build", build_dir, "--target", "tetcut_python"])
        module = build_dir / "python" / "module" / ("tetcut" + sysconfig.get_config_var("EXT_SUFFIX"))
        if not module.exists():
            raise SystemExit(f"{build_dir}: no {module.name}: the tree was configured for another Python than "
                             f"{sys.executable} (its Python3_EXECUTABLE), or without the module (TETCUT_BUILD_PYTHON)")
        target = pathlib.Path(self.get_ext_fullpath(ext.name))
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(module, target)
        # The stub beside the module, as `cmake --install` puts it: IDEs and type checkers read it.
        shutil.copyfile(SOURCE / "python" / "tetcut.pyi", target.parent / "tetcut.pyi")


scratch = pathlib.Path(tempfile.mkdtemp(prefix="tetcut-setuptools-"))
atexit.register(shutil.rmtree, scratch, ignore_errors=True)
setup(
    ext_modules=[CMakeExtension("tetcut")],
    cmdclass={"build_ext": CMakeBuild},
    options={"build": {"build_base": str(scratch / "build")}, "egg_info": {"egg_base": str(scratch)}},
)
