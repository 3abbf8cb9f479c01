"""The PEP 517 build backend of ``pip install .`` (pyproject.toml names it; docs/python.md).

Debian 12 packages no CMake-driven backend (scikit-build-core), so this is one, small and with
no dependency beyond Python's standard library: the wheel holds exactly what ``cmake --install``
installs as the Python package (the install rules of component ``python`` in python/CMakeLists.txt,
the one list of the package's files), built by the project's own CMake.

* Build folder: ``build-pip/`` in the checkout, kept between installs so a second ``pip install .``
  only rebuilds what changed; pip's ``--config-settings build-dir=PATH`` chooses another.
  A folder without a CMakeCache.txt is configured (Release, tests and benchmarks off, for the
  interpreter running pip); one that has a CMakeCache.txt, such as the main build tree, is used as
  it is configured, and only the target of the module is built in it.
* The compiler launcher (ccache), generator and parallelism come from CMake's own environment
  variables: CMAKE_CXX_COMPILER_LAUNCHER, CMAKE_GENERATOR, CMAKE_BUILD_PARALLEL_LEVEL (default: all
  cores).
* Build requirements are Debian packages, not PyPI's (cmake, a C++20 compiler, pybind11-dev,
  python3-dev, ...: .ci/debian-packages.txt): the backend asks pip for nothing, so that
  ``pip install --no-build-isolation --no-index .`` builds offline. The one runtime requirement,
  NumPy, comes from Debian in a venv made with --system-site-packages.
* No sdist and no editable install: install from a checkout; for development use the build tree
  (PYTHONPATH=build/python).
"""

import base64
import hashlib
import os
import re
import subprocess
import sys
import sysconfig
import tempfile
import zipfile

__all__ = ["build_wheel", "get_requires_for_build_wheel", "prepare_metadata_for_build_wheel"]

_SOURCE = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
_NAME = "frictionlab"


def _project():
    """(version, description) from the project() call of CMakeLists.txt, the version's one home."""
    with open(os.path.join(_SOURCE, "CMakeLists.txt"), encoding="utf-8") as f:
        text = f.read()
    call = re.search(r'project\(\s*frictionlab\b((?:[^)"]|"[^"]*")*)\)', text)  # ")" may be quoted
    version = call and re.search(r"\bVERSION\s+([0-9][0-9.]*)", call.group(1))
    description = call and re.search(r'\bDESCRIPTION\s+"([^"]*)"', call.group(1))
    if not version:
        raise RuntimeError(f"frictionlab_build: no project(frictionlab VERSION ...) in {_SOURCE}/CMakeLists.txt")
    return version.group(1), description.group(1) if description else ""


def _dist_info():
    return f"{_NAME}-{_project()[0]}.dist-info"


def _tag():
    """The wheel's tag: this interpreter and platform (the extension is CPython's C ABI)."""
    impl = {"cpython": "cp"}.get(sys.implementation.name, sys.implementation.name)
    python = f"{impl}{sys.version_info.major}{sys.version_info.minor}"
    abi = python + getattr(sys, "abiflags", "")
    platform = sysconfig.get_platform().replace("-", "_").replace(".", "_")
    return f"{python}-{abi}-{platform}"


def _metadata_files():
    version, description = _project()
    metadata = (f"Metadata-Version: 2.1\nName: {_NAME}\nVersion: {version}\nSummary: {description}\n"
                "License: MIT\nRequires-Python: >=3.9\nRequires-Dist: numpy\n")
    wheel = (f"Wheel-Version: 1.0\nGenerator: frictionlab_build (python/packaging)\n"
             f"Root-Is-Purelib: false\nTag: {_tag()}\n")
    return {"METADATA": metadata.encode(), "WHEEL": wheel.encode()}


def _run(*command):
    print("frictionlab_build:", " ".join(command), flush=True)
    try:
        subprocess.run(command, check=True)
    except FileNotFoundError:
        raise RuntimeError(f"frictionlab_build: {command[0]} not found: install the Debian packages of "
                           ".ci/debian-packages.txt (cmake, a C++ compiler, pybind11-dev, python3-dev)") from None


def _build_package(build_dir, stage):
    """Configures (if needed) and builds the module in build_dir; installs the package into stage.
    Returns the folder of the installed package (stage/<FRICTIONLAB_PYTHON_INSTALL_DIR>/frictionlab)."""
    cmake = os.environ.get("CMAKE", "cmake")
    if not os.path.exists(os.path.join(build_dir, "CMakeCache.txt")):
        # CMake finds NumPy through this interpreter; pip's build isolation hides Debian's.
        try:
            import numpy  # noqa: F401
        except ImportError:
            raise RuntimeError("frictionlab_build: NumPy cannot be imported by the build: give pip "
                               "--no-build-isolation, in a venv made with --system-site-packages "
                               "(NumPy from Debian's python3-numpy)") from None
        _run(cmake, "-S", _SOURCE, "-B", build_dir, "-DCMAKE_BUILD_TYPE=Release", "-DBUILD_TESTING=OFF",
             "-DFRICTIONLAB_BUILD_BENCHMARKS=OFF", "-DFRICTIONLAB_BUILD_PYTHON=ON",
             f"-DPython3_EXECUTABLE={sys.executable}")
    jobs = os.environ.get("CMAKE_BUILD_PARALLEL_LEVEL") or str(os.cpu_count() or 1)
    _run(cmake, "--build", build_dir, "--target", "frictionlab_python", "--parallel", jobs)
    _run(cmake, "--install", build_dir, "--component", "python", "--prefix", stage)
    packages = [root for root, dirs, files in os.walk(stage)
                if os.path.basename(root) == _NAME and "__init__.py" in files]
    if len(packages) != 1:
        raise RuntimeError(f"frictionlab_build: `cmake --install --component python` of {build_dir} "
                           f"installed {len(packages)} packages named {_NAME}, not one")
    # The extension must be this interpreter's: a build folder configured for another Python
    # would give a wheel that installs and then fails to import.
    suffix = sysconfig.get_config_var("EXT_SUFFIX")
    if not os.path.exists(os.path.join(packages[0], "_core" + suffix)):
        found = [f for f in os.listdir(packages[0]) if f.startswith("_core")]
        raise RuntimeError(f"frictionlab_build: {build_dir} builds {found} for another Python, not _core{suffix} "
                           f"for {sys.executable}: choose another build folder (--config-settings build-dir=PATH)")
    return packages[0]


def _record_line(path, data):
    digest = base64.urlsafe_b64encode(hashlib.sha256(data).digest()).rstrip(b"=").decode()
    return f"{path},sha256={digest},{len(data)}"


def get_requires_for_build_wheel(config_settings=None):
    return []


def prepare_metadata_for_build_wheel(metadata_directory, config_settings=None):
    folder = os.path.join(metadata_directory, _dist_info())
    os.makedirs(folder, exist_ok=True)
    for name, data in _metadata_files().items():
        with open(os.path.join(folder, name), "wb") as f:
            f.write(data)
    return _dist_info()


def build_wheel(wheel_directory, config_settings=None, metadata_directory=None):
    settings = config_settings or {}
    build_dir = os.path.abspath(settings.get("build-dir") or os.path.join(_SOURCE, "build-pip"))
    version = _project()[0]
    wheel_name = f"{_NAME}-{version}-{_tag()}.whl"
    with tempfile.TemporaryDirectory(prefix="frictionlab-wheel-") as stage:
        package = _build_package(build_dir, stage)
        files = {}
        for name in sorted(os.listdir(package)):
            path = os.path.join(package, name)
            if os.path.isfile(path):
                with open(path, "rb") as f:
                    files[f"{_NAME}/{name}"] = f.read()
        for name, data in _metadata_files().items():
            files[f"{_dist_info()}/{name}"] = data
        record = f"{_dist_info()}/RECORD"
        lines = [_record_line(path, data) for path, data in files.items()] + [f"{record},,"]
        files[record] = ("\n".join(lines) + "\n").encode()
        os.makedirs(wheel_directory, exist_ok=True)
        target = os.path.join(wheel_directory, wheel_name)
        with zipfile.ZipFile(target + ".part", "w", compression=zipfile.ZIP_DEFLATED) as z:
            for path, data in files.items():
                info = zipfile.ZipInfo(path, date_time=(1980, 1, 1, 0, 0, 0))
                info.external_attr = 0o644 << 16
                info.compress_type = zipfile.ZIP_DEFLATED
                z.writestr(info, data)
        os.replace(target + ".part", target)
    return wheel_name
