#!/bin/sh
# SPDX-License-Identifier: BSD-3-Clause
# The same input gives byte-identical JSON at P = 2: each model twice under
# `mpirun -n 2 kinestat analyze --backend petsc MODEL --json`, compared byte for byte. The
# decomposition is deterministic (the same partition on every process, the blocks stacked in
# rank order), so nothing depends on the order messages arrive: the generated 1 000-coupling
# ladder (bench/ladder_network.py) and examples/delta-robot.yaml.
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
