"""Package.PipInstallFromCheckout: `pip install .` from the checkout, as docs/python.md tells a user.

A venv made with Debian's python3-venv (--system-site-packages: NumPy from Debian), then
`pip install --no-index --no-build-isolation` of the source tree: offline, through the in-tree
backend (pyproject.toml, python/packaging/frictionlab_build.py), which runs the project's CMake.
To keep CI fast the backend is pointed at this build tree (--config-settings build-dir=...): it
builds the module's target there (up to date after the build) and installs component `python`
into the wheel. Then the package is imported, from outside the source tree and with no
PYTHONPATH, and must come from the venv; a law is evaluated. Exits 77 (ctest: skipped) when
python3-venv is not installed.

usage: pip_install_check.py SOURCE_DIR BUILD_DIR WORK_DIR
"""

import os
import shutil
import subprocess
import sys

SKIP = 77


def main(source, build, work):
    try:
        import ensurepip  # noqa: F401 (Debian ships venv's pip in python3-venv)
        import venv  # noqa: F401
    except ImportError as e:
        print(f"SKIP: python3-venv is not installed ({e}): apt-get install python3-venv")
        return SKIP
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    env = {k: v for k, v in os.environ.items() if not k.startswith(("PYTHON", "PIP_"))}
    env["PIP_DISABLE_PIP_VERSION_CHECK"] = "1"
    env["PYTHONDONTWRITEBYTECODE"] = "1"  # pip imports the backend from the source tree: keep it clean
    venv_dir = os.path.join(work, "venv")
    subprocess.run([sys.executable, "-m", "venv", "--system-site-packages", venv_dir], check=True, env=env)
    python = os.path.join(venv_dir, "bin", "python")
    subprocess.run([python, "-m", "pip", "install", "--no-index", "--no-build-isolation", "--no-cache-dir",
                    "--config-settings", f"build-dir={build}", source], check=True, env=env, cwd=work)
    # Pure sliding (Omega = 0): F1 = k N = 0.5 * 2 exactly, F2 = M = 0 (friction/law.h).
    check = """if True:
        import os, sys, sysconfig, frictionlab
        where = os.path.realpath(frictionlab.__file__)
        site = os.path.realpath(sysconfig.get_paths()["platlib"])
        assert where.startswith(site + os.sep), f"imported {where}, not from the venv's {site}"
        F1, F2, M = frictionlab.Law("exact")(U=1.0, Omega=0.0, a=0.01, b=0.005, psi=0.3, N=2.0, k=0.5)
        assert (F1, F2, M) == (1.0, 0.0, 0.0), (F1, F2, M)
        # pip's record of it (the backend's metadata) and the module agree on the version.
        from importlib.metadata import version
        assert version("frictionlab") == frictionlab.__version__, (version("frictionlab"), frictionlab.__version__)
        print("imported", where, "version", frictionlab.__version__)
    """
    subprocess.run([python, "-c", check], check=True, env=env, cwd=work)
    return 0


if __name__ == "__main__":
    if len(sys.argv) != 4:
        sys.exit(__doc__.strip().splitlines()[-1])
    sys.exit(main(*(os.path.abspath(a) for a in sys.argv[1:])))
