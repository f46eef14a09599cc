#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# The Debian package: builds build/deb (shared libkinestat.so.0, prefix /usr, the `user`
# preset's settings), checks its installed package (scripts/check-install.sh), makes
# kinestat_<version>_<arch>.deb with CPack and prints its control fields. With --root DIR (a
# clean Debian 12 root, e.g. `debootstrap --variant=minbase bookworm DIR`; needs root and the
# Debian mirror), installs the .deb with apt into a copy of DIR and runs `kinestat analyze` and
# the Python module there; DIR itself is left clean. Prints each step's wall time.
# Usage: scripts/check-deb.sh [--root DIR]
set -euo pipefail
cd "$(dirname "$0")/.."
root=""
case "${1:-}" in
  --root) root=${2:?usage: scripts/check-deb.sh [--root DIR]} ;;
  "") ;;
  *) echo "usage: scripts/check-deb.sh [--root DIR]" >&2; exit 2 ;;
esac
build=build/deb
step() { echo "== $1: $2 s"; }

start=$SECONDS
cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_FLAGS_RELEASE="-O2 -DNDEBUG" -DCMAKE_UNITY_BUILD=ON \
  -DKINESTAT_BUILD_TESTS=OFF -DKINESTAT_BUILD_BENCHMARKS=OFF -DKINESTAT_PETSC=OFF -DKINESTAT_SHARED=ON \
  -DCMAKE_INSTALL_PREFIX=/usr -DKINESTAT_PYTHON_INSTALL_DIR=lib/python3/dist-packages \
  ${CMAKE_CXX_COMPILER_LAUNCHER:+-DCMAKE_CXX_COMPILER_LAUNCHER=$CMAKE_CXX_COMPILER_LAUNCHER} >/dev/null
cmake --build "$build"
step build $((SECONDS - start))

start=$SECONDS
scripts/check-install.sh "$build"
step check-install $((SECONDS - start))

start=$SECONDS
(cd "$build" && cpack -G DEB >/dev/null)
deb=$(ls "$build"/kinestat_*.deb)
dpkg-deb --field "$deb" Package Version Architecture Depends Recommends Installed-Size
dpkg-deb --contents "$deb" | awk '{print $6}' | grep -E 'bin/kinestat$|libkinestat\.so|kinestat\.pc$|kinestatConfig\.cmake$|/_core\.'
step cpack $((SECONDS - start))

[[ -n "$root" ]] || exit 0
# A copy of the clean root, the .deb inside it, apt from Debian's mirror (the root's own sources).
start=$SECONDS
work=$(mktemp -d /tmp/kinestat-deb-root.XXXXXX)
trap 'umount "$work/proc" 2>/dev/null || true; rm -rf "$work"' EXIT
cp -a "$root/." "$work/"
cp "$deb" "$work/tmp/kinestat.deb"
cp examples/davies-2-circuit.yaml examples/braced-square.yaml "$work/tmp/"
cp /etc/resolv.conf "$work/etc/resolv.conf"
mount -t proc proc "$work/proc"
chroot "$work" env DEBIAN_FRONTEND=noninteractive apt-get update -qq
chroot "$work" env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends /tmp/kinestat.deb >/dev/null
step "apt install into the clean root" $((SECONDS - start))
echo "installed: $(chroot "$work" dpkg-query -W kinestat), root now $(du -smx "$work" | cut -f1) MB (clean: $(du -smx "$root" | cut -f1) MB)"
out=$(chroot "$work" kinestat analyze /tmp/davies-2-circuit.yaml)
echo "$out" | head -3
# Davies' 2-circuit network (seed 000): FN = 3, CN = 2.
echo "$out" | grep -q "FN = 3"
echo "$out" | grep -q "CN = 2"
chroot "$work" python3 -c "
import kinestat
r = kinestat.analyze('/tmp/braced-square.yaml')
assert (r.mechanisms, r.self_stresses) == (0, 1), r
print('Python in the clean root:', repr(r).splitlines()[0])"
echo "check-deb: $(basename "$deb") installs with apt and runs in a clean Debian 12 root"
