#!/bin/bash
# Benchmark of the applications (issue 13), in one run on one mesh: farthest-point sampling of
# 100, 1,000 and 10,000 samples (1 and 2 threads), local sparse matrix rows at 5, 10 and 20 mean edge lengths on
# 1 and 2 threads, the all-pairs matrix among FPS samples, and Voronoi diagrams of 10, 100 and
# 1,000 sources (FWP-MMP, and PMMP on 2 threads); each against one full single-source solve of
# the same mesh (VTP, and FWP-MMP for the Voronoi diagram, which is read from an MMP build).
# Prints key=value lines.
# Usage: bench/bench_applications.sh BUILD_DIR MESH [ALL_PAIRS_SAMPLES]   (default 1000)
#   BUILD_DIR: a build with the tool and the benchmarks (-DCGAL_EXT_BUILD_BENCHMARKS=ON)
set -euo pipefail
build=$1
mesh=$2
pairs=${3:-1000}
tool=$build/src/geodesic
matrix=$build/bench/bench_matrix
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

stat() { grep -o "^$1=[^ ]*" | head -1 | cut -d= -f2; }
vertices=$($tool distances "$mesh" --source 0 --output "$work/d.txt" --stats 2>&1 | stat vertices)
# the reference solves: the median of 3 runs each (one run alone is as noisy as this machine)
median_solve() {
  for _ in 1 2 3; do $tool distances "$mesh" --source 0 --algorithm "$1" --output "$work/d.txt" --stats 2>&1 | stat seconds_solve; done |
    sort -g | sed -n 2p
}
vtp=$(median_solve vtp)
mmp=$(median_solve fwp-mmp)
echo "mesh=$mesh vertices=$vertices full_vtp_solve=$vtp full_fwp_mmp_solve=$mmp"

# one thread (VTP), and two (PVTP: samples in batches, the same samples)
for n in 100 1000 10000; do
  s=$($tool sample "$mesh" --count $n --algorithm vtp --output "$work/s$n.txt" --stats 2>&1 | stat seconds_sampling)
  echo "fps samples=$n threads=1 seconds=$s per_full_vtp_solve=$(python3 -c "print(round($s / $vtp, 2))")"
  s=$($tool sample "$mesh" --count $n --algorithm pvtp --threads 2 --output "$work/p$n.txt" --stats 2>&1 | stat seconds_sampling)
  echo "fps samples=$n threads=2 seconds=$s per_full_vtp_solve=$(python3 -c "print(round($s / $vtp, 2))")"
  cmp -s "$work/s$n.txt" "$work/p$n.txt" || echo "fps samples=$n: the samples of 1 and 2 threads differ"
done

for radius in 5 10 20; do
  for threads in 1 2; do
    line=$($matrix --mesh "$mesh" --rows 2000 --radius $radius --threads $threads --sparse 1)
    echo "sparse_rows radius_edges=$radius threads=$threads $(echo "$line" | tr ' ' '\n' | grep -E 'seconds_per_row|entries_per_row' | tr '\n' ' ')full_vtp_solve_per_row=$(python3 -c "print(round($vtp / $(echo "$line" | tr ' ' '\n' | stat seconds_per_row)))")"
  done
done

head -n "$pairs" "$work/s10000.txt" | cut -d' ' -f1 | paste -sd, > "$work/pairs.txt"
s=$($tool matrix "$mesh" --source "$(cat "$work/pairs.txt")" --target sources --threads 2 --output "$work/m.npy" --stats 2>&1 | stat seconds_rows)
echo "all_pairs samples=$pairs threads=2 seconds=$s per_full_vtp_solve=$(python3 -c "print(round($s / $vtp, 1))")"

# the diagram from the windows of one VTP propagation, of PVTP on 2 threads (the tool's default),
# of FWP-MMP and of PMMP on 2 threads; the cells must be the same
for n in 10 100 1000; do
  sources=$(python3 -c "print(','.join(str(i * ($vertices // $n)) for i in range($n)))")
  for algorithm in "vtp" "pvtp --threads 2" "fwp-mmp" "pmmp --threads 2"; do
    # shellcheck disable=SC2086
    line=$($tool voronoi "$mesh" --source "$sources" --algorithm $algorithm --output "$work/c_${algorithm%% *}.txt" --stats 2>&1)
    s=$(echo "$line" | stat seconds_diagram)
    echo "voronoi sources=$n algorithm=${algorithm// /_} seconds=$s bisectors=$(echo "$line" | stat bisectors) vertices=$(echo "$line" | stat voronoi_vertices) unresolved=$(echo "$line" | stat unresolved_parts) per_full_fwp_mmp_solve=$(python3 -c "print(round($s / $mmp, 2))") per_full_vtp_solve=$(python3 -c "print(round($s / $vtp, 2))")"
  done
  for other in vtp pvtp pmmp; do
    cmp -s "$work/c_fwp-mmp.txt" "$work/c_$other.txt" || echo "voronoi sources=$n: the cells of fwp-mmp and $other differ"
  done
done
