# The HTML report's viewer: three.js from the npm registry (viewer/package.json and the
# committed package-lock.json, installed with `npm ci` into the build tree at build time) and
# kinestat's own viewer.js / viewer.css, embedded into the library as string literals.
# Without npm (or with -DKINESTAT_VIEWER=OFF) the build still succeeds and `kinestat report`
# says that HTML output is not built in.
option(KINESTAT_VIEWER "Embed the three.js HTML report viewer (needs npm at build time)" ON)
set(KINESTAT_NPM "")
if(KINESTAT_VIEWER)
  find_program(KINESTAT_NPM_PROGRAM npm)
  if(KINESTAT_NPM_PROGRAM)
    set(KINESTAT_NPM ${KINESTAT_NPM_PROGRAM})
  else()
    message(STATUS "kinestat: npm not found; HTML reports will not be built in")
  endif()
endif()
set(KINESTAT_VIEWER_WORK ${CMAKE_BINARY_DIR}/viewer)
set(KINESTAT_VIEWER_SOURCE ${PROJECT_SOURCE_DIR}/viewer)
file(MAKE_DIRECTORY ${KINESTAT_VIEWER_WORK})
add_custom_command(
  OUTPUT ${KINESTAT_VIEWER_WORK}/viewer_assets.cpp
  COMMAND ${CMAKE_COMMAND} -DNPM=${KINESTAT_NPM} -DVIEWER_SOURCE=${KINESTAT_VIEWER_SOURCE} -DWORK=${KINESTAT_VIEWER_WORK}
          -DOUTPUT=${KINESTAT_VIEWER_WORK}/viewer_assets.cpp -P ${PROJECT_SOURCE_DIR}/cmake/EmbedViewer.cmake
  DEPENDS ${PROJECT_SOURCE_DIR}/cmake/EmbedViewer.cmake ${KINESTAT_VIEWER_SOURCE}/package.json
          ${KINESTAT_VIEWER_SOURCE}/package-lock.json ${KINESTAT_VIEWER_SOURCE}/viewer.js ${KINESTAT_VIEWER_SOURCE}/viewer.css
  COMMENT "Embedding the HTML report viewer (three.js via npm ci)"
  VERBATIM)
add_library(kinestat_viewer_assets STATIC ${KINESTAT_VIEWER_WORK}/viewer_assets.cpp)
set_target_properties(kinestat_viewer_assets PROPERTIES POSITION_INDEPENDENT_CODE ON)
