#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Installs a built kinestat into a fresh prefix, builds tests/consumer against the installed
# package (the C++ example and every installed header compiled alone) and runs the example;
# builds the example again from `pkg-config kinestat` alone; checks that the installed CMake
# package and pkg-config file carry no absolute path, and, for a shared library
# (-DKINESTAT_SHARED=ON), its SONAME.
# Usage: scripts/check-install.sh [build folder, default build/release]
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build/release}
work=$build/install-check
rm -rf "$work"
cmake --install "$build" --prefix "$work/prefix" >/dev/null
prefix=$(cd "$work/prefix" && pwd)
libdir=$(dirname "$(find "$prefix" -name 'libkinestat.*' -print -quit)")
# A shared library (-DKINESTAT_SHARED=ON): its SONAME is libkinestat.so.0, the development link
# points at it, and programs of a prefix outside /usr find it (LD_LIBRARY_PATH for the checks).
shared=false
if [[ -e "$libdir/libkinestat.so.0" ]]; then
  shared=true
  soname=$(objdump -p "$libdir/libkinestat.so.0" | awk '$1 == "SONAME" {print $2}')
  [[ "$soname" == libkinestat.so.0 ]] || { echo "SONAME is '$soname', not libkinestat.so.0" >&2; exit 1; }
  [[ "$(readlink -f "$libdir/libkinestat.so")" == "$(readlink -f "$libdir/libkinestat.so.0")" ]]
  export LD_LIBRARY_PATH=$libdir${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}
  echo "shared library: SONAME $soname"
fi
# The exported CMake package and pkg-config file name no folder of this machine: dependencies
# are found again where the package is used (imported targets, ${pcfiledir}). Allowed: CMake's
# own stanza for a /usr prefix reached through a symbolic link (_realOrig, _IMPORT_PREFIX).
if grep -nE '"?/(usr|work|home|root|opt|tmp)/' "$libdir"/cmake/kinestat/*.cmake "$libdir"/pkgconfig/kinestat.pc |
   grep -vE ':[0-9]+: *#|_realOrig "/|set\(_IMPORT_PREFIX "/'; then
  echo "check-install: absolute paths in the installed CMake package or kinestat.pc (above)" >&2
  exit 1
fi
# pkg-config: a consumer compiled and linked from `pkg-config --cflags --libs` alone (--static
# for the static library, whose private dependencies come from Requires.private and Libs.private).
static_flag=--static
$shared && static_flag=
# shellcheck disable=SC2046 # one flag a word
c++ -std=c++20 -O0 examples/cpp/analyse.cpp -o "$work/pkg-config-analyse" \
  $(PKG_CONFIG_PATH=$libdir/pkgconfig pkg-config --cflags --libs $static_flag kinestat)
"$work/pkg-config-analyse" examples/davies-2-circuit.yaml | grep -q "FN = 3, CN = 2"
echo "pkg-config: $(PKG_CONFIG_PATH=$libdir/pkgconfig pkg-config --modversion kinestat), a consumer built from its flags runs"
cmake -S tests/consumer -B "$work/consumer" -G Ninja -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_PREFIX_PATH="$PWD/$work/prefix" ${CMAKE_CXX_COMPILER_LAUNCHER:+-DCMAKE_CXX_COMPILER_LAUNCHER=$CMAKE_CXX_COMPILER_LAUNCHER}
cmake --build "$work/consumer" -j2
# Seed 000: Davies' 2-circuit network has FN = 3, CN = 2; seed 002's symmetric guide has one
# kinematically indeterminate mode and one self-stress.
out=$("$work/consumer/examples_cpp/analyse" examples/davies-2-circuit.yaml)
echo "$out"
[[ "$out" == *"FN = 3, CN = 2"* ]]
# The verdict, through the installed pipeline: FN = 3 and CN = 2 against one intended motion.
[[ "$out" == *"verdict: Not exactly constrained: 2 extra motions, 2 redundant constraints"* ]]
out=$("$work/consumer/examples_cpp/analyse" examples/folded-sheet-guide-5-symmetric.yaml)
echo "$out"
[[ "$out" == *"modes = 1, self-stresses = 1"* ]]
if "$work/consumer/examples_cpp/analyse" /nonexistent.yaml 2>"$work/err"; then exit 1; fi
grep -q "/nonexistent.yaml" "$work/err"
# The distributed backend, when built: the installed kinestat hands `--backend petsc` over to
# the installed kinestat-mpi beside it (OpenMPI's settings for root and few cores, as in CI).
if [[ -x "$work/prefix/bin/kinestat-mpi" ]] && command -v mpirun >/dev/null; then
  OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1 \
    OMPI_MCA_btl_vader_single_copy_mechanism=none OPENBLAS_NUM_THREADS=1 \
    mpirun -n 1 "$work/prefix/bin/kinestat" analyze --backend petsc examples/davies-2-circuit.yaml --json > "$work/petsc.json"
  /usr/bin/python3 -c "
import json, sys
r = json.load(open(sys.argv[1]))
assert (r['FN'], r['CN'], r['backend']['processes']) == (3, 2, 1), r
print('installed kinestat-mpi: FN = 3, CN = 2 on 1 process')" "$work/petsc.json"
fi
# The Python package, when built: importable from the prefix with Debian's interpreter.
for site in "$work"/prefix/lib/python3*/dist-packages; do
  [[ -d "$site/kinestat" ]] || continue
  PYTHONPATH="$PWD/$site" PYTHONDONTWRITEBYTECODE=1 /usr/bin/python3 -c "
import kinestat
r = kinestat.analyze('examples/davies-2-circuit.yaml')
assert (r.FN, r.CN) == (3, 2), (r.FN, r.CN)
print('installed Python package: FN = 3, CN = 2 from', kinestat.__file__)"
done
echo "check-install: the installed package builds and runs a consumer"
