#!/usr/bin/env bash
# Installs a built kinestat into a fresh prefix, builds tests/consumer against the installed
# package (the C++ example and every installed header compiled alone) and runs the example.
# Usage: scripts/check-install.sh [build folder, default build/release]
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build/release}
work=$build/install-check
rm -rf "$work"
cmake --install "$build" --prefix "$work/prefix" >/dev/null
cmake -S tests/consumer -B "$work/consumer" -G Ninja -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_PREFIX_PATH="$PWD/$work/prefix" ${CMAKE_CXX_COMPILER_LAUNCHER:+-DCMAKE_CXX_COMPILER_LAUNCHER=$CMAKE_CXX_COMPILER_LAUNCHER}
cmake --build "$work/consumer" -j2
# Seed 000: Davies' 2-circuit network has FN = 3, CN = 2; seed 002's symmetric guide has one
# kinematically indeterminate mode and one self-stress.
out=$("$work/consumer/examples_cpp/analyse" examples/davies-2-circuit.yaml)
echo "$out"
[[ "$out" == *"FN = 3, CN = 2"* ]]
out=$("$work/consumer/examples_cpp/analyse" examples/folded-sheet-guide-5-symmetric.yaml)
echo "$out"
[[ "$out" == *"modes = 1, self-stresses = 1"* ]]
if "$work/consumer/examples_cpp/analyse" /nonexistent.yaml 2>"$work/err"; then exit 1; fi
grep -q "/nonexistent.yaml" "$work/err"
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
