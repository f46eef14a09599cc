#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Paired whole-command measurements for bench/README.md: each pair runs back to back, the pairs
# alternate, so load on the shared machine hits both sides alike. Run from the repository root
# after `cmake --build --preset release --target kinestat_cli framework_bench dense_vectors_bench`.
#   bench/scale_pairs.sh [repeats]
set -euo pipefail
repeats=${1:-3}
build=build/release
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
time_of() { /usr/bin/time -f "%e s wall, %U + %S s CPU, %M KB" "$@" 2>&1 >/dev/null | tail -1; }

echo "== 1,121-bar triangulated lattice (20 x 20): kinestat analyze (all vectors) vs numpy.linalg.svd of D(c)"
bench/lattice_model.py triangulated 20 "$work/t20.yaml"
for r in $(seq "$repeats"); do
  echo "kinestat: $(time_of nice -n 10 "$build/kinestat" analyze --json -o "$work/t20.json" "$work/t20.yaml")"
  OPENBLAS_NUM_THREADS=1 nice -n 10 /usr/bin/python3 - <<PY
import sys, time
sys.path.insert(0, "bench")
import numpy
from lattice_model import jacobian
d = jacobian("triangulated", 20)
start, cpu = time.perf_counter(), time.process_time()
numpy.linalg.svd(d)
print(f"numpy:    {time.perf_counter() - start:.2f} s wall, {time.process_time() - cpu:.2f} s CPU for svd of {d.shape[0]} x {d.shape[1]} (full U, V; one OpenBLAS thread)")
PY
done
echo "== the same D(c) in one process: LAPACK dgesdd with full U and V (numpy's call) vs the analysis with all vectors"
KINESTAT_BENCH_MODEL="$work/t20.yaml" OPENBLAS_NUM_THREADS=1 nice -n 10 "$build/bench/dense_vectors_bench" \
  --benchmark_repetitions="$repeats" --benchmark_report_aggregates_only=false 2>/dev/null | grep -E "^BM_"

echo "== 3-D lattice of 103,530 bars (30^3): kinestat analyze (counts) vs CHOLMOD nested dissection of DᵀD"
bench/lattice_model.py spatial 30 "$work/s30.yaml"
for r in $(seq "$repeats"); do
  echo "kinestat: $(time_of nice -n 10 "$build/kinestat" analyze --json -o "$work/s30.json" "$work/s30.yaml")"
  KINESTAT_BENCH_MODEL="$work/s30.yaml" nice -n 10 "$build/bench/framework_bench" --benchmark_filter=BM_FileCholmod \
    --benchmark_min_time=0 2>/dev/null | grep BM_FileCholmod
done
/usr/bin/python3 -c "import json; j = json.load(open('$work/s30.json')); print('counts:', j['rows'], 'x', j['cols'], 'rank', j['rank'], 'mechanisms', j['mechanisms'], 'self_stresses', j['self_stresses'])"
