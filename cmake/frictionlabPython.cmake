# The Python module `frictionlab` (python/, docs/python.md), built with pybind11 for Debian's
# Python 3: the interpreter that python3-dev, python3-numpy and pybind11-dev belong to. Another
# python3 may come first on PATH (pyenv, a virtual environment) and have no NumPy or no headers,
# so /usr/bin/python3 is chosen explicitly unless -DPython3_EXECUTABLE=... says otherwise.
#
# FRICTIONLAB_BUILD_PYTHON is ON by default when frictionlab is the top-level project, not built
# with the sanitizers (an uninstrumented interpreter cannot load an instrumented module), and both
# pybind11 and that interpreter (with its headers and NumPy) are found; turned ON by hand, a
# missing piece stops the configuration.
if(NOT DEFINED Python3_EXECUTABLE AND EXISTS /usr/bin/python3)
  set(Python3_EXECUTABLE /usr/bin/python3 CACHE FILEPATH
      "The Python 3 interpreter the module is built and tested for (Debian's by default)")
endif()
find_package(Python3 3.9 QUIET COMPONENTS Interpreter Development.Module NumPy)
if(Python3_FOUND)
  find_package(pybind11 2.6 CONFIG QUIET)  # after Python3: pybind11 then uses FindPython3's result
endif()
if(PROJECT_IS_TOP_LEVEL AND NOT FRICTIONLAB_SANITIZE AND Python3_FOUND AND pybind11_FOUND)
  set(frictionlab_python_default ON)
else()
  set(frictionlab_python_default OFF)
endif()
option(FRICTIONLAB_BUILD_PYTHON "Build the Python module frictionlab (needs pybind11-dev, python3-dev, python3-numpy)"
       ${frictionlab_python_default})
if(FRICTIONLAB_BUILD_PYTHON)
  if(NOT Python3_FOUND)
    message(FATAL_ERROR "FRICTIONLAB_BUILD_PYTHON is ON but Python 3 with its headers and NumPy was not found "
                        "(${Python3_EXECUTABLE}): install python3-dev and python3-numpy, or set "
                        "-DPython3_EXECUTABLE=..., or -DFRICTIONLAB_BUILD_PYTHON=OFF")
  endif()
  if(NOT pybind11_FOUND)
    message(FATAL_ERROR "FRICTIONLAB_BUILD_PYTHON is ON but pybind11 was not found: install pybind11-dev, "
                        "or -DFRICTIONLAB_BUILD_PYTHON=OFF")
  endif()
  # Where `cmake --install` puts the package, relative to the prefix: a folder on the Debian
  # interpreter's path for both /usr and /usr/local (lib/python3.X/dist-packages).
  set(FRICTIONLAB_PYTHON_INSTALL_DIR "lib/python${Python3_VERSION_MAJOR}.${Python3_VERSION_MINOR}/dist-packages"
      CACHE STRING "Where the Python package frictionlab is installed, relative to the install prefix")
  message(STATUS "frictionlab: Python module for ${Python3_EXECUTABLE} (${Python3_VERSION}), pybind11 ${pybind11_VERSION}")
endif()
