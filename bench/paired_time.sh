#!/bin/bash
# SPDX-License-Identifier: BSD-3-Clause
# Two commands timed alternately in one run (the machines are shared and noisy, so a figure
# is only compared with one taken in the same minutes): CPU (user + sys) min / median / max,
# median wall time and the peak RSS of each, from /usr/bin/time.
# Usage: bench/paired_time.sh ROUNDS COMMAND_A... -- COMMAND_B...
set -eu
rounds=$1
shift
a=()
while [ "$1" != "--" ]; do a+=("$1"); shift; done
shift
b=("$@")
log=$(mktemp)
trap 'rm -f "$log"' EXIT
for _ in $(seq "$rounds"); do
  /usr/bin/time -f "A %U %S %e %M" "${a[@]}" > /dev/null 2>> "$log"
  /usr/bin/time -f "B %U %S %e %M" "${b[@]}" > /dev/null 2>> "$log"
done
for x in A B; do
  grep "^$x " "$log" | awk '{print $2 + $3, $4, $5}' | sort -n |
    awk -v x="$x" '{c[NR] = $1; w[NR] = $2; if ($3 > m) m = $3}
      END {printf "%s cpu min %.2f med %.2f max %.2f s, wall med %.2f s, peak rss %d MB\n", x, c[1], c[int((NR + 1) / 2)], c[NR], w[int((NR + 1) / 2)], m / 1024}'
done
