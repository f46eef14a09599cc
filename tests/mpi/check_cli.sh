#!/bin/sh
# `mpirun -n 2 kinestat analyze --backend petsc` against the serial command on a generated
# 10^4-bar square grid (bench/lattice_model.py; 70 mechanisms and 70 self-stresses by hand:
# tests/support/lattice_generator.hpp), and its errors: a coupling network and a missing file
# are refused with exit 2 by every process.
# Usage: check_cli.sh MPIRUN KINESTAT SOURCE_DIR WORK_DIR
set -eu
mpirun=$1 kinestat=$2 source=$3 work=$4
mkdir -p "$work"
model=$work/square-71.yaml
/usr/bin/python3 "$source/bench/lattice_model.py" square 71 "$model"
"$kinestat" analyze "$model" --json > "$work/serial.json"
"$mpirun" -n 2 "$kinestat" analyze --backend petsc "$model" --json > "$work/petsc.json"
/usr/bin/python3 - "$work/serial.json" "$work/petsc.json" <<'PY'
import json, sys
serial, petsc = (json.load(open(p)) for p in sys.argv[1:3])
for key in ("rows", "cols", "rank", "mechanisms", "self_stresses", "classification"):
    assert serial[key] == petsc[key], (key, serial[key], petsc[key])
assert (petsc["mechanisms"], petsc["self_stresses"]) == (70, 70), (petsc["mechanisms"], petsc["self_stresses"])
assert petsc["method"] == "petsc_mumps" and serial["method"] == "sparse_qr"
assert petsc["rank_decision"]["threshold"] == serial["rank_decision"]["threshold"]
backend = petsc["backend"]
assert backend["processes"] == 2, backend
assert backend["rank_above_margin"] == petsc["rank"], backend
assert "measured" not in backend, backend  # only with --timings: the same input gives the same JSON
print("serial and petsc agree:", petsc["rank"], petsc["mechanisms"], petsc["self_stresses"])
PY
# Text output names the backend.
"$mpirun" -n 2 "$kinestat" analyze --backend petsc "$model" | grep -q "backend: petsc on 2 process(es)"
# Errors: exit 2 with the file named, from every process.
status=0
"$mpirun" -n 2 "$kinestat" analyze --backend petsc "$source/examples/davies-2-circuit.yaml" 2> "$work/err" || status=$?
[ "$status" -eq 2 ] || { echo "network: exit $status, expected 2"; cat "$work/err"; exit 1; }
grep -q "frameworks only" "$work/err"
status=0
"$mpirun" -n 2 "$kinestat" analyze --backend petsc "$work/missing.yaml" 2> "$work/err" || status=$?
[ "$status" -eq 2 ] || { echo "missing file: exit $status, expected 2"; cat "$work/err"; exit 1; }
grep -q "missing.yaml" "$work/err"
echo "ok"
