#!/bin/sh
# SPDX-License-Identifier: BSD-3-Clause
# `mpirun -n 2 kinestat analyze --backend petsc` (domain decomposition) against the serial command
# and against counts by hand: a generated 9,861-bar triangular lattice (bench/lattice_model.py
# triangulated 58: rigid, (n - 1)^2 = 3,249 self-stresses; tests/support/lattice_generator.hpp)
# and a generated planar lattice network of 1,012 revolute couplings (bench/network_model.py
# lattice 1000: a 23 x 23 grid of bodies, C = 2e constraints, generically rigid, so FN = 0 and
# CN = C - 3(n - 1)). The serial report's keys and rank evidence, the backend's notice of what it
# does not compute (also under --vectors), and its errors: a structure model, --dense-limit and
# a missing file are refused with exit 2 by every process, a disconnected network too (found by
# rank 0 after reading); without mpirun the command decides alone (the hand counts). `kinestat` hands the command over to
# the kinestat-mpi beside it, and `kinestat` that has none (copied alone) says so with exit 2.
# Usage: check_cli.sh MPIRUN KINESTAT SOURCE_DIR WORK_DIR
set -eu
mpirun=$1 kinestat=$2 source=$3 work=$4
mkdir -p "$work"
model=$work/triangulated-58.yaml
/usr/bin/python3 "$source/bench/lattice_model.py" triangulated 58 "$model"
"$kinestat" analyze "$model" --json > "$work/serial.json"
"$mpirun" -n 2 "$kinestat" analyze --backend petsc "$model" --json > "$work/petsc.json"
/usr/bin/python3 - "$work/serial.json" "$work/petsc.json" <<'PY'
import json, sys
serial, petsc = (json.load(open(p)) for p in sys.argv[1:3])
for key in ("rows", "cols", "rank", "mechanisms", "self_stresses", "classification"):
    assert serial[key] == petsc[key], (key, serial[key], petsc[key])
n = 58
assert (petsc["rows"], petsc["cols"]) == (2 * n * (n - 1) + (n - 1) ** 2, 2 * n * (n - 1)), (petsc["rows"], petsc["cols"])
assert (petsc["mechanisms"], petsc["self_stresses"]) == (0, (n - 1) ** 2), (petsc["mechanisms"], petsc["self_stresses"])
assert petsc["method"] == "petsc_decomposed_qr" and serial["method"] == "sparse_qr"
# One rank evidence, with the serial keys and the serial threshold.
assert set(petsc["rank_decision"]) == set(serial["rank_decision"]), set(petsc["rank_decision"]) ^ set(serial["rank_decision"])
assert petsc["rank_decision"]["threshold"] == serial["rank_decision"]["threshold"]
assert set(petsc) == set(serial) | {"backend"}, set(petsc) ^ set(serial)
backend = petsc["backend"]
assert backend["processes"] == 2 and len(backend["interior_ranks"]) == 2, backend
assert sum(backend["interior_ranks"]) + backend["interface_rank"] == petsc["rank"], backend
assert backend["interface_columns"] > 0 and min(backend["interior_ranks"]) > 0, backend
assert "modes and stress states" in backend["not_computed"], backend
assert "measured" not in backend, backend  # only with --timings: the same input gives the same JSON
print("triangular lattice: serial and petsc agree:", petsc["rank"], petsc["mechanisms"], petsc["self_stresses"])
PY
# Text output names the backend and what it does not compute; --vectors is answered by that notice.
"$mpirun" -n 2 "$kinestat" analyze --backend petsc "$model" > "$work/petsc.txt"
grep -q "backend: petsc on 2 process(es), domain decomposition" "$work/petsc.txt"
grep -q "not computed by the distributed path: modes and stress states" "$work/petsc.txt"
"$mpirun" -n 2 "$kinestat" analyze --backend petsc "$model" --vectors 3 --json > "$work/petsc-vectors.json"
/usr/bin/python3 -c "
import json, sys
r = json.load(open(sys.argv[1]))
assert r['vectors'] is False and 'modes and stress states' in r['backend']['not_computed'], r['backend']
" "$work/petsc-vectors.json"
# A planar lattice network: the serial sparse path's FN, CN and class, and by hand.
network=$work/lattice-1000.yaml
/usr/bin/python3 "$source/bench/network_model.py" lattice 1000 > "$network"
"$kinestat" analyze "$network" --json > "$work/serial-network.json"
"$mpirun" -n 2 "$kinestat" analyze --backend petsc "$network" --json > "$work/petsc-network.json"
/usr/bin/python3 - "$work/serial-network.json" "$work/petsc-network.json" <<'PY'
import json, sys
serial, petsc = (json.load(open(p)) for p in sys.argv[1:3])
assert serial["method"] == "sparse_body_twist" and petsc["method"] == "petsc_decomposed_qr"
for key in ("d", "n", "e", "F", "C", "l", "FN", "CN", "classification"):
    assert serial[key] == petsc[key], (key, serial[key], petsc[key])
side = 23
assert (petsc["n"], petsc["e"], petsc["C"]) == (side * side, 2 * side * (side - 1), 4 * side * (side - 1)), petsc
assert (petsc["FN"], petsc["CN"]) == (0, petsc["C"] - 3 * (petsc["n"] - 1)), (petsc["FN"], petsc["CN"])
# The serial keys, less σ_min(R11) of the serial factor (no such factor here).
evidence, serial_evidence = petsc["rank_evidence"]["body_twist"], serial["rank_evidence"]["body_twist"]
assert set(evidence) == set(serial_evidence) - {"r11_smallest_singular_value"}, set(evidence) ^ set(serial_evidence)
assert petsc["stressed_couplings"] is None and petsc["moving_couplings"] is None  # not computed, not "none"
assert petsc["rank_evidence"]["body_twist"]["threshold"] == serial["rank_evidence"]["body_twist"]["threshold"]
assert sum(petsc["backend"]["interior_ranks"]) + petsc["backend"]["interface_rank"] == petsc["C"] - petsc["CN"]
assert "couplings that carry a self-stress and that move" in petsc["backend"]["not_computed"], petsc["backend"]
print("network: serial and petsc agree:", petsc["FN"], petsc["CN"])
PY
# Errors: exit 2 with the file named, from every process.
status=0
"$mpirun" -n 2 "$kinestat" analyze --backend petsc "$model" --dense-limit 10 2> "$work/err" || status=$?
[ "$status" -eq 2 ] || { echo "--dense-limit: exit $status, expected 2"; cat "$work/err"; exit 1; }
grep -q "not used with --backend petsc" "$work/err"
status=0
"$mpirun" -n 2 "$kinestat" analyze --backend petsc "$source/examples/class-iii-triad.yaml" 2> "$work/err" || status=$?
[ "$status" -eq 2 ] || { echo "structure: exit $status, expected 2"; cat "$work/err"; exit 1; }
grep -q "frameworks and coupling networks" "$work/err"
status=0
"$mpirun" -n 2 "$kinestat" analyze --backend petsc "$work/missing.yaml" 2> "$work/err" || status=$?
[ "$status" -eq 2 ] || { echo "missing file: exit $status, expected 2"; cat "$work/err"; exit 1; }
grep -q "missing.yaml" "$work/err"
# A network whose bodies are not connected: rank 0 finds it while building K and tells the
# other process to stop (no hang), exit 2 with the serial message.
printf 'kinestat: 1\nkind: network\ndimension: planar\nground: a\ncouplings:\n  - {name: R1, type: revolute, between: [a, b], point: [0, 0]}\n  - {name: R2, type: revolute, between: [c, d], point: [1, 0]}\n' > "$work/split.yaml"
status=0
"$mpirun" -n 2 "$kinestat" analyze --backend petsc "$work/split.yaml" 2> "$work/err" || status=$?
[ "$status" -eq 2 ] || { echo "disconnected network: exit $status, expected 2"; cat "$work/err"; exit 1; }
grep -q "split.yaml.*not all connected" "$work/err"
# Without mpirun (one process, MPI not initialised): the serial decision, the hand counts.
"$kinestat" analyze --backend petsc "$model" --json > "$work/alone-petsc.json"
/usr/bin/python3 -c "
import json, sys
r = json.load(open(sys.argv[1])); n = 58
assert (r['mechanisms'], r['self_stresses']) == (0, (n - 1) ** 2) and r['backend']['processes'] == 1, r['backend']
" "$work/alone-petsc.json"
mkdir -p "$work/alone"
cp "$kinestat" "$work/alone/kinestat"
status=0
"$work/alone/kinestat" analyze --backend petsc "$model" 2> "$work/err" || status=$?
[ "$status" -eq 2 ] || { echo "no kinestat-mpi: exit $status, expected 2"; cat "$work/err"; exit 1; }
grep -q "alone/kinestat-mpi.*cannot be started (No such file or directory)" "$work/err"
"$work/alone/kinestat" analyze "$source/examples/davies-2-circuit.yaml" --json > "$work/alone.json"
/usr/bin/python3 -c "import json, sys; r = json.load(open(sys.argv[1])); assert (r['FN'], r['CN']) == (3, 2), r" "$work/alone.json"
echo "ok"
