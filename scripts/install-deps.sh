#!/usr/bin/env bash
# Installs kinestat's build and test dependencies from Debian 12 packages. The readers of
# other formats are optional (docs/formats.md): libtinyxml2-dev for URDF, libsdformat-dev for
# SDFormat, libmujoco-dev for MJCF; CI installs them so that every reader is tested.
set -euo pipefail
packages=(
  build-essential cmake ninja-build pkg-config
  libeigen3-dev libsuitesparse-dev libgmp-dev libyaml-cpp-dev libcli11-dev nlohmann-json3-dev libfmt-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  libtinyxml2-dev libsdformat-dev libmujoco-dev
  clang libclang-rt-14-dev
  chromium
)
# Node.js and npm build the HTML report viewer. Machines that already have them (for example
# NodeSource's nodejs, which conflicts with Debian's npm package) keep their own.
if ! command -v node >/dev/null 2>&1; then packages+=(nodejs); fi
if ! command -v npm >/dev/null 2>&1; then packages+=(npm); fi
sudo_cmd=()
if [ "$(id -u)" -ne 0 ]; then sudo_cmd=(sudo); fi
"${sudo_cmd[@]}" apt-get update -qq
DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${packages[@]}"
