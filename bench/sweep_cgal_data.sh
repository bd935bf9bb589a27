#!/usr/bin/env bash
# Runs the geodesic tool, as a new user would, on every mesh file of CGAL's data set
# (apt-get install libcgal-demo): distances from vertex 0, then the path to the farthest
# vertex. Prints one line per file (exit code, seconds, file, first words of stderr) and a
# count per exit code. Usage: bench/sweep_cgal_data.sh path/to/geodesic [max file size, e.g. 3M]
set -uo pipefail
tool=${1:?usage: $0 path/to/geodesic [max size]}
max_size=${2:-3M}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
tar xzf /usr/share/doc/libcgal-demo/data.tar.gz -C "$work"
find "$work" -type f \( -name '*.off' -o -name '*.obj' -o -name '*.ply' -o -name '*.stl' \) -size -"$max_size" | sort |
while read -r mesh; do
  start=$(date +%s.%N)
  timeout 120 "$tool" distances "$mesh" --source 0 --output "$work/d.txt" 2> "$work/err" > /dev/null
  rc=$?
  what=distances
  if [ $rc -eq 0 ]; then
    farthest=$(awk '$1 != "inf" && $1 > best {best = $1; at = NR - 1} END {print at + 0}' "$work/d.txt")
    timeout 120 "$tool" path "$mesh" --source 0 --target "$farthest" --output "$work/p.txt" 2>> "$work/err" > /dev/null
    rc=$?
    what=path
  fi
  seconds=$(awk -v s="$start" -v e="$(date +%s.%N)" 'BEGIN {print e - s}')
  printf '%d %s %.2f %s | %s\n' "$rc" "$what" "$seconds" "$(basename "$mesh")" "$(head -c 160 "$work/err" | tr '\n' ' ')"
done | tee "$work/summary"
echo "exit codes:"; awk '{print $1, $2}' "$work/summary" | sort | uniq -c
