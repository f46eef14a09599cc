#!/bin/sh
# SPDX-License-Identifier: BSD-3-Clause
# The same input gives byte-identical JSON at P = 2, where MUMPS sums in the order messages
# arrive: each model twice under `mpirun -n 2 kinestat analyze --backend petsc MODEL --json`,
# compared byte for byte. The models are those whose reports differed before every residual
# was reported as an upper bound at the report floor and every singular value to the digits its
# residual guarantees (docs/scaling.md, "Repeatability"): the generated 1 000-coupling ladder
# (bench/ladder_network.py; smallest_kept_residual 1e-12 in one run of four, 1e-13 in the
# others) and examples/delta-robot.yaml (smallest_kept, largest_dropped, gap and
# smallest_kept_residual differed in one run of six). 5.7 s at load average 4 to 7 on two
# cores, 28 to 50 s with two builds running on them.
# Usage: check_repeatable.sh MPIRUN KINESTAT SOURCE_DIR WORK_DIR
set -eu
mpirun=$1 kinestat=$2 source=$3 work=$4
mkdir -p "$work"
/usr/bin/python3 "$source/bench/ladder_network.py" 1000 > "$work/ladder-1000.yaml"
for model in "$work/ladder-1000.yaml" "$source/examples/delta-robot.yaml"; do
  name=$(basename "$model" .yaml)
  for run in 1 2; do
    "$mpirun" -n 2 "$kinestat" analyze --backend petsc "$model" --json > "$work/$name-$run.json"
  done
  cmp "$work/$name-1.json" "$work/$name-2.json" || { echo "$name: the two runs at P = 2 differ"; diff "$work/$name-1.json" "$work/$name-2.json" | head -20; exit 1; }
  echo "$name: two runs at P = 2 byte-identical"
done
echo "ok"
