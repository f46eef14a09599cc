#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Runs every libFuzzer harness for SECONDS (default 30) each, seeded with the shipped
# examples. The harnesses are those of the `asan` preset's tree (build/asan-clang, built with the
# sanitized tests; CI's), or of another tree given as FUZZ_BUILD (e.g. build/fuzz, the `fuzz`
# preset: the harnesses alone, optimised). Crashes are written to FUZZ_BUILD/fuzz-run/crashes/
# and fail the script; the corpora and each harness's log are kept beside them.
# The seed is fixed (FUZZ_SEED, default 1): a run from an empty corpus then explores the same
# inputs in the same order on every machine, so a longer local run covers what CI's short run
# will try, and a CI failure repeats locally.
# FUZZ_JOBS harnesses (default 2, one a core of CI's machines) run at a time, each for the full
# SECONDS on a core of its own; each prints its lines when it ends.
# Usage: [FUZZ_BUILD=DIR] [FUZZ_SEED=N] [FUZZ_JOBS=N] scripts/run-fuzzers.sh [SECONDS]
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-30}
seed=${FUZZ_SEED:-1}
tree=${FUZZ_BUILD:-build/asan-clang}
run=$tree/fuzz-run
out=$run/crashes
mkdir -p "$out"
jobs=${FUZZ_JOBS:-2}

# run_harness PATH: runs one harness and prints its report; fails when the harness does.
run_harness() {
  local harness=$1 name corpus seeds
  name=$(basename "$harness")
  corpus=$run/corpus/$name
  mkdir -p "$corpus"
  case "$name" in
    fuzz_cli_arguments) seeds=fuzz/seeds/cli ;;
    fuzz_adjacency_matrix) seeds=fuzz/seeds/adjacency ;;
    fuzz_sweep_spec) seeds="fuzz/seeds/sweep examples/sweeps" ;;
    fuzz_spacar_file) seeds="examples/spacar tests/importers/data" ;;
    fuzz_bar_table) seeds=fuzz/seeds/bars ;;
    fuzz_urdf_file | fuzz_sdformat_file | fuzz_mjcf_file) seeds="examples/robots tests/importers/data" ;;
    fuzz_valid_models) seeds=fuzz/seeds/valid ;;  # the bytes are choices of a generator; the seeds are past findings
    *) seeds="examples examples/json fuzz/seeds/model" ;;
  esac
  # fuzz_valid_models analyses each model two to four times with its verdict's change search and
  # every report: up to 10 s an input under ASan on a busy machine, so its hang limit is longer.
  local timeout=20
  [[ $name == fuzz_valid_models ]] && timeout=120
  local status=0
  # shellcheck disable=SC2086 # seeds: one folder a word
  "$harness" -max_total_time="$seconds" -timeout="$timeout" -rss_limit_mb=4096 -max_len=65536 -seed="$seed" \
    -artifact_prefix="$out/$name-" -print_final_stats=1 "$corpus" $seeds >/dev/null 2>"$run/$name.log" || status=1
  # One write, so that the reports of harnesses that end together do not interleave.
  local report="== $name for ${seconds}s"
  if ((status != 0)); then report+=$'\n'$(tail -40 "$run/$name.log"); fi
  report+=$'\n'$(grep -E "stat::number_of_executed_units|stat::peak_rss_mb" "$run/$name.log" || true)
  printf '%s\n' "$report"
  return $status
}

harnesses=("$tree"/fuzz/fuzz_*)
if [[ ! -x ${harnesses[0]} ]]; then
  echo "no fuzz harnesses in $tree/fuzz (build the asan preset, or set FUZZ_BUILD)" >&2
  exit 1
fi
status=0
running=0
for harness in "${harnesses[@]}"; do
  if ((running >= jobs)); then
    wait -n || status=1
    running=$((running - 1))
  fi
  run_harness "$harness" &
  running=$((running + 1))
done
while ((running > 0)); do
  wait -n || status=1
  running=$((running - 1))
done
exit $status
