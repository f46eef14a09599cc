# SPDX-License-Identifier: BSD-3-Clause
# The Python module `kinestat` (python/), built with pybind11 from Debian's python3-pybind11
# against /usr/bin/python3 (python3-dev); nothing is downloaded. KINESTAT_PYTHON=AUTO builds
# it when both are found, ON insists, OFF skips. Its pytest suite is registered in CTest.
set(KINESTAT_PYTHON_BUILT OFF)
if(NOT KINESTAT_PYTHON STREQUAL "OFF")
  # The Debian interpreter: the `python3` first on PATH may be another one without numpy.
  if(NOT DEFINED PYTHON_EXECUTABLE AND EXISTS /usr/bin/python3)
    set(PYTHON_EXECUTABLE /usr/bin/python3 CACHE FILEPATH "Python interpreter the module is built for")
  endif()
  set(have_python_headers FALSE)
  if(PYTHON_EXECUTABLE)
    execute_process(COMMAND ${PYTHON_EXECUTABLE} -c "import sysconfig; print(sysconfig.get_paths()['include'])"
                    OUTPUT_VARIABLE python_include OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
    if(python_include AND EXISTS "${python_include}/Python.h")
      set(have_python_headers TRUE)
    endif()
  endif()
  if(have_python_headers)
    find_package(pybind11 2.6 CONFIG QUIET)
  endif()
  if(have_python_headers AND pybind11_FOUND)
    set(KINESTAT_PYTHON_BUILT ON)
    add_subdirectory(${PROJECT_SOURCE_DIR}/python ${PROJECT_BINARY_DIR}/python)
  elseif(KINESTAT_PYTHON STREQUAL "ON")
    message(FATAL_ERROR "KINESTAT_PYTHON=ON needs pybind11 (Debian: python3-pybind11) and the headers of "
                        "${PYTHON_EXECUTABLE} (python3-dev)")
  else()
    message(STATUS "kinestat: Python module not built (needs python3-pybind11 and python3-dev)")
  endif()
endif()
