#!/bin/sh
# SPDX-License-Identifier: BSD-3-Clause
# `mpirun -n 2 kinestat analyze --backend petsc` against the serial command on a generated
# 10^4-bar square grid (bench/lattice_model.py; 70 mechanisms and 70 self-stresses by hand:
# tests/support/lattice_generator.hpp), with --vectors 3 against the serial path's whole null
# spaces (--vectors 70) by projection; on a generated 1 000-coupling ladder network
# (bench/ladder_network.py) against the serial sparse path; and its errors: a structure model,
# --dense-limit and a missing file are refused with exit 2 by every process. `kinestat` hands the
# command over to the kinestat-mpi beside it, and `kinestat` that has none (copied alone) says so
# with exit 2; the serial commands of that copy still run.
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
# Vectors: the first 3 modes and stress states in the serial report's layout, each with its
# residual below the threshold, inside the serial path's whole null spaces (all 70 of each).
"$kinestat" analyze "$model" --json --vectors 70 > "$work/serial-vectors.json"
"$mpirun" -n 2 "$kinestat" analyze --backend petsc "$model" --json --vectors 3 > "$work/petsc-vectors.json"
/usr/bin/python3 - "$work/serial-vectors.json" "$work/petsc-vectors.json" <<'PY'
import json, sys
import numpy as np
serial, petsc = (json.load(open(p)) for p in sys.argv[1:3])
assert petsc["vectors"] is True and petsc["vector_limit"] == 3, (petsc["vectors"], petsc.get("vector_limit"))
assert len(serial["modes"]) == 70 and len(serial["stresses"]) == 70
assert len(petsc["modes"]) == 3 and len(petsc["stresses"]) == 3
assert set(petsc["modes"][0]) == set(serial["modes"][0]) - {"cause"}, (set(petsc["modes"][0]), set(serial["modes"][0]))
assert set(petsc["stresses"][0]) == set(serial["stresses"][0]) - {"cause"}
bound = petsc["rank_decision"]["threshold"] / petsc["rank_decision"]["largest_singular_value"]
residuals = petsc["backend"]["vector_residuals"]
assert len(residuals["modes"]) == 3 and len(residuals["stresses"]) == 3, residuals
assert all(r < bound for r in residuals["modes"] + residuals["stresses"]), (residuals, bound)
def columns(states, entries):
    rows = [entries(s) for s in states]
    keys = sorted({k for r in rows for k in r})
    return keys, rows
def mode_entries(mode):
    return {f"{node}.{slot}": v for node, slots in mode["velocities"].items() for slot, v in slots.items()}
def stress_entries(state):
    return {f"{r['element']}.{r['deformation']}": r["value"] for r in state["resultants"]}
for kind, entries in (("modes", mode_entries), ("stresses", stress_entries)):
    keys = sorted({k for s in serial[kind] + petsc[kind] for k in entries(s)})
    index = {k: i for i, k in enumerate(keys)}
    def matrix(states):
        m = np.zeros((len(keys), len(states)))
        for j, s in enumerate(states):
            for k, v in entries(s).items():
                m[index[k], j] = v
        return m
    q, _ = np.linalg.qr(matrix(serial[kind]))
    x, _ = np.linalg.qr(matrix(petsc[kind]))
    # sin of the largest principal angle between the spans (values written to 10 digits).
    distance = np.linalg.norm(x - q @ (q.T @ x), 2)
    assert distance < 1e-6, (kind, distance)
    print(kind, "in the serial null space: largest principal angle sine", f"{distance:.1e}")
PY
# A coupling network: FN, CN, class and the stressed and moving couplings of the serial sparse
# path; the serial report's keys plus `backend`; the first 8 basis vectors of each space (the
# serial path's number), each with its residual.
network=$work/ladder-1000.yaml
/usr/bin/python3 "$source/bench/ladder_network.py" 1000 > "$network"
"$kinestat" analyze "$network" --json > "$work/serial-network.json"
"$mpirun" -n 2 "$kinestat" analyze --backend petsc "$network" --json > "$work/petsc-network.json"
/usr/bin/python3 - "$work/serial-network.json" "$work/petsc-network.json" <<'PY'
import json, sys
serial, petsc = (json.load(open(p)) for p in sys.argv[1:3])
assert serial["method"] == "sparse_body_twist" and petsc["method"] == "petsc_mumps"
for key in ("d", "n", "e", "F", "C", "l", "FN", "CN", "classification", "stressed_couplings", "moving_couplings"):
    assert serial[key] == petsc[key], (key, serial[key], petsc[key])
assert set(petsc) == set(serial) | {"backend"}, set(petsc) ^ set(serial)
assert petsc["rank_evidence"]["body_twist"]["threshold"] == serial["rank_evidence"]["body_twist"]["threshold"]
assert petsc["FN"] > 0 and petsc["CN"] > 0
vectors = petsc["basis_vectors"]
assert (vectors["motions"], vectors["self_stresses"]) == (8, 8), vectors
residuals = petsc["backend"]["vector_residuals"]
bound = serial["rank_evidence"]["body_twist"]["threshold"] / serial["rank_evidence"]["body_twist"]["largest_singular_value"]
assert len(residuals["motions"]) == 8 and len(residuals["self_stresses"]) == 8, residuals
assert all(r < bound for r in residuals["motions"] + residuals["self_stresses"]), (residuals, bound)
assert petsc["null_space_residual"] <= bound, (petsc["null_space_residual"], bound)  # an upper bound, at most the floor
# No singular value in (t, 100 t] (the window searched whole and empty): the decision is not
# close, as the serial path's is not (no "close decision" warning on either).
assert petsc["backend"]["window_searched"] and petsc["backend"]["window_kept"] == 0, petsc["backend"]
assert serial["rank_evidence"]["body_twist"]["close"] is False
assert petsc["rank_evidence"]["body_twist"]["close"] is False, petsc["rank_evidence"]["body_twist"]
print("network: serial and petsc agree:", petsc["FN"], petsc["CN"], len(petsc["stressed_couplings"]), len(petsc["moving_couplings"]))
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
mkdir -p "$work/alone"
cp "$kinestat" "$work/alone/kinestat"
status=0
"$work/alone/kinestat" analyze --backend petsc "$model" 2> "$work/err" || status=$?
[ "$status" -eq 2 ] || { echo "no kinestat-mpi: exit $status, expected 2"; cat "$work/err"; exit 1; }
grep -q "alone/kinestat-mpi.*cannot be started (No such file or directory)" "$work/err"
"$work/alone/kinestat" analyze "$source/examples/davies-2-circuit.yaml" --json > "$work/alone.json"
/usr/bin/python3 -c "import json, sys; r = json.load(open(sys.argv[1])); assert (r['FN'], r['CN']) == (3, 2), r" "$work/alone.json"
echo "ok"
