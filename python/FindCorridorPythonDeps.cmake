# Finds what the Python module needs: a Python 3 interpreter with numpy, its headers, and
# pybind11's CMake package (Debian: python3-dev, python3-numpy, pybind11-dev). Sets
# CORRIDOR_PYTHON_DEPS_FOUND. Included by the top CMakeLists.txt before CORRIDOR_BUILD_PYTHON is
# declared, since that option's default depends on it.
#
# The interpreter first on PATH may be one without numpy (a pyenv shim, say): unless
# Python3_EXECUTABLE is given, the first of `python3` on PATH and /usr/bin/python3 that imports
# numpy is taken.
set(CORRIDOR_PYTHON_DEPS_FOUND OFF)
if(NOT DEFINED Python3_EXECUTABLE)
  find_program(corridor_python_on_path NAMES python3 NO_CACHE)
  foreach(candidate ${corridor_python_on_path} /usr/bin/python3)
    if(EXISTS "${candidate}")
      execute_process(COMMAND "${candidate}" -c "import numpy"
                      RESULT_VARIABLE corridor_numpy_rc OUTPUT_QUIET ERROR_QUIET)
      if(corridor_numpy_rc EQUAL 0)
        set(Python3_EXECUTABLE "${candidate}" CACHE FILEPATH "Python 3 interpreter with numpy")
        break()
      endif()
    endif()
  endforeach()
endif()
find_package(Python3 COMPONENTS Interpreter Development.Module NumPy QUIET)
if(Python3_FOUND AND Python3_NumPy_FOUND)
  # Found after Python3, pybind11 uses FindPython's targets (its "new" mode).
  find_package(pybind11 CONFIG QUIET)
  if(pybind11_FOUND)
    set(CORRIDOR_PYTHON_DEPS_FOUND ON)
  endif()
endif()
