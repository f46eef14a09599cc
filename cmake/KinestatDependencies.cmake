# All dependencies come from Debian packages; nothing is downloaded at build time.
find_package(Eigen3 3.3 REQUIRED NO_MODULE)
find_package(yaml-cpp REQUIRED)
find_package(fmt REQUIRED)
find_package(nlohmann_json 3 REQUIRED)
find_package(CLI11 REQUIRED)
find_package(PkgConfig REQUIRED)
pkg_check_modules(GMPXX REQUIRED IMPORTED_TARGET gmpxx gmp)

# SuiteSparse 5 on Debian 12 ships no CMake config for SPQR: find it by hand.
find_path(SUITESPARSE_INCLUDE_DIR SuiteSparseQR.hpp PATH_SUFFIXES suitesparse REQUIRED)
find_library(SPQR_LIBRARY spqr REQUIRED)
find_library(CHOLMOD_LIBRARY cholmod REQUIRED)
find_library(SUITESPARSECONFIG_LIBRARY suitesparseconfig REQUIRED)
# Debian's OpenBLAS (libopenblas-dev) is the BLAS/LAPACK that SuiteSparse's dense kernels run
# on (through the libblas.so.3 alternative); kinestat links it directly to pin its threads.
find_library(OPENBLAS_LIBRARY openblas REQUIRED)
add_library(kinestat_suitesparse INTERFACE)
target_include_directories(kinestat_suitesparse SYSTEM INTERFACE ${SUITESPARSE_INCLUDE_DIR})
target_link_libraries(kinestat_suitesparse INTERFACE ${SPQR_LIBRARY} ${CHOLMOD_LIBRARY} ${SUITESPARSECONFIG_LIBRARY}
  ${OPENBLAS_LIBRARY})
