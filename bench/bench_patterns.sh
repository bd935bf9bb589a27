#!/usr/bin/env bash
# The thesis's Table 5.1 for our code: repetitive pattern detection on meshes with planted
# instances, the time of each step, instances found, recall and precision; how the time grows
# with the number of instances (golf ball at 100k) and of vertices (plane, 60 instances).
# Usage: bench/bench_patterns.sh BUILD [THREADS]   (BUILD configured with -DCGAL_EXT_BUILD_BENCHMARKS=ON)
set -euo pipefail
build=${1:?usage: bench_patterns.sh BUILD [THREADS]}
threads=${2:-2}
bench="$build/bench/bench_patterns"
echo "# $(date -u +%F) $(nproc) cores, threads=$threads, commit $(git -C "$(dirname "$0")" rev-parse --short HEAD)"
echo "| model | V | planted | found | recall | precision | samples | sampling | signatures | matching+clustering | optimization | arrangement | total (s) |"
echo "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
for run in "golf 100000 60" "golf 100000 30" "golf 100000 120" \
           "plane 50000 60" "plane 100000 60" "plane 200000 60" "plane 350000 60" \
           "cylinder 100000 60" "elongated 100000 40" "sizes 100000 50"; do
  # shellcheck disable=SC2086
  "$bench" $run "$threads"
done
