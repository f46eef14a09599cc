#!/bin/sh
# SPDX-License-Identifier: BSD-3-Clause
# Serial sparse path vs the distributed backend on P = 1 and P = 2 processes, side by side in
# one run (bench/README.md, "Distributed backend"): wall time and peak memory per process.
# Serial: /usr/bin/time -v of `kinestat analyze MODEL --json`; P processes: the same for mpirun
# (whole run) and the backend's own report (peak resident memory of each rank, MUMPS's memory).
# Frameworks and coupling networks (networks: C x d(n-1) is K's size, FN and CN the counts).
# Usage: bench/distributed_compare.sh KINESTAT MODEL...
set -eu
kinestat=$1
shift
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
export OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1
work=$(mktemp -d)
for model in "$@"; do
  /usr/bin/time -f "%e %M" -o "$work/time" "$kinestat" analyze "$model" --json > "$work/serial.json"
  read -r seconds kb < "$work/time"
  /usr/bin/python3 -c "
import json, sys
j = json.load(open('$work/serial.json'))
counts = f\"C x d(n-1) = {j['C']} x {j['C'] - j['CN'] + j['FN']} | FN {j['FN']}, CN {j['CN']}\" if j['kind'] == 'network' else f\"{j['rows']} x {j['cols']} | rank {j['rank']}, {j['mechanisms']} / {j['self_stresses']}\"
print(f\"| {sys.argv[1]} | serial sparse QR | {counts} | $seconds s | {$kb / 1024:.0f} MB |\")
" "$(basename "$model")"
  for p in 1 2; do
    /usr/bin/time -f "%e %M" -o "$work/time" mpirun -n "$p" "$kinestat" analyze --backend petsc --timings "$model" --json > "$work/petsc.json" ||
      { echo "| $(basename "$model") | petsc P = $p | failed (exit $?) |"; continue; }
    read -r seconds kb < "$work/time"
    /usr/bin/python3 -c "
import json, sys
j = json.load(open('$work/petsc.json'))
b = j['backend']; m = b['measured']; s = m['seconds']
peaks = ' + '.join(f'{x / 1e6:.0f}' for x in m['peak_memory_bytes'])
counts = f\"C x d(n-1) = {j['C']} x {j['C'] - j['CN'] + j['FN']} | FN {j['FN']}, CN {j['CN']}\" if j['kind'] == 'network' else f\"{j['rows']} x {j['cols']} | rank {j['rank']}, {j['mechanisms']} / {j['self_stresses']}\"
window = f\", window {s['window']:.1f} s\" if 'window' in s else ''
print(f\"| {sys.argv[1]} | petsc P = $p | {counts} | $seconds s (factorisations {s['factorisation']:.1f} s{window}, null vectors {s['null_vectors']:.1f} s) | {peaks} MB per rank; MUMPS {m['mumps_megabytes_max']} MB max |\")
" "$(basename "$model")"
  done
done
rm -rf "$work"
