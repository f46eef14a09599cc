#!/bin/sh
# SPDX-License-Identifier: BSD-3-Clause
# Serial sparse path vs the distributed backend (domain decomposition) on P = 1, 2 and 4
# processes (4 oversubscribed on a 2-core machine), side by side in one run (bench/README.md,
# "Distributed backend"): counts, wall time and peak memory per process. Serial: /usr/bin/time
# of `kinestat analyze MODEL --json`; "alone": the backend without mpirun (one process, MPI not
# initialised); P processes: /usr/bin/time of the whole mpirun, and the backend's own report
# (--timings: peak resident memory of each rank, of which before the decision — rank 0 reads
# the model and builds the matrix, the others receive their rows —, its stages' times).
# Frameworks and coupling networks (networks: C x d(n-1) is K's size, FN and CN the counts).
# One MPI run at a time. Usage: bench/distributed_compare.sh KINESTAT MODEL...
set -eu
kinestat=$1
shift
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
export OMPI_MCA_btl_vader_single_copy_mechanism=none OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1
work=$(mktemp -d)
# One table row from a report: row.py NAME LABEL JSON SECONDS CPU_SECONDS PEAK_KB (serial) or
# row.py NAME LABEL JSON SECONDS (the backend's own peaks per process, and SuiteSparse's count of
# each process's factorisations).
cat > "$work/row.py" <<'PY'
import json, sys
name, label, path, seconds = sys.argv[1:5]
j = json.load(open(path))
if j["kind"] == "network":
    counts = f"K {j['C']} x {j['C'] - j['CN'] + j['FN']}, FN {j['FN']}, CN {j['CN']}"
else:
    counts = f"{j['rows']} x {j['cols']}, rank {j['rank']}, {j['mechanisms']} / {j['self_stresses']}"
if len(sys.argv) > 5:
    print(f"| {name} | {label} | {counts} | {seconds} s ({sys.argv[5]} s CPU) | {float(sys.argv[6]) / 1024:.0f} MB |")
else:
    b = j["backend"]; s = b["measured"]["seconds"]
    peaks = " + ".join(f"{x / 1e6:.0f}" for x in b["measured"]["peak_memory_bytes"])
    before = " + ".join(f"{x / 1e6:.0f}" for x in b["measured"]["peak_before_decision_bytes"])
    factors = " + ".join(f"{x / 1e6:.0f}" for x in b["measured"]["factor_memory_bytes"])
    print(f"| {name} | {label} | {counts} | {seconds} s (interiors {s['interiors']:.2f} s, interface {s['interface']:.2f} s, "
          f"{b['interface_columns']} interface columns) | {peaks} MB (before the decision {before}; factors {factors} MB) |")
PY
echo "load average: $(cut -d' ' -f1-3 /proc/loadavg)"
for model in "$@"; do
  name=$(basename "$model")
  /usr/bin/time -f "%e %U %M" -o "$work/time" "$kinestat" analyze "$model" --json > "$work/serial.json"
  read -r seconds cpu kb < "$work/time"
  /usr/bin/python3 "$work/row.py" "$name" serial "$work/serial.json" "$seconds" "$cpu" "$kb"
  /usr/bin/time -f "%e" -o "$work/time" "$kinestat" analyze --backend petsc --timings "$model" --json > "$work/petsc.json"
  read -r seconds < "$work/time"
  /usr/bin/python3 "$work/row.py" "$name" "alone" "$work/petsc.json" "$seconds"
  for p in 1 2 4; do
    /usr/bin/time -f "%e" -o "$work/time" mpirun -n "$p" "$kinestat" analyze --backend petsc --timings "$model" --json \
      > "$work/petsc.json" || { echo "| $name | P = $p | failed (exit $?) |"; continue; }
    read -r seconds < "$work/time"
    /usr/bin/python3 "$work/row.py" "$name" "P = $p" "$work/petsc.json" "$seconds"
  done
done
rm -rf "$work"
