# SPDX-License-Identifier: BSD-3-Clause
# FLINT (Debian libflint-dev, FLINT 2.9) eliminates for the exact path: ranks, null spaces and
# inverses of rational matrices (src/kinestat/linalg/flint_elimination.*), several times faster
# than kinestat's GMP elimination, which remains the fallback of a build without it.
# KINESTAT_FLINT is ON when FLINT is found (like the optional readers); ON without it stops here.
# Debian's FLINT 2.9 ships no pkg-config file or CMake package: header and library are looked up.
find_path(KINESTAT_FLINT_INCLUDE_DIR flint/fmpq_mat.h)
find_library(KINESTAT_FLINT_LIBRARY flint)
set(kinestat_flint_found OFF)
if(KINESTAT_FLINT_INCLUDE_DIR AND KINESTAT_FLINT_LIBRARY)
  set(kinestat_flint_found ON)
endif()
option(KINESTAT_FLINT "Exact elimination by FLINT (libflint-dev); without it, GMP elimination" ${kinestat_flint_found})
if(KINESTAT_FLINT AND NOT kinestat_flint_found)
  message(FATAL_ERROR "KINESTAT_FLINT=ON but FLINT was not found (Debian: libflint-dev)")
endif()
message(STATUS "kinestat exact elimination: FLINT ${KINESTAT_FLINT}")

# Adds FLINT to `target` (kinestat) privately: KINESTAT_HAVE_FLINT and FLINT's headers for the
# one source that calls it (the rest of the library compiles as without it, and a unity build
# keeps that file apart), the library to the link by name (-lflint), so that an installed
# static kinestat names no path.
function(kinestat_add_flint target)
  if(KINESTAT_FLINT)
    set(source ${PROJECT_SOURCE_DIR}/src/kinestat/linalg/flint_elimination.cpp)
    set_property(SOURCE ${source} TARGET_DIRECTORY ${target} APPEND PROPERTY COMPILE_DEFINITIONS KINESTAT_HAVE_FLINT)
    # Not for /usr/include (Debian's): -isystem /usr/include breaks GCC's #include_next of <cstdlib>.
    if(NOT KINESTAT_FLINT_INCLUDE_DIR MATCHES "^/usr/include/?$")
      set_property(SOURCE ${source} TARGET_DIRECTORY ${target} APPEND PROPERTY COMPILE_OPTIONS "-isystem${KINESTAT_FLINT_INCLUDE_DIR}")
    endif()
    target_link_libraries(${target} PRIVATE $<LINK_ONLY:flint>)
  endif()
endfunction()
