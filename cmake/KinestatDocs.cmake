# SPDX-License-Identifier: BSD-3-Clause
# The documentation site (docs/site/build_site.py): `cmake --build <build> --target docs` writes
# <build>/docs/html/index.html — the tutorial, the gallery of examples/ (pictures by the built
# `kinestat draw`, verdicts by `kinestat analyze`), docs/*.md as the guide, the Python API
# (Sphinx autodoc of the built module) and the C++ API (Doxygen, Doxyfile). Not part of `all`.
# Needs Debian's doxygen, python3-sphinx and python3-myst-parser; the CTest test `docs_site`
# builds it too and is skipped without them.
set(kinestat_docs_command /usr/bin/python3 ${PROJECT_SOURCE_DIR}/docs/site/build_site.py
    --cli $<TARGET_FILE:kinestat_cli> --out ${CMAKE_BINARY_DIR}/docs --version ${PROJECT_VERSION})
if(KINESTAT_PYTHON_BUILT)
  list(APPEND kinestat_docs_command --python ${CMAKE_BINARY_DIR}/python)
endif()
add_custom_target(docs COMMAND ${kinestat_docs_command} WORKING_DIRECTORY ${PROJECT_SOURCE_DIR} USES_TERMINAL
                  COMMENT "Documentation site: ${CMAKE_BINARY_DIR}/docs/html/index.html")
add_dependencies(docs kinestat_cli)
if(KINESTAT_PYTHON_BUILT)
  add_dependencies(docs kinestat_python)
endif()
if(KINESTAT_BUILD_TESTS)
  add_test(NAME docs_site COMMAND ${kinestat_docs_command} WORKING_DIRECTORY ${PROJECT_SOURCE_DIR})
  set_tests_properties(docs_site PROPERTIES LABELS docs TIMEOUT 300 SKIP_RETURN_CODE 77)
endif()
