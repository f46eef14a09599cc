#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Installs kinestat's build and test dependencies from Debian 12 packages. Run it as root, or
# as a user who may use sudo; anything else stops here with a message.
# The readers of other formats are optional (docs/formats.md): libtinyxml2-dev for URDF,
# libsdformat-dev for SDFormat, libmujoco-dev for MJCF; CI installs them so every reader is tested.
set -euo pipefail
# --minimal: only what the `user` preset needs for the library, the command and every reader;
# no test frameworks, benchmarks, clang, Chromium or MPI, no Python module (python3-dev
# python3-pybind11 python3-numpy) and no npm for the HTML report's viewer (without npm the build
# leaves the viewer out and `kinestat report` says so). Install those and build again to add them.
# --build: what the `release` preset needs to configure and compile, with Python and MPI (CI's
# release-build stage); not what only the tests or the `asan` preset use (pytest, SciPy, Jupyter,
# jsonschema, Doxygen, Sphinx, clang, Chromium). .ci/run installs those with a second, full run
# while the release preset builds: apt mostly waits on the network, the build on the cores.
mode=full
case "${1:-}" in
  --minimal) mode=minimal ;;
  --build) mode=build ;;
  "") ;;
  *) echo "usage: scripts/install-deps.sh [--minimal | --build]" >&2; exit 2 ;;
esac
packages=(
  git build-essential cmake ninja-build pkg-config
  libeigen3-dev libsuitesparse-dev libopenblas-dev libgmp-dev libflint-dev libyaml-dev libcli11-dev nlohmann-json3-dev libfmt-dev
  # MuJoCo is found by its header and library (cmake/kinestatMuJoCo.cmake), not by its CMake
  # package, which would also want libgl-dev (Mesa, LLVM) and libqhull-dev.
  libtinyxml2-dev libsdformat-dev libmujoco-dev
)
if [[ $mode != minimal ]]; then
  packages+=(
    # The Python module (pybind11), for Debian's /usr/bin/python3; the `user` preset builds it
    # too when these are installed (KINESTAT_PYTHON=AUTO).
    python3-dev python3-pybind11 python3-numpy
    libgtest-dev libgmock-dev libbenchmark-dev
    # ccache: .ci/run uses it when present (objects shared between CI clones).
    ccache
    # The optional distributed backend (`analyze --backend petsc`, cmake/KinestatPetsc.cmake):
    # OpenMPI (the decomposition's processes; SuiteSparseQR factors each part). CI builds it in the
    # release preset and runs its tests (ctest label `mpi`, under mpirun -n 2); a build without
    # them simply leaves it out.
    libopenmpi-dev openmpi-bin
  )
  # Node.js and npm build the HTML report viewer. Machines that already have them (for example
  # NodeSource's nodejs, which conflicts with Debian's npm package) keep their own.
  if ! command -v node >/dev/null 2>&1; then packages+=(nodejs); fi
  if ! command -v npm >/dev/null 2>&1; then packages+=(npm); fi
fi
if [[ $mode == full ]]; then
  packages+=(
    python3-pytest
    # The Python tests: pip install into a venv, the sparse rigidity matrix, the example notebook
    # executed by Jupyter (each test is skipped without its package).
    python3-venv python3-setuptools python3-wheel python3-scipy jupyter-nbconvert python3-ipykernel
    # JSON Schema validation of every example and report (schemas/).
    python3-jsonschema python3-yaml
    # The documentation site (`cmake --build ... --target docs`, test docs_site).
    doxygen python3-sphinx python3-myst-parser
    clang libclang-rt-14-dev
    chromium
  )
fi
as_root=()
if [ "$(id -u)" -ne 0 ]; then
  if ! command -v sudo >/dev/null 2>&1; then
    echo "install-deps.sh: installing Debian packages needs root: run it as root, or install sudo and" \
         "allow this user to use it (packages: ${packages[*]})" >&2
    exit 1
  fi
  as_root=(sudo)
fi
# `env` carries DEBIAN_FRONTEND through sudo, which would otherwise drop it.
"${as_root[@]}" env DEBIAN_FRONTEND=noninteractive apt-get update -qq
"${as_root[@]}" env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends "${packages[@]}"
