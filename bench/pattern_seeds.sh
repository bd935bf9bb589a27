#!/usr/bin/env bash
# Pattern detection on layouts the tests never use: each synthetic model drawn with other seeds
# (layout, orientations, noise), at 40k vertices and 40 instances asked; one row per run, then
# the mean recall and precision of each model. Tells whether the tests' figures hold beyond
# their own seeds.
# Usage: bench/pattern_seeds.sh BUILD [THREADS [SEEDS]]   (BUILD configured with -DCGAL_EXT_BUILD_BENCHMARKS=ON)
set -euo pipefail
build=${1:?usage: pattern_seeds.sh BUILD [THREADS [SEEDS]]}
threads=${2:-2}
seeds=${3:-"101 102 103 104 105"}
bench="$build/bench/bench_patterns"
echo "# $(date -u +%F) $(nproc) cores, threads=$threads, commit $(git -C "$(dirname "$0")" rev-parse --short HEAD), seeds $seeds"
echo "| model | V | planted | found | recall | precision | samples | sampling | signatures | matching+clustering | optimization | arrangement | total (s) | seed |"
echo "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
rows=$(for model in plane cylinder elongated sizes; do
  for seed in $seeds; do
    echo "$("$bench" "$model" 40000 40 "$threads" "$seed") $seed |"
  done
done)
echo "$rows"
echo
echo "| model | runs | mean recall | mean precision |"
echo "|---|---:|---:|---:|"
echo "$rows" | awk -F'|' '{ r[$2] += $6; p[$2] += $7; n[$2]++ }
  END { for(m in n) printf "|%s| %d | %.3f | %.3f |\n", m, n[m], r[m] / n[m], p[m] / n[m] }'
