# SPDX-License-Identifier: BSD-3-Clause
# The HTML report's viewer: three.js from the npm registry (viewer/package.json and the
# committed package-lock.json, installed with `npm ci` into the build tree at build time) and
# kinestat's own viewer.js / viewer.css, embedded into the library as string literals.
# Without npm, or when `npm ci` fails (offline, a TLS proxy), the build still succeeds and
# `kinestat report` says that HTML output is not built in; the next build looks for npm and
# tries again (the stamp below is written only once the viewer is in, so the step stays out
# of date). -DKINESTAT_VIEWER=OFF leaves the viewer out for good.
option(KINESTAT_VIEWER "Embed the three.js HTML report viewer (needs npm at build time)" ON)
set(KINESTAT_VIEWER_WORK ${CMAKE_BINARY_DIR}/viewer)
set(KINESTAT_VIEWER_SOURCE ${PROJECT_SOURCE_DIR}/viewer)
file(MAKE_DIRECTORY ${KINESTAT_VIEWER_WORK})
add_custom_command(
  OUTPUT ${KINESTAT_VIEWER_WORK}/viewer_assets.cpp ${KINESTAT_VIEWER_WORK}/viewer_built_in.cmake
         ${KINESTAT_VIEWER_WORK}/viewer.complete
  COMMAND ${CMAKE_COMMAND} -DWANT_VIEWER=${KINESTAT_VIEWER} -DVIEWER_SOURCE=${KINESTAT_VIEWER_SOURCE}
          -DWORK=${KINESTAT_VIEWER_WORK} -DOUTPUT=${KINESTAT_VIEWER_WORK}/viewer_assets.cpp
          -P ${PROJECT_SOURCE_DIR}/cmake/EmbedViewer.cmake
  DEPENDS ${PROJECT_SOURCE_DIR}/cmake/EmbedViewer.cmake ${KINESTAT_VIEWER_SOURCE}/package.json
          ${KINESTAT_VIEWER_SOURCE}/package-lock.json ${KINESTAT_VIEWER_SOURCE}/viewer.js ${KINESTAT_VIEWER_SOURCE}/viewer.css
  COMMENT "Embedding the HTML report viewer (three.js via npm ci)"
  VERBATIM)
# Generated code: string literals only; kinestat's warning flags do not apply to it.
set_source_files_properties(${KINESTAT_VIEWER_WORK}/viewer_assets.cpp PROPERTIES COMPILE_OPTIONS -w)
