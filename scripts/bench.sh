#!/usr/bin/env bash
# make bench: runs every Google Benchmark program of the build. The figures
# quoted in the issue notes come from these runs (on an otherwise idle machine).
set -euo pipefail
BUILD=${1:-build}
found=0
while IFS= read -r b; do
  found=1
  echo "== $b"
  "$b" --benchmark_counters_tabular=true
done < <(find "$BUILD" -type f -executable \( -name '*_bench' -o -name '*_benchmark' \) | sort)
[[ $found == 1 ]] || { echo "bench: no benchmark programs in $BUILD (built with -DROOFSWEEP_BENCHMARKS=ON?)"; exit 1; }
