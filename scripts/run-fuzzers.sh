#!/usr/bin/env bash
# Runs every libFuzzer harness for SECONDS (default 30) each, seeded with the shipped
# examples. Crashes are written to build/fuzz/crashes/ and fail the script.
# The seed is fixed (FUZZ_SEED, default 1): a run from an empty corpus then explores the same
# inputs in the same order on every machine, so a longer local run covers what CI's short run
# will try, and a CI failure repeats locally.
# Usage: [FUZZ_SEED=N] scripts/run-fuzzers.sh [SECONDS]
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-30}
seed=${FUZZ_SEED:-1}
out=build/fuzz/crashes
mkdir -p "$out"
status=0
for harness in build/fuzz/fuzz/fuzz_*; do
  name=$(basename "$harness")
  corpus=build/fuzz/corpus/$name
  mkdir -p "$corpus"
  case "$name" in
    fuzz_cli_arguments) seeds=fuzz/seeds/cli ;;
    fuzz_adjacency_matrix) seeds=fuzz/seeds/adjacency ;;
    fuzz_sweep_spec) seeds="fuzz/seeds/sweep examples/sweeps" ;;
    fuzz_spacar_file) seeds="examples/spacar tests/importers/data" ;;
    fuzz_urdf_file | fuzz_sdformat_file | fuzz_mjcf_file) seeds="examples/robots tests/importers/data" ;;
    fuzz_valid_models) seeds="" ;;  # the bytes are choices of a generator: any input is a model
    *) seeds="examples examples/json fuzz/seeds/model" ;;
  esac
  echo "== $name for ${seconds}s"
  if ! "$harness" -max_total_time="$seconds" -timeout=20 -rss_limit_mb=4096 -max_len=65536 -seed="$seed" \
       -artifact_prefix="$out/$name-" -print_final_stats=1 "$corpus" $seeds >/dev/null 2>"build/fuzz/$name.log"; then
    status=1
    tail -40 "build/fuzz/$name.log"
  fi
  grep -E "stat::number_of_executed_units|stat::peak_rss_mb" "build/fuzz/$name.log" || true
done
exit $status
